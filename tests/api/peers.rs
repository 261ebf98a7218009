//! The benchmark peers (bench/peers/, Python) give the service's answers:
//! checked when Python with NumPy is at hand — `.venv/bin/python` (what
//! .ci/run installs) or `python3` — and skipped with a message otherwise.

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::{Value, json};
use std::process::Command;

/// Runs a peer script with its arguments; None (and a message) when there is no Python with NumPy.
fn peer(script: &str, args: &[&str]) -> Option<Value> {
    let root = env!("CARGO_MANIFEST_DIR");
    let venv = format!("{root}/.venv/bin/python");
    let python = if std::path::Path::new(&venv).exists() { venv } else { "python3".into() };
    let has_numpy = Command::new(&python).args(["-c", "import numpy"]).output().is_ok_and(|o| o.status.success());
    if !has_numpy {
        eprintln!(
            "skipped: no Python with NumPy ({python}); `python3 -m venv .venv && .venv/bin/pip install numpy scipy`"
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
    let Some(peer) = peer("kinetostatics_numpy.py", &["360"]) else { return };
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
