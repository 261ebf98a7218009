//! Direct dynamics of a 1-DOF machine in reduced form:
//!
//! ```text
//! I*(φ) φ̈ + ½ I*'(φ) φ̇² = M*(φ)
//! ```
//!
//! integrated in time with Dormand–Prince 5(4) from (φ₀, ω₀). Functions are
//! periodic in φ (reduced to [0, period)); expressions may also read `omega`
//! and `t`. Events — every multiple of 2π
//! crossed in either direction, and the end angle — are located on the
//! dense output by Brent's method, not at the nearest step. Energy check:
//! the work W = ∫M* dφ (quadrature over the angle travelled when M* depends
//! on φ only, else the integrated power ∫M*ω dt) against the change of
//! kinetic energy ΔT = ½I*ω² − ½I*₀ω₀².

use super::function::{Function, Side};
use super::numeric::ode::{Dopri5, Step};
use super::numeric::roots::brent;
use std::f64::consts::PI;

/// When the run ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum End {
    Duration(f64),
    /// Until φ reaches this angle (the end is then an event), or `max_time` passes.
    UntilAngle {
        angle: f64,
        max_time: f64,
    },
}

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
    pub samples: usize,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    pub t: f64,
    pub angle: f64,
    pub speed: f64,
    pub acceleration: f64,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventKind {
    /// φ crossed a multiple of 2π.
    Turn,
    End,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Event {
    pub kind: EventKind,
    pub angle: f64,
    pub t: f64,
    pub speed: f64,
}

#[derive(Clone, Debug, PartialEq)]
pub struct DynamicsSolution {
    pub samples: Vec<Sample>,
    pub events: Vec<Event>,
    /// (W − ΔT)/max(|W|, |ΔT|, T₀, T_end).
    pub energy_residual: f64,
    pub steps: usize,
    pub evaluations: usize,
    /// Why the run stopped early (e.g. the end angle was not reached in time).
    pub stopped: Option<String>,
}

/// Why the motion cannot be computed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DynamicsError {
    #[error("the reduced inertia is not positive at phi = {phi} rad")]
    NonPositiveInertia { phi: f64 },
    #[error("the integration failed at t = {t} s: {reason}")]
    Integration { t: f64, reason: String },
}

const MAX_STEPS: usize = 2_000_000;

impl ReducedProblem {
    fn reduce(&self, phi: f64) -> f64 {
        phi.rem_euclid(self.period)
    }

    /// M*(φ, ω, t).
    fn torque(&self, t: f64, phi: f64, omega: f64) -> f64 {
        let u = self.reduce(phi);
        self.torques.iter().map(|(f, k)| k * f.eval_at(u, Side::Right, [omega, t])).sum()
    }

    /// (φ̇, φ̈, Ẇ) = (ω, (M* − ½I*'ω²)/I*, M*·ω): W is the work of the actions.
    fn rhs(&self, slope: &Function, t: f64, y: &[f64; 3]) -> [f64; 3] {
        let u = self.reduce(y[0]);
        let i = self.inertia.eval(u, Side::Right);
        let m = self.torque(t, y[0], y[1]);
        [y[1], (m - 0.5 * slope.eval(u, Side::Right) * y[1] * y[1]) / i, m * y[1]]
    }

    fn kinetic(&self, phi: f64, omega: f64) -> f64 {
        0.5 * self.inertia.eval(self.reduce(phi), Side::Right) * omega * omega
    }

    /// ∫ M* dφ from a to b, across periods.
    fn work(&self, a: f64, b: f64) -> f64 {
        let (lo, hi, sign) = if a <= b { (a, b, 1.0) } else { (b, a, -1.0) };
        let mut total = 0.0f64;
        let mut x = lo;
        while x < hi {
            let base = (x / self.period).floor() * self.period;
            let end = (base + self.period).min(hi);
            let (u0, u1) = (x - base, end - base);
            for (f, k) in &self.torques {
                total += k * f.integral(u0, u1, 1e-14 * (1.0 + total.abs()), 1e-13).value;
            }
            x = end;
        }
        sign * total
    }
}

/// Integrates the reduced equation of motion.
pub fn solve(p: &ReducedProblem) -> Result<DynamicsSolution, DynamicsError> {
    let slope = p.inertia.derivative();
    for k in 0..=256 {
        let phi = p.period * k as f64 / 256.0;
        let i = p.inertia.eval(phi, Side::Right);
        if i.is_nan() || i <= 0.0 {
            return Err(DynamicsError::NonPositiveInertia { phi });
        }
    }
    let mut f = |t: f64, y: &[f64; 3]| p.rhs(&slope, t, y);
    let rtol = (0.01 * p.tolerance).clamp(1e-13, 1e-4);
    let scale = p.speed0.abs().max(1.0);
    let mut ode = Dopri5::new(&mut f, 0.0, [p.angle0, p.speed0, 0.0], rtol, rtol * scale, f64::INFINITY);
    let mut steps: Vec<Step<3>> = Vec::new();
    let mut events = Vec::new();
    let mut stopped = None;
    let t_end = loop {
        let step = ode
            .step(&mut f, MAX_STEPS)
            .map_err(|e| DynamicsError::Integration { t: ode_time(&steps), reason: e.to_string() })?;
        turns(&step, &mut events);
        if let Some(t) = finished(p, &step, &mut events, &mut stopped) {
            steps.push(step);
            break t;
        }
        steps.push(step);
    };
    events.retain(|e| e.kind == EventKind::End || e.t <= t_end);
    let samples = sample(p, &slope, &steps, t_end);
    let (first, last) = (samples[0], samples[samples.len() - 1]);
    // Position-only actions: their work by quadrature over the angle (independent
    // of the integrator); otherwise the integrated power.
    let w = if p.torques.iter().any(|(f, _)| f.uses_state()) {
        steps.last().map_or(0.0, |s| s.at(t_end)[2])
    } else {
        p.work(first.angle, last.angle)
    };
    let dt = p.kinetic(last.angle, last.speed) - p.kinetic(first.angle, first.speed);
    let denom = w.abs().max(dt.abs()).max(p.kinetic(first.angle, first.speed)).max(p.kinetic(last.angle, last.speed));
    Ok(DynamicsSolution {
        samples,
        events,
        energy_residual: if denom > 0.0 { (w - dt) / denom } else { 0.0 },
        steps: ode.accepted + ode.rejected,
        evaluations: ode.evaluations,
        stopped,
    })
}

fn ode_time(steps: &[Step<3>]) -> f64 {
    steps.last().map_or(0.0, |s| s.t1)
}

/// Multiples of 2π crossed during the step, in either direction.
fn turns(step: &Step<3>, events: &mut Vec<Event>) {
    let (a, b) = (step.y0[0], step.y1[0]);
    let (ka, kb) = ((a / (2.0 * PI)).floor() as i64, (b / (2.0 * PI)).floor() as i64);
    let crossed: Vec<i64> = if kb > ka { (ka + 1..=kb).collect() } else { (kb + 1..=ka).rev().collect() };
    for k in crossed {
        let target = 2.0 * PI * k as f64;
        if target == a {
            continue;
        }
        let t = brent(|s| step.at(s)[0] - target, step.t0, step.t1, 0.0);
        events.push(Event { kind: EventKind::Turn, angle: target, t, speed: step.at(t)[1] });
    }
}

/// The end time if the run ends in this step.
fn finished(p: &ReducedProblem, step: &Step<3>, events: &mut Vec<Event>, stopped: &mut Option<String>) -> Option<f64> {
    let end = |t: f64, events: &mut Vec<Event>| {
        let y = step.at(t);
        events.push(Event { kind: EventKind::End, angle: y[0], t, speed: y[1] });
        Some(t)
    };
    match p.end {
        End::Duration(d) if step.t1 >= d => end(d, events),
        End::UntilAngle { angle, .. }
            if (step.y0[0] - angle) * (step.y1[0] - angle) <= 0.0 && step.y1[0] != step.y0[0] =>
        {
            let t = brent(|s| step.at(s)[0] - angle, step.t0, step.t1, 0.0);
            end(t, events)
        }
        End::UntilAngle { angle, max_time } if step.t1 >= max_time => {
            *stopped = Some(format!("the angle {angle} rad was not reached within {max_time} s"));
            end(max_time, events)
        }
        _ => None,
    }
}

/// Evenly spaced samples in time, both ends included, from the dense output.
fn sample(p: &ReducedProblem, slope: &Function, steps: &[Step<3>], t_end: f64) -> Vec<Sample> {
    let n = p.samples.max(2);
    let mut k = 0;
    (0..n)
        .map(|i| {
            let t = t_end * i as f64 / (n - 1) as f64;
            while k + 1 < steps.len() && steps[k].t1 < t {
                k += 1;
            }
            let y = steps[k].at(t.min(steps[k].t1));
            Sample { t, angle: y[0], speed: y[1], acceleration: p.rhs(slope, t, &y)[1] }
        })
        .collect()
}
