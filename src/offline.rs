//! The binary's offline commands, for grader containers without a network:
//! `solve`, `check` and `grade` give what the service answers, through the
//! same code: `solve` the kind's computation ([`crate::api::kind::AnyKind::solve`]),
//! `check` and `grade` the service's handlers' functions on a store held in
//! memory (so a reference job is computed once per parameter set, as in the
//! service, and nothing is written to disk).

use crate::api::check::{CheckRequest, check_job};
use crate::api::create::Destination;
use crate::api::kind::Registry;
use crate::api::templates::{Template, builtin};
use crate::api::{AppState, json, parts};
use crate::kind::Limits;
use crate::kind::problem::ApiError;
use crate::store::Store;
use std::collections::HashMap;

/// The result of `raw` of `kind` as the service stores it; with `value`,
/// the part at that pointer (in `unit`) as `GET .../result/{pointer}` answers it.
pub fn solve(
    kinds: &Registry,
    kind: &str,
    raw: String,
    value: Option<&str>,
    unit: Option<&String>,
) -> Result<Vec<u8>, ApiError> {
    let Some(k) = kinds.find(kind) else {
        let why =
            crate::i18n::Msg::new("template-kind-unknown").arg("kind", kind).arg("known", kinds.names().join(", "));
        return Err(ApiError::Invalid(vec![crate::kind::problem::FieldError::said("", why)]));
    };
    let result = k.solve(raw, &Limits::default(), kinds)?;
    let Some(pointer) = value else { return Ok(result) };
    let tree: serde_json::Value = serde_json::from_slice(&result).map_err(|e| ApiError::Internal(e.to_string()))?;
    let part = parts::value_at(Some(k), &tree, pointer, unit)?;
    let pointer = format!("/{}", pointer.trim_start_matches('/'));
    let part = part.ok_or(ApiError::NoPart { id: "(offline)".into(), pointer })?;
    Ok(parts::text_of(&part, false, Default::default()).1.into_bytes())
}

/// The service's state, of `kinds`, on a store in memory.
async fn state(kinds: &Registry) -> Result<AppState, ApiError> {
    let store =
        Store::open("sqlite::memory:").await.map_err(|e| ApiError::Internal(format!("in-memory store: {e}")))?;
    Ok(AppState::new(store, kinds.clone()))
}

fn runtime() -> Result<tokio::runtime::Runtime, ApiError> {
    tokio::runtime::Builder::new_current_thread().enable_all().build().map_err(|e| ApiError::Internal(e.to_string()))
}

/// The result of the check `raw` (a `POST /v1/check` body), as the service stores it.
pub fn check(kinds: &Registry, raw: String) -> Result<Vec<u8>, ApiError> {
    runtime()?.block_on(async {
        let state = state(kinds).await?;
        let (row, _) = check_job(&state, json::parse::<CheckRequest>(raw)?, Destination::POSTED).await?;
        Ok(row.result.to_vec())
    })
}

/// A template by built-in id, or read from a file (a template as `GET /v1/templates/{id}` answers it).
pub fn template(name: &str) -> Result<Template, String> {
    if let Some(t) = builtin().iter().find(|t| t.id == name) {
        return Ok(t.clone());
    }
    let ids: Vec<&str> = builtin().iter().map(|t| t.id.as_str()).collect();
    let text = std::fs::read_to_string(name).map_err(|e| {
        format!("'{name}' is neither a built-in template ({}) nor a readable file: {e}", ids.join(", "))
    })?;
    serde_json::from_str(&text).map_err(|e| format!("{name}: not a template: {e}"))
}

/// The graded class CSV `body` for template `t`, with the query of
/// `POST /v1/templates/{id}/grade` (`relative`, `sigfigs`, `reveal`, ...).
pub fn grade(kinds: &Registry, t: &Template, query: &HashMap<String, String>, body: &[u8]) -> Result<String, ApiError> {
    runtime()?.block_on(async { crate::api::check::class::class(&state(kinds).await?, t, query, body).await })
}
