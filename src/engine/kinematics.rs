//! Position, velocity and acceleration of a driven mechanism.
//!
//! Position: Newton–Raphson on Φ(q, φ) = 0 from a predicted q (continuation
//! keeps the assembly branch). Velocity: Φ_q q̇ = ν (the input speeds).
//! Acceleration: Φ_q q̈ = γ. With one input, g = dq/dφ (velocity
//! coefficients) and h = d²q/dφ² give the predictor q + gΔφ + ½hΔφ², to
//! which a sweep adds a third-order term from h's change between its last
//! two positions where that term is small (`sweep.rs`).
//! A sweep works in one [`Workspace`] and refills one [`Configuration`]:
//! after the first two positions nothing is allocated (`sweep.rs`). Where the
//! mechanism is a crank and dyads, each position is placed in closed form
//! first ([`Dyads`]) and Newton only confirms it.

mod cut;
mod dyads;
mod sweep;

pub use dyads::{Dyads, Trig};
pub use sweep::{sweep, sweep_each};

use super::EngineError;
use super::constraints::{State, System, evaluate, evaluate_gamma, evaluate_into, joint_offsets};
use super::mobility::mobility;
use super::model::Mechanism;
use super::numeric::lu::Lu;
use super::numeric::scaled;
use super::numeric::svd::{singular_values, svd};
use nalgebra::{DMatrix, DVector};

/// Newton iterations allowed per position.
const MAX_ITERATIONS: usize = 30;
/// Φ_q is treated as singular beyond this condition number of its scaled
/// form R Φ_q C ([`scaled`] with the coordinates' length scales
/// [`Mechanism::column_lengths`]: the same at any size of the drawing): velocities and
/// forces there are not computed (a regular position has a condition
/// number well below 1e4; at a toggle or change point it is 1e6 or more,
/// from round-off alone).
pub const SINGULAR_CONDITION: f64 = 1e6;

/// The mechanism at one input position.
#[derive(Clone, Debug, Default)]
pub struct Configuration {
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
    /// Velocity coefficients g = dq/dφ (one input only).
    pub g: Option<Vec<f64>>,
    /// (sin θ, cos θ) of every body at q, ground first (empty at a singular position).
    pub trig: Vec<(f64, f64)>,
    /// Φ_q here, kept for the reactions (empty at a singular position).
    pub jacobian: DMatrix<f64>,
    /// LU of Φ_q (regular when Φ_q is square and regular), for the
    /// multipliers (Φ_qᵀλ = b).
    pub lu: Lu,
    /// Condition number of Φ_q in SI units: κ₂ (exact), or below
    /// [`ESTIMATE_LIMIT`] an estimate of κ₁ when the sweep did not ask for
    /// it exactly; NaN where the sweep asked for the scaled one alone
    /// ([`Conditions::Scaled`]).
    pub condition: f64,
    /// The same of Φ_q scaled by the mechanism's size ([`scaled`]): what
    /// decides a singular position, the same at any scale of the drawing.
    pub scaled_condition: f64,
    pub iterations: usize,
    pub residual: f64,
    /// q was placed in closed form ([`Dyads`]) before Newton confirmed it.
    pub placed: bool,
    /// Φ_q is singular here (or Newton could not assemble this one position
    /// while its neighbours assemble): nothing but q (predicted) is valid.
    pub singular: bool,
    /// The contact parameters' columns that jumped here: Newton settled far
    /// from the continuation's prediction (another lobe of a cam, another
    /// stretch of a curve), not where the contact was followed to.
    pub jumped: Vec<usize>,
    /// The contacts whose bodies still cut into each other here, and how
    /// deep (joint, m): no contact outside both was found (`cut.rs`).
    pub cuts: Vec<(usize, f64)>,
}

/// Solves A x = b: LU when A is square and regular, else least squares (SVD).
pub fn solve_linear(a: &DMatrix<f64>, b: &DVector<f64>) -> Option<DVector<f64>> {
    if a.is_square()
        && let Some(x) = a.clone().lu().solve(b)
        && x.iter().all(|v| v.is_finite())
    {
        return Some(x);
    }
    if !b.iter().all(|v| v.is_finite()) {
        return None;
    }
    let svd = svd(a.clone(), true, true)?;
    let tol = 1e-12 * svd.singular_values.max();
    svd.solve(b, tol).ok()
}

/// Estimates above this send a position to the exact κ₂ (an SVD): κ₁ is
/// within a factor n (coordinates) of κ₂ either way in the worst case, and
/// is exact up to [`crate::engine::numeric::lu::EXACT_UP_TO`] coordinates,
/// beyond where Hager's method is rarely off by more than 3, so every
/// position whose κ₂ reaches the near-singular 1e4 is measured exactly for
/// mechanisms of up to 33 bodies; regular positions (κ₂ ~ 10) are not.
pub const ESTIMATE_LIMIT: f64 = 100.0;

/// Which of Φ_q's condition numbers a sweep finds at each position.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Conditions {
    /// Both, each estimated from Φ_q's LU and exact (an SVD) where its
    /// estimate exceeds [`ESTIMATE_LIMIT`].
    Estimated,
    /// Both exact (an SVD each) at every position.
    Exact,
    /// The scaled one alone, as `Estimated` finds it: what decides a
    /// singular position, for a caller that reads nothing else (a large
    /// mechanism's SVD in SI units was half of the start of its dynamics).
    Scaled,
}

/// κ₁ = ‖A‖₁·‖A⁻¹‖₁ of a square A from its LU ([`Lu::inverse_norm1`]):
/// A⁻¹ formed from the factors up to [`crate::engine::numeric::lu::EXACT_UP_TO`]
/// rows, beyond a few solves by Hager's estimator, instead of an SVD; the
/// estimate a lower bound of κ₁, in practice within a factor 3 of it.
pub fn estimated_condition(a: &DMatrix<f64>, lu: &Lu, scratch: [&mut Vec<f64>; 2]) -> f64 {
    scaled::estimated_condition(a, lu, [&[], &[]], scratch)
}

/// 2-norm condition number σ_max/σ_min of a matrix with at least as many rows as columns.
pub fn condition(a: &DMatrix<f64>) -> f64 {
    let Some(s) = singular_values(a) else { return f64::INFINITY };
    let (max, min) = (s.max(), s.min());
    if min > 0.0 { max / min } else { f64::INFINITY }
}

/// What Newton, the velocity and acceleration solves and the condition
/// estimate reuse from one position to the next.
#[derive(Clone, Debug, Default)]
pub struct Workspace {
    /// Φ, Φ_q and γ at the last evaluation.
    pub sys: System,
    /// Φ_q's LU at the last factorisation.
    pub lu: Lu,
    /// The solutions of Φ_q q̇ = ν and Φ_q q̈ = γ after [`Workspace::motion`]
    /// (g and h when the one input's speed is 1 and its acceleration 0).
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
    /// The coordinates' length scales c_j ([`Mechanism::column_lengths`];
    /// empty: all 1) and the rows' r_i at the last evaluation ([`scaled`]).
    pub cols: Vec<f64>,
    rows: Vec<f64>,
    /// Scratch: a right-hand side kept for the least-squares fallback, the
    /// estimators' start vectors (SI, scaled) and their scratch.
    b: Vec<f64>,
    x: Vec<f64>,
    xs: Vec<f64>,
    y: Vec<f64>,
}

impl Workspace {
    /// Newton–Raphson from `q` to Φ = 0 at the given inputs, to |R Φ|∞ ≤
    /// 1e-13 (1 + max |q_j / c_j|) (each row in its own size, [`scaled`]):
    /// the iterations and the final |Φ|∞; Φ and Φ_q there are in `self.sys`,
    /// and R's r_i in `self.rows`.
    pub fn assemble(
        &mut self,
        m: &Mechanism,
        q: &mut [f64],
        inputs: &[[f64; 3]],
        step: usize,
    ) -> Result<(usize, f64), EngineError> {
        let c = |j: usize| self.cols.get(j).copied().unwrap_or(1.0);
        let tol = 1e-13 * (1.0 + q.iter().enumerate().fold(0.0f64, |a, (j, v)| a.max((v / c(j)).abs())));
        let mut residual = f64::INFINITY;
        for iteration in 0..=MAX_ITERATIONS {
            evaluate_into(m, &State { q, qd: None, inputs }, &mut self.sys);
            residual = self.sys.phi.amax();
            scaled::row_scales(&self.sys.jacobian, &self.cols, &mut self.rows);
            if self.sys.phi.iter().zip(&self.rows).all(|(v, r)| (v * r).abs() <= tol) {
                return Ok((iteration, residual));
            }
            // Δq with Φ_q Δq = −Φ, in `qd`'s storage.
            self.lu.factor(&self.sys.jacobian);
            self.qd.clear();
            self.qd.extend(self.sys.phi.iter().map(|v| -v));
            if !solve(&self.sys.jacobian, &self.lu, &mut self.b, &mut self.qd) {
                break;
            }
            q.iter_mut().zip(&self.qd).for_each(|(v, d)| *v += d);
        }
        let joint = widest_gap(m, q, inputs);
        Err(EngineError::NewtonDiverged { step, input: inputs.first().map_or(0.0, |i| i[0]), residual, joint })
    }

    /// q̇ and q̈ (into `self.qd`, `self.qdd`) at a q assembled by
    /// [`Workspace::assemble`] (Φ_q does not depend on the input speeds),
    /// with one factorisation of Φ_q (left in `self.lu`); false where either
    /// has no solution. `self.sys` then holds Φ, Φ_q and γ.
    pub fn motion(&mut self, m: &Mechanism, q: &[f64], inputs: &[[f64; 3]]) -> bool {
        self.lu.factor(&self.sys.jacobian);
        // ν: the input speeds in the drivers' rows.
        self.qd.clear();
        self.qd.resize(self.sys.phi.len(), 0.0);
        let first = self.qd.len() - m.drivers.len();
        inputs.iter().enumerate().for_each(|(k, input)| self.qd[first + k] = input[1]);
        if !solve(&self.sys.jacobian, &self.lu, &mut self.b, &mut self.qd) {
            return false;
        }
        evaluate_gamma(m, &State { q, qd: Some(&self.qd), inputs }, &mut self.sys);
        self.qdd.clear();
        self.qdd.extend(self.sys.gamma.iter());
        solve(&self.sys.jacobian, &self.lu, &mut self.b, &mut self.qdd)
    }

    /// q one Newton step nearer Φ = 0 by the LU [`Workspace::motion`] left
    /// at it (`sys` holds Φ there); q as it was where that LU cannot solve.
    fn refine(&mut self, q: &mut [f64]) {
        self.b.clear();
        self.b.extend(self.sys.phi.iter().map(|v| -v));
        if self.lu.solve(&mut self.b) {
            q.iter_mut().zip(&self.b).for_each(|(v, d)| *v += d);
        }
    }

    /// Φ_q's condition numbers, in SI units and scaled ([`scaled`]), as
    /// `which` asks: each κ₂ exactly when [`Conditions::Exact`] or where its
    /// estimate from Φ_q's LU exceeds [`ESTIMATE_LIMIT`], else the estimate
    /// (the SI one NaN when [`Conditions::Scaled`]).
    /// The r_i are those [`Workspace::assemble`] left for this Φ_q (where
    /// it converged: the last Φ_q it evaluated).
    fn conditions(&mut self, which: Conditions) -> [f64; 2] {
        let a = &self.sys.jacobian;
        let scales = [self.rows.as_slice(), self.cols.as_slice()];
        let estimated = which != Conditions::Exact && self.lu.is_regular();
        let [si, of_scaled] = match which {
            _ if !estimated => [f64::INFINITY; 2],
            Conditions::Scaled => {
                [f64::NAN, scaled::estimated_condition(a, &self.lu, scales, [&mut self.xs, &mut self.y])]
            }
            _ => scaled::estimated_conditions(a, &self.lu, scales, [&mut self.x, &mut self.xs, &mut self.y]),
        };
        [
            match which {
                Conditions::Scaled => f64::NAN,
                _ if si <= ESTIMATE_LIMIT => si,
                _ => condition(a),
            },
            if of_scaled <= ESTIMATE_LIMIT { of_scaled } else { condition(&scaled::scaled(a, scales)) },
        ]
    }
}

/// x with A x = b (b given in x) by A's factors `lu`, or by least squares
/// where A is not square or its LU fails (`b` keeps the right-hand side).
fn solve(a: &DMatrix<f64>, lu: &Lu, b: &mut Vec<f64>, x: &mut Vec<f64>) -> bool {
    b.clone_from(x);
    if lu.solve(x) {
        return true;
    }
    match solve_linear(a, &DVector::from_column_slice(b)) {
        Some(s) => {
            x.clear();
            x.extend(s.iter());
            true
        }
        None => false,
    }
}

/// The joint (or input) whose constraint rows are violated most at `q`.
fn widest_gap(m: &Mechanism, q: &[f64], inputs: &[[f64; 3]]) -> String {
    let phi = evaluate(m, &State { q, qd: None, inputs }).phi;
    let offsets = joint_offsets(m);
    let Some(row) = (0..phi.len()).max_by(|&a, &b| phi[a].abs().total_cmp(&phi[b].abs())) else { return String::new() };
    match offsets.iter().rposition(|&o| o <= row) {
        Some(j) if row < offsets[j] + Mechanism::joint_rows(&m.joints[j].kind) => format!("joint {}", m.joints[j].name),
        _ => "the input".into(),
    }
}

/// The error of positions that cannot be reached, or, when the joints leave
/// the mechanism no freedom at all, that it is locked.
fn unreachable(m: &Mechanism, e: EngineError) -> EngineError {
    match e {
        EngineError::NewtonDiverged { .. } if !m.drivers.is_empty() && mobility(m, &m.reference_q()).dof == 0 => {
            EngineError::Locked { grubler: m.grubler().mobility }
        }
        e => e,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::Deadline;
    use std::f64::consts::FRAC_PI_2;

    /// Positions reach `each` in order, one at a time, and its error stops
    /// the sweep there: the slider-crank over 8 positions, stopped at the 4th.
    #[test]
    fn a_sweep_hands_over_each_position_and_stops_on_an_error() {
        let m = crate::engine::samples::offset_slider_crank();
        let positions: Vec<Vec<[f64; 3]>> = (0..8).map(|k| vec![[0.5 * k as f64, 1.0, 0.0]]).collect();
        let all = sweep(&m, &positions, &Deadline::none(), Conditions::Estimated).unwrap();
        let mut seen = Vec::new();
        let stopped = sweep_each(&m, &positions, &Deadline::none(), Conditions::Estimated, |k, c| {
            seen.push((k, c.q.clone()));
            if k == 3 { Err(EngineError::Singular { step: k, input: 0.0 }) } else { Ok(()) }
        });
        assert!(matches!(stopped, Err(EngineError::Singular { step: 3, .. })));
        assert_eq!(seen.iter().map(|(k, _)| *k).collect::<Vec<_>>(), [0, 1, 2, 3]);
        assert!(seen.iter().all(|(k, q)| *q == all[*k].q), "the same configurations as the whole sweep");
    }

    /// Asked for the scaled condition alone, a sweep finds the same one and
    /// the same singular positions, bit for bit, and no SI one: IFToMM
    /// A02's chain (N = 3) upright, leaning, flat (every loop singular) and
    /// past it, and at N = 40 upright (both estimates above the limit, so
    /// that the SI one would take an SVD of its own).
    #[test]
    fn the_scaled_condition_alone_is_the_one_of_both() {
        let lean = |t: f64| vec![[t, 1.0, 0.0]];
        let cases = [(3, vec![lean(FRAC_PI_2), lean(0.6), lean(0.0), lean(-0.4)]), (40, vec![lean(FRAC_PI_2)])];
        for (n, positions) in cases {
            let m = crate::engine::samples::parallelogram_chain(n);
            let both = sweep(&m, &positions, &Deadline::none(), Conditions::Estimated).unwrap();
            let alone = sweep(&m, &positions, &Deadline::none(), Conditions::Scaled).unwrap();
            for (b, a) in both.iter().zip(&alone) {
                assert_eq!(
                    (a.scaled_condition.to_bits(), a.singular, &a.q),
                    (b.scaled_condition.to_bits(), b.singular, &b.q)
                );
                assert!(a.condition.is_nan() && !b.condition.is_nan(), "N = {n}: {} and {}", a.condition, b.condition);
            }
            assert_eq!(both.iter().filter(|c| c.singular).count(), usize::from(n == 3), "flat at N = 3 only");
            assert!(n == 3 || both[0].condition > ESTIMATE_LIMIT, "N = 40: κ {}", both[0].condition);
        }
    }

    /// A system holding NaN (a state gone bad) has no solution and returns at
    /// once: nalgebra's own SVD never returns on it.
    #[test]
    fn a_system_with_nan_is_unsolvable_not_endless() {
        let a = DMatrix::from_row_slice(3, 2, &[1.0, 0.0, f64::NAN, 1.0, 0.0, 2.0]);
        assert!(solve_linear(&a, &DVector::from_element(3, 1.0)).is_none());
        assert_eq!(condition(&a), f64::INFINITY);
    }

    /// Hager's estimate is a lower bound of κ₁ = ‖A‖₁‖A⁻¹‖₁ (the inverse
    /// formed here) and, on these matrices, equal to it or within a factor 3,
    /// each started from the last one's maximiser as in a sweep:
    /// K1's Φ_q at 36 crank angles (κ ~ 10), a nearly singular 2×2
    /// (κ₁ = (2 + 1e-6)²/1e-6) and a 7×7 with row exchanges.
    #[test]
    fn the_estimated_condition_bounds_the_1_norm_one() {
        let m = crate::engine::samples::offset_slider_crank();
        let positions: Vec<Vec<[f64; 3]>> = (0..36).map(|k| vec![[k as f64 * 0.17, 1.0, 0.0]]).collect();
        let mut matrices: Vec<DMatrix<f64>> = sweep(&m, &positions, &Deadline::none(), Conditions::Exact)
            .unwrap()
            .into_iter()
            .map(|c| c.jacobian)
            .collect();
        matrices.push(DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 1.0, 1.0 + 1e-6]));
        matrices.push(DMatrix::from_fn(7, 7, |i, j| if i == j { 0.0 } else { ((3 * i + 5 * j) as f64).sin() }));
        let norm1 = |a: &DMatrix<f64>| a.column_iter().map(|c| c.abs().sum()).fold(0.0, f64::max);
        // One start vector along the sweep's matrices, as a sweep keeps it.
        let (mut x, mut y) = (Vec::new(), Vec::new());
        for a in matrices {
            let kappa1 = norm1(&a) * norm1(&a.clone().try_inverse().unwrap());
            let mut lu = Lu::default();
            lu.factor(&a);
            let estimate = estimated_condition(&a, &lu, [&mut x, &mut y]);
            assert!(estimate <= kappa1 * (1.0 + 1e-9) && estimate >= kappa1 / 3.0, "{estimate} vs κ₁ {kappa1}");
        }
    }
}
