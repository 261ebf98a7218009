//! Compute budgets: a job over its budget is stopped and answered 422
//! (`/problems/compute-budget`) with how far it got, nothing is stored, and
//! a heavy job runs off the async workers so health checks still answer.

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::Value;
use std::time::Duration;

/// K1 asked at 100000 crank positions (the largest number accepted).
fn heavy_kinetostatics() -> Value {
    let mut body = request("k1_offset_slider_crank");
    body["input"]["steps"] = 100_000.into();
    body
}

async fn assert_over_budget(app: &TestApp, path: &str, body: &Value, budget: &str) {
    let r = app.post(path, body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.content_type, "application/problem+json");
    let problem = r.json();
    assert_eq!(problem["type"], "/problems/compute-budget", "{problem}");
    let detail = problem["detail"].as_str().unwrap();
    assert!(detail.contains(&format!("compute budget of {budget} s ran out")), "{detail}");
    let list = app.get("/v1/jobs").await.json();
    assert!(list["items"].as_array().unwrap().is_empty(), "nothing stored: {list}");
}

#[tokio::test]
async fn kinetostatics_over_its_budget_is_stopped_with_its_progress() {
    let app = TestApp::with_job_budget(Duration::from_millis(20)).await;
    assert_over_budget(&app, "/v1/kinetostatics", &heavy_kinetostatics(), "0.02").await;
}

/// The flywheel of P.103 with the slider-crank itself as the machine: every
/// M* and I* evaluation assembles the mechanism; a 1 ms budget runs out
/// while it is being assembled or solved, and the answer says so instead of
/// reporting the NaN a late machine evaluation returns as bad input.
#[tokio::test]
async fn a_flywheel_of_a_machine_over_its_budget_is_stopped() {
    let app = TestApp::with_job_budget(Duration::from_millis(1)).await;
    assert_over_budget(&app, "/v1/flywheel", &request("p103_slider_machine"), "0.001").await;
}

/// While a job that takes seconds is computing, the health check answers:
/// the engine runs on the blocking pool, not on the async workers (the test
/// runtime has a single worker thread, so a blocking job there would stall it).
#[tokio::test]
async fn a_heavy_job_does_not_stall_the_health_check() {
    let app = TestApp::with_job_budget(Duration::from_secs(3)).await;
    let router = app.app.clone();
    let heavy = tokio::spawn(async move {
        let req = axum::http::Request::post("/v1/kinetostatics")
            .header("content-type", "application/json")
            .body(axum::body::Body::from(heavy_kinetostatics().to_string()))
            .unwrap();
        tower::ServiceExt::oneshot(router, req).await.unwrap().status()
    });
    tokio::time::sleep(Duration::from_millis(100)).await;
    let health = app.get("/healthz").await;
    assert_eq!(health.status, StatusCode::OK, "{}", health.text);
    assert!(!heavy.is_finished(), "the heavy job should still be computing when /healthz answers");
    let status = heavy.await.unwrap();
    assert!(status == StatusCode::CREATED || status == StatusCode::UNPROCESSABLE_ENTITY, "{status}");
}
