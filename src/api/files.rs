//! A job's files besides its JSON and CSV, as its kind makes them from the
//! stored result (a cam's profile as DXF): `GET /v1/jobs/{id}/{name}`.

use super::AppState;
use super::read::result_tree;
use crate::kind::problem::ApiError;
use axum::extract::{Path, State};
use axum::http::header;
use axum::response::{IntoResponse, Response};

/// One file of a job, made from its stored result by its kind (a cam's
/// `profile.dxf`: the profile as a closed polyline in mm, for CAD).
#[utoipa::path(get, path = "/v1/jobs/{id}/{name}", operation_id = "get_job_file", tag = "jobs",
    params(
        ("id" = String, Path, description = "Job id"),
        ("name" = String, Path, description = "The file's name: `profile.dxf` for a cam"),
    ),
    responses(
        (status = 200, description = "The file, in its content type (`application/dxf` for a DXF)", body = String),
        (status = 404, description = "No job with this id, or no file of this name (the message lists the job's files)",
            body = crate::kind::problem::Problem, content_type = "application/problem+json"),
        (status = 503, description = "Too many large answers are being sent, or the database is unavailable",
            body = crate::kind::problem::Problem, content_type = "application/problem+json"),
        crate::kind::problem::PrivateErrors,
    ))]
pub async fn file(
    State(state): State<AppState>,
    Path((id, name)): Path<(String, String)>,
) -> Result<Response, ApiError> {
    let (row, result, _reserved) = result_tree(&state, &id).await?;
    let kind = state.kinds.find(&row.kind);
    let files = kind.map(|k| k.files()).unwrap_or_default();
    let made = files.iter().find(|(n, _)| *n == name).and_then(|(_, t)| Some((*t, kind?.file(&result, &name)?)));
    let Some((content_type, body)) = made else {
        return Err(ApiError::NoFile { id, name, known: files.iter().map(|(n, _)| (*n).to_string()).collect() });
    };
    let disposition = format!("attachment; filename=\"{}-{id}-{name}\"", row.kind);
    Ok(([(header::CONTENT_TYPE, content_type.to_string()), (header::CONTENT_DISPOSITION, disposition)], body)
        .into_response())
}
