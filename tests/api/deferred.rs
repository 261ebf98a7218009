//! Jobs POSTed with `Prefer: respond-async`: answered 202 at once, stored
//! `queued`, computed by a runner into `done` (the result a POST answered
//! at once gives) or `failed` (the problem it would have answered); never
//! lost when their replica stops or is killed.

use crate::crash::{free_port, http, http_with, start_with};
use crate::helpers::{Reply, TestApp, request};
use axum::body::Body;
use axum::http::{Request, StatusCode};
use mechdyn::api::deferred::{self, Deferred, Settings};
use mechdyn::api::{AppState, router};
use mechdyn::store::Store;
use serde_json::{Value, json};
use std::time::{Duration, Instant};

/// POST `body` to `path` with `Prefer: respond-async`.
pub async fn post_async(app: &TestApp, path: &str, body: &Value) -> Reply {
    let req = Request::post(path).header("content-type", "application/json").header("prefer", "respond-async");
    app.send(req.body(Body::from(body.to_string())).unwrap()).await
}

/// The job at `location` once it has ended (done or failed), read every 20 ms.
pub async fn ended(app: &TestApp, location: &str) -> Value {
    let started = Instant::now();
    loop {
        let job = app.get(location).await.json();
        if job["status"] == "done" || job["status"] == "failed" {
            return job;
        }
        assert!(started.elapsed() < Duration::from_secs(60), "not ended in 60 s: {job}");
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
}

/// A fresh app whose deferred jobs are kept as `settings` says, and its
/// state (to start its runner when the test wants it).
async fn app_with(settings: Settings) -> (TestApp, AppState) {
    let dir = tempfile::tempdir().unwrap();
    let store = Store::open(&format!("sqlite://{}/jobs.db", dir.path().display())).await.unwrap();
    let state = AppState { deferred: Deferred::new(settings), ..crate::helpers::state(store) };
    (TestApp::serving(router(state.clone(), &mechdyn::api::Settings::default()), dir), state)
}

/// The P.103 flywheel deferred: 202 at once with its `Location` and
/// `Preference-Applied`, the job `queued` without a result; while no runner
/// runs, a part of its result is a 409 with `Retry-After`, its page asks the
/// browser to come back (`Refresh`), and `/metrics` counts it queued. Once
/// this replica's runner runs, the job is `done`, its label kept, and its
/// result is the one the same request POSTed without the preference gets,
/// byte for byte.
#[tokio::test]
async fn a_deferred_job_is_queued_then_computed() {
    let (app, state) = app_with(Settings::default()).await;
    let body = request("p103_slider");
    let r = post_async(&app, "/v1/flywheel?label=lab-2", &body).await;
    assert_eq!(r.status, StatusCode::ACCEPTED, "{}", r.text);
    assert_eq!(r.headers["preference-applied"], "respond-async");
    let location = r.location.clone().unwrap();
    let queued = r.json();
    assert_eq!(location, format!("/v1/jobs/{}", queued["id"].as_str().unwrap()));
    assert_eq!((queued["status"].as_str(), queued.get("result")), (Some("queued"), None), "{queued}");
    assert_eq!((queued["request"].clone(), queued["label"].as_str()), (body.clone(), Some("lab-2")));
    assert_eq!(app.get(&location).await.text, r.text, "a GET answers the job as the 202 did");
    let part = app.get(&format!("{location}/result/inertia_exact")).await;
    assert_eq!((part.status, part.json()["type"].as_str()), (StatusCode::CONFLICT, Some("/problems/job-not-done")));
    assert_eq!(part.headers["retry-after"], "1");
    assert_eq!(app.get(&format!("{location}/result.csv")).await.status, StatusCode::CONFLICT);
    let page = app.get(&format!("/jobs/{}", queued["id"].as_str().unwrap())).await;
    assert_eq!((page.status, page.headers["refresh"].to_str().unwrap()), (StatusCode::OK, "2"));
    assert!(page.text.contains("queued"), "{}", page.text);
    assert!(app.get("/").await.text.contains("<td>queued</td>"), "the home page's list says so");
    assert!(app.get("/metrics").await.text.contains("mechdyn_deferred_jobs{status=\"queued\"} 1\n"));

    let runner = deferred::spawn(state).unwrap();
    let done = ended(&app, &location).await;
    runner.stop().await;
    let at_once = app.flywheel(&body).await;
    assert_eq!(done["status"], "done", "{done}");
    assert_eq!(done["result"], at_once["result"], "the same result as the POST answered at once");
    assert!(done["timing"]["engine_us"].as_i64().unwrap() > 0 && done["label"] == "lab-2");
    let part = app.get(&format!("{location}/result/inertia_exact")).await;
    assert_eq!(part.text, at_once["result"]["inertia_exact"].to_string());
    let page = app.get(&format!("/jobs/{}", done["id"].as_str().unwrap())).await;
    assert!(page.headers.get("refresh").is_none());
    assert!(app.get("/metrics").await.text.contains("mechdyn_deferred_jobs{status=\"queued\"} 0\n"));
}

/// A deferred job the engine refuses is `failed` with the very problem a
/// POST answered at once gets (the 422 with its pointer); reading its
/// result is a 409 without `Retry-After`. A field the kind does not know is
/// refused at once (422), nothing queued.
#[tokio::test]
async fn a_deferred_job_that_fails_keeps_its_problem() {
    let (app, state) = app_with(Settings::default()).await;
    let runner = deferred::spawn(state).unwrap();
    let mut body = request("p103_slider");
    body["irregularity"] = 3.into();
    let r = post_async(&app, "/v1/flywheel", &body).await;
    assert_eq!(r.status, StatusCode::ACCEPTED, "{}", r.text);
    let failed = ended(&app, r.location.as_deref().unwrap()).await;
    runner.stop().await;
    let at_once = app.post("/v1/flywheel", &body).await;
    assert_eq!(at_once.status, StatusCode::UNPROCESSABLE_ENTITY);
    assert_eq!(failed["status"], "failed");
    assert_eq!(failed["problem"], at_once.json(), "the problem the POST answered at once");
    assert_eq!(failed["problem"]["errors"][0]["pointer"], "/irregularity");
    assert!(failed.get("result").is_none());
    let part = app.get(&format!("{}/result/inertia_exact", r.location.unwrap())).await;
    assert_eq!(part.status, StatusCode::CONFLICT);
    assert!(part.headers.get("retry-after").is_none() && part.json()["detail"].as_str().unwrap().contains("failed"));

    body["irregulartiy"] = 0.04.into();
    let unknown = post_async(&app, "/v1/flywheel", &body).await;
    assert_eq!(unknown.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", unknown.text);
    assert_eq!(unknown.json()["errors"][0]["pointer"], "/irregulartiy");
    assert_eq!(
        app.get("/v1/jobs").await.json()["items"].as_array().unwrap().len(),
        1,
        "the failed job alone: a 422 stores nothing"
    );
}

/// At most `max_queued` deferred jobs wait: the next such POST is a 503
/// with `Retry-After`; a check (the hand-written kind) is deferred too.
#[tokio::test]
async fn the_queue_is_bounded_and_a_check_may_wait_in_it() {
    let (app, state) = app_with(Settings { max_queued: 2, ..Settings::default() }).await;
    let check = json!({"template": "p103-slider-flywheel", "answers": {"inertia_exact": 353.5}});
    let first = post_async(&app, "/v1/check", &check).await;
    assert_eq!(first.status, StatusCode::ACCEPTED, "{}", first.text);
    assert_eq!(
        post_async(&app, "/v1/gears/geometry", &json!({"module": "4 mm", "teeth": 30})).await.status,
        StatusCode::ACCEPTED
    );
    let full = post_async(&app, "/v1/flywheel", &request("p103_slider")).await;
    assert_eq!(
        (full.status, full.json()["type"].as_str()),
        (StatusCode::SERVICE_UNAVAILABLE, Some("/problems/saturated"))
    );
    assert!(full.json()["detail"].as_str().unwrap().contains("2 deferred jobs are waiting"), "{}", full.text);
    assert!(full.headers.contains_key("retry-after"));
    let runner = deferred::spawn(state).unwrap();
    let checked = ended(&app, first.location.as_deref().unwrap()).await;
    runner.stop().await;
    assert_eq!((checked["status"].as_str(), checked["kind"].as_str()), (Some("done"), Some("check")), "{checked}");
    assert_eq!(checked["result"]["passed"], 1, "{checked}");
}

/// IFToMM's A01 pendulum over 5000 s at tolerance 1e-9, 11 samples: seconds
/// of work for a small result, long enough to stop its replica while it
/// computes.
fn heavy() -> String {
    let mut heavy = request("a01_pendulum");
    (heavy["duration"], heavy["samples"], heavy["tolerance"]) = (json!("5000 s"), json!(11), json!(1e-9));
    heavy.to_string()
}

/// The job's status, read from the replica on `port`.
fn status(port: u16, id: &str) -> String {
    let (_, job) = http(port, "GET", &format!("/v1/jobs/{id}"), "").unwrap();
    serde_json::from_str::<Value>(&job).unwrap()["status"].as_str().unwrap().to_string()
}

/// Waits until the job on `port` has `wanted` status, up to 60 s.
fn wait_for(port: u16, id: &str, wanted: &str) {
    let started = Instant::now();
    while status(port, id) != wanted {
        assert!(started.elapsed() < Duration::from_secs(60), "job {id} not {wanted} in 60 s");
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// POSTs `body` to `path` on the replica on `port` with `Prefer:
/// respond-async`: (status, body).
pub fn post_async_raw(port: u16, path: &str, body: &str) -> (u16, String) {
    http_with(port, "POST", path, "Prefer: respond-async\r\n", body).unwrap()
}

/// POSTs the heavy job deferred to the replica on `port`: its id.
fn post_heavy(port: u16) -> String {
    let (status, job) = post_async_raw(port, "/v1/dynamics", &heavy());
    assert_eq!(status, 202, "{job}");
    serde_json::from_str::<Value>(&job).unwrap()["id"].as_str().unwrap().to_string()
}

/// The real binary: a deferred job running when its replica is stopped
/// (SIGTERM) goes back to the queue at once, and one running when its
/// replica is killed (SIGKILL) is taken again once its lease (1 s here)
/// lapses; a replica started again on the database computes both.
#[test]
fn a_deferred_job_outlives_its_replica() {
    let dir = tempfile::tempdir().unwrap();
    let db = format!("sqlite://{}/jobs.db", dir.path().display());
    let port = free_port();
    let env = [("MECHDYN_ASYNC_LEASE_SECONDS", "1"), ("MECHDYN_JOB_SECONDS", "120")];
    let mut replica = start_with(&db, port, &env);
    let stopped = post_heavy(port);
    wait_for(port, &stopped, "running");
    let term = std::process::Command::new("kill").args(["-TERM", &replica.id().to_string()]).status().unwrap();
    assert!(term.success());
    assert!(replica.wait().unwrap().success(), "a clean stop");

    let mut replica = start_with(&db, port, &[("MECHDYN_ASYNC_WORKERS", "0")]);
    assert_eq!(status(port, &stopped), "queued", "put back in the queue by the stopping replica");
    let _ = replica.kill();
    let _ = replica.wait();

    let mut replica = start_with(&db, port, &env);
    wait_for(port, &stopped, "done");
    let killed = post_heavy(port);
    wait_for(port, &killed, "running");
    let _ = replica.kill();
    let _ = replica.wait();

    let mut replica = start_with(&db, port, &env);
    wait_for(port, &killed, "done");
    let _ = replica.kill();
    let _ = replica.wait();
}
