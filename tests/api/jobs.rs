//! Jobs are stored, listed newest first, survive a restart, and export as
//! CSV; a zero is never written -0.0.

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;

#[tokio::test]
async fn a_post_returns_the_job_exactly_as_a_later_get() {
    a_post_returns_the_job_exactly_as_a_later_get_on(TestApp::new().await).await;
}

/// The test's body, on any database (`postgres.rs` runs it on PostgreSQL).
pub async fn a_post_returns_the_job_exactly_as_a_later_get_on(app: TestApp) {
    let r = app.post("/v1/flywheel", &request("p103_slider")).await;
    assert_eq!(r.status, StatusCode::CREATED);
    let job = r.json();
    let location = r.location.unwrap();
    assert_eq!(location, format!("/v1/jobs/{}", job["id"].as_str().unwrap()));
    let again = app.get(&location).await;
    assert_eq!(again.status, StatusCode::OK);
    assert_eq!(again.text, r.text);
    assert_eq!(job["kind"], "flywheel");
    assert_eq!(job["request"], request("p103_slider"));
    assert!(job["timing"]["engine_us"].as_i64().unwrap() > 0);
}

#[tokio::test]
async fn the_request_is_stored_as_sent() {
    let app = TestApp::new().await;
    let raw = "{ \"mean_speed\" : \"60 rpm\",\"irregularity\":4e-2,\n \"torques\":[{\"name\":\"m\",\"value\":{\"expr\":\"100*sin(phi)\"}}]}";
    let r = app.post_raw("/v1/flywheel", "application/json", raw).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    assert!(r.text.contains(raw), "{}", r.text);
}

#[tokio::test]
async fn jobs_survive_a_restart() {
    jobs_survive_a_restart_on(TestApp::new().await).await;
}

/// The test's body, on any database (`postgres.rs` runs it on PostgreSQL).
pub async fn jobs_survive_a_restart_on(app: TestApp) {
    let job = app.flywheel(&request("p113_pulley")).await;
    let before = app.get(&format!("/v1/jobs/{}", job["id"].as_str().unwrap())).await.text;
    let app = app.restart().await;
    let after = app.get(&format!("/v1/jobs/{}", job["id"].as_str().unwrap())).await;
    assert_eq!(after.status, StatusCode::OK);
    assert_eq!(after.text, before);
}

#[tokio::test]
async fn the_list_is_newest_first_and_paginated() {
    the_list_is_newest_first_and_paginated_on(TestApp::new().await).await;
}

/// The test's body, on any database (`postgres.rs` runs it on PostgreSQL).
pub async fn the_list_is_newest_first_and_paginated_on(app: TestApp) {
    let mut ids = Vec::new();
    for _ in 0..5 {
        ids.push(app.flywheel(&request("p113_pulley")).await["id"].as_str().unwrap().to_string());
    }
    ids.reverse();
    let mut seen = Vec::new();
    let mut next = Some("/v1/jobs?kind=flywheel&limit=2".to_string());
    while let Some(url) = next {
        let page = app.get(&url).await.json();
        seen.extend(page["items"].as_array().unwrap().iter().map(|j| j["id"].as_str().unwrap().to_string()));
        next = page["next"].as_str().map(str::to_string);
    }
    assert_eq!(seen, ids);
    let other = app.get("/v1/jobs?kind=rotor").await.json();
    assert!(other["items"].as_array().unwrap().is_empty() && other["next"].is_null());
}

#[tokio::test]
async fn the_csv_has_a_header_with_units_and_one_row_per_sample() {
    let app = TestApp::new().await;
    let mut body = request("p103_slider");
    body["samples"] = 9.into();
    let job = app.flywheel(&body).await;
    let r = app.get(&format!("/v1/jobs/{}/result.csv", job["id"].as_str().unwrap())).await;
    assert_eq!(r.status, StatusCode::OK);
    assert!(r.content_type.starts_with("text/csv"));
    let lines: Vec<&str> = r.text.lines().collect();
    assert_eq!(lines[0], "angle_rad,reduced_torque_N_m,reduced_inertia_kg_m2,work_J,speed_rad_s");
    assert_eq!(lines.len(), 10);
    // Row 3: φ = π/2, M* = 500/π − 500, I* = 5, W = 500/π·π/2 − 500 = −250 (closed form).
    let row: Vec<f64> = lines[3].split(',').map(|v| v.parse().unwrap()).collect();
    assert!((row[0] - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    assert!((row[1] - (500.0 / std::f64::consts::PI - 500.0)).abs() < 1e-9);
    assert!((row[2] - 5.0).abs() < 1e-12 && (row[3] + 250.0).abs() < 1e-9);
}

#[tokio::test]
async fn health_openapi_and_docs_are_served() {
    let app = TestApp::new().await;
    assert_eq!(app.get("/healthz").await.status, StatusCode::OK);
    let spec = app.get("/openapi.json").await;
    assert_eq!(spec.status, StatusCode::OK);
    assert!(spec.json()["openapi"].as_str().unwrap().starts_with("3.1"));
    let docs = app.get("/docs/").await;
    assert_eq!(docs.status, StatusCode::OK);
    assert!(docs.text.contains("swagger"), "{}", &docs.text[..200.min(docs.text.len())]);
}

/// A zero is written 0.0 whatever its sign. K1's answer had 68 of its 186 zeros
/// written -0.0 by rounding (a pin's moment about itself, a reaction's
/// component across a guide), and a sheet showed "-0"; the answer, the
/// stored job read again and its CSV now have none, and are otherwise the
/// same numbers (-0.0 == 0.0).
#[tokio::test]
async fn a_zero_is_never_written_negative() {
    fn zeros(v: &serde_json::Value, signed: &mut usize, all: &mut usize) {
        match v {
            serde_json::Value::Number(n) if n.as_f64() == Some(0.0) => {
                *all += 1;
                *signed += usize::from(n.as_f64().is_some_and(f64::is_sign_negative));
            }
            serde_json::Value::Array(items) => items.iter().for_each(|v| zeros(v, signed, all)),
            serde_json::Value::Object(map) => map.values().for_each(|v| zeros(v, signed, all)),
            _ => {}
        }
    }
    let app = TestApp::new().await;
    let r = app.post("/v1/kinetostatics", &request("k1_offset_slider_crank")).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let id = r.json()["id"].as_str().unwrap().to_string();
    let again = app.get(&format!("/v1/jobs/{id}")).await;
    assert_eq!(again.text, r.text, "read back byte for byte");
    let (mut signed, mut all) = (0, 0);
    zeros(&r.json(), &mut signed, &mut all);
    assert!(all >= 100 && signed == 0, "{signed} of {all} zeros written -0.0");
    let csv = app.get(&format!("/v1/jobs/{id}/result.csv")).await;
    assert_eq!(csv.status, StatusCode::OK);
    let cells: Vec<&str> = csv.text.split([',', '\n']).collect();
    assert!(cells.iter().filter(|c| c.parse::<f64>() == Ok(0.0)).count() >= 100, "zeros in the CSV");
    assert!(!cells.iter().any(|c| c.starts_with('-') && c.parse::<f64>() == Ok(0.0)), "a -0 cell");
}
