//! The friction's magnitudes where the fixed point does not contract (a
//! pass that shrinks the change by less than half): followed from the
//! frictionless mechanism to the given one, every coefficient scaled by t
//! from 0 to 1, by Newton's method on
//!
//! ```text
//! F(f, t) = f − g(L + t·Σ_j f_j Y_j) = 0,   ∂F/∂f = I − t·D,   D_kj = ∂g_k/∂R · Y_jk
//! ```
//!
//! (L_k what presses joint k under the loads, Y_jk what a unit of joint j's
//! friction adds to it, g_k its magnitude, [`super::friction`]). The branch
//! from t = 0 is the one the sliding directions fix: det(I − tD) stays
//! positive along it, and a root where it is not (another branch) is not
//! taken. Where the branch ends before t = 1 — the magnitudes grow without
//! bound as det → 0, or it turns back — no finite effort drives the
//! mechanism with the given coefficients (self-locking); t* there is the
//! fraction of them it would still move with.

use super::Reaction;
use super::friction::Unit;
use super::multipliers::PerUnit;
use crate::engine::{Deadline, EngineError, Progress};
use nalgebra::{DMatrix, DVector};

/// Newton iterations allowed at one t.
const NEWTON_ITERATIONS: usize = 16;

/// The smallest step in t before the branch is taken to end.
const SMALLEST_STEP: f64 = 1e-9;

/// What a unit of each joint's friction adds to what presses the joints,
/// and what presses them under the loads alone.
pub(super) struct Pressing<'a> {
    pub units: &'a [Unit],
    /// L_k, in the units' order.
    pub loads: &'a [Reaction],
    /// `per[j].reactions[k]` = Y_jk.
    pub per: &'a [PerUnit],
    /// |a_k|∞ of each unit: a magnitude's change times it is a force.
    pub sizes: &'a [f64],
}

impl Pressing<'_> {
    /// L_k + t·Σ_j f_j Y_jk.
    pub fn on(&self, k: usize, f: &[f64], t: f64) -> Reaction {
        let mut r = self.loads[k];
        for (p, f) in self.per.iter().zip(f) {
            let (y, s) = (&p.reactions[k], t * f);
            (r.fx, r.fy, r.moment) = (r.fx + s * y.fx, r.fy + s * y.fy, r.moment + s * y.moment);
            r.ends = r.ends.zip(y.ends).map(|([a, b], [c, d])| [a + s * c, b + s * d]);
        }
        r
    }

    /// F(f, t) and ∂F/∂f.
    fn residual(&self, f: &[f64], t: f64) -> (DVector<f64>, DMatrix<f64>) {
        let n = f.len();
        let (mut residual, mut jacobian) = (DVector::zeros(n), DMatrix::identity(n, n));
        for (k, unit) in self.units.iter().enumerate() {
            let r = self.on(k, f, t);
            residual[k] = f[k] - unit.magnitude(&r);
            for (j, p) in self.per.iter().enumerate() {
                jacobian[(k, j)] -= t * unit.slope(&r, &p.reactions[k]);
            }
        }
        (residual, jacobian)
    }

    /// The root at `t` by Newton's method from `f` (into it), on the
    /// branch where det ∂F/∂f > 0; its iterations, or None.
    fn newton(&self, f: &mut [f64], t: f64, tol: f64) -> Option<usize> {
        for iteration in 1..=NEWTON_ITERATIONS {
            let (residual, jacobian) = self.residual(f, t);
            let delta = jacobian.lu().solve(&residual)?;
            let mut change = 0.0f64;
            for ((f, d), size) in f.iter_mut().zip(delta.iter()).zip(self.sizes) {
                *f -= d;
                change = change.max(d.abs() * size / (tol + 1e-13 * f.abs() * size));
            }
            if !change.is_finite() {
                return None;
            }
            if change <= 1.0 {
                let on_branch = self.residual(f, t).1.determinant() > 0.0;
                return on_branch.then_some(iteration);
            }
        }
        None
    }
}

/// The magnitudes at t = 1 into `f`, followed from t = 0: Ok with the
/// Newton iterations spent, or Err(t*) where the branch ends.
pub(super) fn continued(
    pressing: &Pressing,
    f: &mut Vec<f64>,
    (tol, deadline, step): (f64, &Deadline, usize),
) -> Result<Result<usize, f64>, EngineError> {
    f.clear();
    f.extend(pressing.units.iter().zip(pressing.loads).map(|(u, r)| u.magnitude(r)));
    let (mut t, mut dt, mut iterations) = (0.0f64, 1.0f64, 0);
    let mut trial = f.clone();
    while t < 1.0 {
        deadline.check(|| Progress::Friction { step })?;
        let next = (t + dt).min(1.0);
        trial.clone_from(f);
        match pressing.newton(&mut trial, next, tol) {
            Some(spent) => {
                (t, dt, iterations) = (next, 2.0 * dt, iterations + spent);
                std::mem::swap(f, &mut trial);
            }
            None if dt < SMALLEST_STEP => return Ok(Err(t)),
            None => (dt, iterations) = (dt / 4.0, iterations + NEWTON_ITERATIONS),
        }
    }
    Ok(Ok(iterations))
}
