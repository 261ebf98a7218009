//! The vectors one position's actions keep for the next, and the
//! multipliers λ of Φ_qᵀλ = b with what they give: the inputs' driving
//! actions and every joint's reaction.

use super::Reaction;
use super::actuators::Actuated;
use super::friction;
use super::reactions::reactions_into;
use crate::engine::EngineError;
use crate::engine::kinematics::{Configuration, solve_linear};
use crate::engine::model::Mechanism;
use nalgebra::DVector;

/// The vectors of one position's actions, kept for the next: Q, M q̈ − Q,
/// λ, and the first row of every joint.
#[derive(Default)]
pub(super) struct Scratch {
    pub qv: Vec<f64>,
    pub inertial: Vec<f64>,
    pub lambda: Vec<f64>,
    pub offsets: Vec<usize>,
    /// J_a, where an input's effort acts at another joint ([`Actuated`]).
    pub actuated: Option<Actuated>,
    /// Joint friction: the moving joints' units, and per unit a_k, y_k and
    /// the reactions y_k gives; λ₀ and the driving actions of a λ.
    pub units: Vec<friction::Unit>,
    pub per_unit: Vec<PerUnit>,
    pub lambda0: Vec<f64>,
    pub driving: Vec<f64>,
    /// What presses each joint with friction under the loads alone (λ₀).
    pub loads: Vec<Reaction>,
    /// The fixed point's magnitudes.
    pub magnitudes: Magnitudes,
}

/// The magnitudes f_k of the friction's fixed point, its next pass's and
/// each a_k's size: kept from one position to the next.
#[derive(Default)]
pub(super) struct Magnitudes {
    pub f: Vec<f64>,
    pub next: Vec<f64>,
    pub sizes: Vec<f64>,
}

/// One moving joint's friction per unit: a_k, y_k (Φ_qᵀ y_k = a_k) and the
/// normal reactions R(y_k) of the joints with friction, in their order.
#[derive(Default)]
pub(super) struct PerUnit {
    pub a: Vec<f64>,
    pub y: Vec<f64>,
    pub reactions: Vec<Reaction>,
}

/// λ from Φ_qᵀλ = −(M q̈ − Q) (`s.inertial`): the driving actions into
/// `driving` and, if asked, every reaction into `reactions` (else it is
/// left empty); `at` is the step and its input, for the error.
pub(super) fn multipliers(
    m: &Mechanism,
    c: &Configuration,
    s: &mut Scratch,
    reactions_with: Option<&[usize]>,
    at: (usize, f64),
    out: (&mut Vec<f64>, &mut Vec<Reaction>),
) -> Result<(), EngineError> {
    solve_transposed(c, s.actuated.as_ref(), s.inertial.iter().map(|v| -v), &mut s.lambda, at)?;
    read_out(m, c, s, reactions_with, out);
    Ok(())
}

/// x of Φ_qᵀx = b into `x` (J_a's, where an input's effort acts at another
/// joint); a singular Φ_q by least squares, else the error at `at`.
pub(super) fn solve_transposed(
    c: &Configuration,
    actuated: Option<&Actuated>,
    b: impl Iterator<Item = f64> + Clone,
    x: &mut Vec<f64>,
    (step, input): (usize, f64),
) -> Result<(), EngineError> {
    let (jacobian, lu) = actuated.map_or((&c.jacobian, &c.lu), |a| (a.jacobian(), &a.lu));
    x.clear();
    x.extend(b.clone());
    if lu.solve_transposed(x) {
        return Ok(());
    }
    let solved = solve_linear(&jacobian.transpose(), &DVector::from_iterator(x.len(), b));
    let solved = solved.ok_or(EngineError::Singular { step, input })?;
    x.clear();
    x.extend(solved.iter());
    Ok(())
}

/// The inputs' driving actions, −λ over the drivers' rows (the last of
/// Φ_q), into `driving`.
pub(super) fn driving_actions(m: &Mechanism, lambda: &[f64], driving: &mut Vec<f64>) {
    driving.clear();
    driving.extend(lambda[lambda.len() - m.drivers.len()..].iter().map(|l| -l));
}

/// The driving actions and, if asked, every reaction from λ (`s.lambda`).
pub(super) fn read_out(
    m: &Mechanism,
    c: &Configuration,
    s: &Scratch,
    reactions_with: Option<&[usize]>,
    (driving, reactions): (&mut Vec<f64>, &mut Vec<Reaction>),
) {
    let lambda = &s.lambda;
    driving_actions(m, lambda, driving);
    reactions.clear();
    if let Some(indeterminate) = reactions_with {
        let (at, efforts) = ((c.q.as_slice(), c.trig.as_slice()), (&c.jacobian, lambda.as_slice(), driving.as_slice()));
        reactions_into(m, at, efforts, (&s.offsets, indeterminate), reactions);
    }
}
