//! Hard cases of contacts (issue 48): a follower on a cam with concave
//! stretches must rest where the cam lifts it — never with its face or
//! roller inside the cam — and where no contact outside both bodies can be
//! found, the result says so and how deep. References computed here from
//! the curves' own formulas, independently of the engine:
//!
//! - a flat face square to its guide rests on the cam's *support
//!   function*: its height over the cam's centre at cam angle θ is
//!   h(θ) = max_ψ ρ(ψ)·sin(ψ + 90° + θ) (the profile r = ρ(ψ) drawn from
//!   the +y direction, turned by θ counter-clockwise);
//! - a roller of radius R on a guide through the cam's centre rests with
//!   its centre at y(θ) = max_ψ [p_y + √(R² − p_x²)] over the profile's
//!   points p with |p_x| ≤ R: the lowest place where it clears them all.
//!
//! Each maximum is a scan of 7200 angles with its best refined by golden
//! section to 1e-13 rad: exact to about 1e-15 m.

use crate::helpers::{TestApp, template_request};
use serde_json::{Value, json};
use std::f64::consts::{FRAC_PI_2, TAU};

/// max over ψ of f by a scan of 7200 angles and golden section round the best.
pub fn maximum(f: impl Fn(f64) -> f64) -> f64 {
    let n = 7200;
    let h = TAU / n as f64;
    let best = (0..n).map(|k| k as f64 * h).max_by(|a, b| f(*a).total_cmp(&f(*b))).unwrap();
    let (mut a, mut b) = (best - h, best + h);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    while b - a > 1e-13 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if f(c) > f(d) { b = d } else { a = c }
    }
    f(0.5 * (a + b))
}

/// The cam-flat-follower template with its eccentric disk replaced by the
/// polar cam ρ = a + b·cos(nψ) about O, drawn from +y, its follower's
/// contact curve `follower` touching the cam's top at (0, a + b), no
/// friction, 72 steps of 5°.
pub fn polar_cam(a: f64, b: f64, n: u32, follower: Value, touch: [f64; 2]) -> Value {
    let mut body = template_request("cam-flat-follower");
    let m = &mut body["mechanism"];
    m["points"]["F"] = json!(touch);
    m["points"]["G"] = json!(touch);
    let joint = &mut m["joints"][2];
    joint.as_object_mut().unwrap().remove("friction");
    joint["curves"] = json!([{"polar": {"center": "O", "zero": [0, 1], "radius": {"expr": format!("{a} + {b}*cos({n}*psi)")}}}, follower]);
    body["input"]["steps"] = json!(72);
    body
}

/// The height of a roller's centre of radius r on a guide through the
/// cam's centre, the cam ρ(ψ) (drawn from +y) turned by θ: the lowest place
/// where it clears every point of the profile (the module's second reference).
pub fn roller_centre(rho: impl Fn(f64) -> f64, r: f64, theta: f64) -> f64 {
    maximum(|psi: f64| {
        let (s, c) = (psi + FRAC_PI_2 + theta).sin_cos();
        let (x, py) = (rho(psi) * c, rho(psi) * s);
        if x.abs() <= r { py + (r * r - x * x).sqrt() } else { f64::NEG_INFINITY }
    })
}

/// Each step's (θ, the follower's y, its contact).
pub fn follower_steps(result: &Value) -> Vec<(f64, f64, Value)> {
    let steps = result["steps"].as_array().unwrap();
    let y =
        |s: &Value| s["kinematics"].as_array().unwrap().iter().find(|b| b["body"] == "follower").unwrap()["y"].as_f64();
    steps.iter().map(|s| (s["input"].as_f64().unwrap(), y(s).unwrap(), s["contacts"][0].clone())).collect()
}

/// A flat face on three-lobed cams ρ = 0.05 + b·cos 3ψ (b = 6 and 10 mm:
/// concave between the lobes) and on a dimpled limaçon ρ = 0.05 +
/// 0.04·cos ψ: at every step the face is on the support function to 1e-9 m
/// (it used to sit up to 0.10 m below it, on the cam's far side, or 4.5 to
/// 8.8 mm inside it without a word); where it passes from one lobe to the
/// next the contact says `jumped` (once per lobe in a turn: 3, 3 and 1) and
/// a warning says where; nothing is said to cut, overlap or pull.
#[tokio::test]
async fn a_flat_face_rests_on_the_cams_support_function() {
    let app = TestApp::new().await;
    for (b, n, jumps) in [(0.006, 3, 3), (0.01, 3, 3), (0.04, 1, 1)] {
        let top = 0.05 + b;
        let face = json!({"line": {"through": "F", "direction": [1, 0]}});
        let result = app.result("/v1/kinetostatics", &polar_cam(0.05, b, n, face, [0.0, top])).await;
        let rho = |psi: f64| 0.05 + b * (n as f64 * psi).cos();
        for (theta, y, contact) in follower_steps(&result) {
            let h = maximum(|psi| rho(psi) * (psi + FRAC_PI_2 + theta).sin());
            assert!((y - h).abs() < 1e-9, "b = {b}, n = {n}, θ = {:.1}°: face at {y}, support {h}", theta.to_degrees());
            assert!(contact["penetration"].is_null() && contact["overlap"].is_null(), "{contact}");
        }
        let jumped = follower_steps(&result).iter().filter(|s| s.2["jumped"] == true).count();
        assert_eq!(jumped, jumps, "b = {b}, n = {n}");
        let warnings: Vec<&str> = result["warnings"].as_array().unwrap().iter().map(|w| w.as_str().unwrap()).collect();
        assert!(warnings.len() == 1 && warnings[0].contains("jumped"), "{warnings:?}");
    }
}

/// A roller of R = 40 mm on the cam ρ = 0.05 + 0.01·cos 3ψ, whose hollows
/// are concave with a radius of 32 mm: the roller bridges each hollow,
/// its centre at every step where it clears the whole cam (to 1e-9 m);
/// it used to drop through the cam to y = −0.02 m.
#[tokio::test]
async fn a_roller_bridges_a_hollow_narrower_than_itself() {
    let app = TestApp::new().await;
    let r = 0.04;
    let roller = json!({"circle": {"center": "F", "radius": r}});
    let result = app.result("/v1/kinetostatics", &polar_cam(0.05, 0.01, 3, roller, [0.0, 0.06 + r])).await;
    let rho = |psi: f64| 0.05 + 0.01 * (3.0 * psi).cos();
    for (theta, y, contact) in follower_steps(&result) {
        let centre = roller_centre(rho, r, theta);
        assert!((y - centre).abs() < 1e-9, "θ = {:.1}°: roller at {y}, clear at {centre}", theta.to_degrees());
        assert!(contact["penetration"].is_null(), "{contact}");
    }
}

/// A disk of R = 50 mm *rolling* on a fixed bumpy wheel ρ = 0.1 +
/// 0.005·cos 8ψ, whose hollows are concave with a radius of 40 mm: rolling
/// cannot jump across a hollow, so where the disk sinks into one the
/// contact reports how deep the bodies cut into each other — R less the
/// least distance from the disk's centre to the wheel, computed here from
/// the result's own centre — and a warning says where; elsewhere nothing.
#[tokio::test]
async fn a_rolling_disk_that_cannot_bridge_a_hollow_says_how_deep_it_cuts() {
    let app = TestApp::new().await;
    let (r, wheel) = (0.05, |psi: f64| 0.1 + 0.005 * (8.0 * psi).cos());
    let body = json!({
        "mechanism": {
            "points": {"O": [0, 0], "C": [0, 0.105 + r]},
            "bodies": [{"name": "disk", "mass": 1, "inertia": 0.001, "cg": "C"}],
            "joints": [{"name": "K", "type": "contact", "bodies": ["ground", "disk"], "rolling": true, "curves": [
                {"polar": {"center": "O", "zero": [0, 1], "radius": {"expr": "0.1 + 0.005*cos(8*psi)"}}},
                {"circle": {"center": "C", "radius": r}}]}]},
        "input": {"joint": "K", "start": "0 m", "end": "-0.08 m", "steps": 32, "speed": 1},
        "outputs": ["kinematics", "reactions"]
    });
    let result = app.result("/v1/kinetostatics", &body).await;
    let (mut cut, mut clear) = (0, 0);
    for step in result["steps"].as_array().unwrap() {
        let disk = &step["kinematics"][0];
        let (cx, cy) = (disk["x"].as_f64().unwrap(), disk["y"].as_f64().unwrap());
        let nearest = -maximum(|psi| {
            let (s, c) = (psi + FRAC_PI_2).sin_cos();
            -(wheel(psi) * c - cx).hypot(wheel(psi) * s - cy)
        });
        let depth = r - nearest;
        match step["contacts"][0]["penetration"].as_f64() {
            Some(p) => {
                assert!((p - depth).abs() < 1e-9 && p > 0.0, "at {}: said {p}, is {depth}", step["input"]);
                cut += 1;
            }
            None => {
                assert!(depth.abs() < 1e-9, "at {}: cut {depth} unsaid", step["input"]);
                clear += 1;
            }
        }
    }
    assert!(cut > 0 && clear > 0, "{cut} steps cut, {clear} clear");
    assert!(
        result["warnings"].to_string().contains("contact K: the bodies cut into each other at"),
        "{}",
        result["warnings"]
    );
}

/// The cam-flat-follower template's eccentric disk (e = 20 mm) spun at
/// 30 rad/s and left to run (frictionless, its inertia 1 kg·m²): the
/// follower's lift is e(1 − cos θ), so it presses with N = m(g + e(ω²cos θ
/// + α sin θ)), which falls to 0 past θ = 90° where eω² > g. The contact
/// pushes and never pulls: the run stops there with a `separation` event
/// and `stopped: "separation"`, the last sample at that instant with N = 0,
/// and there α = 0 (the follower no longer loads the cam), so g + eω²cos θ
/// = 0 with the event's θ and ω (closed form, to 1e-9 of g). It used to run
/// on to the end with N < 0 at the samples.
#[tokio::test]
async fn a_follower_thrown_off_its_cam_stops_the_run_at_the_separation() {
    let app = TestApp::new().await;
    let mut mechanism = template_request("cam-flat-follower")["mechanism"].clone();
    mechanism["joints"][2].as_object_mut().unwrap().remove("friction");
    mechanism["bodies"][0]["inertia"] = json!(1);
    let body = json!({"machine": {"mechanism": mechanism, "input": {"joint": "O"}},
        "initial": {"angle": 0, "speed": 30}, "duration": 1, "samples": 101, "tolerance": 1e-10});
    let result = app.result("/v1/dynamics", &body).await;
    assert_eq!(result["stopped"], "separation");
    let events = result["events"].as_array().unwrap();
    let separation = events.iter().find(|e| e["kind"] == "separation").expect("a separation event");
    assert_eq!(separation["joint"], "K");
    let (theta, omega, t) = (
        separation["angle"].as_f64().unwrap(),
        separation["speed"].as_f64().unwrap(),
        separation["t"].as_f64().unwrap(),
    );
    let pressing = 9.81 + 0.02 * omega * omega * theta.cos();
    assert!(pressing.abs() < 1e-9 * 9.81, "g + eω²cos θ = {pressing} at θ = {theta}");
    assert!(theta.to_degrees() > 90.0 && theta.to_degrees() < 180.0, "θ = {theta}");
    assert_eq!(events.last().unwrap()["t"], json!(t));
    let samples = result["machine"]["samples"].as_array().unwrap();
    let last = samples.last().unwrap();
    assert_eq!(last["t"].as_f64(), Some(t));
    assert!(last["contacts"][0]["normal"].as_f64().unwrap().abs() < 1e-6, "{}", last["contacts"][0]);
    assert!(samples.iter().all(|s| s["contacts"][0]["normal"].as_f64().unwrap() >= -1e-6));
    assert!(result["warnings"].to_string().contains("the contact 'K' opens at"), "{}", result["warnings"]);
}

/// The library's rolling disk with gravity turned to pull it off its
/// line (a disk under a ceiling): the contact would pull from the start,
/// so the run stops at t = 0 — events `separation` and `end` there, one
/// sample — and says why.
#[tokio::test]
async fn a_disk_under_a_ceiling_parts_at_once() {
    let app = TestApp::new().await;
    let mut body = template_request("rolling-disk");
    body["machine"]["mechanism"]["gravity"] = json!([0, 9.81]);
    let result = app.result("/v1/dynamics", &body).await;
    let kinds: Vec<&str> = result["events"].as_array().unwrap().iter().map(|e| e["kind"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["separation", "end"]);
    assert_eq!(result["events"][0]["t"], 0.0);
    assert_eq!(result["samples"].as_array().unwrap().len(), 1);
    assert_eq!(result["stopped"], "separation");
    assert!(result["warnings"].to_string().contains("pulls at the start"), "{}", result["warnings"]);
}

/// The library's rolling disk (R = 0.1 m, m = 2 kg, I = 0.01 kg·m², on a
/// 30° incline) with μ = 0.05, less than the tan α/3 rolling needs: it
/// slips from the start to the end. Every sample's contact says
/// `"slipping"`, a warning gives the interval from t = 0 s, and the
/// motion is the closed form of sliding with kinetic friction: the centre
/// down the slope by ½g(sin α − μ cos α)t², the disk turned by
/// −½(μ m g cos α R / I)t² (to 1e-9).
#[tokio::test]
async fn a_disk_that_slips_from_the_start_says_so_throughout() {
    let app = TestApp::new().await;
    let mut body = template_request("rolling-disk");
    body["machine"]["mechanism"]["joints"][0]["friction"] = json!({"mu": 0.05});
    let result = app.result("/v1/dynamics", &body).await;
    let (g, alpha, mu) = (9.81, 30f64.to_radians(), 0.05);
    for s in result["machine"]["samples"].as_array().unwrap() {
        assert_eq!(s["contacts"][0]["state"], "slipping", "{s}");
        let t = s["t"].as_f64().unwrap();
        let disk = &s["bodies"][0];
        let along = 0.5 * g * (alpha.sin() - mu * alpha.cos()) * t * t;
        let turned = -0.5 * (mu * 2.0 * g * alpha.cos() * 0.1 / 0.01) * t * t;
        assert!((disk["x"].as_f64().unwrap() - along).abs() < 1e-9, "x({t}) = {} vs {along}", disk["x"]);
        assert!((disk["theta"].as_f64().unwrap() - turned).abs() < 1e-9, "θ({t}) = {} vs {turned}", disk["theta"]);
    }
    let warnings = result["warnings"].to_string();
    assert!(warnings.contains("contact K slips from t = 0 s to t = 1 s"), "{warnings}");
    assert!(result["events"].as_array().unwrap().iter().all(|e| e["kind"] != "slip"), "{}", result["events"]);
}
