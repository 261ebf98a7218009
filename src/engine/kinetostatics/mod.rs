//! Inverse dynamics of a driven mechanism (d'Alembert, in matrix form):
//!
//! ```text
//! Φ_qᵀ λ = Q − M q̈
//! ```
//!
//! M = diag(m, m, I_G) per body, Q the applied generalized forces (gravity,
//! forces at points, torques). The constraint forces on the bodies are
//! −Φ_qᵀλ: the rows of a joint give its reaction, the row of a driver its
//! driving action (−λ_d). Virtual power gives the driving action of every
//! input independently, one equation per independent virtual motion: with
//! g_i = ∂q/∂φ_i (Φ_q g_i = e_i, the row of driver i), T_i = g_iᵀ(M q̈ − Q);
//! and, for one input, I* = gᵀMg, M* = gᵀQ (Zhukovsky). An input whose
//! effort acts at another joint (an actuator) is solved in `actuators.rs`.

mod actions;
mod actuators;
mod contacts;
mod free_body;
mod friction;
mod loads;
mod locking;
mod magnitudes;
mod multipliers;
mod order;
mod reactions;
mod summary;

pub use contacts::{ContactState, Frame, contact_state};
pub use free_body::{Action, Couple, Force, FreeBody, acting_joint, free_bodies, linear_input};
pub use loads::{
    Energy, Load, applied_forces, applied_forces_into, energy, point_acceleration, point_motion, potential,
};
pub use order::{Group, solving_order};
pub use reactions::reactions;
pub use summary::Summary;
use summary::Tally;

use super::constraints::joint_offsets;
use super::kinematics::{Conditions, sweep_each};
use super::mobility::{Mobility, mobility as mobility_at};
use super::model::{BodyId, Mechanism};
use super::{Deadline, EngineError};
use actions::Actions;
use actuators::Actuated;
use multipliers::Scratch;

/// What to compute at every position.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outputs {
    /// The driving actions (without them, reactions or I* and M*, only the
    /// motion is computed: no load is evaluated).
    pub driving: bool,
    pub reactions: bool,
    pub reduced: bool,
    /// Keep q, q̇, q̈ of every step.
    pub kinematics: bool,
    /// Φ_q's 2-norm condition number exactly at every step (an SVD each);
    /// else estimated, and exact only where the estimate is high.
    pub condition: bool,
}

/// The reaction of joint `joint` on body `on` by body `by`: force at the
/// joint point (ground frame) and the couple about that point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reaction {
    pub joint: usize,
    pub on: BodyId,
    pub by: BodyId,
    pub fx: f64,
    pub fy: f64,
    pub moment: f64,
    /// A guide of a given length: the normal forces N₁ at its end at − u·L/2
    /// and N₂ at at + u·L/2 (u the axis), along perp(u), on the second body.
    pub ends: Option<[f64; 2]>,
    /// False when redundant constraints leave this reaction undetermined
    /// (the values are then one of many equilibrium solutions).
    pub determinate: bool,
}

/// Coordinates, velocities and accelerations at a step.
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
}

/// Everything computed over the positions.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution {
    pub steps: Vec<Step>,
    pub totals: Totals,
}

/// What a sweep finds beside its steps.
#[derive(Clone, Debug, PartialEq)]
pub struct Totals {
    pub mobility: Mobility,
    pub summary: Summary,
    /// Largest Newton iteration count and final |Φ| over the steps.
    pub max_iterations: usize,
    pub max_constraint_residual: f64,
    /// Largest fixed-point iteration count of joint friction (0 without friction).
    pub max_friction_iterations: usize,
    /// Every position was placed in closed form (a crank and dyads,
    /// [`crate::engine::kinematics::Dyads`]) and Newton only confirmed it.
    pub closed_form: bool,
}

/// Results at one input position.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Step {
    pub input: Vec<f64>,
    /// Driving action of each input on the second body of its joint.
    pub driving: Vec<f64>,
    /// The same from virtual power, per input (empty where not computed).
    pub driving_virtual_power: Vec<f64>,
    pub reactions: Vec<Reaction>,
    /// The state of every contact joint whose reaction is determinate (with the reactions).
    pub contacts: Vec<ContactState>,
    pub reduced_inertia: Option<f64>,
    pub reduced_torque: Option<f64>,
    /// Quinn's energy-contribution coefficients ε_b = T_b/T of the moving
    /// bodies (one input; share of I* per body, since T_b/T = g_bᵀM_b g_b / I*).
    pub energy_shares: Option<Vec<f64>>,
    /// Φ_q's condition number in SI units, and scaled by the mechanism's
    /// size (what decides near-singular and singular positions).
    pub condition: f64,
    pub scaled_condition: f64,
    pub kinematics: Option<Motion>,
    /// Fixed-point iterations of joint friction (0 without friction).
    pub friction_iterations: usize,
    /// A singular position: no driving action, reaction or reduced quantity is computed.
    pub singular: bool,
}

/// Solves the inverse dynamics at every position of `positions` (per
/// position, per driver: coordinate, speed, acceleration).
pub fn solve(
    m: &Mechanism,
    loads: &[Load],
    positions: &[Vec<[f64; 3]>],
    outputs: Outputs,
    deadline: &Deadline,
) -> Result<Solution, EngineError> {
    let mut steps = Vec::with_capacity(positions.len());
    let totals = solve_each(m, loads, positions, outputs, deadline, |step| {
        steps.push(step.clone());
        Ok(())
    })?;
    Ok(Solution { steps, totals })
}

/// [`solve`], handing each position's step to `each` as soon as it is
/// solved instead of keeping them: one [`Step`] is refilled, so that once
/// its lists have their length nothing is allocated per position. An error
/// of `each` stops the sweep.
pub fn solve_each(
    m: &Mechanism,
    loads: &[Load],
    positions: &[Vec<[f64; 3]>],
    outputs: Outputs,
    deadline: &Deadline,
    mut each: impl FnMut(&Step) -> Result<(), EngineError>,
) -> Result<Totals, EngineError> {
    let mut mobility: Option<Mobility> = None;
    let (mut max_iterations, mut max_constraint_residual, mut closed_form) = (0, 0.0f64, true);
    let inputs = m.drivers.len();
    let mut actions = Actions {
        m,
        loads,
        outputs,
        scratch: Scratch { offsets: joint_offsets(m), actuated: Actuated::new(m), ..Scratch::default() },
        deadline,
    };
    let (mut step, mut tally) = (Step::default(), Tally::new(m.joints.len()));
    // Each position solved as soon as it is assembled, once the mobility at
    // the first regular one has been found to match the inputs (where it
    // does not, the sweep goes on unsolved: a position out of reach is the
    // clearer error, and is said first).
    let conditions = if outputs.condition { Conditions::Exact } else { Conditions::Estimated };
    sweep_each(m, positions, deadline, conditions, |k, c| {
        (max_iterations, max_constraint_residual) =
            (max_iterations.max(c.iterations), max_constraint_residual.max(c.residual));
        closed_form &= c.placed;
        if mobility.is_none() && !c.singular {
            mobility = Some(mobility_at(m, &c.q));
        }
        match mobility.as_ref().filter(|_| !c.singular) {
            Some(mobility) if mobility.dof == inputs => actions.step(c, &positions[k], mobility, k, &mut step)?,
            Some(_) => return Ok(()),
            None => step.set_singular(c, &positions[k]),
        }
        tally.add(&step);
        each(&step)
    })?;
    let mobility = mobility.unwrap_or_else(|| mobility_at(m, &m.reference_q()));
    if mobility.dof != inputs {
        return Err(EngineError::DofMismatch { dof: mobility.dof, inputs });
    }
    Ok(Totals {
        max_friction_iterations: tally.max_friction_iterations(),
        summary: tally.summary(),
        mobility,
        max_iterations,
        max_constraint_residual,
        closed_form,
    })
}
