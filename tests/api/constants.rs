//! `constants` in requests, and a Function's table with its angles in
//! degrees or given as CSV text: each must give the job the plain SI form
//! gives (the same numbers reach the engine), and bad input is named.

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::{Value, json};

/// P.103 with the load's amplitude as a constant F.
fn p103_with(f: Value, expr: &str) -> Value {
    let mut body = request("p103_slider");
    body["constants"] = json!({"F": f});
    body["torques"][0]["value"]["segments"][0]["expr"] = json!(expr);
    body
}

#[tokio::test]
async fn a_constant_reads_as_its_si_value_in_every_expression() {
    let app = TestApp::new().await;
    let plain = app.flywheel(&request("p103_slider")).await["result"].clone();
    // -500*sin(phi) and -F*sin(phi) with F = 500 fold to the same tree: the same doubles.
    for f in [json!(500), json!("0.5 kN"), json!("500 N")] {
        let with = app.flywheel(&p103_with(f.clone(), "-F*sin(phi)")).await["result"].clone();
        assert_eq!(with["inertia_exact"], plain["inertia_exact"], "F = {f}");
        assert_eq!(with["warnings"], plain["warnings"], "F = {f}");
    }
    // In an angle field too: the segment's end as a constant expression.
    let mut body = p103_with(json!(500), "-F*sin(phi)");
    body["constants"]["half"] = json!("180 deg");
    body["torques"][0]["value"]["segments"][0]["to"] = json!("half");
    let with = app.flywheel(&body).await["result"].clone();
    assert!((with["inertia_exact"].as_f64().unwrap() / plain["inertia_exact"].as_f64().unwrap() - 1.0).abs() < 1e-12);
}

#[tokio::test]
async fn an_unused_constant_is_a_warning_and_bad_names_are_named() {
    let app = TestApp::new().await;
    let mut body = p103_with(json!(500), "-F*sin(phi)");
    body["constants"]["Fo"] = json!(1);
    let job = app.flywheel(&body).await;
    let warnings = job["result"]["warnings"].to_string();
    assert!(warnings.contains("constant Fo is not used"), "{warnings}");
    assert!(!warnings.contains("constant F "), "{warnings}");

    let mut bad = p103_with(json!(500), "-F*sin(phi)");
    bad["constants"] = json!({"F": 500, "2F": 1, "phi": 2, "sin": 3, "L": "3 furlongs"});
    bad["irregularity"] = json!(2.5);
    let errors = app.flywheel_422(&bad).await;
    let pointers: Vec<&str> = errors.iter().map(|(p, _)| p.as_str()).collect();
    for p in ["/constants/2F", "/constants/phi", "/constants/sin", "/constants/L", "/irregularity"] {
        assert!(pointers.contains(&p), "{p} not in {errors:?}");
    }
    // A name that is not a constant says which ones there are.
    let unknown = app.flywheel_422(&p103_with(json!(500), "-G*sin(phi)")).await;
    assert!(unknown[0].1.contains("constants: F, pi, e"), "{unknown:?}");
}

/// A flywheel whose load is the table `rows` (angle, N·m) written as `value`.
fn table_job(value: Value) -> Value {
    json!({
        "mean_speed": "60 rpm", "irregularity": 0.04, "reduced_inertia": 5,
        "torques": [{"name": "press", "value": value}, {"name": "motor", "balance": true}]
    })
}

fn sine_rows() -> Vec<(f64, f64)> {
    (0..36).map(|k| (10.0 * k as f64, -500.0 * (10f64 * k as f64).to_radians().sin().max(0.0))).collect()
}

#[tokio::test]
async fn a_table_in_degrees_or_as_csv_is_the_same_table() {
    let app = TestApp::new().await;
    let rows = sine_rows();
    let rad = json!({"table": {"angle": rows.iter().map(|r| r.0.to_radians()).collect::<Vec<_>>(),
        "value": rows.iter().map(|r| r.1).collect::<Vec<_>>()}});
    let deg = json!({"table": {"angle": rows.iter().map(|r| r.0).collect::<Vec<_>>(),
        "value": rows.iter().map(|r| r.1).collect::<Vec<_>>()}, "angle_unit": "deg"});
    let mut text = String::from("phi_deg,M_N_m\n");
    for (a, v) in &rows {
        text += &format!("{a},{v:?}\n");
    }
    let csv = json!({"csv": text, "angle_unit": "deg"});
    let kn = json!({"csv": text.replace(',', ";").replace('.', ","), "angle_unit": "deg", "unit": "N*m"});
    let reference = app.flywheel(&table_job(rad)).await["result"]["inertia_exact"].as_f64().unwrap();
    for (name, value) in [("degrees", deg), ("csv", csv), ("csv with ; and decimal commas", kn)] {
        let r = app.flywheel(&table_job(value)).await["result"]["inertia_exact"].as_f64().unwrap();
        // The angles differ by the rounding of k·10·π/180 against (k·10)·(π/180) at most.
        assert!((r / reference - 1.0).abs() < 1e-12, "{name}: {r} vs {reference}");
    }
}

#[tokio::test]
async fn a_bad_csv_table_names_its_row() {
    let app = TestApp::new().await;
    let errors = app.flywheel_422(&table_job(json!({"csv": "0,1\n90,2\n180,x\n"}))).await;
    assert_eq!(errors[0].0, "/torques/0/value/csv");
    assert!(errors[0].1.starts_with("row 3:"), "{errors:?}");
    let both = app.flywheel_422(&table_job(json!({"csv": "0,1\n", "table": {"angle": [0], "value": [1]}}))).await;
    assert_eq!(both[0].0, "/torques/0/value");
    let r = app.post("/v1/flywheel", &table_job(json!({"expr": "1", "angle_unit": "deg"}))).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY);
    assert_eq!(r.json()["errors"][0]["pointer"], "/torques/0/value/angle_unit");
}
