//! Degrees of freedom from the rank of the constraint Jacobian, redundant
//! constraints, and which joint reactions they leave indeterminate. Ranks
//! are taken of Φ_q scaled by the mechanism's size (`numeric::scaled`),
//! so a mechanism drawn in micrometres or kilometres counts the same.
//!
//! With J = Φ_q of the joints alone, DOF = n − rank J and the redundant
//! constraints number rows(J) − rank J. The multipliers of Φ_qᵀλ = Q − Mq̈
//! are unique up to the left null space of the full Φ_q (joints and
//! drivers): a joint whose rows touch that null space has a reaction the
//! equations cannot determine — it is flagged, never invented.
//!
//! Counted instead (Kutzbach, as the course writes it): n bodies, the
//! ground among them, and p_k pairs of class k (a pair of class k leaves k
//! relative freedoms, so it removes 3 − k in the plane and 6 − k in space):
//! planar M = 3(n − 1) − 2p_I − p_II, spatial M = 6(n − 1) − (5p_I + 4p_II +
//! 3p_III + 2p_IV + p_V).

use super::constraints::{State, evaluate, joint_offsets};
use super::model::{Driver, Grubler, JointKind, Mechanism};
use super::numeric::scaled::{row_scales, scaled};
use super::numeric::svd::{singular_values, svd};
use super::{Deadline, EngineError, Progress};
use nalgebra::{DMatrix, DVector};

/// Relative size below which a singular value counts as zero.
const RANK_TOLERANCE: f64 = 1e-9;

#[derive(Clone, Debug, PartialEq)]
pub struct Mobility {
    pub dof: usize,
    pub redundant_constraints: usize,
    pub grubler: Grubler,
    /// Joints whose reactions are not determined by the equations.
    pub indeterminate_joints: Vec<usize>,
}

fn rank(a: &DMatrix<f64>) -> usize {
    if a.nrows() == 0 || a.ncols() == 0 {
        return 0;
    }
    // A Jacobian that is not finite has no rank worth the name: none.
    let Some(s) = singular_values(a) else { return 0 };
    let tol = RANK_TOLERANCE * s.max();
    s.iter().filter(|v| **v > tol).count()
}

/// Mobility of the mechanism at an assembled configuration `q`.
pub fn mobility(m: &Mechanism, q: &[f64]) -> Mobility {
    let inputs = vec![[0.0; 3]; m.drivers.len()];
    let jac = scaled_jacobian(m, &State { q, qd: None, inputs: &inputs });
    let joint_rows = jac.nrows() - m.drivers.len();
    let rank_joints = rank(&jac.rows(0, joint_rows).into_owned());
    Mobility {
        dof: m.n_coordinates() - rank_joints,
        redundant_constraints: joint_rows - rank_joints,
        grubler: m.grubler(),
        indeterminate_joints: indeterminate(m, &jac),
    }
}

/// R Φ_q C at a state (`numeric::scaled`).
fn scaled_jacobian(m: &Mechanism, state: &State) -> DMatrix<f64> {
    let (jac, cols, mut rows) = (evaluate(m, state).jacobian, m.column_lengths(), Vec::new());
    row_scales(&jac, &cols, &mut rows);
    scaled(&jac, [&rows, &cols])
}

/// Where a Kutzbach count is made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Space {
    Planar,
    Spatial,
}

impl Space {
    /// Freedoms of one free body: 3 in the plane, 6 in space.
    pub fn freedoms(self) -> i64 {
        match self {
            Space::Planar => 3,
            Space::Spatial => 6,
        }
    }
}

/// Kutzbach's count of `bodies` bodies (the ground counted) joined by
/// `pairs[k]` pairs of class k + 1: equations 3(n − 1) or 6(n − 1), unknowns
/// the freedoms the pairs remove (the reactions' components), their difference.
pub fn kutzbach(space: Space, bodies: i64, pairs: &[i64]) -> Grubler {
    let f = space.freedoms();
    let equations = f * (bodies - 1);
    let unknowns = (1..).zip(pairs).map(|(class, p)| (f - class) * p).sum::<i64>();
    Grubler { mobility: equations - unknowns, equations, unknowns }
}

/// Joints whose coordinates can serve together as the `dof` independent
/// inputs at `q`: revolute and prismatic joints, taken in order, each kept
/// when driving it too leaves the mechanism's Jacobian of full row rank
/// (fewer than `dof` where too few joints can be driven).
///
/// One SVD of the joints' rows gives an orthonormal basis of their row
/// space; a joint's driver row raises the rank when it has a part outside
/// the rows kept so far (Gram–Schmidt, twice for rounding), which then
/// joins them — O(n·rank) a joint instead of an SVD a joint (a chain of
/// 200 bodies: 30 s before). The `deadline` is read at every joint.
pub fn candidate_inputs(m: &Mechanism, q: &[f64], dof: usize, deadline: &Deadline) -> Result<Vec<usize>, EngineError> {
    let drivable: Vec<usize> = (0..m.joints.len())
        .filter(|&k| matches!(m.joints[k].kind, JointKind::Revolute | JointKind::Prismatic { .. }))
        .collect();
    if dof == 0 || drivable.is_empty() {
        return Ok(Vec::new());
    }
    let driven = Mechanism { drivers: drivable.iter().map(|&k| Driver::joint(k, 0.0)).collect(), ..m.clone() };
    let inputs = vec![[0.0; 3]; drivable.len()];
    let jac = scaled_jacobian(&driven, &State { q, qd: None, inputs: &inputs });
    let joint_rows = jac.nrows() - drivable.len();
    let mut basis = row_space(&jac.rows(0, joint_rows).into_owned());
    let scale = jac.rows(0, joint_rows).iter().fold(1.0f64, |a, v| a.max(v.abs()));
    let mut chosen = Vec::new();
    for (i, &k) in drivable.iter().enumerate() {
        if chosen.len() == dof {
            break;
        }
        deadline.check(|| Progress::Candidates { joint: i, of: drivable.len() })?;
        let d: DVector<f64> = jac.row(joint_rows + i).transpose();
        let mut r = d.clone();
        for _ in 0..2 {
            for b in &basis {
                r.axpy(-b.dot(&r), b, 1.0);
            }
        }
        let norm = r.norm();
        if norm > RANK_TOLERANCE * scale.max(d.norm()) {
            basis.push(r / norm);
            chosen.push(k);
        }
    }
    Ok(chosen)
}

/// An orthonormal basis of the row space of `a`: its right singular vectors
/// of singular values above the rank's tolerance (none where it has no SVD).
fn row_space(a: &DMatrix<f64>) -> Vec<DVector<f64>> {
    if a.nrows() == 0 || a.ncols() == 0 {
        return Vec::new();
    }
    let Some(svd) = svd(a.clone(), false, true) else { return Vec::new() };
    let Some(v_t) = svd.v_t else { return Vec::new() };
    let tol = RANK_TOLERANCE * svd.singular_values.max();
    (0..svd.singular_values.len())
        .filter(|&i| svd.singular_values[i] > tol)
        .map(|i| v_t.row(i).transpose().normalize())
        .collect()
}

/// Joints with a row in the left null space of Φ_q (eigenvectors of Φ_qΦ_qᵀ
/// with a zero eigenvalue).
fn indeterminate(m: &Mechanism, jac: &DMatrix<f64>) -> Vec<usize> {
    let r = rank(jac);
    if jac.nrows() == 0 || r == jac.nrows() {
        return Vec::new();
    }
    // The rank comes from the SVD; the null space is spanned by the
    // eigenvectors of the (rows − rank) smallest eigenvalues.
    let eig = (jac * jac.transpose()).symmetric_eigen();
    let mut order: Vec<usize> = (0..eig.eigenvalues.len()).collect();
    order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
    let null = &order[..jac.nrows() - r];
    let offsets = joint_offsets(m);
    (0..m.joints.len())
        .filter(|&j| {
            let rows = offsets[j]..offsets[j] + Mechanism::joint_rows(&m.joints[j].kind);
            rows.clone().any(|r| null.iter().any(|&k| eig.eigenvectors[(r, k)].abs() > 1e-8))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::model::{Body, Driver, Joint, JointKind};
    use crate::engine::samples::offset_slider_crank;

    /// Seed 002, question 1: five links, five lower pairs and one higher
    /// pair in the plane, 3·4 − 2·5 − 1 = 1; and a spatial count, a
    /// four-bar of revolutes in space (Bennett's), 6·3 − 5·4 = −2.
    #[test]
    fn kutzbach_counts_as_the_course_writes_them() {
        assert_eq!(kutzbach(Space::Planar, 5, &[5, 1]), Grubler { mobility: 1, equations: 12, unknowns: 11 });
        assert_eq!(kutzbach(Space::Spatial, 4, &[4]).mobility, -2);
    }

    /// The slider-crank is driven by its crank, its first joint; asked for
    /// no input, none.
    #[test]
    fn the_first_joint_that_drives_the_mechanism_is_its_candidate() {
        let m = offset_slider_crank();
        assert_eq!(candidate_inputs(&m, &m.reference_q(), 1, &Deadline::none()).unwrap(), vec![0]);
        assert_eq!(candidate_inputs(&m, &m.reference_q(), 0, &Deadline::none()).unwrap(), Vec::<usize>::new());
    }

    #[test]
    fn the_slider_crank_has_one_dof_and_no_redundancy() {
        let m = offset_slider_crank();
        let mob = mobility(&m, &m.reference_q());
        assert_eq!((mob.dof, mob.redundant_constraints), (1, 0));
        assert_eq!(mob.grubler.mobility, 1);
        assert!(mob.indeterminate_joints.is_empty());
    }

    /// A parallelogram four-bar with a third, parallel crank: Grübler says 0,
    /// the Jacobian's rank says 1 DOF with one redundant constraint, and the
    /// reactions of all six joints are indeterminate: the cranks can carry a
    /// self-stress of axial forces (1, 1, −2) (zero net force and moment on
    /// the coupler) that no equation of equilibrium sees.
    #[test]
    fn a_parallelogram_with_a_redundant_crank_is_detected() {
        let body = |n: &str, cg: [f64; 2]| Body { name: n.into(), mass: 1.0, inertia: 0.01, cg };
        let rev = |n: &str, b: [usize; 2], at: [f64; 2]| Joint {
            name: n.into(),
            kind: JointKind::Revolute,
            bodies: b,
            at,
            friction: None,
            length: None,
        };
        let m = Mechanism {
            bodies: vec![
                body("ground", [0.0, 0.0]),
                body("crank1", [0.0, 0.5]),
                body("coupler", [1.0, 1.0]),
                body("crank2", [2.0, 0.5]),
                body("crank3", [1.0, 0.5]),
            ],
            joints: vec![
                rev("O1", [0, 1], [0.0, 0.0]),
                rev("A", [1, 2], [0.0, 1.0]),
                rev("B", [2, 3], [2.0, 1.0]),
                rev("O2", [0, 3], [2.0, 0.0]),
                rev("O3", [0, 4], [1.0, 0.0]),
                rev("C", [4, 2], [1.0, 1.0]),
            ],
            drivers: vec![Driver::joint(0, 0.0)],
            gravity: [0.0, -9.81],
        };
        let mob = mobility(&m, &m.reference_q());
        assert_eq!(m.grubler().mobility, 0);
        assert_eq!((mob.dof, mob.redundant_constraints), (1, 1));
        assert_eq!(mob.indeterminate_joints, vec![0, 1, 2, 3, 4, 5]);
    }
}
