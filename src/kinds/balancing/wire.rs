//! The balancing kind's request and result as the wire carries them.

use crate::kind::notes::Notes;
use crate::kind::quantity::Quantity;
use crate::kinds::rotor::RotorRequest;
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// A rigid rotor turning about z: its unbalance as point masses (`masses`)
/// or as a rotor request's body (`rotor`, its x' axis the rotor's z), and
/// one correction plane (static balancing) or two (dynamic). With `speed`
/// and `bearings` (or the rotor's own frame speed and bearings) the
/// bearing forces before and after balancing.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({
    "masses": [
        {"mass": "0.2 kg", "radius": "100 mm", "angle": "30 deg", "plane": "50 mm"},
        {"mass": "0.15 kg", "radius": "80 mm", "angle": "150 deg", "plane": "200 mm"},
        {"mass": "0.1 kg", "radius": "120 mm", "angle": "270 deg", "plane": "350 mm"}
    ],
    "planes": [{"z": "0 mm", "radius": "100 mm"}, {"z": "400 mm", "radius": "100 mm"}],
    "speed": "1500 rpm",
    "bearings": ["-50 mm", "450 mm"]
}))]
pub struct BalancingRequest {
    /// Point masses (not with `rotor`), at most 1000.
    #[schema(min_items = 1, max_items = 1000)]
    pub masses: Option<Vec<PointMassDto>>,
    /// A rotor request's body (its mass, inertia with products, cg, bearings
    /// and frame), as `POST /v1/rotor` takes it (not with `masses`).
    pub rotor: Option<RotorRequest>,
    /// One plane (static balancing) or two (dynamic), in any order.
    #[schema(min_items = 1, max_items = 2)]
    pub planes: Vec<CorrectionPlaneDto>,
    /// The rotor's speed for the bearing forces (default: the rotor's frame speed).
    #[schema(value_type = Option<Quantity>)]
    pub speed: Option<Quantity>,
    /// z of bearings A and B (default: the rotor's bearings).
    #[schema(value_type = Option<Vec<Quantity>>, min_items = 2, max_items = 2)]
    pub bearings: Option<[Quantity; 2]>,
}

/// A point mass: its mass, radius and angle (CCW from the rotor's x axis) in the plane at z = `plane`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct PointMassDto {
    #[schema(value_type = Quantity)]
    pub mass: Quantity,
    #[schema(value_type = Quantity)]
    pub radius: Quantity,
    #[schema(value_type = Quantity)]
    pub angle: Quantity,
    #[schema(value_type = Quantity)]
    pub plane: Quantity,
}

/// A correction plane: its axial position and the radius where its mass is put.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CorrectionPlaneDto {
    #[schema(value_type = Quantity)]
    pub z: Quantity,
    #[schema(value_type = Quantity)]
    pub radius: Quantity,
}

/// A vector by its size and its angle (rad, CCW from the rotor's x axis, in [0, 2π)).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct UnbalanceDto {
    pub value: f64,
    pub angle: f64,
}

/// The dynamic unbalance D = Σ m·r·(z − z₁)·e^{iθ} about the first correction plane z₁ (`about`).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct DynamicUnbalanceDto {
    pub value: f64,
    pub angle: f64,
    pub about: f64,
}

/// The mass to add in a plane: at the plane's radius and angle; m·R.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct BalancingCorrectionDto {
    /// z of the plane.
    pub plane: f64,
    pub radius: f64,
    pub mass: f64,
    pub angle: f64,
    pub mass_radius: f64,
}

/// The unbalance left after the corrections: |U| and |D(z₁)| (rounding
/// alone with two planes; one plane leaves the couple).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct BalancingResidualDto {
    #[serde(rename = "static")]
    pub static_: f64,
    pub dynamic: f64,
}

/// The forces bearings A and B put on the rotor turning at `speed` with no
/// other load, [[Fx, Fy], [Fx, Fy]] in the rotor's frame at angle 0, before
/// and after the corrections.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct BearingForcesDto {
    pub speed: f64,
    pub bearings: [f64; 2],
    pub before: [[f64; 2]; 2],
    pub after: [[f64; 2]; 2],
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct BalancingResult {
    /// U = Σ m·r·e^{iθ}.
    pub static_unbalance: UnbalanceDto,
    pub dynamic_unbalance: DynamicUnbalanceDto,
    /// One per plane, ordered by z.
    pub corrections: Vec<BalancingCorrectionDto>,
    pub residual: BalancingResidualDto,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reactions: Option<BearingForcesDto>,
    pub method: String,
    #[serde(flatten)]
    pub notes: Notes,
}

impl crate::kind::JobResult for BalancingResult {
    fn notes(&mut self) -> Option<&mut Notes> {
        Some(&mut self.notes)
    }
}
