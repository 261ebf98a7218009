//! `POST /v1/kinetostatics`: driving actions and joint reactions of a driven mechanism.

mod loads;
mod located;
mod request;
mod result;

pub(crate) use loads::convert_loads;
pub use loads::{LoadDto, LoadType};
pub(crate) use request::machine_parts;
pub use request::{InputDto, Inputs, KinetostaticsRequest, OutputKind};
pub use result::{KinetostaticsResult, ReactionDto, Scalars, csv_table};

use super::json::JsonBody;
use super::limits::Limits;
use super::problem::{ApiError, FieldError, PostErrors};
use super::{AppState, create, jobs, validated};
use crate::engine::Deadline;
use crate::engine::kinetostatics::solve;
use axum::extract::State;
use axum::response::Response;

/// Inverse dynamics over a range of input positions: driving torque or force,
/// every joint reaction, reduced inertia and torque, checked by virtual power.
#[utoipa::path(post, path = "/v1/kinetostatics", operation_id = "create_kinetostatics_job", tag = "kinetostatics", request_body = KinetostaticsRequest,
    responses(
        (status = 201, description = "Job computed and stored; `result` is a KinetostaticsResult", body = jobs::JobOf<KinetostaticsResult>,
            headers(("Location" = String, description = "/v1/jobs/{id}"))),
        PostErrors,
    ))]
pub async fn create(State(state): State<AppState>, body: JsonBody<KinetostaticsRequest>) -> Result<Response, ApiError> {
    let JsonBody { value, raw, unknown } = body;
    let limits = state.limits.clone();
    create::create(&state, "kinetostatics", raw, move || compute_within(&value, unknown, &limits)).await
}

/// Validates and solves a request within the default limits (`mechdyn solve kinetostatics`).
pub fn compute(request: &KinetostaticsRequest, unknown: Vec<FieldError>) -> Result<KinetostaticsResult, ApiError> {
    compute_within(request, unknown, &Limits::default())
}

/// Validates and solves a request within `limits`, stopping when the compute budget runs out.
pub fn compute_within(
    request: &KinetostaticsRequest,
    unknown: Vec<FieldError>,
    limits: &Limits,
) -> Result<KinetostaticsResult, ApiError> {
    let deadline = Deadline::after(limits.budget);
    let problem = validated(unknown, request.to_problem(limits))?;
    let joint_names: Vec<String> = problem.mechanism.joints.iter().map(|j| j.name.clone()).collect();
    let solve_over = |positions: &[Vec<[f64; 3]>]| {
        solve(&problem.mechanism, &problem.loads, positions, problem.outputs, &deadline)
            .map(|s| KinetostaticsResult::new(s, &problem, &joint_names))
            .map_err(|e| problem.written.explain(e))
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
    let step = first.steps.get(1).map_or(0, |s| create::json_len(s) + 1);
    let estimate = create::json_len(&first) + step * (steps - 2);
    if estimate <= limit {
        return Ok(());
    }
    let rows = create::JobResult::rows(&first).map(|r| create::Rows { count: steps, ..r });
    Err(create::too_large(estimate, limit, rows, true))
}
