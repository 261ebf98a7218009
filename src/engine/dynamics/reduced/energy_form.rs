//! The energy form of the reduced equation, a second method for actions
//! that depend on φ only: the kinetic energy is known in closed form,
//!
//! ```text
//! ½ I*(φ) ω(φ)² = T₀ + W(φ),   W(φ) = ∫_{φ₀}^{φ} M*(φ') dφ'
//! t(φ) = ∫_{φ₀}^{φ} dφ' / ω(φ')
//! ```
//!
//! so the time an event angle is reached follows from two nested
//! quadratures, without integrating any differential equation. It holds
//! while the motion goes one way: events are taken in order until the angle
//! turns back. From rest (ω₀ = 0) 1/ω is singular at φ₀ like
//! 1/√(φ − φ₀); the substitution φ = φ₀ + d·s² (d the direction) removes it.

use super::ReducedProblem;
use crate::engine::dynamics::Event;
use crate::engine::function::Side;
use crate::engine::numeric::quadrature::integrate;

/// Most events timed by the energy form (the quadratures grow with them).
const MAX_EVENTS: usize = 200;
const MAX_EVALUATIONS: usize = 20_000;

/// The time of each event by the energy form, in order, while the motion
/// goes one way — until `reversal`, the first time the integration saw the
/// speed change sign — (None after, or when the quadrature fails).
pub(super) fn event_times(p: &ReducedProblem, events: &[Event], reversal: f64) -> Vec<Option<f64>> {
    let Some(first) = events.first() else { return Vec::new() };
    let d = (first.angle - p.angle0).signum();
    let t0 = 0.5 * inertia(p, p.angle0) * p.speed0 * p.speed0;
    let (mut at, mut work, mut time) = (p.angle0, 0.0, 0.0);
    let mut going = d != 0.0 && p.speed0 * d >= 0.0;
    events
        .iter()
        .enumerate()
        .map(|(k, e)| {
            // Past the budget the events go untimed (the solution is then refused as late).
            going = going && k < MAX_EVENTS && e.t < reversal && (e.angle - at) * d >= 0.0 && !p.deadline.expired();
            if !going {
                return None;
            }
            let from_rest = at == p.angle0 && p.speed0 == 0.0;
            let Some(dt) = segment(p, at, e.angle, t0 + work, from_rest) else {
                going = false;
                return None;
            };
            work += p.work(at, e.angle);
            (time, at) = (time + dt, e.angle);
            Some(time)
        })
        .collect()
}

fn inertia(p: &ReducedProblem, phi: f64) -> f64 {
    p.inertia.eval(phi.rem_euclid(p.period), Side::Right)
}

/// ∫ₐᵇ dφ/|ω| with the kinetic energy `energy` at a.
fn segment(p: &ReducedProblem, a: f64, b: f64, energy: f64, from_rest: bool) -> Option<f64> {
    // NaN past the budget: the quadrature stops at once.
    let speed = |phi: f64| {
        if p.deadline.expired() { f64::NAN } else { (2.0 * (energy + p.work(a, phi)) / inertia(p, phi)).sqrt() }
    };
    let tol = |scale: f64| (1e-13 * scale, 1e-12);
    let r = if from_rest {
        let d = (b - a).signum();
        let (abs, rel) = tol((b - a).abs().sqrt());
        integrate(|s| 2.0 * s / speed(a + d * s * s), 0.0, (b - a).abs().sqrt(), abs, rel, MAX_EVALUATIONS)
    } else {
        let (abs, rel) = tol((b - a).abs());
        integrate(|phi| 1.0 / speed(phi), a, b, abs, rel, MAX_EVALUATIONS)
    };
    let t = r.value.abs();
    (t.is_finite() && r.error <= 1e-9 * t.max(1e-9)).then_some(t)
}
