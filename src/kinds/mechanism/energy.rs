//! A mechanism's energies as results say them (a kinetostatics step's, a
//! dynamics sample's).

use super::Name;
use crate::engine::kinetostatics::Energy;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use utoipa::ToSchema;

/// The mechanism's energies, J.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct EnergyDto {
    pub kinetic: KineticEnergy,
    pub potential: PotentialEnergy,
}

/// T = Σ ½(m v_G² + I_G ω²), and each moving body's share.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct KineticEnergy {
    pub total: f64,
    #[schema(value_type = BTreeMap<String, f64>)]
    pub bodies: BTreeMap<Name, f64>,
}

/// Gravity's −Σ m g·r_G (r_G from the drawing's origin) and the springs' Σ ½k(l − l₀)².
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct PotentialEnergy {
    pub gravity: f64,
    pub springs: f64,
}

impl EnergyDto {
    /// The energies of the engine's at (q, q̇), the moving bodies named by `names` (ground first).
    pub fn new(e: Energy, names: &[Name]) -> Self {
        let bodies = names[1..].iter().cloned().zip(e.bodies).collect();
        EnergyDto {
            kinetic: KineticEnergy { total: e.kinetic, bodies },
            potential: PotentialEnergy { gravity: e.gravity, springs: e.springs },
        }
    }
}
