//! `POST /v1/flywheel`: flywheel design jobs.

mod request;
mod result;

pub use request::{DiskDto, FlywheelDto, FlywheelRequest, MachineDto, TorqueDto};
pub use result::{
    AccuracyDto, AreaDto, CSV_COLUMNS, CheckDto, DiskOut, FlywheelResult, InertiaPair, ItemWork, SampleDto, csv_table,
};

use super::json::JsonBody;
use super::limits::Limits;
use super::problem::{ApiError, FieldError, PostErrors};
use super::{AppState, create, engine_failure, jobs, validated};
use crate::engine::Deadline;
use crate::engine::flywheel::solve;
use axum::extract::State;
use axum::response::Response;

/// Designs a flywheel: balance torque, lobes of M*, energy fluctuation, and the
/// inertia by the approximate and the exact (Wittenbauer) method, checked by a
/// time simulation.
#[utoipa::path(post, path = "/v1/flywheel", operation_id = "create_flywheel_job", tag = "flywheel", request_body = FlywheelRequest,
    responses(
        (status = 201, description = "Job computed and stored; `result` is a FlywheelResult", body = jobs::JobOf<FlywheelResult>,
            headers(("Location" = String, description = "/v1/jobs/{id}"))),
        PostErrors,
    ))]
pub async fn create(State(state): State<AppState>, body: JsonBody<FlywheelRequest>) -> Result<Response, ApiError> {
    let JsonBody { value, raw, unknown } = body;
    let limits = state.limits.clone();
    create::create(&state, "flywheel", raw, move || compute_within(&value, unknown, &limits)).await
}

/// Validates and solves a request within the default limits (`mechdyn solve flywheel`).
pub fn compute(request: &FlywheelRequest, unknown: Vec<FieldError>) -> Result<FlywheelResult, ApiError> {
    compute_within(request, unknown, &Limits::default())
}

/// Validates and solves a request within `limits`, stopping when the compute budget runs out.
pub fn compute_within(
    request: &FlywheelRequest,
    unknown: Vec<FieldError>,
    limits: &Limits,
) -> Result<FlywheelResult, ApiError> {
    let deadline = Deadline::after(limits.budget);
    let p = validated(unknown, request.to_problem(limits, deadline)).map_err(|e| match deadline.expired() {
        true => ApiError::OverBudget(deadline.exceeded("while assembling the machine".into()).to_string()),
        false => e,
    })?;
    let solution = solve(&p).map_err(|e| engine_failure(e, "/torques"))?;
    Ok(FlywheelResult::new(solution, p.torques.iter().map(|t| t.name.clone())))
}
