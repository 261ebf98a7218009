//! `GET /metrics`: the service's counters in Prometheus's text format
//! (version 0.0.4, the `prometheus` crate's encoder), one registry per
//! service so that nothing is global.
//!
//! - `mechdyn_http_requests_total{method, route, status}` and
//!   `mechdyn_http_request_duration_seconds{method, route}`: every request,
//!   by its route's template (`/v1/jobs/{id}`, never the id itself, so the
//!   series stay few; `unmatched` for a path no route has);
//! - `mechdyn_jobs_total{kind, status}`: every job that reached a compute
//!   slot, `done` (computed and stored) or `failed` (an invalid request,
//!   refused by the engine, over its budget, or not stored);
//! - `mechdyn_jobs_deleted_total{reason}`: by a `DELETE` (`request`) or by
//!   the retention (`age`, `count`);
//! - `mechdyn_engine_seconds{kind}`: the engine's time per job;
//! - `mechdyn_jobs_computing`, `mechdyn_queue_depth`: this replica's jobs
//!   computing now, and its POSTs not computing yet (their body arriving,
//!   or waiting for a compute slot), read at the scrape;
//! - `mechdyn_jobs_overrun_total{kind}`, `mechdyn_jobs_overrunning`: jobs
//!   that computed well past their compute budget (an escape from it, a
//!   bug: [`super::watchdog`]), and how many are past it now;
//! - `mechdyn_workers_stopped_total{reason}`: worker processes stopped with
//!   their job: killed at its `budget`, out of its `memory`, or ended by a
//!   `crash` ([`super::workers`]);
//! - `mechdyn_connections{listener}`, `mechdyn_connections_refused_total{listener}`,
//!   `mechdyn_connections_closed_total{listener, reason}`: connections open
//!   now, those answered 503 at the cap, those closed by a bound (`header`,
//!   `idle`), on the service's listener and the operator's ([`super::serve`]);
//! - `mechdyn_deferred_jobs{status}`: jobs POSTed with `Prefer:
//!   respond-async` `queued` or `running`, over every replica (the
//!   database's count at the scrape).

use super::AppState;
use super::admission::Admission;
use super::workers::{Pool, Stop};
use crate::store::Waiting;
use axum::extract::{MatchedPath, Request, State};
use axum::http::{StatusCode, header};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use prometheus::{
    HistogramOpts, HistogramVec, IntCounterVec, IntGauge, IntGaugeVec, Opts, Registry, TextEncoder, exponential_buckets,
};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// The service's metrics, shared by its handlers.
#[derive(Clone)]
pub struct Metrics(Arc<Inner>);

struct Inner {
    registry: Registry,
    requests: IntCounterVec,
    request_seconds: HistogramVec,
    jobs: IntCounterVec,
    deleted: IntCounterVec,
    engine_seconds: HistogramVec,
    computing: IntGauge,
    queue_depth: IntGauge,
    deferred: IntGaugeVec,
    overrun: IntCounterVec,
    overrunning: IntGauge,
    stopped: IntCounterVec,
    connections: IntGaugeVec,
    refused: IntCounterVec,
    closed: IntCounterVec,
}

impl Default for Metrics {
    fn default() -> Self {
        Self::new().expect("the metrics' names and labels are fixed and valid")
    }
}

impl Metrics {
    fn new() -> prometheus::Result<Self> {
        let registry = Registry::new();
        let requests = IntCounterVec::new(
            Opts::new("mechdyn_http_requests_total", "HTTP requests answered, by route template and status"),
            &["method", "route", "status"],
        )?;
        // 100 µs to ~50 s: a stored job's read to a long dynamics job.
        let seconds = || exponential_buckets(1e-4, 2.0, 20);
        let request_seconds = HistogramVec::new(
            HistogramOpts::new("mechdyn_http_request_duration_seconds", "Time to answer a request, until its head")
                .buckets(seconds()?),
            &["method", "route"],
        )?;
        let jobs = IntCounterVec::new(
            Opts::new(
                "mechdyn_jobs_total",
                "Jobs by outcome: done (computed and stored) or failed (invalid, refused by the engine, over its budget, not stored)",
            ),
            &["kind", "status"],
        )?;
        let deleted = IntCounterVec::new(
            Opts::new("mechdyn_jobs_deleted_total", "Jobs deleted: by a request, or by the retention's age or count"),
            &["reason"],
        )?;
        // 10 µs (a gear's geometry) to ~80 s (past the largest compute budget's default).
        let engine_seconds = HistogramVec::new(
            HistogramOpts::new("mechdyn_engine_seconds", "The engine's time per job")
                .buckets(exponential_buckets(1e-5, 2.0, 24)?),
            &["kind"],
        )?;
        let computing = IntGauge::new("mechdyn_jobs_computing", "Jobs computing now on this replica")?;
        let queue_depth = IntGauge::new(
            "mechdyn_queue_depth",
            "POSTs on this replica not computing yet: their body arriving, or waiting for a compute slot",
        )?;
        registry.register(Box::new(requests.clone()))?;
        registry.register(Box::new(request_seconds.clone()))?;
        registry.register(Box::new(jobs.clone()))?;
        registry.register(Box::new(deleted.clone()))?;
        registry.register(Box::new(engine_seconds.clone()))?;
        let deferred = IntGaugeVec::new(
            Opts::new(
                "mechdyn_deferred_jobs",
                "Jobs POSTed with Prefer: respond-async not ended, in the database (every replica's)",
            ),
            &["status"],
        )?;
        registry.register(Box::new(deferred.clone()))?;
        registry.register(Box::new(computing.clone()))?;
        registry.register(Box::new(queue_depth.clone()))?;
        let overrun = IntCounterVec::new(
            Opts::new(
                "mechdyn_jobs_overrun_total",
                "Jobs that computed past twice their compute budget and 5 s more: escapes from the budget (a bug)",
            ),
            &["kind"],
        )?;
        let overrunning = IntGauge::new("mechdyn_jobs_overrunning", "Jobs computing past their budget's margin now")?;
        registry.register(Box::new(overrun.clone()))?;
        registry.register(Box::new(overrunning.clone()))?;
        let stopped = IntCounterVec::new(
            Opts::new(
                "mechdyn_workers_stopped_total",
                "Worker processes stopped with their job: killed at its budget, out of its memory, or crashed",
            ),
            &["reason"],
        )?;
        registry.register(Box::new(stopped.clone()))?;
        for stop in Stop::ALL {
            stopped.with_label_values(&[stop.as_str()]);
        }
        let connections = IntGaugeVec::new(
            Opts::new("mechdyn_connections", "Connections open now, on the service's listener or the operator's"),
            &["listener"],
        )?;
        let refused = IntCounterVec::new(
            Opts::new(
                "mechdyn_connections_refused_total",
                "Connections answered 503 at once because the listener held its most connections",
            ),
            &["listener"],
        )?;
        let closed = IntCounterVec::new(
            Opts::new(
                "mechdyn_connections_closed_total",
                "Connections closed by their bounds: a request head not whole in time (header), idle too long (idle)",
            ),
            &["listener", "reason"],
        )?;
        registry.register(Box::new(connections.clone()))?;
        registry.register(Box::new(refused.clone()))?;
        registry.register(Box::new(closed.clone()))?;
        Ok(Self(Arc::new(Inner {
            registry,
            requests,
            request_seconds,
            jobs,
            deleted,
            engine_seconds,
            computing,
            queue_depth,
            deferred,
            overrun,
            overrunning,
            stopped,
            connections,
            refused,
            closed,
        })))
    }

    /// A job of `kind` whose computation took `elapsed`: done or failed.
    pub fn job(&self, kind: &str, done: bool, elapsed: Duration) {
        let status = if done { "done" } else { "failed" };
        self.0.jobs.with_label_values(&[kind, status]).inc();
        self.0.engine_seconds.with_label_values(&[kind]).observe(elapsed.as_secs_f64());
    }

    /// A job of `kind` found computing past its budget's margin.
    pub fn overrun(&self, kind: &str) {
        self.0.overrun.with_label_values(&[kind]).inc();
    }

    /// Every kind's overrun count shown from the start, at 0.
    pub fn kinds<'a>(&self, names: impl Iterator<Item = &'a str>) {
        names.for_each(|kind| drop(self.0.overrun.with_label_values(&[kind])));
    }

    /// How many jobs compute past their budget's margin now.
    pub fn overrunning(&self, n: usize) {
        self.0.overrunning.set(i64::try_from(n).unwrap_or(i64::MAX));
    }

    /// A listener's series shown from its start, at 0.
    pub fn listener(&self, listener: &str) {
        self.0.connections.with_label_values(&[listener]).set(0);
        self.0.refused.with_label_values(&[listener]);
        for reason in ["header", "idle"] {
            self.0.closed.with_label_values(&[listener, reason]);
        }
    }

    /// Connections of `listener` opened (+1) or closed (−1).
    pub fn connections(&self, listener: &str, change: i64) {
        self.0.connections.with_label_values(&[listener]).add(change);
    }

    /// A connection of `listener` answered 503 at the cap.
    pub fn connection_refused(&self, listener: &str) {
        self.0.refused.with_label_values(&[listener]).inc();
    }

    /// A connection of `listener` closed by a bound (`header`, `idle`).
    pub fn connection_closed(&self, listener: &str, reason: &str) {
        self.0.closed.with_label_values(&[listener, reason]).inc();
    }

    /// `n` jobs deleted, for `reason` (`request`, `age`, `count`).
    pub fn deleted(&self, reason: &str, n: u64) {
        self.0.deleted.with_label_values(&[reason]).inc_by(n);
    }

    /// A request answered with `status` after `elapsed`.
    fn request(&self, method: &str, route: &str, status: StatusCode, elapsed: Duration) {
        self.0.requests.with_label_values(&[method, route, status.as_str()]).inc();
        self.0.request_seconds.with_label_values(&[method, route]).observe(elapsed.as_secs_f64());
    }

    /// Every metric in the text format, the gauges read from `admission`
    /// and `waiting` (None: the database did not answer, the last values stay) now.
    fn text(
        &self,
        admission: &Admission,
        waiting: Option<Waiting>,
        workers: Option<&Pool>,
    ) -> Result<String, prometheus::Error> {
        for stop in Stop::ALL {
            let counter = self.0.stopped.with_label_values(&[stop.as_str()]);
            let now = workers.map_or(0, |w| w.stopped(stop));
            counter.inc_by(now.saturating_sub(counter.get()));
        }
        if let Some(w) = waiting {
            self.0.deferred.with_label_values(&["queued"]).set(w.queued);
            self.0.deferred.with_label_values(&["running"]).set(w.running);
        }
        let (computing, in_flight) = (admission.computing(), admission.in_flight());
        self.0.computing.set(i64::try_from(computing).unwrap_or(i64::MAX));
        self.0.queue_depth.set(i64::try_from(in_flight.saturating_sub(computing)).unwrap_or(i64::MAX));
        let mut text = String::new();
        TextEncoder::new().encode_utf8(&self.0.registry.gather(), &mut text)?;
        Ok(text)
    }
}

/// Middleware: counts and times every request by its route's template.
pub async fn track(metrics: Metrics, req: Request, next: Next) -> Response {
    // Both shared, not copied: a matched path is an `Arc<str>`, a method's name static.
    let route = req.extensions().get::<MatchedPath>().cloned();
    let method = req.method().clone();
    let start = Instant::now();
    let response = next.run(req).await;
    let route = route.as_ref().map_or("unmatched", MatchedPath::as_str);
    metrics.request(method.as_str(), route, response.status(), start.elapsed());
    response
}

/// The service's metrics, in Prometheus's text format.
#[utoipa::path(get, path = "/metrics", tag = "service",
    responses((status = 200, description = "Prometheus's text format (version 0.0.4): HTTP requests by route and \
status, jobs by kind and status, the engine's time per job, jobs computing and waiting", body = String,
        content_type = "text/plain; version=0.0.4")))]
pub async fn metrics(State(state): State<AppState>) -> Response {
    let waiting = tokio::time::timeout(Duration::from_secs(1), state.store.waiting()).await.ok().and_then(Result::ok);
    match state.metrics.text(&state.admission, waiting, state.workers.as_ref()) {
        Ok(text) => ([(header::CONTENT_TYPE, prometheus::TEXT_FORMAT)], text).into_response(),
        Err(e) => crate::kind::problem::ApiError::Internal(format!("metrics: {e}")).into_response(),
    }
}
