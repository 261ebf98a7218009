//! The energies of a spatial mechanism: T of its bodies, V of gravity and
//! its springs.

use super::model::{Body, Load, Mechanism, Pose};
use crate::engine::kinetostatics::Energy;
use nalgebra::{DVector, Vector3};

/// T_b = ½m|ṙ|² + ½ω·J·ω of every body at (pose, v), V of gravity
/// (−Σ m·g·r) and of the springs (Σ ½k(L − L₀)²) at `pose`.
pub fn energy(m: &Mechanism, loads: &[Load], pose: &Pose, v: &DVector<f64>) -> Energy {
    let body = |(b, body): (usize, &Body)| {
        let rot = pose.rotation(b + 1);
        let omega = Vector3::from(v.fixed_rows::<3>(6 * b + 3));
        let rdot = Vector3::from(v.fixed_rows::<3>(6 * b));
        0.5 * body.mass * rdot.norm_squared() + 0.5 * omega.dot(&(rot * body.inertia * rot.transpose() * omega))
    };
    let bodies: Vec<f64> = m.bodies.iter().enumerate().map(body).collect();
    let gravity = m.bodies.iter().zip(&pose.r).map(|(b, r)| -b.mass * m.gravity.dot(r)).sum();
    let springs = loads
        .iter()
        .map(|l| match l {
            Load::Spring { bodies, at, k, length, .. } => {
                let ends = [0, 1].map(|e| pose.point(m, bodies[e], &at[e]).0);
                0.5 * k * ((ends[1] - ends[0]).norm() - length).powi(2)
            }
            _ => 0.0,
        })
        .sum();
    Energy { kinetic: bodies.iter().sum(), bodies, gravity, springs }
}

/// T at (pose, v).
pub fn kinetic(m: &Mechanism, pose: &Pose, v: &DVector<f64>) -> f64 {
    energy(m, &[], pose, v).kinetic
}
