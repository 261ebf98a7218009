//! Every joint's and driver's rows against finite differences.

use super::*;
use crate::engine::samples::{
    actuated_arm, eccentric_cam, four_bar, offset_slider_crank, planetary_train, ring_on_rim, scissor_lift,
    scotch_yoke, slider_crank, slotted_lever,
};

/// The eccentric cam with a polar cam ρ = 0.04 + 0.005 cos ψ and a
/// roller of radius 0.01 on the follower: a contact of two curves
/// that both turn (not assembled: the rows are only evaluated here).
fn polar_cam_and_roller() -> Mechanism {
    use crate::engine::curves::Curve;
    use crate::engine::expr::Expr;
    use crate::engine::function::Function;
    let mut m = eccentric_cam();
    if let JointKind::Contact(c) = &mut m.joints[2].kind {
        let rho = Function::Expr(Expr::compile("0.04 + 0.005*cos(phi)", &["phi"]).unwrap());
        c.curves =
            [Curve::polar([0.0, 0.0], 0.0, rho), Curve::Circle { centre: [0.0, 0.055], radius: 0.01, inside: false }];
    }
    m
}

/// The sample's contact made a rolling one (its rows only evaluated).
fn rolling(mut m: Mechanism) -> Mechanism {
    if let JointKind::Contact(c) = &mut m.joints[2].kind {
        c.rolling = true;
    }
    m
}

/// Every sample, covering every joint and driver type, at a displaced state.
fn cases() -> Vec<(&'static str, Mechanism, Vec<f64>, Vec<f64>)> {
    let samples = [
        ("slider-crank", offset_slider_crank()),
        ("scotch yoke", scotch_yoke()),
        ("four-bar", four_bar()),
        ("planetary train", planetary_train()),
        ("actuated arm", actuated_arm()),
        ("slider-crank r/l = 0.95", slider_crank(0.095, 0.1)),
        ("slotted lever", slotted_lever()),
        ("scissor lift", scissor_lift()),
        ("eccentric cam (a contact)", eccentric_cam()),
        ("polar cam under a roller (two curved curves)", polar_cam_and_roller()),
        ("the eccentric cam rolling", rolling(eccentric_cam())),
        ("a polar cam rolling on a roller (arc lengths by quadrature)", rolling(polar_cam_and_roller())),
        ("a ring on a rim (a particle; the arc length as an input)", ring_on_rim()),
    ];
    samples
        .into_iter()
        .map(|(name, m)| {
            let mut q = m.reference_q();
            let qd: Vec<f64> = (0..q.len()).map(|k| (k as f64 * 1.7 + 0.3).cos()).collect();
            for (k, v) in q.iter_mut().enumerate() {
                *v += 0.01 * (k as f64 + 1.0).sin();
            }
            (name, m, q, qd)
        })
        .collect()
}

/// Every joint's analytic Jacobian against central differences of Φ
/// (h = 1e-7; truncation ~h², round-off ~1e-16/h).
#[test]
fn jacobians_match_finite_differences() {
    for (name, m, q, _) in cases() {
        let inputs = vec![[0.3, 0.0, 0.0]; m.drivers.len()];
        let state = State { q: &q, qd: None, inputs: &inputs };
        let jac = evaluate(&m, &state).jacobian;
        let h = 1e-7;
        for c in 0..q.len() {
            let (mut qp, mut qm) = (q.clone(), q.clone());
            qp[c] += h;
            qm[c] -= h;
            let fp = evaluate(&m, &State { q: &qp, ..state }).phi;
            let fm = evaluate(&m, &State { q: &qm, ..state }).phi;
            for r in 0..fp.len() {
                let fd = (fp[r] - fm[r]) / (2.0 * h);
                assert!((fd - jac[(r, c)]).abs() < 1e-7, "{name} row {r} col {c}: {} vs {fd}", jac[(r, c)]);
            }
        }
    }
}

/// The blocks hold the same Φ, γ and Φ_q as the dense evaluation, for
/// every joint and driver type (the same arithmetic: bit for bit).
#[test]
fn blocks_equal_the_dense_evaluation() {
    for (name, m, q, qd) in cases() {
        let inputs = vec![[0.3, 0.2, 0.1]; m.drivers.len()];
        let state = State { q: &q, qd: Some(&qd), inputs: &inputs };
        let dense = evaluate(&m, &state);
        let (phi, gamma, blocks) = evaluate_blocks(&m, &state);
        assert_eq!(dense.phi.as_slice(), &phi[..], "{name}");
        assert_eq!(dense.gamma.as_slice(), &gamma[..], "{name}");
        let mut from_blocks = DMatrix::zeros(phi.len(), q.len());
        for (r, row) in blocks.rows.iter().enumerate() {
            for (c, d) in row.iter() {
                (0..3).for_each(|k| from_blocks[(r, c + k)] += d[k]);
            }
            row.single[..row.singles].iter().for_each(|&(c, d)| from_blocks[(r, c)] += d);
        }
        assert_eq!(dense.jacobian, from_blocks, "{name}");
    }
}

/// A driver's row alone is the same Φ and Φ_q row as in the whole
/// evaluation, for every driver type (bit for bit).
#[test]
fn a_driver_alone_is_its_row_of_the_whole() {
    for (name, m, q, qd) in cases() {
        let inputs = vec![[0.3, 0.2, 0.1]; m.drivers.len()];
        let state = State { q: &q, qd: Some(&qd), inputs: &inputs };
        let (phi, _, blocks) = evaluate_blocks(&m, &state);
        let first = phi.len() - m.drivers.len();
        for k in 0..m.drivers.len() {
            let (alone, row) = evaluate_driver(&m, &state, k);
            assert_eq!(alone, phi[first + k], "{name} driver {k}");
            let whole = blocks.rows[first + k];
            assert_eq!((row.dot(&qd), row.len, row.singles), (whole.dot(&qd), whole.len, whole.singles), "{name} {k}");
        }
    }
}

/// γ = −(Φ_q q̇)_q q̇ (no input acceleration): against the central
/// difference of Φ_q(q + s q̇)·q̇ in s (h = 1e-6).
#[test]
fn gamma_matches_the_derivative_of_the_jacobian_along_the_velocity() {
    for (name, m, q, qd) in cases() {
        let inputs = vec![[0.3, 0.0, 0.0]; m.drivers.len()];
        let gamma = evaluate(&m, &State { q: &q, qd: Some(&qd), inputs: &inputs }).gamma;
        let h = 1e-6;
        let jv = |s: f64| {
            let qs: Vec<f64> = q.iter().zip(&qd).map(|(a, b)| a + s * b).collect();
            let j = evaluate(&m, &State { q: &qs, qd: None, inputs: &inputs }).jacobian;
            &j * DVector::from_column_slice(&qd)
        };
        let fd = (jv(h) - jv(-h)) / (2.0 * h);
        for r in 0..gamma.len() {
            assert!((gamma[r] + fd[r]).abs() < 1e-7, "{name} row {r}: {} vs {}", gamma[r], -fd[r]);
        }
    }
}
