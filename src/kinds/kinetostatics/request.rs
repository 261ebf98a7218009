//! `POST /v1/kinetostatics` request and its conversion into an engine problem.

use super::inputs::positions;
use super::located::Written;
use crate::engine::kinetostatics::{Load, Outputs};
use crate::engine::model::Mechanism;
use crate::engine::shaking::{Counterweight, Linkage, Unbalanceable, counterweights};
use crate::i18n::Msg;
use crate::kind::constants::{self, Constants};
use crate::kind::limits::Limits;
use crate::kind::problem::FieldError;
use crate::kind::quantity::{Errors, Quantity};
use crate::kinds::mechanism::track::{TrackDto, Tracked, resolve};
use crate::kinds::mechanism::{Assembled, Inputs, LoadDto, MechanismDto, convert_loads};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;
use utoipa::ToSchema;

/// A kinetostatic (inverse dynamics) problem: a mechanism, its driven input(s) and its loads.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({
    "mechanism": {
        "points": {"O": [0, 0], "A": [0.08, 0], "B": [0.37933, 0.02]},
        "bodies": [
            {"name": "crank", "mass": "2 kg", "inertia": 0.004, "cg": [0.02, 0]},
            {"name": "rod", "mass": 1.2, "inertia": 0.012, "cg": [0.1698, 0.006]},
            {"name": "piston", "mass": 0.9, "inertia": 0.001, "cg": "B"}
        ],
        "joints": [
            {"name": "O", "type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
            {"name": "A", "type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
            {"name": "B", "type": "revolute", "bodies": ["rod", "piston"], "at": "B"},
            {"name": "guide", "type": "prismatic", "bodies": ["ground", "piston"], "at": "B", "axis": [1, 0]}
        ],
        "gravity": [0, -9.81]
    },
    "input": {"joint": "O", "speed": "1500 rpm", "start": 0, "end": "360 deg", "steps": 36},
    "loads": [{"type": "force", "body": "piston", "at": "B", "direction": [1, 0],
               "magnitude": {"expr": "-8000*exp(3*(cos(phi - 0.35) - 1))"}}]
}))]
pub struct KinetostaticsRequest {
    /// Named values every expression of this request may read, e.g.
    /// `{"F": "1200 N", "r": "0.1 m"}`: each a number (SI) or a quantity,
    /// read in SI. A constant no expression reads is a warning.
    #[schema(value_type = Option<std::collections::BTreeMap<String, Quantity>>)]
    pub constants: Option<Constants>,
    pub mechanism: MechanismDto,
    /// One input, or a list of inputs (one per degree of freedom, sharing `steps`).
    #[schema(value_type = Inputs)]
    pub input: Inputs,
    #[schema(max_items = 500)]
    pub loads: Option<Vec<LoadDto>>,
    /// Compute only these (default: driving, reactions, kinematics and
    /// reduced; "condition" is asked for by name).
    pub outputs: Option<Vec<OutputKind>>,
    /// Points to follow: each step then has their `points` (position,
    /// velocity, acceleration). A name from `points` moves with the body its
    /// joints or centre of mass put it on; `{"name", "body", "at"}` is a
    /// point of one body (a pin in a slot must say which).
    #[schema(max_items = 100)]
    pub track: Option<Vec<TrackDto>>,
    /// Where each input's driving effort acts, one joint per input in
    /// order: a revolute joint (a torque) or a prismatic one (a force along
    /// its axis); `driving` is then the actuators' efforts. Default: each
    /// input's own joint; for an input on a point, a force on the point
    /// along its direction; on a body, a torque on the body.
    #[schema(max_items = 10)]
    pub actuators: Option<Vec<String>>,
    /// Counterweights for a four-bar (on the crank and the rocker: full
    /// force balance) or a slider-crank (on the crank: its rotating masses
    /// and a fraction of the reciprocating one); the result's
    /// `counterweights`, and with "shaking" each step's force once balanced.
    pub balance: Option<BalanceDto>,
}

/// Which links get counterweights, and how much of a slider-crank's
/// reciprocating mass they balance.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({"counterweights": ["crank", "rocker"]}))]
pub struct BalanceDto {
    /// The links pivoted to the frame that carry them, by name: a
    /// four-bar's crank and rocker, a slider-crank's crank.
    #[schema(min_items = 1, max_items = 2)]
    pub counterweights: Vec<String>,
    /// A slider-crank: the fraction f of the reciprocating mass (the slider
    /// and the rod's share at its pin) balanced, 0 to 1 (default 0: the
    /// rotating masses only): a number, or a quantity such as "50 %" or "0,5".
    #[schema(value_type = Option<Quantity>)]
    pub reciprocating_fraction: Option<Quantity>,
}

/// What to compute.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum OutputKind {
    Driving,
    Reactions,
    Kinematics,
    Reduced,
    /// `jacobian_condition` as the exact 2-norm condition number at every
    /// step (an SVD per step; not among the defaults).
    Condition,
    /// Each step's `energy`: kinetic per body and in total, potential of
    /// gravity and of the springs (not among the defaults).
    Energy,
    /// Each step's `points`: the motion of the points of `track` (reported
    /// whenever `track` is given).
    Points,
    /// Each step's `shaking`: the force and moment the moving links'
    /// inertia puts on the frame, and their largest in the summary (not
    /// among the defaults).
    Shaking,
}

/// The validated problem, ready for the engine.
pub struct Problem {
    pub mechanism: Mechanism,
    pub body_names: Vec<String>,
    pub loads: Vec<Load>,
    pub positions: Vec<Vec<[f64; 3]>>,
    pub outputs: Outputs,
    /// Per input: true for a coordinate in metres (a prismatic joint, a point).
    pub linear: Vec<bool>,
    /// Per input: the point it names, if any.
    pub input_points: Vec<Option<String>>,
    /// Per moving body: it has a centre of mass to report (a `cg`, or mass).
    pub centred: Vec<bool>,
    /// Each step's energies (the engine keeps the motion for them).
    pub energy: bool,
    /// The points followed at every step.
    pub tracked: Vec<Tracked>,
    /// The points assembled from the mechanism's dimensions.
    pub assembled: Option<Assembled>,
    /// Each step's bodies' motion is reported.
    pub kinematics: bool,
    /// Each step's shaking force and moment are reported.
    pub shaking: bool,
    /// The counterweights asked for, and the linkage they balance.
    pub balance: Option<(Linkage, Vec<Counterweight>)>,
    /// How the first input was written, for errors at a position.
    pub written: Written,
}

impl KinetostaticsRequest {
    pub fn to_problem(&self, limits: &Limits) -> Result<Problem, Vec<FieldError>> {
        let mut e = Errors::new(limits);
        constants::read(self.constants.as_ref(), &mut e);
        let Some((dto, warnings)) = self.mechanism.assembled(&mut e, "/mechanism") else { return Err(e.list) };
        let dto = dto.as_ref();
        let converted = dto.convert(&mut e, "/mechanism");
        let outputs = self.outputs.clone().unwrap_or_else(|| {
            vec![OutputKind::Driving, OutputKind::Reactions, OutputKind::Kinematics, OutputKind::Reduced]
        });
        let Some(c) = converted else { return Err(e.list) };
        let track = self.track.as_deref().unwrap_or_default();
        let tracked = resolve(dto, track, &c.body_names, &mut e, "/track");
        if outputs.contains(&OutputKind::Points) && track.is_empty() {
            e.say("/outputs", Msg::new("kinetostatics-points-track"));
        }
        let balance = self.balance.as_ref().and_then(|b| balance(b, &c.mechanism, &c.body_names, &mut e));
        let mut mechanism = c.mechanism;
        let inputs = match &self.input {
            Inputs::One(i) => vec![(**i).clone()],
            Inputs::Many(v) => v.clone(),
        };
        let many = matches!(self.input, Inputs::Many(_));
        let parts = (dto, &mechanism, &c.body_names[..]);
        let (drivers, positions, linear) = positions(&mut e, parts, &inputs, self.actuators.as_deref(), many);
        let written = Written::new(
            inputs.first(),
            if many { "/input/0".into() } else { "/input".into() },
            linear.first().copied().unwrap_or(false),
            &positions,
        );
        mechanism.drivers = drivers;
        let period = if linear.first().copied().unwrap_or(false) { 1.0 } else { 2.0 * PI };
        let loads = convert_loads(
            &mut e,
            self.loads.as_deref().unwrap_or_default(),
            dto,
            &c.body_names,
            period,
            "/loads",
            &["phi"],
        );
        if !e.list.is_empty() {
            return Err(e.list);
        }
        Ok(Problem {
            mechanism,
            body_names: c.body_names,
            loads,
            positions,
            outputs: Outputs {
                driving: outputs.contains(&OutputKind::Driving),
                reactions: outputs.contains(&OutputKind::Reactions),
                reduced: outputs.contains(&OutputKind::Reduced),
                kinematics: outputs.contains(&OutputKind::Kinematics)
                    || outputs.contains(&OutputKind::Energy)
                    || outputs.contains(&OutputKind::Shaking)
                    || !tracked.is_empty(),
                condition: outputs.contains(&OutputKind::Condition),
            },
            linear,
            input_points: inputs.iter().map(|i| i.point.clone()).collect(),
            centred: dto.bodies.iter().map(|b| b.cg.is_some()).collect(),
            energy: outputs.contains(&OutputKind::Energy),
            tracked,
            assembled: Assembled::of(&self.mechanism, dto, warnings),
            kinematics: outputs.contains(&OutputKind::Kinematics),
            shaking: outputs.contains(&OutputKind::Shaking),
            balance,
            written,
        })
    }
}

/// The counterweights `b` asks for on `m` (bodies named in `names`, the
/// ground first), or why not at `/balance/...`.
fn balance(b: &BalanceDto, m: &Mechanism, names: &[String], e: &mut Errors) -> Option<(Linkage, Vec<Counterweight>)> {
    let at = "/balance/reciprocating_fraction";
    let f = match &b.reciprocating_fraction {
        Some(q) => e.quantity(q, Dim::NONE, at)?,
        None => 0.0,
    };
    let fraction = (0.0..=1.0).contains(&f);
    if !fraction {
        e.say(at, Msg::new("balance-fraction").num("value", f));
    }
    let mut on = Vec::new();
    for (k, name) in b.counterweights.iter().enumerate() {
        match names.iter().skip(1).position(|n| n == name) {
            Some(i) if on.contains(&(i + 1)) => {
                e.say(&format!("/balance/counterweights/{k}"), Msg::new("balance-twice").arg("body", name));
            }
            Some(i) => on.push(i + 1),
            None => e.say(&format!("/balance/counterweights/{k}"), Msg::new("balance-unknown-body").arg("body", name)),
        }
    }
    if !e.list.is_empty() {
        return None;
    }
    match counterweights(m, &on, f.clamp(0.0, 1.0)) {
        Ok(found) => fraction.then_some(found),
        Err(Unbalanceable::NotALinkage) => e.refuse("/balance", Msg::new("balance-not-linkage")),
        Err(Unbalanceable::NotPivoted { at }) => e.refuse(
            &format!("/balance/counterweights/{at}"),
            Msg::new("balance-not-pivoted").arg("body", &b.counterweights[at]),
        ),
        Err(Unbalanceable::Missing { linkage, body }) => {
            let id = if linkage == Linkage::FourBar { "balance-missing" } else { "balance-missing-crank" };
            e.refuse("/balance/counterweights", Msg::new(id).arg("body", &names[body]))
        }
    }
}
