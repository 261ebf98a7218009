//! The `machine` form of `POST /v1/dynamics`: a planar mechanism whose input
//! joints are free, integrated in its own coordinates (any number of DOF).

use super::Initial;
use crate::engine::dynamics::mechanism::{MechanismSample, MechanismSolution};
use crate::engine::kinetostatics::Load;
use crate::engine::kinetostatics::Motion;
use crate::engine::model::{Driver, JointKind, Mechanism};
use crate::i18n::Msg;
use crate::kind::quantity::{Errors, FunctionDto, Quantity};
use crate::kinds::mechanism::motion::BodyPosition;
use crate::kinds::mechanism::track::{PointState, TrackDto, Tracked, resolve, states};
use crate::kinds::mechanism::{Assembled, MechanismDto, coordinate};
use crate::kinds::mechanism::{
    ContactDto, EnergyDto, InputDto, Inputs, LoadDto, Names, ReactionDto, Reactions, convert_loads,
};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::sync::Arc;
use utoipa::ToSchema;

/// A mechanism with free input joints, and its loads. A spatial one
/// (`"space": "spatial"`) has joints' rotations or slides for inputs, and
/// its result `machine` says `"space": "spatial"`, each body's motion and
/// each reaction as vectors.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct DynamicsMachine {
    pub mechanism: MechanismDto,
    /// The input coordinate(s), one per degree of freedom (a list for
    /// several): a revolute joint's relative angle, a prismatic joint's
    /// displacement, a point's displacement along a direction, a body's
    /// rotation (as in kinetostatics; m and m/s for the lengths). Each input's `start` and
    /// `speed` (a constant) are its state at t = 0 (default 0; `initial` may
    /// give the first input's instead); `reference` as in kinetostatics;
    /// `acceleration`, `end` and `steps` do not apply.
    pub input: Inputs,
    /// Loads as in kinetostatics; their Functions may read `phi` (the first
    /// input's angle reduced to the period), `omega` (its speed) and `t`.
    /// Joint friction is not supported in dynamics, but at a rolling contact
    /// (it rolls while |tangential| ≤ μ·normal, and slips otherwise).
    #[schema(max_items = 500)]
    pub loads: Option<Vec<LoadDto>>,
    /// Points to follow, as in kinetostatics: each sample then has their
    /// `points` (position, velocity, acceleration).
    #[schema(max_items = 100)]
    pub track: Option<Vec<TrackDto>>,
    /// Report the joint reactions at every sample (default true).
    pub reactions: Option<bool>,
    /// Hold the energy T + V to its initial value after every step (the
    /// velocities scaled onto it): a long conservative run's error then
    /// grows linearly with time instead of quadratically. Default: wherever
    /// every load has a potential (springs, constant forces and torques;
    /// gravity always has one);
    /// `false` integrates without it; `true` requires it.
    pub conserve_energy: Option<bool>,
}

/// The converted machine: model, loads, initial state, and what its result reports.
pub(super) struct Parts {
    pub mechanism: Mechanism,
    pub loads: Vec<Load>,
    pub initial: Vec<[f64; 2]>,
    pub report: Report,
}

/// What a machine's result says beside the engine's solution: the names,
/// where the dimensions put the points, the points followed.
pub(super) struct Report {
    pub joint_names: Vec<String>,
    pub body_names: Vec<String>,
    pub assembled: Option<Assembled>,
    pub tracked: Vec<Tracked>,
}

/// Refuses `conserve_energy: true` with a load that has no potential.
fn check_energy(e: &mut Errors, asked: Option<bool>, loads: &[Load]) {
    let Some(k) = loads.iter().position(|l| !l.has_potential()) else { return };
    if asked == Some(true) {
        let what = match loads[k] {
            Load::Force { .. } => "dynamics-varying-force",
            Load::Torque { .. } => "dynamics-varying-torque",
            _ => "dynamics-damper",
        };
        let msg = Msg::new("dynamics-conserve-energy").arg("load", k).with("what", Msg::new(what));
        e.say("/machine/conserve_energy", msg);
    }
}

impl DynamicsMachine {
    pub(super) fn convert(&self, e: &mut Errors, initial: Option<&Initial>, period: f64) -> Option<Parts> {
        let (dto, warnings) = self.mechanism.assembled(e, "/machine/mechanism")?;
        let dto = dto.as_ref();
        let assembled = Assembled::of(&self.mechanism, dto, warnings);
        let c = dto.convert(e, "/machine/mechanism")?;
        let mut mechanism = c.mechanism;
        for (k, j) in mechanism.joints.iter().enumerate() {
            let rolling = matches!(&j.kind, JointKind::Contact(c) if c.rolling);
            if j.friction.is_some() && !rolling {
                let id = match j.kind {
                    JointKind::Contact(_) => "dynamics-sliding-friction",
                    _ => "dynamics-joint-friction",
                };
                e.say(&format!("/machine/mechanism/joints/{k}/friction"), Msg::new(id));
            }
        }
        let (inputs, many) = match &self.input {
            Inputs::One(i) => (vec![i.as_ref().clone()], false),
            Inputs::Many(v) => (v.clone(), true),
        };
        if inputs.is_empty() || inputs.len() > 10 {
            e.say("/machine/input", Msg::new("input-count"));
        }
        let mut drivers = Vec::new();
        let mut states = Vec::new();
        for (k, input) in inputs.iter().enumerate() {
            let at = if many { format!("/machine/input/{k}") } else { "/machine/input".into() };
            let given = if k == 0 { initial } else { None };
            if let Some((driver, state)) = free_input(e, (dto, &mechanism, &c.body_names), input, given, &at) {
                drivers.push(driver);
                states.push(state);
            }
        }
        mechanism.drivers = drivers;
        let loads = self.loads.as_deref().unwrap_or_default();
        let loads = convert_loads(e, loads, dto, &c.body_names, period, "/machine/loads", &["phi", "omega", "t"]);
        if e.list.is_empty() {
            check_energy(e, self.conserve_energy, &loads);
        }
        let tracked = resolve(dto, self.track.as_deref().unwrap_or_default(), &c.body_names, e, "/machine/track");
        let joint_names = mechanism.joints.iter().map(|j| j.name.clone()).collect();
        let report = Report { joint_names, body_names: c.body_names, assembled, tracked };
        e.list.is_empty().then_some(Parts { mechanism, loads, initial: states, report })
    }
}

/// The driver and initial [coordinate, speed] of one free input: an angle
/// (a revolute joint, a body) or a length (a prismatic joint, a point).
fn free_input(
    e: &mut Errors,
    parts: (&MechanismDto, &Mechanism, &[String]),
    input: &InputDto,
    initial: Option<&Initial>,
    at: &str,
) -> Option<(Driver, [f64; 2])> {
    let coordinate = coordinate(e, parts, input, at);
    let state = input_state(e, input, initial, coordinate.is_some_and(|c| c.1), at);
    let (reference, state) = state?;
    Some((Driver { coordinate: coordinate?.0, reference, actuator: None }, state))
}

/// A free input's `reference` and its [coordinate, speed] at t = 0, a
/// length's in m and m/s (`initial` may give the first input's); the
/// fields of a prescribed motion refused.
pub(super) fn input_state(
    e: &mut Errors,
    input: &InputDto,
    initial: Option<&Initial>,
    length: bool,
    at: &str,
) -> Option<(f64, [f64; 2])> {
    let unused = [
        ("acceleration", input.acceleration.is_some()),
        ("end", input.end.is_some()),
        ("steps", input.steps.is_some()),
    ];
    for (name, _) in unused.iter().filter(|u| u.1) {
        e.say(&format!("{at}/{name}"), Msg::new("dynamics-not-applicable"));
    }
    let (dim, rate) = if length { (Dim::LENGTH, Dim::SPEED) } else { (Dim::ANGLE, Dim::ANGULAR_SPEED) };
    let value = |e: &mut Errors, q: &Quantity, at: &str| if length { e.quantity(q, dim, at) } else { e.angle(q, at) };
    let reference = input.reference.as_ref().map_or(Some(0.0), |q| value(e, q, &format!("{at}/reference")));
    let from_initial = initial.is_some_and(|i| i.angle.is_some() || i.speed.is_some());
    if from_initial && (input.start.is_some() || input.speed.is_some()) {
        e.say("/initial", Msg::new("dynamics-initial-once"));
    }
    let start = match (initial.and_then(|i| i.angle.as_ref()), &input.start) {
        (Some(q), _) => value(e, q, "/initial/angle"),
        (None, Some(q)) => value(e, q, &format!("{at}/start")),
        (None, None) => Some(0.0),
    };
    let speed = match (initial.and_then(|i| i.speed.as_ref()), &input.speed) {
        (Some(q), _) => e.quantity(q, rate, "/initial/speed"),
        (None, Some(FunctionDto::Constant(q))) => e.quantity(q, rate, &format!("{at}/speed")),
        (None, Some(FunctionDto::Spec(_))) => e.refuse(&format!("{at}/speed"), Msg::new("dynamics-speed-constant")),
        (None, None) => Some(0.0),
    };
    Some((reference?, [start?, speed?]))
}

/// One input's state at a sample.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct InputState {
    /// The input's coordinate (its `reference` plus its change from the
    /// drawing): rad, or m for a prismatic joint or a point (`input_units`).
    pub angle: f64,
    pub speed: f64,
    pub acceleration: f64,
}

/// The mechanism at one sample (the same instants as `samples`).
#[derive(Clone, Debug, Serialize, ToSchema)]
pub struct MachineSample {
    pub t: f64,
    /// Every input, in the order given.
    pub inputs: Vec<InputState>,
    /// Every moving body's position (the paths and drawings of the plots).
    pub bodies: Vec<BodyPosition>,
    /// Joint reactions (the force body `by` exerts on body `on`), when asked.
    #[schema(value_type = Vec<ReactionDto>)]
    pub reactions: Reactions,
    /// Largest |Φ| of the joint constraints at the sample, m or rad.
    pub constraint_residual: f64,
    pub energy: EnergyDto,
    /// The points of `track`, where given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub points: Option<Vec<PointState>>,
    /// Every contact joint's state, with the reactions.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contacts: Option<Vec<ContactDto>>,
}

/// What the mechanism form adds to a dynamics result.
#[derive(Clone, Debug, Serialize, ToSchema)]
pub struct MachineDynamics {
    /// Degrees of freedom at the start (one input each).
    pub dof: usize,
    /// Constraints that repeat others (their reactions are then not determinate).
    pub redundant_constraints: usize,
    /// Times (s) at which the integration met the joint Jacobian within 1e-5
    /// (relative singular value) of losing rank — a singular position, such
    /// as a parallelogram lying flat, passed at close range. There the motion
    /// along the fold was held (the mechanism stays on its branch) and the
    /// reactions of the joints involved are not determinate. Singular
    /// positions the steps passed over at a distance are not listed.
    pub near_singular: Vec<f64>,
    /// Each input's coordinate unit: "rad" (a revolute joint, a body) or
    /// "m" (a prismatic joint, a point); speeds and accelerations per second.
    pub input_units: Vec<String>,
    pub samples: Vec<MachineSample>,
    /// Where the points went, for a mechanism given by its `dimensions` (m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schema(value_type = Option<BTreeMap<String, Vec<f64>>>)]
    pub assembled_points: Option<BTreeMap<String, [f64; 2]>>,
}

impl MachineDynamics {
    pub(super) fn new(s: &MechanismSolution, m: &Mechanism, report: Report) -> Self {
        let names = Names::new(&report.joint_names, &report.body_names);
        let samples =
            s.details.iter().zip(&s.solution.samples).map(|(d, x)| sample(x.t, d, (&names, m, &report))).collect();
        Self {
            dof: s.mobility.dof,
            redundant_constraints: s.mobility.redundant_constraints,
            near_singular: s.near_singular.clone(),
            assembled_points: report.assembled.map(|a| a.points),
            input_units: m.drivers.iter().map(|d| if m.is_length(d.coordinate) { "m" } else { "rad" }.into()).collect(),
            samples,
        }
    }
}

/// The mechanism at time `t`, as a result says it.
pub(super) fn sample(
    t: f64,
    d: &MechanismSample,
    (names, m, report): (&Arc<Names>, &Mechanism, &Report),
) -> MachineSample {
    let (joint_names, body_names) = (&names.joints, &names.bodies);
    let points = |motion: &Option<Motion>| motion.as_ref().map(|k| states(m, &report.tracked, [&k.q, &k.qd, &k.qdd]));
    MachineSample {
        t,
        inputs: d
            .inputs
            .iter()
            .map(|[angle, speed, acceleration]| InputState {
                angle: *angle,
                speed: *speed,
                acceleration: *acceleration,
            })
            .collect(),
        bodies: d
            .poses
            .iter()
            .zip(body_names.iter().skip(1))
            .map(|(p, body)| BodyPosition { body: body.clone(), x: p[0], y: p[1], theta: p[2] })
            .collect(),
        reactions: Reactions::new(names, &d.reactions, &d.contacts, m),
        contacts: (!d.contacts.is_empty())
            .then(|| d.contacts.iter().map(|c| ContactDto::new(c, joint_names)).collect()),
        constraint_residual: d.constraint_residual,
        energy: EnergyDto::new(d.energy.clone(), body_names, &names.moving),
        points: points(&d.motion),
    }
}
