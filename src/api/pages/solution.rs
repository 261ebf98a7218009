//! The worked solution's page, `/jobs/{id}/solution?step=k`: as a student
//! hands it in — the bodies numbered, the order the groups are solved in
//! and what each gives, every body's free-body diagram with its forces and
//! couples and its three equations with the numbers substituted, and the
//! virtual-power check. Printable; in Spanish with `?lang=es`.

use super::{IdPath, layout};
use crate::api::AppState;
use crate::api::plots;
use crate::api::read::{self, step as asked_step};
use crate::i18n::{self, Msg, tr};
use crate::kind::plots::sig;
use crate::kind::solution::{FreeBody, Solution};
use axum::extract::rejection::QueryRejection;
use axum::extract::{Query, State};
use axum::http::StatusCode;
use axum::response::Response;
use maud::{Markup, html};
use std::collections::HashMap;

/// A job's worked solution at a step, for people.
#[utoipa::path(get, path = "/jobs/{id}/solution", operation_id = "page_solution", tag = "pages",
    params(("id" = String, Path, description = "Job id"),
        ("step" = Option<usize>, Query, minimum = 0, maximum = 99999, description = "The step, from 0 (the default) \
            to the job's last")),
    responses((status = 200, description = "The worked solution's page", content_type = "text/html", body = String),
        (status = 400, description = "An unknown query parameter, or a step not a whole number within the limit", content_type = "text/html", body = String),
        (status = 401, description = "The service keeps its jobs to its token's holders and this browser has not signed in", content_type = "text/html", body = String),
        (status = 404, description = "No job with this id, or a job without free bodies", content_type = "text/html", body = String),
        (status = 422, description = "A step the job has not, or one at a singular position", content_type = "text/html", body = String)))]
pub async fn solution(
    State(state): State<AppState>,
    id: IdPath,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Response {
    let at = read::query(q, &["step"]).and_then(|q| asked_step(&q, state.limits.last_step()));
    let solved = match at {
        Ok(at) => crate::api::solution::solve(&state, &id.0, at.unwrap_or(0)).await,
        Err(e) => Err(e),
    };
    match solved {
        Ok(s) => layout::answer(StatusCode::OK, page(&id.0, &s)),
        Err(e) => layout::error(e),
    }
}

/// The page of solution `s` of job `id`.
fn page(id: &str, s: &Solution) -> Markup {
    let lang = i18n::current();
    let t = |key| tr(lang, key);
    let title = Msg::new("page-solution-title").arg("step", s.step).text();
    let input: Vec<String> = s.input.iter().map(|v| sig(*v)).collect();
    let mut numbering: Vec<(&String, &usize)> = s.numbering.iter().collect();
    numbering.sort_by_key(|(_, n)| **n);
    let step_link = |k: usize| format!("/jobs/{id}/solution?step={k}");
    let body = html! {
        h1 { (title) }
        p.meta { (t("page-solution-input")) " " (input.join(", ")) }
        ul.links.noprint {
            li { a href=(format!("/jobs/{id}?step={}", s.step)) { (t("page-solution-job")) } }
            @if s.step > 0 { li { a href=(step_link(s.step - 1)) { (t("page-solution-previous")) } } }
            li { a href=(step_link(s.step + 1)) { (t("page-solution-next")) } }
            li { a href=(format!("/v1/jobs/{id}/solution?step={}", s.step)) { "JSON" } }
        }
        form.inline.noprint method="get" action=(format!("/jobs/{id}/solution")) {
            label for="step" { (t("page-solution-at-step")) }
            input #step type="number" name="step" min="0" required value=(s.step);
            button type="submit" { (t("page-solution-solve")) }
        }
        h2 { (t("page-solution-numbering")) }
        p { @for (k, (name, n)) in numbering.iter().enumerate() { @if k > 0 { ", " } strong { (n) } " " (name) } }
        h2 { (t("page-solution-order")) }
        p { (t("page-solution-order-why")) }
        ol { @for g in &s.groups { li {
            (Msg::new("page-solution-group").arg("bodies", g.bodies.join(", ")).arg("unknowns", g.unknowns.join(", ")).render(lang))
        } } }
        @for name in &s.order { @if let Some(b) = s.bodies.iter().find(|b| &b.body == name) { (body_section(id, s.step, b)) } }
        (virtual_power(s))
    };
    layout::page(&title, body)
}

/// One body: its diagram, its actions, its three equations with the
/// numbers (six in space: ΣF and ΣM_G along x, y and z).
fn body_section(id: &str, step: usize, b: &FreeBody) -> Markup {
    let lang = i18n::current();
    let t = |key| tr(lang, key);
    let src = format!("{}?step={step}", plots::href(id, &format!("free-body-{}", b.body)));
    let space = b.equations.sum_fz.is_some();
    let component = |k: usize| -> Vec<(String, f64)> {
        let sub = ["ₓ", "ᵧ", "_z"][k];
        b.forces.iter().map(|f| (format!("{}{sub}", f.name), [f.fx, f.fy, f.fz.unwrap_or(0.0)][k])).collect()
    };
    let moments = |k: usize| -> Vec<(String, f64)> {
        let arm = |f: &crate::kind::solution::Force| -> [f64; 3] {
            std::array::from_fn(|i| f.at.get(i).copied().unwrap_or(0.0) - b.cg.get(i).copied().unwrap_or(0.0))
        };
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let sub = if space { ["ₓ", "ᵧ", "_z"][k] } else { "" };
        let forces = b.forces.iter().map(|f| {
            let (r, v) = (arm(f), [f.fx, f.fy, f.fz.unwrap_or(0.0)]);
            let name = if space { format!("(r×{}){sub}", f.name) } else { format!("r×{}", f.name) };
            (name, r[i] * v[j] - r[j] * v[i])
        });
        let couple = |c: &crate::kind::solution::Couple| [c.mx.unwrap_or(0.0), c.my.unwrap_or(0.0), c.moment][k];
        forces.chain(b.couples.iter().map(|c| (format!("{}{sub}", c.name), couple(c)))).collect()
    };
    let e = &b.equations;
    let at = |p: &[f64]| p.iter().map(|v| sig(*v)).collect::<Vec<_>>().join("; ");
    let g = b.number;
    html! {
        h2 { (b.body) " (" (b.number) ")" }
        figure {
            a href=(src) { img src=(src) alt=(b.body) width="820" height="520"; }
            figcaption { (Msg::new("page-solution-diagram").arg("body", &b.body).render(lang)) }
        }
        div.scroll { table {
            thead { tr { th { (t("page-solution-action")) } th { (t("page-solution-from")) } th { (t("page-solution-at")) }
                th { "Fₓ (N)" } th { "Fᵧ (N)" } @if space { th { "F_z (N)" } th { "Mₓ (N·m)" } th { "Mᵧ (N·m)" } }
                th { @if space { "M_z (N·m)" } @else { "M (N·m)" } } } }
            tbody {
                @for f in &b.forces { tr {
                    td { strong { (f.name) } " · " (t(kind_key(&f.kind))) }
                    td { (f.by.as_deref().unwrap_or("")) @if let Some(j) = &f.joint { " (" (j) ")" } }
                    td.num { "(" (at(&f.at)) ")" }
                    td.num { (sig(f.fx)) } td.num { (sig(f.fy)) }
                    @if space { td.num { (sig(f.fz.unwrap_or(0.0))) } td {} td {} }
                    td {}
                } }
                @for c in &b.couples { tr {
                    td { strong { (c.name) } " · " (t(kind_key(&c.kind))) }
                    td { (c.by.as_deref().unwrap_or("")) @if let Some(j) = &c.joint { " (" (j) ")" } }
                    td {} td {} td {}
                    @if space { td {} td.num { (sig(c.mx.unwrap_or(0.0))) } td.num { (sig(c.my.unwrap_or(0.0))) } }
                    td.num { (sig(c.moment)) }
                } }
            }
        } }
        ul {
            li { (equation("ΣFₓ", &component(0), e.sum_fx, "N")) }
            li { (equation("ΣFᵧ", &component(1), e.sum_fy, "N")) }
            @if let Some(fz) = e.sum_fz { li { (equation("ΣF_z", &component(2), fz, "N")) } }
            @if let (Some(mx), Some(my)) = (e.sum_mx_about_cg, e.sum_my_about_cg) {
                li { (equation(&format!("ΣM_G{g}ₓ"), &moments(0), mx, "N·m")) }
                li { (equation(&format!("ΣM_G{g}ᵧ"), &moments(1), my, "N·m")) }
                li { (equation(&format!("ΣM_G{g}_z"), &moments(2), e.sum_moment_about_cg, "N·m")) }
            } @else {
                li { (equation(&format!("ΣM_G{g}"), &moments(2), e.sum_moment_about_cg, "N·m")) }
            }
        }
    }
}

/// "ΣFₓ: R23ₓ + W3ₓ = 120.5 − 120.5 = 3.1e-13 N".
fn equation(sum: &str, terms: &[(String, f64)], total: f64, unit: &str) -> Markup {
    let names: Vec<&str> = terms.iter().map(|(n, _)| n.as_str()).collect();
    let mut numbers = String::new();
    for (k, (_, v)) in terms.iter().enumerate() {
        match (k, *v < 0.0) {
            (0, _) => numbers.push_str(&sig(*v)),
            (_, true) => numbers.push_str(&format!(" − {}", sig(-v))),
            (_, false) => numbers.push_str(&format!(" + {}", sig(*v))),
        }
    }
    html! { strong { (sum) } ": " (names.join(" + ")) " = " (numbers) " = " strong { (sig(total)) " " (unit) } }
}

/// The catalogue's word for an action's kind.
fn kind_key(kind: &str) -> &'static str {
    match kind {
        "reaction" => "page-solution-reaction",
        "inertia" => "page-solution-inertia",
        "weight" => "page-solution-weight",
        "driving" => "page-solution-driving",
        _ => "page-solution-load",
    }
}

/// Each action's power and their sum.
fn virtual_power(s: &Solution) -> Markup {
    let lang = i18n::current();
    let t = |key| tr(lang, key);
    let p = &s.virtual_power;
    html! {
        h2 { (t("page-solution-power")) }
        p { (t("page-solution-power-why")) }
        div.scroll { table {
            thead { tr { th { (t("page-solution-action")) } th { "P (W)" } } }
            tbody {
                @for (name, power) in &p.actions { tr { td { (name) } td.num { (sig(*power)) } } }
                tr { td { (t("page-solution-reactions")) } td.num { (sig(p.reactions)) } }
                tr { td { strong { (t("page-solution-total")) } } td.num { strong { (sig(p.total)) } } }
            }
        } }
    }
}
