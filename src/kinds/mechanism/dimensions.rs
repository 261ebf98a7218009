//! A mechanism given by its dimensions: `points` are then a sketch, and the
//! points used are the least change from it that meets every dimension
//! ([`crate::engine::sketch`]).

use super::{DrawnPoints, MechanismDto};
use crate::engine::numeric::plane::diagonal;
use crate::engine::sketch::{Dimension, solve};
use crate::i18n::Msg;
use crate::kind::quantity::{Errors, Quantity};
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use std::borrow::Cow;
use std::collections::BTreeMap;
use utoipa::ToSchema;

/// Most dimensions of one mechanism.
pub const MAX_DIMENSIONS: usize = 400;

/// One dimension of the statement: exactly one of `distance` ([P, Q]: |PQ|),
/// `angle` ([P, Q]: the direction of P→Q from +x, counter-clockwise), `x`
/// or `y` (P's coordinate), each with its `value` (a length or an angle);
/// or `on` M `between` [A, B] at the fraction `ratio` of A→B (0.5: the midpoint).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({"distance": ["O2", "A"], "value": "100 mm"}))]
pub struct DimensionDto {
    #[schema(min_items = 2, max_items = 2)]
    pub distance: Option<Vec<String>>,
    #[schema(min_items = 2, max_items = 2)]
    pub angle: Option<Vec<String>>,
    pub x: Option<String>,
    pub y: Option<String>,
    /// With `between` and `ratio`: the point M = A + ratio·(B − A).
    pub on: Option<String>,
    #[schema(min_items = 2, max_items = 2)]
    pub between: Option<Vec<String>>,
    pub ratio: Option<f64>,
    /// Required with `distance`, `angle`, `x` and `y`.
    #[schema(value_type = Option<Quantity>)]
    pub value: Option<Quantity>,
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
        given.dimensions.is_some().then(|| Self { points: dto.points.clone().unwrap_or_default().xy, warnings })
    }
}

impl MechanismDto {
    /// The mechanism to work on: itself without `dimensions`, else a copy
    /// with its points assembled from them and the warnings that says
    /// (a point left free to move); None when the dimensions are in error
    /// (the errors are in `e`).
    pub fn assembled(&self, e: &mut Errors, at: &str) -> Option<(Cow<'_, MechanismDto>, Vec<crate::i18n::Msg>)> {
        let Some(dimensions) = self.dimensions.as_ref() else { return Some((Cow::Borrowed(self), Vec::new())) };
        let sketch = self.points.clone().unwrap_or_default().xy;
        let names: Vec<&String> = sketch.keys().collect();
        if dimensions.len() > MAX_DIMENSIONS {
            return e.refuse(&format!("{at}/dimensions"), Msg::new("dimensions-too-many").arg("max", MAX_DIMENSIONS));
        }
        let read: Vec<Option<Dimension>> =
            dimensions.iter().enumerate().map(|(k, d)| read(e, d, &names, &format!("{at}/dimensions/{k}"))).collect();
        let read: Vec<Dimension> = read.into_iter().collect::<Option<_>>()?;
        let weights = self.weights(&names);
        let points: Vec<[f64; 2]> = sketch.values().copied().collect();
        let solved = match solve(&points, &weights, &read, &e.limits.deadline()) {
            Ok(s) => s,
            Err(c) => {
                let (unit, factor) = length_unit(dimensions);
                let misfit = Msg::new("text-value-unit").fig("value", c.residual / factor).arg("unit", unit);
                for k in c.dimensions {
                    let said = Msg::new("dimensions-conflict").with("residual", misfit.clone());
                    e.say(&format!("{at}/dimensions/{k}"), said);
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
        warnings.extend(scale_gap(&points, &solved.points));
        let assembled: BTreeMap<String, [f64; 2]> = names.into_iter().cloned().zip(solved.points).collect();
        let dto = self.clone().carried(&sketch, &assembled);
        Some((
            Cow::Owned(MechanismDto {
                points: Some(DrawnPoints { xy: assembled, z: BTreeMap::new() }),
                dimensions: None,
                ..dto
            }),
            warnings,
        ))
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
    let given = [d.distance.is_some(), d.angle.is_some(), d.x.is_some(), d.y.is_some(), d.on.is_some()];
    if given.iter().filter(|g| **g).count() != 1 {
        return e.refuse(at, Msg::new("dimensions-one-of"));
    }
    if let Some(on) = &d.on {
        let m = index(e, on, &format!("{at}/on"));
        let [a, b] = match &d.between {
            Some(list) => pair(e, list, &format!("{at}/between"))?,
            None => return e.refuse(&format!("{at}/between"), Msg::new("dimensions-between")),
        };
        let ratio = match d.ratio {
            Some(r) if r.is_finite() => r,
            _ => return e.refuse(&format!("{at}/ratio"), Msg::new("dimensions-ratio")),
        };
        return Some(Dimension::Between { on: m?, a, b, ratio });
    }
    let value = format!("{at}/value");
    let Some(given) = d.value.as_ref() else { return e.refuse(&value, Msg::new("dimensions-value")) };
    if let Some(list) = &d.distance {
        let v = e.quantity(given, Dim::LENGTH, &value);
        let v = e.require_said(v, |v| v > 0.0, &value, Msg::new("dimensions-positive"));
        return Some(Dimension::Distance(pair(e, list, &format!("{at}/distance"))?, v?));
    }
    if let Some(list) = &d.angle {
        let v = e.angle(given, &value);
        return Some(Dimension::Angle(pair(e, list, &format!("{at}/angle"))?, v?));
    }
    let (name, is_x) = match (&d.x, &d.y) {
        (Some(p), _) => (p, true),
        (_, Some(p)) => (p, false),
        _ => return None,
    };
    let p = index(e, name, &format!("{at}/{}", if is_x { "x" } else { "y" }));
    let v = e.quantity(given, Dim::LENGTH, &value);
    Some(if is_x { Dimension::X(p?, v?) } else { Dimension::Y(p?, v?) })
}

/// How many times the sketch's extent (its points' bounding box) is the
/// dimensions' where one is ten or more times the other: a sketch drawn in
/// millimetres as bare numbers (read in metres) beside dimensions in mm
/// gave a trial's centres of mass, sketched too, 10 m from their bodies
/// and reactions of 78 MN, with no word of why.
fn scale_gap(sketch: &[[f64; 2]], assembled: &[[f64; 2]]) -> Option<Msg> {
    let ratio = diagonal(sketch.iter().copied()) / diagonal(assembled.iter().copied());
    let round = |r: f64| crate::engine::variants::round_sig(r, 2);
    match ratio {
        r if r.is_finite() && r >= 10.0 => Some(Msg::new("warning-sketch-larger").num("ratio", round(r))),
        r if r > 0.0 && r <= 0.1 => Some(Msg::new("warning-sketch-smaller").num("ratio", round(1.0 / r))),
        _ => None,
    }
}

/// The unit the statement writes its lengths in (the first length given
/// with a unit, as "100 mm"), and its factor to metres; m where none is.
fn length_unit(dimensions: &[DimensionDto]) -> (String, f64) {
    dimensions
        .iter()
        .filter(|d| d.angle.is_none())
        .filter_map(|d| match &d.value {
            Some(Quantity::Text(t)) => crate::units::parse_quantity(t).ok().map(|_| t),
            _ => None,
        })
        .find_map(|t| {
            let unit = t.trim().trim_start_matches(|c: char| c.is_ascii_digit() || ".,+-eE ".contains(c)).trim();
            let factor = crate::units::unit_factor(unit, Dim::LENGTH).ok()?;
            Some((unit.to_string(), factor))
        })
        .unwrap_or_else(|| ("m".into(), 1.0))
}
