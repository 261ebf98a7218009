//! A joint's own fields read against its type: the kind of a lower pair
//! or a gear, its friction and a guide's length, and the fields that
//! belong to another type.

use super::{JointDto, JointType};
use crate::engine::model::{Friction, Guide, JointKind};
use crate::i18n::Msg;
use crate::kind::quantity::Errors;
use crate::units::Dim;

/// A prismatic joint's guide (`length`, on the first body) or block
/// (`slider_length`, on the second), its length > 0, checked against its type.
pub fn guide_length(e: &mut Errors, j: &JointDto, at: &str) -> Option<Guide> {
    let (field, length, guide): (_, _, fn(f64) -> Guide) = match (&j.length, &j.slider_length) {
        (Some(_), Some(_)) => return e.refuse(&format!("{at}/slider_length"), Msg::new("joint-length-one")),
        (Some(l), None) => ("length", l, Guide::Fixed),
        (None, Some(l)) => ("slider_length", l, Guide::Block),
        (None, None) => return None,
    };
    let at = format!("{at}/{field}");
    match j.kind {
        JointType::Prismatic => e.positive(length, Dim::LENGTH, &at).map(guide),
        _ => e.refuse(&at, Msg::new("joint-length-prismatic")),
    }
}

/// The joint's friction, checked against its type.
pub fn friction(e: &mut Errors, j: &JointDto, at: &str) -> Option<Friction> {
    let f = j.friction.as_ref()?;
    let at = format!("{at}/friction");
    if !(f.mu.is_finite() && f.mu >= 0.0) {
        return e.refuse(&format!("{at}/mu"), Msg::new("joint-mu"));
    }
    match (j.kind, &f.radius) {
        (JointType::Revolute, Some(r)) => {
            e.positive(r, Dim::LENGTH, &format!("{at}/radius")).map(|radius| Friction { mu: f.mu, radius })
        }
        (JointType::Revolute, None) => e.refuse(&at, Msg::new("joint-friction-radius")),
        (JointType::Prismatic | JointType::PinSlot | JointType::Contact, None) => {
            Some(Friction { mu: f.mu, radius: 0.0 })
        }
        (JointType::Prismatic | JointType::PinSlot | JointType::Contact, Some(_)) => {
            e.refuse(&format!("{at}/radius"), Msg::new("joint-radius-revolute"))
        }
        (JointType::Gear, _) => e.refuse(&at, Msg::new("joint-gear-friction")),
        (JointType::Cylindrical | JointType::Spherical | JointType::Universal | JointType::SphereInCylinder, _) => {
            e.refuse(&at, Msg::new("joint-spatial-friction"))
        }
    }
}

fn unit_axis(e: &mut Errors, axis: Option<&[f64]>, at: &str) -> Option<[f64; 2]> {
    match axis {
        Some(v) => unit(e, v, &format!("{at}/axis")),
        None => e.refuse(at, Msg::new("joint-axis")),
    }
}

/// A unit vector from a finite, non-zero [x, y] (at pointer `at`).
pub fn unit(e: &mut Errors, v: &[f64], at: &str) -> Option<[f64; 2]> {
    match v {
        [x, y] if x.is_finite() && y.is_finite() && x.hypot(*y) > 0.0 => {
            let n = x.hypot(*y);
            Some([x / n, y / n])
        }
        [_, _, _] => e.refuse(at, Msg::new("mechanism-vector-in-space")),
        _ => e.refuse(at, Msg::new("mechanism-vector")),
    }
}

/// `curves` and `rolling` belong to a contact joint only.
pub fn not_for_others(e: &mut Errors, j: &JointDto, at: &str) {
    if j.kind != JointType::Contact {
        for (field, given) in [("curves", j.curves.is_some()), ("rolling", j.rolling.is_some())] {
            if given {
                e.say(&format!("{at}/{field}"), Msg::new("joint-contact-only"));
            }
        }
    }
}

pub fn joint_kind(e: &mut Errors, j: &JointDto, names: &[String], at: &str) -> Option<JointKind> {
    match j.kind {
        JointType::Contact => None,
        JointType::Cylindrical | JointType::Spherical | JointType::Universal | JointType::SphereInCylinder => {
            e.refuse(&format!("{at}/type"), Msg::new("joint-spatial-type"))
        }
        JointType::Revolute => Some(JointKind::Revolute),
        JointType::Prismatic => unit_axis(e, j.axis.as_deref(), at).map(|axis| JointKind::Prismatic { axis }),
        JointType::PinSlot => unit_axis(e, j.axis.as_deref(), at).map(|axis| JointKind::PinSlot { axis }),
        JointType::Gear => {
            let carrier = match &j.carrier {
                None => Some(0),
                Some(c) => match super::body_id(names, c) {
                    Some(i) => Some(i),
                    None => e.refuse(&format!("{at}/carrier"), super::unknown_body(names, c)),
                },
            };
            let ratio = match (j.ratio, j.teeth.as_deref()) {
                (Some(k), None) if k.is_finite() && k != 0.0 => Some(k),
                (None, Some([z1, z2])) if *z1 > 0.0 && *z2 > 0.0 => {
                    Some(if j.internal.unwrap_or(false) { z1 / z2 } else { -z1 / z2 })
                }
                _ => e.refuse(at, Msg::new("joint-gear-ratio")),
            };
            Some(JointKind::Gear { ratio: ratio?, carrier: carrier?, pitch: None })
        }
    }
}
