//! Pictures of a stored job: `GET /v1/jobs/{id}/plots` lists them,
//! `GET /v1/jobs/{id}/plots/{name}.svg` draws one. A kind says which plots
//! its jobs have and builds each as a [`Chart`] from the stored result (and
//! the stored request where the geometry lives), through [`super::kind::Kind`];
//! one renderer ([`svg`]) draws every chart. Nothing is computed again: the
//! plots show the numbers the result holds.
//!
//! Symbols: φ the reference shaft's angle, M*(φ) and I*(φ) the reduced torque
//! and inertia, W(φ) = ∫₀^φ M* dφ the work since φ = 0 (its values at the
//! crossings are the S_i), ΔE = S_max − S_min, ω_a the mean speed, ε the
//! irregularity, I the flywheel's constant inertia, T₀ the kinetic energy at
//! φ = 0.

pub mod chart;
mod drawing;
mod dynamics;
mod flywheel;
mod kinetostatics;
mod machines;
pub mod svg;

use super::AppState;
use super::kind;
use super::problem::{ApiError, FieldError, ReadErrors};
use super::read::{query, result_tree};
use axum::Json;
use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::header;
use axum::response::{IntoResponse, Response};
pub use chart::{Chart, Listed};
use serde::Serialize;
use serde_json::Value;
use std::collections::HashMap;
use utoipa::ToSchema;

/// The plot's route as axum routes it, and as the document says it (axum
/// cannot match `{name}.svg` within one segment; the handler wants the `.svg`).
pub const ROUTED: &str = "/v1/jobs/{id}/plots/{name}";
pub const DOCUMENTED: &str = "/v1/jobs/{id}/plots/{name}.svg";

/// A kind's plots: how a stored job lists them and how one is drawn.
#[derive(Clone, Copy)]
pub struct Plots {
    pub list: fn(&Job) -> Vec<Listed>,
    pub draw: fn(&Job, &str, &Options) -> Drawn,
}

/// A kind without curves.
pub const NONE: Plots = Plots { list: |_| Vec::new(), draw: |_, _, _| Ok(None) };
pub const FLYWHEEL: Plots = Plots { list: flywheel::list, draw: flywheel::draw };
pub const KINETOSTATICS: Plots = Plots { list: kinetostatics::list, draw: kinetostatics::draw };
pub const DYNAMICS: Plots = Plots { list: dynamics::list, draw: dynamics::draw };
pub const ROTOR: Plots = Plots { list: machines::rotor_plots, draw: machines::rotor_plot };
pub const GEAR: Plots = Plots { list: machines::gear_plots, draw: machines::gear_plot };

/// A stored job as the plots read it.
pub struct Job<'a> {
    pub request: &'a Value,
    pub result: &'a Value,
}

/// What a plot's query may choose.
#[derive(Clone, Copy, Debug, Default)]
pub struct Options {
    /// The step (kinetostatics) or sample (dynamics) a drawing of the mechanism shows.
    pub step: Option<usize>,
}

/// What a kind's `plot` answers: the chart, none of that name, or a 400.
pub type Drawn = Result<Option<Chart>, ApiError>;

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
    responses((status = 200, description = "The job's plots", body = PlotList), ReadErrors))]
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
        ("step" = Option<usize>, Query, description = "The drawing of a mechanism (`mechanism`): the step \
            (kinetostatics) or sample (dynamics) it shows, from 0 (the default)"),
    ),
    responses(
        (status = 200, description = "The plot", content_type = "image/svg+xml", body = String),
        (status = 400, description = "A step beyond the job's, or an unknown query parameter",
            body = crate::api::problem::Problem, content_type = "application/problem+json"),
        (status = 404, description = "No job with this id, or no plot of this name (the message lists the job's plots)",
            body = crate::api::problem::Problem, content_type = "application/problem+json"),
        (status = 503, description = "Too many large answers are being sent, or the database is unavailable",
            body = crate::api::problem::Problem, content_type = "application/problem+json"),
    ))]
pub async fn plot(
    State(state): State<AppState>,
    Path((id, file)): Path<(String, String)>,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Response, ApiError> {
    let q = query(q, &["step"])?;
    let options = Options { step: step(&q)? };
    let Some(name) = file.strip_suffix(".svg") else {
        let known = listed(&state, &id).await?.0.into_iter().map(|p| format!("{}.svg", p.name)).collect();
        return Err(ApiError::NoPlot { id, name: file, known });
    };
    let svg = render(&state, &id, name, options).await?;
    Ok(([(header::CONTENT_TYPE, "image/svg+xml")], svg).into_response())
}

/// The SVG of plot `name` of job `id` (also the pages' pictures).
pub async fn render(state: &AppState, id: &str, name: &str, options: Options) -> Result<String, ApiError> {
    let (row, result, _reserved) = result_tree(state, id).await?;
    let request = serde_json::from_slice::<Value>(&row.request).unwrap_or_default();
    let job = Job { request: &request, result: &result };
    let kind = kind::find(&row.kind);
    let chart = match kind {
        Some(k) => k.plot(&job, name, &options)?,
        None => None,
    };
    let Some(chart) = chart else {
        let known = kind.map(|k| k.plots(&job)).unwrap_or_default().into_iter().map(|p| p.name).collect();
        return Err(ApiError::NoPlot { id: id.into(), name: name.into(), known });
    };
    tokio::task::spawn_blocking(move || svg::render(&chart))
        .await
        .map_err(|e| ApiError::Internal(format!("plot: {e}")))?
        .map_err(ApiError::Internal)
}

/// The plots a stored job has, and the job's row.
pub async fn listed(state: &AppState, id: &str) -> Result<(Vec<Listed>, crate::store::JobRow), ApiError> {
    let (row, result, _reserved) = result_tree(state, id).await?;
    let request = serde_json::from_slice::<Value>(&row.request).unwrap_or_default();
    let plots = kind::find(&row.kind).map(|k| k.plots(&Job { request: &request, result: &result }));
    Ok((plots.unwrap_or_default(), row))
}

/// `?step=`, when given, a whole number (a blank one too is a 400: the
/// document says integer, and the page's form requires the field).
pub fn step(q: &HashMap<String, String>) -> Result<Option<usize>, ApiError> {
    q.get("step")
        .map(|s| {
            s.trim().parse::<usize>().map_err(|_| {
                ApiError::BadQuery(vec![FieldError::parameter("step", format!("'{s}': must be a whole number from 0"))])
            })
        })
        .transpose()
}

/// A step beyond the result's `count` steps, as a 400 at `?step=`.
pub fn no_step(step: usize, count: usize) -> ApiError {
    let message = match count {
        0 => format!("{step}: this job draws no mechanism, so it has no steps to choose"),
        1 => format!("{step}: the job has 1 step (0)"),
        n => format!("{step}: the job has {n} steps (0 to {})", n - 1),
    };
    ApiError::BadQuery(vec![FieldError::parameter("step", message)])
}

/// The number at `key` of `row`.
pub fn num(row: &Value, key: &str) -> Option<f64> {
    row.get(key).and_then(Value::as_f64)
}

/// The rows of the array at `key` of `v`.
pub fn rows<'a>(v: &'a Value, key: &str) -> &'a [Value] {
    v.get(key).and_then(Value::as_array).map_or(&[], Vec::as_slice)
}

/// (x, y) of every row where both are numbers.
pub fn xy(rows: &[Value], x: impl Fn(&Value) -> Option<f64>, y: impl Fn(&Value) -> Option<f64>) -> Vec<(f64, f64)> {
    rows.iter().filter_map(|r| Some((x(r)?, y(r)?))).collect()
}

/// A joint's reaction over the rows: its name, the bodies it acts on and
/// by, and (x, f_x, f_y) wherever it is determinate.
pub struct Series {
    pub joint: String,
    pub on: String,
    pub by: String,
    pub points: Vec<(f64, f64, f64)>,
}

/// Every joint's reaction over the rows (each row's `reactions`, x from
/// `x`), in one pass; joints in the order first met.
pub fn reaction_series(rows: &[Value], x: impl Fn(&Value) -> Option<f64>) -> Vec<Series> {
    let mut out: Vec<Series> = Vec::new();
    let mut index: HashMap<String, usize> = HashMap::new();
    let text = |r: &Value, k: &str| r.get(k).and_then(Value::as_str).unwrap_or("").to_string();
    for row in rows {
        let Some(x) = x(row) else { continue };
        for r in self::rows(row, "reactions") {
            let Some(joint) = r.get("joint").and_then(Value::as_str) else { continue };
            let k = *index.entry(joint.to_string()).or_insert_with(|| {
                out.push(Series { joint: joint.to_string(), on: text(r, "on"), by: text(r, "by"), points: Vec::new() });
                out.len() - 1
            });
            if let (Some(fx), Some(fy)) = (num(r, "fx"), num(r, "fy")) {
                out[k].points.push((x, fx, fy));
            }
        }
    }
    out
}

/// The most joints a plot of every joint's reaction draws (the largest);
/// each joint has its own plot besides.
pub const MOST_JOINTS: usize = 12;

/// |R| of every joint against x, the [`MOST_JOINTS`] largest, into `c`.
pub fn magnitudes(mut c: Chart, mut series: Vec<Series>) -> Chart {
    let largest = |s: &Series| s.points.iter().map(|p| p.1.hypot(p.2)).fold(0.0, f64::max);
    let total = series.len();
    series.sort_by(|a, b| largest(b).total_cmp(&largest(a)));
    for (k, s) in series.iter().take(MOST_JOINTS).enumerate() {
        let points = s.points.iter().map(|p| (p.0, p.1.hypot(p.2))).collect();
        // Beyond the palette's eight colours, the same colours dashed.
        let pen =
            if k < 8 { chart::Pen::solid(k) } else { chart::Pen { dashed: true, width: 2, ..chart::Pen::solid(k) } };
        c = c.line(format!("joint {}", s.joint), points, pen);
    }
    if total > MOST_JOINTS {
        c = c.subtitle(format!("the {MOST_JOINTS} largest of {total} joints; each joint's own plot shows the rest"));
    }
    c
}

/// `v` with four significant figures, for labels.
pub fn sig(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor();
    if !(-3.0..6.0).contains(&magnitude) {
        return format!("{v:.3e}");
    }
    let decimals = (3.0 - magnitude).max(0.0) as usize;
    format!("{v:.decimals$}")
}

/// Radians to degrees, for the angle axes.
pub fn deg(rad: f64) -> f64 {
    rad.to_degrees()
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
