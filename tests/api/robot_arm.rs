//! Seed 000's P.68 (example 3): the 2-DOF robot arm, two rods hinged at the
//! shoulder O (on the ground) and the elbow A, each driven by a motor,
//! through `POST /v1/dynamics` with two inputs — against the seed's own
//! Lagrange equations integrated here by classical Runge–Kutta.
//!
//! Symbols (the seed's): q₁, q₂ the rods' absolute angles from the upward
//! vertical (counter-clockwise); l₁, l₂ lengths; m₁, m₂ masses; I₁, I₂
//! inertias about the centres G₁, G₂ at mid-rod; T₁ the shoulder motor's
//! torque (ground on rod 1), T₂ the elbow motor's (rod 1 on rod 2); the
//! generalized forces Q₁ = T₁ − T₂, Q₂ = T₂. From L = T − V of the seed,
//! with a₁₁ = m₁l₁²/4 + I₁ + m₂l₁², a₂₂ = m₂l₂²/4 + I₂, b = m₂l₁l₂/2, Δ = q₁ − q₂:
//!
//! ```text
//! a₁₁q̈₁ + b cosΔ q̈₂ + b q̇₂² sinΔ − (m₁/2 + m₂) g l₁ sin q₁ = T₁ − T₂
//! b cosΔ q̈₁ + a₂₂q̈₂ − b q̇₁² sinΔ − m₂ g (l₂/2) sin q₂     = T₂
//! ```
//!
//! The service's inputs are the joints' relative angles: φ₁ = q₁ and
//! φ₂ = q₂ − q₁ (the fixture draws both rods upright).

use crate::helpers::{TestApp, close, request};
use axum::http::StatusCode;

const G: f64 = 9.81;
/// The fixture's data: l₁, l₂ (m), m₁, m₂ (kg), I₁ = m₁l₁²/12, I₂ = m₂l₂²/12.
const L1: f64 = 0.5;
const L2: f64 = 0.4;
const M1: f64 = 4.0;
const M2: f64 = 3.0;
const I1: f64 = M1 * L1 * L1 / 12.0;
const I2: f64 = M2 * L2 * L2 / 12.0;

fn torques(t: f64) -> (f64, f64) {
    (12.0 + 2.0 * (3.0 * t).sin(), 0.5 * (2.0 * t).cos())
}

/// [q̈₁, q̈₂] from the two equations above (Cramer's rule).
fn accelerations(t: f64, [q1, q2, w1, w2]: [f64; 4]) -> [f64; 2] {
    let (t1, t2) = torques(t);
    let (a11, a22, b) = (M1 * L1 * L1 / 4.0 + I1 + M2 * L1 * L1, M2 * L2 * L2 / 4.0 + I2, M2 * L1 * L2 / 2.0);
    let (c, s) = ((q1 - q2).cos(), (q1 - q2).sin());
    let r1 = t1 - t2 - b * w2 * w2 * s + (M1 / 2.0 + M2) * G * L1 * q1.sin();
    let r2 = t2 + b * w1 * w1 * s + M2 * G * L2 / 2.0 * q2.sin();
    let det = a11 * a22 - b * c * b * c;
    [(r1 * a22 - b * c * r2) / det, (a11 * r2 - b * c * r1) / det]
}

/// Classical RK4 on y = (q₁, q₂, q̇₁, q̇₂), h = 1e-4 s: a global error
/// of order h⁴ (≈ 1e-12 here), far below the comparison tolerance.
fn rk4(mut y: [f64; 4], until: f64) -> [f64; 4] {
    let f = |t: f64, y: [f64; 4]| {
        let [a1, a2] = accelerations(t, y);
        [y[2], y[3], a1, a2]
    };
    let add = |y: [f64; 4], k: [f64; 4], h: f64| std::array::from_fn(|i| y[i] + h * k[i]);
    let n = (until / 1e-4).round() as usize;
    let h = until / n as f64;
    for i in 0..n {
        let t = i as f64 * h;
        let k1 = f(t, y);
        let k2 = f(t + h / 2.0, add(y, k1, h / 2.0));
        let k3 = f(t + h / 2.0, add(y, k2, h / 2.0));
        let k4 = f(t + h, add(y, k3, h));
        y = std::array::from_fn(|j| y[j] + h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]));
    }
    y
}

/// Every sample over 2 s: the inputs' angles to 1e-8 rad and speeds to
/// 1e-7 rad/s of the Lagrange solution, their accelerations to 1e-6; the
/// shoulder's reaction equal to Σmᵢ(a_Gᵢ − g) of the whole arm (Newton's
/// second law, a_G from the reference state) to 1e-6 N; the energy balance
/// of the time-varying motor torques to 1e-8.
#[tokio::test]
async fn p68_two_link_arm_follows_its_lagrange_equations() {
    let app = TestApp::new().await;
    let r = app.post("/v1/dynamics", &request("p68_two_link_arm")).await;
    assert_eq!(r.status, StatusCode::CREATED, "{}", r.text);
    let result = r.json()["result"].clone();
    let machine = &result["machine"];
    assert_eq!(machine["dof"], 2);
    let y0 = [0.2, 0.5, 1.0, 0.5];
    for sample in machine["samples"].as_array().unwrap() {
        let t = sample["t"].as_f64().unwrap();
        let y = rk4(y0, t);
        let [a1, a2] = accelerations(t, y);
        let (shoulder, elbow) = (&sample["inputs"][0], &sample["inputs"][1]);
        close(&shoulder["angle"], y[0], 1e-8, "φ₁ = q₁");
        close(&elbow["angle"], y[1] - y[0], 1e-8, "φ₂ = q₂ − q₁");
        close(&shoulder["speed"], y[2], 1e-7, "q̇₁");
        close(&elbow["speed"], y[3] - y[2], 1e-7, "q̇₂ − q̇₁");
        close(&shoulder["acceleration"], a1, 1e-6, "q̈₁");
        close(&elbow["acceleration"], a2 - a1, 1e-6, "q̈₂ − q̈₁");
        let reaction = sample["reactions"].as_array().unwrap().iter().find(|x| x["joint"] == "shoulder").unwrap();
        assert_eq!(reaction["on"], "upper arm", "{reaction}");
        let [fx, fy] = shoulder_force(y, [a1, a2]);
        close(&reaction["fx"], fx, 1e-6, "shoulder Fx");
        close(&reaction["fy"], fy, 1e-6, "shoulder Fy");
    }
    assert!(result["energy_residual"].as_f64().unwrap().abs() < 1e-8, "{}", result["energy_residual"]);
    assert!(result["accuracy"]["constraint_drift"].as_f64().unwrap() < 1e-10);
}

/// The ground's force on rod 1: Σ mᵢ a_Gᵢ − Σ mᵢ g, with
/// G₁ = (l₁/2)(−sin q₁, cos q₁) and G₂ = l₁(−sin q₁, cos q₁) + (l₂/2)(−sin q₂, cos q₂).
fn shoulder_force([q1, q2, w1, w2]: [f64; 4], [a1, a2]: [f64; 2]) -> [f64; 2] {
    // Acceleration of the point r(−sin q, cos q) of a rod turning at (q̇, q̈).
    let point =
        |r: f64, q: f64, w: f64, a: f64| [r * (-a * q.cos() + w * w * q.sin()), r * (-a * q.sin() - w * w * q.cos())];
    let g1 = point(L1 / 2.0, q1, w1, a1);
    let a = point(L1, q1, w1, a1);
    let rel = point(L2 / 2.0, q2, w2, a2);
    let g2 = [a[0] + rel[0], a[1] + rel[1]];
    [M1 * g1[0] + M2 * g2[0], M1 * g1[1] + M2 * g2[1] + (M1 + M2) * G]
}
