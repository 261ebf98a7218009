//! The operator's endpoints: liveness, readiness.

use crate::helpers::TestApp;
use axum::http::StatusCode;
use mechdyn::api::{AppState, Settings, router};
use mechdyn::store::Store;

/// `/readyz` is 200 while the database answers and 503 with the reason once
/// it does not; `/healthz`, the liveness check, stays 200 throughout (a
/// database that is down makes a replica unready, not restarted).
#[tokio::test]
async fn readiness_follows_the_database_and_liveness_does_not() {
    let dir = tempfile::tempdir().unwrap();
    let store = Store::open(&format!("sqlite://{}/jobs.db", dir.path().display())).await.unwrap();
    let app = TestApp::serving(router(AppState::new(store.clone()), &Settings::default()));
    let ready = app.get("/readyz").await;
    assert_eq!(ready.status, StatusCode::OK, "{}", ready.text);
    assert_eq!((ready.json()["status"].as_str(), ready.json()["database"].as_str()), (Some("ready"), Some("sqlite")));
    store.close().await;
    let unready = app.get("/readyz").await;
    assert_eq!(unready.status, StatusCode::SERVICE_UNAVAILABLE, "{}", unready.text);
    assert_eq!(unready.json()["status"], "not ready");
    let reason = unready.json()["reason"].as_str().unwrap().to_string();
    assert!(reason.starts_with("the database does not answer: "), "{reason}");
    let live = app.get("/healthz").await;
    assert_eq!((live.status, live.json()["status"].as_str()), (StatusCode::OK, Some("ok")));
}
