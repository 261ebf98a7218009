//! The simple pendulum's closed form, shared by tests/engine and
//! benches/work_precision (which includes this file by path): released from
//! rest at θ₀ from the bottom, sin(θ/2) = k·sn(K − t√(g/L), k), k = sin(θ₀/2).

use std::f64::consts::PI;

/// K(k) = π / (2·AGM(1, √(1 − k²))).
pub fn complete_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    // Quadratic convergence: 8 rounds reach round-off (a loop on |a − b|
    // could cycle forever on the last ulp).
    for _ in 0..8 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    PI / (2.0 * a)
}

/// Jacobi's sn(u, k) by the descending Landen transformation (Abramowitz &
/// Stegun 16.4.2–3): a₀ = 1, b₀ = k', c₀ = k; aₙ, bₙ, cₙ the arithmetic and
/// geometric means and half-differences; φ_N = 2ᴺa_N·u, then
/// φₙ₋₁ = (φₙ + asin(cₙ/aₙ·sin φₙ))/2, sn = sin φ₀.
pub fn sn(u: f64, k: f64) -> f64 {
    let (mut a, mut b, mut c) = (vec![1.0f64], (1.0 - k * k).sqrt(), vec![k]);
    while c.last().unwrap().abs() > 1e-17 && c.len() < 12 {
        let an = *a.last().unwrap();
        c.push(0.5 * (an - b));
        a.push(0.5 * (an + b));
        b = (an * b).sqrt();
    }
    let n = a.len() - 1;
    let mut phi = 2f64.powi(n as i32) * a[n] * u;
    for i in (1..=n).rev() {
        phi = 0.5 * (phi + (c[i] / a[i] * phi.sin()).asin());
    }
    phi.sin()
}
