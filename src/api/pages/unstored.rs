//! The page of a template's job of new values for a browser without the
//! token, where the service keeps its jobs to the token's holders: computed
//! within the anonymous share and stored nowhere, so the page carries
//! everything — its values, and its plots drawn into it as `data:` pictures
//! (no URL of the job's could be read) — with an offer to sign in to keep it.

use super::job::{self, Pictures};
use crate::api::AppState;
use crate::api::plots;
use crate::kind::plots::{Job, Options};
use crate::kind::problem::ApiError;
use crate::store::JobRow;
use maud::Markup;
use percent_encoding::{NON_ALPHANUMERIC, utf8_percent_encode};
use serde_json::Value;

/// Plots drawn into such a page, the first of the job's.
const DRAWN: usize = 6;

/// The page of `row`, a job stored nowhere.
pub async fn page(state: &AppState, row: JobRow) -> Result<Markup, ApiError> {
    let result: Value = serde_json::from_slice(&row.result).map_err(|e| ApiError::Internal(format!("result: {e}")))?;
    let request: Value = serde_json::from_slice(&row.request).unwrap_or_default();
    let kind = state.kinds.find(&row.kind);
    let listed = kind.map(|k| k.plots(&Job { request: &request, result: &result })).unwrap_or_default();
    let names: Vec<String> = listed.into_iter().take(DRAWN).map(|p| p.name).collect();
    let lang = crate::i18n::current();
    let (tree, id) = ((request, result), row.id.clone());
    // Drawn off the async workers, as the plots' own route draws them.
    let drew = tokio::task::spawn_blocking(move || {
        let drawn = crate::i18n::within_sync(lang, || drawn(kind, (&tree.0, &tree.1), &id, &names));
        (drawn, tree.1)
    });
    let (drawn, result) = drew.await.map_err(|e| ApiError::Internal(format!("plots: {e}")))?;
    job::page(state, &row, result, None, Pictures::Inline(&drawn?))
}

/// Each plot of `names` as a `data:` URI of its SVG, by name.
fn drawn(
    kind: Option<&'static dyn crate::api::kind::AnyKind>,
    (request, result): (&Value, &Value),
    id: &str,
    names: &[String],
) -> Result<Vec<(String, String)>, ApiError> {
    let job = Job { request, result };
    let options = Options::default();
    names
        .iter()
        .map(|name| {
            let chart = plots::chart(kind, &job, (id, name), &options)?;
            let svg = plots::animate::render(&chart).map_err(ApiError::Internal)?;
            Ok((
                name.clone(),
                format!("data:image/svg+xml;charset=utf-8,{}", utf8_percent_encode(&svg, NON_ALPHANUMERIC)),
            ))
        })
        .collect()
}
