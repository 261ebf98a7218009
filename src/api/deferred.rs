//! Jobs deferred by `Prefer: respond-async` (RFC 7240): the POST stores the
//! job `queued` and answers `202` with its `Location` at once; a runner on
//! every replica claims the oldest waiting job (any replica may run a
//! queued job), computes it as the POST would have ([`AnyKind::job`] at
//! [`Destination::Claimed`]), and stores it `done`, or `failed` with the
//! problem the POST would have answered.
//!
//! - A replica runs at most `workers` deferred jobs at once; each computes
//!   under admission control as a POST does (a compute slot, its answer's
//!   memory), so deferred and immediate jobs share the cores.
//! - A claim is a lease renewed while the job computes; a replica that
//!   stops releases its claims (the jobs go back to the queue), and one
//!   killed lets them lapse: after the lease any replica claims them again.
//!   A job claimed [`ATTEMPTS`] times without ending fails as interrupted.
//!   Leases are times of the claiming replica's clock compared with another
//!   replica's: their clocks must agree to well within a lease (30 s by
//!   default; NTP keeps them within milliseconds).
//! - A job the replica cannot compute or store for now (saturated, the
//!   database away or full) goes back to the queue, not to `failed`.
//! - At most `max_queued` jobs wait; beyond them a POST is answered 503.

use super::AppState;
use super::body::Chunks;
use super::create::{Destination, now_rfc3339, rfc3339};
use super::job::job_chunks;
use crate::kind::problem::{ApiError, FieldError};
use crate::store::{Claimed, Queued};
use axum::body::Body;
use axum::http::{HeaderMap, HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};
use bytes::Bytes;
use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};
use time::OffsetDateTime;
use tokio::sync::{Notify, Semaphore, watch};

/// Claims of one job before it fails as interrupted.
pub const ATTEMPTS: i64 = 3;
/// How long an idle runner waits before it looks for jobs that another
/// replica queued (its own wake it at once).
const POLL: Duration = Duration::from_millis(500);

/// How deferred jobs are run.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// Deferred jobs this replica computes at once (0: it computes none, and
    /// only queues them for the other replicas).
    pub workers: usize,
    /// Deferred jobs waiting at most, over every replica.
    pub max_queued: i64,
    /// How long a claim lasts without being renewed.
    pub lease: Duration,
}

impl Default for Settings {
    fn default() -> Self {
        let cores = std::thread::available_parallelism().map_or(2, |n| n.get());
        Self { workers: cores, max_queued: 1000, lease: Duration::from_secs(30) }
    }
}

/// The deferred jobs' side of the service's state.
#[derive(Clone, Default)]
pub struct Deferred {
    pub settings: Settings,
    /// Wakes this replica's runner when a job is queued here.
    queued: Arc<Notify>,
}

impl Deferred {
    pub fn new(settings: Settings) -> Self {
        Self { settings, queued: Arc::default() }
    }
}

/// Whether the request asks for `respond-async` (`Prefer`, any of its
/// comma-separated preferences, in any case).
pub fn wanted(headers: &HeaderMap) -> bool {
    let preferences = headers.get_all("prefer").into_iter().filter_map(|v| v.to_str().ok());
    preferences
        .flat_map(|v| v.split(','))
        .any(|p| p.split(';').next().unwrap_or("").trim().eq_ignore_ascii_case("respond-async"))
}

/// The `202` of a deferred job: stored `queued` (its request as sent, its
/// `?label=`), then this replica's runner woken. Unknown fields are refused
/// at once (422); everything else the engine checks becomes the failed
/// job's problem.
pub async fn accept(
    state: &AppState,
    kind: &'static str,
    raw: Bytes,
    unknown: Vec<FieldError>,
) -> Result<Response, ApiError> {
    if !unknown.is_empty() {
        return Err(ApiError::Invalid(unknown));
    }
    let waiting = state.store.waiting().await?.queued;
    if waiting >= state.deferred.settings.max_queued {
        return Err(state
            .admission
            .saturated_because(crate::i18n::Msg::new("saturated-deferred").arg("waiting", waiting)));
    }
    let job = Queued {
        id: uuid::Uuid::new_v4().to_string(),
        kind: kind.into(),
        created_at: now_rfc3339(),
        request: raw,
        label: super::label::current(),
        engine_version: super::create::VERSION.into(),
    };
    let row = state.store.enqueue(job).await.map_err(ApiError::not_stored("the job was not queued"))?;
    state.deferred.queued.notify_one();
    let mut body = Chunks::default();
    job_chunks(&row, &mut body);
    let headers = [
        (header::CONTENT_TYPE, HeaderValue::from_static("application/json")),
        (
            header::LOCATION,
            HeaderValue::try_from(format!("/v1/jobs/{}", row.id)).map_err(|e| ApiError::Internal(e.to_string()))?,
        ),
        (header::HeaderName::from_static("preference-applied"), HeaderValue::from_static("respond-async")),
    ];
    Ok((StatusCode::ACCEPTED, headers, Body::new(body)).into_response())
}

/// This replica's runner: stopped (its claims released) by [`Runner::stop`].
pub struct Runner {
    stop: watch::Sender<bool>,
    task: tokio::task::JoinHandle<()>,
}

/// The claims of the jobs this replica is computing: job id → claim.
type Claims = Arc<Mutex<HashMap<String, String>>>;

/// Starts this replica's runner (none where it computes no deferred job).
pub fn spawn(state: AppState) -> Option<Runner> {
    if state.deferred.settings.workers == 0 {
        return None;
    }
    let (stop, stopped) = watch::channel(false);
    Some(Runner { stop, task: tokio::spawn(run(state, stopped)) })
}

impl Runner {
    /// Stops claiming jobs and puts the jobs this replica is computing back
    /// in the queue, for another replica (or this one, restarted).
    pub async fn stop(self) {
        let _ = self.stop.send(true);
        let _ = self.task.await;
    }
}

async fn run(state: AppState, mut stopped: watch::Receiver<bool>) {
    let slots = Arc::new(Semaphore::new(state.deferred.settings.workers));
    let claims = Claims::default();
    let interrupted = serde_json::to_string(&ApiError::Interrupted(ATTEMPTS).problem()).unwrap_or_default();
    loop {
        let slot = tokio::select! {
            slot = slots.clone().acquire_owned() => slot,
            _ = stopped.changed() => break,
        };
        let Ok(slot) = slot else { break };
        let claim = uuid::Uuid::new_v4().to_string();
        match claim_one(&state, &claim, &interrupted).await {
            Ok(Some(job)) => {
                claims.lock().unwrap_or_else(|e| e.into_inner()).insert(job.id.clone(), claim.clone());
                let (state, claims) = (state.clone(), claims.clone());
                tokio::spawn(async move {
                    let id = job.id.clone();
                    compute(&state, job, claim).await;
                    claims.lock().unwrap_or_else(|e| e.into_inner()).remove(&id);
                    drop(slot);
                });
            }
            Ok(None) => {
                drop(slot);
                tokio::select! {
                    () = state.deferred.queued.notified() => {},
                    () = tokio::time::sleep(POLL) => {},
                    _ = stopped.changed() => break,
                }
            }
            Err(e) => {
                drop(slot);
                tracing::warn!(error = %e, "deferred jobs: cannot claim; trying again");
                tokio::time::sleep(POLL).await;
            }
        }
    }
    let held: Vec<(String, String)> = claims.lock().unwrap_or_else(|e| e.into_inner()).drain().collect();
    for (id, claim) in held {
        match state.store.release((&id, &claim)).await {
            Ok(_) => tracing::info!(job = %id, "deferred job put back in the queue: this replica is stopping"),
            Err(e) => tracing::warn!(job = %id, error = %e, "deferred job not released; its claim will lapse"),
        }
    }
}

/// The oldest waiting job, claimed as `claim` for a lease.
/// (`interrupted`: the problem of a job given up after [`ATTEMPTS`] claims.)
async fn claim_one(
    state: &AppState,
    claim: &str,
    interrupted: &str,
) -> Result<Option<Claimed>, crate::store::StoreError> {
    let now = OffsetDateTime::now_utc();
    let until = rfc3339(now + state.deferred.settings.lease);
    state.store.claim(&rfc3339(now), &until, claim, ATTEMPTS, interrupted).await
}

/// Computes a claimed job and stores how it ended, its lease renewed meanwhile.
async fn compute(state: &AppState, job: Claimed, claim: String) {
    let Claimed { id, kind, request, .. } = job;
    let renewing = tokio::spawn(renew(state.clone(), id.clone(), claim.clone()));
    let started = Instant::now();
    let outcome = match state.kinds.find(&kind) {
        Some(k) => {
            k.job(state, request, Destination::Claimed { id: id.clone(), claim: claim.clone() }).await.map(|_| ())
        }
        None => Err(ApiError::Internal(format!("a job of kind '{kind}', which this version does not know"))),
    };
    renewing.abort();
    let ended = match outcome {
        Ok(()) | Err(ApiError::NotFound(_)) => return,
        Err(e @ (ApiError::Saturated { .. } | ApiError::Unavailable(_) | ApiError::StorageFull(_))) => {
            tracing::warn!(job = %id, error = %e, "deferred job put back in the queue");
            tokio::time::sleep(POLL).await;
            state.store.release((&id, &claim)).await.map(|_| ())
        }
        Err(e) => {
            let problem = serde_json::to_string(&e.problem()).unwrap_or_default();
            let engine_us = i64::try_from(started.elapsed().as_micros()).unwrap_or(i64::MAX);
            state.store.fail((&id, &claim), &problem, engine_us).await.map(|_| ())
        }
    };
    if let Err(e) = ended {
        tracing::warn!(job = %id, error = %e, "deferred job's end not stored; its claim will lapse");
    }
}

/// Renews the claim every third of the lease, until it is lost or aborted.
async fn renew(state: AppState, id: String, claim: String) {
    let lease = state.deferred.settings.lease;
    loop {
        tokio::time::sleep(lease / 3).await;
        match state.store.renew(&id, &claim, &rfc3339(OffsetDateTime::now_utc() + lease)).await {
            Ok(true) => {}
            Ok(false) => return,
            Err(e) => tracing::warn!(job = %id, error = %e, "deferred job's claim not renewed"),
        }
    }
}
