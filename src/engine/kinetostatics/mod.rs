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
//! and, for one input, I* = gᵀMg, M* = gᵀQ (Zhukovsky).

mod friction;
mod loads;
mod summary;

pub use loads::{Load, applied_forces, applied_forces_into, point_motion, potential};
pub use summary::Summary;

use super::constraints::joint_offsets;
use super::kinematics::{Configuration, solve_linear, sweep_each};
use super::mobility::{Mobility, mobility as mobility_at};
use super::model::{BodyId, JointKind, Mechanism, Pitch, cross, perp, rotate};
use super::{Deadline, EngineError};
use nalgebra::{DMatrix, DVector};

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
    pub mobility: Mobility,
    pub summary: Summary,
    /// Largest Newton iteration count and final |Φ| over the steps.
    pub max_iterations: usize,
    pub max_constraint_residual: f64,
    /// Every position was placed in closed form (a crank and dyads,
    /// [`crate::engine::kinematics::Dyads`]) and Newton only confirmed it.
    pub closed_form: bool,
}

/// Results at one input position.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    pub input: Vec<f64>,
    /// Driving action of each input on the second body of its joint.
    pub driving: Vec<f64>,
    /// The same from virtual power, per input (empty where not computed).
    pub driving_virtual_power: Vec<f64>,
    pub reactions: Vec<Reaction>,
    pub reduced_inertia: Option<f64>,
    pub reduced_torque: Option<f64>,
    /// Quinn's energy-contribution coefficients ε_b = T_b/T of the moving
    /// bodies (one input; share of I* per body, since T_b/T = g_bᵀM_b g_b / I*).
    pub energy_shares: Option<Vec<f64>>,
    pub condition: f64,
    pub kinematics: Option<Motion>,
    /// Fixed-point iterations of joint friction (0 without friction).
    pub friction_iterations: usize,
    /// A singular position: no driving action, reaction or reduced quantity is computed.
    pub singular: bool,
}

/// M·v with M = diag(m, m, I_G).
pub(crate) fn mass_times(m: &Mechanism, v: &[f64]) -> DVector<f64> {
    DVector::from_iterator(v.len(), v.iter().enumerate().map(|(k, x)| x * m.mass_of(k)))
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
    let mut mobility: Option<Mobility> = None;
    let (mut max_iterations, mut max_constraint_residual, mut closed_form) = (0, 0.0f64, true);
    let inputs = m.drivers.len();
    let mut actions =
        Actions { m, loads, outputs, scratch: Scratch { offsets: joint_offsets(m), ..Scratch::default() } };
    // Each position solved as soon as it is assembled, once the mobility at
    // the first regular one has been found to match the inputs (where it
    // does not, the sweep goes on unsolved: a position out of reach is the
    // clearer error, and is said first).
    sweep_each(m, positions, deadline, outputs.condition, |k, c| {
        (max_iterations, max_constraint_residual) =
            (max_iterations.max(c.iterations), max_constraint_residual.max(c.residual));
        closed_form &= c.placed;
        if mobility.is_none() && !c.singular {
            mobility = Some(mobility_at(m, &c.q));
        }
        match mobility.as_ref().filter(|_| !c.singular) {
            Some(mobility) if mobility.dof == inputs => steps.push(actions.step(c, &positions[k], mobility, k)?),
            Some(_) => {}
            None => steps.push(singular_step(c, &positions[k])),
        }
        Ok(())
    })?;
    let mobility = mobility.unwrap_or_else(|| mobility_at(m, &m.reference_q()));
    if mobility.dof != inputs {
        return Err(EngineError::DofMismatch { dof: mobility.dof, inputs });
    }
    Ok(Solution {
        summary: Summary::new(&steps, m.joints.len()),
        steps,
        mobility,
        max_iterations,
        max_constraint_residual,
        closed_form,
    })
}

/// A singular position: its input and condition number, nothing solved.
fn singular_step(c: &Configuration, inputs: &[[f64; 3]]) -> Step {
    Step {
        input: inputs.iter().map(|i| i[0]).collect(),
        driving: Vec::new(),
        driving_virtual_power: Vec::new(),
        reactions: Vec::new(),
        reduced_inertia: None,
        reduced_torque: None,
        energy_shares: None,
        condition: c.condition,
        kinematics: None,
        friction_iterations: 0,
        singular: true,
    }
}

/// The vectors of one position's actions, kept for the next: Q, M q̈ − Q,
/// λ, and the first row of every joint.
#[derive(Default)]
struct Scratch {
    qv: Vec<f64>,
    inertial: Vec<f64>,
    lambda: Vec<f64>,
    offsets: Vec<usize>,
}

/// The actions at the regular positions of one sweep.
struct Actions<'a> {
    m: &'a Mechanism,
    loads: &'a [Load],
    outputs: Outputs,
    scratch: Scratch,
}

impl Actions<'_> {
    /// The actions at a regular position (step k).
    fn step(
        &mut self,
        c: &Configuration,
        inputs: &[[f64; 3]],
        mobility: &Mobility,
        k: usize,
    ) -> Result<Step, EngineError> {
        let (m, outputs, s) = (self.m, self.outputs, &mut self.scratch);
        if !(outputs.driving || outputs.reactions || outputs.reduced) {
            return Ok(Step { singular: false, kinematics: motion(c, outputs), ..singular_step(c, inputs) });
        }
        let phi = inputs[0][0];
        applied_forces_into(m, self.loads, &c.q, &c.qd, phi, [inputs[0][1], 0.0], &mut s.qv);
        let friction_iterations = with_friction(m, c, s, k, phi)?;
        s.inertial.clear();
        s.inertial.extend(c.qdd.iter().zip(&s.qv).enumerate().map(|(i, (a, q))| a * m.mass_of(i) - q));
        let driving_virtual_power = virtual_power(m, c, &s.inertial);
        let g = c.g.as_deref().filter(|_| outputs.reduced);
        let reduced_inertia = g.map(|g| g.iter().enumerate().map(|(i, v)| m.mass_of(i) * v * v).sum::<f64>());
        let reduced_torque = g.map(|g| g.iter().zip(&s.qv).map(|(a, b)| a * b).sum());
        let energy_shares = g.zip(reduced_inertia).filter(|&(_, total)| total > 0.0).map(|(g, total)| {
            g.chunks_exact(3)
                .enumerate()
                .map(|(b, g)| {
                    let body = &m.bodies[b + 1];
                    (body.mass * (g[0] * g[0] + g[1] * g[1]) + body.inertia * g[2] * g[2]) / total
                })
                .collect()
        });
        let (driving, reactions) = if outputs.reactions || m.drivers.len() != 1 {
            multipliers(m, c, s, outputs.reactions.then_some(&mobility.indeterminate_joints), k, phi)?
        } else {
            (vec![driving_virtual_power.first().copied().unwrap_or(f64::NAN)], Vec::new())
        };
        Ok(Step {
            input: inputs.iter().map(|i| i[0]).collect(),
            driving,
            driving_virtual_power,
            reactions,
            reduced_inertia,
            reduced_torque,
            energy_shares,
            condition: c.condition,
            kinematics: motion(c, outputs),
            friction_iterations,
            singular: false,
        })
    }
}

/// q, q̇ and q̈ where asked.
fn motion(c: &Configuration, outputs: Outputs) -> Option<Motion> {
    outputs.kinematics.then(|| Motion { q: c.q.clone(), qd: c.qd.clone(), qdd: c.qdd.clone() })
}

/// T_i = g_iᵀ(M q̈ − Q) for every input i, g_i = ∂q/∂φ_i solving Φ_q g_i = e_i
/// (the velocity coefficients of one input are kept from the kinematics).
fn virtual_power(m: &Mechanism, c: &Configuration, inertial: &[f64]) -> Vec<f64> {
    let power = |g: &[f64]| g.iter().zip(inertial).map(|(a, b)| a * b).sum::<f64>();
    if let Some(g) = &c.g {
        return vec![power(g)];
    }
    let rows = c.jacobian.nrows();
    let first_driver = rows - m.drivers.len();
    (first_driver..rows)
        .map(|r| {
            let mut g = vec![0.0; rows];
            g[r] = 1.0;
            if c.lu.solve(&mut g) {
                return power(&g);
            }
            let e = DVector::from_fn(rows, |k, _| if k == r { 1.0 } else { 0.0 });
            solve_linear(&c.jacobian, &e).map_or(f64::NAN, |g| power(g.as_slice()))
        })
        .collect()
}

/// Adds the joints' friction forces to Q (`s.qv`), iterated to a fixed
/// point with the reactions: the iterations (0 without friction).
fn with_friction(
    m: &Mechanism,
    c: &Configuration,
    s: &mut Scratch,
    step: usize,
    input: f64,
) -> Result<usize, EngineError> {
    if !friction::present(m) {
        return Ok(0);
    }
    let q_applied = DVector::from_column_slice(&s.qv);
    let mq = mass_times(m, &c.qdd);
    let scale = q_applied.amax().max(mq.amax()).max(f64::MIN_POSITIVE);
    let mut qf = DVector::zeros(q_applied.len());
    for iteration in 1..=friction::MAX_ITERATIONS {
        s.inertial.clear();
        s.inertial.extend((&mq - &q_applied - &qf).iter());
        let (_, reactions) = multipliers(m, c, s, Some(&Vec::new()), step, input)?;
        let next = friction::forces(m, c, &reactions);
        let change = (&next - &qf).amax();
        qf = next;
        if change <= 1e-13 * scale {
            s.qv.iter_mut().zip(qf.iter()).for_each(|(q, f)| *q += f);
            return Ok(iteration);
        }
    }
    Err(EngineError::FrictionDiverged { step, input })
}

/// λ from Φ_qᵀλ = −(M q̈ − Q) (`s.inertial`): driving actions and, if asked, every reaction.
fn multipliers(
    m: &Mechanism,
    c: &Configuration,
    s: &mut Scratch,
    reactions_with: Option<&Vec<usize>>,
    step: usize,
    input: f64,
) -> Result<(Vec<f64>, Vec<Reaction>), EngineError> {
    let lambda = &mut s.lambda;
    lambda.clear();
    lambda.extend(s.inertial.iter().map(|v| -v));
    if !c.lu.solve_transposed(lambda) {
        let b = DVector::from_iterator(s.inertial.len(), s.inertial.iter().map(|v| -v));
        let solved = solve_linear(&c.jacobian.transpose(), &b).ok_or(EngineError::Singular { step, input })?;
        lambda.clear();
        lambda.extend(solved.iter());
    }
    let first_driver = lambda.len() - m.drivers.len();
    let driving = lambda[first_driver..].iter().map(|l| -l).collect();
    let Some(indeterminate) = reactions_with else { return Ok((driving, Vec::new())) };
    Ok((driving, reactions(m, &c.q, &c.jacobian, lambda, &s.offsets, indeterminate)))
}

/// Every joint's reaction from the multipliers λ of Φ_qᵀλ = Q − M q̈ (the
/// joints' rows first in Φ_q, joint k's from `offsets[k]`), flagged where
/// `indeterminate` lists the joint.
pub fn reactions(
    m: &Mechanism,
    q: &[f64],
    jac: &DMatrix<f64>,
    lambda: &[f64],
    offsets: &[usize],
    indeterminate: &[usize],
) -> Vec<Reaction> {
    m.joints
        .iter()
        .enumerate()
        .map(|(k, joint)| {
            let rows = offsets[k]..offsets[k] + Mechanism::joint_rows(&joint.kind);
            let force_on = |b: BodyId| -> [f64; 3] {
                let Some(col) = m.column(b) else { return [0.0; 3] };
                let f = |d: usize| -rows.clone().map(|r| jac[(r, col + d)] * lambda[r]).sum::<f64>();
                [f(0), f(1), f(2)]
            };
            let [i, j] = joint.bodies;
            // On the second body, or minus the action on the first when the second is the ground.
            let (b, sign) = if j != 0 { (j, 1.0) } else { (i, -1.0) };
            let [fx, fy, mg] = force_on(b);
            let arm = m.column(b).map_or([0.0; 2], |col| rotate(q[col + 2], m.local(b, joint.at)));
            let moment = mg - cross(arm, [fx, fy]);
            let determinate = !indeterminate.contains(&k);
            if let JointKind::Gear { pitch: Some(pitch), .. } = &joint.kind {
                let [tx, ty] = tooth_force(m, q, [i, j], pitch, sign * moment);
                return Reaction { joint: k, on: j, by: i, fx: tx, fy: ty, moment: 0.0, determinate };
            }
            Reaction { joint: k, on: j, by: i, fx: sign * fx, fy: sign * fy, moment: sign * moment, determinate }
        })
        .collect()
}

/// The tooth force on the second gear at the pitch point, from the mesh's
/// couple on it: tangential M₂/r₂, radial |M₂/r₂|·tan α pushing the teeth apart
/// (towards the gear's centre; outwards for the ring of an internal mesh).
fn tooth_force(m: &Mechanism, q: &[f64], [i, j]: [BodyId; 2], pitch: &Pitch, couple: f64) -> [f64; 2] {
    let zero = [0.0; 2];
    let (c1, _) = point_motion(m, q, &vec![0.0; q.len()], (i, pitch.centers[0]));
    let (c2, _) = point_motion(m, q, &vec![0.0; q.len()], (j, pitch.centers[1]));
    let d = [c1[0] - c2[0], c1[1] - c2[1]];
    let length = d[0].hypot(d[1]);
    if length == 0.0 {
        return zero;
    }
    // w: from the second gear's centre to the pitch point.
    let away = pitch.internal && !pitch.second_is_ring;
    let w = if away { [-d[0] / length, -d[1] / length] } else { [d[0] / length, d[1] / length] };
    let t = perp(w);
    let tangential = couple / pitch.radius;
    let radial = tangential.abs() * pitch.pressure_angle.tan() * if pitch.second_is_ring { 1.0 } else { -1.0 };
    [tangential * t[0] + radial * w[0], tangential * t[1] + radial * w[1]]
}
