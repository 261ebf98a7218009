//! Jobs: created by the POST of each calculation (`create.rs`), read back
//! by id, listed, and exported as CSV. A job is sent as the bytes stored, in
//! pieces ([`Chunks`]), with its answer's memory reserved until it is sent.

use super::AppState;
use super::body::{Chunks, guarded};
use super::job::{Job, JobList, job_chunks};
use super::kind;
use super::read::{self, READ_MEMORY_FACTOR, load};
use super::tables::{self, AngleUnit, Angles, Decimal, DecimalMark};
use crate::i18n::Msg;
use crate::kind::problem::{ApiError, FieldError, PrivateErrors, Problem, ReadErrors};
use crate::store::Filter;
use axum::body::Body;
use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::{HeaderMap, StatusCode, header};
use axum::response::{IntoResponse, Response};
use std::collections::HashMap;
use tokio::sync::OwnedSemaphorePermit;
use utoipa::IntoParams;

/// Largest page of the jobs list.
pub const MAX_LIMIT: i64 = 100;

/// A JSON answer of these chunks, holding `reserved` until it is sent.
fn json_answer(body: Chunks, reserved: OwnedSemaphorePermit) -> Response {
    ([(header::CONTENT_TYPE, "application/json")], guarded(Body::new(body), reserved)).into_response()
}

/// Reads a job.
///
/// With `Accept: text/csv` the answer is the job's main table as CSV, as
/// `result.csv` gives it (`?angles=deg` for angles in degrees).
#[utoipa::path(get, path = "/v1/jobs/{id}", operation_id = "get_job", tag = "jobs",
    params(
        ("id" = String, Path, description = "Job id"),
        ("angles" = Option<AngleUnit>, Query, description = "With `Accept: text/csv`: `rad` (default) or `deg`"),
        ("decimal" = Option<DecimalMark>, Query, description = "With `Accept: text/csv`: `point` (default) or `comma` (then `;` between the columns)"),
    ),
    responses(
        (status = 200, description = "The job (JSON), or its table with `Accept: text/csv`",
            content((Job = "application/json"), (String = "text/csv"))),
        (status = 400, description = "An invalid query parameter", body = Problem, content_type = "application/problem+json"),
        ReadErrors,
        PrivateErrors,
    ))]
pub async fn get(
    State(state): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Response, ApiError> {
    let q = read::query(q, &["angles", "decimal"])?;
    let style = (Angles::parse(q.get("angles")).map_err(|e| ApiError::BadQuery(vec![e]))?, Decimal::of(&q)?);
    if read::wants(&headers, None, "text/csv") {
        return csv_answer(&state, &id, style).await;
    }
    let (row, reserved) = load(&state, &id, READ_MEMORY_FACTOR).await?;
    let mut body = Chunks::default();
    job_chunks(&row, &mut body);
    Ok(json_answer(body, reserved))
}

/// Deletes a job.
///
/// When the service has an API token, this needs it as every POST does. The
/// job's answer kept under an `Idempotency-Key` goes with it (a retry of its
/// POST computes it again); a template's job is computed again when its
/// parameters are next asked.
#[utoipa::path(delete, path = "/v1/jobs/{id}", operation_id = "delete_job", tag = "jobs",
    params(("id" = String, Path, description = "Job id")),
    responses(
        (status = 204, description = "The job was deleted"),
        (status = 401, description = "The service has an API token and the request does not carry it",
            body = Problem, content_type = "application/problem+json"),
        (status = 404, description = "No job with this id", body = Problem, content_type = "application/problem+json"),
        (status = 503, description = "The database is unavailable: retry after `Retry-After` seconds",
            body = Problem, content_type = "application/problem+json",
            headers(("Retry-After" = u64, description = "Seconds to wait before retrying"))),
        (status = 507, description = "The service's storage is full: the job was not deleted (a deletion \
            needs room in the database's log too); retry once space returns",
            body = Problem, content_type = "application/problem+json"),
    ))]
pub async fn delete(State(state): State<AppState>, Path(id): Path<String>) -> Result<StatusCode, ApiError> {
    if state.store.delete(&id).await.map_err(ApiError::not_stored("the job was not deleted"))? {
        state.metrics.deleted("request", 1);
        Ok(StatusCode::NO_CONTENT)
    } else {
        Err(ApiError::NotFound(id))
    }
}

/// Query of the jobs list.
#[derive(IntoParams)]
#[into_params(parameter_in = Query)]
#[allow(dead_code)]
pub struct ListParams {
    /// Only jobs of this kind (the document lists them).
    kind: Option<String>,
    /// Only jobs stored with this label (`?label=` on their POST; no control characters or bidirectional overrides).
    #[param(
        min_length = 1,
        max_length = 200,
        pattern = r"^[^\u0000-\u001F\u007F-\u009F\u061C\u200E\u200F\u202A-\u202E\u2066-\u2069]+$"
    )]
    label: Option<String>,
    /// Page size, 1 to 100 (default 50).
    #[param(minimum = 1, maximum = 100)]
    limit: Option<i64>,
    /// Opaque cursor from `next`.
    #[param(minimum = 1)]
    before: Option<i64>,
}

/// Lists jobs, newest first, a page at a time.
///
/// A page is shorter than `limit` when its jobs together would exceed the
/// limit on a result; `next` then goes on from there.
#[utoipa::path(get, path = "/v1/jobs", operation_id = "list_jobs", tag = "jobs", params(ListParams),
    responses(
        (status = 200, description = "A page of jobs", body = JobList),
        (status = 400, description = "Invalid query parameters", body = Problem, content_type = "application/problem+json",
            example = json!({"type": "/problems/invalid-query", "title": "Invalid query parameters", "status": 400,
                "detail": "invalid query parameters", "errors": [{"parameter": "limit", "message": "must be an integer from 1 to 100"}]})),
        (status = 503, description = "Too many large answers are being sent, or the database is unavailable: retry after `Retry-After` seconds",
            body = Problem, content_type = "application/problem+json",
            headers(("Retry-After" = u64, description = "Seconds to wait before retrying"))),
        PrivateErrors,
    ))]
pub async fn list(
    State(state): State<AppState>,
    query: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Response, ApiError> {
    let Query(q) = query.map_err(|e| ApiError::BadQuery(vec![FieldError::parameter("", e.body_text())]))?;
    let (kind, limit, before) = list_params(&state.kinds, &q)?;
    let label = q.get("label").cloned().map(super::label::checked).transpose()?;
    let filter = Filter { kind: kind.as_deref(), label: label.as_deref() };
    // The page's sizes first: its memory is what it holds, reserved before
    // its jobs are loaded (a list reserved 48 MiB for its whole run).
    let plan = state.store.list_plan(&filter, before, limit, state.limits.result_bytes).await?;
    let reserved = state.admission.memory(READ_MEMORY_FACTOR * plan.bytes.max(1)).await?;
    let (rows, cut) = (state.store.list_rows(&filter, &plan).await?, plan.cut);
    let next = (rows.len() as i64 == limit || cut).then(|| {
        let last = rows.last().map_or(0, |r| r.seq);
        let (limit, last) = (limit.to_string(), last.to_string());
        let query =
            [("kind", kind.as_deref()), ("label", label.as_deref()), ("limit", Some(&limit)), ("before", Some(&last))];
        let query: Vec<(&str, &str)> = query.into_iter().filter_map(|(k, v)| Some((k, v?))).collect();
        format!("/v1/jobs?{}", serde_urlencoded::to_string(query).unwrap_or_default())
    });
    let mut body = Chunks::default();
    body.push(&b"{\"items\":["[..]);
    for (i, row) in rows.iter().enumerate() {
        if i > 0 {
            body.push(&b","[..]);
        }
        job_chunks(row, &mut body);
    }
    body.push(format!("],\"next\":{}}}", serde_json::to_string(&next).unwrap_or_else(|_| "null".into())));
    Ok(json_answer(body, reserved))
}

fn list_params(
    kinds: &kind::Registry,
    q: &HashMap<String, String>,
) -> Result<(Option<String>, i64, Option<i64>), ApiError> {
    let mut errors = Vec::new();
    for key in q.keys().filter(|k| !["kind", "label", "limit", "before"].contains(&k.as_str())) {
        errors.push(FieldError::parameter_said(
            key,
            Msg::new("query-unknown").arg("known", "kind, label, limit, before"),
        ));
    }
    let kind = q.get("kind").cloned();
    if let Some(k) = &kind
        && kinds.find(k).is_none()
    {
        errors
            .push(FieldError::parameter_said("kind", Msg::new("field-one-of").arg("known", kinds.names().join(", "))));
    }
    let int = |name: &str, lo: i64, hi: i64, errors: &mut Vec<FieldError>| match q.get(name).map(|v| v.parse::<i64>()) {
        None => None,
        Some(Ok(v)) if (lo..=hi).contains(&v) => Some(v),
        Some(_) => {
            let range = Msg::new("field-integer-between").arg("min", lo).arg("max", hi);
            errors.push(FieldError::parameter_said(name, range));
            None
        }
    };
    let limit = int("limit", 1, MAX_LIMIT, &mut errors).unwrap_or(50);
    let before = int("before", 1, i64::MAX, &mut errors);
    if errors.is_empty() { Ok((kind, limit, before)) } else { Err(ApiError::BadQuery(errors)) }
}

/// The job's tabular result as CSV: one row per sample, header with units.
///
/// A kind without a table (or a job asked for none, e.g. `samples: 0`)
/// answers its values instead, `pointer,value,unit`: never an empty body.
#[utoipa::path(get, path = "/v1/jobs/{id}/result.csv", operation_id = "get_job_result_csv", tag = "jobs",
    params(
        ("id" = String, Path, description = "Job id"),
        ("angles" = Option<AngleUnit>, Query, description = "`rad` (default) or `deg`: angle columns in degrees, their header saying so"),
        ("decimal" = Option<DecimalMark>, Query, description = "`point` (default) or `comma`: numbers with a decimal comma, the columns separated by `;`"),
    ),
    responses(
        (status = 200, description = "CSV table", body = String, content_type = "text/csv"),
        (status = 400, description = "An invalid query parameter", body = Problem, content_type = "application/problem+json"),
        ReadErrors,
        PrivateErrors,
    ))]
pub async fn csv(
    State(state): State<AppState>,
    Path(id): Path<String>,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Response, ApiError> {
    let q = read::query(q, &["angles", "decimal"])?;
    let style = (Angles::parse(q.get("angles")).map_err(|e| ApiError::BadQuery(vec![e]))?, Decimal::of(&q)?);
    csv_answer(&state, &id, style).await
}

/// The CSV of a stored job ([`tables::result_csv`]), converted off the async workers.
async fn csv_answer(state: &AppState, id: &str, style: (Angles, Decimal)) -> Result<Response, ApiError> {
    let (row, result, reserved) = read::result_tree(state, id).await?;
    let kind = state.kinds.find(&row.kind);
    let body = tokio::task::spawn_blocking(move || tables::result_csv(kind, &result, style))
        .await
        .map_err(|e| ApiError::Internal(format!("csv task: {e}")))??;
    let disposition = format!("attachment; filename=\"{}-{id}.csv\"", row.kind);
    Ok((
        [(header::CONTENT_TYPE, "text/csv; charset=utf-8".to_string()), (header::CONTENT_DISPOSITION, disposition)],
        guarded(Body::from(body), reserved),
    )
        .into_response())
}
