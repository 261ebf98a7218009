//! The mobility of a spatial mechanism's drawing: 6n − rank Φ_q, the
//! redundant rows and the joints they leave indeterminate, beside
//! Kutzbach's count 6(N − 1) − Σ(6 − fᵢ).

use super::{Count, MobilityResult, formula};
use crate::engine::mobility::Space;
use crate::engine::spatial::{Pose, candidate_inputs, mobility};
use crate::i18n::Msg;
use crate::kind::limits::Limits;
use crate::kind::notes::Notes;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::Errors;
use crate::kind::{engine_failure, validated};
use crate::kinds::mechanism::MechanismDto;

/// The mobility of a drawn spatial mechanism.
pub fn drawn(dto: &MechanismDto, unknown: Vec<FieldError>, limits: &Limits) -> Result<MobilityResult, ApiError> {
    let deadline = limits.deadline();
    let mut e = Errors::new(limits);
    let converted = dto.spatial(&mut e, "/mechanism");
    let converted = validated(unknown, converted.filter(|_| e.list.is_empty()).ok_or(e.list))?;
    let m = &converted.mechanism;
    let pose = Pose::drawn(m);
    let found = mobility(m, &pose).map_err(|e| engine_failure(e, "/mechanism"))?;
    let candidates = candidate_inputs(m, &pose, found.dof, &deadline).map_err(|e| engine_failure(e, "/mechanism"))?;
    let g = found.kutzbach;
    let dof = found.dof as i64;
    let mut notes = Notes::default();
    if g.mobility != dof {
        let said = Msg::new("warning-mobility-grubler").arg("grubler", g.mobility).arg("dof", dof);
        notes.warn(said.count("count", found.redundant_constraints));
    }
    let mut pairs = vec![0; 5];
    for j in &m.joints {
        pairs[j.kind.freedoms() - 1] += 1;
    }
    let name = |k: usize| m.joints[k].name.clone();
    let mut inputs: Vec<String> = candidates.iter().map(|i| name(i.joint)).collect();
    inputs.dedup();
    Ok(MobilityResult {
        dof: Some(dof),
        grubler: Count::of(g, formula(Space::Spatial, m.n() as i64 + 1, &pairs, g.mobility)),
        redundant_constraints: Some(found.redundant_constraints as i64),
        locked: dof == 0,
        candidate_inputs: inputs,
        indeterminate_joints: found.indeterminate_joints.into_iter().map(name).collect(),
        input_coordinates: None,
        notes,
    })
}
