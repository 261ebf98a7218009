//! A stiff spring through the service: where its ringing is part of the
//! answer the job meets its budget with the reason; where the tolerance
//! lets it go, the automatic integrator hands over to Radau IIA and says so.
//!
//! The machine (IFToMM A05-like): the pendulum's bob (1 kg at 1 m) tied to
//! the ground at (2, 0) by a spring of 10¹⁰ N/m and free length 0.9 m.
//! About θ = 0 the spring's stiffness in θ is k·(d − l₀)·d″ = 0.2k, so
//! gravity's −9.81 N·m holds the bob at θₑ = −9.81/(0.2k) = −4.905 nrad
//! (closed form), and from rest at 0 it rings about θₑ at 4.5·10⁴ rad/s
//! with a speed of 2.2e-4 rad/s.

use crate::helpers::TestApp;
use axum::http::StatusCode;
use serde_json::{Value, json};

fn bob_on_a_stiff_spring(tolerance: Option<f64>) -> Value {
    let mut body = json!({
        "machine": {
            "mechanism": {
                "bodies": [{"name": "bob", "mass": 1, "inertia": 0.01, "cg": [1, 0]}],
                "joints": [{"name": "O", "type": "revolute", "bodies": ["ground", "bob"], "at": [0, 0]}],
                "gravity": [0, -9.81]
            },
            "input": {"joint": "O"},
            "loads": [{"type": "spring", "a": ["bob", [1, 0]], "b": ["ground", [2, 0]], "stiffness": "1e10 N/m", "free_length": 0.9}]
        },
        "duration": "100 s"
    });
    if let Some(t) = tolerance {
        body["tolerance"] = json!(t);
    }
    body
}

/// At the default tolerance the ringing is part of the answer and every
/// method must follow it (the explicit pair's steps are held by accuracy,
/// not stability, so it does not hand over): with the service's job budget
/// set to 0.3 s the job is stopped and answered 422 with the reason, and
/// nothing is stored.
#[tokio::test]
async fn a_job_over_its_compute_budget_is_stopped_with_the_reason() {
    let app = TestApp::with_job_budget(std::time::Duration::from_millis(300)).await;
    let r = app.post("/v1/dynamics", &bob_on_a_stiff_spring(None)).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    assert_eq!(r.content_type, "application/problem+json");
    assert_eq!(r.json()["type"], "/problems/compute-budget", "{}", r.text);
    let message = r.json()["detail"].as_str().unwrap().to_string();
    assert!(message.contains("compute budget of 0.3 s"), "{message}");
    // The simulated time reached, a measured value, to four significant figures.
    let reached = message.split("ran out at t = ").nth(1).and_then(|r| r.split(" s ").next()).expect("t said");
    let digits: String = reached.split('e').next().unwrap_or_default().chars().filter(char::is_ascii_digit).collect();
    assert!(digits.trim_start_matches('0').len() <= 4, "{message}");
    let list = app.get("/v1/jobs").await.json();
    assert!(list["items"].as_array().unwrap().is_empty(), "{list}");
}

/// At tolerance 1e-3 the ringing is below the tolerance (its 2.2e-4 rad/s
/// against 1e-3·Ω = 3.1e-3 rad/s, Ω = √(g/L) the speed scale; at the
/// default 1e-9 it is far above): posted with the
/// integrator left to `auto`, Dormand–Prince finds its steps held by
/// stability and hands over to Radau IIA, which damps the ringing in a few
/// steps and finishes the 100 s at once (61 steps, measured); the answer
/// is 201 with `accuracy.integrator` `radau5`, `accuracy.stiff_at` (within
/// the first 10 ms), the method text saying why, and every sample between
/// 0 and 2θₑ, the last half at θₑ to 1e-10 rad (2 %; measured 1.2e-11).
#[tokio::test]
async fn a_stiff_spring_is_handed_to_radau_and_reported() {
    let app = TestApp::new().await;
    let r = app.post("/v1/dynamics", &bob_on_a_stiff_spring(Some(1e-3))).await;
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

/// The reduced form can be stiff too: I* = 1 kg·m² driven by 10 N·m
/// against a viscous torque of 10⁶ N·m·s·ω, from rest. The speed settles
/// at ω∞ = 10⁻⁵ rad/s within microseconds (λ = −10⁶ s⁻¹), then φ grows
/// slowly: φ(t) = ω∞·(t − (1 − e^{−10⁶t})/10⁶), ω(t) = ω∞·(1 − e^{−10⁶t})
/// (closed form). Over 100 s with the integrator left to `auto` (DOP853 at
/// the default tolerance), the pair hands over to Radau IIA, and every
/// sample's angle and speed are the closed form's to 1e-9 of ω∞·t and ω∞.
#[tokio::test]
async fn the_reduced_form_hands_a_stiff_run_over_too() {
    let app = TestApp::new().await;
    let body = json!({
        "torques": [{"name": "motor against a viscous brake", "value": {"expr": "10 - 1e6*omega"}}],
        "reduced_inertia": 1,
        "initial": {"angle": 0, "speed": 0},
        "duration": "100 s"
    });
    let r = app.post("/v1/dynamics", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let result = &r.json()["result"];
    assert_eq!(result["accuracy"]["integrator"], "radau5", "{}", result["accuracy"]);
    assert!(result["accuracy"]["stiff_at"].is_f64(), "{}", result["accuracy"]);
    // The torque depends on ω: its work is the integrated power, not a quadrature over φ.
    assert!(result["accuracy"]["method"].as_str().unwrap().ends_with("work as the integrated power"), "{}", r.text);
    let w = 1e-5;
    for s in result["samples"].as_array().unwrap() {
        let t = s["t"].as_f64().unwrap();
        let decay = (-1e6 * t).exp();
        let (angle, speed) = (w * (t - (1.0 - decay) / 1e6), w * (1.0 - decay));
        assert!((s["angle"].as_f64().unwrap() - angle).abs() <= 1e-9 * w * t.max(1e-6), "t = {t}: {s}");
        assert!((s["speed"].as_f64().unwrap() - speed).abs() <= 1e-9 * w, "t = {t}: {s}");
    }
}
