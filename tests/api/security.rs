//! Security basics through the real middleware: request ids, panics
//! answered without internals, the optional bearer token, CORS.

use crate::helpers::{TestApp, request};
use axum::body::Body;
use axum::http::{Request, StatusCode};
use axum::routing::get;
use mechdyn::api::Settings;
use mechdyn::api::middleware::layered;
use std::sync::{Arc, Mutex};

async fn boom() -> &'static str {
    panic!("secret detail: table jobs at src/store/mod.rs:42")
}

/// The log lines written while the guard lives (this thread only).
#[derive(Clone, Default)]
struct Log(Arc<Mutex<Vec<u8>>>);

impl std::io::Write for Log {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.lock().unwrap().extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// A handler that panics is answered 500 problem+json saying nothing of the
/// panic, with the request id in `x-request-id`; the log has the panic's
/// message with that request id.
#[tokio::test]
async fn a_panicking_handler_is_answered_500_without_internals() {
    let mut app = TestApp::new().await;
    let state = crate::helpers::state(mechdyn::store::Store::open(&app.url).await.unwrap());
    app.app = layered(axum::Router::new().route("/boom", get(boom)), &Settings::default(), state);
    // A first panic registers the span's and the events' callsites here,
    // before this test's subscriber exists: setting it then asks each of
    // them again. (Registered first by another test's thread, at the moment
    // this subscriber was being set, a callsite could keep "never".)
    let warm = app.send(Request::get("/boom").body(Body::empty()).unwrap()).await;
    assert_eq!(warm.status, StatusCode::INTERNAL_SERVER_ERROR);
    let log = Log::default();
    let writer = log.clone();
    let subscriber = tracing_subscriber::fmt().with_ansi(false).with_writer(move || writer.clone()).finish();
    let _guard = tracing::subscriber::set_default(subscriber);
    let r = app.send(Request::get("/boom").header("x-request-id", "trace-me-42").body(Body::empty()).unwrap()).await;
    let logged = String::from_utf8(log.0.lock().unwrap().clone()).unwrap();
    let line = logged.lines().find(|l| l.contains("handler panicked")).unwrap_or_else(|| panic!("{logged}"));
    assert!(line.contains("request_id=trace-me-42") && line.contains("secret detail"), "{line}");
    assert_eq!(r.status, StatusCode::INTERNAL_SERVER_ERROR);
    assert_eq!(r.content_type, "application/problem+json");
    assert_eq!(r.json()["type"], "/problems/internal", "{}", r.text);
    assert!(!r.text.contains("secret") && !r.text.contains("src/"), "{}", r.text);
    assert_eq!(r.headers["x-request-id"], "trace-me-42");
    // The service answers the next request as before.
    let again = app.send(Request::get("/boom").body(Body::empty()).unwrap()).await;
    assert_eq!(again.status, StatusCode::INTERNAL_SERVER_ERROR);
}

/// Every answer carries a request id: the client's own, or a fresh UUID.
#[tokio::test]
async fn every_answer_has_a_request_id() {
    let app = TestApp::new().await;
    let r = app.get("/healthz").await;
    let id = r.headers["x-request-id"].to_str().unwrap();
    assert!(uuid::Uuid::parse_str(id).is_ok(), "{id}");
    let r = app.get("/v1/jobs/no-such-job").await;
    assert_eq!(r.status, StatusCode::NOT_FOUND);
    assert!(r.headers.contains_key("x-request-id"));
}

/// With a token configured, a POST without it (or with another) is 401
/// problem+json with `WWW-Authenticate: Bearer` and stores nothing; with it,
/// 201. Stored jobs are read with it (`private.rs`: and only with it).
#[tokio::test]
async fn the_api_token_guards_every_post() {
    let settings = Settings { api_token: Some("s3cret-token".into()), ..Settings::default() };
    let app = TestApp::with_settings(&settings).await;
    let body = request("p103_slider").to_string();
    let post = |auth: Option<&str>| {
        let mut req = Request::post("/v1/flywheel").header("content-type", "application/json");
        if let Some(a) = auth {
            req = req.header("authorization", a);
        }
        req.body(Body::from(body.clone())).unwrap()
    };
    for auth in [None, Some("Bearer wrong"), Some("s3cret-token"), Some("Basic s3cret-token")] {
        let r = app.send(post(auth)).await;
        assert_eq!(r.status, StatusCode::UNAUTHORIZED, "{auth:?}: {}", r.text);
        assert_eq!(r.content_type, "application/problem+json");
        assert_eq!(r.headers["www-authenticate"], "Bearer");
        assert_eq!(r.json()["type"], "/problems/unauthorized");
    }
    let list = app.get_as("/v1/jobs", "s3cret-token").await;
    assert_eq!(list.status, StatusCode::OK);
    assert!(list.json()["items"].as_array().unwrap().is_empty());
    let r = app.send(post(Some("Bearer s3cret-token"))).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    assert_eq!(app.get_as(r.location.as_deref().unwrap(), "s3cret-token").await.status, StatusCode::OK);
}

/// CORS: a configured origin gets its preflight allowed and the headers a
/// spreadsheet add-in reads exposed; another origin gets no CORS headers;
/// without configuration there are none at all.
#[tokio::test]
async fn cors_allows_only_the_configured_origins() {
    let preflight = |origin: &str| {
        Request::options("/v1/flywheel")
            .header("origin", origin)
            .header("access-control-request-method", "POST")
            .header("access-control-request-headers", "content-type")
            .body(Body::empty())
            .unwrap()
    };
    let settings = Settings { cors_origins: vec!["https://addin.example.org".into()], ..Settings::default() };
    let app = TestApp::with_settings(&settings).await;
    let r = app.send(preflight("https://addin.example.org")).await;
    assert_eq!(r.headers["access-control-allow-origin"], "https://addin.example.org");
    assert!(r.headers["access-control-allow-methods"].to_str().unwrap().contains("POST"));
    let r = app.send(preflight("https://evil.example.com")).await;
    assert!(!r.headers.contains_key("access-control-allow-origin"));
    let get = Request::get("/healthz").header("origin", "https://addin.example.org").body(Body::empty()).unwrap();
    let r = app.send(get).await;
    assert_eq!(r.headers["access-control-allow-origin"], "https://addin.example.org");
    assert!(r.headers["access-control-expose-headers"].to_str().unwrap().contains("location"));

    let closed = TestApp::new().await;
    let r = closed.send(preflight("https://addin.example.org")).await;
    assert!(!r.headers.contains_key("access-control-allow-origin"));
}

/// With an API token, a GET never stores a new job without it: a template's
/// value or variants for new parameters are computed and answered, nothing
/// stored, and so is the form's page for them; their job is a 401 (it
/// would name a stored job). With the token the job is stored; its value is then read
/// without it, the job itself only with it (stored jobs are the token's
/// holders'). (Before, 22 such GETs without the token stored 69 jobs.)
#[tokio::test]
async fn a_get_stores_a_new_job_only_with_the_token() {
    let app = TestApp::with_settings(&crate::operations::with_token()).await;
    let jobs = || async { app.get_as("/v1/jobs?limit=100", "t0ken").await.json()["items"].as_array().unwrap().len() };
    let value = "/v1/templates/p103-slider-flywheel/result/inertia_exact?F=1100";
    let anonymous = app.get(value).await;
    assert_eq!(anonymous.status, StatusCode::OK, "{}", anonymous.text);
    let variants = app.get("/v1/templates/p103-class/variants?count=3&values=inertia_exact").await;
    assert_eq!(variants.status, StatusCode::OK, "{}", variants.text);
    assert!(variants.json()["variants"].as_array().unwrap().iter().all(|v| v["job"].is_null()), "{}", variants.text);
    let job = app.get("/v1/templates/p103-slider-flywheel/job?F=1100").await;
    assert_eq!(job.status, StatusCode::UNAUTHORIZED, "{}", job.text);
    let page = app.get("/templates/p103-slider-flywheel?F=1100").await;
    assert_eq!(page.status, StatusCode::OK, "the form's page of a job stored nowhere: {}", page.text);
    assert_eq!(jobs().await, 0, "a GET without the token stored a job");
    let req = Request::get(value).header("authorization", "Bearer t0ken").body(Body::empty()).unwrap();
    let with_token = app.send(req).await;
    assert_eq!(with_token.text, anonymous.text, "the same value stored or not");
    assert_eq!(jobs().await, 1, "the GET with the token stored its job");
    assert_eq!(app.get(value).await.text, anonymous.text, "its value read again without the token");
    let job = "/v1/templates/p103-slider-flywheel/job?F=1100";
    assert_eq!(app.get(job).await.status, StatusCode::UNAUTHORIZED, "a stored job is the token holders'");
    let stored = app.get_as(job, "t0ken").await;
    assert_eq!(stored.status, StatusCode::OK, "a stored job is read with the token: {}", stored.text);
}

/// SQLite: text that no row holds, as every database answers it.
#[tokio::test]
async fn text_that_no_row_holds_is_not_found_or_refused() {
    text_that_no_row_holds_on(TestApp::with_settings(&crate::operations::with_token()).await).await;
}

/// A NUL byte in a job's or a template's id finds nothing (404), in a label
/// it is refused (400), as are a label's other control characters and
/// bidirectional overrides (U+202E would show a student's label reversed).
/// On PostgreSQL, whose text cannot hold a NUL, these were "database
/// unavailable, retry" (503): a client retried for ever. For an app with the
/// settings [`crate::operations::with_token`].
pub async fn text_that_no_row_holds_on(app: TestApp) {
    for path in ["/v1/jobs/%00", "/v1/jobs/a%00b/result/x", "/v1/templates/%00", "/v1/templates/x%00/result/y"] {
        let r = app.get_as(path, "t0ken").await;
        assert_eq!(r.status, StatusCode::NOT_FOUND, "{path}: {}", r.text);
    }
    let delete = Request::delete("/v1/jobs/%00").header("authorization", "Bearer t0ken").body(Body::empty()).unwrap();
    assert_eq!(app.send(delete).await.status, StatusCode::NOT_FOUND);
    for label in ["%00", "ana%09", "%E2%80%AEfdp.exe", "x%E2%81%A6y"] {
        let r = app.get_as(&format!("/v1/jobs?label={label}"), "t0ken").await;
        assert_eq!(r.status, StatusCode::BAD_REQUEST, "?label={label}: {}", r.text);
        let req = Request::post(format!("/v1/flywheel?label={label}")).header("content-type", "application/json");
        let req = req.header("authorization", "Bearer t0ken");
        let r = app.send(req.body(Body::from(request("p103_slider").to_string())).unwrap()).await;
        assert_eq!(r.status, StatusCode::BAD_REQUEST, "POST ?label={label}: {}", r.text);
        assert_eq!(r.json()["errors"][0]["parameter"], "label", "{}", r.text);
    }
}

/// CSV injection: a name a spreadsheet would evaluate (`=`, `+`, `-`, `@`)
/// comes back in a CSV answer with a `'` before it (OWASP's advice), so the
/// sheet shows it as text; numbers, negative ones too, are written as they
/// are. A graded class (names from the class CSV) and a job's table (names
/// from the mechanism) both.
#[tokio::test]
async fn names_a_spreadsheet_would_evaluate_come_back_as_text() {
    let app = TestApp::new().await;
    let class = "student,variant,inertia_exact\n\
                 \"=HYPERLINK(\"\"http://evil.example\"\",\"\"x\"\")\",1,255\n\
                 +1+2,2,-300\n@SUM(A1),3,255\n-ana,4,255\n";
    let r = app.post_raw("/v1/templates/p103-class/grade", "text/csv", class).await;
    assert_eq!(r.status, StatusCode::OK, "{}", r.text);
    let rows: Vec<Vec<String>> = csv::Reader::from_reader(r.text.as_bytes())
        .records()
        .map(|rec| rec.unwrap().iter().map(String::from).collect())
        .collect();
    let students: Vec<&str> = rows.iter().map(|r| r[0].as_str()).collect();
    assert_eq!(students, ["'=HYPERLINK(\"http://evil.example\",\"x\")", "'+1+2", "'@SUM(A1)", "'-ana"], "{}", r.text);
    // The second student's answer is negative: its relative error is a number, written as one.
    let error: f64 = rows[1][3].parse().unwrap_or_else(|_| panic!("{:?}", rows[1]));
    assert!(error > 1.0, "{error}");
    let mut mechanism = request("k1_offset_slider_crank");
    mechanism["input"]["steps"] = 4.into();
    let text = serde_json::to_string(&mechanism).unwrap().replace("\"crank\"", "\"=crank\"");
    let job = app.post_raw("/v1/kinetostatics", "application/json", text).await;
    assert_eq!(job.status, StatusCode::CREATED, "{}", job.text);
    let table = app.get(&format!("/v1/jobs/{}/result.csv", job.json()["id"].as_str().unwrap())).await;
    assert!(table.text.contains("'=crank") && !table.text.contains(",=crank"), "{}", table.text);
}
