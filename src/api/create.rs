//! Creating a job: compute under admission control, serialise the result
//! once within the limit on a result, store those bytes and answer with them.

use super::AppState;
use super::body::{Chunks, guarded};
use super::job::job_chunks;
use crate::kind::problem::ApiError;
use crate::kind::{JobResult, JsonBuffer, json_len, too_large, write_json};
use crate::store::{JobRow, NewJob};
use axum::body::Body;
use axum::http::{StatusCode, header};
use axum::response::{IntoResponse, Response};
use bytes::Bytes;
use std::time::Instant;
use tokio::sync::OwnedSemaphorePermit;

/// Runs `compute` once a compute slot is free (off the async workers unless
/// its kind's jobs are short: [`super::admission`]), serialises its result
/// within the limit, stores the job, and answers 201 with the job and its
/// `Location`; the same bytes are stored and sent.
pub async fn create<R, F>(
    state: &AppState,
    kind: &'static str,
    request: Bytes,
    compute: F,
) -> Result<Response, ApiError>
where
    R: JobResult + Send + 'static,
    F: FnOnce() -> Result<R, ApiError> + Send + 'static,
{
    let (row, reserved) = compute_and_store(state, kind, request, Destination::POSTED, compute).await?;
    Ok(created(&row, reserved))
}

/// The 201 of a stored job: the job, its `Location`, its memory held until sent.
pub fn created(row: &JobRow, reserved: OwnedSemaphorePermit) -> Response {
    let mut body = Chunks::default();
    job_chunks(row, &mut body);
    let location = format!("/v1/jobs/{}", row.id);
    let headers = [(header::CONTENT_TYPE, "application/json".to_string()), (header::LOCATION, location)];
    (StatusCode::CREATED, headers, guarded(Body::new(body), reserved)).into_response()
}

tokio::task_local! {
    /// Whether the request being answered may store a new job: false where
    /// the service has an API token and the request does not carry it.
    pub static MAY_STORE: bool;
}

/// Whether the request being answered may store a new job (outside a
/// request — a deferred job, the command line — it may).
pub fn may_store() -> bool {
    MAY_STORE.try_with(|may| *may).unwrap_or(true)
}

/// Where a computed job goes.
#[derive(Clone, Debug)]
pub enum Destination {
    /// A new job: under `key` for a template's parameters (a stored job
    /// found again), else with the request's `?label=` ([`super::label`]).
    New { key: Option<String> },
    /// The deferred job `id` this replica claimed as `claim` ([`super::deferred`]).
    Claimed { id: String, claim: String },
    /// Nowhere: a template's values for a request that may not store a new
    /// job ([`may_store`]); the row answered is stored nowhere.
    Unstored,
}

impl Destination {
    /// A job POSTed directly.
    pub const POSTED: Self = Self::New { key: None };
}

/// The job of `compute`, stored at `to`: the row, with the memory of its
/// answer still reserved.
pub async fn compute_and_store<R, F>(
    state: &AppState,
    kind: &'static str,
    request: Bytes,
    to: Destination,
    compute: F,
) -> Result<(JobRow, OwnedSemaphorePermit), ApiError>
where
    R: JobResult + Send + 'static,
    F: FnOnce() -> Result<R, ApiError> + Send + 'static,
{
    let _slot = state.admission.slot()?;
    let computing = state.admission.compute().await?;
    let limit = state.limits.result_bytes;
    // The largest result is reserved before computing, so that no job is
    // computed only to be refused for want of memory; the spare is given back.
    let reserved = state.admission.memory(limit.saturating_add(request.len())).await?;
    // The compute slot, the memory and the watchdog's entry go with the
    // computation: a client that leaves does not free them while it runs.
    let listed = state.watchdog.start(kind);
    let run = move || {
        let start = Instant::now();
        let r = compute();
        let elapsed = start.elapsed();
        let result = r.and_then(|r| serialized(&r, limit));
        drop((computing, listed));
        (result, elapsed, reserved)
    };
    let (result, elapsed, mut reserved) = match state.admission.inline(kind) {
        Some(_inline) => run(),
        None => tokio::task::spawn_blocking(run).await.map_err(|e| ApiError::Internal(format!("engine task: {e}")))?,
    };
    state.admission.record(kind, elapsed);
    let result = result.inspect_err(|_| state.metrics.job(kind, false, elapsed))?;
    let engine_us = i64::try_from(elapsed.as_micros()).unwrap_or(i64::MAX);
    let bytes = request.len() + result.len();
    if let Some(spare) = reserved.num_permits().checked_sub(bytes).and_then(|n| reserved.split(n)) {
        drop(spare);
    }
    let stored = match to {
        Destination::New { key } => state
            .store
            .insert(new_job(kind, (request, result), engine_us, key))
            .await
            .map_err(ApiError::not_stored("the job was computed but could not be stored")),
        Destination::Unstored => Ok(new_job(kind, (request, result), engine_us, None).unstored()),
        // None: deleted, or claimed again after this replica's lease lapsed; not this replica's to store.
        Destination::Claimed { id, claim } => {
            match state.store.complete((&id, &claim), &result, engine_us, bytes as i64).await {
                Ok(Some(row)) => Ok(row),
                Ok(None) => Err(ApiError::NotFound(id)),
                Err(e) => Err(ApiError::not_stored("the job was computed but its result could not be stored")(e)),
            }
        }
    };
    state.metrics.job(kind, stored.is_ok(), elapsed);
    Ok((stored?, reserved))
}

/// A new job of `kind` (a fresh id, made now), with the request's label
/// unless it is keyed (a template's job, shared between requests).
fn new_job(kind: &str, (request, result): (Bytes, Bytes), engine_us: i64, key: Option<String>) -> NewJob {
    let label = if key.is_some() { None } else { super::label::current() };
    let (id, created_at, engine_version) = (uuid::Uuid::new_v4().to_string(), now_rfc3339(), VERSION.into());
    NewJob { id, kind: kind.into(), created_at, request, result, engine_us, engine_version, label, request_key: key }
}

/// The version of mechdyn that computes the jobs.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// The result as JSON bytes, or a 422 when it would exceed `limit` bytes.
fn serialized<R: JobResult>(result: &R, limit: usize) -> Result<Bytes, ApiError> {
    let mut out = JsonBuffer::new(limit);
    match write_json(&mut out, result) {
        Ok(()) => {
            // The buffer grew by doubling: give back the unused half before it is held in flight.
            out.buf.shrink_to_fit();
            Ok(out.buf.into())
        }
        Err(e) if e.is_io() => {
            drop(out);
            Err(too_large(json_len(result), limit, result.rows(), false))
        }
        Err(e) => Err(ApiError::Internal(format!("result: {e}"))),
    }
}

pub fn now_rfc3339() -> String {
    rfc3339(time::OffsetDateTime::now_utc())
}

/// A time as jobs store it (`created_at`): RFC 3339 in UTC with
/// microseconds, so that the text sorts as the time does.
pub fn rfc3339(t: time::OffsetDateTime) -> String {
    let format =
        time::macros::format_description!("[year]-[month]-[day]T[hour]:[minute]:[second].[subsecond digits:6]Z");
    t.to_offset(time::UtcOffset::UTC).format(&format).unwrap_or_default()
}
