//! The `energy` output of kinetostatics: checked against I* by a second
//! method (T = ½ I* ω² for one input, Zhukovsky), and against the work
//! the driving action does (d(T + V)/dt = T_drive·ω where gravity and a
//! spring are the only loads), by central differences of the reported
//! energies.

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::{Value, json};

/// K1 (the offset slider-crank under gravity) with a spring from the
/// ground to the piston instead of the gas force, at `speed` rad/s
/// constant, from `start` to `end` (rad) in `steps` steps.
fn slider_crank(start: f64, end: f64, steps: u32, outputs: Value) -> Value {
    let mut body = request("k1_offset_slider_crank");
    body["mechanism"]["points"]["S"] = json!([0.6, 0.1]);
    body["loads"] = json!([{"type": "spring", "a": ["piston", "B"], "b": ["ground", "S"], "stiffness": "3 kN/m", "free_length": "150 mm"}]);
    body["input"] = json!({"joint": "O", "speed": 150, "start": start, "end": end, "steps": steps});
    body["outputs"] = outputs;
    body
}

async fn steps(app: &TestApp, body: &Value) -> Vec<Value> {
    let r = app.post("/v1/kinetostatics", body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    r.json()["result"]["steps"].as_array().unwrap().clone()
}

/// T = ½ I* ω² at 36 positions (I* from the velocity coefficients, T from
/// each body's v_G and ω: two routes, 1e-12 relative), and T the sum of
/// the bodies' shares; energy alone keeps the steps free of kinematics.
#[tokio::test]
async fn kinetic_energy_is_half_the_reduced_inertia_times_omega_squared() {
    let app = TestApp::new().await;
    let tau = std::f64::consts::TAU;
    for s in steps(&app, &slider_crank(0.0, tau, 36, json!(["reduced", "energy"]))).await {
        let t = s["energy"]["kinetic"]["total"].as_f64().unwrap();
        let expected = 0.5 * s["reduced_inertia"].as_f64().unwrap() * 150.0 * 150.0;
        assert!((t - expected).abs() <= 1e-12 * expected, "T {t} against ½I*ω² {expected}");
        let shares: f64 =
            s["energy"]["kinetic"]["bodies"].as_object().unwrap().values().map(|v| v.as_f64().unwrap()).sum();
        assert!((shares - t).abs() <= 1e-12 * t);
        assert!(s["kinematics"].is_null(), "kinematics not asked");
    }
}

/// With gravity and a spring only, the driving torque's power is the rate
/// of T + V: (E(φ + h) − E(φ − h))/(2h/ω) against T_drive·ω at 8 crank
/// angles, h = 1e-5 rad (the input from φ − h to φ + 2h in 3 steps: the
/// end is not a step); the central difference errs by about h² E‴, 1e-9
/// of the power here; tolerance 1e-7 of the largest power.
#[tokio::test]
async fn the_driving_power_is_the_rate_of_the_mechanical_energy() {
    let app = TestApp::new().await;
    let (h, omega) = (1e-5, 150.0);
    let total = |s: &Value| {
        let e = &s["energy"];
        e["kinetic"]["total"].as_f64().unwrap()
            + e["potential"]["gravity"].as_f64().unwrap()
            + e["potential"]["springs"].as_f64().unwrap()
    };
    let mut rows = Vec::new();
    for k in 0..8 {
        let phi = 0.3 + f64::from(k) * 0.8;
        let s = steps(&app, &slider_crank(phi - h, phi + 2.0 * h, 3, json!(["driving", "energy"]))).await;
        let rate = (total(&s[2]) - total(&s[0])) / (2.0 * h / omega);
        rows.push((phi, rate, s[1]["driving"].as_f64().unwrap() * omega));
    }
    let scale = rows.iter().map(|r| r.2.abs()).fold(0.0, f64::max);
    assert!(scale > 1e3, "the spring and the masses make the crank work: {scale} W");
    for (phi, rate, power) in rows {
        assert!((rate - power).abs() <= 1e-7 * scale, "at φ = {phi}: d(T+V)/dt {rate} against T·ω {power}");
    }
}

/// A double pendulum released from rest under gravity, with a spring from
/// the ground to its tip: no force does work but gravity's and the
/// spring's, so every sample's reported T + V is the first sample's (to
/// 1e-8 of the largest energy: the run's tolerance is 1e-10, and the
/// energy is not held by projection), while T itself changes by more than
/// half of that scale.
#[tokio::test]
async fn a_conservative_machine_keeps_its_reported_energy() {
    let app = TestApp::new().await;
    let body = json!({
        "machine": {
            "mechanism": {
                "points": {"O": [0, 0], "A": [0.3, 0], "B": [0.5, 0.1]},
                "bodies": [
                    {"name": "upper", "mass": 2, "inertia": 0.015, "cg": [0.15, 0]},
                    {"name": "lower", "mass": 1, "inertia": 0.004, "cg": [0.4, 0.05]}
                ],
                "joints": [
                    {"name": "O", "type": "revolute", "bodies": ["ground", "upper"], "at": "O"},
                    {"name": "A", "type": "revolute", "bodies": ["upper", "lower"], "at": "A"}
                ],
                "gravity": [0, -9.81]
            },
            "input": [{"joint": "O"}, {"joint": "A"}],
            "loads": [{"type": "spring", "a": ["lower", "B"], "b": ["ground", [0.2, 0.4]], "stiffness": 80, "free_length": 0.1}],
            "conserve_energy": false
        },
        "duration": 1.0,
        "tolerance": 1e-10,
        "samples": 21
    });
    let r = app.post("/v1/dynamics", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let samples = r.json()["result"]["machine"]["samples"].as_array().unwrap().clone();
    let parts = |s: &Value| {
        let e = &s["energy"];
        let t = e["kinetic"]["total"].as_f64().unwrap();
        (t, t + e["potential"]["gravity"].as_f64().unwrap() + e["potential"]["springs"].as_f64().unwrap())
    };
    let (_, e0) = parts(&samples[0]);
    let scale = samples.iter().map(|s| parts(s).1.abs().max(parts(s).0)).fold(0.0, f64::max);
    let most_kinetic = samples.iter().map(|s| parts(s).0).fold(0.0, f64::max);
    assert!(most_kinetic > 0.5 * scale, "the pendulum swings: T up to {most_kinetic} J of {scale}");
    for s in &samples {
        let (_, e) = parts(s);
        assert!((e - e0).abs() <= 1e-8 * scale, "at t = {}: T + V = {e} against {e0}", s["t"]);
    }
}
