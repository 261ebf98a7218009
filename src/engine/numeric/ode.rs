//! Explicit embedded Runge–Kutta pairs with step-size control and dense
//! output, for non-stiff systems y' = f(t, y); f writes dy/dt into its
//! third argument. Two pairs: Dormand–Prince 5(4) with Hairer's 4th-order
//! continuous extension ([`Dopri5`], here) and Hairer's DOP853, 8th order
//! with a 7th-order extension ([`super::dop853`]); both share the stepper
//! [`Explicit`] and the step record [`Step`].
//!
//! The caller drives the steps and locates its own events on the dense output
//! ([`Step::at`]), restarting with [`Explicit::restart`] after a discontinuity
//! or moving the state with [`Explicit::project`] (e.g. onto constraints).
//! Every step also tests for stiffness as DOPRI5 and DOP853 do: h·ρ, ρ the
//! Lipschitz estimate ‖f(y₁) − f(Y)‖/‖y₁ − Y‖ between the step's last two
//! stages (both at t + h), beyond the method's stability interval on the
//! negative axis 15 times without 6 steps inside it in a row means the
//! steps are held by stability, not accuracy ([`Explicit::stiff`]); the
//! implicit [`super::radau`] is the method for such a system. [`Stepper`]
//! is what a driver needs from either.
//! Reference: Hairer, Nørsett, Wanner, *Solving ODEs I*, §II.5, §II.10,
//! §IV.2 (stiffness detection) and the codes DOPRI5 and DOP853.

/// One accepted step from `t0` to `t1` with its interpolation data.
#[derive(Clone, Debug, Default)]
pub struct Step {
    pub t0: f64,
    pub t1: f64,
    pub y0: Vec<f64>,
    pub y1: Vec<f64>,
    /// dy/dt at t0 and t1.
    pub f0: Vec<f64>,
    pub f1: Vec<f64>,
    /// The continuous extension's coefficients r₁…r_p: y(t0 + θh) =
    /// y0 + θ(r₁ + (1−θ)(r₂ + θ(r₃ + (1−θ)(r₄ + …)))).
    pub(super) rcont: Vec<Vec<f64>>,
    /// The step's size h as taken (t1 − t0 until [`Step::end_at`] cuts it).
    pub(super) h: f64,
}

impl Step {
    /// How many vectors of coefficients its continuous extension has.
    pub fn stages(&self) -> usize {
        self.rcont.len()
    }

    /// Ends the step at t ∈ [t0, t1] (where the model's equations change:
    /// an event of [`crate::engine::dynamics`]), its dense output kept: y1
    /// is the dense output there, f1 unknown (NaN).
    pub fn end_at(&mut self, t: f64) {
        self.y1 = self.at(t);
        self.f1.fill(f64::NAN);
        self.t1 = t;
    }

    /// Dense-output state at t ∈ [t0, t1].
    pub fn at(&self, t: f64) -> Vec<f64> {
        (0..self.y0.len()).map(|i| self.component(t, i)).collect()
    }

    /// One component of the dense output at t.
    pub fn component(&self, t: f64, i: usize) -> f64 {
        let th = if self.h == 0.0 { 0.0 } else { (t - self.t0) / self.h };
        let mut v = 0.0;
        for (k, r) in self.rcont.iter().enumerate().rev() {
            v = (v + r[i]) * if k % 2 == 0 { th } else { 1.0 - th };
        }
        self.y0[i] + v
    }
}

/// Integration failed: the step size fell below round-off or the step budget ran out.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum OdeError {
    #[error("step size underflow at t = {t}")]
    StepTooSmall { t: f64 },
    #[error("more than {steps} steps")]
    TooManySteps { steps: usize },
    #[error("the derivative is not finite at t = {t}")]
    NotFinite { t: f64 },
}

const C: [f64; 7] = [0.0, 0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0];
const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [0.2, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0, 0.0, 0.0],
    [9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0, 0.0],
    [35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0],
];
/// Error coefficients b − b̂.
const E: [f64; 7] =
    [71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0];
/// Dense-output coefficients (Hairer's CONTD5).
const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

/// What a driver needs from a stepper, explicit or implicit.
pub trait Stepper: Sized {
    /// A stepper at (t, y) with a relative and per-component absolute tolerance.
    fn start(f: &mut impl Rhs, t: f64, y: Vec<f64>, rtol: f64, atol: Vec<f64>) -> Self;
    /// Takes one accepted step (retrying with smaller steps as needed).
    fn step(&mut self, f: &mut impl Rhs, max_steps: usize) -> Result<Step, OdeError>;
    /// Replaces the state at the current time (a projection), keeping the step size.
    fn project(&mut self, f: &mut impl Rhs, y: &[f64]);
    /// Hands back a step the caller is done with: the next step may reuse
    /// its vectors (a stepper that does not simply drops it).
    fn recycle(&mut self, _step: Step) {}
    /// Time reached.
    fn time(&self) -> f64;
    /// Accepted steps, rejected steps and evaluations of f.
    fn counts(&self) -> [usize; 3];
    /// Σ over the accepted steps of each component's local error estimate.
    fn local_errors(&self) -> &[f64];
    /// The steps are held by stability, not accuracy (only an explicit method says so).
    fn stiff(&self) -> bool {
        false
    }
}

/// An embedded explicit Runge–Kutta pair whose last stage is f(t + h, y₁)
/// (first same as last).
pub trait Pair {
    /// Stages of a step, the last one at (t + h, y₁), the one before also at t + h.
    const STAGES: usize;
    /// Where the stability region meets the negative real axis (h·ρ beyond
    /// it, the step is held by stability: Hairer's 3.25 and 6.1).
    const STABILITY: f64;
    /// Stages including those the dense output adds.
    const EXTENDED: usize;
    /// 1/(q + 1), q the order of the error estimate: the step-size exponent.
    const EXPONENT: f64;
    fn c(s: usize) -> f64;
    /// Row s of the Runge–Kutta matrix (its first s entries are used).
    fn a(s: usize) -> &'static [f64];
    /// The error norm of a step of size h from the stages k, components
    /// scaled by `scale`; and each component's error estimate in `estimate`.
    fn error(k: &[Vec<f64>], h: f64, scale: &[f64], estimate: &mut [f64]) -> f64;
    /// The continuous extension's coefficients r₁…r_p of a step from y0 to
    /// y1 (stages k, the extended ones already evaluated), into `r`.
    fn dense(k: &[Vec<f64>], h: f64, y0: &[f64], y1: &[f64], r: &mut Vec<Vec<f64>>);
}

/// Stepper state: current time, state, derivative (FSAL) and next step size.
pub struct Explicit<P: Pair> {
    pub rtol: f64,
    /// Absolute tolerance per component.
    pub atol: Vec<f64>,
    pub h_max: f64,
    t: f64,
    y: Vec<f64>,
    f: Vec<f64>,
    h: f64,
    /// Stage derivatives (extended ones included), a stage state, the error
    /// scale and estimate, reused from step to step.
    k: Vec<Vec<f64>>,
    ys: Vec<f64>,
    stage: Vec<f64>,
    scale: Vec<f64>,
    estimate: Vec<f64>,
    /// Accepted and rejected steps, and evaluations of f.
    pub accepted: usize,
    pub rejected: usize,
    pub evaluations: usize,
    /// Σ over the accepted steps of each component's embedded error
    /// estimate: a first-order estimate of the global error (it ignores how
    /// errors grow or decay along the solution).
    pub local_errors: Vec<f64>,
    /// The state of the stage before the last (at t + h), and the count of
    /// steps beyond the stability interval and of those within it in a row.
    stiff_state: Vec<f64>,
    beyond: usize,
    within: usize,
    /// 15 steps held by stability without 6 free ones in a row: a stiff system.
    pub stiff: bool,
    /// A step handed back ([`Stepper::recycle`]): the next one's storage.
    spare: Option<Step>,
    pair: std::marker::PhantomData<P>,
}

/// The right-hand side: f(t, y, dy/dt).
pub trait Rhs: FnMut(f64, &[f64], &mut [f64]) {}
impl<F: FnMut(f64, &[f64], &mut [f64])> Rhs for F {}

impl<P: Pair> Explicit<P> {
    /// A stepper at (t, y) with tolerances and the largest step allowed.
    pub fn new(f: &mut impl Rhs, t: f64, y: Vec<f64>, rtol: f64, atol: Vec<f64>, h_max: f64) -> Self {
        let n = y.len();
        let mut s = Self {
            rtol,
            atol,
            h_max,
            t,
            y: vec![0.0; n],
            f: vec![0.0; n],
            h: 0.0,
            k: vec![vec![0.0; n]; P::EXTENDED],
            ys: vec![0.0; n],
            stage: vec![0.0; n],
            scale: vec![0.0; n],
            estimate: vec![0.0; n],
            accepted: 0,
            rejected: 0,
            evaluations: 0,
            local_errors: vec![0.0; n],
            stiff_state: vec![0.0; n],
            beyond: 0,
            within: 0,
            stiff: false,
            spare: None,
            pair: std::marker::PhantomData,
        };
        s.restart(f, t, y);
        s
    }

    /// Time and state reached.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Restarts at (t, y), e.g. after a discontinuity of f, with a fresh first step.
    pub fn restart(&mut self, f: &mut impl Rhs, t: f64, y: Vec<f64>) {
        self.t = t;
        self.y = y;
        f(t, &self.y, &mut self.f);
        self.evaluations += 1;
        let sc = |i: usize| self.atol[i] + self.rtol * self.y[i].abs();
        let d0 = rms(self.y.iter().enumerate().map(|(i, v)| v / sc(i)));
        let d1 = rms(self.f.iter().enumerate().map(|(i, v)| v / sc(i)));
        let h0 = if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 };
        self.h = h0.min(self.h_max);
    }

    /// Replaces the state at the current time (a projection), keeping the step size.
    pub fn project(&mut self, f: &mut impl Rhs, y: &[f64]) {
        self.y.copy_from_slice(y);
        f(self.t, &self.y, &mut self.f);
        self.evaluations += 1;
    }

    /// Takes one accepted step (retrying with smaller steps as needed).
    pub fn step(&mut self, f: &mut impl Rhs, max_steps: usize) -> Result<Step, OdeError> {
        loop {
            let h = self.h;
            can_step(self.accepted + self.rejected, max_steps, self.t, h)?;
            self.stages(f, h, 1..P::STAGES);
            let finite = self.ys.iter().chain(self.k[P::STAGES - 1].iter()).all(|v| v.is_finite());
            if !finite {
                self.rejected += 1;
                self.h *= 0.25;
                if self.rejected > max_steps / 2 {
                    return Err(OdeError::NotFinite { t: self.t });
                }
                continue;
            }
            for i in 0..self.y.len() {
                self.scale[i] = self.atol[i] + self.rtol * self.y[i].abs().max(self.ys[i].abs());
            }
            let err = P::error(&self.k, h, &self.scale, &mut self.estimate);
            let factor = (0.9 * err.powf(-P::EXPONENT)).clamp(0.2, 10.0);
            if err <= 1.0 {
                self.local_errors.iter_mut().zip(&self.estimate).for_each(|(s, e)| *s += e.abs());
                self.test_stiffness(h);
                let step = self.accept(f, h);
                self.h = (h * factor).min(self.h_max);
                return Ok(step);
            }
            self.rejected += 1;
            self.h = h * factor.min(1.0);
        }
    }

    /// The stages in `range` (k₁ = f(t, y) is kept from the last step); a
    /// step's leave y₁ in `ys` and f(t + h, y₁) in the last stage.
    fn stages(&mut self, f: &mut impl Rhs, h: f64, range: std::ops::Range<usize>) {
        self.k[0].copy_from_slice(&self.f);
        for s in range.clone() {
            let a = P::a(s);
            for (i, v) in self.stage.iter_mut().enumerate() {
                *v = self.y[i] + h * (0..s).map(|j| a[j] * self.k[j][i]).sum::<f64>();
            }
            let (_, rest) = self.k.split_at_mut(s);
            f(self.t + P::c(s) * h, &self.stage, &mut rest[0]);
            if s == P::STAGES - 2 {
                self.stiff_state.copy_from_slice(&self.stage);
            }
        }
        if range.end == P::STAGES {
            self.ys.copy_from_slice(&self.stage);
        }
        self.evaluations += range.len();
    }

    /// h·ρ of an accepted step against the stability interval (the norms
    /// weighted by the absolute tolerances, components without a finite positive one left out).
    fn test_stiffness(&mut self, h: f64) {
        let last = P::STAGES - 1;
        let (mut num, mut den) = (0.0, 0.0);
        for i in (0..self.y.len()).filter(|&i| self.atol[i] > 0.0 && self.atol[i].is_finite()) {
            num += ((self.k[last][i] - self.k[last - 1][i]) / self.atol[i]).powi(2);
            den += ((self.ys[i] - self.stiff_state[i]) / self.atol[i]).powi(2);
        }
        if den > 0.0 && h.abs() * (num / den).sqrt() > P::STABILITY {
            (self.beyond, self.within) = (self.beyond + 1, 0);
            self.stiff |= self.beyond >= 15;
        } else {
            self.within += 1;
            if self.within >= 6 {
                self.beyond = 0;
            }
        }
    }

    fn accept(&mut self, f: &mut impl Rhs, h: f64) -> Step {
        let last = P::STAGES - 1;
        self.stages(f, h, P::STAGES..P::EXTENDED);
        let mut step = self.spare.take().unwrap_or_default();
        P::dense(&self.k, h, &self.y, &self.ys, &mut step.rcont);
        let copy = |to: &mut Vec<f64>, from: &[f64]| {
            to.clear();
            to.extend_from_slice(from);
        };
        copy(&mut step.y0, &self.y);
        copy(&mut step.y1, &self.ys);
        copy(&mut step.f0, &self.k[0]);
        copy(&mut step.f1, &self.k[last]);
        (step.t0, step.t1, step.h) = (self.t, self.t + h, h);
        self.t += h;
        self.y.copy_from_slice(&step.y1);
        self.f.copy_from_slice(&step.f1);
        self.accepted += 1;
        step
    }
}

impl<P: Pair> Stepper for Explicit<P> {
    fn start(f: &mut impl Rhs, t: f64, y: Vec<f64>, rtol: f64, atol: Vec<f64>) -> Self {
        Self::new(f, t, y, rtol, atol, f64::INFINITY)
    }
    fn step(&mut self, f: &mut impl Rhs, max_steps: usize) -> Result<Step, OdeError> {
        Explicit::step(self, f, max_steps)
    }
    fn project(&mut self, f: &mut impl Rhs, y: &[f64]) {
        Explicit::project(self, f, y)
    }
    fn recycle(&mut self, step: Step) {
        self.spare = Some(step);
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
    fn stiff(&self) -> bool {
        self.stiff
    }
}

/// Dormand–Prince 5(4), Hairer's DOPRI5.
pub struct Dp5;
pub type Dopri5 = Explicit<Dp5>;

impl Pair for Dp5 {
    const STAGES: usize = 7;
    const STABILITY: f64 = 3.25;
    const EXTENDED: usize = 7;
    const EXPONENT: f64 = 0.2;
    fn c(s: usize) -> f64 {
        C[s]
    }
    fn a(s: usize) -> &'static [f64] {
        &A[s]
    }
    fn error(k: &[Vec<f64>], h: f64, scale: &[f64], estimate: &mut [f64]) -> f64 {
        for (i, e) in estimate.iter_mut().enumerate() {
            *e = h * (0..7).map(|j| E[j] * k[j][i]).sum::<f64>();
        }
        rms(estimate.iter().zip(scale).map(|(e, s)| e / s))
    }
    fn dense(k: &[Vec<f64>], h: f64, y0: &[f64], y1: &[f64], r: &mut Vec<Vec<f64>>) {
        let n = y0.len();
        sized(r, 4, n);
        for i in 0..n {
            let ydiff = y1[i] - y0[i];
            let bspl = h * k[0][i] - ydiff;
            r[0][i] = ydiff;
            r[1][i] = bspl;
            r[2][i] = ydiff - h * k[6][i] - bspl;
            r[3][i] = h * (0..7).map(|j| D[j] * k[j][i]).sum::<f64>();
        }
    }
}

/// `r` as `count` vectors of n zeros, over the storage it had.
pub(super) fn sized(r: &mut Vec<Vec<f64>>, count: usize, n: usize) {
    r.resize_with(count, Vec::new);
    r.iter_mut().for_each(|v| {
        v.clear();
        v.resize(n, 0.0);
    });
}

/// Another attempt at (t, h) is allowed: fewer than `max_steps` attempts
/// so far and h finite and above the rounding of t (a step size from a
/// non-finite f at the start is NaN, which no comparison stops).
pub(super) fn can_step(attempts: usize, max_steps: usize, t: f64, h: f64) -> Result<(), OdeError> {
    if !h.is_finite() {
        return Err(OdeError::NotFinite { t });
    }
    if attempts >= max_steps {
        return Err(OdeError::TooManySteps { steps: max_steps });
    }
    if h.abs() <= 8.0 * f64::EPSILON * t.abs().max(1e-300) {
        return Err(OdeError::StepTooSmall { t });
    }
    Ok(())
}

fn rms(v: impl ExactSizeIterator<Item = f64>) -> f64 {
    let n = v.len().max(1);
    (v.map(|x| x * x).sum::<f64>() / n as f64).sqrt()
}

/// x'' = −ω²x, x(0) = 1 over [0, t_end] with the pair P at `rtol`: the
/// largest |x − cos ωt| (closed form) at the step ends and on the dense
/// output between them, and the stepper's counts.
#[cfg(test)]
pub(super) fn oscillator<P: Pair>(omega: f64, t_end: f64, rtol: f64) -> (f64, Explicit<P>) {
    let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| {
        dy[0] = y[1];
        dy[1] = -omega * omega * y[0];
    };
    let mut s = Explicit::<P>::new(&mut f, 0.0, vec![1.0, 0.0], rtol, vec![0.01 * rtol; 2], f64::INFINITY);
    let mut worst: f64 = 0.0;
    while s.t() < t_end {
        let step = s.step(&mut f, 100_000).expect("step");
        for th in [0.0, 0.25, 0.5, 0.75, 1.0] {
            let t = step.t0 + th * (step.t1 - step.t0);
            worst = worst.max((step.at(t)[0] - (omega * t).cos()).abs());
            assert_eq!(step.at(t)[1], step.component(t, 1));
        }
    }
    (worst, s)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f not finite at the start makes the first step size NaN: the first
    /// attempt says so (it used to be retried at h·¼ = NaN until half the
    /// attempts allowed were spent).
    #[test]
    fn a_derivative_not_finite_at_the_start_is_an_error_at_once() {
        let mut f = |_t: f64, _y: &[f64], dy: &mut [f64]| dy[0] = f64::NAN;
        let mut s = Dopri5::new(&mut f, 0.0, vec![1.0], 1e-6, vec![1e-8], f64::INFINITY);
        assert_eq!(s.step(&mut f, 100_000).unwrap_err(), OdeError::NotFinite { t: 0.0 });
        assert_eq!(s.rejected, 0);
    }

    /// x'' = −4x over 6.6 s at rtol 1e-11: cos 2t to 1e-9 (steps and dense output).
    #[test]
    fn harmonic_oscillator_matches_the_closed_form() {
        let (worst, s) = oscillator::<Dp5>(2.0, 6.6, 1e-11);
        assert!(worst < 1e-9, "largest error {worst}");
        assert!(s.accepted > 10 && s.accepted < 2000, "{} steps", s.accepted);
    }

    /// A step handed back lends its storage to the next: the steps and
    /// their dense output are bit for bit those of steps made afresh.
    #[test]
    fn a_recycled_step_is_a_fresh_one() {
        let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| {
            dy[0] = y[1];
            dy[1] = -9.0 * y[0].sin();
        };
        let mut start = || Dopri5::new(&mut f, 0.0, vec![1.0, 0.0], 1e-6, vec![1e-8; 2], 1.0);
        let (mut fresh, mut lent) = (start(), start());
        for _ in 0..50 {
            let (a, b) = (fresh.step(&mut f, 1000).expect("step"), lent.step(&mut f, 1000).expect("step"));
            let mid = 0.5 * (a.t0 + a.t1);
            assert_eq!((a.t1, &a.y1, &a.f0, a.at(mid)), (b.t1, &b.y1, &b.f0, b.at(mid)));
            Stepper::recycle(&mut lent, b);
        }
        assert!(lent.spare.is_some());
    }
}
