//! `POST /v1/kinetostatics` request and its conversion into an engine problem.

use super::located::Written;
use crate::engine::function::{Function, Side};
use crate::engine::kinetostatics::{Load, Outputs};
use crate::engine::model::{Driver, JointKind, Mechanism};
use crate::kind::constants::{self, Constants};
use crate::kind::limits::Limits;
use crate::kind::problem::FieldError;
use crate::kind::quantity::{Errors, Quantity};
use crate::kinds::mechanism::track::{TrackDto, Tracked, resolve};
use crate::kinds::mechanism::{InputDto, Inputs, LoadDto, MechanismDto, convert_loads};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::f64::consts::PI;
use utoipa::ToSchema;

const DEFAULT_STEPS: usize = 360;

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
}

/// Where a mechanism's dimensions put its points, and what they said.
pub struct Assembled {
    pub points: BTreeMap<String, [f64; 2]>,
    pub warnings: Vec<String>,
}

/// The validated problem, ready for the engine.
pub struct Problem {
    pub mechanism: Mechanism,
    pub body_names: Vec<String>,
    pub loads: Vec<Load>,
    pub positions: Vec<Vec<[f64; 3]>>,
    pub outputs: Outputs,
    /// Per input: true for a prismatic (linear) input.
    pub linear: Vec<bool>,
    /// Each step's energies (the engine keeps the motion for them).
    pub energy: bool,
    /// The points followed at every step.
    pub tracked: Vec<Tracked>,
    /// The points assembled from the mechanism's dimensions.
    pub assembled: Option<Assembled>,
    /// Each step's bodies' motion is reported.
    pub kinematics: bool,
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
            e.push("/outputs", "\"points\" follows the points of \"track\": give them");
        }
        let mut mechanism = c.mechanism;
        let inputs = match &self.input {
            Inputs::One(i) => vec![(**i).clone()],
            Inputs::Many(v) => v.clone(),
        };
        let many = matches!(self.input, Inputs::Many(_));
        let (drivers, positions, linear) = positions(&mut e, &mechanism, &inputs, many);
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
                    || !tracked.is_empty(),
                condition: outputs.contains(&OutputKind::Condition),
            },
            linear,
            energy: outputs.contains(&OutputKind::Energy),
            tracked,
            assembled: self
                .mechanism
                .dimensions
                .is_some()
                .then(|| Assembled { points: dto.points.clone().unwrap_or_default(), warnings }),
            kinematics: outputs.contains(&OutputKind::Kinematics),
            written,
        })
    }
}

/// Drivers and the positions (coordinate, speed, acceleration per input) of every step.
fn positions(
    e: &mut Errors,
    m: &Mechanism,
    inputs: &[InputDto],
    many: bool,
) -> (Vec<Driver>, Vec<Vec<[f64; 3]>>, Vec<bool>) {
    let mut drivers = Vec::new();
    let mut ranges = Vec::new();
    let mut linear = Vec::new();
    let steps = inputs.first().and_then(|i| i.steps).unwrap_or(DEFAULT_STEPS);
    if inputs.is_empty() || inputs.len() > 10 {
        e.push("/input", "give 1 to 10 inputs");
    }
    let max = e.limits.steps;
    if steps == 0 || steps > max {
        e.push(if many { "/input/0/steps" } else { "/input/steps" }, format!("must be 1 to {max}"));
    }
    for (k, input) in inputs.iter().enumerate() {
        let at = if many { format!("/input/{k}") } else { "/input".to_string() };
        if k > 0 && input.steps.is_some_and(|s| s != steps) {
            e.push(&format!("{at}/steps"), "all inputs share the steps of the first");
        }
        let Some(j) = m.joints.iter().position(|j| j.name == input.joint) else {
            e.push(&format!("{at}/joint"), format!("unknown joint '{}'", input.joint));
            continue;
        };
        let prismatic = match m.joints[j].kind {
            JointKind::Revolute => false,
            JointKind::Prismatic { .. } => true,
            _ => {
                e.push(&format!("{at}/joint"), "an input must be a revolute or prismatic joint");
                continue;
            }
        };
        if let Some((driver, range)) = input_range(e, input, j, prismatic, &at) {
            drivers.push(driver);
            ranges.push(range);
            linear.push(prismatic);
        }
    }
    // Only a valid count of steps is laid out (a count over the limit would not fit in memory).
    let valid = ranges.len() == inputs.len() && (1..=max).contains(&steps);
    let positions = match valid {
        true => (0..steps).map(|s| ranges.iter().map(|r: &Range| r.at(s as f64 / steps as f64)).collect()).collect(),
        false => Vec::new(),
    };
    (drivers, positions, linear)
}

struct Range {
    start: f64,
    end: f64,
    speed: Function,
    slope: Option<Function>,
    acceleration: Option<f64>,
}

impl Range {
    fn at(&self, fraction: f64) -> [f64; 3] {
        let x = self.start + fraction * (self.end - self.start);
        let w = self.speed.eval(x, Side::Right);
        let a = self.acceleration.unwrap_or_else(|| self.slope.as_ref().map_or(0.0, |s| w * s.eval(x, Side::Right)));
        [x, w, a]
    }
}

fn input_range(e: &mut Errors, input: &InputDto, joint: usize, prismatic: bool, at: &str) -> Option<(Driver, Range)> {
    let (coordinate, speed_dim, accel_dim) = if prismatic {
        (Dim::LENGTH, Dim::SPEED, Dim::ACCELERATION)
    } else {
        (Dim::ANGLE, Dim::ANGULAR_SPEED, Dim::ANGULAR_ACCELERATION)
    };
    let value = |e: &mut Errors, q: &Option<Quantity>, name: &str| match q {
        None => Some(None),
        Some(q) if !prismatic => e.angle(q, &format!("{at}/{name}")).map(Some),
        Some(q) => e.quantity(q, coordinate, &format!("{at}/{name}")).map(Some),
    };
    let start = value(e, &input.start, "start")?.unwrap_or(0.0);
    let end = match value(e, &input.end, "end")? {
        Some(v) => v,
        None if !prismatic => start + 2.0 * PI,
        None => return e.fail(at, "a prismatic input needs \"end\""),
    };
    let reference = value(e, &input.reference, "reference")?.unwrap_or(0.0);
    let period = if prismatic { (end - start).abs().max(f64::MIN_POSITIVE) } else { 2.0 * PI };
    let Some(speed) = &input.speed else { return e.fail(at, "\"speed\" is required") };
    let speed = e.function(speed, speed_dim, period, &format!("{at}/speed"))?;
    let acceleration = match &input.acceleration {
        Some(q) => Some(e.quantity(q, accel_dim, &format!("{at}/acceleration"))?),
        None => None,
    };
    let slope = speed.constant().is_none().then(|| speed.derivative());
    Some((Driver { joint, reference }, Range { start, end, speed, slope, acceleration }))
}
