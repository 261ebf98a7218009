//! The driven inputs of a mechanism (kinetostatics, a flywheel's or a
//! dynamics job's `machine`), and the parts of a flywheel's machine.

use super::loads::{LoadDto, convert_loads};
use super::track::body_of;
use super::{Coords, JointType, MechanismDto, PointRef, body_id};
use crate::engine::kinetostatics::Load;
use crate::engine::model::{Coordinate, Driver, JointKind, Mechanism};
use crate::engine::spatial;
use crate::i18n::Msg;
use crate::kind::quantity::{Errors, FunctionDto, Quantity};
use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::{Deserialize, Serialize};
use std::fmt;
use utoipa::openapi::schema::{ArrayBuilder, OneOfBuilder, Schema};
use utoipa::openapi::{Ref, RefOr};
use utoipa::{PartialSchema, ToSchema};

/// An input coordinate and its range: a driven joint, or where the
/// statement puts the motion (a point along a direction, a body's rotation).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct InputDto {
    /// A revolute (crank) or prismatic (linear actuator) joint: its relative
    /// rotation or displacement along the axis. Or a contact joint that
    /// carries a point along a curve (a ring on a rim): the arc length
    /// along its first curve, growing the way the curve runs — counter-
    /// clockwise round a circle or a polar curve (growing ψ), along a
    /// line's direction, from a spline's first point to its last — so that
    /// a ring at the top of a rim moving to the right has a negative speed.
    #[schema(max_length = 100)]
    pub joint: Option<String>,
    /// Instead of a joint: a point of `points` whose displacement along
    /// `direction` (a fixed direction of the ground) is the coordinate, m.
    #[schema(max_length = 100)]
    pub point: Option<String>,
    /// With `point`: the direction [x, y] of its motion (any length).
    #[schema(value_type = Option<Coords>)]
    pub direction: Option<[f64; 2]>,
    /// With `point`: the body it belongs to, where several hold it (a pin
    /// in a slot). Alone: the body whose absolute rotation is the coordinate.
    #[schema(max_length = 100)]
    pub body: Option<String>,
    /// Speed (rad/s or m/s), or a Function of the coordinate (a motion law).
    /// Required for kinetostatics; a flywheel's machine runs at its mean speed.
    #[schema(value_type = Option<FunctionDto>)]
    pub speed: Option<FunctionDto>,
    /// Acceleration (rad/s² or m/s²); default 0, or ω·dω/dq for a motion law.
    #[schema(value_type = Option<Quantity>)]
    pub acceleration: Option<Quantity>,
    /// First coordinate (default 0): an angle for a revolute joint or a
    /// body, the second body's displacement along the axis in metres for a
    /// prismatic one, the point's along `direction` (a bare number is SI:
    /// rad or m). Coordinates count from the drawn configuration plus `reference`.
    #[schema(value_type = Option<Quantity>)]
    pub start: Option<Quantity>,
    /// End of the range, excluded (default start + 2π for a revolute joint).
    #[schema(value_type = Option<Quantity>)]
    pub end: Option<Quantity>,
    /// Number of positions start + k·(end − start)/steps, k = 0..steps−1 (default 360).
    #[schema(minimum = 1, maximum = 100000)]
    pub steps: Option<usize>,
    /// Coordinate of the drawn configuration (default 0).
    #[schema(value_type = Option<Quantity>)]
    pub reference: Option<Quantity>,
    /// In space: which of the joint's coordinates, `rotation` (about its
    /// axis) or `slide` (along it); a cylindrical joint has both (default:
    /// a revolute's rotation, a prismatic's slide).
    pub coordinate: Option<InputCoordinate>,
}

/// A spatial joint's coordinate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum InputCoordinate {
    Rotation,
    Slide,
}

/// One input or several.
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
pub enum Inputs {
    One(Box<InputDto>),
    Many(Vec<InputDto>),
}

struct InputsVisitor;

impl<'de> Visitor<'de> for InputsVisitor {
    type Value = Inputs;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("json-expect-inputs")
    }
    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Inputs, A::Error> {
        InputDto::deserialize(de::value::MapAccessDeserializer::new(map)).map(|i| Inputs::One(Box::new(i)))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Inputs, A::Error> {
        Vec::<InputDto>::deserialize(de::value::SeqAccessDeserializer::new(seq)).map(Inputs::Many)
    }
}

impl<'de> Deserialize<'de> for Inputs {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(InputsVisitor)
    }
}

impl PartialSchema for Inputs {
    fn schema() -> RefOr<Schema> {
        let one = || RefOr::Ref(Ref::from_schema_name("InputDto"));
        OneOfBuilder::new()
            .item(one())
            .item(ArrayBuilder::new().items(one()).min_items(Some(1)).max_items(Some(10)))
            .into()
    }
}
impl ToSchema for Inputs {
    fn schemas(schemas: &mut Vec<(String, RefOr<Schema>)>) {
        schemas.push(("InputDto".into(), InputDto::schema()));
        <InputDto as ToSchema>::schemas(schemas);
    }
}

/// What an input names, resolved (pointers under `at`): its coordinate, and
/// whether that is a length (a prismatic joint, a point) or an angle.
pub fn coordinate(
    e: &mut Errors,
    (dto, m, names): (&MechanismDto, &Mechanism, &[String]),
    input: &InputDto,
    at: &str,
) -> Option<(Coordinate, bool)> {
    if input.coordinate.is_some() {
        e.say(&format!("{at}/coordinate"), Msg::new("input-coordinate-planar"));
    }
    let moving = |e: &mut Errors, name: &str, ptr: &str| match body_id(names, name) {
        Some(0) => e.refuse(ptr, Msg::new("input-ground")),
        Some(b) => Some(b),
        None => e.refuse(ptr, super::unknown_body(names, name)),
    };
    match (&input.joint, &input.point, &input.body) {
        (Some(joint), None, None) => {
            let Some(k) = m.joints.iter().position(|j| &j.name == joint) else {
                return e.refuse(&format!("{at}/joint"), Msg::new("mechanism-unknown-joint").arg("name", joint));
            };
            match m.joints[k].kind {
                JointKind::Revolute => Some((Coordinate::Joint(k), false)),
                JointKind::Prismatic { .. } => Some((Coordinate::Joint(k), true)),
                // The arc length run along its first curve (a ring driven along a rim).
                JointKind::Contact(ref c) if c.measured_side().is_some() => Some((Coordinate::Joint(k), true)),
                _ => e.refuse(&format!("{at}/joint"), Msg::new("input-joint-kind")),
            }
        }
        (None, Some(point), body) => {
            let direction = unit_direction(e, input.direction, &format!("{at}/direction"));
            let Some(drawn) = dto.points.as_ref().and_then(|p| p.get(point).copied()) else {
                return e.refuse(&format!("{at}/point"), Msg::new("mechanism-unknown-point").arg("name", point));
            };
            let body = match body {
                Some(b) => moving(e, b, &format!("{at}/body")),
                None => body_of(dto, point, names, e, &format!("{at}/point")),
            };
            if body.is_some_and(|b| b == 0 || pinned_to_ground(dto, point, &names[b])) {
                return e.refuse(&format!("{at}/point"), Msg::new("input-on-ground").arg("point", point));
            }
            Some((Coordinate::Point { body: body?, at: drawn, direction: direction? }, true))
        }
        (None, None, Some(body)) => {
            if input.direction.is_some() {
                e.say(&format!("{at}/direction"), Msg::new("input-direction-of-point"));
            }
            Some((Coordinate::Body(moving(e, body, &format!("{at}/body"))?), false))
        }
        (None, None, None) => e.refuse(at, Msg::new("input-none")),
        _ => e.refuse(at, Msg::new("input-one-of")),
    }
}

/// Point `point` of `body` is pinned to the ground there (a revolute joint).
fn pinned_to_ground(dto: &MechanismDto, point: &str, body: &str) -> bool {
    dto.joints.iter().any(|j| {
        matches!(j.kind, JointType::Revolute)
            && matches!(&j.at, Some(PointRef::Name(n)) if n == point)
            && j.bodies.iter().any(|b| super::is_ground(b))
            && j.bodies.iter().any(|b| b == body)
    })
}

/// A direction's unit vector (pointer `at`).
fn unit_direction(e: &mut Errors, direction: Option<[f64; 2]>, at: &str) -> Option<[f64; 2]> {
    let Some([x, y]) = direction else { return e.refuse(at, Msg::new("input-needs-direction")) };
    let length = x.hypot(y);
    match length.is_finite() && length > 0.0 {
        true => Some([x / length, y / length]),
        false => e.refuse(at, Msg::new("input-direction")),
    }
}

/// The mechanism, its loads and a revolute driver for a flywheel's `machine`
/// (pointers under `at`).
pub fn machine_parts(
    e: &mut Errors,
    mech: &MechanismDto,
    input: &InputDto,
    loads: &[LoadDto],
    period: f64,
    at: &str,
) -> Option<(Mechanism, Vec<Load>)> {
    let (mech, _) = mech.assembled(e, &format!("{at}/mechanism"))?;
    let mech = mech.as_ref();
    let c = mech.convert(e, &format!("{at}/mechanism"))?;
    let mut mechanism = c.mechanism;
    if input.point.is_some() || input.body.is_some() {
        e.say(&format!("{at}/input"), Msg::new("input-flywheel-shaft"));
    }
    let shaft = input.joint.as_deref().unwrap_or_default();
    let joint = match mechanism.joints.iter().position(|j| j.name == shaft) {
        Some(j) if mechanism.joints[j].kind == JointKind::Revolute => Some(j),
        Some(_) => e.refuse(&format!("{at}/input/joint"), Msg::new("input-shaft-revolute")),
        None if input.joint.is_none() => e.refuse(&format!("{at}/input/joint"), Msg::new("input-name-shaft")),
        None => e.refuse(&format!("{at}/input/joint"), Msg::new("mechanism-unknown-joint").arg("name", shaft)),
    };
    let reference = match &input.reference {
        Some(q) => e.angle(q, &format!("{at}/input/reference")),
        None => Some(0.0),
    };
    let loads = convert_loads(e, loads, mech, &c.body_names, period, &format!("{at}/loads"), &["phi"]);
    mechanism.drivers = vec![Driver::joint(joint?, reference?)];
    Some((mechanism, loads))
}

/// A flywheel's machine in space: the mechanism with its shaft (a joint's
/// rotation) as its input, the loads (Functions of φ) and φ as drawn (the
/// input's `reference`), every error under `at`.
pub fn spatial_machine_parts(
    e: &mut Errors,
    mech: &MechanismDto,
    input: &InputDto,
    loads: &[LoadDto],
    period: f64,
    at: &str,
) -> Option<(spatial::Mechanism, Vec<spatial::LoadLaw>, f64)> {
    let c = mech.spatial(e, &format!("{at}/mechanism"))?;
    let shaft = super::spatial::joint_coordinate(e, &c.mechanism, input, &format!("{at}/input"));
    let shaft = match shaft {
        Some(s) if s.coordinate == spatial::Coordinate::Slide => {
            e.refuse(&format!("{at}/input/joint"), Msg::new("input-shaft-rotation"))
        }
        s => s,
    };
    let reference = match &input.reference {
        Some(q) => e.angle(q, &format!("{at}/input/reference")),
        None => Some(0.0),
    };
    let loads = super::spatial_loads::spatial_loads(e, loads, (mech, &c), period, &format!("{at}/loads"), &["phi"]);
    Some((spatial::Mechanism { inputs: vec![shaft?], ..c.mechanism }, loads, reference?))
}
