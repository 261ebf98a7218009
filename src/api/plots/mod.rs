//! Pictures of a stored job: `GET /v1/jobs/{id}/plots` lists them,
//! `GET /v1/jobs/{id}/plots/{name}.svg` draws one. A kind says which plots
//! its jobs have and builds each as a [`Chart`] from the stored result (and
//! the stored request where the geometry lives), through [`crate::kind::Kind`];
//! one renderer ([`svg`]) draws every chart. Nothing is computed again: the
//! plots show the numbers the result holds.
//!
//! Symbols: φ the reference shaft's angle, M*(φ) and I*(φ) the reduced torque
//! and inertia, W(φ) = ∫₀^φ M* dφ the work since φ = 0 (its values at the
//! crossings are the S_i), ΔE = S_max − S_min, ω_a the mean speed, ε the
//! irregularity, I the flywheel's constant inertia, T₀ the kinetic energy at
//! φ = 0.

pub mod animate;
pub mod svg;

use super::AppState;
use super::kind::AnyKind;
pub use super::read::step;
use super::read::{query, result_tree};
pub use crate::kind::chart::{Chart, Listed};
use crate::kind::plots::{Job, Options};

use crate::kind::problem::{ApiError, PrivateErrors, ReadErrors};
use axum::Json;
use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::header;
use axum::response::{IntoResponse, Response};
use serde::Serialize;
use serde_json::Value;
use std::collections::HashMap;
use utoipa::ToSchema;

/// The plot's route as axum routes it, and as the document says it (axum
/// cannot match `{name}.svg` within one segment; the handler wants the `.svg`).
pub const ROUTED: &str = "/v1/jobs/{id}/plots/{name}";
pub const DOCUMENTED: &str = "/v1/jobs/{id}/plots/{name}.svg";

/// One plot of a job, as listed.
#[derive(Serialize, ToSchema)]
pub struct PlotLink {
    /// Name in the plot's URL.
    #[schema(example = "torque")]
    pub name: String,
    #[schema(example = "Reduced torque M*(φ) and the lobes of work")]
    pub title: String,
    /// The plot as SVG.
    #[schema(example = "/v1/jobs/0d1e5d8a-6a3c-4f4e-9a53-2f1c0b7e9d41/plots/torque.svg")]
    pub href: String,
}

/// The plots of a job.
#[derive(Serialize, ToSchema)]
pub struct PlotList {
    pub plots: Vec<PlotLink>,
}

/// The plots of a job: each with its title and its SVG's address. A kind
/// without curves (a gear train, equivalent masses, a check) has none; a
/// job whose result holds no curve (a flywheel with `samples: 0`) has those
/// its result can draw.
#[utoipa::path(get, path = "/v1/jobs/{id}/plots", operation_id = "list_job_plots", tag = "jobs",
    params(("id" = String, Path, description = "Job id")),
    responses((status = 200, description = "The job's plots", body = PlotList), ReadErrors, PrivateErrors))]
pub async fn list(State(state): State<AppState>, Path(id): Path<String>) -> Result<Json<PlotList>, ApiError> {
    let (listed, _) = listed(&state, &id).await?;
    let plots =
        listed.into_iter().map(|p| PlotLink { href: href(&id, &p.name), name: p.name, title: p.title }).collect();
    Ok(Json(PlotList { plots }))
}

/// The address of a job's plot.
pub fn href(id: &str, name: &str) -> String {
    format!("/v1/jobs/{id}/plots/{}.svg", segment(name))
}

/// `text` as one segment of a URL's path: every byte but the unreserved
/// ones (RFC 3986: letters, digits, `-._~`) percent-encoded.
pub fn segment(text: &str) -> String {
    const RESERVED: &percent_encoding::AsciiSet =
        &percent_encoding::NON_ALPHANUMERIC.remove(b'-').remove(b'.').remove(b'_').remove(b'~');
    percent_encoding::utf8_percent_encode(text, RESERVED).to_string()
}

/// One plot of a job as SVG (`image/svg+xml`), drawn from its stored result:
/// a title, axes named with their units, a legend below.
#[utoipa::path(get, path = "/v1/jobs/{id}/plots/{name}.svg", operation_id = "get_job_plot", tag = "jobs",
    params(
        ("id" = String, Path, description = "Job id"),
        ("name" = String, Path, description = "The plot's name, as `GET /v1/jobs/{id}/plots` lists it: `torque`, `speed`, `mechanism`"),
        ("step" = Option<usize>, Query, minimum = 0, maximum = 99999, description = "The drawing of a mechanism \
            (`mechanism`): the step (kinetostatics) or sample (dynamics) it shows, from 0 (the default) to the job's \
            last (a 400 beyond it); on the plots against the input or the time, that step's cursor (none beyond the \
            job's). At most the limit on steps or samples less one (by default 99999)"),
    ),
    responses(
        (status = 200, description = "The plot", content_type = "image/svg+xml", body = String),
        (status = 400, description = "A step beyond the job's, or an unknown query parameter",
            body = crate::kind::problem::Problem, content_type = "application/problem+json"),
        (status = 404, description = "No job with this id, or no plot of this name (the message lists the job's plots)",
            body = crate::kind::problem::Problem, content_type = "application/problem+json"),
        (status = 503, description = "Too many large answers are being sent, or the database is unavailable",
            body = crate::kind::problem::Problem, content_type = "application/problem+json"),
        PrivateErrors,
    ))]
pub async fn plot(
    State(state): State<AppState>,
    Path((id, file)): Path<(String, String)>,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Response, ApiError> {
    let q = query(q, &["step"])?;
    let options = Options { step: step(&q, state.limits.last_step())? };
    let Some(name) = file.strip_suffix(".svg") else {
        let known = listed(&state, &id).await?.0.into_iter().map(|p| format!("{}.svg", p.name)).collect();
        return Err(ApiError::NoPlot { id, name: file, known });
    };
    let svg = render(&state, &id, name, options).await?;
    Ok(([(header::CONTENT_TYPE, "image/svg+xml")], svg).into_response())
}

/// The SVG of plot `name` of job `id` (also the pages' pictures).
pub async fn render(state: &AppState, id: &str, name: &str, options: Options) -> Result<String, ApiError> {
    let chart = match name.strip_prefix("free-body-") {
        Some(body) => free_body(state, id, body, options.step.unwrap_or(0)).await?,
        None => {
            let (row, result, _reserved) = result_tree(state, id).await?;
            let request = serde_json::from_slice::<Value>(&row.request).unwrap_or_default();
            let job = Job { request: &request, result: &result };
            chart(state.kinds.find(&row.kind), &job, (id, name), &options)?
        }
    };
    let lang = crate::i18n::current();
    tokio::task::spawn_blocking(move || crate::i18n::within_sync(lang, || animate::render(&chart)))
        .await
        .map_err(|e| ApiError::Internal(format!("plot: {e}")))?
        .map_err(ApiError::Internal)
}

/// Body `body`'s free body at step `step` of job `id` (a kind with a worked
/// solution), or the 404 naming the bodies it has.
async fn free_body(state: &AppState, id: &str, body: &str, step: usize) -> Result<Chart, ApiError> {
    // A step beyond the job's is the plot's 400, as for its other plots.
    let solution = super::solution::solve(state, id, step).await.map_err(|e| match e {
        ApiError::Invalid(errors) if errors.iter().any(|f| f.parameter.as_deref() == Some("step")) => {
            ApiError::BadQuery(errors)
        }
        e => e,
    })?;
    crate::kind::free_body_chart::chart(&solution, body).ok_or_else(|| {
        let known = solution.bodies.iter().map(|b| format!("free-body-{}", b.body)).collect();
        ApiError::NoPlot { id: id.into(), name: format!("free-body-{body}"), known }
    })
}

/// The chart of plot `name` of `job` (of `kind`, its id `id`), or the 404
/// naming the plots it has.
pub fn chart(kind: Option<&dyn AnyKind>, job: &Job, (id, name): (&str, &str), o: &Options) -> Result<Chart, ApiError> {
    let chart = match kind {
        Some(k) => k.plot(job, name, o)?,
        None => None,
    };
    chart.ok_or_else(|| {
        let known = kind.map(|k| k.plots(job)).unwrap_or_default().into_iter().map(|p| p.name).collect();
        ApiError::NoPlot { id: id.into(), name: name.into(), known }
    })
}

/// The plots a stored job has, and the job's row.
pub async fn listed(state: &AppState, id: &str) -> Result<(Vec<Listed>, crate::store::JobRow), ApiError> {
    let (row, result, _reserved) = result_tree(state, id).await?;
    let request = serde_json::from_slice::<Value>(&row.request).unwrap_or_default();
    let plots = state.kinds.find(&row.kind).map(|k| k.plots(&Job { request: &request, result: &result }));
    Ok((plots.unwrap_or_default(), row))
}

#[cfg(test)]
mod tests {
    /// RFC 3986's unreserved characters stay; a space, a slash and UTF-8 are encoded.
    #[test]
    fn a_plots_name_is_one_path_segment() {
        assert_eq!(super::segment("reaction-A_1.x~"), "reaction-A_1.x~");
        assert_eq!(super::segment("a b/é<"), "a%20b%2F%C3%A9%3C");
    }
}
