//! A joint reaction as the results say it, with its joint's and bodies' names.

use crate::engine::kinetostatics::Reaction;
use serde::{Deserialize, Serialize};
use std::sync::Arc;
use utoipa::ToSchema;

/// A joint's or a body's name in a result: shared by every step that names
/// it (a clone is a count, not a copy), serialized as the string.
pub type Name = Arc<str>;

/// The names as results hold them.
pub fn names(list: &[String]) -> Vec<Name> {
    list.iter().map(|n| Name::from(n.as_str())).collect()
}

/// The force body `by` exerts on body `on` at the joint (ground frame) and the
/// couple about the joint point, the joint's friction included (the force
/// along a slide, the couple of a pin), so that every body's forces
/// balance. Null when redundant constraints leave it undetermined.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct ReactionDto {
    #[schema(value_type = String)]
    pub joint: Name,
    #[schema(value_type = String)]
    pub on: Name,
    #[schema(value_type = String)]
    pub by: Name,
    pub fx: Option<f64>,
    pub fy: Option<f64>,
    pub moment: Option<f64>,
    /// A prismatic joint with a `length`: the normal forces N₁, N₂ at the
    /// guide's ends (at − L/2 and at + L/2 along the axis), N, on `on`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ends: Option<[f64; 2]>,
    pub determinate: bool,
}

impl ReactionDto {
    /// The engine's reaction with its joint and body names.
    pub fn new(r: &Reaction, joint_names: &[Name], body_names: &[Name]) -> Self {
        let v = |x: f64| r.determinate.then_some(x);
        Self {
            joint: joint_names[r.joint].clone(),
            on: body_names[r.on].clone(),
            by: body_names[r.by].clone(),
            fx: v(r.fx),
            fy: v(r.fy),
            moment: v(r.moment),
            ends: r.ends.filter(|_| r.determinate),
            determinate: r.determinate,
        }
    }
}
