//! Flywheel design for a machine in steady state.
//!
//! Symbols (one shaft, the *reference*, whose angle φ runs over a period λ):
//! - M*(φ): total reduced torque, Σ kᵢ·Mᵢ(φ) over the torques on shafts turning
//!   kᵢ times the reference (kᵢ = ωᵢ/ω_ref, power equality);
//! - I*(φ): reduced inertia of the machine without flywheel;
//! - ω_a = (ω_max + ω_min)/2 and ε = (ω_max − ω_min)/ω_a;
//! - W(φ) = ∫₀^φ M*; A_i the work of each lobe of M* between sign changes,
//!   S_i their running sum, ΔE = S_max − S_min (S₀ = 0 included).
//!
//! Approximate inertia ΔE/(ε ω_a²) neglects I*; the exact one follows
//! Wittenbauer ([`wittenbauer`]); a time simulation checks it ([`check`]).

mod check;
mod cycle;
mod lobes;
mod solve;
mod wittenbauer;

pub use check::Check;
pub use lobes::Area;
pub use solve::solve;

use super::Deadline;
use super::function::Function;

/// How a torque item is given.
#[derive(Clone, Debug)]
pub enum Load {
    Given(Function),
    /// A constant torque solved so that the work over a cycle is zero.
    Balance,
}

/// A torque acting on the machine, positive when it drives it.
#[derive(Clone, Debug)]
pub struct TorqueItem {
    pub name: String,
    pub load: Load,
    /// ω of its shaft / ω of the reference shaft.
    pub ratio: f64,
    /// Where the item came from, for error messages (e.g. a JSON pointer).
    pub label: String,
}

/// How to size a solid disk flywheel: I = ½MR², M = ρπR²e, v = R·k·ω_a.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DiskSize {
    RimSpeed(f64),
    Radius(f64),
    Thickness(f64),
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiskSpec {
    /// ρ (kg/m³): needed for the thickness (and to size by it), not for M = 2I/R².
    pub density: Option<f64>,
    pub size: DiskSize,
}

/// A validated flywheel problem in SI units.
#[derive(Clone, Debug)]
pub struct FlywheelProblem {
    /// λ (rad of the reference shaft).
    pub period: f64,
    /// ω_a (rad/s).
    pub mean_speed: f64,
    /// ε, in (0, 2).
    pub irregularity: f64,
    pub torques: Vec<TorqueItem>,
    pub reduced_inertia: Function,
    pub reduced_inertia_label: String,
    /// Inertia already on the reference shaft (kg·m²).
    pub existing_inertia: f64,
    /// k of the flywheel's shaft.
    pub flywheel_ratio: f64,
    pub disk: Option<DiskSpec>,
    /// Requested relative accuracy.
    pub tolerance: f64,
    /// Run the time-simulation check.
    pub check: bool,
    /// Rows of the sampled table (0: none), evenly spaced over [0, λ].
    pub samples: usize,
    /// The compute budget, checked between the phases of the solution.
    pub deadline: Deadline,
}

/// Flywheel inertia on its own shaft by both methods.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pair {
    pub approximate: f64,
    pub exact: f64,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disk {
    pub mass: f64,
    pub radius: f64,
    /// None without a density.
    pub thickness: Option<f64>,
    pub rim_speed: f64,
}

/// One row of the sampled cycle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SamplePoint {
    pub angle: f64,
    pub reduced_torque: f64,
    pub reduced_inertia: f64,
    /// W(φ), J.
    pub work: f64,
    /// ω(φ) with the exact inertia, rad/s.
    pub speed: f64,
}

/// How accurate the results are and how that was estimated.
#[derive(Clone, Debug, PartialEq)]
pub struct Accuracy {
    pub estimated_relative_error: f64,
    /// Summed quadrature error estimate of the works (J).
    pub quadrature_error: f64,
    pub function_evaluations: usize,
    /// Largest relative difference between the check and the request (ε, ω_a).
    pub check_relative_difference: Option<f64>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct FlywheelSolution {
    pub balance_torque: Option<f64>,
    pub mean_power: f64,
    /// Work of each torque item over a cycle, reduced to the reference shaft (J).
    pub item_work: Vec<f64>,
    pub crossings: Vec<f64>,
    pub areas: Vec<Area>,
    pub cumulative: Vec<f64>,
    pub energy_fluctuation: f64,
    /// ΔE/(ε ω_a²): the total inertia on the reference shaft, I* neglected.
    pub inertia_approximate: f64,
    /// The total exactly (Wittenbauer): the constant I with which I + I*(φ)
    /// runs at ε, plus I*'s least (the machine's inertia at every angle).
    pub inertia_exact: f64,
    /// min I*(φ) over the cycle (kg·m²).
    pub least_reduced_inertia: f64,
    /// What the flywheel adds, on its own shaft: the totals less the
    /// existing inertia and I*'s least, over k².
    pub flywheel_inertia: Pair,
    pub omega_max: f64,
    pub omega_min: f64,
    pub phi_at_omega_max: f64,
    pub phi_at_omega_min: f64,
    pub omega_at_start: f64,
    pub kinetic_energy_at_start: f64,
    pub check: Option<Check>,
    pub disk: Option<Disk>,
    pub samples: Vec<SamplePoint>,
    pub accuracy: Accuracy,
    pub warnings: Vec<Condition>,
}

/// A condition met on the way that the result reports (the kind says it in
/// words).
#[derive(Clone, Debug, PartialEq)]
pub enum Condition {
    /// The works of a cycle add up to `net` J (≠ 0, within the tolerance):
    /// the loads are used as given.
    NetWork { net: f64 },
    /// The time-integration check failed; the solution stands without it.
    CheckIncomplete(crate::engine::numeric::ode::OdeError),
    /// M* ≡ 0 and I* constant: the speed is constant for any inertia.
    Degenerate,
    /// The flywheel inertia needed, `inertia` kg·m², is not positive: no disk.
    NoDisk { inertia: f64 },
}

#[cfg(test)]
mod tests;
