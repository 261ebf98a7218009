//! The worked solution of one step, as the course writes it (contract part
//! five, "Free bodies"): every moving body isolated with each force and
//! couple on it, named in the notes' notation, and its three equations of
//! equilibrium with those numbers; the order in which the bodies'
//! equations are solved (the Assur groups from the last) and what each
//! group's equations give; the virtual-power check of the same actions. A
//! kind that has free bodies builds this; the service serves it as JSON,
//! draws each body and writes the page.
//!
//! Notation: the bodies are numbered as the notes number them, the ground
//! 1 and the others 2, 3, … in the order the mechanism lists them; R_ij is
//! the force of body i on body j; F_Ij and M_Ij body j's inertia force
//! −m·a_G and couple −I_G·α; W_j its weight; M_m (F_m) an input's driving
//! couple (force), numbered when there are several.

use super::limits::Limits;
use super::plots::Job;
use super::problem::ApiError;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use utoipa::ToSchema;

/// How a kind solves step k of a stored job again and writes it out.
pub type Solve = fn(&Job, usize, &Limits) -> Result<Solution, ApiError>;

/// `GET /v1/jobs/{id}/solution?step=k`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct Solution {
    /// The step (kinetostatics) or sample (dynamics) solved.
    pub step: usize,
    /// Its inputs' coordinates, each in its unit (rad or m).
    pub input: Vec<f64>,
    /// Each body's number, the ground 1.
    pub numbering: BTreeMap<String, usize>,
    /// The moving bodies in the order their equations are solved.
    pub order: Vec<String>,
    /// The groups in that order, each with what its equations give.
    pub groups: Vec<Group>,
    pub bodies: Vec<FreeBody>,
    /// The same actions' powers at the step (the principle of virtual power).
    pub virtual_power: VirtualPower,
}

/// An Assur group (or an input's body with its effort): bodies whose
/// equations, once the groups before are solved, give their unknowns.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct Group {
    pub bodies: Vec<String>,
    /// The reactions and efforts its equations give (`R34`, `M_m`).
    pub unknowns: Vec<String>,
}

/// One body alone, with every action on it.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct FreeBody {
    pub body: String,
    pub number: usize,
    /// Its centre of mass G at the step, m: [x, y], in space [x, y, z].
    pub cg: Vec<f64>,
    pub forces: Vec<Force>,
    pub couples: Vec<Couple>,
    pub equations: Equations,
}

/// A force on the body at the point `at`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct Force {
    /// `R23`, `F_I3`, `W3`, a load's name, `F_m`.
    pub name: String,
    /// `reaction`, `inertia`, `weight`, `load` or `driving`.
    pub kind: String,
    /// The body it comes from (a reaction).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub by: Option<String>,
    /// The joint it acts through (a reaction, a driving effort at a joint).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub joint: Option<String>,
    /// Where it acts at the step, m: [x, y], in space [x, y, z].
    pub at: Vec<f64>,
    /// N
    pub fx: f64,
    /// N
    pub fy: f64,
    /// N, in space.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fz: Option<f64>,
    /// Its power at the step, F·v of its point, W.
    pub power: f64,
}

/// A couple on the body: about z, counter-clockwise positive (seen from +z),
/// and in space about x and y too.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct Couple {
    /// `M_I3`, `M23` (a pin's friction, a guide's couple), `M_m`.
    pub name: String,
    pub kind: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub by: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub joint: Option<String>,
    /// M_z, N·m.
    pub moment: f64,
    /// M_x, N·m, in space.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mx: Option<f64>,
    /// M_y, N·m, in space.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub my: Option<f64>,
    /// M·ω of the body, W.
    pub power: f64,
}

/// The body's three equations with its actions' numbers (six in space):
/// each is zero to rounding.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct Equations {
    /// ΣF_x, N.
    pub sum_fx: f64,
    /// ΣF_y, N.
    pub sum_fy: f64,
    /// ΣM_G, about the body's centre of mass (about z through it in space), N·m.
    pub sum_moment_about_cg: f64,
    /// ΣF_z, N, in space.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sum_fz: Option<f64>,
    /// ΣM_G about x, N·m, in space.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sum_mx_about_cg: Option<f64>,
    /// ΣM_G about y, N·m, in space.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sum_my_about_cg: Option<f64>,
}

/// Each action's power at the step, summed over the bodies: the inputs'
/// driving efforts, the loads, the weights and the inertia forces; the
/// reactions' (the friction's: an ideal joint's two sides cancel); and
/// their sum, zero to rounding.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct VirtualPower {
    /// By action name (`M_m`, `W3`, `F_I3`, `M_I3`, a load's name), W.
    pub actions: BTreeMap<String, f64>,
    /// Every reaction's power summed, W (0 without friction).
    pub reactions: f64,
    /// The sum of all, W.
    pub total: f64,
}
