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
    // Outside the blend without a logarithm: a sine a row, at every
    // evaluation, made them 2.6 % of A02's at N = 40 (the same values).
    if sine >= HOLD.1 {
        return 1.0;
    }
    if sine <= HOLD.0 {
        return 0.0;
    }
    let x = ((sine / HOLD.0).ln() / (HOLD.1 / HOLD.0).ln()).clamp(0.0, 1.0);
    x * x * (3.0 - 2.0 * x)
}

/// Where two joint rows' blocks are on the same body: the pairs (k_a, k_b)
/// of their block indices (found once: the blocks' pattern is the
/// mechanism's, the same at every evaluation).
#[derive(Clone, Copy, Debug, Default)]
struct Shared {
    len: usize,
    at: [(usize, usize); 3],
}

impl Shared {
    fn of(a: &RowBlocks, b: &RowBlocks) -> Self {
        let mut shared = Self::default();
        for (ka, ca) in a.col[..a.len].iter().enumerate() {
            if let Some(kb) = b.col[..b.len].iter().position(|cb| cb == ca) {
                shared.at[shared.len] = (ka, kb);
                shared.len += 1;
            }
        }
        shared
    }

    /// S_ab = J_a W J_bᵀ over the shared bodies.
    fn product(&self, w: &[f64], a: &RowBlocks, b: &RowBlocks) -> f64 {
        self.at[..self.len]
            .iter()
            .map(|&(ka, kb)| {
                debug_assert_eq!(a.col[ka], b.col[kb], "the blocks' pattern changed");
                weighted(w, a.col[ka], &a.val[ka], &b.val[kb])
            })
            .sum()
    }
}

/// S_aa = J_a W J_aᵀ.
fn square(w: &[f64], a: &RowBlocks) -> f64 {
    a.iter().map(|(c, d)| weighted(w, c, d, d)).sum()
}

/// One body's share of J_a W J_bᵀ: its blocks `da`, `db` at column `c`.
fn weighted(w: &[f64], c: usize, da: &[f64; 3], db: &[f64; 3]) -> f64 {
    da[0] * w[c] * db[0] + da[1] * w[c + 1] * db[1] + da[2] * w[c + 2] * db[2]
}

/// S's LDLᵀ in one elimination order, with where S's entries go.
struct Factored {
    ldl: Ldl,
    /// Pairs (i, j, position, shared bodies) of joint rows sharing a body, i > j.
    pairs: Vec<(usize, usize, usize, Shared)>,
    /// Diagonal and lower values of S (elimination order; the fill's stay 0).
    diag: Vec<f64>,
    lower: Vec<f64>,
}

impl Factored {
    /// For S's graph and the joint rows' blocks, the rows `last`
    /// eliminated after the others.
    fn new(neighbours: &[Vec<usize>], last: &[usize], rows: &[RowBlocks]) -> Self {
        let pattern = Pattern::new(neighbours, last);
        let mut pairs: Vec<(usize, usize, usize, Shared)> = Vec::new();
        for (i, ns) in neighbours.iter().enumerate() {
            for &j in ns.iter().filter(|&&j| j < i) {
                let position = pattern.position(i, j).expect("S's entries are in L's pattern");
                pairs.push((i, j, position, Shared::of(&rows[i], &rows[j])));
            }
        }
        pairs.sort_unstable_by_key(|&(i, j, ..)| (i, j));
        pairs.dedup_by_key(|&mut (i, j, ..)| (i, j));
        Self { diag: vec![0.0; pattern.len()], lower: vec![0.0; pattern.entries()], pairs, ldl: Ldl::new(pattern) }
    }

    /// Factors S = J W Jᵀ of the joint rows `rows`; false where an entry is not finite.
    fn factor(&mut self, w: &[f64], rows: &[RowBlocks]) -> bool {
        for (k, &i) in self.ldl.pattern.order.iter().enumerate() {
            self.diag[k] = square(w, &rows[i]);
        }
        for &(i, j, position, shared) in &self.pairs {
            self.lower[position] = shared.product(w, &rows[i], &rows[j]);
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
    /// With rows to hold eliminated last, by those rows (sorted): each
    /// passage of a singular position holds the same ones.
    late: Vec<(Vec<usize>, Factored)>,
    /// The index in `late` of the factors in use (None: `base`).
    current: Option<usize>,
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
            base: Factored::new(&neighbours, &[], &jac.rows[..r]),
            neighbours,
            late: Vec::new(),
            current: None,
            kept: vec![1.0; r],
            hold,
            refine: false,
        })
    }

    /// Whether a combination is wholly held (its sine under the blend's low end).
    pub fn holds_fully(&self) -> bool {
        self.kept.contains(&0.0)
    }

    fn active(&self) -> &Factored {
        self.current.map_or(&self.base, |at| &self.late[at].1)
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
        if !self.base.factor(w, rows) {
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
            let at = self.late.iter().position(|(rows, _)| *rows == weak).unwrap_or_else(|| {
                if self.late.len() >= CACHED {
                    self.late.clear();
                }
                self.late.push((weak.clone(), Factored::new(&self.neighbours, &weak, rows)));
                self.late.len() - 1
            });
            if !self.late[at].1.factor(w, rows) {
                return None;
            }
            self.current = Some(at);
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

    /// ẑ = L⁻¹·b (elimination order); with `hold`, each entry times the
    /// share of it kept (0 where held).
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
    /// held combinations' right-hand sides blended to zero, refined once
    /// where a sine is below [`REFINE`].
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
mod tests;
