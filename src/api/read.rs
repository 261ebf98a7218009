//! Reading stored jobs: the memory of the answer reserved before the job is
//! loaded, and the checks every read's query shares.

use super::AppState;
use crate::i18n::Msg;
use crate::kind::problem::{ApiError, FieldError};
use crate::store::JobRow;
use axum::extract::Query;
use axum::extract::rejection::QueryRejection;
use axum::http::{HeaderMap, header};
use serde_json::Value;
use std::collections::HashMap;
use tokio::sync::OwnedSemaphorePermit;

/// The memory of a stored job's answer reserved, then the job loaded.
pub async fn load(state: &AppState, id: &str, factor: usize) -> Result<(JobRow, OwnedSemaphorePermit), ApiError> {
    let size = state.store.size(id).await?.ok_or_else(|| ApiError::NotFound(id.into()))?;
    // In another language than the stored English a result's texts are
    // written again (kind::notes): one more copy.
    let factor = factor + usize::from(crate::i18n::current() != crate::i18n::Lang::En);
    let reserved = state.admission.memory(size.saturating_mul(factor) + 256).await?;
    let row = state.store.get(id).await?.ok_or_else(|| ApiError::NotFound(id.into()))?;
    Ok((row, reserved))
}

/// The job, if it is done: a deferred job queued, running or failed has no result.
pub fn done(row: &JobRow) -> Result<(), ApiError> {
    match row.status {
        crate::store::Status::Done => Ok(()),
        status => Err(ApiError::NotDone { id: row.id.clone(), status }),
    }
}

/// The query of a read: its parameters by name, each checked against `known`.
pub fn query(
    query: Result<Query<HashMap<String, String>>, QueryRejection>,
    known: &[&str],
) -> Result<HashMap<String, String>, ApiError> {
    let Query(q) = query.map_err(|e| ApiError::BadQuery(vec![FieldError::parameter("", e.body_text())]))?;
    // `lang` and `errors` are every answer's ([`super::language`], [`super::plain_errors`]).
    let mut names: Vec<&String> = q.keys().collect();
    names.sort();
    let unknown: Vec<FieldError> = names
        .into_iter()
        .filter(|k| !known.contains(&k.as_str()) && *k != "lang" && *k != "errors")
        .map(|k| FieldError::parameter_said(k, Msg::new("query-unknown").arg("known", known.join(", "))))
        .collect();
    if unknown.is_empty() { Ok(q) } else { Err(ApiError::BadQuery(unknown)) }
}

/// `?format=`, when given, is `csv` or `json` (any case); else a 400.
pub fn format_checked(q: &HashMap<String, String>) -> Result<(), ApiError> {
    match q.get("format").filter(|f| !["csv", "json"].contains(&f.to_ascii_lowercase().as_str())) {
        Some(f) => Err(ApiError::BadQuery(vec![FieldError::parameter_said(
            "format",
            Msg::new("query-format").arg("value", f),
        )])),
        None => Ok(()),
    }
}

/// Whether the client asked for `mime` in `Accept` (or `?format=`).
pub fn wants(headers: &HeaderMap, format: Option<&String>, mime: &str) -> bool {
    let short = mime.rsplit('/').next().unwrap_or(mime);
    if let Some(f) = format {
        return f.eq_ignore_ascii_case(short);
    }
    headers.get_all(header::ACCEPT).iter().filter_map(|v| v.to_str().ok()).any(|v| v.contains(mime))
}

/// The stored result of a job as a JSON tree, with the memory it takes reserved.
pub async fn result_tree(
    state: &AppState,
    id: &str,
) -> Result<(JobRow, Value, tokio::sync::OwnedSemaphorePermit), ApiError> {
    let (row, reserved) = load(state, id, CSV_MEMORY_FACTOR).await?;
    done(&row)?;
    let mut result =
        serde_json::from_slice(&row.result).map_err(|e| ApiError::Internal(format!("stored result: {e}")))?;
    crate::kind::notes::localise(&mut result);
    Ok((row, result, reserved))
}

/// Memory of a read per byte of the stored job: SQLite's copy of the value,
/// sqlx's, and the answer's (measured: 64 readers of a 16 MB job).
pub const READ_MEMORY_FACTOR: usize = 3;
/// The same for a CSV answer or a part of a result: the read, the result as
/// a JSON tree (about eight times its text) and the CSV text.
pub const CSV_MEMORY_FACTOR: usize = 12;

/// `?step=`, when given, a whole number from 0 to `last` (a blank one too
/// is a 400: the document says integer, and the page's form requires the
/// field); whether the job has that step is its reader's to say.
pub fn step(q: &HashMap<String, String>, last: usize) -> Result<Option<usize>, ApiError> {
    q.get("step")
        .map(|s| {
            s.trim().parse::<usize>().ok().filter(|&n| n <= last).ok_or_else(|| {
                let why = crate::i18n::Msg::new("query-step").arg("text", s).arg("last", last);
                ApiError::BadQuery(vec![FieldError::parameter_said("step", why)])
            })
        })
        .transpose()
}
