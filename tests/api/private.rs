//! Private jobs (issue 70; contract part five, "Private jobs"): with a
//! token, every read of stored jobs needs it — each GET route of the
//! served document, taken from it so that a new route is tried too — while
//! a template's values, variants and form stay public; a browser signs in
//! once with a form and carries an HttpOnly, SameSite=Strict cookie;
//! `--public-jobs` opens the reads again. Every SVG, CSV and HTML answer
//! says `nosniff`, every SVG and HTML one has a Content-Security-Policy.

use crate::helpers::{Reply, TestApp, request};
use axum::body::Body;
use axum::http::{Request, StatusCode};
use mechdyn::api::Settings;
use serde_json::Value;

const TOKEN: &str = "cl4ss-t0ken";

fn settings(public_jobs: bool) -> Settings {
    Settings { api_token: Some(TOKEN.into()), public_jobs, ..Settings::default() }
}

/// A job of each sort the reads need, POSTed with the token: K1 (plots, a
/// table), a cam (a file of its own). Their ids.
async fn jobs(app: &TestApp) -> (String, String) {
    let post = |path: &'static str, body: Value| {
        let req = Request::post(path).header("content-type", "application/json");
        req.header("authorization", format!("Bearer {TOKEN}")).body(Body::from(body.to_string())).unwrap()
    };
    let k1 = app.send(post("/v1/kinetostatics", request("k1_offset_slider_crank"))).await;
    assert_eq!(k1.status, StatusCode::CREATED, "{}", k1.text);
    let cam = app.send(post("/v1/cams", crate::helpers::example("CamRequest"))).await;
    assert_eq!(cam.status, StatusCode::CREATED, "{}", cam.text);
    (k1.json()["id"].as_str().unwrap().into(), cam.json()["id"].as_str().unwrap().into())
}

/// Every GET path of the served document, made concrete: a job's id, its
/// plot, file and part; a template's id and parameter.
async fn read_routes(app: &TestApp, (k1, cam): &(String, String)) -> Vec<String> {
    let doc = app.get("/openapi.json").await.json();
    let mut routes = Vec::new();
    for (path, item) in doc["paths"].as_object().unwrap() {
        if item.get("get").is_none() {
            continue;
        }
        let concrete = if path.ends_with("/variants") {
            path.replace("{id}", "p103-class")
        } else if path.starts_with("/v1/templates/{id}") || path.starts_with("/templates/") {
            path.replace("{id}", "p103-slider-flywheel").replace("{pointer}", "inertia_exact")
        } else if path == "/v1/jobs/{id}/{name}" {
            format!("/v1/jobs/{cam}/profile.dxf")
        } else {
            path.replace("{id}", k1).replace("{name}", "mechanism").replace("{pointer}", "dof")
        };
        routes.push(concrete);
    }
    routes
}

/// Whether a path reads stored jobs.
fn private(path: &str) -> bool {
    path.starts_with("/v1/jobs") || path.starts_with("/jobs/") || path.ends_with("/job")
}

/// With a token, every read route of the document is refused without it
/// where it reads stored jobs (401; a page shows the sign-in form) and
/// answered where it does not; with the token every one is answered; with
/// `--public-jobs` every one is answered without it.
#[tokio::test]
async fn every_read_of_stored_jobs_needs_the_token_and_only_those() {
    let app = TestApp::with_settings(&settings(false)).await;
    let ids = jobs(&app).await;
    let routes = read_routes(&app, &ids).await;
    assert!(routes.len() >= 20, "{routes:?}");
    for path in &routes {
        let without = app.get(path).await;
        if private(path) {
            assert_eq!(without.status, StatusCode::UNAUTHORIZED, "{path}: {}", without.text);
            assert_eq!(without.headers["www-authenticate"], "Bearer", "{path}");
            assert!(!without.text.contains("piston"), "{path} shows the job: {}", without.text);
            if path.starts_with("/jobs/") {
                assert!(without.content_type.starts_with("text/html"), "{path}: {}", without.content_type);
                assert!(without.text.contains(r#"action="/signin""#), "{path}: the sign-in form");
            } else {
                assert_eq!(without.json()["type"], "/problems/unauthorized", "{path}");
            }
        } else {
            assert_ne!(without.status, StatusCode::UNAUTHORIZED, "{path} is public: {}", without.text);
        }
        let with = app.get_as(path, TOKEN).await;
        assert!(with.status.is_success(), "{path} with the token: {} {}", with.status, with.text);
    }
    let public = TestApp::with_settings(&settings(true)).await;
    let ids = jobs(&public).await;
    for path in read_routes(&public, &ids).await {
        // A template's job is stored by a holder first: a GET without the token stores nothing.
        assert!(public.get_as(&path, TOKEN).await.status.is_success(), "{path}");
        let r = public.get(&path).await;
        assert!(r.status.is_success(), "{path} of public jobs: {} {}", r.status, r.text);
    }
}

/// The home page lists the recent jobs only to a token's holder; to
/// another it shows the sign-in form. A template's value is answered to
/// anyone (a spreadsheet's WEBSERVICE() sends no header).
#[tokio::test]
async fn the_home_page_lists_jobs_only_to_the_token_holders() {
    let app = TestApp::with_settings(&settings(false)).await;
    let (k1, _) = jobs(&app).await;
    let anonymous = app.get("/").await;
    assert_eq!(anonymous.status, StatusCode::OK);
    assert!(!anonymous.text.contains(&k1) && anonymous.text.contains(r#"action="/signin""#), "{}", anonymous.text);
    let holder = app.get_as("/", TOKEN).await;
    assert!(holder.text.contains(&k1) && holder.text.contains(r#"action="/signout""#), "{}", holder.text);
    let value = app.get("/v1/templates/p103-slider-flywheel/result/inertia_exact").await;
    assert_eq!(value.status, StatusCode::OK, "{}", value.text);
    assert!(value.text.parse::<f64>().is_ok(), "{}", value.text);
}

/// A template's form computed by a browser without the token shows the
/// job's page at once, stored nowhere: its values (the one the value route
/// answers, to the page's four figures), its plots drawn into the page as
/// `data:` pictures (no link to a job that is not there), an offer to sign
/// in; and no job is stored. Before, such a browser was asked to sign in.
#[tokio::test]
async fn a_forms_job_without_the_token_is_shown_and_stored_nowhere() {
    let app = TestApp::with_settings(&settings(false)).await;
    let count = || async { app.get_as("/v1/jobs?limit=100", TOKEN).await.json()["items"].as_array().unwrap().len() };
    let page = app.get("/templates/p103-slider-flywheel?F=1150").await;
    assert_eq!(page.status, StatusCode::OK, "{}", page.text);
    let value: f64 =
        app.get("/v1/templates/p103-slider-flywheel/result/inertia_exact?F=1150").await.text.parse().unwrap();
    // Four significant figures, as the page writes every value (`{:.4}` of the mantissa would be five).
    let shown = format!("{}", format!("{:.3e}", value).parse::<f64>().unwrap());
    let row = format!(r#"<td class="ptr">inertia_exact</td><td class="num">{shown}</td>"#);
    assert!(page.text.contains(&row), "{row} in the page: {}", page.text);
    assert!(page.text.matches(r#"<img src="data:image/svg+xml"#).count() >= 2, "plots drawn in: {}", page.text);
    assert!(!page.text.contains("/v1/jobs/") && !page.text.contains("href=\"/jobs/"), "no link to an unstored job");
    assert!(page.text.contains(r#"href="/signin""#), "the offer to sign in");
    assert_eq!(count().await, 0, "nothing stored");
    let spanish = app.get("/templates/p103-slider-flywheel?F=1150&lang=es").await;
    assert!(spanish.text.contains("no se guardó"), "{}", spanish.text);
    assert!(spanish.text.contains(&row.replace('.', ",")), "decimal comma: {}", spanish.text);
}

async fn sign_in(app: &TestApp, form: &str) -> Reply {
    let req = Request::post("/signin").header("content-type", "application/x-www-form-urlencoded");
    app.send(req.body(Body::from(form.to_string())).unwrap()).await
}

/// A browser signs in once: the form's POST with the token sets a cookie
/// (HttpOnly, SameSite=Strict, not the token itself) and goes on to the
/// page asked; with the cookie the job's page and its plots are read, and
/// new jobs stored from a template's form; a wrong token is the form again (401); signing out
/// clears the cookie; `next` never leads away from the service.
#[tokio::test]
async fn a_browser_signs_in_once_with_a_cookie_that_is_not_the_token() {
    let app = TestApp::with_settings(&settings(false)).await;
    let (k1, _) = jobs(&app).await;
    let page = format!("/jobs/{k1}?step=3");
    let refused = app.get(&page).await;
    assert!(refused.text.contains(r#"name="next" value="/jobs/"#), "the form comes back to the page: {}", refused.text);
    let wrong = sign_in(&app, "token=guess&next=%2Fjobs%2Fx").await;
    assert_eq!(wrong.status, StatusCode::UNAUTHORIZED);
    assert!(!wrong.headers.contains_key("set-cookie"));
    let next = page.replace('/', "%2F").replace('?', "%3F").replace('=', "%3D");
    let signed = sign_in(&app, &format!("token={TOKEN}&next={next}")).await;
    assert_eq!((signed.status, signed.location.as_deref()), (StatusCode::SEE_OTHER, Some(page.as_str())));
    let set = signed.headers["set-cookie"].to_str().unwrap().to_string();
    assert!(set.contains("HttpOnly") && set.contains("SameSite=Strict") && set.contains("Path=/"), "{set}");
    assert!(!set.contains(TOKEN), "the cookie is not the token: {set}");
    let cookie = set.split(';').next().unwrap().to_string();
    let with_cookie = |path: &str| Request::get(path).header("cookie", &cookie).body(Body::empty()).unwrap();
    let shown = app.send(with_cookie(&page)).await;
    assert_eq!(shown.status, StatusCode::OK, "{}", shown.text);
    assert_eq!(
        app.send(with_cookie(&format!("/v1/jobs/{k1}/plots/mechanism.svg?step=3"))).await.status,
        StatusCode::OK
    );
    let stored = app.send(with_cookie("/templates/p103-slider-flywheel?F=1150")).await;
    assert_eq!(stored.status, StatusCode::SEE_OTHER, "a signed-in form stores its job: {}", stored.text);
    let out = app.send(Request::post("/signout").header("cookie", &cookie).body(Body::empty()).unwrap()).await;
    assert_eq!(out.status, StatusCode::SEE_OTHER);
    assert!(out.headers["set-cookie"].to_str().unwrap().contains("Max-Age=0"));
    let away = sign_in(&app, &format!("token={TOKEN}&next=https%3A%2F%2Fevil.example%2F")).await;
    assert_eq!(away.location.as_deref(), Some("/"));
}

/// Every SVG, CSV and HTML answer carries `X-Content-Type-Options:
/// nosniff`; every SVG and HTML one a Content-Security-Policy that allows
/// no script from elsewhere (the pages' allows none at all).
#[tokio::test]
async fn svg_csv_and_html_answers_say_nosniff_and_their_policy() {
    let app = TestApp::new().await;
    let k1 = app.post("/v1/kinetostatics", &request("k1_offset_slider_crank")).await.json();
    let id = k1["id"].as_str().unwrap();
    let answers = [
        (format!("/v1/jobs/{id}/plots/mechanism.svg"), "image/svg+xml"),
        (format!("/v1/jobs/{id}/result.csv"), "text/csv"),
        (format!("/v1/jobs/{id}/values.csv"), "text/csv"),
        (format!("/jobs/{id}"), "text/html"),
        ("/".into(), "text/html"),
        ("/docs/".into(), "text/html"),
    ];
    for (path, kind) in answers {
        let r = app.get(&path).await;
        assert!(r.content_type.starts_with(kind), "{path}: {}", r.content_type);
        assert_eq!(r.headers["x-content-type-options"], "nosniff", "{path}");
        if kind != "text/csv" {
            let policy = r.headers["content-security-policy"].to_str().unwrap();
            assert!(policy.contains("default-src 'none'") || policy.contains("script-src 'self'"), "{path}: {policy}");
            assert!(!policy.contains("unsafe-eval") && !policy.contains("script-src *"), "{path}: {policy}");
        }
    }
}
