//! IFToMM benchmark A02-like: N = 5 parallelogram four-bars side by side
//! (all bars 1 m, 1 kg, uniform rods), their cranks hinged on the ground
//! 1 m apart, under gravity, turning full circles: every half turn all the
//! bars lie on one line (θ = 0, π), a singular position where the joint
//! Jacobian loses N rows of rank and each parallelogram could fold into an
//! antiparallelogram. The motion must go straight through.
//!
//! Symbols: θ the cranks' angle from +x (all equal in a parallelogram),
//! l = 1 m, m = 1 kg, g = 9.81 m/s². The couplers translate, so the chain is
//! a compound pendulum with I* = (N+1)·ml²/3 + N·ml² and potential
//! V = ((N+1)/2 + N)·m g l sin θ; energy gives θ̇²(θ) = θ̇₀² + 2(V(θ₀) − V(θ))/I*
//! and the time to turn from θ₀ to θ is ∫dθ/θ̇ (closed forms; the integral by
//! Gauss–Legendre quadrature here).

use crate::helpers::TestApp;
use axum::http::StatusCode;
use serde_json::{Value, json};
use std::f64::consts::PI;

const N: usize = 5;
const G: f64 = 9.81;
/// Initial crank speed, rad/s, from upright (θ₀ = π/2): enough to go over the top.
const OMEGA0: f64 = 6.0;

fn speed(theta: f64) -> f64 {
    let n = N as f64;
    let inertia = (n + 1.0) / 3.0 + n;
    let potential = |t: f64| ((n + 1.0) / 2.0 + n) * G * t.sin();
    (OMEGA0 * OMEGA0 + 2.0 * (potential(PI / 2.0) - potential(theta)) / inertia).sqrt()
}

/// ∫ dθ/θ̇ from a to b: 400 panels of 5-point Gauss–Legendre (θ̇ > 4 rad/s
/// and smooth, so far below 1e-12).
fn time(a: f64, b: f64) -> f64 {
    let nodes = [
        (0.0, 0.568_888_888_888_888_9),
        (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (0.906_179_845_938_664, 0.236_926_885_056_189_1),
    ];
    let h = (b - a) / 400.0;
    (0..400)
        .map(|k| {
            let mid = a + (k as f64 + 0.5) * h;
            nodes
                .iter()
                .map(|(x, w)| {
                    w * (1.0 / speed(mid - x * h / 2.0) + if *x == 0.0 { 0.0 } else { 1.0 / speed(mid + x * h / 2.0) })
                })
                .sum::<f64>()
                * h
                / 2.0
        })
        .sum()
}

/// The chain drawn upright: cranks from (i, 0) to (i, 1). `one_coupler`: a
/// single bar of mass N kg across all the cranks' tips instead of N
/// couplers — the same motion, with N − 1 redundant constraints.
fn chain(one_coupler: bool) -> Value {
    let crank = |i: usize| format!("crank {i}");
    let mut bodies: Vec<Value> =
        (0..=N).map(|i| json!({"name": crank(i), "mass": 1, "inertia": 1.0 / 12.0, "cg": [i, 0.5]})).collect();
    let mut joints: Vec<Value> = (0..=N)
        .map(|i| json!({"name": format!("O{i}"), "type": "revolute", "bodies": ["ground", crank(i)], "at": [i, 0]}))
        .collect();
    let pin = |i: usize, coupler: &str| json!({"name": format!("A{i}"), "type": "revolute", "bodies": [crank(i), coupler], "at": [i, 1]});
    if one_coupler {
        bodies.push(json!({"name": "coupler", "mass": N, "inertia": 1.0, "cg": [N as f64 / 2.0, 1]}));
        joints.extend((0..=N).map(|i| pin(i, "coupler")));
    } else {
        for i in 0..N {
            let name = format!("coupler {i}");
            bodies.push(json!({"name": name, "mass": 1, "inertia": 1.0 / 12.0, "cg": [i as f64 + 0.5, 1]}));
            joints.push(pin(i, &name));
            joints.push(
                json!({"name": format!("B{i}"), "type": "revolute", "bodies": [crank(i + 1), name], "at": [i + 1, 1]}),
            );
        }
    }
    json!({
        "machine": {
            "mechanism": {"bodies": bodies, "joints": joints, "gravity": [0, -G]},
            "input": {"joint": "O0", "reference": "90 deg", "start": "90 deg", "speed": OMEGA0},
            "reactions": false
        },
        "duration": 10,
        "tolerance": 1e-9,
        "samples": 101
    })
}

/// Over 10 s (12 turns, 24 singular positions): θ̇ at every sample within
/// 1e-8 of the energy closed form, every turn (θ = 2πk) at the time of the
/// quadrature within 1e-8 s, the positions met near singular reported; for the
/// separate couplers and for the single coupler (N − 1 redundant constraints).
#[tokio::test]
async fn a02_parallelogram_chain_goes_through_its_singular_positions() {
    let app = TestApp::new().await;
    for one_coupler in [false, true] {
        let r = app.post("/v1/dynamics", &chain(one_coupler)).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
        let result = r.json()["result"].clone();
        let machine = &result["machine"];
        assert_eq!(machine["redundant_constraints"], if one_coupler { N - 1 } else { 0 });
        for s in result["samples"].as_array().unwrap() {
            let (theta, omega) = (s["angle"].as_f64().unwrap(), s["speed"].as_f64().unwrap());
            assert!(
                (omega - speed(theta)).abs() <= 1e-8 * speed(theta),
                "θ̇ at θ = {theta}: {omega} vs {}",
                speed(theta)
            );
        }
        let (first, period) = (time(PI / 2.0, 2.0 * PI), time(0.0, 2.0 * PI));
        let turns: Vec<f64> = result["events"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|e| e["kind"] == "turn")
            .map(|e| e["t"].as_f64().unwrap())
            .collect();
        assert_eq!(turns.len(), 12, "{turns:?}");
        for (k, t) in turns.iter().enumerate() {
            let want = first + k as f64 * period;
            assert!((t - want).abs() <= 1e-8, "turn {}: t = {t} vs {want}", k + 1);
        }
        // Each time reported near a singular position is within 1e-4 s (the
        // window's entrance, ~5e-4 rad before) of a flat position θ = kπ.
        let near = machine["near_singular"].as_array().unwrap();
        assert!(!near.is_empty());
        for t in near.iter().map(|t| t.as_f64().unwrap()) {
            let flat = (1..=24).map(|k| time(PI / 2.0, k as f64 * PI));
            assert!(flat.clone().any(|f| (f - t).abs() < 1e-4), "{t} is not at a flat position");
        }
        assert!(result["warnings"][0].as_str().unwrap().contains("singular position"), "{}", result["warnings"]);
    }
}
