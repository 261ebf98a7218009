//! The inputs of a kinetostatics request: each one's coordinate (a joint,
//! a point along a direction, a body's rotation) and range, its actuator,
//! and the positions of every step.

use crate::engine::function::{Function, Side};
use crate::engine::model::{Driver, JointKind, Mechanism};
use crate::engine::spatial;
use crate::i18n::Msg;
use crate::kind::quantity::{Errors, Quantity};
use crate::kinds::mechanism::spatial::joint_coordinate;
use crate::kinds::mechanism::{InputDto, MechanismDto, coordinate};
use crate::units::Dim;
use std::f64::consts::PI;

const DEFAULT_STEPS: usize = 360;

/// Drivers and the positions (coordinate, speed, acceleration per input) of
/// every step, and per input whether its coordinate is a length.
pub fn positions(
    e: &mut Errors,
    parts @ (_, m, _): (&MechanismDto, &Mechanism, &[String]),
    inputs: &[InputDto],
    actuators: Option<&[String]>,
    many: bool,
) -> (Vec<Driver>, Vec<Vec<[f64; 3]>>, Vec<bool>) {
    let mut drivers = Vec::new();
    let mut ranges = Vec::new();
    let mut linear = Vec::new();
    let (steps, max) = counted(e, inputs, many);
    if let Some(a) = actuators.filter(|a| a.len() != inputs.len()) {
        e.say("/actuators", Msg::new("input-actuators").count("inputs", inputs.len()).count("actuators", a.len()));
    }
    for (k, input) in inputs.iter().enumerate() {
        let at = if many { format!("/input/{k}") } else { "/input".to_string() };
        if k > 0 && input.steps.is_some_and(|s| s != steps) {
            e.say(&format!("{at}/steps"), Msg::new("input-same-steps"));
        }
        let Some((coordinate, length)) = coordinate(e, parts, input, &at) else { continue };
        let named = actuators.filter(|a| a.len() == inputs.len()).map(|a| (a[k].as_str(), format!("/actuators/{k}")));
        let actuator = named.and_then(|named| actuator(e, m, named));
        if let Some(a) = actuator.filter(|a| drivers.iter().any(|d: &Driver| d.actuator == Some(*a))) {
            let name = &m.joints[a].name;
            e.say(&format!("/actuators/{k}"), Msg::new("input-own-actuator").arg("name", name));
        }
        if let Some((reference, range)) = input_range(e, input, length, &at) {
            drivers.push(Driver { coordinate, reference, actuator });
            ranges.push(range);
            linear.push(length);
        }
    }
    // Only a valid count of steps is laid out (a count over the limit would not fit in memory).
    let valid = ranges.len() == inputs.len() && (1..=max).contains(&steps);
    let positions = if valid { laid_out(e, &ranges, steps) } else { Vec::new() };
    (drivers, positions, linear)
}

/// The inputs at each of `steps` positions, the budget read every 256 (an
/// input's speed may be an expression to evaluate at each): past it, none
/// and an error, which the budget's 422 replaces ([`crate::kind::compute`]).
fn laid_out(e: &mut Errors, ranges: &[Range], steps: usize) -> Vec<Vec<[f64; 3]>> {
    let deadline = e.limits.deadline();
    let mut positions = Vec::with_capacity(steps);
    for s in 0..steps {
        if s % 256 == 0 && deadline.expired() {
            e.say("/input", Msg::new("progress-reading"));
            return Vec::new();
        }
        positions.push(ranges.iter().map(|r| r.at(s as f64 / steps as f64)).collect());
    }
    positions
}

/// The joint named where an input's effort acts: a revolute or prismatic joint.
fn actuator(e: &mut Errors, m: &Mechanism, (name, at): (&str, String)) -> Option<usize> {
    match m.joints.iter().position(|j| j.name == name) {
        Some(k) if matches!(m.joints[k].kind, JointKind::Revolute | JointKind::Prismatic { .. }) => Some(k),
        Some(_) => e.refuse(&at, Msg::new("input-actuator-kind")),
        None => e.refuse(&at, Msg::new("mechanism-unknown-joint").arg("name", name)),
    }
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

/// An input's reference and range (a length or an angle), pointers under `at`.
fn input_range(e: &mut Errors, input: &InputDto, prismatic: bool, at: &str) -> Option<(f64, Range)> {
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
        // One position: where it ends does not matter.
        None if input.steps == Some(1) => start,
        None => return e.refuse(at, Msg::new("input-needs-end")),
    };
    let reference = value(e, &input.reference, "reference")?.unwrap_or(0.0);
    let period = if prismatic { (end - start).abs().max(f64::MIN_POSITIVE) } else { 2.0 * PI };
    let Some(speed) = &input.speed else { return e.refuse(at, Msg::new("input-speed")) };
    let speed = e.function(speed, speed_dim, period, &format!("{at}/speed"))?;
    let acceleration = match &input.acceleration {
        Some(q) => Some(e.quantity(q, accel_dim, &format!("{at}/acceleration"))?),
        None => None,
    };
    e.differentiable(&speed, 1, &format!("{at}/speed"))?;
    let slope = speed.constant().is_none().then(|| speed.derivative());
    Some((reference, Range { start, end, speed, slope, acceleration }))
}

/// A spatial mechanism's inputs, each a joint's coordinate (a revolute's
/// rotation, a prismatic's slide, a cylindrical's `coordinate`, a
/// spherical's rotation about its `axis`) with its value as drawn, and the
/// positions of every step as the request counts them; per input whether
/// its coordinate is a length.
pub fn spatial(
    e: &mut Errors,
    m: &spatial::Mechanism,
    inputs: &[InputDto],
    many: bool,
) -> (Vec<Drawn>, Vec<Vec<[f64; 3]>>, Vec<bool>) {
    let (steps, max) = counted(e, inputs, many);
    let (mut chosen, mut ranges, mut linear) = (Vec::new(), Vec::new(), Vec::new());
    for (k, input) in inputs.iter().enumerate() {
        let at = if many { format!("/input/{k}") } else { "/input".to_string() };
        if k > 0 && input.steps.is_some_and(|s| s != steps) {
            e.say(&format!("{at}/steps"), Msg::new("input-same-steps"));
        }
        let Some(picked) = joint_coordinate(e, m, input, &at) else { continue };
        let length = picked.coordinate == spatial::Coordinate::Slide;
        if let Some((reference, range)) = input_range(e, input, length, &at) {
            chosen.push(Drawn { input: picked, reference });
            ranges.push(range);
            linear.push(length);
        }
    }
    let valid = ranges.len() == inputs.len() && (1..=max).contains(&steps);
    let positions = if valid { laid_out(e, &ranges, steps) } else { Vec::new() };
    (chosen, positions, linear)
}

/// A spatial input and its value as drawn (its `reference`): the engine
/// counts it from the drawing, the request and the result from the
/// reference.
pub struct Drawn {
    pub input: spatial::Input,
    pub reference: f64,
}

/// The steps the inputs share and the most allowed, each count checked.
fn counted(e: &mut Errors, inputs: &[InputDto], many: bool) -> (usize, usize) {
    let steps = inputs.first().and_then(|i| i.steps).unwrap_or(DEFAULT_STEPS);
    if inputs.is_empty() || inputs.len() > 10 {
        e.say("/input", Msg::new("input-count"));
    }
    let max = e.limits.steps;
    if steps == 0 || steps > max {
        e.say(if many { "/input/0/steps" } else { "/input/steps" }, Msg::new("input-steps").arg("max", max));
    }
    (steps, max)
}
