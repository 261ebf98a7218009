//! Independent check of the exact flywheel: integrate the equation of motion
//! in time over one steady-state cycle,
//!
//! ```text
//! (I + I*(φ)) φ̈ + ½ I*'(φ) φ̇² = M*(φ)
//! ```
//!
//! from φ = 0 with the speed the energy solution gives there, and measure the
//! irregularity and mean speed the motion actually has. Each smooth piece of
//! M* and I* is integrated with its own formula and its end located on the
//! dense output, so jumps in the loads cost no accuracy. Where I* jumps, the
//! kinetic energy is kept: ω₊ = ω₋·√((I + I*₋)/(I + I*₊)).

use super::cycle::Cycle;
use crate::engine::Deadline;
use crate::engine::function::Side;
use crate::engine::numeric::ode::{Dopri5, OdeError, Rhs, Step};
use crate::engine::numeric::roots::brent;

/// What the time simulation measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Check {
    pub irregularity: f64,
    pub mean_speed: f64,
    pub omega_max: f64,
    pub omega_min: f64,
    /// Time to run through one cycle (s).
    pub cycle_time: f64,
    /// |ω(period) − ω(0)| / ω_a: how periodic the simulated motion is.
    pub periodicity_error: f64,
    pub steps: usize,
    pub evaluations: usize,
}

const MAX_STEPS: usize = 400_000;

/// One cycle in time; stopped (not finite) once the `deadline` has passed,
/// which the solution then reports as a spent budget.
pub(crate) fn simulate(
    cycle: &Cycle,
    (inertia, omega0, omega_a): (f64, f64, f64),
    rtol: f64,
    deadline: &Deadline,
) -> Result<Check, OdeError> {
    let mut state = vec![0.0, omega0];
    let (mut t, mut w_max, mut w_min) = (0.0, omega0, omega0);
    let (mut steps, mut evaluations) = (0, 0);
    let h_max = cycle.period / omega_a / 16.0;
    for (k, w) in cycle.pieces.windows(2).enumerate() {
        let (start, end) = (w[0], w[1]);
        if k > 0 {
            let before = inertia + cycle.inertia_at(start, Side::Left);
            let after = inertia + cycle.inertia_at(start, Side::Right);
            state[1] *= (before / after).sqrt();
            (w_max, w_min) = (w_max.max(state[1]), w_min.min(state[1]));
        }
        let anchor = 0.5 * (start + end);
        let mut rhs = |_t: f64, y: &[f64], dy: &mut [f64]| {
            let total = inertia + cycle.inertia.eval_frozen(y[0], anchor);
            let slope = cycle.inertia_slope.as_ref().map_or(0.0, |s| s.eval_frozen(y[0], anchor));
            dy[0] = y[1];
            dy[1] = (cycle.torque_frozen(y[0], anchor) - 0.5 * slope * y[1] * y[1]) / total;
        };
        let mut ode = Dopri5::new(&mut rhs, t, state.clone(), rtol, vec![rtol * omega_a.max(cycle.period); 2], h_max);
        loop {
            if deadline.expired() {
                return Err(OdeError::NotFinite { t });
            }
            let step = ode.step(&mut rhs, MAX_STEPS)?;
            let t_end =
                if step.y1[0] >= end { brent(|s| step.component(s, 0) - end, step.t0, step.t1, 0.0) } else { step.t1 };
            for omega in extremes(&step, t_end, &mut rhs) {
                (w_max, w_min) = (w_max.max(omega), w_min.min(omega));
            }
            if t_end < step.t1 || step.y1[0] >= end {
                (t, state) = (t_end, step.at(t_end));
                state[0] = end;
                break;
            }
        }
        steps += ode.accepted + ode.rejected;
        evaluations += ode.evaluations;
    }
    // Back to φ = 0 of the next cycle: across a jump of I* there, energy is kept.
    let wrap = (inertia + cycle.inertia_at(cycle.period, Side::Left)) / (inertia + cycle.inertia_at(0.0, Side::Right));
    state[1] *= wrap.sqrt();
    let mean = 0.5 * (w_max + w_min);
    Ok(Check {
        irregularity: (w_max - w_min) / mean,
        mean_speed: mean,
        omega_max: w_max,
        omega_min: w_min,
        cycle_time: t,
        periodicity_error: (state[1] - omega0).abs() / omega_a,
        steps,
        evaluations,
    })
}

/// ω at the end of the step (cut at `t_end`) and at an interior extremum,
/// where φ̈ changes sign, located on the dense output.
fn extremes(step: &Step, t_end: f64, rhs: &mut impl Rhs) -> Vec<f64> {
    let mut out = vec![step.component(t_end, 1)];
    let mut dy = [0.0; 2];
    let mut accel = |s: f64| {
        rhs(s, &step.at(s), &mut dy);
        dy[1]
    };
    let (a0, a1) = (step.f0[1], accel(t_end));
    if a0 * a1 < 0.0 {
        let ts = brent(&mut accel, step.t0, t_end, 0.0);
        out.push(step.component(ts, 1));
    }
    out
}
