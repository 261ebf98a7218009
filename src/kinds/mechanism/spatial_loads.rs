//! The loads of a spatial mechanism: a force at a point along a direction
//! [x, y, z], a torque about an axis (its `direction`), each of a Function
//! of the first input's coordinate φ; springs and dampers between two
//! bodies' points. Each is read with its own fields only, every error at
//! its pointer.

use super::loads::has_fields;
use super::spatial::SpatialConverted;
use super::{LoadDto, LoadType, MAX_LOADS, MechanismDto, PointRef, body_id};
use crate::engine::spatial::{Load, LoadLaw};
use crate::i18n::Msg;
use crate::kind::quantity::Errors;
use crate::units::Dim;

/// Reads `list` (pointers under `at`) for the converted mechanism `c`.
pub fn spatial_loads(
    e: &mut Errors,
    list: &[LoadDto],
    (dto, c): (&MechanismDto, &SpatialConverted),
    period: f64,
    at: &str,
    variables: &[&str],
) -> Vec<LoadLaw> {
    if list.len() > MAX_LOADS {
        e.say(at, Msg::new("load-too-many").arg("max", MAX_LOADS));
        return Vec::new();
    }
    let read =
        |e: &mut Errors, (k, l): (usize, &LoadDto)| load(e, l, (dto, c), period, &format!("{at}/{k}"), variables);
    list.iter().enumerate().filter_map(|item| read(e, item)).collect()
}

fn load(
    e: &mut Errors,
    l: &LoadDto,
    (dto, c): (&MechanismDto, &SpatialConverted),
    period: f64,
    at: &str,
    variables: &[&str],
) -> Option<LoadLaw> {
    if !fields(e, l, at) {
        return None;
    }
    let names = &c.body_names;
    let moving = |e: &mut Errors, name: &str| match body_id(names, name) {
        Some(0) => e.refuse(&format!("{at}/body"), Msg::new("load-ground")),
        Some(b) => Some(b),
        None => e.refuse(&format!("{at}/body"), super::unknown_body(names, name)),
    };
    let direction = |e: &mut Errors| super::spatial::unit(e, l.direction.as_deref()?, &format!("{at}/direction"));
    match l.kind {
        LoadType::Force => {
            let body = moving(e, l.body.as_deref()?);
            let point = dto.point_in_space(e, l.at.as_ref()?, &format!("{at}/at"));
            let direction = direction(e);
            let magnitude =
                e.function_of(l.magnitude.as_ref()?, Dim::FORCE, period, &format!("{at}/magnitude"), variables);
            Some(LoadLaw::Force { body: body?, at: point?, direction: direction?, magnitude: magnitude? })
        }
        LoadType::Torque => {
            let body = moving(e, l.body.as_deref()?);
            let axis = direction(e);
            let value = e.function_of(l.value.as_ref()?, Dim::TORQUE, period, &format!("{at}/value"), variables);
            Some(LoadLaw::Torque { body: body?, axis: axis?, value: value? })
        }
        LoadType::Spring | LoadType::Damper => {
            let end = |e: &mut Errors, side: &str, v: &(String, PointRef)| {
                let unknown = super::unknown_body(names, &v.0);
                let b = body_id(names, &v.0).or_else(|| e.refuse(&format!("{at}/{side}/0"), unknown));
                let p = dto.point_in_space(e, &v.1, &format!("{at}/{side}/1"));
                Some((b?, p?))
            };
            let (a, b) = (end(e, "a", l.a.as_ref()?), end(e, "b", l.b.as_ref()?));
            let (k, length, c) = match l.kind {
                LoadType::Spring => {
                    let k = e.quantity(l.stiffness.as_ref()?, Dim::STIFFNESS, &format!("{at}/stiffness"));
                    let l0 = e.quantity(l.free_length.as_ref()?, Dim::LENGTH, &format!("{at}/free_length"));
                    (k?, l0?, 0.0)
                }
                _ => (0.0, 0.0, e.quantity(l.coefficient.as_ref()?, Dim::DAMPING, &format!("{at}/coefficient"))?),
            };
            let ((ba, pa), (bb, pb)) = (a?, b?);
            Some(LoadLaw::Fixed(Load::Spring { bodies: [ba, bb], at: [pa, pb], k, length, c }))
        }
    }
}

/// Whether the load has exactly the fields of its type in space (a
/// torque's `direction` is its axis).
fn fields(e: &mut Errors, l: &LoadDto, at: &str) -> bool {
    let wanted: &[&str] = match l.kind {
        LoadType::Force => &["body", "at", "direction", "magnitude"],
        LoadType::Torque => &["body", "direction", "value"],
        LoadType::Spring => &["a", "b", "stiffness", "free_length"],
        LoadType::Damper => &["a", "b", "coefficient"],
    };
    has_fields(e, l, wanted, at)
}
