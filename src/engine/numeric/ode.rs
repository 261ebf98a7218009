//! Dormand–Prince 5(4) explicit Runge–Kutta with step-size control and
//! Hairer's 4th-order continuous extension (dense output), for small
//! non-stiff systems y' = f(t, y) of fixed size N.
//!
//! The caller drives the steps and locates its own events on the dense output
//! ([`Step::at`]), restarting with [`Dopri5::restart`] after a discontinuity.
//! Reference: Hairer, Nørsett, Wanner, *Solving ODEs I*, §II.5 and DOPRI5.

/// One accepted step from `t0` to `t1` with its interpolation data.
#[derive(Clone, Debug)]
pub struct Step<const N: usize> {
    pub t0: f64,
    pub t1: f64,
    pub y0: [f64; N],
    pub y1: [f64; N],
    /// dy/dt at t0 and t1.
    pub f0: [f64; N],
    pub f1: [f64; N],
    rcont: [[f64; N]; 4],
}

impl<const N: usize> Step<N> {
    /// Dense-output state at t ∈ [t0, t1].
    pub fn at(&self, t: f64) -> [f64; N] {
        let h = self.t1 - self.t0;
        let th = if h == 0.0 { 0.0 } else { (t - self.t0) / h };
        let th1 = 1.0 - th;
        let [r2, r3, r4, r5] = &self.rcont;
        std::array::from_fn(|i| self.y0[i] + th * (r2[i] + th1 * (r3[i] + th * (r4[i] + th1 * r5[i]))))
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

/// Stepper state: current time, state, derivative (FSAL) and next step size.
pub struct Dopri5<const N: usize> {
    pub rtol: f64,
    pub atol: f64,
    pub h_max: f64,
    t: f64,
    y: [f64; N],
    f: [f64; N],
    h: f64,
    /// Accepted and rejected steps, and evaluations of f.
    pub accepted: usize,
    pub rejected: usize,
    pub evaluations: usize,
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

impl<const N: usize> Dopri5<N> {
    /// A stepper at (t, y) with tolerances and the largest step allowed.
    pub fn new(
        f: &mut impl FnMut(f64, &[f64; N]) -> [f64; N],
        t: f64,
        y: [f64; N],
        rtol: f64,
        atol: f64,
        h_max: f64,
    ) -> Self {
        let mut s = Self { rtol, atol, h_max, t, y, f: [0.0; N], h: 0.0, accepted: 0, rejected: 0, evaluations: 0 };
        s.restart(f, t, y);
        s
    }

    /// Restarts at (t, y), e.g. after a discontinuity of f, with a fresh first step.
    pub fn restart(&mut self, f: &mut impl FnMut(f64, &[f64; N]) -> [f64; N], t: f64, y: [f64; N]) {
        self.t = t;
        self.y = y;
        self.f = f(t, &y);
        self.evaluations += 1;
        let sc: [f64; N] = std::array::from_fn(|i| self.atol + self.rtol * y[i].abs());
        let d0 = rms::<N>(&std::array::from_fn(|i| y[i] / sc[i]));
        let d1 = rms::<N>(&std::array::from_fn(|i| self.f[i] / sc[i]));
        let h0 = if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 };
        self.h = h0.min(self.h_max);
    }

    /// Takes one accepted step (retrying with smaller steps as needed).
    pub fn step(
        &mut self,
        f: &mut impl FnMut(f64, &[f64; N]) -> [f64; N],
        max_steps: usize,
    ) -> Result<Step<N>, OdeError> {
        loop {
            if self.accepted + self.rejected >= max_steps {
                return Err(OdeError::TooManySteps { steps: max_steps });
            }
            let h = self.h;
            if h.abs() <= 8.0 * f64::EPSILON * self.t.abs().max(1e-300) {
                return Err(OdeError::StepTooSmall { t: self.t });
            }
            let k = self.stages(f, h);
            let y1: [f64; N] = std::array::from_fn(|i| self.y[i] + h * (0..6).map(|j| A[6][j] * k[j][i]).sum::<f64>());
            let f1 = f(self.t + h, &y1);
            self.evaluations += 1;
            if !f1.iter().chain(y1.iter()).all(|v| v.is_finite()) {
                self.rejected += 1;
                self.h *= 0.25;
                if self.rejected > max_steps / 2 {
                    return Err(OdeError::NotFinite { t: self.t });
                }
                continue;
            }
            let err = self.error_norm(&k, &f1, &y1, h);
            let factor = (0.9 * err.powf(-0.2)).clamp(0.2, 10.0);
            if err <= 1.0 {
                let step = self.accept(&k, y1, f1, h);
                self.h = (h * factor).min(self.h_max);
                return Ok(step);
            }
            self.rejected += 1;
            self.h = h * factor.min(1.0);
        }
    }

    fn stages(&mut self, f: &mut impl FnMut(f64, &[f64; N]) -> [f64; N], h: f64) -> [[f64; N]; 6] {
        let mut k = [[0.0; N]; 6];
        k[0] = self.f;
        for s in 1..6 {
            let ys: [f64; N] = std::array::from_fn(|i| self.y[i] + h * (0..s).map(|j| A[s][j] * k[j][i]).sum::<f64>());
            k[s] = f(self.t + C[s] * h, &ys);
        }
        self.evaluations += 5;
        k
    }

    fn error_norm(&self, k: &[[f64; N]; 6], f1: &[f64; N], y1: &[f64; N], h: f64) -> f64 {
        rms::<N>(&std::array::from_fn(|i| {
            let e = h * ((0..6).map(|j| E[j] * k[j][i]).sum::<f64>() + E[6] * f1[i]);
            e / (self.atol + self.rtol * self.y[i].abs().max(y1[i].abs()))
        }))
    }

    fn accept(&mut self, k: &[[f64; N]; 6], y1: [f64; N], f1: [f64; N], h: f64) -> Step<N> {
        let y0 = self.y;
        let ydiff: [f64; N] = std::array::from_fn(|i| y1[i] - y0[i]);
        let bspl: [f64; N] = std::array::from_fn(|i| h * k[0][i] - ydiff[i]);
        let r4: [f64; N] = std::array::from_fn(|i| ydiff[i] - h * f1[i] - bspl[i]);
        let r5: [f64; N] = std::array::from_fn(|i| h * ((0..6).map(|j| D[j] * k[j][i]).sum::<f64>() + D[6] * f1[i]));
        let step = Step { t0: self.t, t1: self.t + h, y0, y1, f0: k[0], f1, rcont: [ydiff, bspl, r4, r5] };
        self.t += h;
        self.y = y1;
        self.f = f1;
        self.accepted += 1;
        step
    }
}

fn rms<const N: usize>(v: &[f64; N]) -> f64 {
    (v.iter().map(|x| x * x).sum::<f64>() / N as f64).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// x'' = −4x, x(0) = 1: x(t) = cos 2t (closed form), checked at the step
    /// ends and on the dense output between them.
    #[test]
    fn harmonic_oscillator_matches_the_closed_form() {
        let mut f = |_t: f64, y: &[f64; 2]| [y[1], -4.0 * y[0]];
        let mut s = Dopri5::new(&mut f, 0.0, [1.0, 0.0], 1e-11, 1e-13, 0.5);
        let mut worst: f64 = 0.0;
        while let Ok(step) = s.step(&mut f, 100_000) {
            for th in [0.0, 0.3, 0.7, 1.0] {
                let t = step.t0 + th * (step.t1 - step.t0);
                worst = worst.max((step.at(t)[0] - (2.0 * t).cos()).abs());
            }
            if step.t1 > 6.6 {
                break;
            }
        }
        assert!(worst < 1e-9, "largest error {worst}");
        assert!(s.accepted > 10 && s.accepted < 2000, "{} steps", s.accepted);
    }
}
