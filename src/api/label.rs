//! `?label=TEXT` on any POST: a label stored with the job the POST creates
//! (e.g. a student's id), listed and filtered by `GET /v1/jobs?label=`.
//!
//! The middleware reads it from the query and keeps it for the request's
//! task ([`LABEL`]), where [`super::create::compute_and_store`] finds it:
//! every POST gets it without a line of its own. Jobs stored under a request
//! key (a template's parameters, a check's reference) are shared between
//! requests and carry no label.

use crate::i18n::Msg;
use crate::kind::problem::{ApiError, FieldError};
use axum::extract::{Query, Request};
use axum::http::Method;
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use std::collections::HashMap;

/// Longest label, characters.
pub const MAX_LABEL: usize = 200;

tokio::task_local! {
    /// The label of the POST being answered.
    pub static LABEL: Option<String>;
}

/// The label of the request being answered, if any.
pub fn current() -> Option<String> {
    LABEL.try_with(Clone::clone).ok().flatten()
}

/// Runs a POST with its `?label=` kept for its task; a bad label is a 400.
pub async fn labelled(req: Request, next: Next) -> Response {
    if req.method() != Method::POST {
        return next.run(req).await;
    }
    let label = Query::<HashMap<String, String>>::try_from_uri(req.uri()).ok().and_then(|q| q.0.get("label").cloned());
    match label.map(checked).transpose() {
        Ok(label) => LABEL.scope(label, next.run(req)).await,
        Err(e) => e.into_response(),
    }
}

/// A label: 1 to [`MAX_LABEL`] characters, none of them a control
/// character or a bidirectional override (which would show another text
/// than the one stored: `U+202E` turns `exe.txt` round).
pub fn checked(label: String) -> Result<String, ApiError> {
    let bad = |why: Msg| ApiError::BadQuery(vec![FieldError::parameter_said("label", why)]);
    if let Some(c) = label.chars().find(|c| c.is_control() || is_bidi_control(*c)) {
        return Err(bad(Msg::new("label-control").arg("code", format!("U+{:04X}", c as u32))));
    }
    match label.chars().count() {
        0 => Err(bad(Msg::new("label-empty"))),
        n if n > MAX_LABEL => Err(bad(Msg::new("field-at-most-characters").arg("max", MAX_LABEL))),
        _ => Ok(label),
    }
}

/// Unicode's bidirectional embeddings, overrides and isolates (U+202A to
/// U+202E, U+2066 to U+2069) and marks (U+200E, U+200F, U+061C).
fn is_bidi_control(c: char) -> bool {
    matches!(c, '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}' | '\u{200E}' | '\u{200F}' | '\u{061C}')
}
