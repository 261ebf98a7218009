//! Creating a job: compute under admission control, serialise the result
//! once within the limit on a result, store those bytes and answer with them.

use super::AppState;
use super::body::{Chunks, guarded};
use super::job::job_chunks;
use super::workers::Share;
use crate::kind::problem::ApiError;
use crate::kind::{JobResult, Limits, serialized};
use crate::store::{JobRow, NewJob};
use axum::body::Body;
use axum::http::{StatusCode, header};
use axum::response::{IntoResponse, Response};
use bytes::Bytes;
use std::time::Instant;
use tokio::sync::OwnedSemaphorePermit;

/// Computes `work` once a compute slot is free ([`compute_and_store`]),
/// stores the job, and answers 201 with the job and its `Location`; the
/// same bytes are stored and sent.
pub async fn create<R, F>(state: &AppState, work: Work<F>, request: Bytes) -> Result<Response, ApiError>
where
    R: JobResult + Send + 'static,
    F: FnOnce(&Limits) -> Result<R, ApiError> + Send + 'static,
{
    let (row, reserved) = compute_and_store(state, work, request, Destination::POSTED).await?;
    Ok(created(&row, reserved))
}

/// What a job computes: a kind's request, which a worker process computes
/// from the request's bytes alone ([`super::workers`]), or work of the
/// service's own (a check's grading of a stored result); and `here`, the
/// same computed on this process's threads within the limits it is given
/// (a service computing in-process, or the service's own work).
pub struct Work<F> {
    kind: &'static str,
    by_worker: bool,
    here: F,
}

impl<F> Work<F> {
    /// The job of a request of the kind `kind`.
    pub fn kind(kind: &'static str, here: F) -> Self {
        Self { kind, by_worker: true, here }
    }

    /// Work of the service's own, stored as a job of `kind`.
    pub fn own(kind: &'static str, here: F) -> Self {
        Self { kind, by_worker: false, here }
    }
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

/// The job of `work`, stored at `to`: the row, with the memory of its
/// answer still reserved. A request without the token, of a service that
/// has one, computes in the share of its own ([`Share::Anonymous`]).
pub async fn compute_and_store<R, F>(
    state: &AppState,
    work: Work<F>,
    request: Bytes,
    to: Destination,
) -> Result<(JobRow, OwnedSemaphorePermit), ApiError>
where
    R: JobResult + Send + 'static,
    F: FnOnce(&Limits) -> Result<R, ApiError> + Send + 'static,
{
    let (kind, share) = (work.kind, if may_store() { Share::Holder } else { Share::Anonymous });
    let (_slot, computing) = match share {
        Share::Holder => (state.admission.slot()?, state.admission.compute().await?),
        Share::Anonymous => (None, state.admission.anonymous().await?),
    };
    let limits = state.admission.limits(share, &state.limits);
    // The largest result is reserved before computing, so that no job is
    // computed only to be refused for want of memory; the spare is given back.
    let reserved = state.admission.memory(limits.result_bytes.saturating_add(request.len())).await?;
    // The compute slot, the memory and the watchdog's entry go with the
    // computation: a client that leaves does not free them while it runs.
    let listed = state.watchdog.start(kind);
    let held = (computing, listed, reserved);
    let (result, elapsed, mut reserved) = match (&state.workers, work.by_worker) {
        (Some(pool), true) => {
            let (pool, sent) = (pool.clone(), request.clone());
            let by_worker = move || {
                let start = Instant::now();
                match pool.run(kind, &sent, &limits, share) {
                    Ok((result, elapsed)) => (Ok(result), elapsed),
                    Err(e) => (Err(e), start.elapsed()),
                }
            };
            computed(state, kind, held, by_worker).await?
        }
        _ => {
            let compute = work.here;
            let here = move || {
                let start = Instant::now();
                let r = compute(&limits);
                let elapsed = start.elapsed();
                (r.and_then(|r| serialized(&r, limits.result_bytes)), elapsed)
            };
            computed(state, kind, held, here).await?
        }
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

/// What a computation holds while it runs: its compute slot, its entry in
/// the watchdog's list and its answer's memory.
type Held = (OwnedSemaphorePermit, super::watchdog::Computing, OwnedSemaphorePermit);

/// What a computation gives: its result's JSON or its error, its compute
/// time, and its answer's memory, still reserved.
type Computed = (Result<Bytes, ApiError>, std::time::Duration, OwnedSemaphorePermit);

/// `compute` run — on a worker process, or on this process's own threads —
/// from a thread that waits for it: the async worker that read the request
/// where its kind's jobs are short ([`super::admission`]), else the blocking
/// pool, where a client that leaves stops nothing. What it holds is let go
/// when it ends.
async fn computed<F>(state: &AppState, kind: &'static str, held: Held, compute: F) -> Result<Computed, ApiError>
where
    F: FnOnce() -> (Result<Bytes, ApiError>, std::time::Duration) + Send + 'static,
{
    let run = move || {
        let (result, elapsed) = compute();
        let (computing, listed, reserved) = held;
        drop((computing, listed));
        (result, elapsed, reserved)
    };
    match state.admission.inline(kind) {
        Some(_inline) => Ok(run()),
        None => tokio::task::spawn_blocking(run).await.map_err(|e| ApiError::Internal(format!("engine task: {e}"))),
    }
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
