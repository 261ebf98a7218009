//! Loads of a mechanism: wire form and conversion into engine loads.

use super::{MechanismDto, PointRef, body_id};
use crate::engine::kinetostatics::Load;
use crate::i18n::Msg;
use crate::kind::quantity::{Errors, FunctionDto, Quantity};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// Most loads in one job.
pub const MAX_LOADS: usize = 500;

/// Load types.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum LoadType {
    Force,
    Torque,
    Spring,
    Damper,
}

/// A load. `force`: body, at, direction (fixed in the ground), magnitude (Function);
/// `torque`: body, value (Function); `spring`: a, b ([body, point]), stiffness,
/// free_length; `damper`: a, b, coefficient. Functions take `phi`, the first input's coordinate.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct LoadDto {
    #[serde(rename = "type")]
    pub kind: LoadType,
    pub body: Option<String>,
    #[schema(value_type = Option<PointRef>)]
    pub at: Option<PointRef>,
    /// [x, y]; in space [x, y, z], and a torque's axis.
    #[schema(min_items = 2, max_items = 3)]
    pub direction: Option<Vec<f64>>,
    #[schema(value_type = Option<FunctionDto>)]
    pub magnitude: Option<FunctionDto>,
    #[schema(value_type = Option<FunctionDto>)]
    pub value: Option<FunctionDto>,
    #[schema(value_type = Option<crate::kinds::mechanism::BodyPoint>)]
    pub a: Option<(String, PointRef)>,
    #[schema(value_type = Option<crate::kinds::mechanism::BodyPoint>)]
    pub b: Option<(String, PointRef)>,
    /// N/m
    #[schema(value_type = Option<Quantity>)]
    pub stiffness: Option<Quantity>,
    #[schema(value_type = Option<Quantity>)]
    pub free_length: Option<Quantity>,
    /// N·s/m
    #[schema(value_type = Option<Quantity>)]
    pub coefficient: Option<Quantity>,
}

/// Converts a list of loads (pointers under `at`, e.g. "/loads").
pub fn convert_loads(
    e: &mut Errors,
    list: &[LoadDto],
    mech: &MechanismDto,
    names: &[String],
    period: f64,
    at: &str,
    variables: &[&str],
) -> Vec<Load> {
    if list.len() > MAX_LOADS {
        e.say(at, Msg::new("load-too-many").arg("max", MAX_LOADS));
        return Vec::new();
    }
    list.iter()
        .enumerate()
        .filter_map(|(k, l)| load(e, l, mech, names, period, &format!("{at}/{k}"), variables))
        .collect()
}

fn point_of(e: &mut Errors, p: &PointRef, dto: &MechanismDto, at: &str) -> Option<[f64; 2]> {
    match p {
        PointRef::Coords(c) if c.iter().all(|v| v.is_finite()) => Some(*c),
        PointRef::Coords(_) => e.refuse(at, Msg::new("mechanism-coordinates")),
        PointRef::Space(_) => e.refuse(at, Msg::new("mechanism-spatial-point")),
        PointRef::Name(n) => match dto.points.as_ref().and_then(|ps| ps.get(n)) {
            Some(c) => Some(*c),
            None => e.refuse(at, Msg::new("mechanism-unknown-point").arg("name", n)),
        },
    }
}

fn moving_body(e: &mut Errors, names: &[String], name: &str, at: &str) -> Option<usize> {
    match body_id(names, name) {
        Some(0) => e.refuse(at, Msg::new("load-ground")),
        Some(b) => Some(b),
        None => e.refuse(at, super::unknown_body(names, name)),
    }
}

/// Builds one load, checking that it has exactly the fields of its type.
/// One load; its Functions' expressions may read `variables`.
fn load(
    e: &mut Errors,
    l: &LoadDto,
    mech: &MechanismDto,
    names: &[String],
    period: f64,
    at: &str,
    variables: &[&str],
) -> Option<Load> {
    let wanted: &[&str] = match l.kind {
        LoadType::Force => &["body", "at", "direction", "magnitude"],
        LoadType::Torque => &["body", "value"],
        LoadType::Spring => &["a", "b", "stiffness", "free_length"],
        LoadType::Damper => &["a", "b", "coefficient"],
    };
    if !has_fields(e, l, wanted, at) {
        return None;
    }
    let ends = |e: &mut Errors, side: &str, v: &(String, PointRef)| {
        let unknown = super::unknown_body(names, &v.0);
        let b = body_id(names, &v.0).or_else(|| e.refuse(&format!("{at}/{side}/0"), unknown));
        let p = point_of(e, &v.1, mech, &format!("{at}/{side}/1"));
        Some((b?, p?))
    };
    match l.kind {
        LoadType::Force => {
            let body = moving_body(e, names, l.body.as_deref()?, &format!("{at}/body"));
            let point = point_of(e, l.at.as_ref()?, mech, &format!("{at}/at"));
            let direction = match l.direction.as_deref() {
                Some([x, y]) if x.is_finite() && y.is_finite() && x.hypot(*y) > 0.0 => {
                    Some([x / x.hypot(*y), y / x.hypot(*y)])
                }
                Some([_, _, _]) => e.refuse(&format!("{at}/direction"), Msg::new("mechanism-vector-in-space")),
                _ => e.refuse(&format!("{at}/direction"), Msg::new("mechanism-vector")),
            };
            let magnitude =
                e.function_of(l.magnitude.as_ref()?, Dim::FORCE, period, &format!("{at}/magnitude"), variables);
            Some(Load::Force { body: body?, at: point?, direction: direction?, magnitude: magnitude? })
        }
        LoadType::Torque => {
            let body = moving_body(e, names, l.body.as_deref()?, &format!("{at}/body"));
            let value = e.function_of(l.value.as_ref()?, Dim::TORQUE, period, &format!("{at}/value"), variables);
            Some(Load::Torque { body: body?, value: value? })
        }
        LoadType::Spring => {
            let (a, b) = (ends(e, "a", l.a.as_ref()?), ends(e, "b", l.b.as_ref()?));
            let k = e.quantity(l.stiffness.as_ref()?, Dim::STIFFNESS, &format!("{at}/stiffness"));
            let l0 = e.quantity(l.free_length.as_ref()?, Dim::LENGTH, &format!("{at}/free_length"));
            Some(Load::Spring { a: a?, b: b?, stiffness: k?, free_length: l0? })
        }
        LoadType::Damper => {
            let (a, b) = (ends(e, "a", l.a.as_ref()?), ends(e, "b", l.b.as_ref()?));
            let c = e.quantity(l.coefficient.as_ref()?, Dim::DAMPING, &format!("{at}/coefficient"));
            Some(Load::Damper { a: a?, b: b?, coefficient: c? })
        }
    }
}

/// Whether the load has exactly the `wanted` fields; each missing one said
/// at the load, each extra one at its own pointer.
pub fn has_fields(e: &mut Errors, l: &LoadDto, wanted: &[&str], at: &str) -> bool {
    let present = [
        ("body", l.body.is_some()),
        ("at", l.at.is_some()),
        ("direction", l.direction.is_some()),
        ("magnitude", l.magnitude.is_some()),
        ("value", l.value.is_some()),
        ("a", l.a.is_some()),
        ("b", l.b.is_some()),
        ("stiffness", l.stiffness.is_some()),
        ("free_length", l.free_length.is_some()),
        ("coefficient", l.coefficient.is_some()),
    ];
    let before = e.list.len();
    for (name, given) in present {
        match (wanted.contains(&name), given) {
            (true, false) => {
                let kind = format!("{:?}", l.kind).to_lowercase();
                e.say(at, Msg::new("load-needs").arg("type", kind).arg("field", name))
            }
            (false, true) => e.say(&format!("{at}/{name}"), Msg::new("load-not-this-type")),
            _ => {}
        }
    }
    e.list.len() == before
}
