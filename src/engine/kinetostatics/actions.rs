//! The actions at one position, written into one [`Step`] that a sweep
//! refills: Q, the virtual-power driving actions, I* and M*, the
//! multipliers λ of Φ_qᵀλ = Q − M q̈ and every joint's reaction. Once the
//! step's lists have their length, a position of a mechanism of one input
//! allocates nothing (several inputs solve for each g_i in a vector of its
//! own, and joint friction iterates on vectors of its own).

use super::actuators::Actuated;
use super::loads::applied_forces_into;
use super::magnitudes::with_friction;
use super::multipliers::{Scratch, multipliers};
use super::{ContactState, Motion, Outputs, Step, friction};
use crate::engine::kinematics::{Configuration, solve_linear};
use crate::engine::mobility::Mobility;
use crate::engine::model::Mechanism;
use crate::engine::{Deadline, EngineError};
use nalgebra::DVector;

/// The actions at the regular positions of one sweep.
pub(super) struct Actions<'a> {
    pub m: &'a Mechanism,
    pub loads: &'a [super::Load],
    pub outputs: Outputs,
    pub scratch: Scratch,
    /// The job's budget, read at every iteration of friction.
    pub deadline: &'a Deadline,
}

impl Step {
    /// This step at a new position, nothing solved yet: its input and
    /// condition number, its lists emptied (their storage kept); the motion
    /// and the energy shares are left to the caller.
    fn clear(&mut self, c: &Configuration, inputs: &[[f64; 3]]) {
        self.input.clear();
        self.input.extend(inputs.iter().map(|i| i[0]));
        self.driving.clear();
        self.driving_virtual_power.clear();
        self.reactions.clear();
        self.contacts.clear();
        (self.reduced_inertia, self.reduced_torque) = (None, None);
        (self.condition, self.scaled_condition) = (c.condition, c.scaled_condition);
        (self.friction_iterations, self.singular) = (0, false);
    }

    /// This step as a singular position: its input and condition number, nothing solved.
    pub(super) fn set_singular(&mut self, c: &Configuration, inputs: &[[f64; 3]]) {
        self.clear(c, inputs);
        (self.energy_shares, self.kinematics, self.singular) = (None, None, true);
    }

    /// q, q̇ and q̈ where asked, in the storage of the last step's.
    fn set_motion(&mut self, c: &Configuration, outputs: Outputs) {
        self.kinematics = outputs.kinematics.then(|| {
            let mut motion =
                self.kinematics.take().unwrap_or(Motion { q: Vec::new(), qd: Vec::new(), qdd: Vec::new() });
            motion.q.clone_from(&c.q);
            motion.qd.clone_from(&c.qd);
            motion.qdd.clone_from(&c.qdd);
            motion
        });
    }
}

impl Actions<'_> {
    /// The actions at a regular position (step k), into `out`.
    pub fn step(
        &mut self,
        c: &Configuration,
        inputs: &[[f64; 3]],
        mobility: &Mobility,
        k: usize,
        out: &mut Step,
    ) -> Result<(), EngineError> {
        let (m, outputs, s) = (self.m, self.outputs, &mut self.scratch);
        out.clear(c, inputs);
        out.set_motion(c, outputs);
        let shares = out.energy_shares.take();
        if !(outputs.driving || outputs.reactions || outputs.reduced) {
            return Ok(());
        }
        let phi = inputs[0][0];
        if let Some(a) = s.actuated.as_mut()
            && !a.at(&c.q, inputs)
        {
            let actuators = m.drivers.iter().filter_map(|d| d.actuator).map(|a| m.joints[a].name.as_str());
            return Err(EngineError::Unactuated {
                step: k,
                input: phi,
                actuators: actuators.collect::<Vec<_>>().join(", "),
            });
        }
        applied_forces_into(m, self.loads, (&c.q, &c.trig), &c.qd, phi, [inputs[0][1], 0.0], &mut s.qv);
        s.inertial.clear();
        s.inertial.extend(c.qdd.iter().zip(&s.qv).enumerate().map(|(i, (a, q))| a * m.mass_of(i) - q));
        let with = outputs.reactions.then_some(&mobility.indeterminate_joints[..]);
        let frictional = friction::present(m);
        if frictional {
            let indeterminate = with.unwrap_or(&[]);
            out.friction_iterations =
                with_friction(m, c, s, indeterminate, (k, phi), self.deadline, (&mut out.driving, &mut out.reactions))?;
        }
        virtual_power(m, c, &s.inertial, s.actuated.as_ref(), &mut out.driving_virtual_power);
        let g = c.g.as_deref().filter(|_| outputs.reduced);
        out.reduced_inertia = g.map(|g| g.iter().enumerate().map(|(i, v)| m.mass_of(i) * v * v).sum::<f64>());
        out.reduced_torque = g.map(|g| g.iter().zip(&s.qv).map(|(a, b)| a * b).sum());
        out.energy_shares = g.zip(out.reduced_inertia).filter(|&(_, total)| total > 0.0).map(|(g, total)| {
            let mut shares = shares.unwrap_or_default();
            shares.clear();
            shares.extend(g[..m.n_body_coordinates()].chunks_exact(3).enumerate().map(|(b, g)| {
                let body = &m.bodies[b + 1];
                (body.mass * (g[0] * g[0] + g[1] * g[1]) + body.inertia * g[2] * g[2]) / total
            }));
            shares
        });
        if outputs.reactions || m.drivers.len() != 1 {
            if !frictional {
                multipliers(m, c, s, with, (k, phi), (&mut out.driving, &mut out.reactions))?;
            } else if !outputs.reactions {
                out.reactions.clear();
            }
            if outputs.reactions {
                let states = out.reactions.iter().filter(|r| r.determinate);
                let jumped =
                    |k: usize| (0..2).any(|side| m.contact_column(k, side).is_some_and(|col| c.jumped.contains(&col)));
                out.contacts.extend(
                    states.filter_map(|r| super::contact_state(m, (&c.q, &c.qd), Some(&c.trig), r)).map(|s| {
                        ContactState {
                            jumped: jumped(s.joint),
                            penetration: c.cuts.iter().find(|cut| cut.0 == s.joint).map(|cut| cut.1),
                            ..s
                        }
                    }),
                );
            }
        } else {
            out.driving.clear();
            out.reactions.clear();
            out.driving.push(out.driving_virtual_power.first().copied().unwrap_or(f64::NAN));
        }
        Ok(())
    }
}

/// T_i = g_iᵀ(M q̈ − Q) for every input i into `out`, g_i = ∂q/∂φ_i solving
/// Φ_q g_i = e_i (the velocity coefficients of one input are kept from the
/// kinematics); with actuators elsewhere, their efforts from the T_i.
fn virtual_power(m: &Mechanism, c: &Configuration, inertial: &[f64], actuated: Option<&Actuated>, out: &mut Vec<f64>) {
    let power = |g: &[f64]| g.iter().zip(inertial).map(|(a, b)| a * b).sum::<f64>();
    out.clear();
    if let (Some(g), None) = (&c.g, actuated) {
        out.push(power(g));
        return;
    }
    let rows = c.jacobian.nrows();
    let first_driver = rows - m.drivers.len();
    let g: Vec<Vec<f64>> = (first_driver..rows)
        .map(|r| {
            let mut g = vec![0.0; rows];
            g[r] = 1.0;
            if c.lu.solve(&mut g) {
                return g;
            }
            let e = DVector::from_fn(rows, |k, _| if k == r { 1.0 } else { 0.0 });
            solve_linear(&c.jacobian, &e).map_or_else(|| vec![f64::NAN; c.q.len()], |g| g.as_slice().to_vec())
        })
        .collect();
    let t: Vec<f64> = g.iter().map(|g| power(g)).collect();
    match actuated {
        Some(a) => out.extend(a.efforts(&g, &t)),
        None => out.extend(t),
    }
}
