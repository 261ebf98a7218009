//! A template's form: each parameter with its unit, range and description,
//! at its default. Submitting it (a GET with the parameters, the same
//! names `GET /v1/templates/{id}/job` takes) finds or computes the job and
//! redirects to its page — or, for a browser without the token of a service
//! that has one, shows the page of the job computed and stored nowhere
//! ([`super::unstored`]); a value the template refuses shows the form again
//! with the message under its field.

use super::{IdPath, layout, query_of};
use crate::api::AppState;
use crate::api::templates::{self, Parameter, Template};
use crate::i18n::{self, Msg, tr};
use crate::kind::problem::{ApiError, FieldError};
use crate::units::parse_unit;
use axum::extract::rejection::QueryRejection;
use axum::extract::{Query, State};
use axum::http::{StatusCode, header};
use axum::response::{IntoResponse, Response};
use maud::{Markup, html};
use serde_json::Value;
use std::collections::HashMap;

/// A template's form; with parameters, their job's page.
#[utoipa::path(get, path = "/templates/{id}", operation_id = "page_template", tag = "pages",
    params(("id" = String, Path, description = "Template id, e.g. `p103-slider-flywheel`"),
        ("parameters" = Option<HashMap<String, String>>, Query, style = Form, explode,
            description = "The form's fields: when given, the job of these parameters (blank ones at their defaults)")),
    responses((status = 200, description = "The form", content_type = "text/html", body = String),
        (status = 303, description = "The job of these parameters: `Location` is its page", headers(("Location" = String, description = "/jobs/{id}"))),
        (status = 400, description = "A value the template refuses: the form again, the message at its field", content_type = "text/html", body = String),
        (status = 200, description = "Without the token, of a service that has one: the job of these values, computed within the share of requests without it and stored nowhere, its values and plots in the page", content_type = "text/html", body = String),
        (status = 404, description = "No template with this id", content_type = "text/html", body = String),
        (status = 422, description = "These parameters give no valid problem: the form again with why", content_type = "text/html", body = String),
        (status = 503, description = "Saturated or the database unavailable", content_type = "text/html", body = String)))]
pub async fn template(
    State(state): State<AppState>,
    id: IdPath,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Response {
    let given = match query_of(q) {
        Ok(q) => q,
        Err(e) => return layout::error(e),
    };
    let t = match templates::find(&state, &id.0).await {
        Ok(t) => t,
        Err(e) => return layout::error(e),
    };
    // Only the answer's own settings (`?lang=es`): the form, in that language.
    if given.keys().all(|k| templates::RESERVED.contains(&k.as_str())) {
        return layout::answer(StatusCode::OK, form(&t, &given, None, &super::job::kind_title(&state, &t.kind)));
    }
    // A field left blank or at its default is not asked: an unchanged form is
    // the template's own job, the one `/v1/templates/{id}/job` gives. A name
    // the template has not is asked, blank or not, and refused.
    let unchanged = |k: &String, v: &String| {
        t.parameters.get(k).is_some_and(|p| v.trim().is_empty() || default_text(&t, p) == v.trim())
    };
    let asked: HashMap<String, String> =
        given.iter().filter(|(k, v)| !unchanged(k, v)).map(|(k, v)| (k.clone(), v.clone())).collect();
    // A browser without the token, of a service that has one, stores no job:
    // the job of these values is computed within the anonymous share and its
    // page shown at once, unless it is stored and the browser may read it.
    let want = if crate::api::create::may_store() { templates::Want::Job } else { templates::Want::Values };
    match templates::job_for(&state, &t, &asked, want).await {
        Ok((row, _)) if row.seq == 0 || !crate::api::access::jobs_readable() => {
            match super::unstored::page(&state, row).await {
                Ok(page) => layout::answer(StatusCode::OK, page),
                Err(e) => layout::error(e),
            }
        }
        Ok((row, _)) => {
            // The language asked in the query goes with the redirect (a browser keeps it in its cookie too).
            let lang =
                given.get("lang").map(|l| format!("?lang={}", crate::api::plots::segment(l))).unwrap_or_default();
            (StatusCode::SEE_OTHER, [(header::LOCATION, format!("/jobs/{}{lang}", row.id))]).into_response()
        }
        Err(
            e @ (ApiError::BadQuery(_)
            | ApiError::Invalid(_)
            | ApiError::OverBudget(_)
            | ApiError::ResultTooLarge { .. }),
        ) => layout::answer(e.status(), form(&t, &given, Some(&e), &super::job::kind_title(&state, &t.kind))),
        Err(e) => layout::error(e),
    }
}

/// The form, with the values given and the errors of a refused submission.
fn form(t: &Template, given: &HashMap<String, String>, error: Option<&ApiError>, kind: &str) -> Markup {
    let fields = error.map_or(&[][..], ApiError::fields);
    let at = |name: &str| fields.iter().filter(|f| f.parameter.as_deref() == Some(name)).collect::<Vec<&FieldError>>();
    let others: Vec<&FieldError> =
        fields.iter().filter(|f| f.parameter.as_deref().is_none_or(|p| !t.parameters.contains_key(p))).collect();
    let lang = i18n::current();
    let title = t.title_in(lang);
    let tx = |key| tr(lang, key);
    let body = html! {
        h1 { (title) }
        p.meta { (Msg::new("page-template-meta").arg("id", &t.id).arg("kind", kind).render(lang))
            @if let Some(s) = t.source_in(lang) { " · " (s) } }
        @if let Some(e) = error {
            p.error { (e.msg().render(lang)) }
            @if !others.is_empty() { ul { @for f in &others { li.error { ((*f).clone().in_lang(lang).describe()) } } } }
        }
        p { (tx("page-form-help")) }
        form.params method="get" action=(format!("/templates/{}", crate::api::plots::segment(&t.id))) {
            @for (name, p) in &t.parameters {
                div {
                    label for=(name) { (name) @if let Some(u) = &p.unit { " (" (u) ")" } }
                    input id=(name) name=(name) type="text" autocomplete="off"
                        value=(given.get(name).cloned().unwrap_or_else(|| default_text(t, p)));
                    p.hint { (hint(p, t.description_in(name, lang))) }
                    @for f in at(name) { p.error { ((*f).clone().in_lang(lang).message) } }
                }
            }
            div { button type="submit" { (tx("page-compute")) } }
        }
        p { (tx("page-form-url")) " "
            code { "/v1/templates/" (t.id) "/job?" (tx("page-name-value")) } " " (tx("page-form-url-json")) " "
            code { "/v1/templates/" (t.id) "/result/" (tx("page-pointer")) "?" (tx("page-name-value")) } "." }
    };
    layout::page(&title, body)
}

/// A parameter's description and range, in its unit.
fn hint(p: &Parameter, description: Option<&str>) -> String {
    let unit = p.unit.as_deref().map_or(String::new(), |u| format!(" {u}"));
    let range = match (p.min, p.max, &p.choices) {
        (_, _, Some(c)) => {
            Some(Msg::new("page-one-of").arg("choices", c.iter().map(crate::kind::cell).collect::<Vec<_>>().join(", ")))
        }
        (Some(a), Some(b), None) => Some(Msg::new("page-from-to").num("min", a).num("max", b)),
        (Some(a), None, None) => Some(Msg::new("page-at-least").num("min", a)),
        (None, Some(b), None) => Some(Msg::new("page-at-most").num("max", b)),
        _ => None,
    };
    let range = range.map_or_else(String::new, |r| r.arg("unit", unit).text());
    let text = description.unwrap_or_default().to_string();
    match (text.is_empty(), range.is_empty()) {
        (false, false) => format!("{text}; {range}."),
        (true, false) => format!("{range}."),
        _ => text,
    }
}

/// The default of a parameter as a person would type it: a quantity string
/// as the template has it, a number in the parameter's unit.
fn default_text(t: &Template, p: &Parameter) -> String {
    match t.request.pointer(&p.pointer) {
        Some(Value::Number(n)) => {
            let x = n.as_f64().unwrap_or(0.0);
            let factor = p.unit.as_deref().and_then(|u| parse_unit(u).ok()).map_or(1.0, |(f, _)| f);
            i18n::current().decimal(super::job::number(x / factor))
        }
        Some(Value::String(s)) => s.clone(),
        Some(other) => other.to_string(),
        None => String::new(),
    }
}
