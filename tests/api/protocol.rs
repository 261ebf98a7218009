//! HTTP's own rules, as clients exercise them: a query parameter given
//! twice, the bearer scheme in another case, an HTTP/1.0 POST without a
//! length, a byte order mark before a JSON body.

use crate::helpers::{TestApp, request};
use axum::body::Body;
use axum::http::{Request, StatusCode, Version};

/// `F=1&F=2` asks two questions: a 400 naming the parameter, on every
/// route (before, the last value was taken silently); a page's is a page.
#[tokio::test]
async fn a_parameter_given_twice_is_a_400_naming_it() {
    let app = TestApp::new().await;
    let page = app.get("/templates/p103-slider-flywheel?F=1000&eps=0.03&F=1200").await;
    assert_eq!(page.status, StatusCode::BAD_REQUEST, "{}", page.text);
    assert!(page.content_type.starts_with("text/html"), "{}", page.content_type);
    assert!(page.text.contains("F: is given more than once"), "{}", page.text);
    for path in [
        "/v1/templates/p103-slider-flywheel/result/inertia_exact?F=1000&F=1200",
        "/v1/jobs?limit=2&kind=flywheel&limit=3",
    ] {
        let r = app.get(path).await;
        assert_eq!(r.status, StatusCode::BAD_REQUEST, "{path}: {}", r.text);
        assert_eq!(r.json()["type"], "/problems/invalid-query", "{path}: {}", r.text);
        let twice = r.json()["errors"][0]["parameter"].as_str().unwrap().to_string();
        assert!(path.contains(&format!("{twice}=")) && path.matches(&format!("{twice}=")).count() == 2, "{path}");
        assert!(r.json()["errors"][0]["message"].as_str().unwrap().contains("more than once"), "{}", r.text);
    }
}

/// `Authorization: bearer …`: the scheme's name is case-insensitive (RFC
/// 9110, 11.1), so the token in lower case is the token.
#[tokio::test]
async fn the_bearer_scheme_is_read_in_any_case() {
    let settings = crate::operations::with_token();
    let app = TestApp::with_settings(&settings).await;
    for scheme in ["bearer", "BEARER", "Bearer"] {
        let req = Request::post("/v1/flywheel").header("content-type", "application/json");
        let req = req.header("authorization", format!("{scheme} t0ken"));
        let r = app.send(req.body(Body::from(request("p103_slider").to_string())).unwrap()).await;
        assert_eq!(r.status, StatusCode::CREATED, "{scheme}: {}", r.text);
    }
    let req = Request::post("/v1/flywheel").header("content-type", "application/json");
    let req = req.header("authorization", "bearer wrong");
    let r = app.send(req.body(Body::from(request("p103_slider").to_string())).unwrap()).await;
    assert_eq!(r.status, StatusCode::UNAUTHORIZED, "{}", r.text);
}

/// An HTTP/1.0 POST without `Content-Length` has no way to say where its
/// body ends: 411 Length Required, not "the body is not valid JSON".
#[tokio::test]
async fn an_http_1_0_post_without_a_length_is_411() {
    let app = TestApp::new().await;
    let req = Request::post("/v1/flywheel").version(Version::HTTP_10).header("content-type", "application/json");
    let r = app.send(req.body(Body::from(request("p103_slider").to_string())).unwrap()).await;
    assert_eq!(r.status, StatusCode::LENGTH_REQUIRED, "{}", r.text);
    assert_eq!(r.json()["type"], "/problems/length-required");
    assert!(r.json()["detail"].as_str().unwrap().contains("Content-Length"), "{}", r.text);
}

/// A UTF-8 byte order mark before a JSON body (Notepad, some spreadsheet
/// macros write one) is ignored, as RFC 8259 (8.1) allows: the job is
/// computed, and stored without it.
#[tokio::test]
async fn a_byte_order_mark_before_a_json_body_is_ignored() {
    let app = TestApp::new().await;
    let body = format!("\u{feff}{}", request("p103_slider"));
    let r = app.post_raw("/v1/flywheel", "application/json", body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    assert_eq!(r.json()["request"], request("p103_slider"));
    let stored = app.get(&format!("/v1/jobs/{}", r.json()["id"].as_str().unwrap())).await;
    assert!(!stored.text.contains('\u{feff}'), "the mark was stored");
}

/// A client that asks `Expect: 100-continue` (curl does, for large bodies)
/// waits for the answer before it sends its body: refused at once (401),
/// it is told so at once, without a `100 Continue` asking it to send a
/// body that is refused (reading the body to drain it would send one).
#[test]
fn a_client_that_waits_to_send_is_answered_at_once() {
    use std::io::{Read, Write};
    let dir = tempfile::tempdir().unwrap();
    let port = crate::crash::free_port();
    let db = format!("sqlite://{}/jobs.db", dir.path().display());
    let mut child = crate::crash::start_with(&db, port, &[("MECHDYN_API_TOKEN", "t0ken")]);
    let mut s = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.set_read_timeout(Some(std::time::Duration::from_secs(5))).unwrap();
    let head = "POST /v1/flywheel HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\n\
                Content-Length: 1000000\r\nExpect: 100-continue\r\n\r\n";
    s.write_all(head.as_bytes()).unwrap();
    let mut first = [0u8; 12];
    let read = s.read_exact(&mut first);
    child.kill().unwrap();
    child.wait().unwrap();
    read.expect("an answer within 5 s, the body unsent");
    assert_eq!(&first, b"HTTP/1.1 401", "{}", String::from_utf8_lossy(&first));
}
