//! Inverse dynamics of a driven mechanism (d'Alembert, in matrix form):
//!
//! ```text
//! Φ_qᵀ λ = Q − M q̈
//! ```
//!
//! M = diag(m, m, I_G) per body, Q the applied generalized forces (gravity,
//! forces at points, torques). The constraint forces on the bodies are
//! −Φ_qᵀλ: the rows of a joint give its reaction, the row of a driver its
//! driving action (−λ_d). Virtual power gives the driving action of a
//! single input independently: with g = dq/dφ (Φ_q g = e_driver),
//! T = gᵀ(M q̈ − Q); and I* = gᵀMg, M* = gᵀQ (Zhukovsky).

use super::EngineError;
use super::constraints::{State, evaluate, joint_offsets};
use super::function::{Function, Side};
use super::kinematics::{Configuration, motion, solve_linear, sweep};
use super::model::{BodyId, Mechanism, cross, rotate};
use nalgebra::DVector;

/// A load on a body; functions take the first input coordinate φ.
#[derive(Clone, Debug)]
pub enum Load {
    /// A force of signed `magnitude` along the unit `direction` (fixed in the
    /// ground), applied at the body's point `at` (reference coordinates).
    Force { body: BodyId, at: [f64; 2], direction: [f64; 2], magnitude: Function },
    /// A couple on the body (counter-clockwise positive).
    Torque { body: BodyId, value: Function },
    /// A linear spring between point `a` of one body and `b` of another:
    /// tension k·(L − L₀) along the line between them.
    Spring { a: (BodyId, [f64; 2]), b: (BodyId, [f64; 2]), stiffness: f64, free_length: f64 },
    /// A linear damper: tension c·dL/dt along the line between the points.
    Damper { a: (BodyId, [f64; 2]), b: (BodyId, [f64; 2]), coefficient: f64 },
}

/// What to compute at every position.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outputs {
    pub reactions: bool,
    pub reduced: bool,
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
}

/// Results at one input position.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    pub input: Vec<f64>,
    /// Driving action of each input on the second body of its joint.
    pub driving: Vec<f64>,
    /// The same from virtual power (one input only).
    pub driving_virtual_power: Option<f64>,
    pub reactions: Vec<Reaction>,
    pub reduced_inertia: Option<f64>,
    pub reduced_torque: Option<f64>,
    pub condition: f64,
}

/// Generalized applied forces Q at a configuration (velocities `qd` for dampers).
pub fn applied_forces(m: &Mechanism, loads: &[Load], q: &[f64], qd: &[f64], phi: f64) -> DVector<f64> {
    let mut qv = DVector::zeros(m.n_coordinates());
    // Force f at point `at` of body b, plus a couple.
    let mut apply = |b: BodyId, at: [f64; 2], f: [f64; 2], couple: f64| {
        if let Some(c) = m.column(b) {
            let arm = rotate(q[c + 2], m.local(b, at));
            qv[c] += f[0];
            qv[c + 1] += f[1];
            qv[c + 2] += cross(arm, f) + couple;
        }
    };
    for (b, body) in m.bodies.iter().enumerate() {
        apply(b, body.cg, [body.mass * m.gravity[0], body.mass * m.gravity[1]], 0.0);
    }
    for load in loads {
        match load {
            Load::Force { body, at, direction, magnitude } => {
                let f = magnitude.eval(phi, Side::Right);
                apply(*body, *at, [f * direction[0], f * direction[1]], 0.0);
            }
            Load::Torque { body, value } => apply(*body, [0.0, 0.0], [0.0, 0.0], value.eval(phi, Side::Right)),
            Load::Spring { a, b, stiffness, free_length } => {
                let (u, length, _) = line(m, q, qd, *a, *b);
                let t = stiffness * (length - free_length);
                apply(a.0, a.1, [t * u[0], t * u[1]], 0.0);
                apply(b.0, b.1, [-t * u[0], -t * u[1]], 0.0);
            }
            Load::Damper { a, b, coefficient } => {
                let (u, _, rate) = line(m, q, qd, *a, *b);
                let t = coefficient * rate;
                apply(a.0, a.1, [t * u[0], t * u[1]], 0.0);
                apply(b.0, b.1, [-t * u[0], -t * u[1]], 0.0);
            }
        }
    }
    qv
}

/// Unit vector from point a to point b, their distance and its rate.
fn line(m: &Mechanism, q: &[f64], qd: &[f64], a: (BodyId, [f64; 2]), b: (BodyId, [f64; 2])) -> ([f64; 2], f64, f64) {
    let (pa, va) = point_motion(m, q, qd, a);
    let (pb, vb) = point_motion(m, q, qd, b);
    let d = [pb[0] - pa[0], pb[1] - pa[1]];
    let length = d[0].hypot(d[1]);
    let u = if length > 0.0 { [d[0] / length, d[1] / length] } else { [0.0, 0.0] };
    (u, length, u[0] * (vb[0] - va[0]) + u[1] * (vb[1] - va[1]))
}

/// Position and velocity of a body point (reference coordinates `p`).
pub fn point_motion(m: &Mechanism, q: &[f64], qd: &[f64], (b, p): (BodyId, [f64; 2])) -> ([f64; 2], [f64; 2]) {
    let Some(c) = m.column(b) else { return (p, [0.0, 0.0]) };
    let s = m.local(b, p);
    let (a, ds) = (rotate(q[c + 2], s), super::model::rotate_d(q[c + 2], s));
    ([q[c] + a[0], q[c + 1] + a[1]], [qd[c] + ds[0] * qd[c + 2], qd[c + 1] + ds[1] * qd[c + 2]])
}

/// M·v with M = diag(m, m, I_G).
fn mass_times(m: &Mechanism, v: &[f64]) -> DVector<f64> {
    DVector::from_iterator(
        v.len(),
        v.iter().enumerate().map(|(k, x)| {
            let body = &m.bodies[k / 3 + 1];
            x * if k % 3 == 2 { body.inertia } else { body.mass }
        }),
    )
}

/// Solves the inverse dynamics at every position of `positions` (per
/// position, per driver: coordinate, speed, acceleration).
pub fn solve(
    m: &Mechanism,
    loads: &[Load],
    positions: &[Vec<[f64; 3]>],
    outputs: Outputs,
) -> Result<Vec<Step>, EngineError> {
    let configurations = sweep(m, positions)?;
    configurations
        .iter()
        .zip(positions)
        .enumerate()
        .map(|(k, (c, inputs))| step(m, loads, c, inputs, outputs, k))
        .collect()
}

fn step(
    m: &Mechanism,
    loads: &[Load],
    c: &Configuration,
    inputs: &[[f64; 3]],
    outputs: Outputs,
    k: usize,
) -> Result<Step, EngineError> {
    let phi = inputs[0][0];
    let qv = applied_forces(m, loads, &c.q, &c.qd, phi);
    let inertial = mass_times(m, &c.qdd) - &qv;
    let single = m.drivers.len() == 1;
    let g = if single { motion(m, &c.q, &[[phi, 1.0, 0.0]]).map(|(g, _, _)| g) } else { None };
    let driving_virtual_power = g.as_ref().map(|g| g.iter().zip(inertial.iter()).map(|(a, b)| a * b).sum::<f64>());
    let (reduced_inertia, reduced_torque) = match (&g, outputs.reduced) {
        (Some(g), true) => {
            let mg = mass_times(m, g);
            (
                Some(g.iter().zip(mg.iter()).map(|(a, b)| a * b).sum()),
                Some(g.iter().zip(qv.iter()).map(|(a, b)| a * b).sum()),
            )
        }
        _ => (None, None),
    };
    let (driving, reactions) = if outputs.reactions || !single {
        multipliers(m, c, &inertial, outputs.reactions, k, phi)?
    } else {
        (vec![driving_virtual_power.unwrap_or(f64::NAN)], Vec::new())
    };
    Ok(Step {
        input: inputs.iter().map(|i| i[0]).collect(),
        driving,
        driving_virtual_power,
        reactions,
        reduced_inertia,
        reduced_torque,
        condition: c.condition,
    })
}

/// λ from Φ_qᵀλ = −(M q̈ − Q): driving actions and, if asked, every reaction.
fn multipliers(
    m: &Mechanism,
    c: &Configuration,
    inertial: &DVector<f64>,
    with_reactions: bool,
    step: usize,
    input: f64,
) -> Result<(Vec<f64>, Vec<Reaction>), EngineError> {
    let inputs: Vec<[f64; 3]> = vec![[input, 0.0, 0.0]; m.drivers.len()];
    let jac = evaluate(m, &State { q: &c.q, qd: None, inputs: &inputs }).jacobian;
    let lambda = solve_linear(&jac.transpose(), &(-inertial)).ok_or(EngineError::Singular { step, input })?;
    let first_driver = lambda.len() - m.drivers.len();
    let driving = (first_driver..lambda.len()).map(|r| -lambda[r]).collect();
    if !with_reactions {
        return Ok((driving, Vec::new()));
    }
    let offsets = joint_offsets(m);
    let reactions = m
        .joints
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
            let arm = m.column(b).map_or([0.0; 2], |col| rotate(c.q[col + 2], m.local(b, joint.at)));
            let moment = mg - cross(arm, [fx, fy]);
            Reaction { joint: k, on: j, by: i, fx: sign * fx, fy: sign * fy, moment: sign * moment }
        })
        .collect();
    Ok((driving, reactions))
}
