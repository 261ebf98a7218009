//! Direct dynamics: the motion of a machine under given actions.
//!
//! Two models share one driver of the integration ([`run`]): the reduced
//! 1-DOF equation ([`reduced`]) and a planar mechanism of any DOF in
//! dependent coordinates ([`mechanism`]). It steps with one of three
//! Runge–Kutta methods with dense output ([`Integrator`]): Dormand–Prince
//! 5(4), Hairer's DOP853 (order 8) for tight tolerances and long runs, or
//! the implicit Radau IIA (order 5) for stiff models. Chosen automatically,
//! an explicit pair that finds its steps held by stability (a stiff spring)
//! hands the run to Radau IIA, started again from t = 0.
//! Events — every multiple of 2π the first input coordinate φ crosses, in
//! either direction, and the end angle — are located on the dense output by
//! Brent's method, not at the nearest step. A run ends at its duration, at
//! its end angle, or cleanly (with the reason) when the end angle is not
//! reached in time; it fails with [`DynamicsError`] when the integration
//! cannot go on or the compute budget runs out.

mod events;
mod failure;
pub mod mechanism;
mod range_space;
pub mod reduced;
mod rows;
mod sampler;

pub use events::MAX_TURN_EVENTS;
pub use failure::{DynamicsError, Failure, Start};
pub use reduced::{ReducedProblem, solve};

use super::numeric::dop853::Dp853;
use super::numeric::ode::{Dp5, Explicit, Stepper};
use super::numeric::radau::Radau5;
use crate::engine::Deadline;
pub use sampler::KEPT_BYTES;
use sampler::Sampler;

/// The Runge–Kutta method that integrates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Integrator {
    /// Dormand–Prince 5(4): 6 evaluations a step, 4th-order dense output.
    Dopri5,
    /// DOP853, order 8: 12 evaluations a step and 3 for its 7th-order dense
    /// output, far fewer steps at tight tolerances.
    Dop853,
    /// Radau IIA, order 5, implicit (Newton on its three stages, J by
    /// differences): steps sized by the slow motion of a stiff model.
    Radau5,
}

impl Integrator {
    /// For a smooth model (the reduced form), the pair that takes fewer
    /// evaluations at this requested tolerance (measured in
    /// docs/BENCHMARKS.md): DOP853 from 1e-5 down. A mechanism's dy/dt jumps
    /// where its rows are held or dropped (singular positions, changes of
    /// rank), where a high order gains nothing and its 12 stages cost more
    /// at every rejected step: Dormand–Prince unless asked. (Asked, DOP853
    /// and Radau IIA leave a mechanism's branch at a fold: there the run is
    /// made again with Dormand–Prince, [`mechanism::solve_in`].)
    pub fn auto(tolerance: f64, smooth: bool) -> Self {
        if smooth && tolerance <= AUTO_DOP853 { Self::Dop853 } else { Self::Dopri5 }
    }

    pub fn name(self) -> &'static str {
        match self {
            Self::Dopri5 => "Dormand-Prince 5(4)",
            Self::Dop853 => "DOP853 (order 8, 7th-order dense output)",
            Self::Radau5 => "Radau IIA (order 5, implicit, for stiff models)",
        }
    }
}

/// The requested tolerance at and below which [`Integrator::auto`] picks DOP853.
pub const AUTO_DOP853: f64 = 1e-5;

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

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    pub t: f64,
    pub angle: f64,
    pub speed: f64,
    pub acceleration: f64,
    /// (W − ΔT)/max(|W|, |ΔT|, T₀, T, T_peak) from the start to this sample, W the
    /// integrated power of the actions: how the energy balance drifts.
    pub energy_residual: f64,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventKind {
    /// φ crossed a multiple of 2π.
    Turn,
    /// A rolling contact began to slip (or its slip turned back).
    Slip,
    /// A slipping contact began to roll.
    Roll,
    /// A contact's normal force fell to 0: the bodies part (the run stops).
    Separation,
    End,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Event {
    pub kind: EventKind,
    pub angle: f64,
    pub t: f64,
    pub speed: f64,
    /// The joint whose contact changed (slip, roll).
    pub joint: Option<usize>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct DynamicsSolution {
    pub samples: Vec<Sample>,
    pub events: Vec<Event>,
    /// Reduced form with actions of φ only: each event's time by the energy
    /// form t = ∫dφ/ω (None once the motion has turned back); else empty.
    pub energy_times: Vec<Option<f64>>,
    /// (W − ΔT)/max(|W|, |ΔT|, T₀, T_end, T_peak).
    pub energy_residual: f64,
    /// W by quadrature over the angle (the reduced form's actions of φ
    /// only); else the integrated power.
    pub work_by_quadrature: bool,
    pub steps: usize,
    pub evaluations: usize,
    pub integrator: Integrator,
    /// Chosen automatically, the explicit pair found the model stiff at
    /// this time and the run was made again with Radau IIA (the steps and
    /// evaluations count both runs).
    pub stiff_at: Option<f64>,
    /// The run ended at an angle after more steps than it keeps
    /// ([`KEPT_BYTES`]) and was made again to the end time it found, for the
    /// states at the instants asked (the steps and evaluations count both).
    pub repeated: bool,
    /// Σ over the steps of the local error estimate of the angle (rad; for a
    /// mechanism the largest over its bodies' angles): a first-order
    /// estimate of the global error that ignores its growth or decay.
    pub estimated_error: f64,
    /// Why the run stopped early (e.g. the end angle was not reached in time).
    pub stopped: Option<Stopped>,
    /// Turns crossed after the first [`MAX_TURN_EVENTS`] listed as events.
    pub unlisted_turns: u64,
}

/// Why a run stopped before its end.
#[derive(Clone, Debug, PartialEq)]
pub enum Stopped {
    /// The end angle (rad) was not reached within `max_time` (s).
    NotReached { angle: f64, max_time: f64 },
    /// The normal force of contact `joint` (its name and index) fell to 0
    /// at `t` (s), or was below 0 at the start: the bodies would separate,
    /// and what follows is not these joints' motion.
    ContactOpens { joint: String, index: usize, t: f64 },
    /// The contacts changed between rolling and slipping `switches` times
    /// by `t` (s): they chatter.
    Chatter { switches: usize, t: f64 },
    /// A guard crossed where the model has none.
    Unexpected,
}

/// What the integrator needs from a model with state y.
pub(crate) trait Model {
    /// dy/dt.
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]);
    /// The first input coordinate φ and its speed.
    fn angle(&self, y: &[f64]) -> f64;
    fn speed(&self, y: &[f64]) -> f64;
    /// φ̇ at a step's end where the model asks when the motion first turns
    /// back ([`Run::reversal`]; the reduced form's energy times); None, the
    /// default, skips it (for a mechanism it would assemble the constraints).
    fn end_speed(&self, _y: &[f64]) -> Option<f64> {
        None
    }
    /// Forgets what an earlier run from t = 0 left that would change this
    /// one (a run is made again after a hand-over, or for its samples).
    fn restart(&self) {}
    /// Moves an accepted state back onto the model's invariants (e.g. the
    /// constraints, the energy); returns the largest constraint violation removed.
    fn project(&self, _y: &mut [f64]) -> f64 {
        0.0
    }
    /// The guards of the model's present equations at (t, y), each ≥ 0 while
    /// they hold (a rolling contact's μN − |F_t|, a slip's direction, a
    /// contact's normal force): one that crosses 0 within a step is an
    /// event there ([`events`]). None, the default: the equations never change.
    fn guards(&self, _t: f64, _y: &[f64]) -> Vec<f64> {
        Vec::new()
    }
    /// Guard k crossed 0 at (t, y): the model changes its equations there,
    /// or the run stops.
    fn cross(&self, _k: usize, _t: f64, _y: &[f64]) -> Crossing {
        Crossing::Stop(Stopped::Unexpected)
    }
    /// Guard k stops the run (a contact's normal force): one already below
    /// 0 at the start stops it there.
    fn stops(&self, _k: usize) -> bool {
        false
    }
}

/// What a model does where one of its guards crosses 0.
pub(crate) enum Crossing {
    /// Its equations change there: an event of this kind at this joint.
    Switch(EventKind, usize),
    /// The run stops there, for this reason.
    Stop(Stopped),
}

/// How to integrate.
#[derive(Clone, Debug)]
pub(crate) struct Settings {
    pub end: End,
    /// How many instants the run reports, evenly spaced over [0, t_end].
    pub samples: usize,
    /// The memory of kept steps allowed where the end time is found on the
    /// way ([`KEPT_BYTES`]).
    pub kept_bytes: usize,
    pub rtol: f64,
    pub atol: Vec<f64>,
    pub integrator: Integrator,
    /// The integrator was chosen, not asked for: an explicit one that finds
    /// the model stiff hands over to Radau IIA.
    pub automatic: bool,
    /// The job's compute budget, read after every step and before every
    /// evaluation of dy/dt (an evaluation after it answers NaN, so the step
    /// in progress ends at once).
    pub deadline: Deadline,
}

/// The states at the instants asked, with the events.
pub(crate) struct Run {
    /// (t, y) at `samples` instants evenly spaced over [0, t_end].
    pub states: Vec<(f64, Vec<f64>)>,
    /// t₀ of the first step whose end speed ([`Model::end_speed`]) is ≤ 0,
    /// and of the first whose end speed is ≥ 0 (∞ where none is).
    pub reversal: [f64; 2],
    pub events: Vec<Event>,
    pub t_end: f64,
    pub stopped: Option<Stopped>,
    pub attempted: usize,
    pub evaluations: usize,
    /// Largest constraint violation removed by a projection.
    pub drift: f64,
    /// Σ of the local error estimates of each state component.
    pub local_errors: Vec<f64>,
    /// The method that made the run, and when an explicit one found the model stiff.
    pub integrator: Integrator,
    pub stiff_at: Option<f64>,
    pub repeated: bool,
    /// Turns crossed after the first [`events::MAX_TURN_EVENTS`], not listed.
    pub unlisted_turns: u64,
}

const MAX_STEPS: usize = 2_000_000;
/// The most changes of a model's equations in a run ([`Model::cross`]).
const MAX_SWITCHES: usize = 10_000;

/// Integrates the model from y₀ at t = 0 until the end condition; a run
/// the explicit pair finds stiff is made again with Radau IIA when the
/// pair was chosen automatically. A run that ends at an angle after more
/// steps than it may keep is made again as a duration to the end time it
/// found, with the method that finished it: the same steps, the states at
/// the instants asked, its counts added ([`sampler`]).
pub(crate) fn run(model: &impl Model, y0: Vec<f64>, s: &Settings) -> Result<Run, DynamicsError> {
    let mut first = attempt(model, y0.clone(), s)?;
    if first.states.is_empty() {
        let again =
            Settings { end: End::Duration(first.t_end), integrator: first.integrator, automatic: false, ..s.clone() };
        let second = attempt(model, y0, &again)?;
        first.states = second.states;
        first.attempted += second.attempted;
        first.evaluations += second.evaluations;
        first.repeated = true;
    }
    Ok(first)
}

/// [`run`] once, with the hand-over to Radau IIA.
fn attempt(model: &impl Model, y0: Vec<f64>, s: &Settings) -> Result<Run, DynamicsError> {
    let first = match s.integrator {
        Integrator::Dopri5 => drive::<Explicit<Dp5>>(model, y0.clone(), s)?,
        Integrator::Dop853 => drive::<Explicit<Dp853>>(model, y0.clone(), s)?,
        Integrator::Radau5 => drive::<Radau5>(model, y0.clone(), s)?,
    };
    match first {
        Ok(run) => Ok(run),
        Err(Handover { t, attempted, evaluations }) => {
            let mut run = drive::<Radau5>(model, y0, &Settings { integrator: Integrator::Radau5, ..s.clone() })?
                .unwrap_or_else(|_| unreachable!("Radau IIA does not hand over"));
            run.stiff_at = Some(t);
            run.attempted += attempted;
            run.evaluations += evaluations;
            Ok(run)
        }
    }
}

/// Where an automatically chosen explicit pair found the model stiff, and
/// what it had spent.
struct Handover {
    t: f64,
    attempted: usize,
    evaluations: usize,
}

/// The run with the stepper S, or the handover to Radau IIA.
fn drive<S: Stepper>(model: &impl Model, y0: Vec<f64>, s: &Settings) -> Result<Result<Run, Handover>, DynamicsError> {
    model.restart();
    let deadline = s.deadline;
    // The clock is read at every 8th evaluation (a read takes ~25 ns, a
    // small mechanism's evaluation ~0.5 µs); once late, every evaluation
    // is NaN, and the step that meets it fails.
    let (mut calls, mut late) = (0u32, false);
    let mut f = |t: f64, y: &[f64], dy: &mut [f64]| {
        calls = calls.wrapping_add(1);
        late = late || (calls % 8 == 0 && deadline.expired());
        if late { dy.fill(f64::NAN) } else { model.rhs(t, y, dy) }
    };
    let over = |ode: &S| DynamicsError::Budget { seconds: deadline.seconds(), t: ode.time(), steps: ode.counts()[0] };
    let mut ode = S::start(&mut f, 0.0, y0, s.rtol, s.atol.clone());
    let known = match s.end {
        End::Duration(d) => Some(d),
        End::UntilAngle { .. } => None,
    };
    let mut sampler = Sampler::new(s.samples, known, s.kept_bytes);
    let (mut events, mut stopped, mut drift, mut reversal) = (Vec::new(), None, 0.0f64, [f64::INFINITY; 2]);
    let (mut guards, mut switches, mut spent) = (None, 0, events::Spent { counts: [0; 3], errors: Vec::new() });
    let (mut turns, mut y) = (events::Turns::default(), Vec::new());
    let t_end = loop {
        if deadline.expired() {
            return Err(over(&ode));
        }
        let step = ode.step(&mut f, MAX_STEPS);
        if deadline.expired() {
            return Err(over(&ode));
        }
        let step = step.map_err(|e| DynamicsError::Integration { t: ode.time(), reason: Failure::Ode(e) })?;
        if s.automatic && ode.stiff() {
            spent.add(&ode);
            let [accepted, rejected, evaluations] = spent.counts;
            return Ok(Err(Handover { t: step.t1, attempted: accepted + rejected, evaluations }));
        }
        let mut step = step;
        let crossing = events::crossing(model, &mut step, s.end, &mut guards);
        // φ at both ends of the step, evaluated once: for a mechanism each
        // evaluation assembles the constraints.
        let span = (model.angle(&step.y0), model.angle(&step.y1));
        events::turns(model, &step, events::to_end(model, s.end, &step, span), &mut events, &mut turns);
        if let Some(w) = model.end_speed(&step.y1) {
            let first = |t: f64, reached: bool| if reached { t.min(step.t0) } else { t };
            reversal = [first(reversal[0], w <= 0.0), first(reversal[1], w >= 0.0)];
        }
        if let Some(t) = events::finished(model, s.end, &step, span, &mut events, &mut stopped) {
            sampler.accept(step, true);
            break t;
        }
        y.clear();
        y.extend_from_slice(&step.y1);
        if let Some(k) = crossing {
            let t = step.t1;
            let reason = match model.cross(k, t, &y) {
                Crossing::Switch(..) if switches == MAX_SWITCHES => Some(Stopped::Chatter { switches, t }),
                Crossing::Switch(kind, joint) => {
                    events.push(events::at(model, kind, t, &y, Some(joint)));
                    None
                }
                Crossing::Stop(reason) => Some(reason),
            };
            if let Some(reason) = reason {
                if let Stopped::ContactOpens { index, .. } = reason {
                    events.push(events::at(model, EventKind::Separation, t, &y, Some(index)));
                }
                events.push(events::at(model, EventKind::End, t, &y, None));
                stopped = Some(reason);
                sampler.accept(step, true);
                break t;
            }
            // The equations change here: the stepper starts again from the event.
            switches += 1;
            drift = drift.max(model.project(&mut y));
            spent.add(&ode);
            ode = S::start(&mut f, t, y.clone(), s.rtol, s.atol.clone());
            sampler.accept(step, false);
            continue;
        }
        drift = drift.max(model.project(&mut y));
        if y != step.y1 {
            ode.project(&mut f, &y);
        }
        if let Some(done) = sampler.accept(step, false) {
            ode.recycle(done);
        }
    };
    events.retain(|e| e.kind == EventKind::End || e.t <= t_end);
    spent.add(&ode);
    Ok(Ok(Run {
        states: sampler.finish(t_end),
        reversal,
        events,
        t_end,
        stopped,
        attempted: spent.counts[0] + spent.counts[1],
        evaluations: spent.counts[2],
        drift,
        local_errors: spent.errors,
        integrator: s.integrator,
        stiff_at: None,
        repeated: false,
        unlisted_turns: turns.unlisted,
    }))
}

/// (W − ΔT)/max(|W|, |ΔT|, T₀, T_end, T_peak), T_peak the largest kinetic
/// energy sampled so far (a swing that ends at rest, as it started, is
/// measured against the energy it swung with, not the ~0 at its ends).
pub(crate) fn energy_residual(work: f64, t0: f64, t1: f64, peak: f64) -> f64 {
    let dt = t1 - t0;
    let denom = work.abs().max(dt.abs()).max(t0).max(t1).max(peak);
    if denom > 0.0 { (work - dt) / denom } else { 0.0 }
}
