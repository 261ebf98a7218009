//! `POST /v1/mobility`: a mechanism's degrees of freedom, from its drawing
//! (the Jacobian's rank at the drawn position, Grübler's count beside it,
//! redundant constraints, the joints that can drive it) or from the counts
//! alone as the course writes Kutzbach's formula (planar or spatial).
//!
//! Symbols: n the bodies (the ground counted), p_k the pairs of class k (a
//! pair of class k leaves k relative freedoms), M the mobility.

mod space;

use crate::engine::mobility::{Space, candidate_inputs, kutzbach, mobility};
use crate::engine::model::Grubler;
use crate::i18n::Msg;
use crate::kind::limits::Limits;
use crate::kind::notes::Notes;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::Errors;
use crate::kind::{JobResult, Kind, engine_failure, validated};
use crate::kinds::mechanism::MechanismDto;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use utoipa::ToSchema;

/// The most bodies or pairs of one class a count may hold.
const MAX_COUNT: i64 = 10_000;
/// The classes of pairs, in order: a class-k pair leaves k relative freedoms.
const CLASSES: [&str; 5] = ["I", "II", "III", "IV", "V"];

/// A mechanism without inputs (its drawing), or the counts alone.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({"counts": {"space": "planar", "bodies": 5, "pairs": {"I": 5, "II": 1}}}))]
pub struct MobilityRequest {
    /// A mechanism as kinetostatics takes it, without inputs: its mobility
    /// at the drawn position (planar, or with `"space": "spatial"` in space:
    /// 6n − rank beside Kutzbach's 6(N − 1) − Σ(6 − fᵢ)).
    pub mechanism: Option<MechanismDto>,
    /// The counts alone: Kutzbach's formula.
    pub counts: Option<PairCounts>,
}

/// Bodies and pairs counted, as the course's exercises give them.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct PairCounts {
    /// `planar` (the default, as the course's exercises are) or `spatial`.
    #[serde(default)]
    pub space: MobilitySpace,
    /// Bodies, the ground counted.
    #[schema(minimum = 1, maximum = 10000)]
    pub bodies: i64,
    /// Pairs by class (`I` to `II` in the plane, `I` to `V` in space; a
    /// class-k pair leaves k relative freedoms).
    #[schema(value_type = Object, example = json!({"I": 5, "II": 1}))]
    pub pairs: BTreeMap<String, i64>,
}

/// Plane (3 freedoms a body) or space (6).
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum MobilitySpace {
    #[default]
    Planar,
    Spatial,
}

/// Grübler's (Kutzbach's) count.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct Count {
    /// M = equations − unknowns.
    pub mobility: i64,
    /// 3(n − 1) in the plane, 6(n − 1) in space.
    pub equations: i64,
    /// The freedoms the pairs remove (their reactions' components).
    pub unknowns: i64,
    /// The count written out, e.g. `3(5 − 1) − (2·5 + 1·1) = 1`.
    pub formula: String,
    /// The kinetostatic problem's unknowns as the course's notes count them:
    /// the driving actions (one an input coordinate, the mobility) and the
    /// reactions, N_INC = G + 2P_I + P_II in the plane (12 for seed 002's
    /// question 1, as many as its 3(N − 1) equations).
    pub unknowns_with_actions: i64,
}

impl Count {
    fn of(g: Grubler, formula: String) -> Self {
        let actions = g.mobility.max(0);
        Count {
            formula,
            mobility: g.mobility,
            equations: g.equations,
            unknowns: g.unknowns,
            unknowns_with_actions: actions + g.unknowns,
        }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct MobilityResult {
    /// Degrees of freedom from the Jacobian's rank at the drawn position
    /// (null for counts).
    pub dof: Option<i64>,
    pub grubler: Count,
    /// Constraints the others already impose (rows − rank; null for counts).
    pub redundant_constraints: Option<i64>,
    /// No freedom: dof 0 (for counts, a mobility of 0 or less).
    pub locked: bool,
    /// Joints whose coordinates can serve together as the inputs.
    pub candidate_inputs: Vec<String>,
    /// Joints whose reactions equilibrium cannot determine (redundant constraints).
    pub indeterminate_joints: Vec<String>,
    /// For counts: how many input coordinates describe the motion, and what
    /// counts alone cannot tell of which (null for a drawing: see `candidate_inputs`).
    pub input_coordinates: Option<String>,
    #[serde(flatten)]
    pub notes: Notes,
}

impl JobResult for MobilityResult {
    fn notes(&mut self) -> Option<&mut Notes> {
        Some(&mut self.notes)
    }
}

/// Mobility: `POST /v1/mobility`.
pub struct Mobility;

impl Kind for Mobility {
    const NAME: &'static str = "mobility";
    const TITLE: &'static str = "kind-mobility";
    const PATH: &'static str = "/v1/mobility";
    const OPERATION_ID: &'static str = "create_mobility_job";
    const TAG: &'static str = "calculators";
    const SUMMARY: &'static str =
        "Degrees of freedom of a mechanism, from its drawing or from the counts of its bodies and pairs.";
    const UNITS: &'static [(&'static str, &'static str)] = &[
        ("/dof", "1"),
        ("/grubler/mobility", "1"),
        ("/grubler/equations", "1"),
        ("/grubler/unknowns", "1"),
        ("/grubler/unknowns_with_actions", "1"),
        ("/redundant_constraints", "1"),
    ];
    type Request = MobilityRequest;
    type Result = MobilityResult;

    fn compute(
        request: &MobilityRequest,
        unknown: Vec<FieldError>,
        limits: &Limits,
    ) -> Result<MobilityResult, ApiError> {
        match (&request.mechanism, &request.counts) {
            (Some(mechanism), None) if mechanism.is_spatial() => space::drawn(mechanism, unknown, limits),
            (Some(mechanism), None) => drawn(mechanism, unknown, limits),
            (None, Some(counts)) => counted(counts, unknown),
            _ => {
                let mut errors = unknown;
                errors.push(FieldError::said("", Msg::new("mobility-one-of")));
                Err(ApiError::Invalid(errors))
            }
        }
    }
}

/// The mobility of a drawn mechanism.
fn drawn(dto: &MechanismDto, unknown: Vec<FieldError>, limits: &Limits) -> Result<MobilityResult, ApiError> {
    let deadline = limits.deadline();
    let mut e = Errors::new(limits);
    let converted = dto.assembled(&mut e, "/mechanism").and_then(|(dto, _)| dto.convert(&mut e, "/mechanism"));
    let converted = validated(unknown, converted.filter(|_| e.list.is_empty()).ok_or(e.list))?;
    let m = &converted.mechanism;
    let q = m.reference_q();
    let found = mobility(m, &q);
    let candidates = candidate_inputs(m, &q, found.dof, &deadline).map_err(|e| engine_failure(e, "/mechanism"))?;
    let name = |k: &usize| m.joints[*k].name.clone();
    let dof = found.dof as i64;
    let g = found.grubler;
    let mut notes = Notes::default();
    if g.mobility != dof {
        let said = crate::i18n::Msg::new("warning-mobility-grubler").arg("grubler", g.mobility).arg("dof", dof);
        notes.warn(said.count("count", found.redundant_constraints));
    }
    Ok(MobilityResult {
        dof: Some(dof),
        grubler: Count::of(g, formula(Space::Planar, m.bodies.len() as i64, &m.pairs(), g.mobility)),
        redundant_constraints: Some(found.redundant_constraints as i64),
        locked: dof == 0,
        candidate_inputs: candidates.iter().map(name).collect(),
        indeterminate_joints: found.indeterminate_joints.iter().map(name).collect(),
        input_coordinates: None,
        notes,
    })
}

/// The mobility of counted bodies and pairs.
fn counted(c: &PairCounts, unknown: Vec<FieldError>) -> Result<MobilityResult, ApiError> {
    let space = match c.space {
        MobilitySpace::Planar => Space::Planar,
        MobilitySpace::Spatial => Space::Spatial,
    };
    let classes = (space.freedoms() - 1) as usize;
    let mut errors = unknown;
    if !(1..=MAX_COUNT).contains(&c.bodies) {
        errors.push(FieldError::said("/counts/bodies", Msg::new("mobility-bodies").arg("max", MAX_COUNT)));
    }
    let mut pairs = vec![0; classes];
    for (class, count) in &c.pairs {
        let at = format!("/counts/pairs/{}", crate::kind::problem::escape(class));
        match CLASSES[..classes].iter().position(|k| k == class) {
            Some(_) if !(0..=MAX_COUNT).contains(count) => {
                errors.push(FieldError::said(at, Msg::new("mobility-pairs").arg("max", MAX_COUNT)))
            }
            Some(k) => pairs[k] = *count,
            None => {
                let known = CLASSES[..classes].join(", ");
                let msg = Msg::new("mobility-unknown-class").arg("class", class).with("space", space_name(space));
                errors.push(FieldError::said(at, msg.arg("known", known)));
            }
        }
    }
    if !errors.is_empty() {
        return Err(ApiError::Invalid(errors));
    }
    let g = kutzbach(space, c.bodies, &pairs);
    let mut notes = Notes::default();
    // The question's second half: how many input coordinates, and what counts alone cannot tell.
    let inputs = Msg::new("mobility-counts-inputs").count("inputs", g.mobility.max(0) as usize);
    let input_coordinates = (g.mobility > 0).then(|| notes.say("/input_coordinates", inputs));
    Ok(MobilityResult {
        dof: None,
        grubler: Count::of(g, formula(space, c.bodies, &pairs, g.mobility)),
        redundant_constraints: None,
        locked: g.mobility <= 0,
        candidate_inputs: Vec::new(),
        indeterminate_joints: Vec::new(),
        input_coordinates,
        notes,
    })
}

fn space_name(space: Space) -> Msg {
    match space {
        Space::Planar => Msg::new("mobility-planar"),
        Space::Spatial => Msg::new("mobility-spatial"),
    }
}

/// `3(5 − 1) − (2·5 + 1·1) = 1`: the count written out, classes without pairs left out.
fn formula(space: Space, bodies: i64, pairs: &[i64], mobility: i64) -> String {
    let f = space.freedoms();
    let terms: Vec<String> =
        (1..).zip(pairs).filter(|(_, p)| **p > 0).map(|(class, p)| format!("{}·{p}", f - class)).collect();
    let removed = match terms.len() {
        0 => "0".to_string(),
        1 => terms[0].clone(),
        _ => format!("({})", terms.join(" + ")),
    };
    format!("{f}({bodies} − 1) − {removed} = {mobility}")
}
