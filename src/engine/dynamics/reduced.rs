//! The reduced 1-DOF equation of motion
//!
//! ```text
//! I*(φ) φ̈ + ½ I*'(φ) φ̇² = M*(φ, φ̇, t)
//! ```
//!
//! with state (φ, ω, W). Functions are periodic in φ (reduced to
//! [0, period)); expressions may also read `omega` and `t`. Energy check:
//! the work W = ∫M* dφ (quadrature over the angle travelled when M* depends
//! on φ only, else the integrated power ∫M*ω dt) against the change of
//! kinetic energy ΔT = ½I*ω² − ½I*₀ω₀². With actions of φ only, the
//! events are also timed by the energy form ([`super::energy_form`]).

mod energy_form;

use super::{DynamicsError, DynamicsSolution, End, Integrator, Model, Sample, Settings, energy_residual, run};
use crate::engine::Deadline;
use crate::engine::function::{Function, Side};

/// A validated reduced problem in SI units.
#[derive(Clone, Debug)]
pub struct ReducedProblem {
    /// k·M(φ) terms (k = ratio of the shaft a torque acts on).
    pub torques: Vec<(Function, f64)>,
    pub inertia: Function,
    pub period: f64,
    pub angle0: f64,
    pub speed0: f64,
    pub end: End,
    pub tolerance: f64,
    /// The Runge–Kutta pair (None: [`Integrator::auto`] of the tolerance).
    pub integrator: Option<Integrator>,
    pub samples: usize,
    /// The memory of kept steps a run ending at an angle may hold before it
    /// is made again for its samples (the service's: [`super::KEPT_BYTES`]).
    pub kept_bytes: usize,
    /// The job's compute budget.
    pub deadline: Deadline,
}

struct Reduced<'a> {
    p: &'a ReducedProblem,
    slope: Function,
}

impl Model for Reduced<'_> {
    /// (φ̇, φ̈, Ẇ) = (ω, (M* − ½I*'ω²)/I*, M*·ω): W is the work of the actions.
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        let u = self.p.reduce(y[0]);
        let i = self.p.inertia.eval(u, Side::Right);
        let m = self.p.torque(t, y[0], y[1]);
        dy[0] = y[1];
        dy[1] = (m - 0.5 * self.slope.eval(u, Side::Right) * y[1] * y[1]) / i;
        dy[2] = m * y[1];
    }

    fn angle(&self, y: &[f64]) -> f64 {
        y[0]
    }

    fn speed(&self, y: &[f64]) -> f64 {
        y[1]
    }

    fn end_speed(&self, y: &[f64]) -> Option<f64> {
        Some(y[1])
    }
}

impl ReducedProblem {
    fn reduce(&self, phi: f64) -> f64 {
        phi.rem_euclid(self.period)
    }

    /// M*(φ, ω, t).
    fn torque(&self, t: f64, phi: f64, omega: f64) -> f64 {
        let u = self.reduce(phi);
        self.torques.iter().map(|(f, k)| k * f.eval_at(u, Side::Right, [omega, t])).sum()
    }

    fn kinetic(&self, phi: f64, omega: f64) -> f64 {
        0.5 * self.inertia.eval(self.reduce(phi), Side::Right) * omega * omega
    }

    /// ∫ M* dφ from a to b, across periods: the whole periods between them
    /// counted (n·∫₀ᵀ, one quadrature however many turns), the partial
    /// periods at both ends integrated. The periods are numbered by integers,
    /// never found again from an angle that rounding puts a hair below a
    /// multiple of T (that loop never ended at 11 turns).
    pub(super) fn work(&self, a: f64, b: f64) -> f64 {
        let (lo, hi, sign) = if a <= b { (a, b, 1.0) } else { (b, a, -1.0) };
        let period = self.period;
        let (k_lo, k_hi) = ((lo / period).floor(), (hi / period).floor());
        // Where in its period each end lies, within [0, T].
        let (u_lo, u_hi) = ((lo - k_lo * period).clamp(0.0, period), (hi - k_hi * period).clamp(0.0, period));
        let integral = |u0: f64, u1: f64| -> f64 {
            if u1 <= u0 {
                return 0.0;
            }
            self.torques.iter().map(|(f, k)| k * f.integral(u0, u1, 1e-14, 1e-13).value).sum()
        };
        let total = if k_lo == k_hi {
            integral(u_lo, u_hi)
        } else {
            let whole = k_hi - k_lo - 1.0;
            let cycle = if whole > 0.0 { whole * integral(0.0, period) } else { 0.0 };
            integral(u_lo, period) + cycle + integral(0.0, u_hi)
        };
        sign * total
    }
}

/// Integrates the reduced equation of motion.
pub fn solve(p: &ReducedProblem) -> Result<DynamicsSolution, DynamicsError> {
    for k in 0..=256 {
        let phi = p.period * k as f64 / 256.0;
        let i = p.inertia.eval(phi, Side::Right);
        if i.is_nan() || i <= 0.0 {
            return Err(DynamicsError::NonPositiveInertia { phi });
        }
    }
    let model = Reduced { p, slope: p.inertia.derivative() };
    let rtol = (0.01 * p.tolerance).clamp(1e-13, 1e-4);
    let atol = rtol * p.speed0.abs().max(1.0);
    let integrator = p.integrator.unwrap_or_else(|| Integrator::auto(p.tolerance, true));
    let automatic = p.integrator.is_none();
    let (end, samples, kept_bytes, deadline) = (p.end, p.samples, p.kept_bytes, p.deadline);
    let settings = Settings { end, samples, kept_bytes, rtol, atol: vec![atol; 3], integrator, automatic, deadline };
    let run = run(&model, vec![p.angle0, p.speed0, 0.0], &settings)?;
    let mut dy = [0.0; 3];
    let t0 = p.kinetic(p.angle0, p.speed0);
    let mut peak = 0.0f64;
    let samples: Vec<Sample> = run
        .states
        .iter()
        .map(|(t, y)| {
            model.rhs(*t, y, &mut dy);
            let kinetic = p.kinetic(y[0], y[1]);
            peak = peak.max(kinetic);
            let energy_residual = energy_residual(y[2], t0, kinetic, peak);
            Sample { t: *t, angle: y[0], speed: y[1], acceleration: dy[1], energy_residual }
        })
        .collect();
    let (first, last) = (samples[0], samples[samples.len() - 1]);
    // Position-only actions: their work by quadrature over the angle (independent
    // of the integrator); otherwise the integrated power.
    let position_only = !p.torques.iter().any(|(f, _)| f.uses_state());
    let w = if position_only { p.work(first.angle, last.angle) } else { run.states.last().map_or(0.0, |(_, y)| y[2]) };
    let energy_times = if position_only {
        // The first step whose end moves against the first event's direction.
        let d = run.events.first().map_or(0.0, |e| (e.angle - p.angle0).signum());
        let reversal = match d {
            d if d > 0.0 => run.reversal[0],
            d if d < 0.0 => run.reversal[1],
            _ => 0.0,
        };
        energy_form::event_times(p, &run.events, reversal)
    } else {
        Vec::new()
    };
    if p.deadline.expired() {
        return Err(DynamicsError::Budget { seconds: p.deadline.seconds(), t: run.t_end, steps: run.attempted });
    }
    Ok(DynamicsSolution {
        samples,
        energy_times,
        work_by_quadrature: position_only,
        energy_residual: energy_residual(
            w,
            p.kinetic(first.angle, first.speed),
            p.kinetic(last.angle, last.speed),
            peak,
        ),
        events: run.events,
        steps: run.attempted,
        evaluations: run.evaluations,
        integrator: run.integrator,
        stiff_at: run.stiff_at,
        repeated: run.repeated,
        estimated_error: run.local_errors[0],
        stopped: run.stopped,
        unlisted_turns: run.unlisted_turns,
    })
}
