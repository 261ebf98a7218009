//! Pages for people, rendered by the service (maud; no JavaScript, nothing
//! from elsewhere): `/` the recent jobs and the templates, `/jobs/{id}` a
//! job's values with their units, warnings, accuracy, timing and plots,
//! `/templates/{id}` a form of a template's parameters whose GET computes
//! (or finds) the job and shows its page.

pub mod form;
pub mod job;
mod layout;
pub mod signin;
pub mod solution;
mod unstored;

use super::AppState;
use super::templates::builtin;
use crate::i18n::{self, tr};
use crate::kind::problem::ApiError;
use crate::store::Status;
use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::StatusCode;
use axum::response::Response;
use maud::html;
use std::collections::HashMap;

pub use layout::error;

/// Whether `path` is a page's, whose errors are answered as pages too.
pub fn is_page(path: &str) -> bool {
    path == "/" || path.starts_with("/jobs/") || path.starts_with("/templates/") || path == "/signin"
}

/// How many recent jobs the home page lists.
const RECENT: i64 = 25;

/// The home page: the recent jobs, the templates, the API's documentation.
#[utoipa::path(get, path = "/", operation_id = "page_home", tag = "pages",
    responses((status = 200, description = "The home page", content_type = "text/html", body = String),
        (status = 503, description = "The database is unavailable", content_type = "text/html", body = String)))]
pub async fn home(State(state): State<AppState>) -> Response {
    // The recent jobs only to whom may read them (`api::access`).
    let readable = crate::api::access::jobs_readable();
    let jobs = match readable {
        true => match state.store.recent(RECENT).await {
            Ok(jobs) => jobs,
            Err(e) => return layout::error(e.into()),
        },
        false => Vec::new(),
    };
    let mut templates = builtin().to_vec();
    if let Ok(stored) = state.store.templates().await {
        templates.extend(stored.iter().filter_map(|b| serde_json::from_str(b).ok()));
    }
    let lang = i18n::current();
    let t = |id| tr(lang, id);
    let body = html! {
        h1 { "mechdyn" }
        p.meta { (t("page-home-intro")) }
        h2 { (t("page-templates")) }
        div.scroll { table {
            thead { tr { th { (t("page-col-template")) } th { (t("page-col-kind")) } th { (t("page-col-problem")) } } }
            tbody { @for t in &templates { tr {
                td.id { a href=(format!("/templates/{}", super::plots::segment(&t.id))) { (t.id) } }
                td { (job::kind_title(&state, &t.kind)) }
                td { (t.title_in(lang)) }
            } } }
        } }
        h2 { (t("page-recent")) }
        @if !readable {
            (signin::section("/", false))
        } @else if jobs.is_empty() {
            p { (t("page-no-job")) " " a href="/docs/" { (t("page-nav-docs")) } }
        } @else {
            div.scroll { table {
                thead { tr {
                    th { (t("page-col-job")) } th { (t("page-col-kind")) } th { (t("page-col-label")) }
                    th { (t("page-col-created")) } th { (t("page-col-time")) }
                } }
                tbody { @for j in &jobs { tr {
                    td.id { a href=(format!("/jobs/{}", j.id)) { (j.id) } }
                    td { (job::kind_title(&state, &j.kind)) }
                    td { (j.label.as_deref().map(super::plots::svg::clean).unwrap_or_default()) }
                    td.num { (job::when(&j.created_at)) }
                    @if j.status == Status::Done { td.num { (job::duration(j.engine_us)) } } @else { td { (j.status.as_str()) } }
                } } }
            } }
        }
        h2 { (t("page-for-programs")) }
        ul.links {
            li { a href="/docs/" { (t("page-nav-docs")) } }
            li { a href="/openapi.json" { (t("page-nav-openapi")) } }
            li { a href="/v1/jobs" { (t("page-jobs-json")) } }
            li { a href="/v1/templates" { (t("page-templates-json")) } }
        }
    };
    layout::answer(StatusCode::OK, layout::page(&t("page-nav-home"), body))
}

/// No icon: an answer a browser takes without logging a failed request
/// (it asks for `/favicon.ico` whatever a page says).
#[utoipa::path(get, path = "/favicon.ico", operation_id = "favicon", tag = "pages",
    responses((status = 204, description = "No icon")))]
pub async fn favicon() -> StatusCode {
    StatusCode::NO_CONTENT
}

/// The query of a page, or its error.
fn query_of(q: Result<Query<HashMap<String, String>>, QueryRejection>) -> Result<HashMap<String, String>, ApiError> {
    q.map(|Query(q)| q)
        .map_err(|e| ApiError::BadQuery(vec![crate::kind::problem::FieldError::parameter("", e.body_text())]))
}

/// The job page's route and the form's take their id from the path.
pub type IdPath = Path<String>;
