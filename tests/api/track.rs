//! `track`: any point's motion at every step, against closed forms and the
//! bodies' own reported motion (the offset slider-crank K1: crank 0.08 m
//! about O at the origin, the rod A–B, the piston's centre of mass at B).

use crate::helpers::{TestApp, request};
use axum::http::StatusCode;
use serde_json::{Value, json};

fn k1_tracking(track: Value) -> Value {
    let mut body = request("k1_offset_slider_crank");
    body["input"] = json!({"joint": "O", "speed": 150, "acceleration": 40, "start": 0, "end": "360 deg", "steps": 24});
    body["track"] = track;
    body
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("a number: {v}"))
}

/// A on the crank moves on its circle: r(cos φ, sin φ), v = rω(−sin φ,
/// cos φ), a = −rω²(cos φ, sin φ) + rα(−sin φ, cos φ) (1e-12 of each
/// scale); B moves with the piston whose centre of mass it is (the
/// piston's reported kinematics, 1e-12); the rod's midpoint P, a point
/// that `points` does not hold, is the mean of A and B in position,
/// velocity and acceleration (a rigid body's motion is affine in its
/// points, 1e-12).
#[tokio::test]
async fn tracked_points_move_as_their_bodies_do() {
    let app = TestApp::new().await;
    let b = [0.37933259094191533, 0.02];
    let p = json!({"name": "P", "body": "rod", "at": [(0.08 + b[0]) / 2.0, b[1] / 2.0]});
    let r = app.post("/v1/kinetostatics", &k1_tracking(json!(["A", "B", p]))).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let (radius, omega, alpha) = (0.08, 150.0, 40.0);
    for s in r.json()["result"]["steps"].as_array().unwrap() {
        let phi = f(&s["input"]);
        let [a, bp, mid] = [0, 1, 2].map(|k| s["points"][k].clone());
        assert_eq!((a["name"].as_str(), a["body"].as_str()), (Some("A"), Some("crank")));
        let (c, sn) = (phi.cos(), phi.sin());
        let expected = [
            ("x", radius * c, radius),
            ("y", radius * sn, radius),
            ("vx", -radius * omega * sn, radius * omega),
            ("vy", radius * omega * c, radius * omega),
            ("ax", -radius * omega * omega * c - radius * alpha * sn, radius * omega * omega),
            ("ay", -radius * omega * omega * sn + radius * alpha * c, radius * omega * omega),
        ];
        for (key, value, scale) in expected {
            assert!((f(&a[key]) - value).abs() <= 1e-12 * scale, "A.{key} at φ = {phi}: {} against {value}", a[key]);
        }
        let piston = s["kinematics"].as_array().unwrap().iter().find(|k| k["body"] == "piston").unwrap();
        for key in ["x", "y", "vx", "vy", "ax", "ay"] {
            // The crank pin's own scales bound the piston's: rω = 12 m/s, rω² = 1800 m/s².
            let scale = if key.starts_with('a') { 2000.0 } else { 15.0 };
            assert!((f(&bp[key]) - f(&piston[key])).abs() <= 1e-12 * scale, "B.{key} at φ = {phi}");
            let mean = (f(&a[key]) + f(&bp[key])) / 2.0;
            assert!((f(&mid[key]) - mean).abs() <= 1e-12 * scale, "P.{key} at φ = {phi}: {} against {mean}", mid[key]);
        }
    }
}

/// An unknown point or body, a pin in a slot without its body, and
/// "points" without `track`: each a 422 at its field.
#[tokio::test]
async fn tracking_errors_point_at_the_field() {
    let app = TestApp::new().await;
    let body = k1_tracking(json!(["Q", {"name": "P", "body": "beam", "at": [0, 0]}, {"name": "Z", "body": "rod"}]));
    let r = app.post("/v1/kinetostatics", &body).await;
    assert_eq!(r.status, StatusCode::UNPROCESSABLE_ENTITY, "{}", r.text);
    let errors = r.json()["errors"].as_array().unwrap().clone();
    let pointers: Vec<&str> = errors.iter().map(|e| e["pointer"].as_str().unwrap()).collect();
    assert_eq!(pointers, ["/track/0", "/track/1/body", "/track/2/name"]);
    let mut yoke = request("d1_scotch_yoke_machine")["machine"].clone();
    yoke["input"] = json!({"joint": "O", "speed": 10, "start": 0, "end": 1, "steps": 2});
    yoke.as_object_mut().unwrap().remove("loads");
    yoke["track"] = json!(["A"]);
    let r = app.post("/v1/kinetostatics", &yoke).await;
    assert_eq!(r.json()["errors"][0]["pointer"], "/track/0", "{}", r.text);
    assert!(r.json()["errors"][0]["message"].as_str().unwrap().contains("pin of the slot 'pin'"), "{}", r.text);
    let mut bare = k1_tracking(json!([]));
    bare["outputs"] = json!(["driving", "points"]);
    let r = app.post("/v1/kinetostatics", &bare).await;
    assert_eq!(r.json()["errors"][0]["pointer"], "/outputs", "{}", r.text);
}

/// A dynamics machine follows points too: a pendulum (a 1 kg bob at the
/// end of a massless 0.8 m rod, drawn hanging, released at 50°) tracks its
/// tip P, which moves as l(sin θ, −cos θ) with θ the pivot's reported
/// angle: v = lθ̇(cos θ, sin θ), a = lθ̈(cos θ, sin θ) + lθ̇²(−sin θ, cos θ)
/// (1e-9 of lθ̇², lθ̈ scales, from the same sample's θ, θ̇, θ̈).
#[tokio::test]
async fn a_dynamics_machine_reports_its_tracked_points() {
    let app = TestApp::new().await;
    let l = 0.8;
    let body = json!({
        "machine": {
            "mechanism": {
                "points": {"O": [0, 0], "P": [0, -l]},
                "bodies": [{"name": "rod", "mass": 1, "cg": "P"}],
                "joints": [{"name": "O", "type": "revolute", "bodies": ["ground", "rod"], "at": "O"}],
                "gravity": [0, -9.81]
            },
            "input": {"joint": "O", "start": "50 deg"},
            "track": [{"name": "P", "body": "rod"}]
        },
        "duration": "1 s", "tolerance": 1e-10, "samples": 11
    });
    let r = app.post("/v1/dynamics", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let scale = 2.0 * 9.81;
    for s in r.json()["result"]["machine"]["samples"].as_array().unwrap() {
        let (theta, w, alpha) =
            (f(&s["inputs"][0]["angle"]), f(&s["inputs"][0]["speed"]), f(&s["inputs"][0]["acceleration"]));
        let (sn, c) = theta.sin_cos();
        let p = &s["points"][0];
        assert_eq!((p["name"].as_str(), p["body"].as_str()), (Some("P"), Some("rod")));
        let expected = [
            ("x", l * sn),
            ("y", -l * c),
            ("vx", l * w * c),
            ("vy", l * w * sn),
            ("ax", l * alpha * c - l * w * w * sn),
            ("ay", l * alpha * sn + l * w * w * c),
        ];
        for (key, want) in expected {
            assert!((f(&p[key]) - want).abs() < 1e-9 * scale, "{key} at t = {}: {} vs {want}", s["t"], p[key]);
        }
    }
}
