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
//! S = L D Lᵀ is Gram–Schmidt on the joint rows in the metric W: Ĵ = L⁻¹J
//! has W-orthogonal rows, Ĵ_k the part of row k not along the rows
//! eliminated before it, with |Ĵ_k|² = D_k. The *sine* of row k, √(D_k/S_kk),
//! is that part's share of the row. The equations read Ĵ q̈ = ĝ = L⁻¹γ,
//! λ̂ = Lᵀλ = D⁻¹(Ĵ W Q − ĝ).
//!
//! Near a singular position (a parallelogram four-bar lying flat) a row
//! becomes dependent on the others and its sine goes to 0: the constraint
//! along Ĵ_k repeats the others, and its right-hand side ĝ_k amplifies the
//! integrator's tiny violation by 1/sine. The combination is then *held*,
//! as the dense form holds its nearly dependent singular combinations
//! ([`super::rows`]): Ĵ_k q̈ = 0 instead of ĝ_k (blended between the two
//! over [`HOLD`]), so the mechanism keeps its fold velocity through the
//! point — nearly exact for a parallelogram, which does not fold — and the
//! position correction leaves Ĵ_k alone. For Ĵ_k to be the part of the
//! span orthogonal to *all* the other rows, not only to those eliminated
//! before it, the weak rows are eliminated last ([`LATE`]; an order per
//! set of such rows, kept). Where a pivot is rounding ([`DROP`]) the form
//! declines and the dense form decides. Forming S squares Φ_q's
//! condition, so q̈'s rounding error is ~ε/sine² of its size; below
//! [`REFINE`] the solution is refined once on the augmented system (its
//! residual solved for again with the same factors), which leaves ~ε/sine.
//!
//! Without the hold ([`RangeSpace::new`]'s `hold` false) the form declines
//! wherever a sine is under [`REGULAR`], and the dense form holds there:
//! the way to run again when the hold's steps fail.

use crate::engine::constraints::{Blocks, RowBlocks};
use crate::engine::numeric::ldl::{Ldl, Pattern};
use std::collections::HashMap;

/// Pivot sines between which a combination's right-hand side is blended
/// from held (0 below `HOLD.0`) to kept whole (above `HOLD.1`): a hold that
/// switched at one sine would make q̈ jump there, and the steps shrink to
/// nothing on the jump. Chosen on A02 (N = 3 to 40, crank speeds 1 and
/// 6 rad/s, tolerances 1e-6 to 1e-9): lower, and the violation the
/// integrator leaves, amplified by 1/sine, bends the path (errors to 1e-5);
/// a narrower blend, and the steps underflow.
const HOLD: (f64, f64) = (3e-4, 1e-3);
/// Rows whose sines are below this in the minimum-degree order are
/// eliminated last: well above `HOLD.1`, so that the order does not change
/// where a right-hand side is blended.
const LATE: f64 = 1e-2;
/// Pivot sine below which the pivot is rounding (D_k ~ a few ε of S_kk)
/// and the sparse form declines.
const DROP: f64 = 1e-8;
/// Without the hold, the sparse form declines below this sine.
const REGULAR: f64 = 1e-2;
/// Pivot sine below which the accelerations are refined once.
const REFINE: f64 = 0.1;
/// Orders with rows last kept at once (a mechanism meets a few).
const CACHED: usize = 16;

/// The share of a right-hand side kept at a pivot's sine: 0 to 1 between
/// the ends of [`HOLD`], smooth (cubic in the log of the sine).
fn kept(sine: f64) -> f64 {
    let x = ((sine / HOLD.0).ln() / (HOLD.1 / HOLD.0).ln()).clamp(0.0, 1.0);
    x * x * (3.0 - 2.0 * x)
}

/// S's LDLᵀ in one elimination order, with where S's entries go.
struct Factored {
    ldl: Ldl,
    /// Pairs (i, j, position) of joint rows sharing a body, i > j.
    pairs: Vec<(usize, usize, usize)>,
    /// Diagonal and lower values of S (elimination order).
    diag: Vec<f64>,
    lower: Vec<f64>,
}

impl Factored {
    /// For S's graph, the rows `last` eliminated after the others.
    fn new(neighbours: &[Vec<usize>], last: &[usize]) -> Self {
        let pattern = Pattern::new(neighbours, last);
        let mut pairs: Vec<(usize, usize, usize)> = Vec::new();
        for (i, ns) in neighbours.iter().enumerate() {
            for &j in ns.iter().filter(|&&j| j < i) {
                pairs.push((i, j, pattern.position(i, j).expect("S's entries are in L's pattern")));
            }
        }
        pairs.sort_unstable();
        pairs.dedup();
        Self { diag: vec![0.0; pattern.len()], lower: vec![0.0; pattern.entries()], pairs, ldl: Ldl::new(pattern) }
    }

    /// Factors S of entries S_ij = `product(i, j)`; false where one is not finite.
    fn factor(&mut self, product: impl Fn(usize, usize) -> f64) -> bool {
        for (k, &i) in self.ldl.pattern.order.iter().enumerate() {
            self.diag[k] = product(i, i);
        }
        self.lower.fill(0.0);
        for &(i, j, pos) in &self.pairs {
            self.lower[pos] = product(i, j);
        }
        if !(self.diag.iter().all(|v| v.is_finite()) && self.lower.iter().all(|v| v.is_finite())) {
            return false;
        }
        self.ldl.factor(&self.diag, &self.lower);
        true
    }

    /// Per pivot (elimination order): whether its sine is below `limit` (or not finite).
    fn sine_below(&self, limit: f64) -> impl Iterator<Item = bool> + '_ {
        self.ldl.d.iter().zip(&self.diag).map(move |(d, s)| (*d < limit * limit * s) || d.is_nan())
    }
}

/// S factorised at one configuration, with its workspaces.
pub(crate) struct RangeSpace {
    /// W per coordinate.
    w: Vec<f64>,
    /// S's graph: the joint rows sharing a body with each.
    neighbours: Vec<Vec<usize>>,
    /// In the minimum-degree order.
    base: Factored,
    /// With rows to hold eliminated last, by those rows: each passage of a
    /// singular position holds the same ones.
    late: HashMap<Vec<usize>, Factored>,
    /// The key in `late` of the factors in use (None: `base`).
    current: Option<Vec<usize>>,
    /// Per pivot of the factors in use (elimination order): the share of
    /// its equation's right-hand side kept (0: held, 1: as it is).
    kept: Vec<f64>,
    /// Whether combinations are held here (else the form declines near a singular position).
    hold: bool,
    /// A pivot's sine is below [`REFINE`].
    refine: bool,
}

impl RangeSpace {
    /// For `r` joint rows with the blocks of `jac` (their pattern is the
    /// mechanism's and does not change); None when a body has no mass or
    /// no inertia.
    pub fn new(jac: &Blocks, r: usize, mass: &[f64], hold: bool) -> Option<Self> {
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
        Some(Self {
            w: mass.iter().map(|m| 1.0 / m).collect(),
            base: Factored::new(&neighbours, &[]),
            neighbours,
            late: HashMap::new(),
            current: None,
            kept: vec![1.0; r],
            hold,
            refine: false,
        })
    }

    /// (J_a W J_bᵀ) of two rows.
    fn product(w: &[f64], a: &RowBlocks, b: &RowBlocks) -> f64 {
        let mut s = 0.0;
        for (ca, da) in a.iter() {
            for (cb, db) in b.iter().filter(|(cb, _)| *cb == ca) {
                s += (0..3).map(|k| da[k] * w[cb + k] * db[k]).sum::<f64>();
            }
        }
        s
    }

    /// Whether a combination is wholly held (its sine under the blend's low end).
    pub fn holds_fully(&self) -> bool {
        self.kept.contains(&0.0)
    }

    fn active(&self) -> &Factored {
        self.current.as_ref().and_then(|k| self.late.get(k)).unwrap_or(&self.base)
    }

    /// Factors S at the configuration of `jac`: how many combinations are
    /// held there, wholly or in part (0 away from singular positions);
    /// None where the dense form decides: S not finite, a sine under
    /// [`DROP`], or, without the hold, under [`REGULAR`]. The rows whose
    /// sines are under [`LATE`] in the minimum-degree order are eliminated
    /// again, last, so that what is held of them is the part of the rows'
    /// span orthogonal to all the other rows.
    pub fn factor(&mut self, jac: &Blocks) -> Option<usize> {
        let (w, rows) = (&self.w, &jac.rows);
        if !self.base.factor(|i, j| Self::product(w, &rows[i], &rows[j])) {
            return None;
        }
        self.current = None;
        if !self.hold {
            self.refine = false;
            return (!self.base.sine_below(REGULAR).any(|b| b)).then_some(0);
        }
        let order = &self.base.ldl.pattern.order;
        let mut weak: Vec<usize> = self.base.sine_below(LATE).zip(order).filter(|(b, _)| *b).map(|(_, &i)| i).collect();
        if !weak.is_empty() {
            weak.sort_unstable();
            let neighbours = &self.neighbours;
            if self.late.len() >= CACHED && !self.late.contains_key(&weak) {
                self.late.clear();
            }
            let late = self.late.entry(weak.clone()).or_insert_with(|| Factored::new(neighbours, &weak));
            if !late.factor(|i, j| Self::product(w, &rows[i], &rows[j])) {
                return None;
            }
            self.current = Some(weak);
        }
        let active = self.active();
        if active.sine_below(DROP).any(|b| b) {
            return None;
        }
        let keep = active.ldl.d.iter().zip(&active.diag).map(|(d, s)| kept((d / s).sqrt())).collect();
        let refine = active.sine_below(REFINE).any(|b| b);
        (self.kept, self.refine) = (keep, refine);
        Some(self.kept.iter().filter(|k| **k < 1.0).count())
    }

    /// b in elimination order.
    fn ordered(&self, b: &[f64]) -> Vec<f64> {
        self.active().ldl.pattern.order.iter().map(|&i| b[i]).collect()
    }

    /// ẑ = L⁻¹·b (elimination order), with the held entries 0 if `hold`.
    fn transformed(&self, b: &[f64], hold: bool) -> Vec<f64> {
        let mut z = self.ordered(b);
        self.active().ldl.forward(&mut z);
        if hold {
            z.iter_mut().zip(&self.kept).for_each(|(v, k)| *v *= k);
        }
        z
    }

    /// y = L⁻ᵀD⁻¹·ẑ in the original row order (ẑ in elimination order).
    fn back(&self, mut z: Vec<f64>) -> Vec<f64> {
        z.iter_mut().zip(&self.active().ldl.d).for_each(|(v, d)| *v /= d);
        self.active().ldl.backward(&mut z);
        let mut y = vec![0.0; z.len()];
        for (k, &i) in self.active().ldl.pattern.order.iter().enumerate() {
            y[i] = z[k];
        }
        y
    }

    /// q̈ and λ (original rows) from Q and γ, after [`Self::factor`]: the
    /// held combinations with zero right-hand side, refined once where a
    /// sine is below [`REFINE`].
    pub fn accelerations(&self, jac: &Blocks, forces: &[f64], gamma: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let g_hat = self.transformed(gamma, true);
        let (mut qdd, mut lambda) = self.solve_motion(jac, forces, &g_hat);
        if self.refine {
            // r₁ = Q − M q̈ − Φ_qᵀλ and ĝ − Ĵ q̈: the residual of the equations solved.
            let mut r1: Vec<f64> = forces.iter().zip(&qdd).zip(&self.w).map(|((f, a), w)| f - a / w).collect();
            subtract_transpose(jac, &lambda, &mut r1);
            let jq: Vec<f64> = jac.rows[..gamma.len()].iter().map(|row| row.dot(&qdd)).collect();
            let r2: Vec<f64> = g_hat.iter().zip(self.transformed(&jq, false)).map(|(g, j)| g - j).collect();
            let (dq, dl) = self.solve_motion(jac, &r1, &r2);
            qdd.iter_mut().zip(&dq).for_each(|(a, d)| *a += d);
            lambda.iter_mut().zip(&dl).for_each(|(a, d)| *a += d);
        }
        (qdd, lambda)
    }

    /// λ = L⁻ᵀD⁻¹(L⁻¹J W Q − ĝ) and q̈ = W (Q − Jᵀλ).
    fn solve_motion(&self, jac: &Blocks, forces: &[f64], g_hat: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let wq: Vec<f64> = forces.iter().zip(&self.w).map(|(f, w)| f * w).collect();
        let jwq: Vec<f64> = jac.rows[..g_hat.len()].iter().map(|row| row.dot(&wq)).collect();
        let z = self.transformed(&jwq, false).iter().zip(g_hat).map(|(a, g)| a - g).collect();
        let lambda = self.back(z);
        let mut qdd = forces.to_vec();
        subtract_transpose(jac, &lambda, &mut qdd);
        qdd.iter_mut().zip(&self.w).for_each(|(a, w)| *a *= w);
        (qdd, lambda)
    }

    /// The least correction dx (metric M) with J·dx = −e, after
    /// [`Self::factor`]; with `hold`, none along the held combinations (a
    /// position correction: J·dx = −e holds for the others only).
    pub fn correction(&self, jac: &Blocks, e: &[f64], hold: bool) -> Vec<f64> {
        let y = self.back(self.transformed(e, hold));
        let mut dx = vec![0.0; self.w.len()];
        subtract_transpose(jac, &y, &mut dx);
        dx.iter_mut().zip(&self.w).for_each(|(a, w)| *a *= w);
        dx
    }

    /// The largest |ẑ_k| = |(L⁻¹e)_k| over the combinations not held: what
    /// a position correction with `hold` leaves to remove.
    pub fn unheld_residual(&self, e: &[f64]) -> f64 {
        self.transformed(e, true).iter().fold(0.0f64, |a, v| a.max(v.abs()))
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
}
