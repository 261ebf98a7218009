//! The HTTP interface: routes, OpenAPI document, interactive docs.
//!
//! Handlers stay short: parse the body ([`json::JsonBody`]), convert it to
//! an engine problem collecting every error with its JSON pointer, run the
//! engine off the async workers, store the job ([`create::create`]).

pub mod access;
pub mod admission;
pub mod body;
pub mod check;
pub mod create;
pub mod deferred;
pub mod examples;
pub mod files;
pub mod generators;
pub mod idempotency;
pub mod job;
pub mod jobs;
pub mod json;
pub mod kind;
pub mod label;
pub mod language;
pub mod metrics;
pub mod middleware;
pub mod pace;
pub mod pages;
pub mod parts;
pub mod plain_errors;
pub mod plots;
pub mod read;
pub mod retention;
pub mod serve;
pub mod service;
pub mod solution;
pub mod tables;
pub mod templates;
pub mod watchdog;
pub mod workers;

use crate::kind::Limits;
use crate::kind::problem::{ApiError, FieldError, Problem};
use crate::kind::quantity;
use crate::store::Store;
pub use admission::{Admission, Capacity};
use axum::Router;
use axum::http::header;
use axum::routing::get;
pub use middleware::Settings;
use utoipa::OpenApi;
use utoipa_axum::router::OpenApiRouter;
use utoipa_swagger_ui::{Config, SwaggerUi};

/// Shared state of the handlers.
#[derive(Clone)]
pub struct AppState {
    /// The kinds served, handed over by `main.rs` ([`crate::registry`]).
    pub kinds: kind::Registry,
    pub store: Store,
    /// What one request may ask, and the compute budget of a job.
    pub limits: Limits,
    /// How many jobs compute and wait at once, and the memory of answers.
    pub admission: Admission,
    /// What `/metrics` reports.
    pub metrics: metrics::Metrics,
    /// Jobs POSTed with `Prefer: respond-async`, and how they are run.
    pub deferred: deferred::Deferred,
    /// The answers of template parts asked before, bounded by bytes.
    pub answers: templates::Answers,
    /// The jobs computing now, watched for escapes from their budget.
    pub watchdog: watchdog::Watchdog,
    /// The worker processes that compute the kinds' jobs; None: they
    /// compute on the service's own threads, stopped only by the engine's
    /// own reading of the deadline (`--in-process`).
    pub workers: Option<workers::Pool>,
    /// The token, and whether stored jobs are its holders' (set by [`router`] from its settings).
    pub access: access::Access,
}

impl AppState {
    /// The state of a service of `kinds` on `store`, with the default
    /// limits and capacity, computing in-process ([`Self::with_workers`]).
    pub fn new(store: Store, kinds: kind::Registry) -> Self {
        let (limits, admission) = (Limits::default(), Admission::default());
        let (metrics, deferred, answers, watchdog) = Default::default();
        let access = access::Access::default();
        Self { kinds, store, limits, admission, metrics, deferred, answers, watchdog, workers: None, access }
    }

    /// This state with its jobs computed by the worker processes of `settings`.
    pub fn with_workers(self, settings: workers::Settings) -> Self {
        Self { workers: Some(workers::Pool::new(settings)), ..self }
    }
}

/// Path of the health check (also probed by `mechdyn healthcheck`).
pub const HEALTH_PATH: &str = "/healthz";

/// Default limit of a request body, bytes.
pub const DEFAULT_BODY_LIMIT: usize = 1 << 20;

#[derive(OpenApi)]
#[openapi(
    info(
        title = "mechdyn",
        description = "Machine-dynamics calculations: kinetostatics (inverse dynamics) of planar mechanisms, \
flywheels (approximate and exact Wittenbauer methods), direct dynamics (reduced 1-DOF form or a mechanism of \
any DOF), rigid rotors on two bearings, and the gear and equivalent-mass calculators of the course; every job \
is stored and readable later.\n\nQuantities are SI numbers or `\"VALUE UNIT\"` strings \
(`\"300 rpm\"`, `\"3200 ft*lbf\"`, `\"20 slug*ft^2\"`, `\"4 %\"`); results are SI. A name of a list \
(an `integrator`, a joint's `type`) is read in any case (`\"DOPRI5\"` as `dopri5`). Errors are \
`application/problem+json` with a JSON pointer for every invalid field.\n\nLimits (the defaults; the \
service's operator may configure each, see `MECHDYN_*` in docs/operators.md): request body 1 MiB (413 beyond it); \
expressions 2000 characters and 64 levels of nesting; tables 100000 rows; 1000 segments per function; \
100000 result samples; 100000 steps per kinetostatics job (422 at the field beyond them); a result of \
16 MiB (422 `/problems/result-too-large`, saying which `steps` or `samples` would fit); a job's compute \
budget 20 s (a job over it is stopped and answered 422 `/problems/compute-budget`: jobs compute in worker \
processes, and one that has not answered half a second past its budget is killed); a job's memory (422 \
`/problems/job-memory` beyond it); a crash inside a computation is that job's 500 `/problems/compute-failed` \
alone. Fixed: 100 torques; 200 bodies and joints and 500 loads per mechanism.\n\nUnder load: as many jobs compute at once as the \
service has cores, 64 more wait; beyond that a POST is answered 503 `/problems/saturated` with \
`Retry-After`. A full disk is a 507 `/problems/storage-full` (reads go on). When the service has an API \
token (`MECHDYN_API_TOKEN`), every POST and DELETE needs `Authorization: Bearer <token>` (401 without it), and so \
does every read of stored jobs (the list, a job, its parts, CSV, plots, files and page; a browser signs in once at \
`/signin`) unless the service keeps them public (`MECHDYN_PUBLIC_JOBS`); a template's value, variants and form stay \
public, computed without storing within a share of their own (one at a time, 2 s each by default; beyond it 503 \
with `Retry-After`); every answer carries an `x-request-id` header, and `X-Content-Type-Options: nosniff`.\n\nOn any POST: `?label=TEXT` (1 to 200 characters, no control characters or bidirectional overrides) stores a label \
with the job it creates (`GET /v1/jobs?label=TEXT` lists them); an `Idempotency-Key` header (1 to 255 visible \
characters) makes a retry safe: the same key with the same request answers the first successful answer again \
(with `Idempotent-Replayed: true`), nothing computed or stored twice; the same key with another request is a \
422, and while the first is still being answered a 409 with `Retry-After`. Keys are kept 7 days."
    ),
    components(schemas(
        Problem, FieldError, service::Health, service::Readiness, quantity::Quantity, quantity::FunctionDto, quantity::FunctionSpec,
        tables::AngleUnit, tables::Format, tables::DecimalMark
    )),
    tags(
        (name = "flywheel", description = "Flywheel design for a machine in steady state"),
        (name = "kinetostatics", description = "Inverse dynamics of planar mechanisms"),
        (name = "dynamics", description = "Direct dynamics: motion under given actions"),
        (name = "gears", description = "Gear calculators"),
        (name = "calculators", description = "Smaller calculators of the course"),
        (name = "jobs", description = "Stored computations"),
        (name = "templates", description = "Problems with parameters: one number of a job by URL (a spreadsheet's WEBSERVICE), a parameter study as CSV"),
        (name = "grading", description = "Students' answers checked by the engine: tolerances as course platforms define them, feedback naming common slips, seeded per-student variants, a whole class in one CSV"),
        (name = "service", description = "Liveness, readiness and metrics, for the operator"),
        (name = "pages", description = "HTML pages for people (no JavaScript): the recent jobs and templates, a job's values and plots, a template's form"),
    )
)]
pub struct ApiDoc;

/// Every route of the service with its OpenAPI operation, from one list:
/// each kind of the registry, then the generic reads.
fn routes(kinds: &kind::Registry) -> OpenApiRouter<AppState> {
    let mut routes = OpenApiRouter::with_openapi(ApiDoc::openapi());
    for kind in kinds.iter() {
        routes = routes.routes(kind.route());
    }
    routes
        .routes(utoipa_axum::routes!(jobs::list))
        .routes(utoipa_axum::routes!(jobs::get, jobs::delete))
        .routes(utoipa_axum::routes!(jobs::csv))
        .routes(utoipa_axum::routes!(parts::values))
        .routes(utoipa_axum::routes!(parts::values_csv))
        .routes(utoipa_axum::routes!(plots::list))
        .routes(svg_route(utoipa_axum::routes!(plots::plot)))
        .routes(utoipa_axum::routes!(templates::list, templates::create))
        .routes(utoipa_axum::routes!(templates::get))
        .routes(utoipa_axum::routes!(templates::job))
        .routes(utoipa_axum::routes!(templates::table))
        .routes(utoipa_axum::routes!(templates::variants))
        .routes(utoipa_axum::routes!(check::class::grade))
        .routes(rest_of_path(utoipa_axum::routes!(templates::result), "pointer"))
        .routes(rest_of_path(utoipa_axum::routes!(parts::part), "pointer"))
        .routes(utoipa_axum::routes!(service::healthz))
        .routes(utoipa_axum::routes!(service::readyz))
        .routes(utoipa_axum::routes!(metrics::metrics))
        .routes(utoipa_axum::routes!(pages::home))
        .routes(utoipa_axum::routes!(pages::job::job))
        .routes(utoipa_axum::routes!(pages::solution::solution))
        .routes(utoipa_axum::routes!(pages::form::template))
        .routes(utoipa_axum::routes!(pages::favicon))
        .routes(utoipa_axum::routes!(pages::signin::form, pages::signin::sign_in))
        .routes(utoipa_axum::routes!(pages::signin::sign_out))
        .routes(utoipa_axum::routes!(solution::solution))
        .routes(utoipa_axum::routes!(files::file))
}

/// A route whose last path parameter takes the rest of the path (a JSON
/// pointer with its `/`s): routed as `{*NAME}`, documented as `{NAME}`.
fn rest_of_path(
    (schemas, mut paths, method): utoipa_axum::router::UtoipaMethodRouter<AppState>,
    name: &str,
) -> utoipa_axum::router::UtoipaMethodRouter<AppState> {
    let (from, to) = (format!("{{{name}}}"), format!("{{*{name}}}"));
    let mut routed = utoipa::openapi::path::Paths::new();
    for (path, item) in std::mem::take(&mut paths.paths) {
        routed.paths.insert(path.replace(&from, &to), item);
    }
    (schemas, routed, method)
}

/// The plot's route: axum cannot match `{name}.svg` within a segment, so it
/// is routed as `{name}` (the handler wants the `.svg`) and documented as
/// `{name}.svg`.
fn svg_route(
    (schemas, mut paths, method): utoipa_axum::router::UtoipaMethodRouter<AppState>,
) -> utoipa_axum::router::UtoipaMethodRouter<AppState> {
    let mut routed = utoipa::openapi::path::Paths::new();
    for (path, item) in std::mem::take(&mut paths.paths) {
        routed.paths.insert(path.replace(plots::DOCUMENTED, plots::ROUTED), item);
    }
    (schemas, routed, method)
}

/// The OpenAPI document of a service of `kinds`, as served at
/// `/openapi.json` (and printed by `cargo run -- openapi`): the routes'
/// operations and schemas, then what the registry adds ([`examples`]): every
/// POST's 201 example computed by the engine, the units of every result's
/// fields; and what client generators need ([`generators`]). Kept as JSON:
/// utoipa's types cannot read back a schema that allows any value.
/// [`kind::Registry::document`] makes it once.
fn document(kinds: &kind::Registry) -> (serde_json::Value, bytes::Bytes) {
    let (_, doc) = routes(kinds).split_for_parts();
    let mut value = serde_json::to_value(&doc).unwrap_or_default();
    examples::add(&mut value, kinds);
    generators::add(&mut value, kinds);
    let text = serde_json::to_string_pretty(&value).unwrap_or_default();
    (value, text.into())
}

/// The service's router with its middleware ([`middleware::layered`]).
/// The operator's endpoints alone (`/healthz`, `/readyz`, `/metrics`), for
/// the operator's listener: connections of their own, so an orchestrator's
/// probes are answered while every connection of the service's is taken.
pub fn operator_router(state: AppState) -> Router {
    Router::new()
        .route(HEALTH_PATH, get(service::healthz))
        .route("/readyz", get(service::readyz))
        .route("/metrics", get(metrics::metrics))
        .fallback(|| async { ApiError::NoRoute })
        .with_state(state)
}

pub fn router(state: AppState, settings: &Settings) -> Router {
    let state = AppState { access: access::Access::new(settings.api_token.as_deref(), settings.public_jobs), ..state };
    let (routes, _) = routes(&state.kinds).split_for_parts();
    let kinds = state.kinds.clone();
    let document = move || async move { ([(header::CONTENT_TYPE, "application/json")], kinds.document().1.clone()) };
    let routes = routes
        .route("/openapi.json", get(document))
        // The validator would send the document's URL to validator.swagger.io and show a broken image offline.
        .merge(SwaggerUi::new("/docs").config(Config::new(["/openapi.json"]).validator_url("none")))
        .fallback(|| async { ApiError::NoRoute })
        .method_not_allowed_fallback(|| async { ApiError::MethodNotAllowed })
        .with_state(state.clone());
    middleware::layered(routes, settings, state)
}
