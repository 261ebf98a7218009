//! Mobility from the drawing: M = 6n − rank Φ_q of the joints' rows, the
//! redundant rows (rows − rank) and the joints that hold one, beside
//! Kutzbach's count 6(N − 1) − Σ(6 − fᵢ) (N the bodies with the ground, fᵢ
//! a pair's freedoms), which a linkage of special geometry (Bricard's,
//! Bennett's, a spherical four-bar such as Hooke's joint) contradicts.

use super::constraints::evaluate;
use super::kinematics::{RANK_TOLERANCE, SVD_EPSILON, SVD_ITERATIONS, Scaled};
use super::model::{Coordinate, Input, JointKind, Mechanism, Pose};
use crate::engine::mobility::{Space, kutzbach};
use crate::engine::model::Grubler;
use crate::engine::{Deadline, EngineError, Progress};
use nalgebra::DMatrix;

/// A left-null vector's share of a row above which the row is one of the dependent.
const SHARE: f64 = 1e-6;

#[derive(Clone, Debug, PartialEq)]
pub struct Mobility {
    /// Degrees of freedom: 6n − rank.
    pub dof: usize,
    /// Rows − rank.
    pub redundant_constraints: usize,
    /// Joints with a row among the dependent: equilibrium cannot tell their reactions.
    pub indeterminate_joints: Vec<usize>,
    /// Kutzbach's count.
    pub kutzbach: Grubler,
}

/// The mobility at `pose` (the joints' rows only); a drawing whose
/// numbers are out of range is an error.
pub fn mobility(m: &Mechanism, pose: &Pose) -> Result<Mobility, EngineError> {
    let rows = evaluate(m, pose, None, &[]);
    let joints = m.joint_rows();
    let scaled = Scaled::new(&rows, joints, m.size());
    let rank = scaled.checked_rank()?;
    let dependent = dependent_rows(&scaled);
    let (offsets, _) = m.offsets();
    let indeterminate_joints = (0..m.joints.len())
        .filter(|&k| (offsets[k]..offsets[k] + m.joints[k].kind.rows()).any(|r| dependent[r]))
        .collect();
    let mut pairs = vec![0; 5];
    for j in &m.joints {
        pairs[j.kind.freedoms() - 1] += 1;
    }
    Ok(Mobility {
        dof: 6 * m.n() - rank,
        redundant_constraints: joints - rank,
        indeterminate_joints,
        kutzbach: kutzbach(Space::Spatial, m.n() as i64 + 1, &pairs),
    })
}

/// Whether each row of the scaled Φ_q has a share in its left null space
/// (a combination of rows that vanishes): such rows' multipliers are not
/// determined. Φ_qᵀ padded with zero rows to be at least square gives the
/// whole null space from one SVD.
pub fn dependent_rows(scaled: &Scaled) -> Vec<bool> {
    let (rows, cols) = scaled.jac.shape();
    if rows == 0 {
        return Vec::new();
    }
    let mut padded = DMatrix::zeros(cols.max(rows), rows);
    padded.view_mut((0, 0), (cols, rows)).copy_from(&scaled.jac.transpose());
    let Some(svd) = padded.try_svd(false, true, SVD_EPSILON, SVD_ITERATIONS) else { return vec![false; rows] };
    let (Some(v_t), s) = (svd.v_t, svd.singular_values) else { return vec![false; rows] };
    let tolerance = RANK_TOLERANCE * s.max();
    let mut share = vec![0.0; rows];
    for (k, _) in s.iter().enumerate().filter(|(_, x)| **x <= tolerance) {
        for (r, x) in share.iter_mut().enumerate() {
            *x += v_t[(k, r)].powi(2);
        }
    }
    share.into_iter().map(|x| x > SHARE).collect()
}

/// Inputs that can serve together as the `dof` independent ones at
/// `pose`: each coordinate of a revolute (rotation), prismatic (slide) or
/// cylindrical (both) joint in turn, kept where its row raises Φ_q's rank
/// (an SVD a coordinate, the `deadline` read at each).
pub fn candidate_inputs(
    m: &Mechanism,
    pose: &Pose,
    dof: usize,
    deadline: &Deadline,
) -> Result<Vec<Input>, EngineError> {
    let mut trial = Mechanism { inputs: Vec::new(), ..m.clone() };
    let mut rank = Scaled::new(&evaluate(&trial, pose, None, &[]), m.joint_rows(), m.size()).rank();
    let coordinates = m.joints.iter().enumerate().flat_map(|(joint, j)| {
        let of: &[Coordinate] = match j.kind {
            JointKind::Revolute { .. } => &[Coordinate::Rotation],
            JointKind::Prismatic { .. } => &[Coordinate::Slide],
            JointKind::Cylindrical { .. } => &[Coordinate::Rotation, Coordinate::Slide],
            _ => &[],
        };
        of.iter().map(move |&coordinate| Input { joint, coordinate })
    });
    for (k, input) in coordinates.enumerate() {
        if trial.inputs.len() == dof {
            break;
        }
        deadline.check(|| Progress::Candidates { joint: k, of: m.joints.len() })?;
        trial.inputs.push(input);
        let values = vec![[0.0; 3]; trial.inputs.len()];
        let rows = evaluate(&trial, pose, None, &values);
        let raised = Scaled::new(&rows, rows.phi.len(), m.size()).rank();
        if raised > rank {
            rank = raised;
        } else {
            trial.inputs.pop();
        }
    }
    Ok(trial.inputs)
}
