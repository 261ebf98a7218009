//! A mechanism given by its dimensions: `points` are then a sketch, and the
//! points used are the least change from it that meets every dimension
//! ([`crate::engine::sketch`]).

use super::MechanismDto;
use crate::engine::sketch::{Dimension, solve};
use crate::engine::variants::round_sig;
use crate::i18n::Msg;
use crate::kind::quantity::{Errors, Quantity};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use std::borrow::Cow;
use std::collections::BTreeMap;
use utoipa::ToSchema;

/// Most dimensions of one mechanism.
pub const MAX_DIMENSIONS: usize = 400;
/// How much more a point on the ground weighs in the least change.
const GROUND_WEIGHT: f64 = 1e6;

/// One dimension of the statement: exactly one of `distance` ([P, Q]: |PQ|),
/// `angle` ([P, Q]: the direction of P→Q from +x, counter-clockwise), `x`
/// or `y` (P's coordinate), and its `value` (a length or an angle).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({"distance": ["O2", "A"], "value": "100 mm"}))]
pub struct DimensionDto {
    #[schema(min_items = 2, max_items = 2)]
    pub distance: Option<Vec<String>>,
    #[schema(min_items = 2, max_items = 2)]
    pub angle: Option<Vec<String>>,
    pub x: Option<String>,
    pub y: Option<String>,
    #[schema(value_type = Quantity)]
    pub value: Quantity,
}

/// Where a mechanism's dimensions put its points, and what they said.
#[derive(Clone, Debug)]
pub struct Assembled {
    pub points: BTreeMap<String, [f64; 2]>,
    pub warnings: Vec<crate::i18n::Msg>,
}

impl Assembled {
    /// For a result: what [`MechanismDto::assembled`] made of `given`
    /// (`dto`, its `warnings`); None for a mechanism without dimensions.
    pub fn of(given: &MechanismDto, dto: &MechanismDto, warnings: Vec<crate::i18n::Msg>) -> Option<Self> {
        given.dimensions.is_some().then(|| Self { points: dto.points.clone().unwrap_or_default(), warnings })
    }
}

impl MechanismDto {
    /// The mechanism to work on: itself without `dimensions`, else a copy
    /// with its points assembled from them and the warnings that says
    /// (a point left free to move); None when the dimensions are in error
    /// (the errors are in `e`).
    pub fn assembled(&self, e: &mut Errors, at: &str) -> Option<(Cow<'_, MechanismDto>, Vec<crate::i18n::Msg>)> {
        let Some(dimensions) = self.dimensions.as_ref() else { return Some((Cow::Borrowed(self), Vec::new())) };
        let sketch = self.points.clone().unwrap_or_default();
        let names: Vec<&String> = sketch.keys().collect();
        if dimensions.len() > MAX_DIMENSIONS {
            return e.refuse(&format!("{at}/dimensions"), Msg::new("dimensions-too-many").arg("max", MAX_DIMENSIONS));
        }
        let read: Vec<Option<Dimension>> =
            dimensions.iter().enumerate().map(|(k, d)| read(e, d, &names, &format!("{at}/dimensions/{k}"))).collect();
        let read: Vec<Dimension> = read.into_iter().collect::<Option<_>>()?;
        let on_ground = |name: &str| {
            self.joints.iter().any(|j| {
                matches!(&j.at, Some(super::PointRef::Name(n)) if n == name) && j.bodies.iter().any(|b| b == "ground")
            })
        };
        let weights: Vec<f64> = names.iter().map(|n| if on_ground(n) { GROUND_WEIGHT } else { 1.0 }).collect();
        let points: Vec<[f64; 2]> = sketch.values().copied().collect();
        let solved = match solve(&points, &weights, &read, &e.limits.deadline()) {
            Ok(s) => s,
            Err(c) => {
                for k in c.dimensions {
                    let msg = Msg::new("dimensions-conflict").num("residual", round_sig(c.residual, 4));
                    e.say(&format!("{at}/dimensions/{k}"), msg);
                }
                return None;
            }
        };
        for k in crate::engine::sketch::reversed(&solved.points, &read) {
            e.say(&format!("{at}/dimensions/{k}/angle"), Msg::new("dimensions-reversed"));
        }
        let mut warnings = Vec::new();
        if solved.underdetermined {
            warnings.push(crate::i18n::Msg::new("warning-dimensions-free"));
        }
        let assembled: BTreeMap<String, [f64; 2]> = names.into_iter().cloned().zip(solved.points).collect();
        let dto = MechanismDto { points: Some(assembled), dimensions: None, ..self.clone() };
        Some((Cow::Owned(dto), warnings))
    }
}

/// One dimension by point index, its value in SI.
fn read(e: &mut Errors, d: &DimensionDto, names: &[&String], at: &str) -> Option<Dimension> {
    let index = |e: &mut Errors, name: &String, ptr: &str| {
        names
            .iter()
            .position(|n| *n == name)
            .or_else(|| e.refuse(ptr, Msg::new("dimensions-unknown-point").arg("name", name)))
    };
    let pair = |e: &mut Errors, list: &Vec<String>, ptr: &str| match list.as_slice() {
        [p, q] => Some([index(e, p, &format!("{ptr}/0"))?, index(e, q, &format!("{ptr}/1"))?]),
        _ => e.refuse(ptr, Msg::new("dimensions-two-points")),
    };
    let given = [d.distance.is_some(), d.angle.is_some(), d.x.is_some(), d.y.is_some()].iter().filter(|g| **g).count();
    if given != 1 {
        return e.refuse(at, Msg::new("dimensions-one-of"));
    }
    let value = format!("{at}/value");
    if let Some(list) = &d.distance {
        let v = e.quantity(&d.value, Dim::LENGTH, &value);
        let v = e.require_said(v, |v| v > 0.0, &value, Msg::new("dimensions-positive"));
        return Some(Dimension::Distance(pair(e, list, &format!("{at}/distance"))?, v?));
    }
    if let Some(list) = &d.angle {
        let v = e.angle(&d.value, &value);
        return Some(Dimension::Angle(pair(e, list, &format!("{at}/angle"))?, v?));
    }
    let (name, is_x) = match (&d.x, &d.y) {
        (Some(p), _) => (p, true),
        (_, Some(p)) => (p, false),
        _ => return None,
    };
    let p = index(e, name, &format!("{at}/{}", if is_x { "x" } else { "y" }));
    let v = e.quantity(&d.value, Dim::LENGTH, &value);
    Some(if is_x { Dimension::X(p?, v?) } else { Dimension::Y(p?, v?) })
}
