//! A flywheel's machine in space (`POST /v1/flywheel` with a `machine`
//! whose mechanism says `"space": "spatial"`): checked against the planar
//! engine on a mechanism both can pose, and against the closed form of a
//! Hooke's joint; its refusals at their fields.

use crate::helpers::TestApp;
use crate::spatial_dynamics::four_bar;
use serde_json::{Value, json};
use std::f64::consts::PI;

fn number(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The four-bar of `spatial_dynamics` under gravity, a torque of −4 N·m on
/// the rocker (about z in space) and a spring pulling B down to the
/// ground, driven at O2 at 200 rpm ± 2.5 % by a balancing motor: I*(φ) and
/// M*(φ) of the plane (its own coordinates, Zhukovsky by g = dq/dφ) and of
/// space (six coordinates a body, I* as 2T at unit speed) are the same
/// functions, so every number of the flywheel agrees: the balance torque,
/// ΔE and both inertias to 1e-8 of their size (the quadrature's tolerance
/// is 1e-9), the speeds' angles to 1e-6 rad.
#[tokio::test]
async fn a_planar_machine_in_space_needs_the_flywheel_the_plane_computes() {
    let app = TestApp::new().await;
    let request = |spatial: bool| {
        let torque = if spatial {
            json!({"type": "torque", "body": "rocker", "direction": [0, 0, 1], "value": "-4 N*m"})
        } else {
            json!({"type": "torque", "body": "rocker", "value": "-4 N*m"})
        };
        let (b, low) = if spatial { (json!("B"), json!([0.27, -0.1, 0])) } else { (json!("B"), json!([0.27, -0.1])) };
        let spring = json!({"type": "spring", "a": ["rocker", b], "b": ["ground", low],
                            "stiffness": "300 N/m", "free_length": "0.1 m"});
        json!({"mean_speed": "200 rpm", "irregularity": 0.05,
               "machine": {"mechanism": four_bar(spatial), "input": {"joint": "O2"}, "loads": [torque, spring]},
               "torques": [{"name": "motor", "balance": true}]})
    };
    let plane = app.post("/v1/flywheel", &request(false)).await;
    assert_eq!(plane.status, 201, "{}", plane.text);
    let space = app.post("/v1/flywheel", &request(true)).await;
    assert_eq!(space.status, 201, "{}", space.text);
    let (p, s) = (&plane.json()["result"], &space.json()["result"]);
    for field in
        ["balance_torque", "energy_fluctuation", "inertia_approximate", "inertia_exact", "least_reduced_inertia"]
    {
        let (x, y) = (number(&p[field]), number(&s[field]));
        assert!((x - y).abs() <= 1e-8 * x.abs().max(1e-3), "{field}: plane {x}, space {y}");
    }
    for field in ["phi_at_omega_max", "phi_at_omega_min"] {
        let (x, y) = (number(&p[field]), number(&s[field]));
        assert!((x - y).abs() <= 1e-6, "{field}: plane {x}, space {y}");
    }
    assert!(p["machine_poses"].is_array() && s.get("machine_poses").is_none());
}

/// A Hooke's joint at β = 30° driven at 300 rpm ± 1 %, a constant torque
/// T = 20 N·m against its output shaft, a balancing motor on the input:
/// the output turns θ₂ = atan2(sin θ / cos β, cos θ), so the balance
/// torque is T (the output turns once a turn) and the motor's work less
/// the load's from 0 to θ is T·(θ − θ₂(θ)): ΔE = T·(max − min) of θ − θ₂
/// over a turn (closed form, sampled at 10⁵ points: error below 1e-9·T),
/// to 1e-8 of it. One shaft's bearing is on the "Bastidor" (the ground in
/// a Spanish lab's word).
#[tokio::test]
async fn a_hooke_joint_machine_fluctuates_as_its_closed_form() {
    let app = TestApp::new().await;
    let (beta, t): (f64, f64) = (PI / 6.0, 20.0);
    let e2 = [beta.cos(), beta.sin(), 0.0];
    let mechanism = json!({"space": "spatial",
        "bodies": [{"name": "input", "mass": 1, "cg": [0, 0, 0], "inertia": [0.01, 0.05, 0.05]},
                   {"name": "output", "mass": 1, "cg": [0, 0, 0], "inertia": [0.02, 0.02, 0.02]}],
        "joints": [
            {"name": "A", "type": "revolute", "bodies": ["Bastidor", "input"], "at": [0, 0, 0], "axis": [1, 0, 0]},
            {"name": "B", "type": "revolute", "bodies": ["ground", "output"], "at": [0, 0, 0], "axis": e2},
            {"name": "cross", "type": "universal", "bodies": ["input", "output"], "at": [0, 0, 0],
             "axes": [[0, 1, 0], [0, 0, 1]]}]});
    let load = json!({"type": "torque", "body": "output", "direction": e2.map(|c| -c), "value": format!("{t} N*m")});
    let request = json!({"mean_speed": "300 rpm", "irregularity": 0.01,
        "machine": {"mechanism": mechanism, "input": {"joint": "A"}, "loads": [load]},
        "torques": [{"name": "motor", "balance": true}]});
    let r = app.post("/v1/flywheel", &request).await;
    assert_eq!(r.status, 201, "{}", r.text);
    let result = &r.json()["result"];
    let lag = |theta: f64| {
        let t2 = (theta.sin() / beta.cos()).atan2(theta.cos());
        theta - (t2 + 2.0 * PI * ((theta - t2) / (2.0 * PI)).round())
    };
    let values: Vec<f64> = (0..=100_000).map(|k| lag(2.0 * PI * k as f64 / 100_000.0)).collect();
    let spread = values.iter().fold(f64::MIN, |a, &b| a.max(b)) - values.iter().fold(f64::MAX, |a, &b| a.min(b));
    let expected = t * spread;
    assert!((number(&result["balance_torque"]) - t).abs() < 1e-8 * t, "{}", result["balance_torque"]);
    let found = number(&result["energy_fluctuation"]);
    assert!((found - expected).abs() < 1e-8 * expected, "ΔE {found} against {expected}");
}

/// A flywheel's shaft must turn: a cylindrical joint's slide is refused at
/// the input's joint, in Spanish when asked; an unknown shaft at its name;
/// a misspelt body at its place, with the bodies there are.
#[tokio::test]
async fn a_spatial_machine_is_refused_at_its_fields() {
    let app = TestApp::new().await;
    let mut m = four_bar(true);
    m["joints"][0]["type"] = json!("cylindrical");
    let request = |m: &Value, input: Value| {
        json!({"mean_speed": "200 rpm", "irregularity": 0.05, "machine": {"mechanism": m, "input": input},
               "torques": [{"name": "motor", "balance": true}]})
    };
    let r = app.post("/v1/flywheel?lang=es", &request(&m, json!({"joint": "O2", "coordinate": "slide"}))).await;
    assert_eq!(r.status, 422, "{}", r.text);
    let e = &r.json()["errors"][0];
    assert_eq!(e["pointer"], "/machine/input/joint", "{}", r.text);
    assert!(e["message"].as_str().unwrap().contains("el eje del volante gira"), "{}", r.text);
    let r = app.post("/v1/flywheel", &request(&four_bar(true), json!({"joint": "O9"}))).await;
    assert_eq!(r.status, 422, "{}", r.text);
    assert_eq!(r.json()["errors"][0]["pointer"], "/machine/input/joint", "{}", r.text);
    let mut typo = four_bar(true);
    typo["joints"][0]["bodies"][0] = json!("bastidr");
    let r = app.post("/v1/flywheel?lang=es", &request(&typo, json!({"joint": "O2"}))).await;
    let e = &r.json()["errors"][0];
    assert_eq!(e["pointer"], "/machine/mechanism/joints/0/bodies/0", "{}", r.text);
    let said = e["message"].as_str().unwrap();
    assert!(said.contains("'bastidr' (los cuerpos: ground, crank, coupler, rocker)"), "{said}");
}
