//! Compute budgets: a job over its budget is stopped and answered 422
//! (`/problems/compute-budget`) with how far it got, nothing is stored, and
//! a heavy job runs off the async workers so health checks still answer.

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::{Value, json};
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

/// How far a stopped job got, in the asker's language: K1's sweep at 100000
/// positions stopped at 150 ms says at which position, in English and in
/// Spanish (its numbers with the language's marks); the message's id is in
/// the catalogue of both. (At 20 ms a CI machine under load once spent the
/// budget before the sweep began, reading the request.)
#[tokio::test]
async fn a_spent_budget_says_how_far_it_got_in_the_askers_language() {
    let app = TestApp::with_job_budget(Duration::from_millis(150)).await;
    let r = app.post("/v1/kinetostatics", &heavy_kinetostatics()).await;
    let detail = r.json()["detail"].as_str().unwrap().to_string();
    let at = detail.split("(the mechanism was assembled at ").nth(1).unwrap_or_else(|| panic!("{detail}"));
    assert!(at.contains(" of 100000 positions)"), "{detail}");
    let r = crate::spanish::in_spanish(&app, "POST", "/v1/kinetostatics", Some(&heavy_kinetostatics())).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let detail = r.json()["detail"].as_str().unwrap().to_string();
    let at = detail.strip_prefix("se agotó el presupuesto de cálculo de 0,15 s (el mecanismo se había montado en ");
    assert!(at.is_some_and(|a| a.contains(" de 100000 posiciones); pida menos pasos")), "{detail}");
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

/// Small limits, as an operator may configure them.
fn tight() -> mechdyn::kind::Limits {
    mechdyn::kind::Limits {
        steps: 10,
        samples: 5,
        table_rows: 3,
        segments: 2,
        expression_length: 20,
        expression_depth: 3,
        ..Default::default()
    }
}

/// Each configured limit refuses the first request over it with 422 at the
/// field and the limit in the message; the same requests pass the defaults.
#[tokio::test]
async fn each_configured_limit_is_enforced_at_its_field() {
    let (tight_app, default_app) = (TestApp::with_limits(tight()).await, TestApp::new().await);
    let mut k1 = request("k1_offset_slider_crank");
    k1["input"]["steps"] = 11.into();
    let r = tight_app.post("/v1/kinetostatics", &k1).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/input/steps");
    assert!(r.json()["errors"][0]["message"].as_str().unwrap().contains("1 to 10"), "{}", r.text);
    assert_eq!(default_app.post("/v1/kinetostatics", &k1).await.status, StatusCode::CREATED);

    let base = request("p103_slider");
    let edits: [(&str, Value, &str, &str); 5] = [
        ("/samples", 6.into(), "/samples", "at most 5"),
        (
            "/torques/0/value",
            json!({"segments": [{"from": 0, "to": 1, "expr": "1"}, {"from": 1, "to": 2, "expr": "2"}, {"from": 2, "to": 3, "expr": "-3"}]}),
            "/torques/0/value",
            "1 to 2 segments",
        ),
        (
            "/torques/0/value",
            json!({"table": {"angle": [0, 1, 2, 3], "value": [1, 2, -3, 1]}}),
            "/torques/0/value/table/angle",
            "1 to 3 angles",
        ),
        ("/reduced_inertia", json!({"expr": "5 + 0*phi + 0*phi + 1"}), "/reduced_inertia", "maximum is 20"),
        ("/reduced_inertia", json!({"expr": "((((5))))"}), "/reduced_inertia", "nest"),
    ];
    for (at, value, pointer, message) in edits {
        let mut body = base.clone();
        match body.pointer_mut(at) {
            Some(slot) => *slot = value,
            None => body[&at[1..]] = value,
        }
        let errors = tight_app.flywheel_422(&body).await;
        assert!(
            errors.iter().any(|(p, m)| p.starts_with(pointer) && m.contains(message)),
            "{at}: want {pointer} '{message}', got {errors:?}"
        );
        default_app.flywheel(&body).await;
    }
}

/// What Python's urllib sends (`method`, a JSON array of about `kib`
/// KiB, more `headers` as a Python dict's items) and then reads, through
/// the real binary, five times over (a connection closed unread loses the
/// answer only now and then): each answer's status, content type and body,
/// or its error, a line each.
fn urllib(port: u16, method: &str, path: &str, kib: usize, headers: &str) -> String {
    let script = format!(
        "import urllib.request, urllib.error\n\
         body = b'[' + b'0,' * ({kib} << 9) + b'0]'\n\
         for _ in range(5):\n\
         \x20   req = urllib.request.Request('http://127.0.0.1:{port}{path}', data=body, method='{method}', \
         headers={{'Content-Type': 'application/json', {headers}}})\n\
         \x20   try:\n        print(urllib.request.urlopen(req).status)\n\
         \x20   except urllib.error.HTTPError as e:\n        print(e.code, e.headers['Content-Type'], e.read().decode())\n\
         \x20   except OSError as e:\n        print('error', e)\n"
    );
    let out = std::process::Command::new("python3").args(["-c", &script]).output().expect("python3 runs");
    format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr))
}

/// A 5 MB body from Python's urllib, which writes the whole body before it
/// reads: the service reads and discards the excess, so the client gets
/// the 413 problem instead of a broken pipe.
#[test]
fn a_client_that_sends_its_whole_body_first_reads_the_413() {
    let dir = tempfile::tempdir().unwrap();
    let port = crate::crash::free_port();
    let mut child = crate::crash::start(&format!("sqlite://{}/jobs.db", dir.path().display()), port);
    let said = urllib(port, "POST", "/v1/flywheel", 5 << 10, "");
    child.kill().unwrap();
    child.wait().unwrap();
    for line in said.lines() {
        assert!(line.starts_with("413 application/problem+json"), "{said}");
        assert!(line.contains("/problems/payload-too-large"), "{said}");
    }
}

/// Every answer given before a body was read (a missing token, no such
/// route or method, a wrong content type, a bad query) reaches a client
/// that writes its whole body (1 MB, near the limit; 3 MB for the token) first: the service drains
/// the body (before, it closed the connection and urllib saw a broken pipe).
#[test]
fn a_client_that_sends_its_whole_body_first_reads_every_early_answer() {
    let dir = tempfile::tempdir().unwrap();
    let port = crate::crash::free_port();
    let db = format!("sqlite://{}/jobs.db", dir.path().display());
    let mut child = crate::crash::start_with(&db, port, &[("MECHDYN_API_TOKEN", "t0ken")]);
    let token = "'Authorization': 'Bearer t0ken'";
    let cases = [
        ("POST", "/v1/flywheel", 3 << 10, "", "401", "/problems/unauthorized"),
        ("POST", "/v1/no-such-kind", 1000, token, "404", "/problems/not-found"),
        ("PUT", "/v1/flywheel", 1000, token, "405", "/problems/method-not-allowed"),
        ("POST", "/v1/jobs/5e1b7c43-0d4f-4f7e-9a7e-1b8d2f3c4a5b", 1000, token, "405", "/problems/method-not-allowed"),
        ("POST", "/v1/flywheel", 1000, &format!("{token}, 'Content-Type': 'text/plain'"), "415", "media-type"),
        ("POST", "/v1/flywheel?label=", 1000, token, "400", "/problems/invalid-query"),
    ];
    let said: Vec<String> = cases.iter().map(|(m, path, kib, h, ..)| urllib(port, m, path, *kib, h)).collect();
    child.kill().unwrap();
    child.wait().unwrap();
    for ((method, path, _, _, status, kind), said) in cases.iter().zip(&said) {
        assert_eq!(said.lines().count(), 5, "{method} {path}: {said}");
        for line in said.lines() {
            assert!(line.starts_with(&format!("{status} application/problem+json")), "{method} {path}: {line}");
            assert!(line.contains(kind), "{method} {path}: {line}");
        }
    }
}

/// A count of steps far beyond the limit (found by the fuzz test: the
/// positions were laid out before the count was refused, and 10¹² of them
/// did not fit in memory) is refused at its field, nothing allocated.
#[tokio::test]
async fn a_huge_count_of_steps_is_refused_before_anything_is_laid_out() {
    let app = TestApp::new().await;
    let mut body = request("k1_offset_slider_crank");
    body["input"]["steps"] = 1_000_000_000_000u64.into();
    let r = app.post("/v1/kinetostatics", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/input/steps", "{}", r.text);
}

/// A long smooth run at a tight tolerance over its budget with the
/// 5th-order method (the machine form's automatic choice) is told of the
/// 8th-order one; asked with the 8th-order one, it is not. A01's pendulum
/// over 100000 s at 1e-12, budget 50 ms.
#[tokio::test]
async fn a_long_run_over_its_budget_is_told_of_the_eighth_order_method() {
    let app = TestApp::with_job_budget(Duration::from_millis(50)).await;
    let mut body = request("a01_pendulum");
    (body["duration"], body["tolerance"]) = (json!("100000 s"), json!(1e-12));
    let hint = "\"integrator\": \"dop853\" takes far fewer steps";
    assert_over_budget(&app, "/v1/dynamics", &body, "0.05").await;
    let r = app.post("/v1/dynamics", &body).await;
    assert!(r.json()["detail"].as_str().unwrap().ends_with(hint), "{}", r.text);
    body["integrator"] = json!("dop853");
    let r = app.post("/v1/dynamics", &body).await;
    assert_eq!(r.json()["type"], "/problems/compute-budget", "{}", r.text);
    assert!(!r.json()["detail"].as_str().unwrap().contains(hint), "{}", r.text);
}
