//! The equations of motion by the range-space method, at a cost linear in
//! the size of the mechanism. With W = M⁻¹ (diagonal: every body's 1/m,
//! 1/m, 1/I_G) and J = Φ_q of the joints, the index-1 system
//! M q̈ + Jᵀλ = Q, J q̈ = γ becomes
//!
//! ```text
//! S λ = J W Q − γ,   q̈ = W (Q − Jᵀλ),   S = J W Jᵀ,
//! ```
//!
//! S sparse (S_ij ≠ 0 only where joint rows i and j share a body) and
//! factored by a sparse LDLᵀ ([`Ldl`]) in an order fixed once per problem.
//! It needs every moving body's mass and inertia positive, and joint rows
//! independent at the start (no redundant constraint): [`RangeSpace::new`]
//! declines otherwise and the dense form is used.
//!
//! Near a singular position S loses rank and its pivots their digits: the
//! form declines there ([`RangeSpace::regular`]) and the caller uses the
//! dense form with its handling of nearly dependent rows. D_k/S_kk is the
//! squared sine of the angle (metric W) between joint row k and the rows
//! eliminated before it; the sparse form is used while every sine is at
//! least [`REGULAR`].

use crate::engine::constraints::{Blocks, RowBlocks};
use crate::engine::numeric::ldl::{Ldl, Pattern};

/// Smallest sine of a pivot at which the sparse form is used: well outside
/// the dense form's window (a singular value within 1e-5 of the largest is
/// held there; on the chain of parallelograms below that is ~1e-4 rad from
/// flat, where the sines are ~1e-4).
pub const REGULAR: f64 = 1e-2;

/// The factorised S at one configuration, with its workspaces.
pub(crate) struct RangeSpace {
    ldl: Ldl,
    /// W per coordinate.
    w: Vec<f64>,
    /// Pairs (i, j, position) of joint rows sharing a body, i > j.
    pairs: Vec<(usize, usize, usize)>,
    /// Diagonal and lower values of S (elimination order).
    diag: Vec<f64>,
    lower: Vec<f64>,
    /// Scratch in elimination order.
    z: Vec<f64>,
}

impl RangeSpace {
    /// For `r` joint rows with the blocks of `jac` (their pattern is the
    /// mechanism's and does not change); None when a body has no mass or
    /// no inertia.
    pub fn new(jac: &Blocks, r: usize, mass: &[f64]) -> Option<Self> {
        if mass.iter().any(|m| *m <= 0.0 || !m.is_finite()) {
            return None;
        }
        let mut by_column: std::collections::BTreeMap<usize, Vec<usize>> = Default::default();
        for (i, row) in jac.rows[..r].iter().enumerate() {
            for (c, _) in row.iter() {
                by_column.entry(c).or_default().push(i);
            }
        }
        let mut neighbours = vec![Vec::new(); r];
        for rows in by_column.values() {
            for &i in rows {
                neighbours[i].extend(rows.iter().copied().filter(|&j| j != i));
            }
        }
        let pattern = Pattern::new(&neighbours);
        let mut pairs: Vec<(usize, usize, usize)> = Vec::new();
        for (i, ns) in neighbours.iter().enumerate() {
            for &j in ns.iter().filter(|&&j| j < i) {
                pairs.push((i, j, pattern.position(i, j).expect("S's entries are in L's pattern")));
            }
        }
        pairs.sort_unstable();
        pairs.dedup();
        Some(Self {
            w: mass.iter().map(|m| 1.0 / m).collect(),
            pairs,
            diag: vec![0.0; r],
            lower: vec![0.0; pattern.entries()],
            z: vec![0.0; r],
            ldl: Ldl::new(pattern),
        })
    }

    /// (J_a W J_bᵀ) of two rows.
    fn product(&self, a: &RowBlocks, b: &RowBlocks) -> f64 {
        let mut s = 0.0;
        for (ca, da) in a.iter() {
            for (cb, db) in b.iter().filter(|(cb, _)| *cb == ca) {
                s += (0..3).map(|k| da[k] * self.w[cb + k] * db[k]).sum::<f64>();
            }
        }
        s
    }

    /// Factors S at the configuration of `jac`; whether the sparse form
    /// holds there (every pivot's sine at least [`REGULAR`], all finite).
    pub fn regular(&mut self, jac: &Blocks) -> bool {
        let rows = &jac.rows;
        for (k, &i) in self.ldl.pattern.order.iter().enumerate() {
            self.diag[k] = self.product(&rows[i], &rows[i]);
        }
        let mut lower = std::mem::take(&mut self.lower);
        lower.fill(0.0);
        for &(i, j, pos) in &self.pairs {
            lower[pos] = self.product(&rows[i], &rows[j]);
        }
        self.ldl.factor(&self.diag, &lower);
        self.lower = lower;
        self.ldl.d.iter().zip(&self.diag).all(|(d, s)| d.is_finite() && *d >= REGULAR * REGULAR * s)
    }

    /// y = S⁻¹·b, arguments in the original row order.
    fn solve(&mut self, b: &[f64], y: &mut [f64]) {
        let order = &self.ldl.pattern.order;
        for (k, &i) in order.iter().enumerate() {
            self.z[k] = b[i];
        }
        self.ldl.solve(&mut self.z);
        for (k, &i) in order.iter().enumerate() {
            y[i] = self.z[k];
        }
    }

    /// q̈ and λ (original rows) from Q and γ, after [`Self::regular`].
    pub fn accelerations(&mut self, jac: &Blocks, forces: &[f64], gamma: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let r = self.z.len();
        let wq: Vec<f64> = forces.iter().zip(&self.w).map(|(f, w)| f * w).collect();
        let rhs: Vec<f64> = jac.rows[..r].iter().zip(gamma).map(|(row, g)| row.dot(&wq) - g).collect();
        let mut lambda = vec![0.0; r];
        self.solve(&rhs, &mut lambda);
        let mut qdd = forces.to_vec();
        subtract_transpose(jac, &lambda, &mut qdd);
        qdd.iter_mut().zip(&self.w).for_each(|(a, w)| *a *= w);
        (qdd, lambda)
    }

    /// The least correction dx (metric M) with J·dx = −e, after [`Self::regular`].
    pub fn correction(&mut self, jac: &Blocks, e: &[f64]) -> Vec<f64> {
        let mut y = vec![0.0; e.len()];
        self.solve(e, &mut y);
        let mut dx = vec![0.0; self.w.len()];
        subtract_transpose(jac, &y, &mut dx);
        dx.iter_mut().zip(&self.w).for_each(|(a, w)| *a *= w);
        dx
    }
}

/// out −= Jᵀ·y.
fn subtract_transpose(jac: &Blocks, y: &[f64], out: &mut [f64]) {
    for (row, yi) in jac.rows.iter().zip(y) {
        for (c, d) in row.iter() {
            (0..3).for_each(|k| out[c + k] -= d[k] * yi);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::constraints::{State, evaluate, evaluate_blocks};
    use crate::engine::dynamics::equations::masses;
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
        let qd: Vec<f64> =
            pose(n, alpha + h).iter().zip(pose(n, alpha - h)).map(|(a, b)| (a - b) / (2.0 * h)).collect();
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
            let mut rs = RangeSpace::new(&jac, r, &mass).expect("every body has mass");
            assert!(rs.regular(&jac));
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
        let mut rs = RangeSpace::new(&jac, r, &mass).expect("every body has mass");
        assert!(rs.regular(&jac));
        let e: Vec<f64> = (0..r).map(|i| 1e-6 * (i as f64 * 0.7).sin()).collect();
        let dx = rs.correction(&jac, &e);
        for (i, row) in jac.rows[..r].iter().enumerate() {
            assert!((row.dot(&dx) + e[i]).abs() < 1e-18, "row {i}");
        }
        // q̇ from a central difference is in the null space to ~1e-9 of its size.
        let along: f64 = dx.iter().zip(&qd).zip(&mass).map(|((d, v), m)| d * v * m).sum();
        let size = dx.iter().zip(&mass).map(|(d, m)| d * d * m).sum::<f64>().sqrt()
            * qd.iter().zip(&mass).map(|(v, m)| v * v * m).sum::<f64>().sqrt();
        assert!(along.abs() < 1e-8 * size, "{along} of {size}");
    }

    /// Near a singular position (every crank 1e-4 rad from lying flat:
    /// sines of the pivots ~1e-4) the sparse form declines; at 0.1 rad it holds.
    #[test]
    fn declines_near_a_singular_position() {
        for (delta, regular) in [(1e-4, false), (0.1, true)] {
            let (m, _, _, jac, _, _) = state(3, FRAC_PI_2 - delta);
            let mut rs = RangeSpace::new(&jac, jac.rows.len() - 1, &masses(&m)).expect("every body has mass");
            assert_eq!(rs.regular(&jac), regular, "δ = {delta}");
        }
    }
}
