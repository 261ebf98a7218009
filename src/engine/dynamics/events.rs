//! Events within a step, located on its dense output by Brent's method:
//! the multiples of 2π the first input crosses, the run's end, and the
//! crossings of a model's guards (where its equations change: a contact
//! that starts to slip or to roll, or one that opens), and what the
//! steppers spent over the restarts there.

use super::{End, Event, EventKind, Model};
use crate::engine::numeric::ode::{Step, Stepper};
use crate::engine::numeric::roots::brent;
use std::f64::consts::PI;

/// The event of `kind` at (t, y).
pub(super) fn at(model: &impl Model, kind: EventKind, t: f64, y: &[f64], joint: Option<usize>) -> Event {
    Event { kind, angle: model.angle(y), t, speed: model.speed(y), joint }
}

/// The first guard that crosses 0 within the step (≥ 0 at its start, < 0
/// at its end) before the run's end, the step ended there — or, in the
/// run's first step, a guard that stops the run ([`Model::stops`]) and is
/// below 0 already at t = 0, the step ended at once; `cache` holds
/// the guards at the step's start (those at its end, for the next step;
/// None after a change of equations).
pub(super) fn crossing(model: &impl Model, step: &mut Step, end: End, cache: &mut Option<Vec<f64>>) -> Option<usize> {
    let g0 = cache.take().unwrap_or_else(|| model.guards(step.t0, &step.y0));
    if g0.is_empty() {
        return None;
    }
    let g1 = model.guards(step.t1, &step.y1);
    let limit = match end {
        End::Duration(d) => d,
        End::UntilAngle { max_time, .. } => max_time,
    };
    let at_start = |k: usize| step.t0 == 0.0 && g0[k] < 0.0 && model.stops(k);
    let crossed: Vec<(usize, f64)> = (0..g0.len())
        .filter(|&k| (g0[k] >= 0.0 && g1[k] < 0.0) || at_start(k))
        .map(|k| match at_start(k) {
            true => (k, step.t0),
            false => (k, brent(|t| model.guards(t, &step.at(t))[k], step.t0, step.t1, 0.0)),
        })
        .filter(|&(_, t)| t < limit)
        .collect();
    // The earliest; of guards crossing together (within 1e-9 of the step),
    // the one listed last (a model lists its most decisive guards last).
    let earliest = crossed.iter().map(|c| c.1).fold(f64::INFINITY, f64::min);
    let together = 1e-9 * (step.t1 - step.t0);
    let first = crossed.into_iter().filter(|c| c.1 <= earliest + together).max_by_key(|c| c.0);
    *cache = first.is_none().then_some(g1);
    let (k, t) = first?;
    step.end_at(t);
    Some(k)
}

/// The most turns a run lists as events; those crossed after are counted.
pub const MAX_TURN_EVENTS: usize = 100_000;

/// The turns a run has listed, and those it crossed without listing them.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Turns {
    pub listed: usize,
    pub unlisted: u64,
    /// The lowest and highest multiples k of 2π the angle has reached (from
    /// the start's; empty, lo > hi, where the start is on none).
    pub reached: Option<(f64, f64)>,
}

/// Multiples of 2π crossed during the step for the first time, in either
/// direction — a whole turn more than the angle had made — listed while the
/// run has listed fewer than [`MAX_TURN_EVENTS`]; the others counted in
/// `unlisted` (a rotor at 2·10⁶ rad/s crosses millions in a step). A swing
/// back and forth across a multiple is no turn: a rocker lists none.
pub(super) fn turns(model: &impl Model, step: &Step, (a, b): (f64, f64), events: &mut Vec<Event>, tally: &mut Turns) {
    // The first step starts at the start's angle: the multiples it is on.
    let (lo, hi) = *tally.reached.get_or_insert(((a / (2.0 * PI)).ceil(), (a / (2.0 * PI)).floor()));
    let (ka, kb) = ((a / (2.0 * PI)).floor(), (b / (2.0 * PI)).floor());
    if !(ka.is_finite() && kb.is_finite()) || ka == kb {
        return;
    }
    // Up: ka + 1 ..= kb; down: ka ..= kb + 1, but ka itself where the step starts on it.
    let (first, dir) = match kb > ka {
        true => (ka + 1.0, 1.0),
        false if 2.0 * PI * ka == a => (ka - 1.0, -1.0),
        false => (ka, -1.0),
    };
    // Only the multiples beyond those reached: up from hi + 1, down from lo − 1.
    let first = if dir > 0.0 { first.max(hi + 1.0) } else { first.min(lo - 1.0) };
    // Up: first ..= kb; down: first down to kb + 1.
    let count = if dir > 0.0 { kb - first + 1.0 } else { first - kb }.max(0.0);
    if count > 0.0 {
        tally.reached = Some(if dir > 0.0 { (lo, kb) } else { (kb + 1.0, hi) });
    }
    let shown = count.min(MAX_TURN_EVENTS.saturating_sub(tally.listed) as f64);
    tally.listed += shown as usize;
    tally.unlisted += (count - shown) as u64;
    for i in 0..shown as u64 {
        let target = 2.0 * PI * (first + dir * i as f64);
        let t = brent(|s| model.angle(&step.at(s)) - target, step.t0, step.t1, 0.0);
        events.push(at(model, EventKind::Turn, t, &step.at(t), None));
    }
}

/// φ at the step's ends, the second cut at the run's end where the run
/// ends within the step (a free rotor's last step may run far past it).
pub(super) fn to_end(model: &impl Model, end: End, step: &Step, (a, b): (f64, f64)) -> (f64, f64) {
    let ends_at = |t: f64| if step.t1 > t { (a, model.angle(&step.at(t.max(step.t0)))) } else { (a, b) };
    match end {
        End::Duration(d) => ends_at(d),
        End::UntilAngle { angle, .. } if (a - angle) * (b - angle) <= 0.0 && a != b => (a, angle),
        End::UntilAngle { max_time, .. } => ends_at(max_time),
    }
}

/// The end time if the run ends in this step.
pub(super) fn finished(
    model: &impl Model,
    end: End,
    step: &Step,
    (a0, a1): (f64, f64),
    events: &mut Vec<Event>,
    stopped: &mut Option<super::Stopped>,
) -> Option<f64> {
    let close = |t: f64, events: &mut Vec<Event>| {
        events.push(at(model, EventKind::End, t, &step.at(t), None));
        Some(t)
    };
    match end {
        End::Duration(d) if step.t1 >= d => close(d, events),
        End::UntilAngle { angle, .. } if (a0 - angle) * (a1 - angle) <= 0.0 && a1 != a0 => {
            let t = brent(|s| model.angle(&step.at(s)) - angle, step.t0, step.t1, 0.0);
            close(t, events)
        }
        End::UntilAngle { angle, max_time } if step.t1 >= max_time => {
            *stopped = Some(super::Stopped::NotReached { angle, max_time });
            close(max_time, events)
        }
        _ => None,
    }
}

/// What the steppers of one run spent, over the restarts at its events.
pub(super) struct Spent {
    pub counts: [usize; 3],
    pub errors: Vec<f64>,
}

impl Spent {
    pub fn add(&mut self, ode: &impl Stepper) {
        self.counts.iter_mut().zip(ode.counts()).for_each(|(a, b)| *a += b);
        self.errors.resize(ode.local_errors().len(), 0.0);
        self.errors.iter_mut().zip(ode.local_errors()).for_each(|(a, b)| *a += b);
    }
}
