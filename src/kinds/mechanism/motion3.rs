//! What a spatial mechanism's step says (contract part five): each body's
//! motion with its rotation matrix, each joint's reaction as a force and a
//! moment, vectors in ground axes.

use crate::engine::spatial::{Mechanism, Pose, Reaction};
use crate::kinds::mechanism::Name;
use nalgebra::DVector;
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// A body in space: its centre of mass's position, velocity and
/// acceleration, its rotation from the drawing, its angular velocity and
/// acceleration (ground axes, SI).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct BodyMotion3 {
    #[schema(value_type = String)]
    pub body: Name,
    pub position: [f64; 3],
    /// R, the rotation from the drawn body to the body now (rows).
    pub rotation: [[f64; 3]; 3],
    pub velocity: [f64; 3],
    pub angular_velocity: [f64; 3],
    pub acceleration: [f64; 3],
    pub angular_acceleration: [f64; 3],
}

/// A joint's reaction on its second body (`on`) by its first (`by`): the
/// force, and the moment about the joint's point as `on` carries it.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct Reaction3 {
    pub joint: String,
    pub on: String,
    pub by: String,
    pub force: [f64; 3],
    pub moment: [f64; 3],
    /// |force|, N.
    pub magnitude: f64,
    /// False where the joint's rows are redundant: equilibrium cannot
    /// tell its share (this is the share of least norm).
    pub determinate: bool,
}

impl BodyMotion3 {
    /// Body b ≥ 1, named `name`, at (pose, v, a).
    pub fn new(name: &str, b: usize, pose: &Pose, v: &DVector<f64>, a: &DVector<f64>) -> Self {
        let rot = pose.rotation(b);
        let at = |x: &DVector<f64>, k: usize| vector(&x.as_slice()[6 * (b - 1) + k..]);
        BodyMotion3 {
            body: Name::from(name),
            position: vector(pose.r[b - 1].as_slice()),
            rotation: [0, 1, 2].map(|i| [0, 1, 2].map(|j| rot[(i, j)])),
            velocity: at(v, 0),
            angular_velocity: at(v, 3),
            acceleration: at(a, 0),
            angular_acceleration: at(a, 3),
        }
    }
}

impl Reaction3 {
    /// The engine's reaction, with the joints' and bodies' names (the ground's first).
    pub fn new(r: &Reaction, m: &Mechanism, body_names: &[String]) -> Self {
        Reaction3 {
            joint: m.joints[r.joint].name.clone(),
            on: body_names[r.on].clone(),
            by: body_names[r.by].clone(),
            force: vector(r.wrench.force.as_slice()),
            moment: vector(r.wrench.moment.as_slice()),
            magnitude: r.wrench.force.norm(),
            determinate: r.determinate,
        }
    }
}

/// The first three numbers of `v`.
fn vector(v: &[f64]) -> [f64; 3] {
    [v[0], v[1], v[2]]
}

/// A joint's reaction in a CSV: where in the item, and the column's name.
pub const REACTION_3: [(&str, &str); 6] = [
    ("/force/0", "fx_N"),
    ("/force/1", "fy_N"),
    ("/force/2", "fz_N"),
    ("/moment/0", "mx_N_m"),
    ("/moment/1", "my_N_m"),
    ("/moment/2", "mz_N_m"),
];

/// A body's motion in a CSV: where in the item, and the column's name.
pub const MOTION_3: [(&str, &str); 15] = [
    ("/position/0", "x_m"),
    ("/position/1", "y_m"),
    ("/position/2", "z_m"),
    ("/velocity/0", "vx_m_s"),
    ("/velocity/1", "vy_m_s"),
    ("/velocity/2", "vz_m_s"),
    ("/angular_velocity/0", "omega_x_rad_s"),
    ("/angular_velocity/1", "omega_y_rad_s"),
    ("/angular_velocity/2", "omega_z_rad_s"),
    ("/acceleration/0", "ax_m_s2"),
    ("/acceleration/1", "ay_m_s2"),
    ("/acceleration/2", "az_m_s2"),
    ("/angular_acceleration/0", "alpha_x_rad_s2"),
    ("/angular_acceleration/1", "alpha_y_rad_s2"),
    ("/angular_acceleration/2", "alpha_z_rad_s2"),
];
