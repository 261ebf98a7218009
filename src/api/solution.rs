//! A job's worked solution at one step, as the course writes it (contract
//! part five, "Free bodies"): `GET /v1/jobs/{id}/solution?step=k`, made by
//! the job's kind from its stored request ([`crate::kind::solution`]).

use super::AppState;
use super::read::{query, result_tree, step as asked_step};
use crate::kind::plots::Job;
use crate::kind::problem::{ApiError, PrivateErrors, ReadErrors};
use crate::kind::solution::Solution;
use axum::Json;
use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use serde_json::Value;
use std::collections::HashMap;

/// Every moving body of a kinetostatics job alone at step k (default 0):
/// each force and couple on it, named as the notes name them (R_ij the
/// force of body i on body j, the ground 1; F_Ij, M_Ij the inertia force
/// and couple; W_j the weight; M_m the driving couple), its three
/// equations of equilibrium with these numbers (each zero to rounding), the
/// order in which the bodies' equations are solved (the Assur groups from
/// the last) with what each group's give, and the same actions' powers,
/// whose sum is zero (virtual power). The step is solved again from the
/// stored request, on the same branch: the numbers are the job's.
#[utoipa::path(get, path = "/v1/jobs/{id}/solution", operation_id = "get_job_solution", tag = "jobs",
    params(
        ("id" = String, Path, description = "Job id"),
        ("step" = Option<usize>, Query, minimum = 0, maximum = 99999, description = "The step, from 0 (the default) \
            to the job's last"),
    ),
    responses(
        (status = 200, description = "The worked solution of the step", body = Solution),
        (status = 400, description = "An unknown query parameter, or `step` given twice or not a whole number within \
            the limit", body = crate::kind::problem::Problem, content_type = "application/problem+json"),
        (status = 422, description = "A step the job has not, or one at a singular position, where no force is solved",
            body = crate::kind::problem::Problem, content_type = "application/problem+json"),
        ReadErrors, PrivateErrors,
    ))]
pub async fn solution(
    State(state): State<AppState>,
    Path(id): Path<String>,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Json<Solution>, ApiError> {
    let q = query(q, &["step"])?;
    let at = asked_step(&q, state.limits.last_step())?.unwrap_or(0);
    Ok(Json(solve(&state, &id, at).await?))
}

/// Step `at` of job `id` solved again by its kind, on a blocking thread within the job budget.
pub async fn solve(state: &AppState, id: &str, at: usize) -> Result<Solution, ApiError> {
    let (row, result, _reserved) = result_tree(state, id).await?;
    let request = serde_json::from_slice::<Value>(&row.request).unwrap_or_default();
    let (kinds, limits, lang) = (state.kinds.clone(), state.limits.started(), crate::i18n::current());
    let (id, kind) = (id.to_string(), row.kind.clone());
    tokio::task::spawn_blocking(move || {
        crate::i18n::within_sync(lang, || {
            let job = Job { request: &request, result: &result };
            let solved = kinds.find(&kind).and_then(|k| k.solution(&job, at, &limits));
            // A kind whose job has no bodies (a run in reduced form) names it without its id.
            match solved {
                None | Some(Err(ApiError::NoSolution { .. })) => Err(ApiError::NoSolution { id, kind }),
                Some(solved) => solved,
            }
        })
    })
    .await
    .map_err(|e| ApiError::Internal(format!("solution: {e}")))?
}
