//! What a spatial mechanism's step says (contract part five): each body's
//! motion with its rotation matrix, each joint's reaction as a force and a
//! moment, vectors in ground axes.

use crate::kinds::mechanism::Name;
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
