//! Radau IIA of order 5 for stiff systems y' = f(t, y): the three-stage
//! implicit Runge–Kutta collocation method of Hairer & Wanner's RADAU5
//! (*Solving ODEs II*, §IV.8), its step and step-size control as in SciPy's
//! `Radau`. L-stable and stiffly accurate: a mode far faster than the
//! motion is damped in a step, not followed, so a stiff spring costs steps
//! sized by the slow motion instead of by its period.
//!
//! Symbols: h the step; c₁, c₂, c₃ = 1 the collocation nodes; zᵢ = Yᵢ − y
//! the stage increments at t + cᵢh (Z the three); J ≈ ∂f/∂y by forward
//! differences, computed again only when Newton converges slowly; T, T⁻¹
//! the transformation that turns the method's A⁻¹ into γ and the pair
//! α ± iβ, so that the simplified Newton iteration on W = T⁻¹Z solves one
//! real system (γ/h − J) and one complex ((α − iβ)/h − J) of the size of y
//! instead of one three times as large. Where one J for the three stages
//! does not contract (a stiff direction that turns within the step), the
//! stages' own Jacobians act through products, each one evaluation, in
//! GMRES preconditioned by those two systems (`krylov`). The error estimate is the
//! embedded one filtered through (γ/h − J)⁻¹ (so it stays bounded on a
//! stiff mode); the dense output is the collocation polynomial through
//! y and the three stages.

use super::ode::{OdeError, Rhs, Step, Stepper, can_step};
use nalgebra::{Complex, DMatrix, DVector, Dyn, linalg::LU};
use newton::{newton_tolerance, rms3};

/// Collocation nodes c₁, c₂, c₃ = (4 ∓ √6)/10, 1.
const C: [f64; 3] = [0.155_051_025_721_682_2, 0.644_948_974_278_317_8, 1.0];
/// The embedded estimate's weights (−13 ∓ 7√6)/3, −1/3, on Z/h.
const E: [f64; 3] = [-10.048_809_399_827_414, 1.382_142_733_160_748, -1.0 / 3.0];
/// γ, the real eigenvalue of A⁻¹, and α − iβ of its pair (SciPy's MU_REAL, MU_COMPLEX).
const GAMMA: f64 = 3.637_834_252_744_496;
const ALPHA: f64 = 2.681_082_873_627_752_3;
const BETA: f64 = 3.050_430_199_247_411;
/// T and T⁻¹ (SciPy's `radau.T`, `radau.TI`; the test checks T⁻¹A⁻¹T).
const T: [[f64; 3]; 3] = [
    [0.094_438_762_488_975_24, -0.141_255_295_020_954_2, 0.030_029_194_105_147_42],
    [0.250_213_122_965_333_3, 0.204_129_352_293_799_94, -0.382_942_112_757_261_9],
    [1.0, 1.0, 0.0],
];
const TI: [[f64; 3]; 3] = [
    [4.178_718_591_551_904, 0.327_682_820_761_062_37, 0.523_376_445_499_449_5],
    [-4.178_718_591_551_904, -0.327_682_820_761_062_37, 0.476_623_554_500_550_44],
    [0.502_872_634_945_786_8, -2.571_926_949_855_605, 0.596_039_204_828_224_9],
];
const NEWTON_MAXITER: usize = 6;
const FULL_NEWTON_MAXITER: usize = 8;
/// J is computed again after a step whose simplified iteration contracted
/// slower than this (RADAU5's THET, at the 0.1 its notes advise where a
/// Jacobian is costly: here n evaluations against three an iteration), or
/// whose Krylov iteration needed more than this many products an iteration
/// (J has turned away from the stages').
const JACOBIAN_RATE: f64 = 0.1;
const KRYLOV_JACOBIAN: usize = 3;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 10.0;
/// Consecutive attempts with a non-finite f before giving up.
const NOT_FINITE: usize = 40;

type Stages = [Vec<f64>; 3];
type Factors = (LU<f64, Dyn, Dyn>, LU<Complex<f64>, Dyn, Dyn>);

/// The stepper's state: time, state, f there, step size, Jacobian and its factorizations.
pub struct Radau5 {
    rtol: f64,
    atol: Vec<f64>,
    t: f64,
    y: Vec<f64>,
    f: Vec<f64>,
    h: f64,
    /// The last accepted step's size and error norm (the predictive controller's memory).
    last: Option<(f64, f64)>,
    jac: DMatrix<f64>,
    /// J was computed at the current state.
    jac_current: bool,
    /// The full Newton iteration's last Jacobian (at y₁), for the next step.
    pending_jac: Option<DMatrix<f64>>,
    /// LU of γ/h − J and of (α − iβ)/h − J for the current h.
    lu: Option<Factors>,
    /// The last step's collocation polynomial, extrapolated for Newton's start.
    previous: Option<Step>,
    newton_tol: f64,
    /// GMRES's products and Newton's iterations of the step just solved by the Krylov iteration.
    krylov: Option<(usize, usize)>,
    /// The last step needed the Krylov iteration with this J: the simplified one is not tried.
    simplified_fails: bool,
    /// RADAU5's FACCON: θ/(1 − θ) of Newton's last contraction rate θ,
    /// carried from step to step, so that an iteration can converge at its
    /// first increment when the last ones contracted fast (the increment
    /// of a stiff f can be at its rounding, where no rate can be measured).
    contraction: f64,
    pub accepted: usize,
    pub rejected: usize,
    pub evaluations: usize,
    /// Evaluations of J.
    pub jacobians: usize,
    pub local_errors: Vec<f64>,
}

enum Newton {
    Converged { z: Stages, iterations: usize, rate: f64 },
    Failed,
    NotFinite,
}

impl Stepper for Radau5 {
    fn start(f: &mut impl Rhs, t: f64, y: Vec<f64>, rtol: f64, atol: Vec<f64>) -> Self {
        let n = y.len();
        let mut s = Self {
            rtol,
            atol,
            t,
            y,
            f: vec![0.0; n],
            h: 0.0,
            last: None,
            jac: DMatrix::zeros(n, n),
            jac_current: false,
            pending_jac: None,
            lu: None,
            previous: None,
            newton_tol: newton_tolerance(rtol),
            krylov: None,
            simplified_fails: false,
            contraction: 1.0,
            accepted: 0,
            rejected: 0,
            evaluations: 0,
            jacobians: 0,
            local_errors: vec![0.0; n],
        };
        f(t, &s.y, &mut s.f);
        s.evaluations += 1;
        s.h = s.first_step();
        s.jacobian(f);
        s
    }

    fn step(&mut self, f: &mut impl Rhs, max_steps: usize) -> Result<Step, OdeError> {
        let mut not_finite = 0;
        let mut rejected_here = false;
        loop {
            let h = self.h;
            can_step(self.accepted + self.rejected, max_steps, self.t, h)?;
            if self.lu.is_none() {
                self.lu = self.factor(h);
            }
            let Some(outcome) = self.solve(f, h)? else { continue };
            let (z, iterations, rate) = match outcome {
                Newton::Converged { z, iterations, rate } => (z, iterations, rate),
                failed => {
                    not_finite = if matches!(failed, Newton::NotFinite) { not_finite + 1 } else { 0 };
                    if not_finite >= NOT_FINITE || (not_finite > 0 && !self.finite_here(f)) {
                        return Err(OdeError::NotFinite { t: self.t });
                    }
                    self.reject(0.5);
                    continue;
                }
            };
            let y1: Vec<f64> = self.y.iter().zip(&z[2]).map(|(y, z)| y + z).collect();
            let scale: Vec<f64> =
                (0..y1.len()).map(|i| self.atol[i] + self.rtol * self.y[i].abs().max(y1[i].abs())).collect();
            let (estimate, err) = self.error(f, h, &z, &scale, rejected_here);
            let safety = 0.9 * (2 * NEWTON_MAXITER + 1) as f64 / (2 * NEWTON_MAXITER + iterations) as f64;
            if !err.is_finite() || err > 1.0 {
                let factor = if err.is_finite() { self.predict(h, err) } else { MIN_FACTOR };
                self.reject((safety * factor).max(MIN_FACTOR));
                rejected_here = true;
                continue;
            }
            self.local_errors.iter_mut().zip(&estimate).for_each(|(s, e)| *s += e.abs());
            self.simplified_fails = self.krylov.is_some();
            let recompute = match self.krylov {
                Some((products, iterations)) => products > KRYLOV_JACOBIAN * iterations,
                None => iterations > 2 && rate > JACOBIAN_RATE,
            };
            let factor = (safety * self.predict(h, err)).min(MAX_FACTOR);
            let factor = if !recompute && factor < 1.2 { 1.0 } else { factor };
            return Ok(self.accept(f, h, z, y1, err, factor, recompute));
        }
    }

    fn project(&mut self, f: &mut impl Rhs, y: &[f64]) {
        self.y.copy_from_slice(y);
        f(self.t, &self.y, &mut self.f);
        self.evaluations += 1;
    }

    fn time(&self) -> f64 {
        self.t
    }

    fn counts(&self) -> [usize; 3] {
        [self.accepted, self.rejected, self.evaluations]
    }

    fn local_errors(&self) -> &[f64] {
        &self.local_errors
    }
}

impl Radau5 {
    /// Newton's iteration for the step h: the simplified one (unless it
    /// failed with this J at the last step), else the Krylov one; where
    /// that fails too, J computed again if it was not current (None: the
    /// step starts over), else the full iteration with formed Jacobians.
    fn solve(&mut self, f: &mut impl Rhs, h: f64) -> Result<Option<Newton>, OdeError> {
        self.krylov = None;
        let simplified = self.lu.is_some() && !self.simplified_fails;
        let outcome = if simplified { self.newton(f, h) } else { Newton::Failed };
        let outcome = match outcome {
            Newton::Failed if self.lu.is_some() => self.krylov_newton(f, h),
            other => other,
        };
        Ok(Some(match outcome {
            Newton::Failed if !self.jac_current => {
                self.jacobian(f);
                // A Jacobian not finite at an accepted state stays so at any step size
                // (f answers NaN past a job's budget): no factorisation can help.
                if !self.jac.iter().all(|v| v.is_finite()) {
                    return Err(OdeError::NotFinite { t: self.t });
                }
                self.lu = None;
                return Ok(None);
            }
            Newton::Failed if self.lu.is_some() => self.full_newton(f, h),
            other => other,
        }))
    }

    /// Whether f is finite at the accepted state: where it is not (past a
    /// job's budget f answers NaN), no smaller step can help.
    fn finite_here(&mut self, f: &mut impl Rhs) -> bool {
        let mut here = vec![0.0; self.y.len()];
        f(self.t, &self.y, &mut here);
        self.evaluations += 1;
        here.iter().all(|v| v.is_finite())
    }

    /// 1 % of the state's scale over f's (as the explicit stepper starts).
    fn first_step(&self) -> f64 {
        let sc = |i: usize| self.atol[i] + self.rtol * self.y[i].abs();
        let rms = |v: &[f64]| {
            let terms = v.iter().enumerate().filter(|(i, _)| sc(*i).is_finite());
            (terms.map(|(i, x)| (x / sc(i)).powi(2)).sum::<f64>() / v.len().max(1) as f64).sqrt()
        };
        let (d0, d1) = (rms(&self.y), rms(&self.f));
        if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 }
    }

    /// The embedded estimate (γ/h − J)⁻¹(f(y) + Σ eᵢzᵢ/h) and its RMS norm
    /// scaled; after a rejection in this step, once more through f (as RADAU5).
    fn error(&mut self, f: &mut impl Rhs, h: f64, z: &Stages, scale: &[f64], again: bool) -> (Vec<f64>, f64) {
        let n = self.y.len();
        let ze: Vec<f64> = (0..n).map(|i| (0..3).map(|s| E[s] * z[s][i]).sum::<f64>() / h).collect();
        let lu = self.lu.take().expect("factored");
        let solve = |rhs: &[f64]| {
            let mut v = DVector::from_fn(n, |i, _| rhs[i] + ze[i]);
            lu.0.solve_mut(&mut v);
            v.as_slice().to_vec()
        };
        let norm = |e: &[f64]| rms3(&[e.to_vec()], scale);
        let mut estimate = solve(&self.f);
        let mut err = norm(&estimate);
        if again && err > 1.0 {
            let shifted: Vec<f64> = self.y.iter().zip(&estimate).map(|(y, e)| y + e).collect();
            let mut fe = vec![0.0; n];
            f(self.t, &shifted, &mut fe);
            self.evaluations += 1;
            estimate = solve(&fe);
            err = norm(&estimate);
        }
        self.lu = Some(lu);
        (estimate, err)
    }

    /// Gustafsson's predictive step-size factor (before the safety factor).
    fn predict(&self, h: f64, err: f64) -> f64 {
        if err == 0.0 {
            return MAX_FACTOR;
        }
        let multiplier = match self.last {
            Some((h_old, err_old)) => h / h_old * (err_old / err).powf(0.25),
            None => 1.0,
        };
        multiplier.min(1.0) * err.powf(-0.25)
    }

    fn reject(&mut self, factor: f64) {
        self.h *= factor;
        self.lu = None;
        self.rejected += 1;
    }

    #[allow(clippy::too_many_arguments)]
    fn accept(
        &mut self,
        f: &mut impl Rhs,
        h: f64,
        z: Stages,
        y1: Vec<f64>,
        err: f64,
        factor: f64,
        recompute: bool,
    ) -> Step {
        let mut f1 = vec![0.0; y1.len()];
        f(self.t + h, &y1, &mut f1);
        self.evaluations += 1;
        let step = Step {
            t0: self.t,
            t1: self.t + h,
            rcont: collocation(&z),
            y0: std::mem::replace(&mut self.y, y1.clone()),
            y1,
            f0: std::mem::replace(&mut self.f, f1.clone()),
            f1,
            h,
        };
        self.t += h;
        self.accepted += 1;
        self.last = Some((h, err));
        self.h = h * factor;
        if factor != 1.0 {
            self.lu = None;
        }
        self.jac_current = false;
        if let Some(jac) = self.pending_jac.take() {
            (self.jac, self.jac_current, self.lu) = (jac, true, None);
        } else if recompute {
            self.jacobian(f);
            self.lu = None;
        }
        self.previous = Some(step.clone());
        step
    }
}

/// The collocation polynomial through (0, 0), (c₁, z₁), (c₂, z₂), (1, z₃)
/// in the dense output's form θ(r₁ + (1−θ)(r₂ + θr₃)): r₁ = z₃, and
/// r₂ + cr₃ = (z(c)/c − r₁)/(1 − c) at c₁ and c₂.
fn collocation(z: &Stages) -> Vec<Vec<f64>> {
    let n = z[0].len();
    let d = |s: usize, i: usize| (z[s][i] / C[s] - z[2][i]) / (1.0 - C[s]);
    let r3: Vec<f64> = (0..n).map(|i| (d(0, i) - d(1, i)) / (C[0] - C[1])).collect();
    let r2: Vec<f64> = (0..n).map(|i| d(0, i) - C[0] * r3[i]).collect();
    vec![z[2].clone(), r2, r3]
}

mod krylov;
mod newton;
#[cfg(test)]
mod tests;
