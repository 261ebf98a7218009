//! `POST /v1/equivalent-masses`: point masses equivalent to a rigid link.

use crate::engine::equivalent::equivalent_masses;
use crate::i18n::Msg;
use crate::kind::Kind;
use crate::kind::limits::Limits;
use crate::kind::notes::Notes;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::{Errors, Quantity};
use crate::kind::validated;
use crate::units::Dim;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use utoipa::ToSchema;

/// A link (mass, inertia about its centre of mass G, G) and the points where
/// the masses go (at most 20; include G itself for the three-mass bar).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({"mass": 3, "inertia": 0.09, "cg": [0.2, 0], "points": {"A": [0, 0], "B": [0.6, 0], "G": [0.2, 0]}}))]
pub struct EquivalentRequest {
    #[schema(value_type = Quantity)]
    pub mass: Quantity,
    #[schema(value_type = Quantity)]
    pub inertia: Quantity,
    /// G, m.
    #[schema(min_items = 2, max_items = 2)]
    pub cg: Vec<f64>,
    /// Named points, m.
    #[schema(value_type = Object)]
    pub points: BTreeMap<String, [f64; 2]>,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct EquivalentResult {
    /// Mass at each point, kg.
    pub masses: BTreeMap<String, f64>,
    /// Mass, centre of mass and inertia all match (completely equivalent).
    pub complete: bool,
    /// The points determine the masses (otherwise a minimum-norm set is given).
    pub unique: bool,
    /// Largest relative residual of the four conditions.
    pub residual: f64,
    #[serde(flatten)]
    pub notes: Notes,
}

impl crate::kind::JobResult for EquivalentResult {
    fn notes(&mut self) -> Option<&mut Notes> {
        Some(&mut self.notes)
    }
}

/// EquivalentMasses: `POST /v1/equivalent-masses`.
pub struct EquivalentMasses;

impl Kind for EquivalentMasses {
    const NAME: &'static str = "equivalent_masses";
    const TITLE: &'static str = "kind-equivalent";
    const PATH: &'static str = "/v1/equivalent-masses";
    const OPERATION_ID: &'static str = "create_equivalent_masses_job";
    const TAG: &'static str = "calculators";
    const SUMMARY: &'static str = "Masses at the given points with the link's mass, centre of mass and inertia.";
    const UNITS: &'static [(&'static str, &'static str)] = &[("/masses/*", "kg"), ("/residual", "1")];
    type Request = EquivalentRequest;
    type Result = EquivalentResult;

    fn compute(
        request: &EquivalentRequest,
        unknown: Vec<FieldError>,
        _limits: &Limits,
    ) -> Result<EquivalentResult, ApiError> {
        compute(request, unknown)
    }
}

/// Validates and computes a request.
fn compute(request: &EquivalentRequest, unknown: Vec<FieldError>) -> Result<EquivalentResult, ApiError> {
    let (mass, inertia, points) = validated(unknown, request.validate())?;
    let e = equivalent_masses(mass, inertia, &points);
    if !(e.residual.is_finite() && e.masses.iter().all(|m| m.is_finite())) {
        return Err(ApiError::Invalid(vec![FieldError::said("/points", Msg::new("equivalent-too-far"))]));
    }
    let complete = e.residual <= 1e-9;
    let mut notes = Notes::default();
    if !complete {
        notes.warn(Msg::new("warning-equivalent-incomplete").fig("residual", e.residual));
    }
    if !e.unique {
        notes.warn(Msg::new("warning-equivalent-not-unique"));
    }
    Ok(EquivalentResult {
        masses: request.points.keys().cloned().zip(e.masses).collect(),
        complete,
        unique: e.unique,
        residual: e.residual,
        notes,
    })
}

/// Mass, inertia and the points relative to G.
type Link = (f64, f64, Vec<[f64; 2]>);

impl EquivalentRequest {
    fn validate(&self) -> Result<Link, Vec<FieldError>> {
        let mut e = Errors::default();
        let mass = e.positive(&self.mass, Dim::MASS, "/mass");
        let inertia = e.quantity(&self.inertia, Dim::INERTIA, "/inertia");
        let inertia = e.require_said(inertia, |i| i >= 0.0, "/inertia", Msg::new("equivalent-not-negative"));
        let cg = match self.cg.as_slice() {
            [x, y] if x.is_finite() && y.is_finite() => Some([*x, *y]),
            _ => e.refuse("/cg", Msg::new("equivalent-cg")),
        };
        if self.points.is_empty() || self.points.len() > 20 {
            e.say("/points", Msg::new("equivalent-points").arg("max", 20));
        }
        if let Some(name) = self.points.iter().find(|(_, p)| !p.iter().all(|v| v.is_finite())).map(|(n, _)| n) {
            e.say(&format!("/points/{}", crate::kind::problem::escape(name)), Msg::new("equivalent-coordinates"));
        }
        match (mass, inertia, cg) {
            (Some(m), Some(i), Some(g)) if e.list.is_empty() => {
                Ok((m, i, self.points.values().map(|p| [p[0] - g[0], p[1] - g[1]]).collect()))
            }
            _ => Err(e.list),
        }
    }
}
