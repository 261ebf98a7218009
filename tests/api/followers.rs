//! Followers beyond the translating flat face: `POST /v1/cams` for
//! oscillating followers, each output checked by a second way of reading
//! the drawing it gives (the profile against the envelope drawn from
//! neighbouring positions of the follower, the pressure angle against the
//! arm's motion and the pitch curve drawn by differences, the contact
//! force against the moment about the pivot); and a designed cam, for a
//! flat face or a roller, drawn as a `cam` curve in a mechanism against
//! its design.

use crate::helpers::TestApp;
use axum::http::StatusCode;
use serde_json::{Value, json};

/// Pivot a = 120 mm, arm L = 90 mm (roller r = 12 mm, or a flat face at f
/// = 10 mm), base circle 40 mm; rise 20° cycloidal, dwell, 3-4-5 return,
/// dwell; ω = 10 rad/s; 720 samples (Δθ = 0.5°).
fn request(kind: &str) -> Value {
    let follower = match kind {
        "roller" => {
            json!({"type": "roller", "motion": "oscillating", "roller_radius": "12 mm", "pivot": "120 mm", "arm": "90 mm"})
        }
        _ => json!({"type": "flat", "motion": "oscillating", "pivot": "120 mm", "arm": "10 mm"}),
    };
    json!({
        "follower": follower,
        "program": [{"to": "100 deg", "law": "cycloidal", "lift": "20 deg"}, {"to": "160 deg", "law": "dwell"},
                    {"to": "260 deg", "law": "polynomial-345", "lift": 0}, {"to": "360 deg", "law": "dwell"}],
        "base_radius": "40 mm", "speed": "10 rad/s", "samples": 720,
        "dynamics": {"follower_mass": "0.004 kg*m^2", "spring": {"stiffness": "5 N*m/rad", "preload": "1.5 N*m"}}
    })
}

async fn design(app: &TestApp, body: &Value) -> Vec<Value> {
    let r = app.post("/v1/cams", body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let result = r.json()["result"].clone();
    assert_eq!(result["summary"]["lift_unit"], "rad");
    result["samples"].as_array().unwrap().clone()
}

fn point(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap()
}

/// A cam-frame point x at θ in the ground (the cam turned by θ, ccw).
fn ground(x: [f64; 2], theta: f64) -> [f64; 2] {
    let (s, c) = theta.sin_cos();
    [c * x[0] - s * x[1], s * x[0] + c * x[1]]
}

/// The arm from the pivot A = (a, 0) to the roller's centre P (ground):
/// its length is L, its angle from A→O is ψ₀ + s with cos ψ₀ = (a² + L² −
/// R_p²)/(2aL) (1e-12). The pressure angle is the angle between the pitch
/// curve's normal, drawn by central differences (fourth order) of the
/// pitch points in the cam's frame, and the roller centre's velocity (square to the arm)
/// (1e-6 rad). The profile point lies r from the pitch point, along that
/// normal (1e-6 of r).
#[tokio::test]
async fn an_oscillating_roller_follows_its_arm_and_its_pressure_angle_is_the_drawn_one() {
    let app = TestApp::new().await;
    let samples = design(&app, &request("roller")).await;
    let (a, l, rp, r): (f64, f64, f64, f64) = (0.12, 0.09, 0.052, 0.012);
    let psi0 = ((a * a + l * l - rp * rp) / (2.0 * a * l)).acos();
    let n = samples.len();
    for k in (0..n).step_by(7) {
        let x = &samples[k];
        let theta = f(&x["theta"]);
        let p = ground(point(&x["pitch_point"]), theta);
        let arm = [p[0] - a, p[1]];
        assert!((arm[0].hypot(arm[1]) - l).abs() < 1e-12, "|AP| = L at {theta}");
        let psi = arm[1].atan2(-arm[0]);
        assert!((psi - psi0 - f(&x["lift"])).abs() < 1e-12, "ψ = ψ₀ + s at {theta}: {psi}");
        // Central differences to the fourth order: (8(P₊₁ − P₋₁) − (P₊₂ − P₋₂))/12.
        let [m2, m1, p1, p2] = [n - 2, n - 1, 1, 2].map(|j| point(&samples[(k + j) % n]["pitch_point"]));
        let tangent = [0, 1].map(|i| (8.0 * (p1[i] - m1[i]) - (p2[i] - m2[i])) / 12.0);
        let normal = ground([-tangent[1], tangent[0]], theta);
        let velocity = [arm[1], -arm[0]]; // d/dψ of P, square to the arm
        let cross = velocity[0] * normal[1] - velocity[1] * normal[0];
        let angle = (cross / (velocity[0].hypot(velocity[1]) * normal[0].hypot(normal[1]))).asin();
        assert!((f(&x["pressure_angle"]) - angle).abs() < 1e-6, "φ at {theta}: {} vs {angle}", x["pressure_angle"]);
        let c = point(&x["profile_point"]);
        let q = point(&x["pitch_point"]);
        let gap = [q[0] - c[0], q[1] - c[1]];
        assert!((gap[0].hypot(gap[1]) - r).abs() < 1e-12);
        let unit = normal[0].hypot(normal[1]);
        let along = ground(gap, theta);
        assert!((along[0] * normal[1] - along[1] * normal[0]).abs() / unit < 1e-6 * r, "along the normal at {theta}");
    }
}

/// The flat face's profile is the envelope of its lines: the line at each
/// angle (drawn from the arm: normal n̂ = (sin ψ, cos ψ), distance a sin ψ −
/// f, sin ψ₀ = (R_b + f)/a) passes through the profile point (1e-12 m), and
/// the crossing of neighbouring lines (0.5° and 1° apart, extrapolated to
/// 0°) is the profile point (1e-7 m: ~1e-9 where the lift is smooth,
/// 2e-8 at a joint of segments, where s‴ jumps and the extrapolation
/// loses an order).
#[tokio::test]
async fn an_oscillating_flat_face_s_profile_is_the_envelope_of_its_lines() {
    let app = TestApp::new().await;
    let samples = design(&app, &request("flat")).await;
    let (a, face, base): (f64, f64, f64) = (0.12, 0.01, 0.04);
    let psi0 = ((base + face) / a).asin();
    let line = |x: &Value| {
        let (theta, psi) = (f(&x["theta"]), psi0 + f(&x["lift"]));
        // The line in the cam's frame: normal turned back by θ, same distance.
        let normal = ground([psi.sin(), psi.cos()], -theta);
        (normal, a * psi.sin() - face)
    };
    let n = samples.len();
    for k in (0..n).step_by(5) {
        let c = point(&samples[k]["profile_point"]);
        let (nk, pk) = line(&samples[k]);
        assert!((c[0] * nk[0] + c[1] * nk[1] - pk).abs() < 1e-12, "on its line at {k}");
        // Lines ±j samples away cross at c + O(j²h²): Richardson's (4X₁ − X₂)/3 leaves O(h⁴).
        let cross = |j: usize| {
            let ((n0, p0), (n2, p2)) = (line(&samples[(k + n - j) % n]), line(&samples[(k + j) % n]));
            let det = n0[0] * n2[1] - n0[1] * n2[0];
            [(p0 * n2[1] - p2 * n0[1]) / det, (n0[0] * p2 - n2[0] * p0) / det]
        };
        let (x1, x2) = (cross(1), cross(2));
        let crossing = [0, 1].map(|i| (4.0 * x1[i] - x2[i]) / 3.0);
        let miss = (crossing[0] - c[0]).hypot(crossing[1] - c[1]);
        assert!(miss < 1e-7, "the envelope at {k}: {miss} m off");
    }
}

/// The contact force's moment about the pivot is the follower's moment
/// from the cam Q = I s″ω² + k s + M₀ (I = 0.004 kg·m², k = 5 N·m/rad, M₀
/// = 1.5 N·m): N times the distance from the pivot to the contact's normal
/// line (through the profile and pitch points as reported) (1e-9 N·m); the
/// cam's torque is Q s′ (power) (1e-12 N·m).
#[tokio::test]
async fn an_oscillating_roller_s_contact_force_balances_its_moment_about_the_pivot() {
    let app = TestApp::new().await;
    let samples = design(&app, &request("roller")).await;
    let (a, w) = (0.12, 10.0);
    for x in samples.iter().step_by(11) {
        let theta = f(&x["theta"]);
        let q = 0.004 * f(&x["d2lift"]) * w * w + 5.0 * f(&x["lift"]) + 1.5;
        let (c, p) = (ground(point(&x["profile_point"]), theta), ground(point(&x["pitch_point"]), theta));
        let normal = [p[0] - c[0], p[1] - c[1]];
        let length = normal[0].hypot(normal[1]);
        let arm = ((c[0] - a) * normal[1] - c[1] * normal[0]).abs() / length;
        let force = f(&x["contact_force"]);
        assert!((force.abs() * arm - q.abs()).abs() < 1e-9, "N·d = Q at {theta}: {} vs {q}", force * arm);
        assert!((f(&x["cam_torque"]) - q * f(&x["dlift"])).abs() < 1e-12);
    }
}

/// An oscillating follower needs its pivot and arm, has no offset, and an
/// arm that cannot reach the base circle is refused at the arm; its lift
/// is an angle.
#[tokio::test]
async fn an_oscillating_follower_s_bad_input_is_named_at_its_fields() {
    let app = TestApp::new().await;
    let mut body = request("roller");
    body["follower"] = json!({"type": "roller", "motion": "oscillating", "roller_radius": "12 mm", "offset": "5 mm"});
    body["program"][0]["lift"] = json!("20 mm");
    let pointers = app.pointers("/v1/cams", &body).await;
    for p in ["/follower", "/follower/offset", "/program/0/lift"] {
        assert!(pointers.iter().any(|q| q == p), "{p} in {pointers:?}");
    }
    let mut body = request("roller");
    body["follower"]["arm"] = json!("20 mm");
    assert_eq!(app.pointers("/v1/cams", &body).await, ["/follower/arm"]);
    let mut body = request("flat");
    body["follower"]["pivot"] = json!("45 mm");
    assert_eq!(app.pointers("/v1/cams", &body).await, ["/follower/arm"]);
}

/// The smallest base circle for a largest pressure angle of 30° under an
/// oscillating roller: its pressure angle reaches 30° (1e-6 rad), and a
/// base circle 1 % smaller exceeds it.
#[tokio::test]
async fn an_oscillating_roller_s_smallest_base_circle_meets_its_pressure_angle() {
    let app = TestApp::new().await;
    let mut body = request("roller");
    body.as_object_mut().unwrap().remove("base_radius");
    body["size"] = json!({"max_pressure_angle": "30 deg"});
    let r = app.post("/v1/cams", &body).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let summary = r.json()["result"]["summary"].clone();
    let limit = 30f64.to_radians();
    assert!((f(&summary["max_pressure_angle"]["value"]) - limit).abs() < 1e-6, "{summary}");
    body.as_object_mut().unwrap().remove("size");
    body["base_radius"] = json!(0.99 * f(&summary["base_radius"]));
    let r = app.post("/v1/cams", &body).await;
    assert!(f(&r.json()["result"]["summary"]["max_pressure_angle"]["value"]) > limit + 1e-6);
}

/// The same program two ways, for a flat face and for a roller (10 mm on
/// an axis offset 5 mm): designed by `POST /v1/cams` (base 30 mm, a
/// harmonic rise of 15 mm over 180° and a cycloidal return, the follower
/// 1 kg under its weight at 10 rad/s) and drawn as a `cam` curve under the
/// follower's face or roller on a vertical guide, solved by kinetostatics.
/// The follower rises by s(θ) (1e-9 m); the driving torque and the
/// contact's normal force are the design's cam torque and contact force
/// (1e-8 of m g R_b and of m g: the follower's axial equation and power
/// against the whole mechanism's multipliers).
#[tokio::test]
async fn a_designed_cam_drawn_in_a_mechanism_lifts_and_loads_its_follower_alike() {
    let app = TestApp::new().await;
    let program = json!([{"to": "180 deg", "law": "harmonic", "lift": "15 mm"}, {"to": "360 deg", "law": "cycloidal", "lift": 0}]);
    let (e, pitch): (f64, f64) = (0.005, 0.04);
    let centre = [-e, (pitch * pitch - e * e).sqrt()];
    let cases = [
        (
            json!({"type": "flat"}),
            json!({"F": [0, 0.03], "G": [0, 0.08]}),
            0.08,
            json!({"line": {"through": "F", "direction": [1, 0]}}),
        ),
        (
            json!({"type": "roller", "roller_radius": "10 mm", "offset": "5 mm"}),
            json!({"G": centre}),
            centre[1],
            json!({"circle": {"center": "G", "radius": "10 mm"}}),
        ),
    ];
    for (follower, mut points, rest, face) in cases {
        let design = json!({"follower": follower, "program": program, "base_radius": "30 mm", "speed": 10,
            "samples": 24, "dynamics": {"follower_mass": 1, "force": -9.81}});
        let r = app.post("/v1/cams", &design).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
        let designed = r.json()["result"]["samples"].clone();
        points["O"] = json!([0, 0]);
        let curve = json!({"cam": {"center": "O", "zero": [0, 1], "follower": follower, "program": program, "base_radius": "30 mm"}});
        let machine = json!({
            "mechanism": {
                "points": points,
                "bodies": [{"name": "cam", "mass": 1, "inertia": 0.001, "cg": "O"},
                           {"name": "follower", "mass": 1, "inertia": 0.01, "cg": "G"}],
                "joints": [
                    {"name": "O", "type": "revolute", "bodies": ["ground", "cam"], "at": "O"},
                    {"name": "guide", "type": "prismatic", "bodies": ["ground", "follower"], "at": "G", "axis": [0, 1]},
                    {"name": "K", "type": "contact", "bodies": ["cam", "follower"], "curves": [curve, face]}
                ],
                "gravity": [0, -9.81]
            },
            "input": {"joint": "O", "start": 0, "end": "360 deg", "steps": 24, "speed": 10},
            "outputs": ["driving", "reactions", "kinematics"]
        });
        let r = app.post("/v1/kinetostatics", &machine).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
        let solved = r.json()["result"]["steps"].clone();
        let scale = 9.81 * 0.03;
        for (a, b) in designed.as_array().unwrap().iter().zip(solved.as_array().unwrap()) {
            let (theta, kind) = (f(&a["theta"]), &follower["type"]);
            assert!((f(&b["input"]) - theta).abs() < 1e-12, "the same angles");
            let lift = f(&b["kinematics"][1]["y"]) - rest;
            assert!((lift - f(&a["lift"])).abs() < 1e-9, "{kind} θ = {theta}: lift {lift} vs {}", a["lift"]);
            let torque = f(&b["driving"]);
            let want = f(&a["cam_torque"]);
            assert!((torque - want).abs() < 1e-8 * scale, "{kind} θ = {theta}: torque {torque} vs {want}");
            let (normal, want) = (f(&b["contacts"][0]["normal"]), f(&a["contact_force"]));
            assert!((normal - want).abs() < 1e-8 * 9.81, "{kind} θ = {theta}: N {normal} vs {want}");
        }
    }
}
