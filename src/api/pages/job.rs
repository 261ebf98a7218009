//! A job's page: what it is (kind, label, when, engine time), its warnings,
//! its accuracy, its plots, its values with their units (a long table's
//! rows left to its CSV), its request, and links to each as data.

use super::{IdPath, layout};
use crate::api::AppState;
use crate::api::kind::AnyKind;
use crate::api::plots::{self, Listed};
use crate::api::read::{self, result_tree};
use crate::api::tables::{self, Scalar};
use crate::i18n::{self, Msg, tr};
use crate::kind::problem::{ApiError, Problem};
use crate::store::{JobRow, Status};
use axum::extract::rejection::QueryRejection;
use axum::extract::{Query, State};
use axum::http::StatusCode;
use axum::response::Response;
use maud::{Markup, html};
use serde_json::Value;
use std::collections::HashMap;

/// Plots shown as pictures on the page; the others (a large mechanism's
/// joints, one each) are listed as links.
const SHOWN: usize = 12;

/// Arrays longer than this, or of more objects than [`ROWS`], are tables:
/// the page names them and links their CSV.
const LONG: usize = 12;
const ROWS: usize = 4;

/// A job's page.
#[utoipa::path(get, path = "/jobs/{id}", operation_id = "page_job", tag = "pages",
    params(("id" = String, Path, description = "Job id"),
        ("step" = Option<usize>, Query, minimum = 0, maximum = 99999, description = "The step or sample the drawing \
            of a mechanism shows, from 0 to the job's last (a 400 beyond it); at most the limit on steps or samples \
            less one (by default 99999)")),
    responses((status = 200, description = "The job's page", content_type = "text/html", body = String),
        (status = 400, description = "A step beyond the job's or an unknown query parameter", content_type = "text/html", body = String),
        (status = 401, description = "The service keeps its jobs to its token's holders and this browser has not signed in: the sign-in form, which comes back here", content_type = "text/html", body = String),
        (status = 404, description = "No job with this id", content_type = "text/html", body = String),
        (status = 503, description = "Saturated or the database unavailable", content_type = "text/html", body = String)))]
pub async fn job(
    State(state): State<AppState>,
    id: IdPath,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Response {
    let q = match read::query(q, &["step"]) {
        Ok(q) => q,
        Err(e) => return layout::error(e),
    };
    match render(&state, &id.0, &q).await {
        Ok(Rendered::Done(page)) => layout::answer(StatusCode::OK, page),
        Ok(Rendered::Waiting(page)) => {
            let mut answer = layout::answer(StatusCode::OK, page);
            answer.headers_mut().insert("refresh", axum::http::HeaderValue::from_static("2"));
            answer
        }
        Err(e) => layout::error(e),
    }
}

/// A job's page: of a done or failed job, or of one still waiting (the
/// browser asks again every 2 s, by the `Refresh` header: no script).
enum Rendered {
    Done(Markup),
    Waiting(Markup),
}

async fn render(state: &AppState, id: &str, q: &HashMap<String, String>) -> Result<Rendered, ApiError> {
    let step = plots::step(q, state.limits.last_step())?;
    let (row, result, _reserved) = match result_tree(state, id).await {
        Err(ApiError::NotDone { status, .. }) => {
            let (row, _reserved) = read::load(state, id, read::READ_MEMORY_FACTOR).await?;
            let page = not_done(&row, &kind_title(state, &row.kind));
            return Ok(if status == Status::Failed { Rendered::Done(page) } else { Rendered::Waiting(page) });
        }
        read => read?,
    };
    if let Some(s) = step {
        let count = steps(&result);
        if s >= count {
            return Err(crate::kind::plots::no_step(s, count));
        }
    }
    page(state, &row, result, step, Pictures::Linked).map(Rendered::Done)
}

/// How a page shows its plots: linked to the job's (stored), or drawn into
/// the page (a job not stored: `data:` pictures, by the plots' names).
pub enum Pictures<'a> {
    Linked,
    Inline(&'a [(String, String)]),
}

/// The page of a done job (`row`, its `result`), its mechanism drawn at
/// `step`; of a job not stored, without links to it.
pub fn page(
    state: &AppState,
    row: &JobRow,
    mut result: Value,
    step: Option<usize>,
    pictures: Pictures,
) -> Result<Markup, ApiError> {
    let request = serde_json::from_slice::<Value>(&row.request).unwrap_or_default();
    let kind = state.kinds.find(&row.kind).ok_or_else(|| ApiError::Internal(format!("job of kind {}", row.kind)))?;
    let listed = kind.plots(&crate::kind::plots::Job { request: &request, result: &result });
    let stored = matches!(pictures, Pictures::Linked);
    let named = kind.title();
    // The kind's own files this result has (a cam's profile.dxf).
    let files: Vec<&str> = kind.files().iter().map(|f| f.0).filter(|name| kind.has_file(&result, name)).collect();
    let summary = summary(row, &result);
    // Asked before `values` takes the long lists out of the result.
    let solution = kind.has_solution(&result);
    let (values, long) = values(kind, &mut result);
    let (lang, id) = (i18n::current(), &row.id);
    let t = |key| tr(lang, key);
    let body = html! {
        h1 { (title(row, &named)) }
        (meta(row, stored))
        @if stored { ul.links.noprint {
            li { a href=(format!("/v1/jobs/{id}")) { "JSON" } }
            li { a href=(format!("/v1/jobs/{id}/result.csv")) { (t("page-csv-table")) } }
            li { a href=(format!("/v1/jobs/{id}/values?format=csv")) { (t("page-every-value")) } }
            li { a href=(format!("/v1/jobs/{id}/plots")) { (t("page-plots-json")) } }
            @for name in &files { li { a href=(format!("/v1/jobs/{id}/{name}")) { (name) } } }
            @if solution {
                li { a href=(format!("/jobs/{id}/solution?step={}", step.unwrap_or(0))) { (t("page-solution-link")) } }
            }
        } } @else {
            p.meta { (t("page-not-stored")) " " a href="/signin" { (t("page-signin-title")) } }
        }
        h2 { (t("page-values")) }
        @if !long.is_empty() {
            p { (t("page-long-tables")) " "
                @for (k, (pointer, n)) in long.iter().enumerate() {
                    @if k > 0 { ", " } code { (pointer) } " (" (Msg::new("page-rows").arg("n", n).render(lang)) ")"
                } }
        }
        (value_table(stored.then_some(id.as_str()), &values))
        (summary)
        @match pictures {
            Pictures::Linked => (plot_figures(id, &listed, step)),
            Pictures::Inline(drawn) => (drawn_figures(&listed, drawn)),
        }
        (request_sent(row))
    };
    Ok(layout::page(&title(row, &named), body))
}

/// The page of a deferred job not done: where it is, or why it failed.
fn not_done(row: &JobRow, named: &str) -> Markup {
    let problem: Option<Problem> = row.problem.as_deref().and_then(|p| serde_json::from_slice(p).ok());
    let lang = i18n::current();
    let body = html! {
        h1 { (title(row, named)) }
        (meta(row, true))
        @match &problem {
            Some(p) => {
                h2 { (Msg::new("page-failed").arg("title", &p.title).render(lang)) }
                p.error { (p.detail) }
                @if !p.errors.is_empty() { ul { @for e in &p.errors { li { (e.describe()) } } } }
            }
            None => p { (Msg::new("page-waiting").arg("status", row.status.as_str()).render(lang)) }
        }
        ul.links.noprint { li { a href=(format!("/v1/jobs/{}", row.id)) { "JSON" } } }
        (request_sent(row))
    };
    layout::page(&title(row, named), body)
}

/// The job's id (where it is `stored`), when it was computed, its label, the engine.
fn meta(row: &JobRow, stored: bool) -> Markup {
    let t = |key| tr(i18n::current(), key);
    html! {
        p.meta { @if stored { (t("page-job")) " " span.id { (row.id) } " · " }
            (t("page-created")) " " (when(&row.created_at)) " UTC"
            @if let Some(l) = &row.label { " · " (t("page-label")) " " strong { (plots::svg::clean(l)) } }
            " · " (t("page-engine")) " " (row.engine_version) }
    }
}

/// The request as it was sent, folded.
fn request_sent(row: &JobRow) -> Markup {
    let t = |key| tr(i18n::current(), key);
    html! {
        h2 { (t("page-request")) }
        details { summary { (t("page-request-sent")) } pre { (String::from_utf8_lossy(&row.request)) } }
    }
}

/// "flywheel job: LABEL", "trabajo volante: LABEL" (`named`: the kind for people).
fn title(row: &JobRow, named: &str) -> String {
    let msg = match &row.label {
        Some(l) => Msg::new("page-job-title-label").arg("label", plots::svg::clean(l)),
        None => Msg::new("page-job-title"),
    };
    msg.arg("kind", named).text()
}

/// The kind `name` for people (its name when the registry has it not).
pub fn kind_title(state: &AppState, name: &str) -> String {
    state.kinds.find(name).map_or_else(|| name.to_string(), |k| k.title())
}

/// The number of steps (kinetostatics) or samples (dynamics) a drawing, or
/// the plots' cursor, can show.
fn steps(result: &Value) -> usize {
    let machine = result.pointer("/machine/samples").and_then(Value::as_array);
    let listed = |name: &str| result.get(name).and_then(Value::as_array);
    machine.or_else(|| listed("steps")).or_else(|| listed("samples")).map_or(0, Vec::len)
}

/// `x` in its shortest exact form, a whole number without `.0`.
pub fn number(x: f64) -> String {
    if x.fract() == 0.0 && x.abs() < 1e15 { format!("{}", x as i64) } else { tables::number_text(x) }
}

/// A stored time (RFC 3339, UTC) to the second: "2026-11-24 00:57:56".
pub fn when(created_at: &str) -> String {
    created_at.replace('T', " ").chars().take(19).collect()
}

/// "0.84 ms", "1.2 s" ("0,84 ms" on a Spanish page).
pub fn duration(us: i64) -> String {
    let s = us as f64 / 1e6;
    let text = if s >= 1.0 { format!("{s:.2} s") } else { format!("{:.2} ms", s * 1e3) };
    i18n::current().decimal(text)
}

/// Timing, accuracy (estimates: four figures) and warnings.
fn summary(row: &JobRow, result: &Value) -> Markup {
    let warnings: Vec<&str> =
        result.get("warnings").and_then(Value::as_array).into_iter().flatten().filter_map(Value::as_str).collect();
    let accuracy = result.get("accuracy").and_then(Value::as_object);
    let lang = i18n::current();
    html! {
        h2 { (tr(lang, "page-accuracy")) }
        p { (Msg::new("page-computed-in").arg("time", duration(row.engine_us)).render(lang)) }
        @if let Some(a) = accuracy {
            div.scroll { table.accuracy { tbody { @for (k, v) in a { tr {
                th { (accuracy_label(lang, k)) }
                @if v.is_number() { td.num { (text(v)) } } @else { td { (text(v)) } }
            } } } } }
        } @else {
            p { (tr(lang, "page-no-accuracy")) }
        }
        @if !warnings.is_empty() {
            h2 { (tr(lang, "page-warnings")) }
            ul.warnings { @for w in &warnings { li { (w) } } }
        }
    }
}

/// A field of a result's `accuracy` in the page's words (the catalogue's
/// `page-accuracy-…`), or its name with spaces where the catalogue has none.
fn accuracy_label(lang: i18n::Lang, key: &str) -> String {
    i18n::tr_named(lang, &format!("page-accuracy-{}", key.replace('_', "-"))).unwrap_or_else(|| key.replace('_', " "))
}

fn plot_figures(id: &str, listed: &[Listed], step: Option<usize>) -> Markup {
    // The step drawn is every plot's cursor (a plot without one ignores it).
    let src = |p: &Listed| match step.filter(|_| p.name != "motion") {
        Some(s) => format!("{}?step={s}", plots::href(id, &p.name)),
        None => plots::href(id, &p.name),
    };
    let t = |key| tr(i18n::current(), key);
    html! {
        @if !listed.is_empty() {
            h2 { (t("page-plots")) }
            @if listed.iter().any(|p| p.name == "mechanism") {
                form.inline.noprint method="get" action=(format!("/jobs/{id}")) {
                    label for="step" { (t("page-draw-at")) }
                    input #step type="number" name="step" min="0" required value=(step.unwrap_or(0));
                    button type="submit" { (t("page-draw")) }
                }
            }
            div.plots { @for p in listed.iter().take(SHOWN) { figure {
                a href=(src(p)) { img src=(src(p)) alt=(p.title) width="820" height="520"; }
                figcaption { (p.title) " · " a href=(src(p)) { "SVG" } }
            } } }
            @if listed.len() > SHOWN {
                p { (t("page-more-plots")) }
                ul { @for p in listed.iter().skip(SHOWN) { li { a href=(src(p)) { (p.title) } } } }
            }
        }
    }
}

/// The plots drawn into the page (`drawn`: each one's name and `data:` URI).
fn drawn_figures(listed: &[Listed], drawn: &[(String, String)]) -> Markup {
    let uri = |p: &Listed| drawn.iter().find(|(name, _)| *name == p.name).map(|(_, uri)| uri.as_str());
    html! {
        @if !drawn.is_empty() {
            h2 { (tr(i18n::current(), "page-plots")) }
            div.plots { @for p in listed { @if let Some(src) = uri(p) { figure {
                img src=(src) alt=(p.title) width="820" height="520";
                figcaption { (p.title) }
            } } } }
        }
    }
}

/// The result's scalars (accuracy and warnings shown above), and its long
/// arrays (pointer and length) left to the CSV: pruned from `result` in
/// place (a copy would double the memory its read reserved).
fn values(kind: &dyn AnyKind, result: &mut Value) -> (Vec<Scalar>, Vec<(String, usize)>) {
    let mut long = Vec::new();
    prune(result, String::new(), &mut long);
    let short = &*result;
    let skip = |p: &str| p.starts_with("/accuracy/") || p.starts_with("/warnings/") || long.iter().any(|(l, _)| l == p);
    let values = tables::flatten(kind, short).into_iter().filter(|s| !skip(&s.pointer)).collect();
    (values, long)
}

/// Replaces every table (an array of more than [`ROWS`] objects, or of
/// more than [`LONG`] items) by null, noting where and how long.
fn prune(v: &mut Value, at: String, long: &mut Vec<(String, usize)>) {
    match v {
        Value::Array(items) if items.len() > LONG || (items.len() > ROWS && items.iter().any(Value::is_object)) => {
            long.push((at, items.len()));
            *v = Value::Null;
        }
        Value::Array(items) => items.iter_mut().enumerate().for_each(|(i, x)| prune(x, format!("{at}/{i}"), long)),
        Value::Object(map) => {
            map.iter_mut().for_each(|(k, x)| prune(x, format!("{at}/{}", crate::api::json::escape(k)), long))
        }
        _ => {}
    }
}

/// The values, each number to four significant figures (in the page's
/// language) linked to its full value ([`crate::api::parts`]) where the job
/// `id` is stored.
fn value_table(id: Option<&str>, values: &[Scalar]) -> Markup {
    let t = |key| tr(i18n::current(), key);
    html! { div.scroll { table {
        thead { tr { th { (t("page-col-quantity")) } th { (t("page-col-value")) } th { (t("page-col-unit")) } } }
        tbody { @for s in values { tr {
            td.ptr { @for (k, part) in s.pointer.trim_start_matches('/').split('/').enumerate() { @if k > 0 { "/" wbr; } (part) } }
            @match (s.value.is_number(), id) {
                (true, Some(id)) => td.num {
                    a href=(format!("/v1/jobs/{id}/result{}", s.pointer)) title=(t("page-full-value")) { (text(&s.value)) }
                },
                (true, None) => td.num { (text(&s.value)) },
                _ => td { (text(&s.value)) },
            }
            td { (s.unit.as_deref().filter(|u| *u != "1").unwrap_or("")) }
        } } }
    } } }
}

/// A value as a person reads it: a whole number without `.0`, others to
/// four significant figures, with a decimal comma on a Spanish page.
fn text(v: &Value) -> String {
    match v {
        Value::Number(n) if n.is_f64() => {
            let x = n.as_f64().unwrap_or(f64::NAN);
            if x.fract() == 0.0 { number(x) } else { i18n::current().figures(x) }
        }
        Value::Number(n) => n.to_string(),
        Value::String(s) => plots::svg::clean(s),
        Value::Null => "—".into(),
        other => other.to_string(),
    }
}
