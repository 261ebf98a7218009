//! `POST /v1/kinetostatics`: driving actions and joint reactions of a driven mechanism.

mod inputs;
mod located;
mod plots;
mod request;
mod result;
mod shaking;
mod solution;
mod space;
mod table;

pub use request::{KinetostaticsRequest, OutputKind};
pub use result::{KinetostaticsResult, Scalars, StepDto};
pub use table::csv_table;

use crate::engine::kinetostatics::solve_each;
use crate::kind::limits::Limits;
use crate::kind::plots::Plots;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::validated;
use crate::kind::{Kind, Table, unit_in};
use crate::kinds::mechanism::Names;
use serde_json::Value;

/// Kinetostatics: `POST /v1/kinetostatics`.
pub struct Kinetostatics;

impl Kind for Kinetostatics {
    const NAME: &'static str = "kinetostatics";
    const TITLE: &'static str = "kind-kinetostatics";
    const PATH: &'static str = "/v1/kinetostatics";
    const OPERATION_ID: &'static str = "create_kinetostatics_job";
    const TAG: &'static str = "kinetostatics";
    const SUMMARY: &'static str = "Inverse dynamics over a range of input positions: driving torque or force, every joint reaction, reduced inertia and torque, checked by virtual power.";
    const UNITS: &'static [(&'static str, &'static str)] = &[
        ("/dof", "1"),
        ("/grubler/*", "1"),
        ("/redundant_constraints", "1"),
        ("/steps/*/reduced_inertia", "@inertia"),
        ("/steps/*/reduced_torque", "@torque"),
        ("/steps/*/energy_contribution/*", "1"),
        ("/steps/*/jacobian_condition", "1"),
        ("/steps/*/scaled_condition", "1"),
        ("/steps/*/kinematics/*/x", "m"),
        ("/steps/*/kinematics/*/y", "m"),
        ("/steps/*/kinematics/*/theta", "rad"),
        ("/steps/*/kinematics/*/vx", "m/s"),
        ("/steps/*/kinematics/*/vy", "m/s"),
        ("/steps/*/kinematics/*/omega", "rad/s"),
        ("/steps/*/kinematics/*/ax", "m/s^2"),
        ("/steps/*/kinematics/*/ay", "m/s^2"),
        ("/steps/*/kinematics/*/alpha", "rad/s^2"),
        ("/steps/*/kinematics/*/inertia_force/*", "N"),
        ("/steps/*/kinematics/*/inertia_moment", "N*m"),
        ("/assembled_points/*/*", "m"),
        ("/steps/*/points/*/x", "m"),
        ("/steps/*/points/*/y", "m"),
        ("/steps/*/points/*/vx", "m/s"),
        ("/steps/*/points/*/vy", "m/s"),
        ("/steps/*/points/*/ax", "m/s^2"),
        ("/steps/*/points/*/ay", "m/s^2"),
        ("/steps/*/energy/kinetic/total", "J"),
        ("/steps/*/energy/kinetic/bodies/*", "J"),
        ("/steps/*/energy/potential/gravity", "J"),
        ("/steps/*/energy/potential/springs", "J"),
        ("/steps/*/reactions/*/fx", "N"),
        ("/steps/*/reactions/*/fy", "N"),
        ("/steps/*/reactions/*/moment", "N*m"),
        ("/steps/*/reactions/*/force/*", "N"),
        ("/steps/*/reactions/*/moment/*", "N*m"),
        ("/steps/*/reactions/*/magnitude", "N"),
        ("/steps/*/kinematics/*/position/*", "m"),
        ("/steps/*/kinematics/*/rotation/*/*", "1"),
        ("/steps/*/kinematics/*/velocity/*", "m/s"),
        ("/steps/*/kinematics/*/angular_velocity/*", "rad/s"),
        ("/steps/*/kinematics/*/acceleration/*", "m/s^2"),
        ("/steps/*/kinematics/*/angular_acceleration/*", "rad/s^2"),
        ("/steps/*/reactions/*/ends/*", "N"),
        ("/steps/*/reactions/*/normal", "N"),
        ("/steps/*/reactions/*/tangential", "N"),
        ("/steps/*/reactions/*/mu_required", "1"),
        ("/steps/*/contacts/*/point/*", "m"),
        ("/steps/*/contacts/*/sliding_velocity", "m/s"),
        ("/steps/*/contacts/*/velocities/*/*", "m/s"),
        ("/steps/*/contacts/*/normal", "N"),
        ("/steps/*/contacts/*/tangential", "N"),
        ("/steps/*/contacts/*/curvature_radius/*", "m"),
        ("/steps/*/contacts/*/pressure_angle", "rad"),
        ("/steps/*/contacts/*/penetration", "m"),
        ("/steps/*/shaking/force/*", "N"),
        ("/steps/*/shaking/moment", "N*m"),
        ("/steps/*/shaking/balanced_force/*", "N"),
        ("/summary/max_shaking_force", "N"),
        ("/summary/max_shaking_moment", "N*m"),
        ("/summary/max_shaking_force_balanced", "N"),
        ("/counterweights/*/mass_radius", "kg*m"),
        ("/counterweights/*/angle", "rad"),
        ("/summary/max_reaction/*", "N"),
        ("/summary/virtual_power_residual", "1"),
        ("/summary/max_jacobian_condition", "1"),
        ("/summary/max_scaled_condition", "1"),
        ("/accuracy/max_constraint_residual", "m or rad"),
        ("/accuracy/max_newton_iterations", "1"),
        ("/accuracy/max_friction_iterations", "1"),
        ("/accuracy/virtual_power_residual", "1"),
    ];
    type Request = KinetostaticsRequest;
    type Result = KinetostaticsResult;
    const PLOTS: Plots = Plots { list: plots::list, draw: plots::draw };
    const SOLUTION: Option<crate::kind::solution::Solve> = Some(solution::solution);

    fn compute(
        request: &KinetostaticsRequest,
        unknown: Vec<FieldError>,
        limits: &Limits,
    ) -> Result<KinetostaticsResult, ApiError> {
        compute(request, unknown, limits)
    }

    fn table(result: &Value) -> Option<Table> {
        Some(csv_table(result))
    }

    /// Inputs and driving actions are in the units of their input (m and N
    /// for a slider, rad and N·m for a crank), as are I* and M* of the first.
    fn unit(result: &Value, pointer: &[&str]) -> Option<String> {
        let input = |k: usize, key: &str| result["inputs"][k][key].as_str().map(String::from);
        let linear = input(0, "coordinate_unit").is_some_and(|u| u == "m");
        let scalar = |rest: &[&str]| match rest {
            [] => Some(0),
            [k] => k.parse().ok(),
            _ => None,
        };
        match pointer {
            ["steps", _, "input", rest @ ..] => input(scalar(rest)?, "coordinate_unit"),
            ["summary", "singular_inputs" | "near_singular_inputs", _, rest @ ..] => {
                input(scalar(rest)?, "coordinate_unit")
            }
            ["steps", _, "driving", rest @ ..]
            | ["summary", "max_abs_driving" | "mean_driving" | "rms_driving", rest @ ..] => {
                input(scalar(rest)?, "driving_unit")
            }
            _ => match unit_in(Self::UNITS, pointer)? {
                "@inertia" => Some(if linear { "kg" } else { "kg*m^2" }.into()),
                "@torque" => Some(if linear { "N" } else { "N*m" }.into()),
                u => Some(u.into()),
            },
        }
    }
}

/// Validates and solves a request within `limits`, stopping when the compute budget runs out.
fn compute(
    request: &KinetostaticsRequest,
    unknown: Vec<FieldError>,
    limits: &Limits,
) -> Result<KinetostaticsResult, ApiError> {
    if request.mechanism.is_spatial() {
        return space::compute(request, unknown, limits);
    }
    let deadline = limits.deadline();
    let problem = validated(unknown, request.to_problem(limits))?;
    let joint_names: Vec<String> = problem.mechanism.joints.iter().map(|j| j.name.clone()).collect();
    let names = Names::new(&joint_names, &problem.body_names);
    // Each step written as the result says it as soon as it is solved: the
    // engine refills one step and keeps none.
    let solve_over = |positions: &[Vec<[f64; 3]>]| {
        let mut steps = Vec::with_capacity(positions.len());
        let totals = solve_each(&problem.mechanism, &problem.loads, positions, problem.outputs, &deadline, |s| {
            steps.push(StepDto::new(s, &problem, &names));
            Ok(())
        })
        .map_err(|e| problem.written.explain(e))?;
        Ok::<_, ApiError>(KinetostaticsResult::new(totals, steps, &problem, &joint_names))
    };
    if problem.positions.len() > 2 {
        refuse_if_too_large(solve_over(&problem.positions[..2])?, problem.positions.len(), limits.result_bytes)?;
    }
    solve_over(&problem.positions)
}

/// Estimates the size of the result of `steps` positions from the result of
/// the first two (every step has the same fields; the second, away from the
/// drawn position's round numbers, stands for the rest) and refuses the job
/// before it is computed when that is over `limit`.
fn refuse_if_too_large(first: KinetostaticsResult, steps: usize, limit: usize) -> Result<(), ApiError> {
    let step = first.steps.get(1).map_or(0, |s| crate::kind::json_len(s) + 1);
    let estimate = crate::kind::json_len(&first) + step * (steps - 2);
    if estimate <= limit {
        return Ok(());
    }
    let rows = crate::kind::JobResult::rows(&first).map(|r| crate::kind::Rows { count: steps, ..r });
    Err(crate::kind::too_large(estimate, limit, rows, crate::kind::SizeBy::About))
}
