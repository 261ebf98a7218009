//! The operator's endpoints: liveness (`/healthz`: the process answers),
//! readiness (`/readyz`: the service can serve: its database answers, and
//! its writes commit).
//!
//! A container orchestrator restarts a replica whose liveness fails and
//! stops sending it traffic while its readiness fails: a database that is
//! down for a while makes every replica unready, not restarted.

use super::AppState;
use axum::Json;
use axum::extract::State;
use axum::http::StatusCode;
use serde::Serialize;
use std::time::Duration;
use utoipa::ToSchema;

#[derive(Serialize, ToSchema)]
pub struct Health {
    #[schema(example = "ok")]
    pub status: &'static str,
    pub version: &'static str,
}

/// Liveness: the process is up and answering.
///
/// It checks nothing else (the database has `/readyz`), so a replica is not
/// restarted for a fault outside it.
#[utoipa::path(get, path = "/healthz", tag = "service",
    responses((status = 200, description = "The service is up", body = Health)))]
pub async fn healthz() -> Json<Health> {
    Json(Health { status: "ok", version: env!("CARGO_PKG_VERSION") })
}

/// Whether the service can serve, and what it checked.
#[derive(Serialize, ToSchema)]
pub struct Readiness {
    /// `ready` or `not ready`.
    #[schema(example = "ready")]
    pub status: &'static str,
    /// The database, as its URL's scheme names it (`sqlite`, `postgres`).
    #[schema(example = "sqlite")]
    pub database: &'static str,
    /// Why the service cannot serve; absent when it can.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = "the database does not answer: pool timed out while waiting for an open connection")]
    pub reason: Option<String>,
    pub version: &'static str,
}

/// How long readiness waits for the database: a probe's own timeout is
/// often 1 s (Kubernetes' default), and a query waits up to 5 s for a
/// connection while the database is away.
const CHECK_WAIT: Duration = Duration::from_secs(1);

/// Readiness: 200 when the service can serve (its database answers within 1 s
/// and the last write committed, or a write of its size does now), 503 otherwise.
#[utoipa::path(get, path = "/readyz", tag = "service",
    responses(
        (status = 200, description = "The service can serve", body = Readiness),
        (status = 503, description = "The service cannot serve (its database does not answer, or cannot store jobs: \
            its storage is full); `reason` says why",
            body = Readiness),
    ))]
pub async fn readyz(State(state): State<AppState>) -> (StatusCode, Json<Readiness>) {
    let (version, database) = (env!("CARGO_PKG_VERSION"), state.store.backend().name());
    let check = async {
        state.store.check().await.map_err(|e| format!("the database does not answer: {e}"))?;
        state.store.writable().await.map_err(|e| format!("the database cannot store jobs: {e}"))
    };
    let checked = match tokio::time::timeout(CHECK_WAIT, check).await {
        Ok(answer) => answer,
        Err(_) => Err(format!(
            "the database does not answer: no answer within {} s (to a query, or to a write while writes were failing)",
            CHECK_WAIT.as_secs()
        )),
    };
    match checked {
        Ok(()) => (StatusCode::OK, Json(Readiness { status: "ready", database, reason: None, version })),
        Err(e) => {
            tracing::warn!(error = %e, "not ready");
            let reason = Some(e);
            (StatusCode::SERVICE_UNAVAILABLE, Json(Readiness { status: "not ready", database, reason, version }))
        }
    }
}
