//! Coulomb friction in the joints, which makes the kinetostatic problem
//! nonlinear: the friction forces depend on the reactions they change. Solved
//! by fixed-point iteration on Q_f (generalized friction forces):
//!
//! ```text
//! Φ_qᵀλ_k = Q + Q_f(λ_{k−1}) − M q̈,   until |Q_f,k − Q_f,k−1| ≤ tol·|Q|
//! ```
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
//! joint is λ's (normal) part plus its friction ([`add_to`]): every body's
//! reported forces balance.

use super::Reaction;
use super::loads::add_force;
use crate::engine::kinematics::Configuration;
use crate::engine::model::{JointKind, Mechanism, dot, perp, rotate, rotate_d};
use nalgebra::DVector;

/// Fixed-point iterations allowed per position.
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

/// Q_f for the given reactions (one per joint, in joint order).
pub fn forces(m: &Mechanism, c: &Configuration, reactions: &[Reaction]) -> DVector<f64> {
    let mut qf = DVector::zeros(m.n_coordinates());
    for (k, force, couple) in actions(m, c, reactions) {
        let [i, j] = m.joints[k].bodies;
        // At the joint's point; a contact's where its curves touch now.
        let at = |b: usize| m.contact_point(k, b, &c.q).unwrap_or(m.joints[k].at);
        add_force(m, &c.trig, qf.as_mut_slice(), j, at(j), force, couple);
        add_force(m, &c.trig, qf.as_mut_slice(), i, at(i), [-force[0], -force[1]], -couple);
    }
    qf
}

/// The reported reactions made whole: each joint's friction added to its
/// reaction (the normal part λ gives), so that every body's reported
/// forces balance. The friction is the force on the second body at the
/// joint's point (no moment about it) and, in a revolute joint, its couple.
pub fn add_to(m: &Mechanism, c: &Configuration, reactions: &mut [Reaction]) {
    let all: Vec<_> = actions(m, c, reactions).collect();
    for (k, force, couple) in all {
        // The reactions are in joint order (one per joint).
        if let Some(r) = reactions.get_mut(k).filter(|r| r.joint == k) {
            r.fx += force[0];
            r.fy += force[1];
            r.moment += couple;
        }
    }
}

/// Each joint's friction on its second body, from the normal reactions:
/// (joint, force at the joint's point, couple).
fn actions<'a>(
    m: &'a Mechanism,
    c: &'a Configuration,
    reactions: &'a [Reaction],
) -> impl Iterator<Item = (usize, [f64; 2], f64)> + 'a {
    let pose = |b: usize| m.column(b).map_or((0.0, 0.0), |col| (c.q[col + 2], c.qd[col + 2]));
    let velocity = move |b: usize, at: [f64; 2]| {
        m.column(b).map_or([0.0, 0.0], |col| {
            let v = rotate_d(c.q[col + 2], m.local(b, at));
            [c.qd[col] + v[0] * c.qd[col + 2], c.qd[col + 1] + v[1] * c.qd[col + 2]]
        })
    };
    reactions.iter().filter_map(move |r| {
        let joint = &m.joints[r.joint];
        let f = joint.friction?;
        let [i, j] = joint.bodies;
        match joint.kind {
            JointKind::Revolute => {
                let couple = -f.mu * f.radius * r.fx.hypot(r.fy) * sign(pose(j).1 - pose(i).1);
                Some((r.joint, [0.0, 0.0], couple))
            }
            JointKind::Prismatic { axis } | JointKind::PinSlot { axis } => {
                let u = rotate(pose(i).0, axis);
                let normal = r.ends.map_or(dot(perp(u), [r.fx, r.fy]).abs(), |[n1, n2]| n1.abs() + n2.abs());
                let (vj, vi) = (velocity(j, joint.at), velocity(i, joint.at));
                let slide = sign(dot(u, [vj[0] - vi[0], vj[1] - vi[1]]));
                Some((r.joint, [-f.mu * normal * slide * u[0], -f.mu * normal * slide * u[1]], 0.0))
            }
            // Rolling: the tangential force is the constraint's own, not friction.
            JointKind::Contact(ref contact) if contact.rolling => None,
            JointKind::Contact(_) => {
                let t = m.contact_tangent(r.joint, &c.q)?;
                let normal = dot(perp(t), [r.fx, r.fy]).abs();
                let (pj, pi) = (m.contact_point(r.joint, j, &c.q)?, m.contact_point(r.joint, i, &c.q)?);
                let (vj, vi) = (velocity(j, pj), velocity(i, pi));
                let slide = sign(dot(t, [vj[0] - vi[0], vj[1] - vi[1]]));
                Some((r.joint, [-f.mu * normal * slide * t[0], -f.mu * normal * slide * t[1]], 0.0))
            }
            JointKind::Gear { .. } => None,
        }
    })
}
