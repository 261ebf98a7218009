//! A stored job as the API answers it: its schema (and a typed one per kind
//! for the document), and its JSON written around the stored bytes.

use super::body::Chunks;
use crate::store::{JobRow, Status};
use serde::Serialize;
use serde_json::value::RawValue;
use utoipa::ToSchema;

#[derive(Serialize, ToSchema)]
pub struct Timing {
    /// Wall time of the engine, microseconds.
    pub engine_us: i64,
}

/// Where a job is. A POST answered at once stores its job `done`; one sent
/// with `Prefer: respond-async` is `queued`, then `running` on a replica,
/// then `done` or `failed`.
#[derive(Serialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum JobStatus {
    Queued,
    Running,
    Done,
    Failed,
}

/// A stored computation: the request as sent, and its result.
#[derive(Serialize, ToSchema)]
pub struct Job {
    /// Random UUID.
    pub id: String,
    #[schema(example = "flywheel")]
    pub kind: String,
    pub status: JobStatus,
    /// RFC 3339, UTC.
    pub created_at: String,
    /// The request body exactly as sent.
    #[schema(value_type = Object)]
    pub request: Box<RawValue>,
    /// The result; its schema depends on `kind` (e.g. FlywheelResult).
    /// Absent until the job is done.
    #[schema(value_type = Option<Object>)]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub result: Option<Box<RawValue>>,
    /// Why the job failed (a `failed` job's problem, as a POST answered at
    /// once would have answered it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub problem: Option<crate::kind::problem::Problem>,
    /// The engine's time: 0 until the job has been computed.
    pub timing: Timing,
    /// Version of mechdyn that computed the result.
    pub engine_version: String,
    /// The label stored with the job (`?label=` on its POST); absent without one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub label: Option<String>,
}

/// A job of one kind, for the OpenAPI document (the answer of a POST): its
/// `result` has that kind's schema. The same fields as [`Job`].
#[derive(ToSchema)]
#[allow(dead_code)]
pub struct JobOf<R> {
    /// Random UUID.
    id: String,
    kind: String,
    /// `done` (answered at once); a POST with `Prefer: respond-async` is
    /// answered 202 with the job `queued`.
    status: JobStatus,
    /// RFC 3339, UTC.
    created_at: String,
    /// The request body exactly as sent.
    #[schema(value_type = Object)]
    request: (),
    result: R,
    timing: Timing,
    /// Version of mechdyn that computed the result.
    engine_version: String,
    /// The label stored with the job (`?label=` on its POST); absent without one.
    label: Option<String>,
}

/// A page of jobs, newest first.
#[derive(Serialize, ToSchema)]
pub struct JobList {
    pub items: Vec<Job>,
    /// Relative URL of the next page, or null on the last one.
    pub next: Option<String>,
}

/// Appends the job as JSON, in the order of [`Job`]'s fields: its request,
/// result and problem are the stored bytes themselves (a result's texts
/// written again in the asker's language: [`crate::kind::notes`]).
pub fn job_chunks(r: &JobRow, out: &mut Chunks) {
    let text = |s: &str| serde_json::to_string(s).unwrap_or_default();
    out.push(format!(
        "{{\"id\":{},\"kind\":{},\"status\":\"{}\",\"created_at\":{},\"request\":",
        text(&r.id),
        text(&r.kind),
        r.status.as_str(),
        text(&r.created_at)
    ));
    out.push(r.request.clone());
    if r.status == Status::Done {
        out.push(&b",\"result\":"[..]);
        match crate::kind::notes::localise_bytes(&r.result) {
            Some(said) => out.push(said),
            None => out.push(r.result.clone()),
        }
    }
    if let Some(problem) = &r.problem {
        out.push(&b",\"problem\":"[..]);
        out.push(problem.clone());
    }
    out.push(format!(",\"timing\":{{\"engine_us\":{}}},\"engine_version\":{}", r.engine_us, text(&r.engine_version)));
    match &r.label {
        Some(label) => out.push(format!(",\"label\":{}}}", text(label))),
        None => out.push(&b"}"[..]),
    }
}
