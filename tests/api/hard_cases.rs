//! The hard cases (issue 48): requests where a plain method gives a
//! confident wrong answer, each checked against an independent reference.
//! Every future change runs them.
//!
//! **Size.** A mechanism drawn s times larger, with its masses kept, its
//! inertias s² times larger, gravity s times stronger and its torques s²
//! times larger, moves in the same angles at the same times: its lengths
//! and forces are s times, its torques and inertias s² times those at
//! s = 1 (dimensional analysis: every term of m·a = F and I·α = M is
//! scaled alike). Singularity, mobility and accuracy must not depend on s.

use crate::helpers::{TestApp, request, template_request};
use serde_json::{Value, json};

/// The scales tried: from micrometres to thousands of kilometres.
const SCALES: [f64; 5] = [1e-6, 1e-3, 1.0, 1e3, 1e6];

/// A length (a point, `[x, y]`, or a number) times s.
fn lengths(v: &mut Value, s: f64) {
    match v {
        Value::Array(items) => items.iter_mut().for_each(|x| lengths(x, s)),
        Value::Number(n) => *v = json!(n.as_f64().unwrap() * s),
        _ => {}
    }
}

/// `mechanism` drawn s times larger: its points, centres of mass, joints'
/// points, inertias (s²) and gravity (s).
fn drawn_at(mechanism: &mut Value, s: f64) {
    if let Some(points) = mechanism["points"].as_object_mut() {
        points.values_mut().for_each(|p| lengths(p, s));
    }
    for body in mechanism["bodies"].as_array_mut().unwrap() {
        lengths(&mut body["cg"], s);
        lengths(&mut body["inertia"], s * s);
    }
    for joint in mechanism["joints"].as_array_mut().unwrap() {
        lengths(&mut joint["at"], s);
    }
    lengths(&mut mechanism["gravity"], s);
}

/// The relative gap of `b` scaled back by s^power to `a`, over the numbers
/// of two results alike in shape, each key's power given (others skipped),
/// relative to the largest |a| of that key.
fn gaps(a: &Value, b: &Value, s: f64, powers: &[(&str, i32)], out: &mut Vec<(String, f64, f64)>) {
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            for (k, va) in x {
                let vb = &y[k];
                match (powers.iter().find(|(name, _)| name == k), va.as_f64(), vb.as_f64()) {
                    (Some((_, p)), Some(fa), Some(fb)) => out.push((k.clone(), fa, fb / s.powi(*p))),
                    _ => gaps(va, vb, s, powers, out),
                }
            }
        }
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len(), "results alike in shape");
            x.iter().zip(y).for_each(|(va, vb)| gaps(va, vb, s, powers, out));
        }
        _ => {}
    }
}

/// Asserts the numbers of `b` at scale s, scaled back, within `tol` of `a`'s
/// (relative to the largest of each key).
#[track_caller]
fn same_scaled(a: &Value, b: &Value, s: f64, powers: &[(&str, i32)], tol: f64) {
    let mut pairs = Vec::new();
    gaps(a, b, s, powers, &mut pairs);
    assert!(!pairs.is_empty(), "nothing compared");
    for (key, _) in powers {
        let of_key: Vec<_> = pairs.iter().filter(|(k, ..)| k == key).collect();
        let largest = of_key.iter().map(|(_, x, _)| x.abs()).fold(0.0, f64::max);
        for (_, x, y) in of_key {
            assert!((x - y).abs() <= tol * largest.max(f64::MIN_POSITIVE), "at s = {s}, {key}: {y} vs {x}");
        }
    }
}

/// The library's four-bar (crank-rocker, a resisting torque on the rocker,
/// gravity) from 1 µm to 1000 km: the same driving torques (s²), reactions
/// (s), I* (s²) and M* (s²) at every step to 1e-9 of the largest, no step
/// singular, the same scale-free condition number and warnings.
#[tokio::test]
async fn the_four_bar_answers_the_same_at_every_size() {
    let app = TestApp::new().await;
    let at = |s: f64| {
        let mut body = template_request("four-bar");
        drawn_at(&mut body["mechanism"], s);
        body["constants"]["M"] = json!(20.0 * s * s);
        body
    };
    let reference = app.result("/v1/kinetostatics", &at(1.0)).await;
    let powers = [("driving", 2), ("fx", 1), ("fy", 1), ("reduced_inertia", 2), ("reduced_torque", 2)];
    for s in SCALES {
        let r = app.result("/v1/kinetostatics", &at(s)).await;
        assert!(r["steps"].as_array().unwrap().iter().all(|k| k["driving"].is_number()), "at s = {s}: {r}");
        same_scaled(&reference["steps"], &r["steps"], s, &powers, 1e-9);
        let kappa = |r: &Value| r["summary"]["max_scaled_condition"].as_f64().unwrap();
        assert!(
            (kappa(&r) - kappa(&reference)).abs() <= 1e-6 * kappa(&reference),
            "at s = {s}: {} {}",
            r["summary"],
            reference["summary"]
        );
        assert_eq!(r["warnings"], reference["warnings"], "at s = {s}");
    }
}

/// The library's slider-crank started from rest by a constant torque on
/// its crank (a mechanism's direct dynamics), drawn from 1 µm to 1000 km:
/// the crank turns through the same angle in the same 2 s (to 1e-7 of a
/// turn, the run's tolerance being 1e-10 relative), its energy held, the
/// joints closed to 1e-12 of the size.
#[tokio::test]
async fn the_slider_crank_starts_the_same_at_every_size() {
    let app = TestApp::new().await;
    let at = |s: f64| {
        let mut body = request("slider_crank_startup");
        drawn_at(&mut body["machine"]["mechanism"], s);
        body["machine"]["loads"][0]["value"] = json!(10.0 * s * s);
        body
    };
    let reference = app.result("/v1/dynamics", &at(1.0)).await;
    for s in SCALES {
        let r = app.result("/v1/dynamics", &at(s)).await;
        let accuracy = &r["accuracy"];
        assert_eq!(accuracy["energy_conserved"], json!(true), "at s = {s}: {accuracy}");
        let drift = accuracy["constraint_drift"].as_f64().unwrap();
        assert!(drift <= 1e-11 * s, "at s = {s}: {accuracy}");
        same_scaled(&reference["samples"], &r["samples"], s, &[("angle", 0), ("speed", 0), ("t", 0)], 1e-7);
    }
}

/// The four-bar's drawing counted from 1 nm to 1000 km: one degree of
/// freedom, no redundant constraint, the crank a candidate input.
#[tokio::test]
async fn mobility_counts_the_same_at_every_size() {
    let app = TestApp::new().await;
    for s in [1e-9, 1e-6, 1.0, 1e6] {
        let mut mechanism = template_request("four-bar")["mechanism"].clone();
        drawn_at(&mut mechanism, s);
        let r = app.result("/v1/mobility", &json!({"mechanism": mechanism})).await;
        assert_eq!((r["dof"].as_i64(), r["redundant_constraints"].as_i64()), (Some(1), Some(0)), "at s = {s}: {r}");
        assert_eq!(r["candidate_inputs"][0], "O2", "at s = {s}: {r}");
    }
}

/// A contact used as an input: the driving effort is the actuator's, and
/// the contact's reaction is what is left. A bead of 1 kg threaded on a
/// frictionless slope at α = 30° and pushed up it at constant speed: the
/// actuator holds m·g·sin α = 4.905 N along the slope, the slope only
/// presses, |N| = m·g·cos α, tangential 0 (closed forms).
#[tokio::test]
async fn a_contact_driven_along_itself_carries_no_driving_force() {
    let app = TestApp::new().await;
    let (alpha, g) = (30f64.to_radians(), 9.81);
    let body = json!({
        "mechanism": {
            "points": {"A": [0, 0], "P": [alpha.cos(), alpha.sin()]},
            "bodies": [{"name": "bead", "mass": 1, "inertia": 0, "cg": "P"}],
            "joints": [{"name": "slope", "type": "contact", "bodies": ["ground", "bead"],
                "curves": [{"line": {"through": "A", "direction": [alpha.cos(), alpha.sin()]}}, {"point": "P"}]}],
            "gravity": [0, -g]
        },
        "input": {"joint": "slope", "speed": 0.2, "start": 0, "end": 0.5, "steps": 5},
        "outputs": ["driving", "reactions"]
    });
    let r = app.result("/v1/kinetostatics", &body).await;
    for step in r["steps"].as_array().unwrap() {
        let slope = &step["reactions"][0];
        assert!((step["driving"].as_f64().unwrap() - g * alpha.sin()).abs() < 1e-12, "{step}");
        assert!((slope["normal"].as_f64().unwrap().abs() - g * alpha.cos()).abs() < 1e-12, "{slope}");
        assert!(slope["tangential"].as_f64().unwrap().abs() < 1e-12, "{slope}");
    }
}

/// The ring-on-rim template (a ring run along the rim of a turning disk):
/// the frictionless rim's reaction on the ring has no tangential part, and
/// the ring's free body balances with each force named once — the rim's
/// reaction plus the actuator's effort along the rim's tangent (−x at the
/// top of a circle run counter-clockwise) is m·a of the ring.
#[tokio::test]
async fn the_ring_on_the_rim_balances_with_each_force_named_once() {
    let app = TestApp::new().await;
    let r = app.result("/v1/kinetostatics", &template_request("ring-on-rim")).await;
    let step = &r["steps"][0];
    let rim = &step["reactions"][1];
    assert_eq!(rim["joint"], "rim");
    let effort = step["driving"][1].as_f64().unwrap();
    let ring = &step["kinematics"][1];
    let m = 0.05;
    assert!(rim["tangential"].as_f64().unwrap().abs() < 1e-12, "{rim}");
    let fx = rim["fx"].as_f64().unwrap() - effort;
    let fy = rim["fy"].as_f64().unwrap();
    assert!((fx - m * ring["ax"].as_f64().unwrap()).abs() < 1e-12, "{fx} vs m·a_x: {ring}");
    assert!((fy - m * ring["ay"].as_f64().unwrap()).abs() < 1e-12, "{fy} vs m·a_y: {ring}");
    assert!(effort.abs() > 1e-3, "the ring is accelerated along the rim: {effort}");
}

/// Rolling exactly at its friction limit: the library's disk (a uniform
/// disk on a 30° incline, released from rest) with μ = tan α / 3, the
/// least friction that rolls it. Rolling and slipping are then the same
/// motion, and it must roll: no `slip` event, the disk's centre down the
/// slope by ½·(2/3)g sin α·t² = 1.635 m in 1 s (closed form, to 1e-9 m),
/// where it froze at the start with 10 001 slip events before.
#[tokio::test]
async fn a_disk_at_exactly_its_friction_limit_rolls() {
    let app = TestApp::new().await;
    let mut body = template_request("rolling-disk");
    let alpha = 30f64.to_radians();
    body["machine"]["mechanism"]["joints"][0]["friction"] = json!({"mu": alpha.tan() / 3.0});
    let r = app.result("/v1/dynamics", &body).await;
    let events: Vec<&str> = r["events"].as_array().unwrap().iter().map(|e| e["kind"].as_str().unwrap()).collect();
    assert_eq!(events, ["end"], "{}", r["events"]);
    let last = r["samples"].as_array().unwrap().last().unwrap().clone();
    let (t, s) = (last["t"].as_f64().unwrap(), last["angle"].as_f64().unwrap());
    let expected = 0.5 * (2.0 / 3.0) * 9.81 * alpha.sin() * t * t;
    assert!((t - 1.0).abs() < 1e-12 && (s.abs() - expected).abs() < 1e-9, "{s} m vs {expected} m at {t} s");
}
