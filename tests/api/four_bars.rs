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

/// ∫ dθ/θ̇ from a to b: 400 panels of 5-point Gauss–Legendre (θ̇ ≥ 6 rad/s
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
    chain_of(N, one_coupler, OMEGA0)
}

/// [`chain`] of `n` parallelograms started at `omega0` rad/s.
fn chain_of(n: usize, one_coupler: bool, omega0: f64) -> Value {
    let crank = |i: usize| format!("crank {i}");
    let mut bodies: Vec<Value> =
        (0..=n).map(|i| json!({"name": crank(i), "mass": 1, "inertia": 1.0 / 12.0, "cg": [i, 0.5]})).collect();
    let mut joints: Vec<Value> = (0..=n)
        .map(|i| json!({"name": format!("O{i}"), "type": "revolute", "bodies": ["ground", crank(i)], "at": [i, 0]}))
        .collect();
    let pin = |i: usize, coupler: &str| json!({"name": format!("A{i}"), "type": "revolute", "bodies": [crank(i), coupler], "at": [i, 1]});
    if one_coupler {
        bodies.push(json!({"name": "coupler", "mass": n, "inertia": 1.0, "cg": [n as f64 / 2.0, 1]}));
        joints.extend((0..=n).map(|i| pin(i, "coupler")));
    } else {
        for i in 0..n {
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
            "input": {"joint": "O0", "reference": "90 deg", "start": "90 deg", "speed": omega0},
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
        let said = result["warnings"][0].as_str().unwrap();
        assert!(said.contains("singular position") && said.contains("kept on its branch"), "{said}");
        // Gravity has a potential, so T + V is held, but only up to the first
        // singular position: not throughout, and after fewer than all steps.
        let accuracy = &result["accuracy"];
        let (held, steps) = (accuracy["energy_held_steps"].as_u64().unwrap(), accuracy["steps"].as_u64().unwrap());
        assert_eq!(accuracy["energy_conserved"], false, "{accuracy}");
        assert!(0 < held && held < steps, "held after {held} of {steps} steps");
        // The separate couplers in the sparse form, which holds the folds
        // itself; the single coupler's redundant rows in the dense one.
        let method = accuracy["method"].as_str().unwrap();
        let form = if one_coupler { "solved by LU" } else { "pivot sines fall from 1e-3 to 3e-4 held" };
        assert!(method.contains(form), "{method}");
    }
}

/// Asked for DOP853 or Radau IIA, the chain leaves its branch at a flat
/// position (found on 2026-11-30: DOP853 at 1e-9 folded the chain of 2 at
/// its first and ran to the budget, the chain of 1 came out 14 rad/s off):
/// the run is made again with Dormand–Prince, which the fold's hold keeps on
/// the branch, and says so, in English and in Spanish. Its samples are, bit
/// for bit, those of the run asked with Dormand–Prince (the same run), and
/// so the closed form's θ̇(θ) within 1e-8 as above; the time it was replaced
/// is a flat position's within 1e-3 s.
#[tokio::test]
async fn an_integrator_that_leaves_the_branch_at_a_fold_is_replaced_by_dormand_prince() {
    let app = TestApp::new().await;
    let asked = |integrator: &str| {
        let mut request = chain(false);
        request["integrator"] = json!(integrator);
        request
    };
    let plain = app.result("/v1/dynamics", &asked("dopri5")).await;
    assert!(plain["accuracy"].get("integrator_replaced_at").is_none(), "{}", plain["accuracy"]);
    for integrator in ["dop853", "radau5"] {
        let result = app.result("/v1/dynamics", &asked(integrator)).await;
        let accuracy = &result["accuracy"];
        assert_eq!(accuracy["integrator"], "dopri5", "{integrator}: {accuracy}");
        assert_eq!(result["samples"], plain["samples"], "{integrator}");
        let t = accuracy["integrator_replaced_at"].as_f64().unwrap();
        let flat = (1..=24).map(|k| time(PI / 2.0, k as f64 * PI));
        assert!(flat.clone().any(|f| (f - t).abs() < 1e-3), "{integrator}: {t} is not at a flat position");
        let said = result["warnings"][0].as_str().unwrap();
        assert!(said.starts_with(&format!("the integrator asked, \"{integrator}\", met")), "{said}");
        assert!(said.contains("made again from the start with Dormand-Prince"), "{said}");
    }
    let r = app.post("/v1/dynamics?lang=es", &asked("dop853")).await;
    let said = r.json()["result"]["warnings"][0].as_str().unwrap().to_string();
    assert!(said.starts_with("el integrador pedido, \"dop853\", llegó") && said.contains("se repitió"), "{said}");
}

/// A hard case of the same family: IFToMM A02's chain of 10 (its published
/// size) started upright at 0.5 rad/s comes out of a flat position folded
/// (found and measured in issue 48; the integration is not mended yet). It
/// is said, not shown as right: the warning names where the energy balance
/// fails and the singular position passed before it; every sample before
/// that time is the closed form's θ̇(θ) within 1e-6, and the motion does go
/// wrong after it (θ̇ off by more than 1e-3 rad/s).
#[tokio::test]
async fn a_chain_that_folds_at_a_flat_position_is_said_to_have_left_its_branch() {
    let (n, omega0) = (10.0, 0.5);
    let speed = |theta: f64| {
        let potential = |t: f64| ((n + 1.0) / 2.0 + n) * G * t.sin();
        (omega0 * omega0 + 2.0 * (potential(PI / 2.0) - potential(theta)) / ((n + 1.0) / 3.0 + n)).sqrt()
    };
    // Its dense reruns near the folds take ~10 s of a debug build on a quick machine: a budget that a slow one does not run out of.
    let app = TestApp::with_job_budget(std::time::Duration::from_secs(300)).await;
    let result = app.result("/v1/dynamics", &chain_of(10, false, omega0)).await;
    let said = result["warnings"][0].as_str().unwrap();
    assert!(said.contains("may have left its branch"), "{}", result["warnings"]);
    let from: f64 = said.split("fails from t = ").nth(1).unwrap().split(' ').next().unwrap().parse().unwrap();
    let off = |s: &Value| (s["speed"].as_f64().unwrap() - speed(s["angle"].as_f64().unwrap())).abs();
    let samples = result["samples"].as_array().unwrap();
    let t = |s: &Value| s["t"].as_f64().unwrap();
    assert!(samples.iter().filter(|s| t(s) < from).all(|s| off(s) <= 1e-6), "a sample before {from} s is off");
    assert!(samples.iter().any(|s| t(s) >= from && off(s) > 1e-3), "nothing goes wrong after {from} s");
}

/// Seed 000's P.65 (example 2): a four-bar in dependent coordinates, here a
/// Grashof crank-rocker (crank l₁ = 0.1, coupler l₂ = 0.35, rocker
/// l₃ = 0.3 m, pivots A, D l₄ = 0.4 m apart; uniform rods of 1, 2, 1.5 kg,
/// Iᵢ = mᵢlᵢ²/12) started from rest by a constant 5 N·m on the crank, under
/// gravity. (The seed's closure equations (5), (6), (15)–(17) write the
/// crank's φ for the rocker's ψ.) Reference: the energy balance in closed
/// form, ½I*(φ)ω² = 5(φ − φ₀) − (V(φ) − V(φ₀)), with I*(φ) and V(φ) from the
/// four-bar's position and velocity loops solved here in closed form.
mod p65 {
    use super::*;

    const L: [f64; 4] = [0.1, 0.35, 0.3, 0.4];
    const M: [f64; 3] = [1.0, 2.0, 1.5];

    /// B, C and the angles θ (coupler), ψ (rocker) at crank angle φ (open branch, C above AD).
    fn position(phi: f64) -> ([f64; 2], [f64; 2], f64, f64) {
        let b = [L[0] * phi.cos(), L[0] * phi.sin()];
        let d = [L[3] - b[0], -b[1]];
        let r = d[0].hypot(d[1]);
        let a = (L[1] * L[1] - L[2] * L[2] + r * r) / (2.0 * r);
        let h = (L[1] * L[1] - a * a).sqrt();
        let c = [b[0] + (a * d[0] - h * d[1]) / r, b[1] + (a * d[1] + h * d[0]) / r];
        (b, c, (c[1] - b[1]).atan2(c[0] - b[0]), c[1].atan2(c[0] - L[3]))
    }

    /// I*(φ) = Σ (mᵢ|v_Gᵢ|² + Iᵢωᵢ²) for ω₁ = 1, and V(φ) = g Σ mᵢ y_Gᵢ.
    fn reduced(phi: f64) -> (f64, f64) {
        let (b, c, theta, psi) = position(phi);
        // l₂ω₂ e⊥(θ) − l₃ω₃ e⊥(ψ) = −l₁ e⊥(φ) (velocity loop, ω₁ = 1), e⊥(a) = (−sin a, cos a).
        let (p, t, s) = ([-phi.sin(), phi.cos()], [-theta.sin(), theta.cos()], [-psi.sin(), psi.cos()]);
        let (a11, a12, a21, a22) = (L[1] * t[0], -L[2] * s[0], L[1] * t[1], -L[2] * s[1]);
        let (r1, r2) = (-L[0] * p[0], -L[0] * p[1]);
        let det = a11 * a22 - a12 * a21;
        let (w2, w3) = ((r1 * a22 - a12 * r2) / det, (a11 * r2 - a21 * r1) / det);
        let vg2 = [L[0] * p[0] + L[1] / 2.0 * w2 * t[0], L[0] * p[1] + L[1] / 2.0 * w2 * t[1]];
        let rod = |m: f64, l: f64| m * l * l / 12.0;
        let inertia = (rod(M[0], L[0]) + M[0] * L[0] * L[0] / 4.0)
            + (M[1] * (vg2[0] * vg2[0] + vg2[1] * vg2[1]) + rod(M[1], L[1]) * w2 * w2)
            + (rod(M[2], L[2]) + M[2] * L[2] * L[2] / 4.0) * w3 * w3;
        let potential = G * (M[0] * b[1] / 2.0 + M[1] * (b[1] + c[1]) / 2.0 + M[2] * c[1] / 2.0);
        (inertia, potential)
    }

    fn request() -> Value {
        let (b, c, ..) = position(0.0);
        let mid = |p: [f64; 2], q: [f64; 2]| [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0];
        let rod = |name: &str, k: usize, cg: [f64; 2]| json!({"name": name, "mass": M[k], "inertia": M[k] * L[k] * L[k] / 12.0, "cg": cg});
        let pin = |name: &str, a: &str, b: &str, at: [f64; 2]| json!({"name": name, "type": "revolute", "bodies": [a, b], "at": at});
        json!({
            "machine": {
                "mechanism": {
                    "bodies": [rod("crank", 0, mid([0.0, 0.0], b)), rod("coupler", 1, mid(b, c)), rod("rocker", 2, mid(c, [L[3], 0.0]))],
                    "joints": [
                        pin("A", "ground", "crank", [0.0, 0.0]),
                        pin("B", "crank", "coupler", b),
                        pin("C", "coupler", "rocker", c),
                        pin("D", "ground", "rocker", [L[3], 0.0])
                    ],
                    "gravity": [0, -G]
                },
                "input": {"joint": "A"},
                "loads": [{"type": "torque", "body": "crank", "value": "5 N*m"}]
            },
            "duration": "1 s",
            "tolerance": 1e-10,
            "samples": 51
        })
    }

    /// Every sample's crank speed within 1e-8 of the energy balance at its
    /// angle (the closed form above), over about four turns.
    #[tokio::test]
    async fn p65_crank_rocker_start_up_matches_its_energy_balance() {
        let app = TestApp::new().await;
        let r = app.post("/v1/dynamics", &request()).await;
        assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
        let result = r.json()["result"].clone();
        let v0 = reduced(0.0).1;
        for s in result["samples"].as_array().unwrap().iter().skip(1) {
            let (phi, omega) = (s["angle"].as_f64().unwrap(), s["speed"].as_f64().unwrap());
            let (inertia, v) = reduced(phi);
            let want = (2.0 * (5.0 * phi - (v - v0)) / inertia).sqrt();
            assert!((omega - want).abs() <= 1e-8 * want, "ω at φ = {phi}: {omega} vs {want}");
        }
        assert!(result["samples"][50]["angle"].as_f64().unwrap() > 4.0 * PI, "{}", result["samples"][50]);
        assert!(result["warnings"].as_array().unwrap().is_empty(), "{}", result["warnings"]);
    }
}
