//! `Idempotency-Key` on any POST: a grading script that retries after a
//! timeout gets the first answer again, and nothing is computed or stored
//! twice.
//!
//! The request's fingerprint is SHA-256 of its method, path and query,
//! content type and body. The first successful (2xx) answer is kept under
//! the key: a job's answer as the job's id (answered again as its GET
//! answers it: the same bytes), any other answer (a CSV, a template) as its
//! bytes. The same key with the same fingerprint answers that again, with
//! `Idempotent-Replayed: true`; with another fingerprint it is a 422; while
//! the first is still being answered, a 409 with `Retry-After`. Failures
//! are not kept: a retry after a 503 or a 422 is tried again. Keys are kept
//! 7 days ([`crate::store::idempotency`]).

use super::AppState;
use super::body::Chunks;
use super::job::job_chunks;
use super::read::{self, READ_MEMORY_FACTOR};
use crate::i18n::Msg;
use crate::kind::problem::{ApiError, FieldError};
use crate::store::Answer;
use axum::body::Body;
use axum::extract::Request;
use axum::http::{HeaderValue, Method, StatusCode, header};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use http_body_util::BodyExt;
use sha2::{Digest, Sha256};
use std::collections::HashSet;
use std::sync::{Arc, Mutex};

/// The request header.
pub const HEADER: &str = "idempotency-key";
/// The header on an answer given again.
pub const REPLAYED: &str = "idempotent-replayed";
/// Longest key, characters.
pub const MAX_KEY: usize = 255;

/// Keys whose first request is being answered.
#[derive(Clone, Default)]
pub struct InFlight(Arc<Mutex<HashSet<String>>>);

/// Removes its key from [`InFlight`] when dropped (answered, failed or cancelled).
struct Claim(InFlight, String);

impl Drop for Claim {
    fn drop(&mut self) {
        self.0.0.lock().unwrap_or_else(|e| e.into_inner()).remove(&self.1);
    }
}

impl InFlight {
    fn claim(&self, key: &str) -> Option<Claim> {
        let fresh = self.0.lock().unwrap_or_else(|e| e.into_inner()).insert(key.to_string());
        fresh.then(|| Claim(self.clone(), key.to_string()))
    }
}

/// The middleware: POSTs with the header are answered once.
pub async fn idempotent(state: AppState, flight: InFlight, limit: usize, req: Request, next: Next) -> Response {
    let Some(key) = req.headers().get(HEADER).filter(|_| req.method() == Method::POST) else {
        return next.run(req).await;
    };
    match answer_once(&state, &flight, key.clone(), limit, req, next).await {
        Ok(r) | Err(r) => r,
    }
}

async fn answer_once(
    state: &AppState,
    flight: &InFlight,
    key: HeaderValue,
    limit: usize,
    req: Request,
    next: Next,
) -> Result<Response, Response> {
    let key = checked(&key).map_err(IntoResponse::into_response)?;
    let (parts, body) = req.into_parts();
    let body = super::json::read_within(body, limit).await.map_err(IntoResponse::into_response)?;
    let fingerprint = fingerprint(&parts, &body);
    if let Some(kept) = state.store.answer(&key).await.map_err(|e| ApiError::from(e).into_response())? {
        return replay(state, kept, &fingerprint).await.map_err(IntoResponse::into_response);
    }
    let Some(_claim) = flight.claim(&key) else {
        return Err(ApiError::InProgress(key).into_response());
    };
    let answer = next.run(Request::from_parts(parts, Body::from(body))).await;
    if !answer.status().is_success() {
        return Ok(answer);
    }
    keep(state, &key, fingerprint, answer).await
}

/// A key: 1 to [`MAX_KEY`] visible ASCII characters.
fn checked(key: &HeaderValue) -> Result<String, ApiError> {
    let bad = |why: Msg| ApiError::BadQuery(vec![FieldError::parameter_said("Idempotency-Key", why)]);
    let key = key.to_str().map_err(|_| bad(Msg::new("header-ascii")))?.trim();
    if key.is_empty() || key.len() > MAX_KEY {
        return Err(bad(Msg::new("header-characters").count("max", MAX_KEY)));
    }
    Ok(key.to_string())
}

fn fingerprint(parts: &axum::http::request::Parts, body: &[u8]) -> String {
    let mut hash = Sha256::new();
    let content_type = parts.headers.get(header::CONTENT_TYPE).map(HeaderValue::as_bytes).unwrap_or_default();
    let target = parts.uri.path_and_query().map(|p| p.as_str()).unwrap_or_default();
    for part in [parts.method.as_str().as_bytes(), target.as_bytes(), content_type, body] {
        hash.update((part.len() as u64).to_le_bytes());
        hash.update(part);
    }
    hash.finalize().iter().map(|b| format!("{b:02x}")).collect()
}

/// Keeps a successful answer under `key`, and answers it.
async fn keep(state: &AppState, key: &str, fingerprint: String, answer: Response) -> Result<Response, Response> {
    let (parts, body) = answer.into_parts();
    let status = i64::from(parts.status.as_u16());
    let content_type = parts.headers.get(header::CONTENT_TYPE).and_then(|v| v.to_str().ok()).map(String::from);
    let job_id = parts.headers.get(header::LOCATION).and_then(|v| v.to_str().ok()?.strip_prefix("/v1/jobs/"));
    let mut kept = Answer { fingerprint, status, content_type, job_id: job_id.map(String::from), body: None };
    let body = if kept.job_id.is_some() {
        body
    } else {
        let bytes = body.collect().await.map_err(|_| ApiError::Internal("answer body".into()).into_response())?;
        let bytes = bytes.to_bytes();
        kept.body = Some(bytes.to_vec());
        Body::from(bytes)
    };
    let now = time::OffsetDateTime::now_utc();
    let forget_before = super::create::rfc3339(now - crate::store::KEEP);
    if let Err(e) = state.store.keep_answer(key, &super::create::rfc3339(now), &forget_before, &kept).await {
        // The job is stored and the answer goes out; only a retry would compute it again.
        tracing::warn!(error = %e, key, "idempotency key not kept");
    }
    Ok(Response::from_parts(parts, body))
}

/// The kept answer again, or a 422 when the key came with another request.
async fn replay(state: &AppState, kept: Answer, fingerprint: &str) -> Result<Response, ApiError> {
    if kept.fingerprint != fingerprint {
        let why = Msg::new("header-key-reused");
        return Err(ApiError::Invalid(vec![FieldError::parameter_said("Idempotency-Key", why)]));
    }
    let status = StatusCode::from_u16(u16::try_from(kept.status).unwrap_or(200)).unwrap_or(StatusCode::OK);
    let content_type = kept.content_type.unwrap_or_else(|| "application/octet-stream".into());
    let mut r = match (kept.job_id, kept.body) {
        (Some(id), _) => {
            let (row, reserved) = read::load(state, &id, READ_MEMORY_FACTOR).await?;
            let mut body = Chunks::default();
            job_chunks(&row, &mut body);
            let location = format!("/v1/jobs/{id}");
            let headers = [(header::CONTENT_TYPE, content_type), (header::LOCATION, location)];
            (status, headers, super::body::guarded(Body::new(body), reserved)).into_response()
        }
        (None, body) => (status, [(header::CONTENT_TYPE, content_type)], body.unwrap_or_default()).into_response(),
    };
    r.headers_mut().insert(REPLAYED, HeaderValue::from_static("true"));
    Ok(r)
}
