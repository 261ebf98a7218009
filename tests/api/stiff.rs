//! A stiff model through the service: the automatic integrator hands over
//! to Radau IIA and says so.

use crate::helpers::TestApp;
use axum::http::StatusCode;
use serde_json::{Value, json};

/// The pendulum's bob (1 kg at 1 m) tied to the ground at (2, 0) by a
/// spring of 10¹⁰ N/m and free length 0.9 m (IFToMM A05-like; the same
/// machine as tests/api/dynamics.rs's budget test). About θ = 0 the
/// spring's stiffness in θ is k·(d − l₀)·d″ = 0.2k, so gravity's
/// −9.81 N·m holds the bob at θₑ = −9.81/(0.2k) = −4.905 nrad (closed
/// form), and from rest at 0 it rings about θₑ at 4.5·10⁴ rad/s. At the
/// default tolerance that ringing (2.2e-4 rad/s) is part of the answer and
/// must be followed: the budget test. At tolerance 1e-3 it is not:
/// posted with the integrator left to `auto`, Dormand–Prince finds its
/// steps held by stability and hands over to Radau IIA, which damps the
/// ringing in a few steps and finishes the 100 s at once; the answer is
/// 201 with `accuracy.integrator` `radau5`, `accuracy.stiff_at` (within
/// the first 10 ms), the method text saying why, and every sample between
/// 0 and 2θₑ, the last half at θₑ to 1e-10 rad (2 %; measured 1.2e-11).
#[tokio::test]
async fn a_stiff_spring_is_handed_to_radau_and_reported() {
    let app = TestApp::new().await;
    let body = json!({
        "machine": {
            "mechanism": {
                "bodies": [{"name": "bob", "mass": 1, "inertia": 0.01, "cg": [1, 0]}],
                "joints": [{"name": "O", "type": "revolute", "bodies": ["ground", "bob"], "at": [0, 0]}],
                "gravity": [0, -9.81]
            },
            "input": {"joint": "O"},
            "loads": [{"type": "spring", "a": ["bob", [1, 0]], "b": ["ground", [2, 0]], "stiffness": "1e10 N/m", "free_length": 0.9}]
        },
        "duration": "100 s",
        "tolerance": 1e-3
    });
    let r = app.post("/v1/dynamics", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let result = &r.json()["result"];
    let accuracy = &result["accuracy"];
    assert_eq!(accuracy["integrator"], "radau5", "{accuracy}");
    assert!(accuracy["stiff_at"].as_f64().is_some_and(|t| t > 0.0 && t < 0.01), "{accuracy}");
    assert!(accuracy["method"].as_str().unwrap().contains("found the model stiff"), "{accuracy}");
    let theta_e = -9.81 / (0.2 * 1e10);
    let samples: Vec<&Value> = result["samples"].as_array().unwrap().iter().collect();
    for (k, s) in samples.iter().enumerate() {
        let (t, angle) = (s["t"].as_f64().unwrap(), s["angle"].as_f64().unwrap());
        assert!(angle <= 1e-12 && angle >= 2.0 * theta_e - 1e-12, "t = {t}: θ = {angle}");
        if 2 * k >= samples.len() {
            assert!((angle - theta_e).abs() < 1e-10, "t = {t}: θ = {angle}, θₑ = {theta_e}");
        }
    }
}
