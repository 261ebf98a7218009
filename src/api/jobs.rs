//! Jobs: created by the POST of each calculation, read back by id, listed,
//! and exported as CSV.

use super::AppState;
use super::problem::{ApiError, FieldError, Problem};
use crate::store::{JobRow, NewJob};
use axum::Json;
use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::{StatusCode, header};
use axum::response::{IntoResponse, Response};
use serde::Serialize;
use serde_json::value::RawValue;
use std::collections::HashMap;
use std::time::Instant;
use utoipa::{IntoParams, ToSchema};

/// Kinds of job, as used in `kind` and `GET /v1/jobs?kind=`.
pub const KINDS: &[&str] =
    &["flywheel", "kinetostatics", "dynamics", "rotor", "gears", "gear_train", "equivalent_masses"];
/// Largest page of the jobs list.
pub const MAX_LIMIT: i64 = 100;

#[derive(Serialize, ToSchema)]
pub struct Timing {
    /// Wall time of the engine, microseconds.
    pub engine_us: i64,
}

/// A stored computation: the request as sent, and its result.
#[derive(Serialize, ToSchema)]
pub struct Job {
    /// Random UUID.
    pub id: String,
    #[schema(example = "flywheel")]
    pub kind: String,
    /// RFC 3339, UTC.
    pub created_at: String,
    /// The request body exactly as sent.
    #[schema(value_type = Object)]
    pub request: Box<RawValue>,
    /// The result; its schema depends on `kind` (e.g. FlywheelResult).
    #[schema(value_type = Object)]
    pub result: Box<RawValue>,
    pub timing: Timing,
    /// Version of mechdyn that computed the result.
    pub engine_version: String,
}

impl Job {
    fn from_row(r: JobRow) -> Result<Self, ApiError> {
        let raw = |s: String| RawValue::from_string(s).map_err(|e| ApiError::Internal(format!("stored JSON: {e}")));
        Ok(Self {
            id: r.id,
            kind: r.kind,
            created_at: r.created_at,
            request: raw(r.request)?,
            result: raw(r.result)?,
            timing: Timing { engine_us: r.engine_us },
            engine_version: r.engine_version,
        })
    }
}

/// A page of jobs, newest first.
#[derive(Serialize, ToSchema)]
pub struct JobList {
    pub items: Vec<Job>,
    /// Relative URL of the next page, or null on the last one.
    pub next: Option<String>,
}

/// Runs `compute` off the async workers, stores the job, and answers 201
/// with the job and its `Location`.
pub async fn create<R, F>(
    state: &AppState,
    kind: &'static str,
    request: String,
    compute: F,
) -> Result<Response, ApiError>
where
    R: Serialize + Send + 'static,
    F: FnOnce() -> Result<R, ApiError> + Send + 'static,
{
    let (result, elapsed) = tokio::task::spawn_blocking(move || {
        let start = Instant::now();
        let r = compute();
        (r, start.elapsed())
    })
    .await
    .map_err(|e| ApiError::Internal(format!("engine task: {e}")))?;
    let result = serde_json::to_string(&result?).map_err(|e| ApiError::Internal(e.to_string()))?;
    let id = uuid::Uuid::new_v4().to_string();
    let row = NewJob {
        id: id.clone(),
        kind: kind.into(),
        created_at: now_rfc3339(),
        request,
        result,
        engine_us: i64::try_from(elapsed.as_micros()).unwrap_or(i64::MAX),
        engine_version: env!("CARGO_PKG_VERSION").into(),
    };
    let job = Job::from_row(state.store.insert(row).await?)?;
    Ok((StatusCode::CREATED, [(header::LOCATION, format!("/v1/jobs/{id}"))], Json(job)).into_response())
}

fn now_rfc3339() -> String {
    let format =
        time::macros::format_description!("[year]-[month]-[day]T[hour]:[minute]:[second].[subsecond digits:6]Z");
    time::OffsetDateTime::now_utc().format(&format).unwrap_or_default()
}

/// Reads a job.
#[utoipa::path(get, path = "/v1/jobs/{id}", operation_id = "get_job", tag = "jobs",
    params(("id" = String, Path, description = "Job id")),
    responses(
        (status = 200, description = "The job", body = Job),
        (status = 404, description = "No such job", body = Problem, content_type = "application/problem+json"),
    ))]
pub async fn get(State(state): State<AppState>, Path(id): Path<String>) -> Result<Json<Job>, ApiError> {
    let row = state.store.get(&id).await?.ok_or(ApiError::NotFound(id))?;
    Ok(Json(Job::from_row(row)?))
}

/// Query of the jobs list.
#[derive(IntoParams)]
#[into_params(parameter_in = Query)]
#[allow(dead_code)]
pub struct ListParams {
    /// Only jobs of this kind.
    #[param(pattern = "^(flywheel|kinetostatics|dynamics|rotor|gears|gear_train|equivalent_masses)$")]
    kind: Option<String>,
    /// Page size, 1 to 100 (default 50).
    #[param(minimum = 1, maximum = 100)]
    limit: Option<i64>,
    /// Opaque cursor from `next`.
    #[param(minimum = 1)]
    before: Option<i64>,
}

/// Lists jobs, newest first, a page at a time.
#[utoipa::path(get, path = "/v1/jobs", operation_id = "list_jobs", tag = "jobs", params(ListParams),
    responses(
        (status = 200, description = "A page of jobs", body = JobList),
        (status = 400, description = "Invalid query parameters", body = Problem, content_type = "application/problem+json"),
    ))]
pub async fn list(
    State(state): State<AppState>,
    query: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Json<JobList>, ApiError> {
    let Query(q) = query.map_err(|e| ApiError::BadQuery(vec![FieldError::parameter("", e.body_text())]))?;
    let (kind, limit, before) = list_params(&q)?;
    let rows = state.store.list(kind.as_deref(), before, limit).await?;
    let next = (rows.len() as i64 == limit).then(|| {
        let last = rows.last().map_or(0, |r| r.seq);
        let kind = kind.as_ref().map(|k| format!("kind={k}&")).unwrap_or_default();
        format!("/v1/jobs?{kind}limit={limit}&before={last}")
    });
    let items = rows.into_iter().map(Job::from_row).collect::<Result<_, _>>()?;
    Ok(Json(JobList { items, next }))
}

fn list_params(q: &HashMap<String, String>) -> Result<(Option<String>, i64, Option<i64>), ApiError> {
    let mut errors = Vec::new();
    for key in q.keys().filter(|k| !["kind", "limit", "before"].contains(&k.as_str())) {
        errors.push(FieldError::parameter(key, "unknown parameter (known: kind, limit, before)"));
    }
    let kind = q.get("kind").cloned();
    if let Some(k) = &kind
        && !KINDS.contains(&k.as_str())
    {
        errors.push(FieldError::parameter("kind", format!("must be one of {}", KINDS.join(", "))));
    }
    let int = |name: &str, lo: i64, hi: i64, errors: &mut Vec<FieldError>| match q.get(name).map(|v| v.parse::<i64>()) {
        None => None,
        Some(Ok(v)) if (lo..=hi).contains(&v) => Some(v),
        Some(_) => {
            errors.push(FieldError::parameter(name, format!("must be an integer from {lo} to {hi}")));
            None
        }
    };
    let limit = int("limit", 1, MAX_LIMIT, &mut errors).unwrap_or(50);
    let before = int("before", 1, i64::MAX, &mut errors);
    if errors.is_empty() { Ok((kind, limit, before)) } else { Err(ApiError::BadQuery(errors)) }
}

/// The job's tabular result as CSV: one row per sample, header with units.
#[utoipa::path(get, path = "/v1/jobs/{id}/result.csv", operation_id = "get_job_result_csv", tag = "jobs",
    params(("id" = String, Path, description = "Job id")),
    responses(
        (status = 200, description = "CSV table", body = String, content_type = "text/csv"),
        (status = 404, description = "No such job", body = Problem, content_type = "application/problem+json"),
    ))]
pub async fn csv(State(state): State<AppState>, Path(id): Path<String>) -> Result<Response, ApiError> {
    let row = state.store.get(&id).await?.ok_or_else(|| ApiError::NotFound(id.clone()))?;
    let body = to_csv(&row.kind, &row.result)?;
    let disposition = format!("attachment; filename=\"{}-{id}.csv\"", row.kind);
    Ok((
        [(header::CONTENT_TYPE, "text/csv; charset=utf-8".to_string()), (header::CONTENT_DISPOSITION, disposition)],
        body,
    )
        .into_response())
}

/// The CSV of a stored result: the table of its kind, header row with units.
fn to_csv(kind: &str, result: &str) -> Result<String, ApiError> {
    let value: serde_json::Value = serde_json::from_str(result).map_err(|e| ApiError::Internal(e.to_string()))?;
    let (header, rows) = match kind {
        "flywheel" => super::flywheel::csv_table(&value),
        "kinetostatics" => super::kinetostatics::csv_table(&value),
        "dynamics" => super::dynamics::csv_table(&value),
        _ => (Vec::new(), Vec::new()),
    };
    let mut w = csv::Writer::from_writer(Vec::new());
    let internal = |e: csv::Error| ApiError::Internal(e.to_string());
    w.write_record(&header).map_err(internal)?;
    for row in rows {
        w.write_record(&row).map_err(internal)?;
    }
    let bytes = w.into_inner().map_err(|e| ApiError::Internal(e.to_string()))?;
    String::from_utf8(bytes).map_err(|e| ApiError::Internal(e.to_string()))
}
