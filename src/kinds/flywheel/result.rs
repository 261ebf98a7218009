//! The `result` of a flywheel job, as stored and served.

use crate::engine::flywheel as fw;
use crate::i18n::Msg;
use crate::kind::notes::Notes;
use crate::kinds::mechanism::motion::BodyPosition;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use utoipa::ToSchema;

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct AreaDto {
    /// Start of the lobe (rad).
    pub from: f64,
    pub to: f64,
    /// Work of M* over the lobe (J): the textbook's A_i.
    pub work: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct InertiaPair {
    pub approximate: f64,
    pub exact: f64,
}

/// Measured on an independent time simulation of the steady state with `inertia_exact`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct CheckDto {
    pub irregularity: f64,
    /// (ω_max + ω_min)/2 of the simulation, rad/s.
    pub mean_speed: f64,
    pub omega_max: f64,
    pub omega_min: f64,
    /// Duration of one cycle, s.
    pub cycle_time: f64,
    /// |ω(period) − ω(0)|/ω_a of the simulated motion.
    pub periodicity_error: f64,
    pub steps: usize,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct DiskOut {
    /// kg
    pub mass: f64,
    /// m
    pub radius: f64,
    /// m; null without a `density`.
    pub thickness: Option<f64>,
    /// m/s, R·k·ω_a: the rim's mean speed (k the flywheel shaft's `ratio`).
    pub rim_speed: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct AccuracyDto {
    /// Estimated relative error of the works, ΔE and the inertias.
    pub estimated_relative_error: f64,
    /// Summed quadrature error estimate, J.
    pub quadrature_error: f64,
    pub function_evaluations: usize,
    /// max(|ε_check − ε|/ε, |ω_check − ω_a|/ω_a): agreement of the independent check.
    pub check_relative_difference: Option<f64>,
    pub method: String,
}

/// Work of one torque item over a cycle, reduced to the reference shaft.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct ItemWork {
    pub name: String,
    /// J
    pub work: f64,
    /// The item's mean torque on the reference shaft, work over the period
    /// (C* = W/λ, N·m): a constant motor's reduced torque (the balance
    /// torque) or a load's mean.
    pub mean_torque: f64,
}

/// One row of the sampled cycle (also the rows of the CSV export).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(as = FlywheelSample)]
pub struct SampleDto {
    /// φ, rad
    pub angle: f64,
    /// M*(φ), N·m
    pub reduced_torque: f64,
    /// I*(φ), kg·m²
    pub reduced_inertia: f64,
    /// W(φ) = ∫₀^φ M*, J
    pub work: f64,
    /// ω(φ) with the exact inertia, rad/s
    pub speed: f64,
}

/// Result of a flywheel job (SI units: rad, rad/s, N·m, J, W, kg·m², kg, m).
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct FlywheelResult {
    /// Solved balance torque on its own shaft, N·m.
    pub balance_torque: Option<f64>,
    /// Mean power of the torques doing positive work over the cycle, W.
    pub mean_power: f64,
    pub item_work: Vec<ItemWork>,
    /// Angles in (0, period) where M* changes sign.
    pub crossings: Vec<f64>,
    pub areas: Vec<AreaDto>,
    /// S_i: running sums of the areas.
    pub cumulative: Vec<f64>,
    /// ΔE = S_max − S_min, J.
    pub energy_fluctuation: f64,
    /// ΔE/(ε ω_a²), I* neglected: the total inertia on the reference shaft, kg·m².
    pub inertia_approximate: f64,
    /// The total inertia on the reference shaft, exactly (Wittenbauer): the
    /// constant inertia I with which I + I*(φ) runs at exactly ε and ω_a, plus
    /// `least_reduced_inertia` (the machine's inertia there at every angle, a
    /// pulley's), kg·m². The same whether a pulley is a body of the `machine`
    /// or `existing_inertia`.
    pub inertia_exact: f64,
    /// min I*(φ) over the cycle (of `reduced_inertia` and the `machine`), kg·m².
    pub least_reduced_inertia: f64,
    /// What the flywheel adds, on its own shaft: each total less
    /// `existing_inertia` and `least_reduced_inertia`, over ratio², kg·m².
    pub flywheel_inertia: InertiaPair,
    pub omega_max: f64,
    pub omega_min: f64,
    pub phi_at_omega_max: f64,
    pub phi_at_omega_min: f64,
    /// ω at φ = 0 in the exact steady state.
    pub omega_at_start: f64,
    /// ½(I + I*(0))ω(0)², J.
    pub kinetic_energy_at_start: f64,
    pub check: Option<CheckDto>,
    pub disk: Option<DiskOut>,
    pub accuracy: AccuracyDto,
    #[serde(flatten)]
    pub notes: Notes,
    pub samples: Vec<SampleDto>,
    /// Where a machine's points went, for a mechanism given by its `dimensions` (m).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schema(value_type = Option<BTreeMap<String, Vec<f64>>>)]
    pub assembled_points: Option<BTreeMap<String, [f64; 2]>>,
    /// A `machine`'s moving bodies at evenly spaced input angles over the
    /// period (its motion on the page).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub machine_poses: Option<Vec<MachinePose>>,
}

/// A machine's moving bodies at one input angle.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
pub struct MachinePose {
    /// φ, rad.
    pub angle: f64,
    pub bodies: Vec<BodyPosition>,
}

impl crate::kind::JobResult for FlywheelResult {
    fn notes(&mut self) -> Option<&mut Notes> {
        Some(&mut self.notes)
    }
    fn rows(&self) -> Option<crate::kind::Rows> {
        let (field, count) = ("/samples".into(), self.samples.len());
        Some(crate::kind::Rows { field, count, also: "size-also-table" })
    }
}

impl FlywheelResult {
    /// The wire form of `s`, its torque items named by `names`, over a
    /// period of `period` rad.
    pub fn new(s: fw::FlywheelSolution, names: impl Iterator<Item = String>, period: f64) -> Self {
        let mut notes = Notes::default();
        notes.extend(s.warnings.iter().map(condition));
        Self {
            balance_torque: s.balance_torque,
            mean_power: s.mean_power,
            item_work: names
                .zip(&s.item_work)
                .map(|(name, &work)| ItemWork { name, work, mean_torque: work / period })
                .collect(),
            crossings: s.crossings,
            areas: s.areas.iter().map(|a| AreaDto { from: a.from, to: a.to, work: a.work }).collect(),
            cumulative: s.cumulative,
            energy_fluctuation: s.energy_fluctuation,
            inertia_approximate: s.inertia_approximate,
            inertia_exact: s.inertia_exact,
            least_reduced_inertia: s.least_reduced_inertia,
            flywheel_inertia: InertiaPair {
                approximate: s.flywheel_inertia.approximate,
                exact: s.flywheel_inertia.exact,
            },
            omega_max: s.omega_max,
            omega_min: s.omega_min,
            phi_at_omega_max: s.phi_at_omega_max,
            phi_at_omega_min: s.phi_at_omega_min,
            omega_at_start: s.omega_at_start,
            kinetic_energy_at_start: s.kinetic_energy_at_start,
            check: s.check.map(|c| CheckDto {
                irregularity: c.irregularity,
                mean_speed: c.mean_speed,
                omega_max: c.omega_max,
                omega_min: c.omega_min,
                cycle_time: c.cycle_time,
                periodicity_error: c.periodicity_error,
                steps: c.steps,
            }),
            disk: s.disk.map(|d| DiskOut {
                mass: d.mass,
                radius: d.radius,
                thickness: d.thickness,
                rim_speed: d.rim_speed,
            }),
            accuracy: AccuracyDto {
                estimated_relative_error: s.accuracy.estimated_relative_error,
                quadrature_error: s.accuracy.quadrature_error,
                function_evaluations: s.accuracy.function_evaluations,
                check_relative_difference: s.accuracy.check_relative_difference,
                method: notes.say("/accuracy/method", Msg::new("accuracy-flywheel")),
            },
            notes,
            assembled_points: None,
            machine_poses: None,
            samples: s
                .samples
                .iter()
                .map(|r| SampleDto {
                    angle: r.angle,
                    reduced_torque: r.reduced_torque,
                    reduced_inertia: r.reduced_inertia,
                    work: r.work,
                    speed: r.speed,
                })
                .collect(),
        }
    }
}

/// A condition of the solution in words.
fn condition(c: &fw::Condition) -> Msg {
    match c {
        fw::Condition::NetWork { net } => Msg::new("warning-flywheel-net-work").fig("net", *net),
        fw::Condition::CheckIncomplete(e) => Msg::new("warning-flywheel-check").with("why", ode_msg(e)),
        fw::Condition::Degenerate => Msg::new("warning-flywheel-degenerate"),
        fw::Condition::NoDisk { inertia } => Msg::new("warning-flywheel-no-disk").fig("inertia", *inertia),
    }
}

/// Why a time integration stopped, in words.
pub fn ode_msg(e: &crate::engine::numeric::ode::OdeError) -> Msg {
    use crate::engine::numeric::ode::OdeError;
    match *e {
        OdeError::StepTooSmall { t } => Msg::new("warning-ode-step-too-small").fig("t", t),
        OdeError::TooManySteps { steps } => Msg::new("warning-ode-too-many-steps").count("steps", steps),
        OdeError::NotFinite { t } => Msg::new("warning-ode-not-finite").fig("t", t),
    }
}

/// CSV columns of the flywheel table: JSON key of a sample row, header with unit.
pub const CSV_COLUMNS: &[(&str, &str)] = &[
    ("angle", "angle_rad"),
    ("reduced_torque", "reduced_torque_N_m"),
    ("reduced_inertia", "reduced_inertia_kg_m2"),
    ("work", "work_J"),
    ("speed", "speed_rad_s"),
];

/// The CSV table of a stored flywheel result: one row per sample.
pub fn csv_table(result: &serde_json::Value) -> (Vec<String>, Vec<Vec<String>>) {
    let header = CSV_COLUMNS.iter().map(|c| c.1.to_string()).collect();
    let rows = result["samples"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|row| CSV_COLUMNS.iter().map(|c| row[c.0].to_string()).collect())
        .collect();
    (header, rows)
}
