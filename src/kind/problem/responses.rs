//! The error answers of the endpoints, for the OpenAPI document only: each
//! status with its problem document's example.

use super::Problem;

/// The error answers of every `POST` of a job, for the OpenAPI document,
/// each with an example of its own.
#[derive(utoipa::IntoResponses)]
#[allow(dead_code)]
pub enum PostErrors {
    /// Body is not valid JSON
    #[response(status = 400, content_type = "application/problem+json", example = json!({
        "type": "/problems/malformed-json", "title": "The body is not valid JSON", "status": 400,
        "detail": "the body is not valid JSON: expected value at line 1, column 42, near `NaN}`; NaN and Infinity are not JSON numbers: give a finite number"
    }))]
    MalformedJson(Problem),
    /// The service was started with an API token (MECHDYN_API_TOKEN) and the request does not carry it
    #[response(status = 401, content_type = "application/problem+json", example = json!({
        "type": "/problems/unauthorized", "title": "Missing or wrong bearer token", "status": 401,
        "detail": "this service stores and deletes jobs only for a request with \"Authorization: Bearer <token>\": every POST and DELETE, and a GET of a template's job or page that would store a new job"
    }))]
    Unauthorized(Problem),
    /// The body did not arrive at the pace a client must keep (by default 32 KiB/s once 5 s
    /// have passed); the connection is closed
    #[response(status = 408, content_type = "application/problem+json", example = json!({
        "type": "/problems/request-timeout", "title": "The request's body did not arrive in time", "status": 408,
        "detail": "the request's body did not arrive in time: 130 bytes in 5.0 s; this service needs a body to keep arriving at 32768 bytes/s once 5 s have passed"
    }))]
    RequestTimeout(Problem),
    /// An HTTP/1.0 request without `Content-Length`
    #[response(status = 411, content_type = "application/problem+json", example = json!({
        "type": "/problems/length-required", "title": "The body's length is required", "status": 411,
        "detail": "an HTTP/1.0 POST needs a Content-Length header: its body's end cannot be told otherwise"
    }))]
    LengthRequired(Problem),
    /// Body larger than the limit (default 1 MiB)
    #[response(status = 413, content_type = "application/problem+json", example = json!({
        "type": "/problems/payload-too-large", "title": "Request body too large", "status": 413,
        "detail": "the body is larger than the limit of 1048576 bytes"
    }))]
    TooLarge(Problem),
    /// Content type is not application/json
    #[response(status = 415, content_type = "application/problem+json", example = json!({
        "type": "/problems/unsupported-media-type", "title": "Unsupported content type", "status": 415,
        "detail": "the content type must be application/json"
    }))]
    UnsupportedMediaType(Problem),
    /// Not a valid problem (an invalid field, a mechanism that cannot be assembled, a cycle
    /// not in steady state, ...; `errors` has a JSON pointer for every invalid field), a result
    /// larger than the limit on a result (type `/problems/result-too-large`, saying what fits), a
    /// job stopped at its compute budget (type `/problems/compute-budget`), or one past the memory a
    /// job may take (type `/problems/job-memory`)
    #[response(status = 422, content_type = "application/problem+json", example = json!({
        "type": "/problems/invalid-request", "title": "The request is not a valid problem", "status": 422,
        "detail": "2 invalid fields",
        "errors": [
            {"pointer": "/mean_speed", "message": "unknown unit 'furlongs'; known units: m, mm, ..."},
            {"pointer": "/irregularity", "message": "must be greater than 0 and less than 2"}
        ]
    }))]
    Invalid(Problem),
    /// The job's computation crashed (a panic, an abort, a stack overflow in its worker process):
    /// that job alone; the `x-request-id` header finds it in the service's log
    #[response(status = 500, content_type = "application/problem+json", example = json!({
        "type": "/problems/compute-failed", "title": "The job's computation failed", "status": 500,
        "detail": "the job's computation stopped without an answer: a fault of the service, which the x-request-id header of this answer finds in its log; no other job was affected"
    }))]
    ComputeFailed(Problem),
    /// The service is saturated (every job slot and queue place taken, or too many large
    /// answers being sent) or its database is unavailable: retry after `Retry-After` seconds
    #[response(status = 503, content_type = "application/problem+json",
        headers(("Retry-After" = u64, description = "Seconds to wait before retrying")),
        example = json!({
            "type": "/problems/saturated", "title": "The service is saturated", "status": 503,
            "detail": "the service is saturated (every job slot and queue place is taken); retry after 2 s"
        }))]
    Saturated(Problem),
    /// The job was computed but the service's storage is full: nothing was stored; reads
    /// still work, and jobs are stored again once space returns
    #[response(status = 507, content_type = "application/problem+json", example = json!({
        "type": "/problems/storage-full", "title": "The service's storage is full", "status": 507,
        "detail": "the job was computed but could not be stored: the service's storage is full; reads still work, and writes resume once space returns"
    }))]
    StorageFull(Problem),
}

/// The error answers of a read of stored jobs, for the OpenAPI document.
#[derive(utoipa::IntoResponses)]
#[allow(dead_code)]
pub enum ReadErrors {
    /// No job with this id
    #[response(status = 404, content_type = "application/problem+json", example = json!({
        "type": "/problems/not-found", "title": "Job not found", "status": 404,
        "detail": "no job with id '0d1e5d8a-6a3c-4f4e-9a53-2f1c0b7e9d41'"
    }))]
    NotFound(Problem),
    /// A read of a result: the job was deferred (`Prefer: respond-async`) and is queued or
    /// running (retry after `Retry-After` seconds), or it failed
    #[response(status = 409, content_type = "application/problem+json",
        headers(("Retry-After" = u64, description = "Seconds to wait before retrying (queued or running)")),
        example = json!({
            "type": "/problems/job-not-done", "title": "The job has no result", "status": 409,
            "detail": "job '0d1e5d8a-6a3c-4f4e-9a53-2f1c0b7e9d41' is running: its result is not there yet; retry after 1 s"
        }))]
    NotDone(Problem),
    /// Too many large answers are being sent, or the database is unavailable: retry after
    /// `Retry-After` seconds
    #[response(status = 503, content_type = "application/problem+json",
        headers(("Retry-After" = u64, description = "Seconds to wait before retrying")),
        example = json!({
            "type": "/problems/saturated", "title": "The service is saturated", "status": 503,
            "detail": "the service is saturated (too many large answers are being sent); retry after 1 s"
        }))]
    Saturated(Problem),
}

/// The error answer of a read of stored jobs where the service keeps them
/// to its token's holders, for the OpenAPI document.
#[derive(utoipa::IntoResponses)]
#[allow(dead_code)]
pub enum PrivateErrors {
    /// The service has an API token and keeps its stored jobs to its holders: this read does not
    /// carry it (`Authorization: Bearer <token>`, or a browser's sign-in cookie)
    #[response(status = 401, content_type = "application/problem+json", example = json!({
        "type": "/problems/unauthorized", "title": "Missing or wrong bearer token", "status": 401,
        "detail": "this service keeps its stored jobs to the holders of its token: send \"Authorization: Bearer <token>\", or sign in once at /signin in a browser; a template's values (GET /v1/templates/{id}/result/…) and variants need no token"
    }))]
    PrivateJobs(Problem),
}
