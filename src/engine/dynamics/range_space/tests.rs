//! The range-space form against the dense augmented system and the
//! parallelogram chain's closed form, up to and at its flat position.

use super::*;
use crate::engine::constraints::{State, evaluate, evaluate_blocks};
use crate::engine::dynamics::mechanism::equations::masses;
use crate::engine::model::Mechanism;
use crate::engine::samples::parallelogram_chain as chain;
use nalgebra::{DMatrix, DVector};
use std::f64::consts::FRAC_PI_2;

/// The chain's coordinates with every crank turned by α from upright.
fn pose(n: usize, alpha: f64) -> Vec<f64> {
    let (s, c) = (FRAC_PI_2 + alpha).sin_cos();
    let mut q: Vec<f64> = (0..=n).flat_map(|i| [i as f64 + 0.5 * c, 0.5 * s, alpha]).collect();
    q.extend((0..n).flat_map(|i| [i as f64 + 0.5 + c, s, 0.0]));
    q
}

/// The crank's θ̈ by the chain's 1-DOF reduction (all cranks turn alike,
/// the couplers translate; m = 1 kg, l = 1 m): I* = (N+1)/3 + N and
/// V = ((N+1)/2 + N)·g·sin θ with θ = π/2 + α, so θ̈ = −V'(θ)/I*.
fn closed_form(n: usize, alpha: f64) -> f64 {
    let n = n as f64;
    -((n + 1.0) / 2.0 + n) * 9.81 * (FRAC_PI_2 + alpha).cos() / ((n + 1.0) / 3.0 + n)
}

/// Blocks, γ and Q at crank angle α, turning at α̇ = 1 rad/s (q̇ by a
/// central difference of the pose, h = 1e-7: error ~1e-14), gravity only.
fn state(n: usize, alpha: f64) -> (Mechanism, Vec<f64>, Vec<f64>, Blocks, Vec<f64>, Vec<f64>) {
    let m = chain(n);
    let q = pose(n, alpha);
    let h = 1e-7;
    let qd: Vec<f64> = pose(n, alpha + h).iter().zip(pose(n, alpha - h)).map(|(a, b)| (a - b) / (2.0 * h)).collect();
    let (_, gamma, jac) = evaluate_blocks(&m, &State { q: &q, qd: Some(&qd), inputs: &[[0.0; 3]] });
    let forces = (0..q.len()).map(|k| if k % 3 == 1 { -9.81 } else { 0.0 }).collect();
    (m, q, qd, jac, gamma, forces)
}

/// Away from singular positions q̈ and λ equal the dense augmented
/// system's (LU of [M Φ_qᵀ; Φ_q 0]) to 1e-12, and every crank's θ̈ the
/// closed form to 1e-9 (the central difference's error, amplified).
#[test]
fn agrees_with_the_dense_system_and_the_closed_form() {
    for (n, alpha) in [(3, 0.3), (3, 2.0), (12, -0.7)] {
        let (m, q, qd, jac, gamma, forces) = state(n, alpha);
        let r = jac.rows.len() - 1;
        let mass = masses(&m);
        let mut rs = RangeSpace::new(&jac, r, &mass, true).expect("every body has mass");
        assert_eq!(rs.factor(&jac), Some(0), "nothing held");
        let (qdd, lambda) = rs.accelerations(&jac, &forces, &gamma[..r]);
        let sys = evaluate(&m, &State { q: &q, qd: Some(&qd), inputs: &[[0.0; 3]] });
        let nq = q.len();
        let mut a = DMatrix::zeros(nq + r, nq + r);
        a.view_mut((0, 0), (nq, nq)).copy_from(&DMatrix::from_diagonal(&DVector::from_vec(mass)));
        let j = sys.jacobian.rows(0, r).into_owned();
        a.view_mut((0, nq), (nq, r)).copy_from(&j.transpose());
        a.view_mut((nq, 0), (r, nq)).copy_from(&j);
        let b = DVector::from_iterator(nq + r, forces.iter().copied().chain(sys.gamma.iter().take(r).copied()));
        let x = a.lu().solve(&b).expect("regular");
        for (k, v) in qdd.iter().chain(&lambda).enumerate() {
            assert!((v - x[k]).abs() <= 1e-12 * x.amax(), "N = {n}, α = {alpha}: unknown {k}: {v} vs {}", x[k]);
        }
        for crank in 0..=n {
            let want = closed_form(n, alpha);
            assert!((qdd[3 * crank + 2] - want).abs() < 1e-9, "crank {crank}: {} vs {want}", qdd[3 * crank + 2]);
        }
    }
}

/// The position correction is the least one in the metric M: J·dx = −e,
/// and dx = M⁻¹Jᵀy for some y (it has no part in J's null space: every
/// motion the constraints allow, here the chain's turning ∂q/∂α, is
/// M-orthogonal to it).
#[test]
fn corrects_along_the_constraint_normals() {
    let (m, _, qd, jac, _, _) = state(4, 0.4);
    let r = jac.rows.len() - 1;
    let mass = masses(&m);
    let mut rs = RangeSpace::new(&jac, r, &mass, true).expect("every body has mass");
    assert_eq!(rs.factor(&jac), Some(0), "nothing held");
    let e: Vec<f64> = (0..r).map(|i| 1e-6 * (i as f64 * 0.7).sin()).collect();
    let dx = rs.correction(&jac, &e, true);
    for (i, row) in jac.rows[..r].iter().enumerate() {
        assert!((row.dot(&dx) + e[i]).abs() < 1e-18, "row {i}");
    }
    // q̇ from a central difference is in the null space to ~1e-9 of its size.
    let along: f64 = dx.iter().zip(&qd).zip(&mass).map(|((d, v), m)| d * v * m).sum();
    let size = dx.iter().zip(&mass).map(|(d, m)| d * d * m).sum::<f64>().sqrt()
        * qd.iter().zip(&mass).map(|(v, m)| v * v * m).sum::<f64>().sqrt();
    assert!(along.abs() < 1e-8 * size, "{along} of {size}");
}

/// Blocks, γ and Q with q̇ exact (α̇ = 1 rad/s: cranks turn about
/// their pivots, couplers translate with the cranks' tips).
fn exact_state(n: usize, alpha: f64) -> (Vec<f64>, Blocks, Vec<f64>, Vec<f64>) {
    let (m, q, _, _, _, forces) = state(n, alpha);
    let (s, c) = (FRAC_PI_2 + alpha).sin_cos();
    let mut qd: Vec<f64> = (0..=n).flat_map(|_| [-0.5 * s, 0.5 * c, 1.0]).collect();
    qd.extend((0..n).flat_map(|_| [-s, c, 0.0]));
    let (_, gamma, jac) = evaluate_blocks(&m, &State { q: &q, qd: Some(&qd), inputs: &[[0.0; 3]] });
    (masses(&m), jac, gamma, forces)
}

/// Every crank's θ̈ against the closed form, relative error.
fn crank_error(n: usize, alpha: f64, qdd: &[f64]) -> f64 {
    let want = closed_form(n, alpha);
    (0..=n).map(|crank| (qdd[3 * crank + 2] - want).abs() / want.abs()).fold(0.0, f64::max)
}

/// Towards a flat position (every crank δ from lying flat; the pivots'
/// sines ~δ) every crank's θ̈ stays the closed form's: refined where a
/// sine is under 0.1 (without the refinement the error was 1.5e-11 at
/// δ = 0.011, N = 40, and grows as 1/δ²; the dense LU's was 1.4e-10 at
/// δ = 1e-4, N = 3), and the N fold combinations held from δ ≈ 3e-4 on:
/// the parallelogram does not fold, so holding its fold changes θ̈ by
/// ~δ/10 only (the SVD's hold in the dense form: ~δ/300). Bounds: ε/δ
/// with room where nothing is held (measured 2e-16…4e-13); where held,
/// δ/3 and the rounding of a vanishing pivot, ε/sine² (measured 1e-7 at
/// δ = 1e-6 for N = 3, 9e-6 for N = 40; 4e-3 at 1e-7 for N = 40, a
/// window of ~1e-8 s on A02). Within ~1e-8 rad the form declines.
#[test]
fn accelerations_keep_their_digits_up_to_and_at_a_singular_position() {
    for n in [3, 40] {
        for delta in [0.1, 0.011, 2e-3, 5e-4, 1e-4, 1e-5, 1e-6, 1e-7, 1e-10] {
            let alpha = FRAC_PI_2 - delta;
            let (mass, jac, gamma, forces) = exact_state(n, alpha);
            let r = jac.rows.len() - 1;
            let mut rs = RangeSpace::new(&jac, r, &mass, true).expect("every body has mass");
            let Some(held) = rs.factor(&jac) else {
                assert!(delta < 1e-8, "N = {n}, δ = {delta}: declined");
                continue;
            };
            let (qdd, _) = rs.accelerations(&jac, &forces, &gamma[..r]);
            let error = crank_error(n, alpha, &qdd);
            let bound =
                if held > 0 { delta / 3.0 + f64::EPSILON / (delta * delta) } else { 1e-13f64.max(1e-15 / delta) };
            assert!(error < bound, "N = {n}, δ = {delta}: θ̈ off by {error:.1e} of it (bound {bound:.0e})");
            if delta <= 1e-4 {
                assert!(held == n && rs.holds_fully(), "N = {n}, δ = {delta}: {held} of the {n} folds held");
            }
        }
    }
}
