//! Kinetostatics through the HTTP API: reference case K1 and invalid mechanisms.

use crate::helpers::{TestApp, case, close, request};
use axum::http::StatusCode;
use serde_json::{Value, json};

async fn post(app: &TestApp, body: &Value) -> Value {
    let r = app.post("/v1/kinetostatics", body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    r.json()
}

async fn errors(app: &TestApp, body: &Value) -> Vec<String> {
    let r = app.post("/v1/kinetostatics", body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    r.json()["errors"].as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap().to_string()).collect()
}

/// K1 (offset slider-crank with gravity and a gas force), 12 crank angles at
/// 150 rad/s: driving torque, every reaction and I* against the case at its
/// tolerance 1e-9 (relative to the largest force at each angle).
#[tokio::test]
async fn k1_offset_slider_crank_through_the_api() {
    let (app, c) = (TestApp::new().await, case("K1_offset_slider_crank"));
    let job = post(&app, &request("k1_offset_slider_crank")).await;
    let r = &job["result"];
    assert_eq!((r["dof"].as_u64(), r["redundant_constraints"].as_u64()), (Some(1), Some(0)));
    assert_eq!(r["grubler"], json!({"mobility": 1, "equations": 9, "unknowns": 9}));
    let rows = c["expected"]["table"].as_array().unwrap();
    for (row, step) in rows.iter().zip(r["steps"].as_array().unwrap()) {
        let scale = row["reactions"]
            .as_object()
            .unwrap()
            .values()
            .map(|v| v["magnitude_N"].as_f64().unwrap())
            .fold(1.0, f64::max);
        let t = 1e-9 * scale;
        close(&step["input"], row["phi_rad"].as_f64().unwrap(), 1e-12, "input");
        assert!((step["driving"].as_f64().unwrap() - row["T_drive_Nm"].as_f64().unwrap()).abs() < t, "{step}");
        close(&step["reduced_inertia"], row["I_star_kg_m2"].as_f64().unwrap(), 1e-9, "I*");
        for reaction in step["reactions"].as_array().unwrap() {
            let expected = &row["reactions"][reaction["joint"].as_str().unwrap()];
            assert_eq!(reaction["on"], expected["on"]);
            assert_eq!(reaction["by"], expected["from"]);
            for (got, want) in [("fx", "Fx_N"), ("fy", "Fy_N")] {
                let d = reaction[got].as_f64().unwrap() - expected[want].as_f64().unwrap();
                assert!(d.abs() < t, "{} {got}: {d}", reaction["joint"]);
            }
        }
        let piston = &step["kinematics"][2];
        close(&piston["x"], row["piston_x_m"].as_f64().unwrap(), 1e-11, "piston x");
        close(&piston["vx"], row["piston_v_m_s"].as_f64().unwrap(), 1e-9, "piston v");
        close(&piston["ax"], row["piston_a_m_s2"].as_f64().unwrap(), 1e-9, "piston a");
    }
    assert!(r["summary"]["virtual_power_residual"].as_f64().unwrap() < 1e-12);
    assert_eq!(r["summary"]["singular"], false);
}

/// Asking only for the driving torque leaves reactions, I* and kinematics out.
#[tokio::test]
async fn only_what_is_asked_is_computed() {
    let app = TestApp::new().await;
    let mut body = request("k1_offset_slider_crank");
    body["outputs"] = json!(["driving"]);
    let r = post(&app, &body).await["result"].clone();
    let step = &r["steps"][1];
    assert!(step["reactions"].is_null() && step["reduced_inertia"].is_null() && step["kinematics"].is_null());
    assert!((step["driving"].as_f64().unwrap() - -228.491215292969).abs() < 1e-6, "K1 at 30°: {step}");
}

#[tokio::test]
async fn the_csv_has_one_row_per_step_with_units() {
    let app = TestApp::new().await;
    let job = post(&app, &request("k1_offset_slider_crank")).await;
    let csv = app.get(&format!("/v1/jobs/{}/result.csv", job["id"].as_str().unwrap())).await.text;
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 13);
    assert!(
        lines[0]
            .starts_with("input_rad,driving_N_m,reduced_inertia_kg_m2,reduced_torque_N_m,jacobian_condition,O_fx_N"),
        "{}",
        lines[0]
    );
}

#[tokio::test]
async fn invalid_mechanisms_are_named_field_by_field() {
    let app = TestApp::new().await;
    let mut body = request("k1_offset_slider_crank");
    body["mechanism"]["bodies"][0]["mass"] = json!(-2);
    body["mechanism"]["joints"][1]["bodies"] = json!(["crank", "crank"]);
    body["mechanism"]["joints"][2]["bodies"][0] = json!("rood");
    body["mechanism"]["joints"][3]["axis"] = json!([0, 0]);
    body["mechanism"]["joints"][0]["at"] = json!("Q");
    body["input"]["joint"] = json!("O");
    let p = errors(&app, &body).await;
    for want in [
        "/mechanism/bodies/0/mass",
        "/mechanism/joints/1/bodies",
        "/mechanism/joints/2/bodies/0",
        "/mechanism/joints/3/axis",
        "/mechanism/joints/0/at",
    ] {
        assert!(p.iter().any(|x| x == want), "{want} missing from {p:?}");
    }
    let mut body = request("k1_offset_slider_crank");
    body["input"]["joint"] = json!("crankshaft");
    assert_eq!(errors(&app, &body).await, ["/input/joint"]);
    let mut body = request("k1_offset_slider_crank");
    body["loads"][0]["body"] = json!("ground");
    assert_eq!(errors(&app, &body).await, ["/loads/0/body"]);
}

/// A non-Grashof four-bar (s + l = 0.5 + 1.0 > p + q = 0.6 + 0.7): the crank
/// cannot turn fully; asked for a full turn the answer is a 422 naming the
/// input value where the links stop closing, not garbage. Geometry: O2 (0, 0),
/// O4 (1, 0), A (0.6, 0), B = (1.1, √0.24) so that AB = 0.7 and O4B = 0.5.
#[tokio::test]
async fn a_non_grashof_crank_asked_for_a_full_turn_is_422() {
    let app = TestApp::new().await;
    let body = json!({
        "mechanism": {
            "points": {"O2": [0, 0], "O4": [1, 0], "A": [0.6, 0], "B": [1.1, 0.24f64.sqrt()]},
            "bodies": [{"name": "crank"}, {"name": "coupler"}, {"name": "rocker"}],
            "joints": [
                {"name": "O2", "type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
                {"name": "A", "type": "revolute", "bodies": ["crank", "coupler"], "at": "A"},
                {"name": "B", "type": "revolute", "bodies": ["coupler", "rocker"], "at": "B"},
                {"name": "O4", "type": "revolute", "bodies": ["rocker", "ground"], "at": "O4"}
            ]
        },
        "input": {"joint": "O2", "speed": "60 rpm", "steps": 360}
    });
    let r = app.post("/v1/kinetostatics", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let e = &r.json()["errors"][0];
    assert_eq!(e["pointer"], "/input");
    let message = e["message"].as_str().unwrap();
    assert!(
        message.contains("at input") && (message.contains("cannot be assembled") || message.contains("singular")),
        "{message}"
    );
}
