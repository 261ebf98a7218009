//! Every moving body of a spatial mechanism alone at a known motion (the
//! course's d'Alembert, seed 000, in space): each joint's reaction on it
//! from the multipliers of that joint's rows (a force at the joint's point
//! and a couple), the inputs' efforts, its weight, the loads, the springs'
//! and dampers' pulls, and its inertia force −m·r̈ at G and couple
//! −(J·α + ω × J·ω). Its six equations, ΣF = 0 and ΣM_G = 0, are summed
//! with these numbers: each is zero to rounding.

use super::kinematics::Motion;
use super::kinetostatics::{Actions, spring_ends};
use super::model::{BodyId, Load, Mechanism};
use nalgebra::Vector3;

/// Who acts on the body: the plane's actions, the same in space.
pub use crate::engine::kinetostatics::Action;

/// A force at a point (ground axes), N and m.
#[derive(Clone, Debug, PartialEq)]
pub struct Force {
    pub action: Action,
    pub at: Vector3<f64>,
    pub f: Vector3<f64>,
}

/// A couple (ground axes), N·m.
#[derive(Clone, Debug, PartialEq)]
pub struct Couple {
    pub action: Action,
    pub moment: Vector3<f64>,
}

/// One body alone.
#[derive(Clone, Debug, PartialEq)]
pub struct FreeBody {
    pub body: BodyId,
    /// G now, its velocity and the body's ω.
    pub cg: Vector3<f64>,
    pub v_cg: Vector3<f64>,
    pub omega: Vector3<f64>,
    pub forces: Vec<Force>,
    pub couples: Vec<Couple>,
    /// ΣF (N) and ΣM about G (N·m).
    pub sums: [Vector3<f64>; 2],
}

impl FreeBody {
    /// The power of force `f` at `at`: f·(v_G + ω × (at − G)).
    pub fn power(&self, at: &Vector3<f64>, f: &Vector3<f64>) -> f64 {
        f.dot(&(self.v_cg + self.omega.cross(&(at - self.cg))))
    }
}

/// Every moving body's free body at `motion`, under gravity and `loads`,
/// with the multipliers and efforts of `actions` (from `inverse_dynamics`
/// at the same motion).
pub fn free_bodies(m: &Mechanism, loads: &[Load], motion: &Motion, actions: &Actions) -> Vec<FreeBody> {
    let mut bodies: Vec<FreeBody> = (1..=m.n()).map(|b| own_actions(m, motion, b)).collect();
    let (offsets, first_input) = m.offsets();
    for (k, joint) in m.joints.iter().enumerate() {
        let rows = offsets[k]..offsets[k] + joint.kind.rows();
        for (side, &b) in joint.bodies.iter().enumerate() {
            let by = joint.bodies[1 - side];
            let wrench = rows_on(motion, actions, rows.clone(), b, -1.0);
            place(m, motion, &mut bodies, b, Action::Reaction { joint: k, by }, (&joint.at, joint.bodies[1]), wrench);
        }
    }
    for (i, input) in m.inputs.iter().enumerate() {
        let joint = &m.joints[input.joint];
        let row = first_input + i;
        for &b in &joint.bodies {
            let wrench = rows_on(motion, actions, row..row + 1, b, -1.0);
            place(m, motion, &mut bodies, b, Action::Driving(i), (&joint.at, joint.bodies[1]), wrench);
        }
    }
    for (k, load) in loads.iter().enumerate() {
        add_load(m, motion, &mut bodies, k, load);
    }
    for fb in &mut bodies {
        let force = fb.forces.iter().map(|f| f.f).sum::<Vector3<f64>>();
        let moment = fb.forces.iter().map(|f| (f.at - fb.cg).cross(&f.f)).sum::<Vector3<f64>>()
            + fb.couples.iter().map(|c| c.moment).sum::<Vector3<f64>>();
        fb.sums = [force, moment];
    }
    bodies
}

/// Body b's weight and inertia, with its motion.
fn own_actions(m: &Mechanism, motion: &Motion, b: BodyId) -> FreeBody {
    let body = &m.bodies[b - 1];
    let part = |from: usize| Vector3::from(motion.v.fixed_rows::<3>(from));
    let (v_cg, omega) = (part(6 * b - 6), part(6 * b - 3));
    let (a_cg, alpha) =
        (Vector3::from(motion.a.fixed_rows::<3>(6 * b - 6)), Vector3::from(motion.a.fixed_rows::<3>(6 * b - 3)));
    let rot = motion.pose.rotation(b);
    let j = rot * body.inertia * rot.transpose();
    let cg = motion.pose.origin(b);
    let mut forces = vec![Force { action: Action::Inertia, at: cg, f: -a_cg * body.mass }];
    if body.mass != 0.0 && m.gravity != Vector3::zeros() {
        forces.push(Force { action: Action::Weight, at: cg, f: m.gravity * body.mass });
    }
    let couples = vec![Couple { action: Action::Inertia, moment: -(j * alpha + omega.cross(&(j * omega))) }];
    FreeBody { body: b, cg, v_cg, omega, forces, couples, sums: [Vector3::zeros(); 2] }
}

/// The wrench (force, moment about G) of `rows` on body b: `sign`·Σ Φ_qᵀλ.
fn rows_on(
    motion: &Motion,
    actions: &Actions,
    rows: std::ops::Range<usize>,
    b: BodyId,
    sign: f64,
) -> (Vector3<f64>, Vector3<f64>) {
    let mut w = [0.0; 6];
    if b > 0 {
        for r in rows {
            for (c, x) in w.iter_mut().enumerate() {
                *x += sign * motion.rows.jac[(r, 6 * (b - 1) + c)] * actions.lambda[r];
            }
        }
    }
    (Vector3::new(w[0], w[1], w[2]), Vector3::new(w[3], w[4], w[5]))
}

/// A wrench about G put on body b as a force at the joint's point (as
/// `carrier` carries it) and the couple left, where b moves.
fn place(
    m: &Mechanism,
    motion: &Motion,
    bodies: &mut [FreeBody],
    b: BodyId,
    action: Action,
    (at, carrier): (&Vector3<f64>, BodyId),
    (force, about_g): (Vector3<f64>, Vector3<f64>),
) {
    let Some(fb) = b.checked_sub(1).and_then(|i| bodies.get_mut(i)) else { return };
    let (point, _) = motion.pose.point(m, carrier, at);
    let couple = about_g - (point - fb.cg).cross(&force);
    if force != Vector3::zeros() || couple == Vector3::zeros() {
        fb.forces.push(Force { action, at: point, f: force });
    }
    if couple != Vector3::zeros() {
        fb.couples.push(Couple { action, moment: couple });
    }
}

/// Load k on the bodies it acts on.
fn add_load(m: &Mechanism, motion: &Motion, bodies: &mut [FreeBody], k: usize, load: &Load) {
    let mut on = |b: BodyId, force: Option<Force>, couple: Option<Couple>| {
        let Some(fb) = b.checked_sub(1).and_then(|i| bodies.get_mut(i)) else { return };
        fb.forces.extend(force);
        fb.couples.extend(couple);
    };
    let action = Action::Load(k);
    match load {
        Load::Force { body, at, force } => {
            let (point, _) = motion.pose.point(m, *body, at);
            on(*body, Some(Force { action, at: point, f: *force }), None);
        }
        Load::Torque { body, torque } => on(*body, None, Some(Couple { action, moment: *torque })),
        Load::Spring { bodies: ends, .. } => {
            for (b, (point, _, f)) in
                ends.iter().zip(spring_ends(m, load, &motion.pose, &motion.v).into_iter().flatten())
            {
                on(*b, Some(Force { action, at: point, f }), None);
            }
        }
    }
}
