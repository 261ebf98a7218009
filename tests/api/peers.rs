//! The benchmark peers (bench/peers/, Python) give the service's answers:
//! checked when Python with NumPy is at hand — `.venv/bin/python` (what
//! .ci/run installs) or `python3` — and skipped with a message otherwise.

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::{Value, json};
use std::process::Command;

/// Runs a peer script with its arguments; None (and a message) when there
/// is no Python with NumPy, SciPy and the script's own `modules`.
fn peer(script: &str, args: &[&str], modules: &str) -> Option<Value> {
    let root = env!("CARGO_MANIFEST_DIR");
    let venv = format!("{root}/.venv/bin/python");
    let python = if std::path::Path::new(&venv).exists() { venv } else { "python3".into() };
    let import = format!("import numpy, scipy{modules}");
    let has_modules = Command::new(&python).args(["-c", &import]).output().is_ok_and(|o| o.status.success());
    if !has_modules {
        eprintln!(
            "skipped: no Python with NumPy, SciPy{modules} ({python}); \
             `python3 -m venv .venv && .venv/bin/pip install numpy scipy exudyn pylinkage`"
        );
        return None;
    }
    let out = Command::new(&python).arg(format!("{root}/bench/peers/{script}")).args(args).output().unwrap();
    assert!(out.status.success(), "{script}: {}", String::from_utf8_lossy(&out.stderr));
    Some(serde_json::from_slice(&out.stdout).unwrap())
}

/// K1's driving torque at 360 crank positions: the NumPy peer (closed-form
/// kinematics, one Newton–Euler system per position) and the service agree
/// to 1e-10 of the largest torque; the peer's own virtual-power residual is
/// below 1e-12.
#[tokio::test]
async fn the_numpy_kinetostatics_peer_gives_the_same_driving_torque() {
    let Some(peer) = peer("kinetostatics_numpy.py", &["360"], "") else { return };
    assert!(peer["virtual_power_residual"].as_f64().unwrap() < 1e-12, "{}", peer["virtual_power_residual"]);
    let mut body = request("k1_offset_slider_crank");
    body["input"]["steps"] = json!(360);
    body["outputs"] = json!(["driving"]);
    let app = TestApp::new().await;
    let r = app.post("/v1/kinetostatics", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let steps = r.json()["result"]["steps"].as_array().unwrap().clone();
    let want: Vec<f64> = peer["torque"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
    let scale = want.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert_eq!(steps.len(), want.len());
    for (s, w) in steps.iter().zip(&want) {
        let got = s["driving"].as_f64().unwrap();
        assert!((got - w).abs() <= 1e-10 * scale, "at φ = {}: {got} vs {w}", s["input"]);
    }
}

/// F1 (P.103): the SciPy flywheel peer (quad + brentq at 1e-10) and the
/// service give the same approximate and exact inertia to 1e-10 relative;
/// both agree with the case's I_exact = 353.52142732201185 kg·m² (closed
/// form and nested brentq) to 1e-10.
#[tokio::test]
async fn the_scipy_flywheel_peer_gives_the_same_inertias() {
    let Some(peer) = peer("flywheel_scipy.py", &[], "") else { return };
    let app = TestApp::new().await;
    let r = app.post("/v1/flywheel", &request("p103_slider")).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let result = r.json()["result"].clone();
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    for key in ["inertia_approximate", "inertia_exact"] {
        let (ours, theirs) = (result[key].as_f64().unwrap(), peer[key].as_f64().unwrap());
        assert!(rel(ours, theirs) < 1e-10, "{key}: {ours} vs the peer's {theirs}");
    }
    let reference = 353.521_427_322_011_85;
    assert!(rel(peer["inertia_exact"].as_f64().unwrap(), reference) < 1e-10, "{}", peer["inertia_exact"]);
}

/// A slider-crank starting from rest under a constant torque, 2 s: the
/// service's crank angle equals the energy-balance reference (t(φ) = ∫dφ/ω
/// with the closed-form I*, by SciPy quad + brentq) to 1e-9 rad, and Exudyn's
/// generalized-alpha converges to the same angle at second order (the error
/// falls ~16× from 8000 to 32000 steps; their Richardson extrapolation is
/// within 1e-7 rad).
#[tokio::test]
async fn exudyn_and_the_energy_balance_give_the_services_slider_crank_start_up() {
    let Some(peer) = peer("slider_crank_exudyn.py", &["8000", "32000"], ", exudyn") else { return };
    let reference = peer["reference_angle"].as_f64().unwrap();
    let app = TestApp::new().await;
    let r = app.post("/v1/dynamics", &request("slider_crank_startup")).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let samples = r.json()["result"]["machine"]["samples"].as_array().unwrap().clone();
    let ours = samples.last().unwrap()["inputs"][0]["angle"].as_f64().unwrap();
    assert!((ours - reference).abs() < 1e-9, "{ours} vs the energy balance's {reference}");
    let angle = |k: usize| peer["points"][k]["angle"].as_f64().unwrap();
    let (coarse, fine) = ((angle(0) - reference).abs(), (angle(1) - reference).abs());
    assert!((10.0..20.0).contains(&(coarse / fine)), "Exudyn errors {coarse:e} → {fine:e}");
    let extrapolated = angle(1) + (angle(1) - angle(0)) / 15.0;
    assert!((extrapolated - reference).abs() < 1e-7, "Exudyn extrapolated: {extrapolated} vs {reference}");
}

/// The library's four-bar over a turn of 360 positions, kinematics only
/// (`"outputs": ["kinematics"]`): pylinkage (PyPI, its own circle-circle
/// intersections; step k has the crank at (k + 1)·1°) puts the coupler's
/// pin B where the service's coupler pose does, to 1e-12 m (both are exact
/// but for rounding; B = G + A(θ)(B₀ − G₀) from the pose).
#[tokio::test]
async fn pylinkage_places_the_four_bar_where_the_service_does() {
    let Some(peer) = peer("four_bar_pylinkage.py", &["360"], ", pylinkage") else { return };
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/library/four-bar.json");
    let library: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let mut body = library["request"].clone();
    body["input"]["steps"] = json!(360);
    body["outputs"] = json!(["kinematics"]);
    let (b0, g0) = (&body["mechanism"]["points"]["B"], &body["mechanism"]["bodies"][1]["cg"]);
    let s: Vec<f64> = (0..2).map(|k| b0[k].as_f64().unwrap() - g0[k].as_f64().unwrap()).collect();
    let r = TestApp::new().await.post("/v1/kinetostatics", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let steps = r.json()["result"]["steps"].as_array().unwrap().clone();
    let want = peer["b"].as_array().unwrap();
    assert_eq!((steps.len(), want.len()), (360, 360));
    for (k, step) in steps.iter().enumerate() {
        assert!(step["driving"].is_null() && step["reactions"].is_null(), "kinematics only: {step}");
        let coupler = &step["kinematics"][1];
        assert_eq!(coupler["body"], "coupler");
        let [x, y, theta] = ["x", "y", "theta"].map(|f| coupler[f].as_f64().unwrap());
        let (sin, cos) = theta.sin_cos();
        let b = [x + cos * s[0] - sin * s[1], y + sin * s[0] + cos * s[1]];
        let w = &want[(k + 359) % 360];
        let gap = (b[0] - w[0].as_f64().unwrap()).hypot(b[1] - w[1].as_f64().unwrap());
        assert!(gap <= 1e-12, "at φ = {}: B = {b:?}, pylinkage {w}", step["input"]);
    }
}
