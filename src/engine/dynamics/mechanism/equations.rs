//! The mechanism's equations of motion at a state, in one of two forms
//! that give the same q̈ and λ:
//! - *sparse* ([`RangeSpace`]): S = Φ_q M⁻¹ Φ_qᵀ factored by a sparse
//!   LDLᵀ, whose small pivots tell and hold the nearly dependent rows at a
//!   singular position; cost linear in the mechanism's size. Used whenever
//!   it applies (every body with mass and inertia, no redundant constraint);
//! - *dense*: the augmented matrix [M Φ_qᵀ; Φ_q 0] by LU, rows combined
//!   by [`Rows`] (which holds the nearly dependent combinations at a
//!   singular position by Φ_q's singular values and drops the dependent
//!   ones); any mechanism, cost growing as its size cubed. Also where the
//!   sparse form holds a combination and a sample asks which joints'
//!   reactions are indeterminate.

use super::MechanismProblem;
use super::grip::{Grip, Grips, Mode, friction};
use super::plain::{Plain, Reported, Sizes};
use crate::engine::constraints::{State, System, evaluate, evaluate_blocks, evaluate_driver};
use crate::engine::dynamics::Integrator;
use crate::engine::dynamics::range_space::RangeSpace;
use crate::engine::dynamics::rows::Rows;
use crate::engine::kinetostatics::{Frame, applied_forces, potential};
use crate::engine::model::Mechanism;
use crate::engine::numeric::scaled::{row_scales, scaled};
use nalgebra::{DMatrix, DVector};
use std::cell::{Cell, RefCell};

/// q̈ and λ at a state, with what a sample reports.
pub(super) struct Motion {
    pub qdd: Vec<f64>,
    pub lambda: Vec<f64>,
    pub forces: Vec<f64>,
    /// Coordinate, speed and acceleration of every input.
    pub inputs: Vec<[f64; 3]>,
    /// |Φ| of the joints.
    pub residual: f64,
    /// Joint rows in a held or dropped combination, when asked for (empty:
    /// none; always so in the sparse form, which leaves a sample that holds
    /// a combination to the dense form).
    pub loose: Vec<bool>,
}

pub(super) struct Equations<'a> {
    pub p: &'a MechanismProblem,
    /// Coordinates n and joint rows r.
    pub n: usize,
    pub r: usize,
    pub mass: Vec<f64>,
    /// Column scale S of Φ_q for [`Rows`], the projection and the
    /// equations of motion: c_j/L (`model::scale`), 1 for x, y and 1/L for angles.
    pub scale: Vec<f64>,
    /// Position tolerance of the projection, m (angles: rad times L).
    pub tol: f64,
    /// The sparse form, when it applies.
    pub sparse: Option<RefCell<RangeSpace>>,
    /// The dense form's common case, where the sparse form does not apply
    /// and no contact has friction.
    pub plain: Option<RefCell<Plain>>,
    /// Times of the evaluations that held a fold.
    pub held_at: RefCell<Vec<f64>>,
    /// Evaluations in the dense form.
    pub dense: Cell<usize>,
    /// The energy E = T + V to hold after every step (loads with a potential V only).
    pub energy: Option<f64>,
    /// Steps after which T + V was E (set so, or already within rounding of it).
    pub energy_held: Cell<usize>,
    /// The rolling contacts with friction, their state now, at the start,
    /// and after each change (from its time on) for the samples.
    pub grips: Vec<Grip>,
    /// The other contacts that push and never pull: (joint, first row).
    pub one_sided: Vec<(usize, usize)>,
    pub held: RefCell<Grips>,
    pub start: Grips,
    pub history: RefCell<Vec<(f64, Grips)>>,
}

impl Equations<'_> {
    /// The time of the first fold held, where the pair asked is not
    /// Dormand–Prince, the one pair whose steps the hold keeps on the
    /// mechanism's branch: the run stops there (every evaluation after it
    /// NaN, so that its steps fail) and is made again with it.
    pub fn stopped_at_fold(&self) -> Option<f64> {
        let stops = self.p.integrator.is_some_and(|i| i != Integrator::Dopri5);
        stops.then(|| self.held_at.borrow().first().copied()).flatten()
    }

    fn zeros(&self) -> Vec<[f64; 3]> {
        vec![[0.0; 3]; self.p.mechanism.drivers.len()]
    }

    /// A bound of the first input's error from errors `e` of the
    /// coordinates: Σ|∂φ/∂q_j|·e_j at q.
    pub fn input_error(&self, q: &[f64], e: &[f64]) -> f64 {
        let zeros = self.zeros();
        let (_, row) = evaluate_driver(&self.p.mechanism, &State { q, qd: None, inputs: &zeros }, 0);
        let blocks: f64 = row.iter().map(|(c, d)| (0..3).map(|k| d[k].abs() * e[c + k]).sum::<f64>()).sum();
        blocks + row.single[..row.singles].iter().map(|&(c, d)| d.abs() * e[c]).sum::<f64>()
    }

    /// φ and φ̇ of the first input.
    pub fn input(&self, q: &[f64], qd: Option<&[f64]>) -> (f64, f64) {
        let zeros = self.zeros();
        let (phi, row) = evaluate_driver(&self.p.mechanism, &State { q, qd: None, inputs: &zeros }, 0);
        (phi, qd.map_or(0.0, |v| row.dot(v)))
    }

    fn forces(&self, t: f64, q: &[f64], qd: &[f64], [phi, omega]: [f64; 2]) -> Vec<f64> {
        let phi = phi.rem_euclid(self.p.period);
        applied_forces(&self.p.mechanism, &self.p.loads, q, qd, phi, [omega, t]).data.into()
    }

    /// The motion at a state; None where the equations are singular or the
    /// state is not finite.
    pub fn motion(&self, t: f64, q: &[f64], qd: &[f64], loose: bool) -> Option<Motion> {
        match self.plain_motion(t, q, qd, loose) {
            Some(motion) => Some(motion).filter(finite),
            None => self.general_motion(t, q, qd, loose),
        }
    }

    /// [`Self::motion`] without [`Plain`]: the sparse form, else the
    /// general dense one (what the integrator asks where [`Self::plain`]
    /// declined, so that the plain test is not made twice).
    pub fn general_motion(&self, t: f64, q: &[f64], qd: &[f64], loose: bool) -> Option<Motion> {
        let sparse = self.sparse.as_ref().and_then(|rs| self.sparse_motion(&mut rs.borrow_mut(), t, q, qd, loose));
        let motion = match sparse {
            Some(motion) => motion,
            None => self.dense_motion(t, q, qd, loose)?,
        };
        Some(motion).filter(finite)
    }

    fn sizes(&self) -> Sizes<'_> {
        Sizes { n: self.n, r: self.r, mass: &self.mass, scale: &self.scale }
    }

    /// q̈ into `qdd` and the loads' power Qᵀq̇ by [`Plain`], where it
    /// applies (None: [`Self::general_motion`] decides).
    pub fn plain(&self, t: f64, q: &[f64], qd: &[f64], qdd: &mut [f64]) -> Option<f64> {
        let sizes = self.sizes();
        let power = self.plain.as_ref()?.borrow_mut().accelerations(self.p, &sizes, t, [q, qd], qdd)?;
        self.dense.set(self.dense.get() + 1);
        (power.is_finite() && qdd.iter().all(|v| v.is_finite())).then_some(power)
    }

    /// [`Self::motion`] by [`Self::plain`], where it applies (every row
    /// kept: none is loose): the integrator's evaluation, and what a sample
    /// reports of it.
    fn plain_motion(&self, t: f64, q: &[f64], qd: &[f64], loose: bool) -> Option<Motion> {
        let mut qdd = vec![0.0; self.n];
        self.plain(t, q, qd, &mut qdd)?;
        let Reported { lambda, forces, inputs, residual } =
            self.plain.as_ref()?.borrow().reported(&self.sizes(), qd, &qdd);
        let loose = if loose { vec![false; self.r] } else { Vec::new() };
        Some(Motion { qdd, lambda, forces, inputs, residual, loose })
    }

    /// The sparse form's motion, or None where the dense form decides: S
    /// not finite, or a combination held where `loose` rows are asked for.
    fn sparse_motion(&self, rs: &mut RangeSpace, t: f64, q: &[f64], qd: &[f64], loose: bool) -> Option<Motion> {
        let zeros = self.zeros();
        let (phi, gamma, jac) = evaluate_blocks(&self.p.mechanism, &State { q, qd: Some(qd), inputs: &zeros });
        let held = rs.factor(&jac)?;
        if held > 0 {
            if loose {
                return None;
            }
            if rs.holds_fully() {
                self.held_at.borrow_mut().push(t);
            }
        }
        let forces = self.forces(t, q, qd, [phi[self.r], jac.rows[self.r].dot(qd)]);
        let (qdd, lambda) = rs.accelerations(&jac, &forces, &gamma[..self.r]);
        let inputs =
            (self.r..phi.len()).map(|k| [phi[k], jac.rows[k].dot(qd), jac.rows[k].dot(&qdd) - gamma[k]]).collect();
        let residual = phi[..self.r].iter().fold(0.0f64, |a, v| a.max(v.abs()));
        Some(Motion { qdd, lambda, forces, inputs, residual, loose: Vec::new() })
    }

    fn dense_motion(&self, t: f64, q: &[f64], qd: &[f64], loose: bool) -> Option<Motion> {
        self.dense.set(self.dense.get() + 1);
        let (n, r) = (self.n, self.r);
        let sys = self.system(q, Some(qd));
        let active = self.active_rows();
        let jac = sys.jacobian.rows(0, r).select_rows(&active);
        let rows = Rows::of(&jac, &self.scale);
        if rows.holds() {
            self.held_at.borrow_mut().push(t);
        }
        // Solved for S⁻¹q̈ (S the columns' `scale`): [S M S, (Φ_q S)ᵀ; Φ_q S, 0]
        // alike in every entry's size at any size of the mechanism.
        let s = &self.scale;
        let jac = scaled(&rows.motion(jac), [&[], s]);
        let k = jac.nrows();
        let speed = |row: usize, v: &DVector<f64>| (sys.jacobian.row(row) * v)[0];
        let qd_v = DVector::from_column_slice(qd);
        let mut forces = self.forces(t, q, qd, [sys.phi[r], speed(r, &qd_v)]);
        let mut a = DMatrix::zeros(n + k, n + k);
        for (i, m) in self.mass.iter().enumerate() {
            a[(i, i)] = m * s[i] * s[i];
        }
        a.view_mut((0, n), (n, k)).copy_from(&jac.transpose());
        a.view_mut((n, 0), (k, n)).copy_from(&jac);
        let lu = a.lu();
        let mut b = DVector::zeros(n + k);
        b.rows_mut(0, n).iter_mut().zip(forces.iter().zip(s)).for_each(|(b, (f, s))| *b = f * s);
        b.rows_mut(n, k).copy_from(&rows.gamma(sys.gamma.select_rows(&active)));
        let mut x = lu.solve(&b)?;
        // λ of every joint row (0 for a slipping grip's rolling row, left out).
        let lambda = |x: &DVector<f64>| {
            let mut all = vec![0.0; r];
            let kept = rows.multipliers(x.rows(n, k).into_owned());
            active.iter().zip(kept.iter()).for_each(|(row, v)| all[*row] = *v);
            all
        };
        let mut lambda_all = lambda(&x);
        let slipping = self.slipping(q, qd);
        if !slipping.is_empty() {
            let gradients: Vec<DVector<f64>> =
                slipping.iter().map(|(g, ..)| sys.jacobian.row(g.roll_row).transpose()).collect();
            let units: Vec<DVector<f64>> = gradients
                .iter()
                .map(|g| lu.solve(&DVector::from_fn(n + k, |i, _| if i < n { g[i] * s[i] } else { 0.0 })))
                .collect::<Option<_>>()?;
            let unit_lambda: Vec<Vec<f64>> = units.iter().map(&lambda).collect();
            let alpha = friction(&slipping, &lambda_all, &unit_lambda)?;
            for (a, (unit, g)) in alpha.iter().zip(units.iter().zip(&gradients)) {
                x.axpy(*a, unit, 1.0);
                forces.iter_mut().zip(g.iter()).for_each(|(f, gi)| *f += a * gi);
            }
            lambda_all = lambda(&x);
            // The rolling row's multiplier in effect: the friction along it.
            slipping.iter().zip(&alpha).for_each(|((grip, ..), a)| lambda_all[grip.roll_row] = *a);
        }
        let qdd = x.rows(0, n).component_mul(&DVector::from_column_slice(s));
        let inputs = (r..sys.phi.len()).map(|row| [sys.phi[row], speed(row, &qd_v), speed(row, &qdd) - sys.gamma[row]]);
        Some(Motion {
            inputs: inputs.collect(),
            residual: sys.phi.select_rows(&active).amax(),
            // Indexed by joint row: a slipping grip's rolling row, left out, is not loose.
            loose: if loose {
                (0..r).map(|row| active.iter().position(|a| *a == row).is_some_and(|i| rows.touches_loose(i))).collect()
            } else {
                Vec::new()
            },
            lambda: lambda_all,
            qdd: qdd.data.into(),
            forces,
        })
    }

    /// Φ, Φ_q (and γ with velocities) at q, each grip's rolling row less
    /// the arc length it has slipped.
    pub(super) fn system(&self, q: &[f64], qd: Option<&[f64]>) -> System {
        let mut sys = evaluate(&self.p.mechanism, &State { q, qd, inputs: &self.zeros() });
        for (grip, slipped) in self.grips.iter().zip(&self.held.borrow().slipped) {
            sys.phi[grip.roll_row] -= slipped;
        }
        sys
    }

    /// The joint rows in the equations now: all but slipping grips' rolling rows.
    fn active_rows(&self) -> Vec<usize> {
        let held = self.held.borrow();
        let out = |row: &usize| self.grips.iter().zip(&held.modes).any(|(g, m)| g.roll_row == *row && *m != Mode::Roll);
        (0..self.r).filter(|row| !out(row)).collect()
    }

    /// The slipping grips, with σ and their frame at (q, q̇).
    fn slipping(&self, q: &[f64], qd: &[f64]) -> Vec<(Grip, f64, Frame)> {
        let held = self.held.borrow();
        let m = &self.p.mechanism;
        let slip = |(g, mode): (&Grip, &Mode)| match mode {
            Mode::Slip(sigma) => Frame::of(m, g.joint, q, qd).map(|f| (*g, *sigma, f)),
            Mode::Roll => None,
        };
        self.grips.iter().zip(&held.modes).filter_map(slip).collect()
    }

    /// The x with J x = b (J of full row rank) of least |S⁻¹x|, S the
    /// columns' `scale`: the least change in lengths of the mechanism's
    /// size, whatever that size.
    fn min_norm(&self, jac: DMatrix<f64>, b: &DVector<f64>) -> Option<DVector<f64>> {
        let jac = scaled(&jac, [&[], &self.scale]);
        let ch = (&jac * jac.transpose()).cholesky()?;
        Some((jac.transpose() * ch.solve(b)).component_mul(&DVector::from_column_slice(&self.scale)))
    }

    pub fn kinetic(&self, qd: &[f64]) -> f64 {
        kinetic(&self.mass, qd)
    }

    /// Moves y onto Φ = 0 and Φ_q q̇ = 0 (Newton, least corrections: in the
    /// metric M in the sparse form, Euclidean in the dense), then onto the
    /// energy when it is held; the largest |Φ| removed.
    pub fn project(&self, y: &mut [f64]) -> f64 {
        let removed = match (&self.sparse, &self.plain) {
            (Some(rs), _) => self.project_sparse(&mut rs.borrow_mut(), y),
            (None, Some(plain)) => {
                let plain = plain.borrow_mut().project(self.p, &self.sizes(), self.tol, y);
                plain.unwrap_or_else(|removed| removed.max(self.project_dense(y)))
            }
            (None, None) => self.project_dense(y),
        };
        // Not once a singular position has been met: on A02's chain (N = 20)
        // holding it past the held folds took 6× the steps and 40× the
        // dense evaluations (measured).
        if let Some(e) = self.energy.filter(|_| self.held_at.borrow().is_empty()) {
            self.hold_energy(e, y);
        }
        removed
    }

    /// Scales q̇ by s = √((E − V(q))/T): the correction along M⁻¹·∂T/∂q̇ =
    /// q̇, which keeps Φ_q·q̇ = 0. Skipped where it would change q̇ by more
    /// than 1 % (near a turning point, T → 0, where s is ill-conditioned:
    /// the next steps correct it), and where the defect E − V − T is within
    /// 100× the rounding of its terms (with T ≪ |V| that rounding, not the
    /// integration, would set the correction).
    fn hold_energy(&self, e: f64, y: &mut [f64]) {
        let n = self.n;
        let Some(v) = potential(&self.p.mechanism, &self.p.loads, &y[..n]) else { return };
        let t = self.kinetic(&y[n..2 * n]);
        let rounding = 100.0 * f64::EPSILON * (e.abs() + v.abs() + t);
        let s = ((e - v) / t).sqrt();
        if (s - 1.0).abs() <= 0.01 {
            if (e - v - t).abs() > rounding {
                y[n..2 * n].iter_mut().for_each(|v| *v *= s);
            }
            self.energy_held.set(self.energy_held.get() + 1);
        }
    }

    fn project_sparse(&self, rs: &mut RangeSpace, y: &mut [f64]) -> f64 {
        let (n, r) = (self.n, self.r);
        let zeros = self.zeros();
        let mut removed = 0.0f64;
        for _ in 0..8 {
            let (phi, _, jac) = evaluate_blocks(&self.p.mechanism, &State { q: &y[..n], qd: None, inputs: &zeros });
            let phi = &phi[..r];
            removed = phi.iter().fold(removed, |a, v| a.max(v.abs()));
            let Some(held) = rs.factor(&jac) else {
                return removed.max(self.project_dense(y));
            };
            // A held combination is not corrected in position (nor counted).
            let left = if held > 0 { rs.unheld_residual(phi) } else { phi.iter().fold(0.0f64, |a, v| a.max(v.abs())) };
            if left <= self.tol {
                let v: Vec<f64> = jac.rows[..r].iter().map(|row| row.dot(&y[n..2 * n])).collect();
                let dv = rs.correction(&jac, &v, false);
                y[n..2 * n].iter_mut().zip(&dv).for_each(|(a, d)| *a += d);
                break;
            }
            let dq = rs.correction(&jac, phi, true);
            y[..n].iter_mut().zip(&dq).for_each(|(a, d)| *a += d);
        }
        removed
    }

    fn project_dense(&self, y: &mut [f64]) -> f64 {
        let (n, r) = (self.n, self.r);
        let mut removed = 0.0f64;
        for _ in 0..8 {
            let sys = self.system(&y[..n], None);
            let active = self.active_rows();
            let (jac, phi) = (sys.jacobian.rows(0, r).select_rows(&active), sys.phi.rows(0, r).select_rows(&active));
            removed = removed.max(phi.amax());
            // A held or dropped combination is not corrected in position.
            let rows = Rows::of(&jac, &self.scale);
            let phi = rows.position_residual(phi);
            // Each row in its own size: a length row within `tol`, an angle row within tol/L.
            let (positions, mut size) = (rows.positions(jac.clone()), Vec::new());
            row_scales(&positions, &self.scale, &mut size);
            if phi.iter().zip(&size).all(|(v, r)| (v * r).abs() <= self.tol) {
                let jac = rows.motion(jac);
                let v = &jac * DVector::from_column_slice(&y[n..2 * n]);
                if let Some(dv) = self.min_norm(jac, &(-v)) {
                    y[n..2 * n].iter_mut().zip(dv.iter()).for_each(|(a, d)| *a += d);
                }
                break;
            }
            let Some(dq) = self.min_norm(positions, &(-phi)) else { break };
            y[..n].iter_mut().zip(dq.iter()).for_each(|(a, d)| *a += d);
        }
        removed
    }
}

/// q̈ and λ are finite (else the state or its equations are not).
fn finite(motion: &Motion) -> bool {
    motion.qdd.iter().chain(&motion.lambda).all(|v| v.is_finite())
}

/// T = ½ q̇ᵀ M q̇ with M's diagonal `mass`.
pub(super) fn kinetic(mass: &[f64], qd: &[f64]) -> f64 {
    0.5 * mass.iter().zip(qd).map(|(m, v)| m * v * v).sum::<f64>()
}

/// The diagonal of M: m, m, I_G of every moving body.
pub(in crate::engine::dynamics) fn masses(m: &Mechanism) -> Vec<f64> {
    (0..m.n_coordinates()).map(|k| m.mass_of(k)).collect()
}
