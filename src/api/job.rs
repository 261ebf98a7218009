//! A stored job as the API answers it: its schema (and a typed one per kind
//! for the document), and its JSON written around the stored bytes.

use super::body::Chunks;
use crate::store::JobRow;
use serde::Serialize;
use serde_json::value::RawValue;
use utoipa::ToSchema;

#[derive(Serialize, ToSchema)]
pub struct Timing {
    /// Wall time of the engine, microseconds.
    pub engine_us: i64,
}

/// A stored computation: the request as sent, and its result.
#[derive(Serialize, ToSchema)]
pub struct Job {
    /// Random UUID.
    pub id: String,
    #[schema(example = "flywheel")]
    pub kind: String,
    /// RFC 3339, UTC.
    pub created_at: String,
    /// The request body exactly as sent.
    #[schema(value_type = Object)]
    pub request: Box<RawValue>,
    /// The result; its schema depends on `kind` (e.g. FlywheelResult).
    #[schema(value_type = Object)]
    pub result: Box<RawValue>,
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

/// Appends the job as JSON, in the order of [`Job`]'s fields: its request
/// and result are the stored bytes themselves.
pub fn job_chunks(r: &JobRow, out: &mut Chunks) {
    let text = |s: &str| serde_json::to_string(s).unwrap_or_default();
    out.push(format!(
        "{{\"id\":{},\"kind\":{},\"created_at\":{},\"request\":",
        text(&r.id),
        text(&r.kind),
        text(&r.created_at)
    ));
    out.push(r.request.clone());
    out.push(&b",\"result\":"[..]);
    out.push(r.result.clone());
    out.push(format!(",\"timing\":{{\"engine_us\":{}}},\"engine_version\":{}", r.engine_us, text(&r.engine_version)));
    match &r.label {
        Some(label) => out.push(format!(",\"label\":{}}}", text(label))),
        None => out.push(&b"}"[..]),
    }
}
