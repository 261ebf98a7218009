//! The one error type of the API, answered as `application/problem+json`
//! (RFC 9457), its title, detail and field messages in the asker's language
//! (`type` and pointers as they are); the details' words are in `said.rs`.

mod responses;
mod said;

pub use responses::{PostErrors, PrivateErrors, ReadErrors};

use crate::i18n::{self, Lang, Msg};
use axum::http::{StatusCode, header};
use axum::response::{IntoResponse, Response};
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// One invalid input: a JSON pointer into the request body, or a query parameter.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct FieldError {
    /// JSON pointer (RFC 6901) to the field in the request body.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pointer: Option<String>,
    /// Name of the query parameter.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub parameter: Option<String>,
    /// Row of a CSV body, counted as a spreadsheet counts them (the header
    /// is row 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub row: Option<u32>,
    /// Column of a CSV body, by its header's name.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub column: Option<String>,
    pub message: String,
    /// The message as the catalogue has it, rendered in the asker's language
    /// (boxed: an error is small on the paths that return it).
    #[serde(skip)]
    pub text: Option<Box<Msg>>,
}

impl FieldError {
    /// An error at `pointer` said by the catalogue's `msg`.
    pub fn said(pointer: impl Into<String>, msg: Msg) -> Self {
        Self { pointer: Some(pointer.into()), ..Self::of(msg) }
    }

    /// An error of the query parameter `name` said by the catalogue's `msg`.
    pub fn parameter_said(name: impl Into<String>, msg: Msg) -> Self {
        Self { parameter: Some(name.into()), ..Self::of(msg) }
    }

    /// An error of a CSV body, at its `row` (the header is row 1) and
    /// `column` where it has them, said by the catalogue's `msg`.
    pub fn cell(row: Option<usize>, column: Option<&str>, msg: Msg) -> Self {
        Self {
            row: row.map(|r| u32::try_from(r).unwrap_or(u32::MAX)),
            column: column.map(String::from),
            ..Self::of(msg)
        }
    }

    /// `msg`, nowhere yet.
    fn of(msg: Msg) -> Self {
        Self { text: Some(Box::new(msg.clone())), ..Self::plain(msg.render(Lang::En)) }
    }

    /// This error with its message in `lang` (where the catalogue has it).
    pub fn in_lang(mut self, lang: Lang) -> Self {
        if let Some(msg) = &self.text {
            self.message = msg.render(lang);
        }
        self
    }

    /// "where: message" (the query parameter, the pointer, or the CSV's
    /// column), for a person.
    pub fn describe(&self) -> String {
        match (&self.parameter, &self.pointer, &self.column) {
            (Some(p), _, _) | (None, Some(p), _) | (None, None, Some(p)) if !p.is_empty() => {
                format!("{p}: {}", self.message)
            }
            _ => self.message.clone(),
        }
    }

    pub fn at(pointer: impl Into<String>, message: impl Into<String>) -> Self {
        Self { pointer: Some(pointer.into()), ..Self::plain(message) }
    }

    pub fn parameter(name: impl Into<String>, message: impl Into<String>) -> Self {
        Self { parameter: Some(name.into()), ..Self::plain(message) }
    }

    /// A message not from the catalogue, nowhere yet.
    fn plain(message: impl Into<String>) -> Self {
        Self { pointer: None, parameter: None, row: None, column: None, message: message.into(), text: None }
    }
}

/// An RFC 9457 problem document.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[schema(example = json!({
    "type": "/problems/invalid-request",
    "title": "The request is not a valid problem",
    "status": 422,
    "detail": "2 invalid fields",
    "errors": [
        {"pointer": "/mean_speed", "message": "unknown unit 'furlongs'; known units: m, mm, ..."},
        {"pointer": "/irregularity", "message": "must be greater than 0 and less than 2"}
    ]
}))]
pub struct Problem {
    /// URI reference identifying the kind of problem.
    #[serde(rename = "type")]
    pub kind: String,
    pub title: String,
    pub status: u16,
    pub detail: String,
    /// The invalid inputs, for 400 and 422 answers.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub errors: Vec<FieldError>,
}

/// Everything a handler can fail with.
#[derive(Debug)]
pub enum ApiError {
    MalformedJson(Msg),
    UnsupportedMediaType,
    UnsupportedTable,
    PayloadTooLarge(usize),
    Invalid(Vec<FieldError>),
    BadQuery(Vec<FieldError>),
    /// A CSV body's rows or columns that cannot be read, each by row and column.
    BadTable(Vec<FieldError>),
    NotFound(String),
    NoPart {
        id: String,
        pointer: String,
    },
    NoPlot {
        id: String,
        name: String,
        known: Vec<String>,
    },
    NoFile {
        id: String,
        name: String,
        known: Vec<String>,
    },
    NoTemplate(String),
    /// A job of a kind without a worked solution (`GET /v1/jobs/{id}/solution`).
    NoSolution {
        id: String,
        kind: String,
    },
    Conflict(Msg),
    /// The first request of an `Idempotency-Key` is still being answered.
    InProgress(String),
    /// A read of a result that a deferred job does not have (yet).
    NotDone {
        id: String,
        status: crate::store::Status,
    },
    /// A deferred job whose replica stopped every time it was claimed.
    Interrupted(i64),
    NoRoute,
    MethodNotAllowed,
    /// The job ran out of its compute budget and was stopped.
    OverBudget(Msg),
    /// The job's computation passed the limit on a job's memory (bytes).
    JobMemory(u64),
    /// The job's computation crashed (a panic, an abort, a stack overflow):
    /// its worker ended without an answer (logged).
    ComputeFailed,
    /// The result would exceed the limit on a result; `errors` say what would fit.
    ResultTooLarge {
        limit: usize,
        errors: Vec<FieldError>,
    },
    /// Too many jobs computing or waiting, or too many large answers in flight.
    Saturated {
        reason: Msg,
        retry_after: u64,
    },
    /// The database's storage is full: `.0` says what was not done (nothing was stored).
    StorageFull(&'static str),
    /// The database cannot be used at the moment (logged).
    Unavailable(String),
    Unauthorized,
    /// A read of stored jobs without the token, of a service that keeps them to its holders.
    PrivateJobs,
    /// A request's body fell behind the pace a client must keep ([`super::pace`]).
    RequestTimeout(Msg),
    /// An HTTP/1.0 POST with no `Content-Length`.
    LengthRequired,
    /// Logged; the client sees no details.
    Internal(String),
}

impl ApiError {
    /// The status, the problem type and the id of its title in the catalogue.
    fn parts(&self) -> (StatusCode, &'static str, &'static str) {
        match self {
            Self::MalformedJson(_) => (StatusCode::BAD_REQUEST, "malformed-json", "problem-malformed-json"),
            Self::UnsupportedMediaType => {
                (StatusCode::UNSUPPORTED_MEDIA_TYPE, "unsupported-media-type", "problem-unsupported-media-type")
            }
            Self::UnsupportedTable => {
                (StatusCode::UNSUPPORTED_MEDIA_TYPE, "unsupported-media-type", "problem-unsupported-media-type")
            }
            Self::PayloadTooLarge(_) => {
                (StatusCode::PAYLOAD_TOO_LARGE, "payload-too-large", "problem-payload-too-large")
            }
            Self::Invalid(_) => (StatusCode::UNPROCESSABLE_ENTITY, "invalid-request", "problem-invalid-request"),
            Self::BadQuery(_) => (StatusCode::BAD_REQUEST, "invalid-query", "problem-invalid-query"),
            Self::BadTable(_) => (StatusCode::BAD_REQUEST, "invalid-table", "problem-invalid-table"),
            Self::NotFound(_) => (StatusCode::NOT_FOUND, "not-found", "problem-job-not-found"),
            Self::NoRoute => (StatusCode::NOT_FOUND, "not-found", "problem-not-found"),
            Self::NoTemplate(_) => (StatusCode::NOT_FOUND, "not-found", "problem-template-not-found"),
            Self::Conflict(_) => (StatusCode::CONFLICT, "conflict", "problem-conflict"),
            Self::InProgress(_) => (StatusCode::CONFLICT, "in-progress", "problem-in-progress"),
            Self::Interrupted(_) => (StatusCode::SERVICE_UNAVAILABLE, "interrupted", "problem-interrupted"),
            Self::NotDone { .. } => (StatusCode::CONFLICT, "job-not-done", "problem-job-not-done"),
            Self::NoPart { .. } => (StatusCode::NOT_FOUND, "no-such-part", "problem-no-such-part"),
            Self::NoPlot { .. } => (StatusCode::NOT_FOUND, "no-such-plot", "problem-no-such-plot"),
            Self::NoFile { .. } => (StatusCode::NOT_FOUND, "no-such-file", "problem-no-such-file"),
            Self::NoSolution { .. } => (StatusCode::NOT_FOUND, "no-such-solution", "problem-no-such-solution"),
            Self::MethodNotAllowed => {
                (StatusCode::METHOD_NOT_ALLOWED, "method-not-allowed", "problem-method-not-allowed")
            }
            Self::OverBudget(_) => (StatusCode::UNPROCESSABLE_ENTITY, "compute-budget", "problem-compute-budget"),
            Self::JobMemory(_) => (StatusCode::UNPROCESSABLE_ENTITY, "job-memory", "problem-job-memory"),
            Self::ComputeFailed => (StatusCode::INTERNAL_SERVER_ERROR, "compute-failed", "problem-compute-failed"),
            Self::ResultTooLarge { .. } => {
                (StatusCode::UNPROCESSABLE_ENTITY, "result-too-large", "problem-result-too-large")
            }
            Self::Saturated { .. } => (StatusCode::SERVICE_UNAVAILABLE, "saturated", "problem-saturated"),
            Self::StorageFull(_) => (StatusCode::INSUFFICIENT_STORAGE, "storage-full", "problem-storage-full"),
            Self::Unavailable(_) => {
                (StatusCode::SERVICE_UNAVAILABLE, "database-unavailable", "problem-database-unavailable")
            }
            Self::Unauthorized | Self::PrivateJobs => {
                (StatusCode::UNAUTHORIZED, "unauthorized", "problem-unauthorized")
            }
            Self::RequestTimeout(_) => (StatusCode::REQUEST_TIMEOUT, "request-timeout", "problem-request-timeout"),
            Self::LengthRequired => (StatusCode::LENGTH_REQUIRED, "length-required", "problem-length-required"),
            Self::Internal(_) => (StatusCode::INTERNAL_SERVER_ERROR, "internal", "problem-internal"),
        }
    }

    /// The answer's status.
    pub fn status(&self) -> StatusCode {
        self.parts().0
    }

    /// The field errors, each as "where: message" (a page shows them).
    pub fn fields(&self) -> &[FieldError] {
        match self {
            Self::Invalid(e) | Self::BadQuery(e) | Self::BadTable(e) | Self::ResultTooLarge { errors: e, .. } => e,
            _ => &[],
        }
    }

    /// A 422 of a request nested in another (a template's, a check's): its
    /// pointers under `prefix`; any other error as it is.
    pub fn under(self, prefix: &str) -> Self {
        match self {
            Self::Invalid(errors) => Self::Invalid(
                errors
                    .into_iter()
                    .map(|mut f| {
                        f.pointer = Some(format!("{prefix}{}", f.pointer.unwrap_or_default()));
                        f
                    })
                    .collect(),
            ),
            other => other,
        }
    }

    /// The problem document of this error.
    pub fn problem(&self) -> Problem {
        let (status, kind, title) = self.parts();
        let errors = match self {
            Self::Invalid(e) | Self::BadQuery(e) | Self::BadTable(e) | Self::ResultTooLarge { errors: e, .. } => {
                e.clone()
            }
            _ => Vec::new(),
        };
        let lang = i18n::current();
        let errors = errors.into_iter().map(|f| f.in_lang(lang)).collect();
        Problem {
            kind: format!("/problems/{kind}"),
            title: i18n::tr(lang, title),
            status: status.as_u16(),
            detail: self.msg().render(lang),
            errors,
        }
    }
}

impl From<crate::store::StoreError> for ApiError {
    fn from(e: crate::store::StoreError) -> Self {
        Self::not_stored("nothing was stored")(e)
    }
}

impl ApiError {
    /// A store's failure to write, the storage full saying `what` was not done.
    pub fn not_stored(what: &'static str) -> impl Fn(crate::store::StoreError) -> Self {
        move |e| match e {
            crate::store::StoreError::Full => Self::StorageFull(what),
            crate::store::StoreError::Unavailable(why) => Self::Unavailable(why),
            crate::store::StoreError::Refused(why) => {
                Self::Invalid(vec![FieldError::at("", format!("the database refused a value of this request: {why}"))])
            }
        }
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        match &self {
            Self::Internal(detail) => tracing::error!(%detail, "internal error"),
            Self::Unavailable(detail) => tracing::error!(%detail, "database unavailable"),
            _ => {}
        }
        let problem = self.problem();
        let status = StatusCode::from_u16(problem.status).unwrap_or(StatusCode::INTERNAL_SERVER_ERROR);
        let body = serde_json::to_vec(&problem).unwrap_or_default();
        let mut response = (status, [(header::CONTENT_TYPE, "application/problem+json")], body).into_response();
        let headers = response.headers_mut();
        match self {
            Self::Unauthorized | Self::PrivateJobs => {
                headers.insert(header::WWW_AUTHENTICATE, header::HeaderValue::from_static("Bearer"));
            }
            Self::Saturated { retry_after, .. } => {
                headers.insert(header::RETRY_AFTER, header::HeaderValue::from(retry_after));
            }
            Self::Unavailable(_) => {
                headers.insert(header::RETRY_AFTER, header::HeaderValue::from_static("5"));
            }
            Self::InProgress(_) => {
                headers.insert(header::RETRY_AFTER, header::HeaderValue::from_static("1"));
            }
            Self::RequestTimeout(_) => {
                headers.insert(header::CONNECTION, header::HeaderValue::from_static("close"));
            }
            Self::NotDone { status, .. } if status != crate::store::Status::Failed => {
                headers.insert(header::RETRY_AFTER, header::HeaderValue::from_static("1"));
            }
            _ => {}
        }
        response
    }
}

/// Escapes one reference token of a JSON pointer (RFC 6901).
pub fn escape(token: &str) -> String {
    token.replace('~', "~0").replace('/', "~1")
}
