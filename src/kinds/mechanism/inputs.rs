//! The driven inputs of a mechanism (kinetostatics, a flywheel's or a
//! dynamics job's `machine`), and the parts of a flywheel's machine.

use super::MechanismDto;
use super::loads::{LoadDto, convert_loads};
use crate::engine::kinetostatics::Load;
use crate::engine::model::{Driver, JointKind, Mechanism};
use crate::kind::quantity::{Errors, FunctionDto, Quantity};
use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::{Deserialize, Serialize};
use std::fmt;
use utoipa::openapi::schema::{ArrayBuilder, OneOfBuilder, Schema};
use utoipa::openapi::{Ref, RefOr};
use utoipa::{PartialSchema, ToSchema};

/// A driven joint and the range of its coordinate.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct InputDto {
    /// A revolute (crank) or prismatic (linear actuator) joint.
    pub joint: String,
    /// Speed (rad/s or m/s), or a Function of the coordinate (a motion law).
    /// Required for kinetostatics; a flywheel's machine runs at its mean speed.
    #[schema(value_type = Option<FunctionDto>)]
    pub speed: Option<FunctionDto>,
    /// Acceleration (rad/s² or m/s²); default 0, or ω·dω/dq for a motion law.
    #[schema(value_type = Option<Quantity>)]
    pub acceleration: Option<Quantity>,
    /// First coordinate (default 0): an angle for a revolute joint, the
    /// second body's displacement along the axis in metres for a prismatic
    /// one (a bare number is SI: rad or m).
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
        f.write_str("an input object or a list of them")
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
    let joint = match mechanism.joints.iter().position(|j| j.name == input.joint) {
        Some(j) if mechanism.joints[j].kind == JointKind::Revolute => Some(j),
        Some(_) => e.fail(&format!("{at}/input/joint"), "the flywheel's shaft must be a revolute joint"),
        None => e.fail(&format!("{at}/input/joint"), format!("unknown joint '{}'", input.joint)),
    };
    let reference = match &input.reference {
        Some(q) => e.angle(q, &format!("{at}/input/reference")),
        None => Some(0.0),
    };
    let loads = convert_loads(e, loads, mech, &c.body_names, period, &format!("{at}/loads"), &["phi"]);
    mechanism.drivers = vec![Driver { joint: joint?, reference: reference? }];
    Some((mechanism, loads))
}
