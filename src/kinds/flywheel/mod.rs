//! `POST /v1/flywheel`: flywheel design jobs.

mod plots;
mod request;
mod result;

pub use request::{DiskDto, FlywheelDto, FlywheelRequest, MachineDto, TorqueDto};
pub use result::{
    AccuracyDto, AreaDto, CSV_COLUMNS, CheckDto, DiskOut, FlywheelResult, InertiaPair, ItemWork, SampleDto, csv_table,
};

use crate::engine::Progress;
use crate::engine::flywheel::solve;
use crate::engine::machine::Machine;
use crate::kind::limits::Limits;
use crate::kind::plots::Plots;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::Errors;
use crate::kind::{Kind, Table};
use crate::kind::{engine_failure, validated};
use crate::kinds::mechanism::motion::BodyPosition;
use crate::kinds::mechanism::{Assembled, names};
use result::MachinePose;
use serde_json::Value;

/// Flywheel: `POST /v1/flywheel`.
pub struct Flywheel;

impl Kind for Flywheel {
    const NAME: &'static str = "flywheel";
    const TITLE: &'static str = "kind-flywheel";
    const PATH: &'static str = "/v1/flywheel";
    const OPERATION_ID: &'static str = "create_flywheel_job";
    const TAG: &'static str = "flywheel";
    const SUMMARY: &'static str = "Designs a flywheel: balance torque, lobes of M*, energy fluctuation, and the inertia by the approximate and the exact (Wittenbauer) method, checked by a time simulation.";
    const UNITS: &'static [(&'static str, &'static str)] = &[
        ("/accuracy/check_relative_difference", "1"),
        ("/assembled_points/*/*", "m"),
        ("/accuracy/estimated_relative_error", "1"),
        ("/accuracy/function_evaluations", "1"),
        ("/accuracy/quadrature_error", "J"),
        ("/areas/*/from", "rad"),
        ("/areas/*/to", "rad"),
        ("/areas/*/work", "J"),
        ("/balance_torque", "N*m"),
        ("/check/cycle_time", "s"),
        ("/check/irregularity", "1"),
        ("/check/mean_speed", "rad/s"),
        ("/check/omega_max", "rad/s"),
        ("/check/omega_min", "rad/s"),
        ("/check/periodicity_error", "1"),
        ("/check/steps", "1"),
        ("/crossings/*", "rad"),
        ("/cumulative/*", "J"),
        ("/disk/mass", "kg"),
        ("/disk/radius", "m"),
        ("/disk/rim_speed", "m/s"),
        ("/disk/thickness", "m"),
        ("/energy_fluctuation", "J"),
        ("/flywheel_inertia/*", "kg*m^2"),
        ("/inertia_approximate", "kg*m^2"),
        ("/inertia_exact", "kg*m^2"),
        ("/least_reduced_inertia", "kg*m^2"),
        ("/item_work/*/mean_torque", "N*m"),
        ("/item_work/*/work", "J"),
        ("/kinetic_energy_at_start", "J"),
        ("/mean_power", "W"),
        ("/omega_at_start", "rad/s"),
        ("/omega_max", "rad/s"),
        ("/omega_min", "rad/s"),
        ("/phi_at_omega_max", "rad"),
        ("/phi_at_omega_min", "rad"),
        ("/samples/*/angle", "rad"),
        ("/samples/*/reduced_inertia", "kg*m^2"),
        ("/samples/*/reduced_torque", "N*m"),
        ("/samples/*/speed", "rad/s"),
        ("/samples/*/work", "J"),
        ("/machine_poses/*/angle", "rad"),
        ("/machine_poses/*/bodies/*/x", "m"),
        ("/machine_poses/*/bodies/*/y", "m"),
        ("/machine_poses/*/bodies/*/theta", "rad"),
    ];
    type Request = FlywheelRequest;
    type Result = FlywheelResult;
    const PLOTS: Plots = Plots { list: plots::list, draw: plots::draw };

    fn compute(
        request: &FlywheelRequest,
        unknown: Vec<FieldError>,
        limits: &Limits,
    ) -> Result<FlywheelResult, ApiError> {
        compute(request, unknown, limits)
    }

    fn table(result: &Value) -> Option<Table> {
        Some(csv_table(result))
    }
}

/// Validates and solves a request within `limits`, stopping when the compute budget runs out.
fn compute(request: &FlywheelRequest, unknown: Vec<FieldError>, limits: &Limits) -> Result<FlywheelResult, ApiError> {
    let deadline = limits.deadline();
    let (p, machine) =
        validated(unknown, request.to_problem(limits, deadline)).map_err(|e| match deadline.expired() {
            true => {
                ApiError::OverBudget(crate::kind::refused::engine_msg(&deadline.exceeded(Progress::AssemblingMachine)))
            }
            false => e,
        })?;
    let solution = solve(&p).map_err(|e| engine_failure(e, "/torques"))?;
    let mut result = FlywheelResult::new(solution, p.torques.iter().map(|t| t.name.clone()), p.period);
    // Where a machine's dimensions put its points: the sketch solved again
    // (microseconds) rather than carried through the engine's problem.
    if let Some(m) = request.machine.as_ref().filter(|m| m.mechanism.dimensions.is_some())
        && let Some((dto, warnings)) = m.mechanism.assembled(&mut Errors::new(limits), "/machine/mechanism")
        && let Some(a) = Assembled::of(&m.mechanism, &dto, warnings)
    {
        result.notes.extend(a.warnings);
        result.assembled_points = Some(a.points);
    }
    // A spatial machine's motion is not drawn (yet): the page draws the plane's.
    if let Some(request::MachineModel::Planar(m)) = machine {
        result.machine_poses = Some(poses(&m, p.period));
    }
    Ok(result)
}

/// The frames a machine's motion shows over its period.
const POSES: usize = 72;

/// The machine's moving bodies at [`POSES`] evenly spaced angles over the
/// period (where it assembles).
fn poses(m: &Machine, period: f64) -> Vec<MachinePose> {
    let names = names(&m.mechanism().bodies.iter().map(|b| b.name.clone()).collect::<Vec<_>>());
    (0..POSES)
        .map(|k| period * k as f64 / POSES as f64)
        .filter_map(|angle| Some(MachinePose { angle, bodies: BodyPosition::all(&m.pose(angle)?, &names) }))
        .collect()
}
