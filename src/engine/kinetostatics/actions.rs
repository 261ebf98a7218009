//! The actions at one position, written into one [`Step`] that a sweep
//! refills: Q, the virtual-power driving actions, I* and M*, the
//! multipliers λ of Φ_qᵀλ = Q − M q̈ and every joint's reaction. Once the
//! step's lists have their length, a position of a mechanism of one input
//! allocates nothing (several inputs solve for each g_i in a vector of its
//! own, and joint friction iterates on vectors of its own).

use super::actuators::Actuated;
use super::loads::applied_forces_into;
use super::reactions::{reaction_of, reactions_into};
use super::{ContactState, Motion, Outputs, Reaction, Step, friction};
use crate::engine::kinematics::{Configuration, solve_linear};
use crate::engine::mobility::Mobility;
use crate::engine::model::Mechanism;
use crate::engine::{Deadline, EngineError, Progress};
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
    f: Vec<f64>,
    next: Vec<f64>,
    sizes: Vec<f64>,
}

/// One moving joint's friction per unit: a_k, y_k (Φ_qᵀ y_k = a_k) and the
/// normal reactions R(y_k) of the joints with friction, in their order.
#[derive(Default)]
pub(super) struct PerUnit {
    a: Vec<f64>,
    y: Vec<f64>,
    reactions: Vec<Reaction>,
}

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

/// Moving joints with friction up to which λ is made linear in their
/// magnitudes (a solve each, then a fixed point over scalars); with more,
/// each pass of the fixed point is one solve for all of them.
const COUPLED_UNITS: usize = 4;

/// Adds the joints' friction to Q (`s.qv`) and takes it from M q̈ − Q
/// (`s.inertial`), with the driving actions and every reaction (each with
/// its friction) into `out` ([`friction`]): the fixed point's passes. The
/// passes read only what presses each joint with friction; every reaction
/// is read once, from the last λ.
fn with_friction(
    m: &Mechanism,
    c: &Configuration,
    s: &mut Scratch,
    indeterminate: &[usize],
    at: (usize, f64),
    deadline: &Deadline,
    out: (&mut Vec<f64>, &mut Vec<Reaction>),
) -> Result<usize, EngineError> {
    let scale = c.qdd.iter().enumerate().map(|(i, a)| (a * m.mass_of(i)).abs());
    let tol = 1e-13 * scale.chain(s.qv.iter().map(|q| q.abs())).fold(f64::MIN_POSITIVE, f64::max);
    // λ₀ of the loads alone; a_k of each moving joint with friction.
    solve_transposed(c, s.actuated.as_ref(), s.inertial.iter().map(|v| -v), &mut s.lambda0, at)?;
    let (mut units, mut per) = (std::mem::take(&mut s.units), std::mem::take(&mut s.per_unit));
    friction::units(m, c, &mut units);
    per.resize_with(units.len(), Default::default);
    for (unit, p) in units.iter().zip(per.iter_mut()) {
        p.a.clear();
        p.a.resize(s.qv.len(), 0.0);
        unit.add_generalized(m, c, 1.0, &mut p.a);
    }
    let mut loads = std::mem::take(&mut s.loads);
    unit_reactions(m, c, (&s.offsets, &units), &s.lambda0, &mut s.driving, &mut loads);
    let coupled = units.len() <= COUPLED_UNITS;
    let mut magnitudes = std::mem::take(&mut s.magnitudes);
    let passes = if coupled {
        linear(m, c, s, (&units, &mut per), &loads, (tol, deadline, &mut magnitudes), at)
    } else {
        iterated(m, c, s, (&units, &per), &loads, (tol, deadline, &mut magnitudes), at)
    };
    s.loads = loads;
    let f = &magnitudes.f;
    let result = passes.and_then(|passes| {
        for (p, f) in per.iter().zip(f) {
            s.qv.iter_mut().zip(&p.a).for_each(|(q, a)| *q += f * a);
            s.inertial.iter_mut().zip(&p.a).for_each(|(q, a)| *q -= f * a);
        }
        if coupled {
            // λ = λ₀ + Σ f_k y_k.
            s.lambda.clone_from(&s.lambda0);
            for (p, f) in per.iter().zip(f) {
                s.lambda.iter_mut().zip(&p.y).for_each(|(l, y)| *l += f * y);
            }
            read_out(m, c, s, Some(indeterminate), (&mut *out.0, &mut *out.1));
        } else {
            multipliers(m, c, s, Some(indeterminate), at, (&mut *out.0, &mut *out.1))?;
        }
        for (unit, f) in units.iter().zip(f) {
            unit.add_to(*f, &mut out.1[unit.joint]);
        }
        Ok(passes)
    });
    (s.units, s.per_unit, s.magnitudes) = (units, per, magnitudes);
    result
}

/// The normal reactions of the joints with friction (`units`, in their
/// order) from multipliers `lambda`, into `out`; `driving` is scratch.
fn unit_reactions(
    m: &Mechanism,
    c: &Configuration,
    (offsets, units): (&[usize], &[friction::Unit]),
    lambda: &[f64],
    driving: &mut Vec<f64>,
    out: &mut Vec<Reaction>,
) {
    driving_actions(m, lambda, driving);
    let efforts = (&c.jacobian, lambda, driving.as_slice());
    out.clear();
    out.extend(units.iter().map(|u| reaction_of(m, (&c.q, &c.trig), efforts, offsets, u.joint)));
}

/// The magnitudes with λ linear in them: y_k and what it presses the joints
/// with solved once per joint, then f_k = g_k(R_k(λ₀) + Σ_j f_j R_k(y_j))
/// over scalars.
fn linear(
    m: &Mechanism,
    c: &Configuration,
    s: &mut Scratch,
    (units, per): (&[friction::Unit], &mut [PerUnit]),
    loads: &[Reaction],
    (tol, deadline, magnitudes): (f64, &Deadline, &mut Magnitudes),
    (step, input): (usize, f64),
) -> Result<usize, EngineError> {
    for p in per.iter_mut() {
        solve_transposed(c, s.actuated.as_ref(), p.a.iter().copied(), &mut p.y, (step, input))?;
        unit_reactions(m, c, (&s.offsets, units), &p.y, &mut s.driving, &mut p.reactions);
    }
    fixed_point(per, (tol, deadline, magnitudes), (step, input), |f, next| {
        for (k, unit) in units.iter().enumerate() {
            let mut r = loads[k];
            for (p, f) in per.iter().zip(f) {
                let y = &p.reactions[k];
                (r.fx, r.fy, r.moment) = (r.fx + f * y.fx, r.fy + f * y.fy, r.moment + f * y.moment);
                r.ends = r.ends.zip(y.ends).map(|([a, b], [c, d])| [a + f * c, b + f * d]);
            }
            next[k] = unit.magnitude(&r);
        }
        Ok(())
    })
}

/// The magnitudes where each pass solves for λ with the last pass's
/// friction (the first is the loads' alone, solved already).
fn iterated(
    m: &Mechanism,
    c: &Configuration,
    s: &mut Scratch,
    (units, per): (&[friction::Unit], &[PerUnit]),
    loads: &[Reaction],
    (tol, deadline, magnitudes): (f64, &Deadline, &mut Magnitudes),
    at: (usize, f64),
) -> Result<usize, EngineError> {
    let (mut b, mut reactions) = (Vec::new(), Vec::new());
    fixed_point(per, (tol, deadline, magnitudes), at, |f, next| {
        let solved = if f.iter().all(|f| *f == 0.0) {
            loads
        } else {
            // Φ_qᵀλ = −(M q̈ − Q − Σ f_k a_k).
            b.clear();
            b.extend(s.inertial.iter().map(|v| -v));
            for (p, f) in per.iter().zip(f) {
                b.iter_mut().zip(&p.a).for_each(|(b, a)| *b += f * a);
            }
            solve_transposed(c, s.actuated.as_ref(), b.iter().copied(), &mut s.lambda, at)?;
            unit_reactions(m, c, (&s.offsets, units), &s.lambda, &mut s.driving, &mut reactions);
            &reactions[..]
        };
        units.iter().zip(solved).zip(next.iter_mut()).for_each(|((unit, r), next)| *next = unit.magnitude(r));
        Ok(())
    })
}

/// f from 0 by `pass` (g(f) into its second argument) until no f_k·|a_k|∞
/// changes by more than `tol`: f in `magnitudes.f`, and the passes.
fn fixed_point(
    per: &[PerUnit],
    (tol, deadline, magnitudes): (f64, &Deadline, &mut Magnitudes),
    (step, input): (usize, f64),
    mut pass: impl FnMut(&[f64], &mut [f64]) -> Result<(), EngineError>,
) -> Result<usize, EngineError> {
    let Magnitudes { f, next, sizes } = magnitudes;
    sizes.clear();
    sizes.extend(per.iter().map(|p| p.a.iter().fold(0.0f64, |a, v| a.max(v.abs()))));
    for v in [&mut *f, &mut *next] {
        v.clear();
        v.resize(per.len(), 0.0);
    }
    for passes in 1..=friction::MAX_ITERATIONS {
        // The clock read every 8th pass (most positions take one or two;
        // a read was 1.4 % of the library cam's position).
        if passes % 8 == 0 {
            deadline.check(|| Progress::Friction { step })?;
        }
        pass(f, next)?;
        let change =
            f.iter().zip(next.iter()).zip(sizes.iter()).map(|((a, b), s)| (a - b).abs() * s).fold(0.0, f64::max);
        std::mem::swap(f, next);
        if change <= tol {
            return Ok(passes);
        }
    }
    Err(EngineError::FrictionDiverged { step, input })
}

/// λ from Φ_qᵀλ = −(M q̈ − Q) (`s.inertial`): the driving actions into
/// `driving` and, if asked, every reaction into `reactions` (else it is
/// left empty); `at` is the step and its input, for the error.
fn multipliers(
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
fn solve_transposed(
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
fn driving_actions(m: &Mechanism, lambda: &[f64], driving: &mut Vec<f64>) {
    driving.clear();
    driving.extend(lambda[lambda.len() - m.drivers.len()..].iter().map(|l| -l));
}

/// The driving actions and, if asked, every reaction from λ (`s.lambda`).
fn read_out(
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
