//! The rigid rotor of seed 003 through the HTTP API (the engine's tests in
//! tests/engine/rotor.rs quote the seed's printed answers and its slips).

use crate::helpers::{TestApp, close, example};
use axum::http::StatusCode;
use serde_json::{Value, json};

/// Seed 003's disk (the documented example of `RotorRequest`): 1.5 kg,
/// G at (0, −0.04, 0.1) m, spinning at 20 rad/s about y' in a frame turning
/// at 10 rad/s, bearings at x' = ∓0.15 m, at 0° and 90°.
fn seed_disk() -> Value {
    example("RotorRequest")
}

/// At φ = 0: Y'_D = 5.35, Y'_E = 15.35, Z' = −7.5 N, the gyroscopic moment
/// 1.5 k' N·m, T = 2.5575 J, M_x = −0.1·mg; at φ = π/2 in the fixed axes
/// Z_D = −2, Z_E = 8 and Y = 7.35 + 7.5 N (seed 003 items 2, 5–7; 1e-12).
#[tokio::test]
async fn seed_003_disk_through_the_api() {
    let app = TestApp::new().await;
    let r = app.post("/v1/rotor", &seed_disk()).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let states = r.json()["result"]["states"].clone();
    let total = &states[0]["reactions"]["total"];
    close(&total["d"][1], 5.35, 1e-12, "Y'_D");
    close(&total["e"][1], 15.35, 1e-12, "Y'_E");
    close(&total["d"][2], -7.5, 1e-12, "Z'_D");
    close(&total["driving_moment"], -0.1 * 1.5 * 9.8, 1e-12, "M_x");
    close(&states[0]["gyroscopic_moment"][2], 1.5, 1e-12, "gyroscopic moment");
    close(&states[0]["kinetic_energy"], 2.5575, 1e-12, "T");
    let fixed = &states[1]["reactions_fixed"]["total"];
    close(&states[1]["t"], std::f64::consts::PI / 20.0, 1e-12, "t at 90°");
    close(&fixed["d"][2], -2.0, 1e-12, "Z_D");
    close(&fixed["e"][2], 8.0, 1e-12, "Z_E");
    close(&fixed["d"][1], 14.85, 1e-12, "Y_D");
    close(&states[1]["reactions"]["static"]["d"][2], -7.35, 1e-12, "static Z'_D");
}

/// A spin about an axis the body is not symmetric about, an impossible
/// inertia, equal bearings and both angles and times: 422 at each field.
#[tokio::test]
async fn rotor_errors_point_at_the_field() {
    let app = TestApp::new().await;
    let mut body = seed_disk();
    body["spin"] = json!([0, 0, 20]);
    body["bearings"] = json!([0.1, 0.1]);
    body["times"] = json!([0]);
    let r = app.post("/v1/rotor", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let pointers: Vec<String> =
        r.json()["errors"].as_array().unwrap().iter().map(|e| e["pointer"].as_str().unwrap().to_string()).collect();
    for p in ["/spin", "/bearings", ""] {
        assert!(pointers.contains(&p.to_string()), "{p} in {pointers:?}");
    }
    let mut bad = seed_disk();
    bad["inertia"] = json!({"xx": 1, "yy": 1, "zz": 3});
    let r = app.post("/v1/rotor", &bad).await;
    assert_eq!(r.json()["errors"][0]["pointer"], "/inertia", "{}", r.text);
}

/// Inputs at the limits of f64 (schemathesis's case: a speed of 1.8e308
/// rad/s, a bearing at 1.8e308 m) overflow the reactions: a 422 that says
/// the result is not finite, never a 201 with nulls in place of numbers.
#[tokio::test]
async fn a_rotor_that_overflows_is_refused() {
    let app = TestApp::new().await;
    let body = json!({"bearings": [4.502005810726814e16, 1.7976931348623157e308],
        "cg": [1.1320928443869089e-206, -1.1754943508222875e-38, -1.7976931348623157e308],
        "frame": {"speed": 1.7976931348623157e308}, "inertia": {"xx": 0.0, "yy": 0.0, "zz": 0.0},
        "mass": 4.502005810726814e16, "gravity": [1.1320928443869089e-206, 0.0, 0.0], "spin": [0.0, 0.0, 0.0]});
    let r = app.post("/v1/rotor", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert!(r.text.contains("non-finite"), "{}", r.text);
}
