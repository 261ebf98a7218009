//! Bounded memory: the limit on a result (refused 422 saying what would fit,
//! estimated before computing where it can be), admission control (a POST
//! beyond the jobs and the queue is answered 503 with Retry-After), answers
//! that hold their memory until they are sent, and pages of the jobs list
//! bounded in bytes.

use crate::helpers::{TestApp, request};
use axum::body::Body;
use axum::http::{Request, StatusCode};
use http_body_util::BodyExt;
use mechdyn::api::pace::Pace;
use mechdyn::api::{Admission, AppState, Capacity, Settings, router};
use mechdyn::kind::Limits;
use mechdyn::store::Store;
use serde_json::Value;
use std::time::Duration;
use tower::ServiceExt;

/// The number after `NAME ≤ ` in a too-large message.
fn would_fit(message: &str, name: &str) -> usize {
    let after = message.split(&format!("{name} ≤ ")).nth(1).unwrap_or_else(|| panic!("no advice: {message}"));
    after.split(|c: char| !c.is_ascii_digit()).next().unwrap().parse().unwrap()
}

/// The problem of a 422 result-too-large at `pointer`: its message.
fn too_large(r: &crate::helpers::Reply, pointer: &str) -> String {
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let p = r.json();
    assert_eq!(p["type"], "/problems/result-too-large", "{p}");
    assert_eq!(p["errors"][0]["pointer"], pointer, "{p}");
    p["errors"][0]["message"].as_str().unwrap().to_string()
}

/// K1 at 3600 positions under a 200 kB limit: refused before computing with
/// the number of steps that fits; that number is then accepted, within the
/// limit; nothing was stored for the refusal.
#[tokio::test]
async fn a_kinetostatics_result_over_the_limit_is_refused_with_the_steps_that_fit() {
    let limit = 200_000;
    let app = TestApp::with_limits(Limits { result_bytes: limit, ..Limits::default() }).await;
    let mut body = request("k1_offset_slider_crank");
    body["input"]["steps"] = 3600.into();
    let message = too_large(&app.post("/v1/kinetostatics", &body).await, "/input/steps");
    assert!(message.contains("would be about") && message.contains("outputs"), "{message}");
    assert!(app.get("/v1/jobs").await.json()["items"].as_array().unwrap().is_empty(), "nothing stored");
    let fit = would_fit(&message, "steps");
    assert!((10..3600).contains(&fit), "{message}");
    body["input"]["steps"] = fit.into();
    let r = app.post("/v1/kinetostatics", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", &r.text[..r.text.len().min(400)]);
    let result = serde_json::to_string(&r.json()["result"]).unwrap();
    assert!(result.len() <= limit, "{} bytes", result.len());
}

/// A cam's samples over the limit: refused at `samples` with how many fit,
/// which then fit (issue 48: 36 000 samples were refused saying only the size).
#[tokio::test]
async fn a_cams_samples_over_the_limit_are_refused_with_the_samples_that_fit() {
    let limit = 300_000;
    let app = TestApp::with_limits(Limits { result_bytes: limit, ..Limits::default() }).await;
    let mut body = crate::helpers::template_request("cam-design");
    body["samples"] = 3600.into();
    let message = too_large(&app.post("/v1/cams", &body).await, "/samples");
    let fit = would_fit(&message, "samples");
    assert!((100..3600).contains(&fit), "{message}");
    body["samples"] = fit.into();
    let r = app.post("/v1/cams", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", &r.text[..r.text.len().min(400)]);
    assert!(serde_json::to_string(&r.json()["result"]).unwrap().len() <= limit);
}

/// A flywheel's table over the limit is found when the result is written
/// (no estimate before): refused with the samples that fit, which then fit.
#[tokio::test]
async fn a_flywheel_table_over_the_limit_is_refused_with_the_samples_that_fit() {
    let limit = 50_000;
    let app = TestApp::with_limits(Limits { result_bytes: limit, ..Limits::default() }).await;
    let mut body = request("p113_pulley");
    body["samples"] = 5000.into();
    let message = too_large(&app.post("/v1/flywheel", &body).await, "/samples");
    let fit = would_fit(&message, "samples");
    body["samples"] = fit.into();
    let r = app.post("/v1/flywheel", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    assert!(serde_json::to_string(&r.json()["result"]).unwrap().len() <= limit);
}

fn post(path: &str, body: Body) -> Request<Body> {
    Request::post(path).header("content-type", "application/json").body(body).unwrap()
}

/// One job computing and no queue: while a POST holds the only slot (its
/// answer not yet taken), another is answered 503 problem+json with
/// Retry-After; once the first answer is gone, POSTs are served again.
#[tokio::test]
async fn a_post_beyond_the_jobs_and_the_queue_is_answered_503_with_retry_after() {
    let admission = Admission::new(Capacity { jobs: 1, queue: 0, ..Capacity::default() });
    let app = TestApp::new().await.reopened(|s| mechdyn::api::AppState { admission, ..s }).await;
    let body = || Body::from(request("p113_pulley").to_string());
    let first = app.app.clone().oneshot(post("/v1/flywheel", body())).await.unwrap();
    assert_eq!(first.status(), StatusCode::CREATED);
    let second = app.post("/v1/flywheel", &request("p113_pulley")).await;
    assert_eq!(second.status, StatusCode::SERVICE_UNAVAILABLE, "{}", second.text);
    assert_eq!(second.content_type, "application/problem+json");
    assert_eq!(second.json()["type"], "/problems/saturated", "{}", second.text);
    let retry: u64 = second.headers["retry-after"].to_str().unwrap().parse().unwrap();
    assert!((1..=60).contains(&retry), "Retry-After {retry}");
    // /metrics counts the POST holding the slot as queued, not computing, and the 503s by route.
    let metrics = app.get("/metrics").await.text;
    assert!(
        metrics.contains("\nmechdyn_queue_depth 1\n") && metrics.contains("\nmechdyn_jobs_computing 0\n"),
        "{metrics}"
    );
    let refused = r#"mechdyn_http_requests_total{method="POST",route="/v1/flywheel",status="503"}"#;
    assert!(metrics.lines().any(|l| l.starts_with(refused)), "{metrics}");
    drop(first);
    assert_eq!(app.post("/v1/flywheel", &request("p113_pulley")).await.status, StatusCode::CREATED);
    assert!(app.get("/metrics").await.text.contains("\nmechdyn_queue_depth 0\n"));
}

/// A body still arriving holds no slot: with one slot and no queue, a POST
/// whose body trickles does not stop another from being served; once it
/// falls behind the pace (here 100 ms of grace, then 1000 bytes/s) it is
/// answered 408 with the connection closed, saying how much arrived.
#[tokio::test]
async fn a_body_still_arriving_holds_no_slot_and_is_cut_off_behind_the_pace() {
    let admission = Admission::new(Capacity { jobs: 1, queue: 0, ..Capacity::default() });
    let pace = Pace { rate: 1000, grace: Duration::from_millis(100) };
    let dir = tempfile::tempdir().unwrap();
    let store = Store::open(&format!("sqlite://{}/jobs.db", dir.path().display())).await.unwrap();
    let state = AppState { admission, ..crate::helpers::state(store) };
    let app = TestApp::serving(router(state, &Settings { pace, ..Settings::default() }), dir);
    let (mut sender, slow) = http_body_util::channel::Channel::<bytes::Bytes>::new(1);
    let body = request("p113_pulley").to_string();
    let first = tokio::spawn(app.app.clone().oneshot(post("/v1/flywheel", Body::new(slow))));
    sender.send_data(body[..10].to_string().into()).await.unwrap();
    let second = app.post("/v1/flywheel", &request("p113_pulley")).await;
    assert_eq!(second.status, StatusCode::CREATED, "{}", second.text);
    let started = std::time::Instant::now();
    let timed_out = first.await.unwrap().unwrap();
    assert_eq!(timed_out.status(), StatusCode::REQUEST_TIMEOUT);
    assert_eq!(timed_out.headers()["connection"], "close");
    // 100 ms of grace, and 10 ms more for the 10 bytes at 1000 bytes/s; not the 10 s a drain would take.
    assert!(started.elapsed() < Duration::from_secs(5), "{:?}", started.elapsed());
    let text = String::from_utf8(timed_out.into_body().collect().await.unwrap().to_bytes().to_vec()).unwrap();
    assert!(text.contains("/problems/request-timeout") && text.contains("10 bytes in "), "{text}");
}

/// An answer holds its memory until it has been sent: with room for one
/// copy of a job, a second read waits while the first answer is unread,
/// and is answered 503 once its wait is over; after the first answer has
/// gone, reads are served again.
#[tokio::test]
async fn answers_hold_their_memory_until_sent() {
    let app = TestApp::new().await;
    let job = app.flywheel(&request("p113_pulley")).await;
    let path = format!("/v1/jobs/{}", job["id"].as_str().unwrap());
    let size =
        serde_json::to_string(&job["request"]).unwrap().len() + serde_json::to_string(&job["result"]).unwrap().len();
    let capacity = Capacity { memory: size * 3 / 2, wait: Duration::from_millis(200), ..Capacity::default() };
    let app = app.reopened(|s| mechdyn::api::AppState { admission: Admission::new(capacity), ..s }).await;
    let read = || app.app.clone().oneshot(Request::get(&path).body(Body::empty()).unwrap());
    let unread = read().await.unwrap();
    assert_eq!(unread.status(), StatusCode::OK);
    let length: usize = unread.headers()["content-length"].to_str().unwrap().parse().unwrap();
    let waiting = read().await.unwrap();
    assert_eq!(waiting.status(), StatusCode::SERVICE_UNAVAILABLE);
    assert!(waiting.headers().contains_key("retry-after"));
    let sent = unread.into_body().collect().await.unwrap().to_bytes();
    assert_eq!(sent.len(), length, "Content-Length is the body's length");
    assert_eq!(read().await.unwrap().status(), StatusCode::OK);
}

/// A page of the jobs list stops before its jobs exceed the limit on a
/// result (one job at least); `next` leads to the rest, and every job is
/// listed once.
#[tokio::test]
async fn a_page_of_the_jobs_list_is_bounded_in_bytes() {
    let probe = TestApp::new().await;
    let one = probe.post("/v1/flywheel", &request("p113_pulley")).await.text.len();
    let limit = one * 5 / 2;
    let app = TestApp::with_limits(Limits { result_bytes: limit, ..Limits::default() }).await;
    for _ in 0..5 {
        app.flywheel(&request("p113_pulley")).await;
    }
    let (mut seen, mut next, mut pages) = (Vec::new(), Some("/v1/jobs".to_string()), 0);
    while let Some(path) = next {
        let page = app.get(&path).await;
        assert!(page.text.len() <= limit + 200, "{} bytes over {limit}", page.text.len());
        let page: Value = page.json();
        let items = page["items"].as_array().unwrap();
        assert!(!items.is_empty() || seen.len() == 5);
        seen.extend(items.iter().map(|j| j["id"].as_str().unwrap().to_string()));
        next = page["next"].as_str().map(str::to_string);
        pages += 1;
    }
    seen.sort();
    seen.dedup();
    assert_eq!(seen.len(), 5, "every job once");
    assert!(pages >= 3, "two jobs a page: {pages} pages");
}

/// A job that cannot start within the queue's wait is answered 503 with
/// Retry-After rather than left hanging: one job computing (K1 at 100000
/// positions with the exact condition number, an SVD each: seconds of
/// work), the next allowed 100 ms in the queue.
#[tokio::test]
async fn a_job_that_waits_too_long_in_the_queue_is_answered_503() {
    let capacity = Capacity { jobs: 1, queue_wait: Duration::from_millis(100), ..Capacity::default() };
    let limits = Limits { result_bytes: 1 << 30, ..Limits::default() };
    let app = TestApp::new()
        .await
        .reopened(|s| mechdyn::api::AppState { admission: Admission::new(capacity), limits, ..s })
        .await;
    let mut heavy = request("k1_offset_slider_crank");
    heavy["input"]["steps"] = 100_000.into();
    heavy["outputs"] = serde_json::json!(["driving", "condition"]);
    let first = tokio::spawn(app.app.clone().oneshot(post("/v1/kinetostatics", Body::from(heavy.to_string()))));
    // The heavy job takes about a second here (debug build): admitted well
    // within 150 ms, still computing when the second has waited its 100 ms.
    tokio::time::sleep(Duration::from_millis(150)).await;
    let second = app.post("/v1/flywheel", &request("p113_pulley")).await;
    assert_eq!(second.status, StatusCode::SERVICE_UNAVAILABLE, "{}", second.text);
    assert!(second.json()["detail"].as_str().unwrap().contains("did not finish in time"), "{}", second.text);
    assert!(second.headers.contains_key("retry-after"));
    assert_eq!(first.await.unwrap().unwrap().status(), StatusCode::CREATED);
}

/// A GET that computes a template's new job goes through admission as a
/// POST does: with the only slot held, it is answered 503; a GET of a job
/// already stored is not held up (before, such GETs computed beside the
/// jobs and the queue).
#[tokio::test]
async fn a_get_that_computes_takes_a_slot_as_a_post_does() {
    let admission = Admission::new(Capacity { jobs: 1, queue: 0, ..Capacity::default() });
    let app = TestApp::new().await.reopened(|s| mechdyn::api::AppState { admission, ..s }).await;
    let stored = "/v1/templates/p103-slider-flywheel/result/inertia_exact?F=1000";
    assert_eq!(app.get(stored).await.status, StatusCode::OK);
    let body = Body::from(request("p113_pulley").to_string());
    let holding = app.app.clone().oneshot(post("/v1/flywheel", body)).await.unwrap();
    assert_eq!(holding.status(), StatusCode::CREATED);
    let new = app.get("/v1/templates/p103-slider-flywheel/result/inertia_exact?F=1300").await;
    assert_eq!(new.status, StatusCode::SERVICE_UNAVAILABLE, "{}", new.text);
    assert_eq!(new.json()["type"], "/problems/saturated");
    assert_eq!(app.get(stored).await.status, StatusCode::OK, "a stored job needs no slot");
    drop(holding);
    assert_eq!(app.get("/v1/templates/p103-slider-flywheel/result/inertia_exact?F=1300").await.status, StatusCode::OK);
}

/// A body holds the bodies' budget only for what has arrived: POSTs whose
/// bodies have not begun hold nothing, so another is served; a body that
/// has arrived holds its bytes until it is whole, and one that would go
/// beyond the budget waits, then is answered 503.
#[tokio::test]
async fn bodies_hold_their_budget_for_what_has_arrived() {
    use http_body_util::channel::Channel;
    let body = request("p103_slider").to_string();
    let capacity = Capacity { bodies: body.len() + 100, wait: Duration::from_millis(200), ..Capacity::default() };
    let admission = Admission::new(capacity);
    let app = TestApp::new().await.reopened(|s| mechdyn::api::AppState { admission, ..s }).await;
    let silent: Vec<_> = (0..10)
        .map(|_| {
            let (sender, nothing) = Channel::<bytes::Bytes>::new(1);
            (sender, tokio::spawn(app.app.clone().oneshot(post("/v1/flywheel", Body::new(nothing)))))
        })
        .collect();
    tokio::task::yield_now().await;
    let served = app.post("/v1/flywheel", &request("p103_slider")).await;
    assert_eq!(served.status, StatusCode::CREATED, "ten silent bodies held the budget: {}", served.text);
    let (mut sender, arriving) = Channel::<bytes::Bytes>::new(1);
    let first = tokio::spawn(app.app.clone().oneshot(post("/v1/flywheel", Body::new(arriving))));
    sender.send_data(body.clone().into()).await.unwrap();
    tokio::time::sleep(Duration::from_millis(20)).await;
    let refused = app.post("/v1/flywheel", &request("p103_slider")).await;
    assert_eq!(refused.status, StatusCode::SERVICE_UNAVAILABLE, "{}", refused.text);
    assert!(refused.json()["detail"].as_str().unwrap().contains("request bodies"), "{}", refused.text);
    drop(sender);
    assert_eq!(first.await.unwrap().unwrap().status(), StatusCode::CREATED);
    drop(silent);
}
