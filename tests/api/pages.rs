//! The HTML pages through the real router: the home page, a job's page, a
//! template's form and its round trip, errors as pages, and escaping.
//! (`browser.rs` loads the same pages in a real Chromium.)

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::json;

fn html(r: &crate::helpers::Reply) -> &str {
    assert!(r.content_type.starts_with("text/html"), "{} {}", r.content_type, r.text);
    let policy = r.headers.get("content-security-policy").and_then(|v| v.to_str().ok()).unwrap_or("");
    assert!(policy.contains("default-src 'none'"), "no script, nothing from elsewhere: {policy}");
    assert!(!r.text.contains("<script"), "a page has no script");
    &r.text
}

#[tokio::test]
async fn the_home_page_lists_templates_and_recent_jobs() {
    let app = TestApp::new().await;
    let id = app.post("/v1/flywheel?label=lab%201", &request("p103_slider")).await.json()["id"]
        .as_str()
        .unwrap()
        .to_string();
    let r = app.get("/").await;
    assert_eq!(r.status, StatusCode::OK);
    let page = html(&r);
    assert!(page.contains(&format!("href=\"/jobs/{id}\"")), "the job links its page");
    assert!(page.contains("lab 1"), "its label");
    assert!(page.contains("href=\"/templates/p103-slider-flywheel\""));
    assert!(page.contains("href=\"/docs/\"") && page.contains("href=\"/openapi.json\""));
}

#[tokio::test]
async fn a_jobs_page_has_its_values_with_units_accuracy_time_plots_and_links() {
    let app = TestApp::new().await;
    let job = app.post("/v1/flywheel", &request("p103_slider")).await.json();
    let id = job["id"].as_str().unwrap();
    let r = app.get(&format!("/jobs/{id}")).await;
    assert_eq!(r.status, StatusCode::OK, "{}", r.text);
    let page = html(&r);
    // The value to four significant figures as a person reads it, with its
    // unit, linked to the full value as the JSON has it (shortest round-trip form).
    let exact = job["result"]["inertia_exact"].as_f64().unwrap();
    let link = format!("/v1/jobs/{id}/result/inertia_exact");
    let row = format!(
        "inertia_exact</td><td class=\"num\"><a href=\"{link}\" title=\"the full value\">{exact:.1}</a></td><td>kg*m^2</td>"
    );
    assert!(page.contains(&row), "{row} in the page");
    assert_eq!(app.get(&link).await.text, exact.to_string(), "the full value one click away");
    assert!(page.contains("estimated relative error"), "accuracy");
    assert!(page.contains("of engine time"), "timing");
    for plot in ["torque", "work", "speed", "wittenbauer"] {
        assert!(page.contains(&format!("src=\"/v1/jobs/{id}/plots/{plot}.svg\"")), "{plot}");
    }
    for link in
        [format!("/v1/jobs/{id}"), format!("/v1/jobs/{id}/result.csv"), format!("/v1/jobs/{id}/values?format=csv")]
    {
        assert!(page.contains(&format!("href=\"{link}\"")), "{link}");
    }
    // Every link of the page answers (a link to a route that is not there was one).
    let links: Vec<String> =
        page.split("href=\"").skip(1).map(|h| h[..h.find('"').unwrap()].replace("&amp;", "&")).collect();
    for link in links.iter().filter(|l| l.starts_with('/')) {
        assert_eq!(app.get(link).await.status, StatusCode::OK, "{link}");
    }
    // 361 rows: a flywheel's default samples, one a degree over the cycle.
    assert!(page.contains("<code>/samples</code> (361 rows)"), "a long table is named, its rows left to the CSV");
    assert!(!page.contains("samples/0/"), "no row of it in the page");
}

#[tokio::test]
async fn a_templates_form_computes_its_job_and_shows_errors_at_their_field() {
    let app = TestApp::new().await;
    let r = app.get("/templates/p103-slider-flywheel").await;
    assert_eq!(r.status, StatusCode::OK);
    let page = html(&r);
    for (name, default) in [("F", "500"), ("eps", "0.04"), ("speed", "60 rpm")] {
        assert!(page.contains(&format!("name=\"{name}\" type=\"text\"")), "{name}");
        assert!(page.contains(&format!("value=\"{default}\"")), "{name} at {default}");
    }
    assert!(page.contains("method=\"get\" action=\"/templates/p103-slider-flywheel\""));
    // Submitting: the job of these parameters, the same the JSON route gives.
    let r = app.get("/templates/p103-slider-flywheel?F=1200&I0=5&eps=0.03&speed=60%20rpm").await;
    assert_eq!(r.status, StatusCode::SEE_OTHER);
    let location = r.location.clone().unwrap();
    let same = app.get("/v1/templates/p103-slider-flywheel/job?F=1200&eps=0.03").await;
    assert_eq!(location, same.headers["content-location"].to_str().unwrap().replace("/v1/jobs/", "/jobs/"));
    assert_eq!(app.get(&location).await.status, StatusCode::OK);
    // A blank field keeps its default.
    let r = app.get("/templates/p103-slider-flywheel?F=1200&I0=&eps=0.03&speed=").await;
    assert_eq!(r.location.as_deref(), Some(location.as_str()));
    // A name the template has not, even blank, is refused, not ignored (found by schemathesis, seed 14681382).
    let r = app.get("/templates/p103-slider-flywheel?F=1200&nope=").await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST);
    assert!(html(&r).contains("nope"), "the unknown name is said");
    // A value out of range: the form again, the message at its field, the value kept.
    let r = app.get("/templates/p103-slider-flywheel?F=-3&eps=0.03").await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST);
    let page = html(&r);
    assert!(page.contains("value=\"-3\""), "the value given is kept");
    let after_f = &page[page.find("name=\"F\"").unwrap()..];
    let error = after_f.find("class=\"error\"").unwrap();
    assert!(!after_f[..error].contains("<input"), "the message is under F's field, before the next one");
    assert!(after_f[error..].contains("-3 is below the least value, 0 N*m"), "{page}");
}

#[tokio::test]
async fn errors_are_pages_with_their_status() {
    let app = TestApp::new().await;
    let r = app.get("/jobs/no-such-job").await;
    assert_eq!(r.status, StatusCode::NOT_FOUND);
    assert!(html(&r).contains("no job with id"));
    let r = app.get("/templates/nothing").await;
    assert_eq!(r.status, StatusCode::NOT_FOUND);
    assert!(html(&r).contains("no template with id"));
    let id = app.post("/v1/kinetostatics", &request("k1_offset_slider_crank")).await.json()["id"]
        .as_str()
        .unwrap()
        .to_string();
    let r = app.get(&format!("/jobs/{id}?step=99")).await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST);
    assert!(html(&r).contains("0 to 11"));
    // A blank step (a cleared form field) is no whole number: 400, not the page.
    let r = app.get(&format!("/jobs/{id}?step=")).await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST);
    assert!(html(&r).contains("must be a whole number"), "{}", r.text);
    let r = app.get(&format!("/jobs/{id}?step=4")).await;
    assert!(html(&r).contains(&format!("/v1/jobs/{id}/plots/mechanism.svg?step=4")), "the drawing at the step asked");
}

/// A label or a body name with markup stays text, escaped, everywhere.
#[tokio::test]
async fn markup_in_labels_and_names_stays_text() {
    let app = TestApp::new().await;
    let evil = "<script>alert(1)</script>";
    let mut k1 = request("k1_offset_slider_crank");
    k1["mechanism"]["bodies"][0]["name"] = json!(evil);
    for j in k1["mechanism"]["joints"].as_array_mut().unwrap() {
        for b in j["bodies"].as_array_mut().unwrap() {
            if b == "crank" {
                *b = json!(evil);
            }
        }
    }
    let label = "%3Cimg%20src%3Dx%20onerror%3Dalert(1)%3E";
    let r = app.post(&format!("/v1/kinetostatics?label={label}"), &k1).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let id = r.json()["id"].as_str().unwrap().to_string();
    for path in [format!("/jobs/{id}"), "/".to_string()] {
        let r = app.get(&path).await;
        let page = html(&r);
        assert!(page.contains("&lt;img src=x onerror=alert(1)&gt;"), "{path}: the label as text");
        assert!(!page.contains("<img src=x"), "{path}");
    }
    let page = app.get(&format!("/jobs/{id}")).await.text;
    assert!(page.contains("&lt;script&gt;alert(1)&lt;/script&gt;"), "the body's name as text");
    // A label that would reverse the text after it ("evil" shown as "live") is refused at the POST;
    // one stored before that rule is shown with its mark as U+FFFD, not obeyed.
    let r = app.post("/v1/kinetostatics?label=%E2%80%AElive", &request("k1_offset_slider_crank")).await;
    assert_eq!(r.status, StatusCode::BAD_REQUEST, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["parameter"], "label", "{}", r.text);
    let store = mechdyn::store::Store::open(&app.url).await.unwrap();
    let old = mechdyn::store::NewJob {
        id: uuid::Uuid::new_v4().to_string(),
        kind: "flywheel".into(),
        created_at: "2026-11-01T00:00:00.000000Z".into(),
        request: "{}".into(),
        result: "{}".into(),
        engine_us: 1,
        engine_version: "0.1.0".into(),
        request_key: None,
        label: Some("\u{202E}live".into()),
    };
    store.insert(old).await.unwrap();
    let home = app.get("/").await.text;
    assert!(home.contains("\u{FFFD}live") && !home.contains('\u{202E}'), "the direction mark is shown, not obeyed");
}
