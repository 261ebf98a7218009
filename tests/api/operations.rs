//! The operator's endpoints and duties: liveness, readiness, deleting
//! jobs, the retention.

use crate::crash::{free_port, http, start_with};
use crate::helpers::{TestApp, request};
use axum::body::Body;
use axum::http::{Request, StatusCode};
use mechdyn::api::retention::{self, Policy};
use mechdyn::api::{Settings, router};
use mechdyn::store::Store;
use std::time::Duration;

/// `/readyz` is 200 while the database answers and 503 with the reason once
/// it does not; `/healthz`, the liveness check, stays 200 throughout (a
/// database that is down makes a replica unready, not restarted).
#[tokio::test]
async fn readiness_follows_the_database_and_liveness_does_not() {
    let dir = tempfile::tempdir().unwrap();
    let store = Store::open(&format!("sqlite://{}/jobs.db", dir.path().display())).await.unwrap();
    let app = TestApp::serving(router(crate::helpers::state(store.clone()), &Settings::default()), dir);
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

/// `DELETE /v1/jobs/{id}` needs the API token as a POST does (401 without),
/// answers 204 and then the job is gone (404 to a read, absent from the
/// list, 404 to a second DELETE). An `Idempotency-Key` answered with the
/// job goes with it: the same POST again computes a new job instead of
/// answering with one that is gone.
#[tokio::test]
async fn a_deleted_job_is_gone_and_its_idempotency_key_with_it() {
    a_deleted_job_is_gone_on(TestApp::with_settings(&with_token()).await).await;
}

/// Settings with the API token "t0ken".
pub fn with_token() -> Settings {
    Settings { api_token: Some("t0ken".into()), ..Settings::default() }
}

/// The test's body, on any database, for an app with the settings [`with_token`].
pub async fn a_deleted_job_is_gone_on(app: TestApp) {
    let body = request("p103_slider").to_string();
    let post = || {
        let req = Request::post("/v1/flywheel").header("content-type", "application/json");
        let req = req.header("authorization", "Bearer t0ken").header("idempotency-key", "lab-3-run-1");
        req.body(Body::from(body.clone())).unwrap()
    };
    let first = app.send(post()).await;
    assert_eq!(first.status, StatusCode::CREATED, "{}", first.text);
    let id = first.json()["id"].as_str().unwrap().to_string();
    let path = format!("/v1/jobs/{id}");
    let delete = |auth: Option<&str>| {
        let req = Request::delete(&path);
        let req = if let Some(a) = auth { req.header("authorization", a) } else { req };
        req.body(Body::empty()).unwrap()
    };
    let refused = app.send(delete(None)).await;
    assert_eq!((refused.status, refused.content_type.as_str()), (StatusCode::UNAUTHORIZED, "application/problem+json"));
    assert_eq!(app.get_as(&path, "t0ken").await.status, StatusCode::OK, "a refused DELETE deletes nothing");
    let deleted = app.send(delete(Some("Bearer t0ken"))).await;
    assert_eq!((deleted.status, deleted.text.as_str()), (StatusCode::NO_CONTENT, ""));
    assert_eq!(app.get_as(&path, "t0ken").await.status, StatusCode::NOT_FOUND);
    assert_eq!(app.get_as(&format!("{path}/result.csv"), "t0ken").await.status, StatusCode::NOT_FOUND);
    assert_eq!(app.get_as("/v1/jobs", "t0ken").await.json()["items"], serde_json::json!([]));
    let again = app.send(delete(Some("Bearer t0ken"))).await;
    assert_eq!((again.status, again.json()["type"].as_str()), (StatusCode::NOT_FOUND, Some("/problems/not-found")));
    let retried = app.send(post()).await;
    assert_eq!(retried.status, StatusCode::CREATED, "{}", retried.text);
    assert!(!retried.headers.contains_key("idempotent-replayed"));
    assert_ne!(retried.json()["id"].as_str().unwrap(), id, "a new job, computed again");
    let metrics = app.get("/metrics").await.text;
    assert!(metrics.contains("mechdyn_jobs_deleted_total{reason=\"request\"} 1\n"), "{metrics}");
}

/// A sweep of the retention keeps the newest `max_jobs` jobs, and deletes
/// the jobs created before `now − max_age` and no other.
#[tokio::test]
async fn the_retention_deletes_by_count_and_by_age() {
    let dir = tempfile::tempdir().unwrap();
    the_retention_deletes_on(&format!("sqlite://{}/jobs.db", dir.path().display())).await;
}

/// The test's body, on the database at `url`.
pub async fn the_retention_deletes_on(url: &str) {
    let store = Store::open(url).await.unwrap();
    let state = crate::helpers::state(store);
    // The database is at `url` (SQLite's folder kept by the caller, or a PostgreSQL server).
    let app = TestApp::serving(router(state.clone(), &Settings::default()), tempfile::tempdir().unwrap());
    let mut ids = Vec::new();
    for k in 0..5 {
        let mut body = request("p103_slider");
        body["irregularity"] = (0.01 * f64::from(k + 1)).into();
        ids.push(app.flywheel(&body).await["id"].as_str().unwrap().to_string());
    }
    let now = time::OffsetDateTime::now_utc();
    let by_count = Policy { max_jobs: Some(2), ..Policy::default() };
    assert_eq!(retention::sweep(&state, &by_count, now).await.unwrap(), 3);
    assert_eq!(ids_listed(&app).await, vec![ids[4].clone(), ids[3].clone()], "the newest two, newest first");
    let day = Duration::from_secs(86_400);
    let by_age = Policy { max_age: Some(day), ..Policy::default() };
    assert_eq!(retention::sweep(&state, &by_age, now + day / 2).await.unwrap(), 0, "half a day old: kept");
    assert_eq!(ids_listed(&app).await.len(), 2);
    assert_eq!(retention::sweep(&state, &by_age, now + day * 2).await.unwrap(), 2, "two days old: deleted");
    assert!(ids_listed(&app).await.is_empty());
    let metrics = app.get("/metrics").await.text;
    assert!(metrics.contains("mechdyn_jobs_deleted_total{reason=\"count\"} 3\n"), "{metrics}");
    assert!(metrics.contains("mechdyn_jobs_deleted_total{reason=\"age\"} 2\n"), "{metrics}");
}

/// The real binary with `MECHDYN_RETENTION_JOBS=1` sweeps on its own: of
/// three jobs POSTed, only the newest remains.
#[test]
fn the_service_sweeps_on_its_own() {
    let dir = tempfile::tempdir().unwrap();
    let port = free_port();
    let db = format!("sqlite://{}/jobs.db", dir.path().display());
    let env = [("MECHDYN_RETENTION_JOBS", "1"), ("MECHDYN_RETENTION_INTERVAL_SECONDS", "0.2")];
    let mut service = start_with(&db, port, &env);
    let mut newest = String::new();
    for k in 1..=3 {
        let mut body = request("p103_slider");
        body["irregularity"] = (0.01 * f64::from(k)).into();
        let (status, job) = http(port, "POST", "/v1/flywheel", &body.to_string()).unwrap();
        assert_eq!(status, 201, "{job}");
        newest = serde_json::from_str::<serde_json::Value>(&job).unwrap()["id"].as_str().unwrap().to_string();
    }
    let started = std::time::Instant::now();
    let ids = loop {
        let list: serde_json::Value = serde_json::from_str(&http(port, "GET", "/v1/jobs", "").unwrap().1).unwrap();
        let ids: Vec<String> = list["items"].as_array().unwrap().iter().map(|j| j["id"].to_string()).collect();
        if ids.len() == 1 || started.elapsed() > Duration::from_secs(20) {
            break ids;
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let _ = service.kill();
    let _ = service.wait();
    assert_eq!(ids, vec![format!("\"{newest}\"")], "only the newest job is kept");
}

/// The ids of the jobs list's first page, newest first.
async fn ids_listed(app: &TestApp) -> Vec<String> {
    let list = app.get("/v1/jobs").await.json();
    list["items"].as_array().unwrap().iter().map(|j| j["id"].as_str().unwrap().to_string()).collect()
}
