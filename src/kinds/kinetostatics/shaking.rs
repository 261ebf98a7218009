//! What a kinetostatics result says of the frame's shaking and of the
//! counterweights asked for (`engine::shaking`).

use super::request::Problem;
use crate::engine::kinetostatics::Motion;
use crate::engine::shaking::{Counterweight, shaking};
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// The force and moment the moving links' inertia puts on the frame at a
/// step: F = −Σ m·a_G and M = −Σ (r_G × m·a_G + I_G·α) about the origin
/// (with no gravity and no load, the sum of what the links put on the frame).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct ShakingDto {
    /// N.
    pub force: [f64; 2],
    /// About the origin, N·m.
    pub moment: f64,
    /// With the result's `counterweights` added (`balance`): F plus their
    /// inertia forces, N.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub balanced_force: Option<[f64; 2]>,
}

impl ShakingDto {
    /// At motion `m`, where the problem asks for it.
    pub fn new(p: &Problem, m: &Motion) -> Option<Self> {
        if !p.shaking {
            return None;
        }
        let s = shaking(&p.mechanism, m);
        let balanced_force = p
            .balance
            .as_ref()
            .map(|(_, weights)| weights.iter().map(|w| w.force(m)).fold(s.force, |f, c| [f[0] + c[0], f[1] + c[1]]));
        Some(Self { force: s.force, moment: s.moment, balanced_force })
    }
}

/// A counterweight on a link pivoted to the frame.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CounterweightDto {
    pub body: String,
    /// m·r, measured from the link's joint with the frame, kg·m.
    pub mass_radius: f64,
    /// In the link's frame, from the line joining its joint with the frame
    /// to its other joint, CCW, rad.
    pub angle: f64,
}

impl CounterweightDto {
    pub fn new(w: &Counterweight, body_names: &[String]) -> Self {
        Self { body: body_names[w.body].clone(), mass_radius: w.mass_radius, angle: w.angle }
    }
}

/// The largest |F|, |M| and |F| once balanced over the steps that have them.
pub fn largest<'a>(steps: impl Iterator<Item = &'a ShakingDto>) -> [Option<f64>; 3] {
    let bigger = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => Some(a.max(b)),
        (a, b) => a.or(b),
    };
    steps.fold([None; 3], |[f, m, b], s| {
        [
            bigger(f, Some(s.force[0].hypot(s.force[1]))),
            bigger(m, Some(s.moment.abs())),
            bigger(b, s.balanced_force.map(|v| v[0].hypot(v[1]))),
        ]
    })
}
