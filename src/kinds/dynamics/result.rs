//! The `result` of a dynamics job, as stored and served, and its CSV table.

use super::{IntegratorChoice, MachineDynamics, SpatialMachineDynamics};
use crate::engine::dynamics::mechanism::MechanismSolution;
use crate::engine::dynamics::{DynamicsSolution, EventKind, Integrator, KEPT_BYTES, MAX_TURN_EVENTS, Stopped};
use crate::engine::model::Mechanism;
use crate::engine::variants::round_sig;
use crate::i18n::Msg;
use crate::kind::notes::Notes;
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// One sample of the motion.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(as = DynamicsSample)]
pub struct SampleDto {
    pub t: f64,
    pub angle: f64,
    pub speed: f64,
    pub acceleration: f64,
    /// (W − ΔT)/max(|W|, |ΔT|, T₀, T, T_peak) from the start to this sample, W the
    /// work of the actions (mechanism form: −ΔV where they have a
    /// potential and no contact has friction; else their integrated power),
    /// T_peak the largest T sampled so far: the energy balance's drift.
    pub energy_residual: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct EventDto {
    /// "turn" (a multiple of 2π first crossed, either direction: a whole turn; a swing back across one is none), "slip" (a
    /// rolling contact with friction starts to slip, or its slip turns
    /// back), "roll" (a slipping contact rolls again), "separation" (a
    /// contact's normal force fell to 0, or was below 0 at the start: the
    /// bodies part, and the run stops there) or "end".
    pub kind: String,
    /// The contact joint of a "slip", "roll" or "separation" event.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub joint: Option<String>,
    pub angle: f64,
    pub t: f64,
    pub speed: f64,
    /// Reduced form with actions of φ only: the time of the event by the
    /// energy form t = ∫dφ/ω, ω from ½I*ω² = T₀ + ∫M*dφ (nested quadratures,
    /// no differential equation), while the motion has not turned back.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub t_energy_form: Option<f64>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct DynamicsAccuracy {
    /// (W − ΔT)/max(|W|, |ΔT|, T₀, T_end, T_peak): the work of the actions against
    /// the change of kinetic energy. W is a quadrature over the angle when the
    /// reduced actions depend on φ only, else the integrated power.
    pub energy_residual: f64,
    /// The largest |t − t_energy_form| over the events (s), when any has one:
    /// an independent measure of the integration's error.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_form_time_difference: Option<f64>,
    /// A bound of the error of the angle (rad; for a mechanism, of its first
    /// input's coordinate, in its unit — m for a slider): 1.5 times
    /// `global_error` where that was made, or Σ over the steps of the
    /// integrator's local error estimate (for a mechanism's angle the largest
    /// over its bodies' angles too) where larger or where no `global_error`
    /// could be had — a first-order estimate that ignores how errors grow
    /// along the motion. `error_estimate` says which.
    pub estimated_error: f64,
    /// The largest difference of the angle over the samples between this run
    /// and the same run at a tolerance a hundred times tighter: the global
    /// error, growth included. Absent where it did not fit (`error_estimate`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub global_error: Option<f64>,
    /// How `estimated_error` was found, and where `global_error` is absent, why.
    #[serde(default)]
    pub error_estimate: String,
    pub steps: usize,
    pub function_evaluations: usize,
    /// Mechanism form: the largest constraint violation |Φ| (m or rad)
    /// removed by the projection after a step.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub constraint_drift: Option<f64>,
    /// The Runge–Kutta method that integrated (`dopri5`, `dop853` or `radau5`).
    pub integrator: IntegratorChoice,
    /// Chosen automatically, the explicit pair found the model stiff (its
    /// steps held by stability, not accuracy) at this time, s, and the run
    /// was made again from the start with Radau IIA; `steps` and
    /// `function_evaluations` count both runs (as they do where a run
    /// ending at an angle was made twice for its samples: see `method`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stiff_at: Option<f64>,
    /// Mechanism form: the integrator asked (`dop853` or `radau5`) met a
    /// singular position at this time, s, where its steps leave the
    /// mechanism's branch (it may fold into another assembly); the run was
    /// made again from the start with `dopri5`, the pair whose steps the
    /// fold's hold keeps on the branch, and `integrator`, `steps` and
    /// `function_evaluations` are that run's (a warning says so too).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub integrator_replaced_at: Option<f64>,
    /// Mechanism form: whether the energy T + V was held to its initial
    /// value throughout the run (see `machine.conserve_energy`; skipped near
    /// turning points, as `energy_held_steps` says): false where the loads
    /// have no potential, where the hold was turned off, and where a
    /// singular position was met (the hold stops there).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_conserved: Option<bool>,
    /// Mechanism form: the steps after which T + V was E₀ (not near turning
    /// points, where the correction would exceed 1 %, nor after a singular
    /// position); compare with `steps`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub energy_held_steps: Option<usize>,
    pub method: String,
}

/// Result of a dynamics job (SI units).
#[derive(Clone, Debug, Serialize, ToSchema)]
pub struct DynamicsResult {
    pub samples: Vec<SampleDto>,
    pub events: Vec<EventDto>,
    /// Where the run ended: the last of `events`, at an address that does
    /// not depend on how many turns came before (`/end/t`, `/end/speed`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub end: Option<EventDto>,
    /// Why the run stopped before its end, where it did: "separation" (a
    /// contact's normal force fell to 0: the bodies part), "not_reached"
    /// (the end angle was not reached within the longest duration),
    /// "chatter" (contacts switched between rolling and slipping without
    /// end); a warning says more.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stopped: Option<String>,
    pub energy_residual: f64,
    pub accuracy: DynamicsAccuracy,
    /// Mechanism form: every input, the reactions and the constraint residual at the samples.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub machine: Option<MachineResult>,
    #[serde(flatten)]
    pub notes: Notes,
}

/// The mechanism form's part of a result: a planar mechanism's, or a
/// spatial one's (with `"space": "spatial"`).
#[derive(Clone, Debug, Serialize, ToSchema)]
#[serde(untagged)]
pub enum MachineResult {
    Planar(MachineDynamics),
    Spatial(SpatialMachineDynamics),
}

impl MachineResult {
    /// The planar mechanism's part, where it is one.
    pub fn planar(&self) -> Option<&MachineDynamics> {
        match self {
            Self::Planar(m) => Some(m),
            Self::Spatial(_) => None,
        }
    }
}

impl crate::kind::JobResult for DynamicsResult {
    fn notes(&mut self) -> Option<&mut Notes> {
        Some(&mut self.notes)
    }
    fn rows(&self) -> Option<crate::kind::Rows> {
        let (field, count) = ("/samples".into(), self.samples.len());
        Some(crate::kind::Rows { field, count, also: "size-also-events" })
    }
}

impl From<DynamicsSolution> for DynamicsResult {
    fn from(s: DynamicsSolution) -> Self {
        let events: Vec<EventDto> = s
            .events
            .iter()
            .enumerate()
            .map(|(k, v)| EventDto {
                kind: match v.kind {
                    EventKind::Turn => "turn",
                    EventKind::Slip => "slip",
                    EventKind::Roll => "roll",
                    EventKind::Separation => "separation",
                    EventKind::End => "end",
                }
                .into(),
                joint: None,
                angle: v.angle,
                t: v.t,
                speed: v.speed,
                t_energy_form: s.energy_times.get(k).copied().flatten(),
            })
            .collect();
        let mut notes = Notes::default();
        notes.extend(s.stopped.as_ref().map(stopped));
        if s.unlisted_turns > 0 {
            let said = Msg::new("warning-dynamics-turns-unlisted").count("listed", MAX_TURN_EVENTS);
            notes.warn(said.count("more", usize::try_from(s.unlisted_turns).unwrap_or(usize::MAX)));
        }
        Self {
            samples: s
                .samples
                .iter()
                .map(|x| SampleDto {
                    t: x.t,
                    angle: x.angle,
                    speed: x.speed,
                    acceleration: x.acceleration,
                    energy_residual: x.energy_residual,
                })
                .collect(),
            end: events.iter().rev().find(|e| e.kind == "end").cloned(),
            events,
            stopped: s.stopped.as_ref().and_then(|s| match s {
                Stopped::ContactOpens { .. } => Some("separation".into()),
                Stopped::NotReached { .. } => Some("not_reached".into()),
                Stopped::Chatter { .. } => Some("chatter".into()),
                Stopped::Unexpected => None,
            }),
            energy_residual: s.energy_residual,
            accuracy: DynamicsAccuracy {
                energy_residual: s.energy_residual,
                energy_form_time_difference: s
                    .events
                    .iter()
                    .zip(&s.energy_times)
                    .filter_map(|(e, t)| t.map(|t| (e.t - t).abs()))
                    .reduce(f64::max),
                estimated_error: s.estimated_error,
                global_error: None,
                error_estimate: String::new(),
                steps: s.steps,
                function_evaluations: s.evaluations,
                constraint_drift: None,
                integrator: s.integrator.into(),
                stiff_at: s.stiff_at,
                integrator_replaced_at: None,
                energy_conserved: None,
                energy_held_steps: None,
                method: notes.say("/accuracy/method", method(&s)),
            },
            machine: None,
            notes,
        }
    }
}

/// The id of the warning that the end angle was not reached.
pub(super) const NOT_REACHED: &str = "warning-dynamics-not-reached";

/// Why the run stopped before its end, in words.
fn stopped(s: &Stopped) -> Msg {
    match s {
        Stopped::NotReached { angle, max_time } => Msg::new(NOT_REACHED)
            .with("angle", Msg::new("text-value-unit").num("value", *angle).arg("unit", "rad"))
            .with("time", Msg::new("text-value-unit").num("value", *max_time).arg("unit", "s")),
        Stopped::ContactOpens { joint, t, .. } if *t == 0.0 => {
            Msg::new("warning-dynamics-contact-open-at-start").arg("name", joint)
        }
        Stopped::ContactOpens { joint, t, .. } => {
            Msg::new("warning-dynamics-contact-opens").arg("name", joint).with("t", at_time(*t))
        }
        Stopped::Chatter { switches, t } => {
            Msg::new("warning-dynamics-chatter").count("count", *switches).with("t", at_time(*t))
        }
        Stopped::Unexpected => Msg::new("warning-dynamics-unexpected-guard"),
    }
}

/// An instant of the motion, to the microsecond.
pub(super) fn at_time(t: f64) -> Msg {
    Msg::new("warning-at-time").num("t", (t * 1e6).round() / 1e6)
}

/// The warning that the integrator asked met a singular position and the
/// run was made again with Dormand–Prince.
/// The pair is named as the request names it (`dop853`), in any language.
pub(super) fn replaced(s: &MechanismSolution, asked: Option<Integrator>) -> Option<Msg> {
    let t = s.integrator_replaced_at?;
    let asked = serde_json::to_value(IntegratorChoice::from(asked?)).ok()?;
    Some(Msg::new("warning-dynamics-integrator-replaced").arg("asked", asked.as_str()?).with("t", at_time(t)))
}

/// The warning of the singular positions a mechanism passed at close range:
/// kept on its branch while the energy balance holds; where it fails after
/// one (a sample's residual over max(100·tolerance, 1e-6), nothing slipping),
/// the mechanism may have folded into another assembly there (IFToMM A02's
/// chain of 10 from 0.5 rad/s lost half its energy at its 16th flat
/// position, the balance of every run that stays on its branch within 3e-8).
pub(super) fn singular(s: &MechanismSolution, tolerance: f64) -> Option<Msg> {
    let first = *s.near_singular.first()?;
    let slips = !s.slipping_from_start.is_empty() || s.solution.events.iter().any(|e| e.kind == EventKind::Slip);
    let bound = (100.0 * tolerance).max(1e-6);
    let off = s.solution.samples.iter().find(|x| x.energy_residual.abs() > bound).filter(|_| !slips);
    Some(match off {
        None => Msg::new("warning-dynamics-near-singular")
            .count("count", s.near_singular.len())
            .with("first", at_time(first)),
        Some(x) => {
            let passed = s.near_singular.iter().rev().find(|t| **t <= x.t).copied().unwrap_or(first);
            Msg::new("warning-dynamics-branch-left")
                .with("at", at_time(passed))
                .with("t", at_time(x.t))
                .num("residual", round_sig(x.energy_residual, 3))
                .num("bound", bound)
        }
    })
}

/// How a reduced machine's motion was integrated.
fn method(s: &DynamicsSolution) -> Msg {
    let work = if s.work_by_quadrature { "accuracy-work-quadrature" } else { "accuracy-work-power" };
    Msg::new("accuracy-dynamics")
        .with("integrator", integrator(s))
        .with("work", Msg::new(work))
        .with("repeated", repeated(s))
}

/// How a mechanism's motion was integrated.
pub(super) fn machine_method(s: &MechanismSolution) -> Msg {
    let form = match (s.sparse, s.sparse_hold) {
        (true, true) => "accuracy-form-sparse-held",
        (true, false) => "accuracy-form-sparse",
        _ => "accuracy-form-lu",
    };
    let energy = match s.energy_held_steps {
        0 => Msg::new("text-nothing"),
        held => Msg::new("accuracy-energy-held").count("held", held).count("steps", s.solution.steps),
    };
    Msg::new("accuracy-dynamics-mechanism")
        .with("integrator", integrator(&s.solution))
        .with("form", Msg::new(form))
        .with("energy", energy)
        .with("repeated", repeated(&s.solution))
}

/// The integrator's name, and why it was chosen when an explicit pair handed over.
fn integrator(s: &DynamicsSolution) -> Msg {
    match s.stiff_at {
        Some(t) => Msg::new("accuracy-integrator-stiff").arg("name", s.integrator.name()).fig("t", t),
        None => Msg::new("text-as-is").arg("why", s.integrator.name()),
    }
}

/// The end of the method's text where the run was made twice for its samples.
fn repeated(s: &DynamicsSolution) -> Msg {
    match s.repeated {
        true => Msg::new("accuracy-repeated").count("mib", KEPT_BYTES >> 20),
        false => Msg::new("text-nothing"),
    }
}

/// The intervals in which each rolling contact with friction slips, from
/// the run's events (a slip from the start counted from t = 0, one still
/// on at the end closed there): a warning per contact.
pub(super) fn slipping(s: &MechanismSolution, m: &Mechanism) -> Vec<Msg> {
    use std::collections::BTreeMap;
    let mut open: BTreeMap<usize, f64> = s.slipping_from_start.iter().map(|&j| (j, 0.0)).collect();
    let mut spans: BTreeMap<usize, Vec<(f64, f64)>> = BTreeMap::new();
    for e in &s.solution.events {
        match (e.kind, e.joint) {
            (EventKind::Slip, Some(j)) => {
                open.entry(j).or_insert(e.t);
            }
            (EventKind::Roll, Some(j)) => {
                if let Some(from) = open.remove(&j) {
                    spans.entry(j).or_default().push((from, e.t));
                }
            }
            (EventKind::End, _) => {
                for (j, from) in std::mem::take(&mut open) {
                    spans.entry(j).or_default().push((from, e.t));
                }
            }
            _ => {}
        }
    }
    let span = |&(a, b): &(f64, f64)| Msg::new("warning-span").with("from", at_time(a)).with("to", at_time(b));
    (spans.into_iter())
        .map(|(j, list)| {
            Msg::new("warning-contact-slipping")
                .arg("name", &m.joints[j].name)
                .list("at", list.iter().map(span).collect())
        })
        .collect()
}
