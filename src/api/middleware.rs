//! The service's middleware, outermost first: a request id (`x-request-id`,
//! a random UUID unless the client sent one, echoed on the answer), the
//! request's log span carrying it, the request counted and timed by its
//! route ([`super::metrics`]), CORS for the origins configured, every answer
//! given before its request's body was read draining that body first
//! ([`super::body::drain_unread`]), the answer's language
//! ([`super::language`]), panics caught and answered 500
//! problem+json without internals, a query parameter given twice refused,
//! the optional token every POST and DELETE must carry, and every read of
//! stored jobs where they are its holders' ([`super::access`]), admission control (a
//! POST's body read whole at the client's pace, then a slot, 503 when none
//! is free), a POST's `?label=` ([`super::label`]), its `Idempotency-Key`
//! ([`super::idempotency`]), and the body limit.

use super::AppState;
use super::access::{Access, Refused};
use super::admission::Admission;
use super::body::{drain_unread, guarded};
use super::idempotency::{InFlight, idempotent};
use super::json::BodyLimit;
use super::pace::{Pace, read_body};
use crate::i18n::Msg;
use crate::kind::problem::{ApiError, FieldError};
use axum::Router;
use axum::extract::{DefaultBodyLimit, Request};
use axum::http::{HeaderName, HeaderValue, Method, Version, header};
use axum::middleware::{Next, from_fn};
use axum::response::{IntoResponse, Response};
use axum::{Extension, body::Body};
use http_body::Body as _;
use std::any::Any;
use tower_http::catch_panic::CatchPanicLayer;
use tower_http::cors::{AllowOrigin, CorsLayer};
use tower_http::request_id::{MakeRequestUuid, PropagateRequestIdLayer, SetRequestIdLayer};
use tower_http::trace::{DefaultOnFailure, DefaultOnResponse, TraceLayer};
use tracing::Level;

/// Header of the request id.
pub const REQUEST_ID: &str = "x-request-id";

/// What the middleware is configured with.
#[derive(Clone, Debug)]
pub struct Settings {
    /// Largest accepted request body, bytes (413 beyond it).
    pub body_limit: usize,
    /// When set, every POST and DELETE needs `Authorization: Bearer <token>` (401 without),
    /// and a GET stores a new job only with it ([`super::create::may_store`]).
    pub api_token: Option<String>,
    /// With a token: stored jobs readable without it (`--public-jobs`).
    pub public_jobs: bool,
    /// Origins allowed by CORS (`*` for any); none: no CORS headers.
    pub cors_origins: Vec<String>,
    /// The pace a request's body must keep ([`super::pace`]).
    pub pace: Pace,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            body_limit: super::DEFAULT_BODY_LIMIT,
            api_token: None,
            public_jobs: false,
            cors_origins: Vec::new(),
            pace: Pace::default(),
        }
    }
}

impl Settings {
    /// The defaults with another body limit.
    pub fn with_body_limit(body_limit: usize) -> Self {
        Self { body_limit, ..Self::default() }
    }
}

/// `routes` with the service's middleware.
pub fn layered(routes: Router, s: &Settings, state: AppState) -> Router {
    let access = state.access.clone();
    let (admission, limit, flight, pace) = (state.admission.clone(), s.body_limit, InFlight::default(), s.pace);
    let metrics = state.metrics.clone();
    let routes = routes
        .layer(DefaultBodyLimit::max(s.body_limit))
        .layer(Extension(BodyLimit(s.body_limit)))
        .layer(from_fn(move |req, next| idempotent(state.clone(), flight.clone(), limit, req, next)))
        .layer(from_fn(super::label::labelled))
        .layer(from_fn(move |req, next| admit(admission.clone(), (limit, pace), req, next)))
        .layer(from_fn(move |req, next| require_token(access.clone(), req, next)))
        .layer(from_fn(single_parameters))
        .layer(CatchPanicLayer::custom(panic_response))
        .layer(from_fn(drain_unread))
        .layer(from_fn(super::plain_errors::as_text))
        .layer(from_fn(super::language::in_language));
    let routes = match cors(&s.cors_origins) {
        Some(cors) => routes.layer(cors),
        None => routes,
    };
    let request_id = HeaderName::from_static(REQUEST_ID);
    routes
        .layer(from_fn(security_headers))
        .layer(from_fn(move |req, next| super::metrics::track(metrics.clone(), req, next)))
        .layer(PropagateRequestIdLayer::new(request_id.clone()))
        .layer(
            TraceLayer::new_for_http()
                .make_span_with(span)
                .on_response(DefaultOnResponse::new().level(Level::INFO))
                // 503 and 507 are conditions, logged as warnings; internal errors log their own error.
                .on_failure(DefaultOnFailure::new().level(Level::WARN)),
        )
        .layer(SetRequestIdLayer::new(request_id, MakeRequestUuid))
}

/// An SVG opened by itself: no script, nothing from elsewhere, its own styles.
const SVG_POLICY: &str = "default-src 'none'; style-src 'unsafe-inline'; img-src data:; frame-ancestors 'self'";

/// Another HTML page (the interactive documentation, Swagger UI): its own
/// scripts, styles and the document, nothing from elsewhere. The service's
/// own pages set a stricter one, with no script at all.
const HTML_POLICY: &str = "default-src 'self'; img-src 'self' data:; style-src 'self' 'unsafe-inline'; \
script-src 'self'; connect-src 'self'; form-action 'self'; base-uri 'none'; frame-ancestors 'none'";

/// Every answer says that its content type is what it is (`nosniff`: a
/// browser never runs a CSV or a plain text as a script); an SVG or HTML
/// answer without a Content-Security-Policy of its own gets one.
async fn security_headers(req: Request, next: Next) -> Response {
    let mut response = next.run(req).await;
    let h = response.headers_mut();
    h.entry(header::X_CONTENT_TYPE_OPTIONS).or_insert(HeaderValue::from_static("nosniff"));
    let kind = h.get(header::CONTENT_TYPE).and_then(|v| v.to_str().ok()).unwrap_or("");
    let policy = match kind {
        k if k.starts_with("image/svg+xml") => Some(SVG_POLICY),
        k if k.starts_with("text/html") => Some(HTML_POLICY),
        _ => None,
    };
    if let Some(policy) = policy {
        h.entry(header::CONTENT_SECURITY_POLICY).or_insert(HeaderValue::from_static(policy));
    }
    response
}

fn span(req: &Request) -> tracing::Span {
    let id = req.headers().get(REQUEST_ID).and_then(|v| v.to_str().ok()).unwrap_or("");
    tracing::info_span!("request", method = %req.method(), uri = %req.uri(), request_id = %id)
}

/// A panic in a handler: logged (inside the request's span, so with its id)
/// and answered 500 problem+json that tells nothing of it.
fn panic_response(panic: Box<dyn Any + Send + 'static>) -> Response<Body> {
    let message = panic
        .downcast_ref::<String>()
        .map(String::as_str)
        .or_else(|| panic.downcast_ref::<&str>().copied())
        .unwrap_or("(no message)");
    ApiError::Internal(format!("handler panicked: {message}")).into_response()
}

fn cors(origins: &[String]) -> Option<CorsLayer> {
    if origins.is_empty() {
        return None;
    }
    let allow = if origins.iter().any(|o| o == "*") {
        AllowOrigin::any()
    } else {
        AllowOrigin::list(origins.iter().filter_map(|o| HeaderValue::from_str(o).ok()))
    };
    Some(
        CorsLayer::new()
            .allow_origin(allow)
            .allow_methods([Method::GET, Method::POST, Method::DELETE])
            .allow_headers([
                header::CONTENT_TYPE,
                header::AUTHORIZATION,
                HeaderName::from_static(super::idempotency::HEADER),
            ])
            .expose_headers([
                header::LOCATION,
                HeaderName::from_static(REQUEST_ID),
                HeaderName::from_static(super::idempotency::REPLAYED),
            ]),
    )
}

/// A write needs the token, and so does a read of stored jobs where they
/// are its holders' ([`super::access`]); any other request is answered with
/// what it may do held for its task. A page of stored jobs refused is the
/// sign-in form, to come back to it.
async fn require_token(access: Access, req: Request, next: Next) -> Response {
    match access.allow(req.method(), req.uri().path(), req.headers()) {
        Ok(allowed) => super::access::within(allowed, next.run(req)).await,
        Err(Refused::Write) => ApiError::Unauthorized.into_response(),
        Err(Refused::Read) if super::pages::is_page(req.uri().path()) => {
            super::pages::signin::refused(req.uri().path_and_query().map_or("/", |p| p.as_str()))
        }
        Err(Refused::Read) => ApiError::PrivateJobs.into_response(),
    }
}

/// A POST's body is read whole first, within the body limit (413) and at
/// the client's pace (408), what has arrived held in the bodies' budget;
/// then the POST takes a slot of admission control and keeps it until its
/// answer has been sent, or is answered 503 with `Retry-After`. A slow body
/// never holds a slot.
async fn admit(admission: Admission, (limit, pace): (usize, Pace), req: Request, next: Next) -> Response {
    if req.method() != Method::POST {
        return next.run(req).await;
    }
    let (parts, body) = req.into_parts();
    // HTTP/1.0 has no chunked coding: without a length the body's end is the connection's.
    if parts.version == Version::HTTP_10 && !parts.headers.contains_key(header::CONTENT_LENGTH) {
        return ApiError::LengthRequired.into_response();
    }
    // A refused body's rest is drained by `drain_unread`, outside.
    if body.size_hint().exact().is_some_and(|n| n > limit as u64) {
        return ApiError::PayloadTooLarge(limit).into_response();
    }
    let bytes = match read_body(body, limit, pace, &admission).await {
        Ok(b) => b,
        Err(e) => return e.into_response(),
    };
    let Some(slot) = admission.enter() else {
        return admission.saturated("saturated-slots").into_response();
    };
    Admission::holding(next.run(Request::from_parts(parts, Body::from(bytes)))).await.map(|b| guarded(b, slot))
}

/// A query that gives a parameter twice (`F=1&F=2`) is a 400 naming it:
/// the routes read each parameter once, and taking the last silently would
/// answer for another question than the one asked.
async fn single_parameters(req: Request, next: Next) -> Response {
    let pairs: Vec<(String, String)> = serde_urlencoded::from_str(req.uri().query().unwrap_or("")).unwrap_or_default();
    let mut seen = std::collections::HashSet::new();
    let twice: std::collections::BTreeSet<&str> =
        pairs.iter().map(|(k, _)| k.as_str()).filter(|k| !seen.insert(*k)).collect();
    if twice.is_empty() {
        return next.run(req).await;
    }
    let error = |name: &str| FieldError::parameter_said(name, Msg::new("query-twice"));
    let refused = ApiError::BadQuery(twice.into_iter().map(error).collect());
    if super::pages::is_page(req.uri().path()) { super::pages::error(refused) } else { refused.into_response() }
}
