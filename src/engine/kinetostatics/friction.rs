//! Coulomb friction in the joints, which makes the kinetostatic problem
//! nonlinear: the friction forces depend on the reactions they change.
//!
//! Each moving joint k with friction acts with a magnitude f_k (the size of
//! the reaction that presses it) along a direction fixed by the position
//! and the velocities alone: Q_f = Σ f_k a_k, a_k the generalized force of
//! a unit of it ([`Unit`]). λ of Φ_qᵀλ = Q + Q_f − M q̈ is then linear in
//! the f_k, and so is every reaction R:
//!
//! ```text
//! λ = λ₀ + Σ f_k y_k,   Φ_qᵀ y_k = a_k,   R(λ) = R(λ₀) + Σ f_k R(y_k)
//! ```
//!
//! so one solve for the loads and one per moving joint with friction give
//! everything; the magnitudes are then a fixed point over scalars,
//! f_k = g_k(R_k(λ₀) + Σ_j f_j R_k(y_j)), iterated without a solve until
//! |Δf| ≤ 1e-13 of the loads (piecewise linear g converge in two passes,
//! |R| in a few). With more than a few such joints (a stack of sliders)
//! a solve each would cost more than the passes: each pass then solves
//! once for λ with the last pass's friction (`magnitudes.rs`). Near
//! self-locking the passes contract slowly or not at all (by 2μe/L a pass
//! for a stem in its guide): where a pass shrinks the change by less than
//! half, the magnitudes are followed from the frictionless mechanism by
//! Newton's method (`locking.rs`), to the true limit.
//!
//! Revolute: couple −μ·r·|R|·sign(ω₂ − ω₁) on the second body (and its
//! opposite on the first). Prismatic and pin-in-slot: force −μ·|N|·sign(v)
//! along the slide at the joint point, v the sliding speed of the second body;
//! a guide of length L bears N as N₁ and N₂ at its ends (N₁ + N₂ = N,
//! (L/2)(N₂ − N₁) = the couple M), each with its friction: −μ(|N₁| + |N₂|)·sign(v),
//! whose moment about the joint point is nil (both act along the axis).
//! A contact: force −μ·|N|·sign(v) along the common tangent at the
//! contact point, v the second body's material point sliding on the
//! first's there. Where the joint does not move (sign 0) there is no
//! friction (static friction is not determined by kinetostatics). The reported reaction of a
//! joint is λ's (normal) part plus its friction ([`Unit::add_to`]): every body's
//! reported forces balance.

use super::Reaction;
use super::contacts::Touch;
use super::loads::add_force;
use crate::engine::kinematics::Configuration;
use crate::engine::model::{JointKind, Mechanism, dot, perp, rotate, rotate_d};

/// Fixed-point passes allowed per position before [`super::locking`] takes over.
pub const MAX_ITERATIONS: usize = 100;

/// Whether any joint has friction.
pub fn present(m: &Mechanism) -> bool {
    m.joints.iter().any(|j| j.friction.is_some_and(|f| f.mu > 0.0))
}

fn sign(v: f64) -> f64 {
    if v > 0.0 {
        1.0
    } else if v < 0.0 {
        -1.0
    } else {
        0.0
    }
}

/// d|x + s·y|/ds at s = 0⁺.
fn signum(x: f64, y: f64) -> f64 {
    if x != 0.0 { x.signum() * y } else { y.abs() }
}

/// What presses a joint, from its normal reaction (λ's part).
#[derive(Clone, Copy, Debug)]
enum Measure {
    /// |R|: a revolute joint's whole force.
    Resultant,
    /// |n · F|: the force across a slide or a contact, n its normal.
    Across([f64; 2]),
    /// |N₁| + |N₂|: a guide of a given length, at its two ends (else as `Across`).
    Ends([f64; 2]),
}

/// A moving joint's friction per unit of what presses it: the force on its
/// second body (at the joint's point, or where a contact touches) and the couple.
#[derive(Clone, Copy, Debug)]
pub struct Unit {
    pub joint: usize,
    force: [f64; 2],
    couple: f64,
    measure: Measure,
    /// Where it acts on the second body and on the first (a contact's
    /// points, found once; else the joint's point).
    at: [[f64; 2]; 2],
}

impl Unit {
    /// The magnitude f that the joint's normal reaction `r` gives.
    pub fn magnitude(&self, r: &Reaction) -> f64 {
        match self.measure {
            Measure::Resultant => r.fx.hypot(r.fy),
            Measure::Across(n) => dot(n, [r.fx, r.fy]).abs(),
            Measure::Ends(n) => r.ends.map_or(dot(n, [r.fx, r.fy]).abs(), |[n1, n2]| n1.abs() + n2.abs()),
        }
    }

    /// The rate at which the magnitude grows at `r` as the reaction grows
    /// by `y`: d/ds g(r + s·y) at s = 0⁺ (|R|'s at R = 0 is |y|).
    pub fn slope(&self, r: &Reaction, y: &Reaction) -> f64 {
        let across = |n: [f64; 2]| signum(dot(n, [r.fx, r.fy]), dot(n, [y.fx, y.fy]));
        match self.measure {
            Measure::Resultant => {
                let size = r.fx.hypot(r.fy);
                if size > 0.0 { (r.fx * y.fx + r.fy * y.fy) / size } else { y.fx.hypot(y.fy) }
            }
            Measure::Across(n) => across(n),
            Measure::Ends(n) => match (r.ends, y.ends) {
                (Some([n1, n2]), Some([y1, y2])) => signum(n1, y1) + signum(n2, y2),
                _ => across(n),
            },
        }
    }

    /// a_k·f added to the generalized forces `qv`.
    pub fn add_generalized(&self, m: &Mechanism, c: &Configuration, f: f64, qv: &mut [f64]) {
        let [i, j] = m.joints[self.joint].bodies;
        let (force, couple) = ([f * self.force[0], f * self.force[1]], f * self.couple);
        add_force(m, &c.trig, qv, j, self.at[0], force, couple);
        add_force(m, &c.trig, qv, i, self.at[1], [-force[0], -force[1]], -couple);
    }

    /// The friction of magnitude f added to the joint's reported reaction.
    pub fn add_to(&self, f: f64, r: &mut Reaction) {
        r.fx += f * self.force[0];
        r.fy += f * self.force[1];
        r.moment += f * self.couple;
    }
}

/// The friction of every joint with friction that moves at this position,
/// per unit of what presses it, into `out`.
pub fn units(m: &Mechanism, c: &Configuration, out: &mut Vec<Unit>) {
    out.clear();
    let pose = |b: usize| m.column(b).map_or((0.0, 0.0), |col| (c.q[col + 2], c.qd[col + 2]));
    let velocity = |b: usize, at: [f64; 2]| {
        m.column(b).map_or([0.0, 0.0], |col| {
            let v = rotate_d(c.q[col + 2], m.local(b, at));
            [c.qd[col] + v[0] * c.qd[col + 2], c.qd[col + 1] + v[1] * c.qd[col + 2]]
        })
    };
    let sliding = |u: [f64; 2], [pj, pi]: [[f64; 2]; 2], [i, j]: [usize; 2]| {
        let (vj, vi) = (velocity(j, pj), velocity(i, pi));
        sign(dot(u, [vj[0] - vi[0], vj[1] - vi[1]]))
    };
    out.extend(m.joints.iter().enumerate().filter_map(|(k, joint)| {
        let f = joint.friction.filter(|f| f.mu > 0.0)?;
        let [i, j] = joint.bodies;
        let mut at = [joint.at; 2];
        let (force, couple, measure) = match joint.kind {
            JointKind::Revolute => ([0.0; 2], -f.mu * f.radius * sign(pose(j).1 - pose(i).1), Measure::Resultant),
            JointKind::Prismatic { axis } | JointKind::PinSlot { axis } => {
                let u = rotate(pose(i).0, axis);
                let slide = sliding(u, at, [i, j]);
                let measure = if joint.length.is_some() { Measure::Ends(perp(u)) } else { Measure::Across(perp(u)) };
                ([-f.mu * slide * u[0], -f.mu * slide * u[1]], 0.0, measure)
            }
            // Rolling: the tangential force is the constraint's own, not friction.
            JointKind::Contact(ref contact) if contact.rolling => return None,
            JointKind::Contact(_) => {
                let touch = Touch::of(m, k, &c.q, Some(&c.trig))?;
                let t = touch.tangent()?;
                at = [touch.point(1), touch.point(0)];
                let slide = sign(touch.sliding(m, t, &c.q, &c.qd));
                ([-f.mu * slide * t[0], -f.mu * slide * t[1]], 0.0, Measure::Across(perp(t)))
            }
            JointKind::Gear { .. } => return None,
        };
        (force != [0.0; 2] || couple != 0.0).then_some(Unit { joint: k, force, couple, measure, at })
    }));
}
