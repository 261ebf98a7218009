//! A calculation kind, described once: its name and path, its request and
//! result types, how it computes, its table and the units of its result's
//! fields, its plots. Every generic feature (the POST, the OpenAPI operation,
//! the CLI's `solve`, CSV, parts of a result with their units, the
//! document's examples, plots and pages) is written once over [`Kind`] and reaches every kind through
//! the registry ([`KINDS`]), never through a `match` on a kind's name.

use super::create::{Destination, Work};
use super::json::JsonBody;
use super::{AppState, job};
use crate::kind::limits::Limits;
use crate::kind::plots;
use crate::kind::problem::{ApiError, PostErrors};
use crate::kind::solution::Solution;
use crate::kind::{Kind, Register, Table, compute, json_bytes, serialized};
use crate::store::JobRow;
use axum::extract::State;
use axum::http::HeaderMap;
use axum::response::Response;
use bytes::Bytes;
use serde_json::Value;
use std::marker::PhantomData;
use std::sync::{Arc, OnceLock};
use tokio::sync::OwnedSemaphorePermit;
use utoipa::openapi::path::{HttpMethod, OperationBuilder, ParameterBuilder, ParameterIn, Paths, PathsBuilder};
use utoipa::openapi::request_body::RequestBodyBuilder;
use utoipa::openapi::{ContentBuilder, HeaderBuilder, Ref, Required, ResponseBuilder, ResponsesBuilder};
use utoipa::{PartialSchema, ToSchema};
use utoipa_axum::router::UtoipaMethodRouter;

/// The POST of every kind: its body read strictly, computed and stored
/// ([`super::create::create`]), or deferred ([`super::deferred`]).
pub async fn post<K: Kind>(
    State(state): State<AppState>,
    headers: HeaderMap,
    body: JsonBody<K::Request>,
) -> Result<Response, ApiError> {
    let JsonBody { value, raw, unknown } = body;
    if super::deferred::wanted(&headers) {
        return super::deferred::accept(&state, K::NAME, raw, unknown).await;
    }
    let request = raw.clone();
    let work = Work::kind(K::NAME, move |limits: &Limits| compute::<K>(&value, unknown, &request, limits));
    super::create::create(&state, work, raw).await
}

/// A job computed and stored, with the memory of its answer reserved.
pub type StoredJob<'a> =
    std::pin::Pin<Box<dyn std::future::Future<Output = Result<(JobRow, OwnedSemaphorePermit), ApiError>> + Send + 'a>>;

/// A kind seen without its types: what the registry holds.
pub trait AnyKind: Send + Sync {
    fn name(&self) -> &'static str;
    /// The kind named for people, in the request's language ("volante").
    fn title(&self) -> String;
    fn path(&self) -> &'static str;
    /// The POST's route with its OpenAPI operation and schemas.
    fn route(&self) -> UtoipaMethodRouter<AppState>;
    /// Parses and computes a JSON request as the POST would: the result's
    /// JSON, the same bytes the service stores (`kinds`: the service's, for
    /// a kind that computes another's request).
    fn solve(&self, raw: String, limits: &Limits, kinds: &Registry) -> Result<Vec<u8>, ApiError>;
    /// Reads and computes a request as the POST would, within `limits` (its
    /// budget from now), and writes its result's JSON within the limit on a
    /// result: what a worker process runs ([`super::workers::serve`]). A kind
    /// that is not computed by a worker (`check`) has none.
    fn run(&self, _raw: Bytes, _limits: &Limits) -> Result<Bytes, ApiError> {
        Err(ApiError::Internal(format!("a job of kind '{}' is not computed by a worker", self.name())))
    }
    /// Computes the job of `request` (JSON text, as it will be stored) and
    /// stores it at `to`: the row, with its answer's memory reserved.
    fn job<'a>(&'a self, state: &'a AppState, request: Bytes, to: Destination) -> StoredJob<'a>;
    fn request_schema(&self) -> String;
    fn result_schema(&self) -> String;
    fn units(&self) -> &'static [(&'static str, &'static str)];
    fn table(&self, result: &Value) -> Option<Table>;
    fn unit(&self, result: &Value, pointer: &[&str]) -> Option<String>;
    fn plots(&self, job: &plots::Job) -> Vec<crate::kind::chart::Listed>;
    fn plot(&self, job: &plots::Job, name: &str, options: &plots::Options) -> plots::Drawn;
    /// Its files' names and content types, and one made from a result.
    fn files(&self) -> &'static [(&'static str, &'static str)] {
        &[]
    }
    /// Its worked solution of step `step` of a stored job, within `limits`;
    /// None for a kind without one.
    fn solution(&self, _job: &plots::Job, _step: usize, _limits: &Limits) -> Option<Result<Solution, ApiError>> {
        None
    }
    /// Whether a stored result of it has a worked solution.
    fn has_solution(&self, _result: &Value) -> bool {
        false
    }
    fn file(&self, _result: &Value, _name: &str) -> Option<Vec<u8>> {
        None
    }
    fn has_file(&self, _result: &Value, _name: &str) -> bool {
        false
    }
}

/// A [`Kind`] in the registry.
pub struct Registered<K>(PhantomData<fn() -> K>);

impl<K: Kind> AnyKind for Registered<K> {
    fn name(&self) -> &'static str {
        K::NAME
    }
    fn title(&self) -> String {
        crate::i18n::say(K::TITLE)
    }
    fn path(&self) -> &'static str {
        K::PATH
    }
    fn route(&self) -> UtoipaMethodRouter<AppState> {
        let mut schemas = Vec::new();
        K::Request::schemas(&mut schemas);
        K::Result::schemas(&mut schemas);
        schemas.push((K::Request::name().into(), K::Request::schema()));
        schemas.push((K::Result::name().into(), K::Result::schema()));
        schemas.push((job_schema::<K>(), job::JobOf::<K::Result>::schema()));
        (schemas, operation::<K>(), axum::routing::post(post::<K>))
    }
    fn solve(&self, raw: String, limits: &Limits, _: &Registry) -> Result<Vec<u8>, ApiError> {
        let body = super::json::parse::<K::Request>(raw)?;
        let result = compute::<K>(&body.value, body.unknown, &body.raw, limits)?;
        json_bytes(&result).map_err(|e| ApiError::Internal(format!("result: {e}")))
    }
    fn run(&self, raw: Bytes, limits: &Limits) -> Result<Bytes, ApiError> {
        let body = super::json::parse::<K::Request>(raw)?;
        let result = compute::<K>(&body.value, body.unknown, &body.raw, limits)?;
        serialized(&result, limits.result_bytes)
    }
    fn job<'a>(&'a self, state: &'a AppState, request: Bytes, to: Destination) -> StoredJob<'a> {
        Box::pin(async move {
            let body = super::json::parse::<K::Request>(request.clone())?;
            let raw = request.clone();
            let compute = move |limits: &Limits| compute::<K>(&body.value, body.unknown, &raw, limits);
            super::create::compute_and_store(state, Work::kind(K::NAME, compute), request, to).await
        })
    }
    fn request_schema(&self) -> String {
        K::Request::name().into()
    }
    fn result_schema(&self) -> String {
        K::Result::name().into()
    }
    fn units(&self) -> &'static [(&'static str, &'static str)] {
        K::UNITS
    }
    fn table(&self, result: &Value) -> Option<Table> {
        K::table(result)
    }
    fn unit(&self, result: &Value, pointer: &[&str]) -> Option<String> {
        // A template's statement quantity has the unit of the field it comes from.
        match statement_source(result, pointer) {
            Some(from) => K::unit(result, &from.iter().map(String::as_str).collect::<Vec<_>>()),
            None => K::unit(result, pointer),
        }
    }
    fn plots(&self, job: &plots::Job) -> Vec<crate::kind::chart::Listed> {
        let request = super::json::canonical::<K::Request>(job.request);
        (K::PLOTS.list)(&plots::Job { request: &request, result: job.result })
    }
    fn plot(&self, job: &plots::Job, name: &str, options: &plots::Options) -> plots::Drawn {
        let request = super::json::canonical::<K::Request>(job.request);
        (K::PLOTS.draw)(&plots::Job { request: &request, result: job.result }, name, options)
    }
    fn files(&self) -> &'static [(&'static str, &'static str)] {
        K::FILES
    }
    fn file(&self, result: &Value, name: &str) -> Option<Vec<u8>> {
        K::file(result, name)
    }
    fn has_file(&self, result: &Value, name: &str) -> bool {
        K::has_file(result, name)
    }
    fn solution(&self, job: &plots::Job, step: usize, limits: &Limits) -> Option<Result<Solution, ApiError>> {
        let request = super::json::canonical::<K::Request>(job.request);
        K::SOLUTION.map(|solve| solve(&plots::Job { request: &request, result: job.result }, step, limits))
    }
    fn has_solution(&self, result: &Value) -> bool {
        K::has_solution(result)
    }
}

/// The POST's operation: the request's schema, the 201 job with this
/// kind's result, and the errors every POST may answer.
fn operation<K: Kind>() -> Paths {
    let names = (K::Request::name().to_string(), K::Result::name().to_string());
    operation_for(K::PATH, K::OPERATION_ID, K::TAG, K::SUMMARY, names)
}

/// The operation of a POST at `path` that answers 201 with a job whose
/// `result` has schema `names.1`, for a body of schema `names.0`.
pub fn operation_for(path: &str, id: &str, tag: &str, summary: &str, names: (String, String)) -> Paths {
    let (request_name, result_name) = names;
    let request = RequestBodyBuilder::new()
        .content("application/json", ContentBuilder::new().schema(Some(Ref::from_schema_name(&request_name))))
        .required(Some(Required::True));
    let created = ResponseBuilder::new()
        .description(format!("Job computed and stored; `result` is {}", with_article(&result_name)))
        .header(
            "Location",
            HeaderBuilder::new().schema(Some(String::schema())).description(Some("/v1/jobs/{id}")).build(),
        )
        .content(
            "application/json",
            ContentBuilder::new().schema(Some(Ref::from_schema_name(format!("JobOf_{result_name}")))).build(),
        );
    let accepted = ResponseBuilder::new()
        .description(
            "With `Prefer: respond-async`: the job stored `queued`, to be computed by any replica; \
             `GET /v1/jobs/{id}` answers it `queued` or `running` (no `result`), then `done` with its result, or \
             `failed` with the `problem` this POST would have answered",
        )
        .header(
            "Location",
            HeaderBuilder::new().schema(Some(String::schema())).description(Some("/v1/jobs/{id}")).build(),
        )
        .header(
            "Preference-Applied",
            HeaderBuilder::new().schema(Some(String::schema())).description(Some("respond-async")).build(),
        )
        .content("application/json", ContentBuilder::new().schema(Some(Ref::from_schema_name("Job"))).build());
    let prefer = ParameterBuilder::new()
        .name("Prefer")
        .parameter_in(ParameterIn::Header)
        .required(Required::False)
        .schema(Some(String::schema()))
        .description(Some(
            "`respond-async`: answer 202 at once and compute the job in the background (RFC 7240); a body that \
             is not JSON, or has a field the kind does not know, is still answered at once",
        ));
    let responses = ResponsesBuilder::new()
        .response("201", created)
        .response("202", accepted)
        .responses_from_into_responses::<PostErrors>();
    let op = OperationBuilder::new()
        .tag(tag)
        .summary(Some(summary))
        .operation_id(Some(id))
        .parameter(prefer)
        .request_body(Some(request.build()))
        .responses(responses);
    PathsBuilder::new().path(path, utoipa::openapi::PathItem::new(HttpMethod::Post, op)).build()
}

/// Name of the schema of a job of kind `K` (its `result` typed).
fn job_schema<K: Kind>() -> String {
    format!("JobOf_{}", K::Result::name())
}

/// "an EquivalentResult", "a FlywheelResult".
fn with_article(name: &str) -> String {
    let vowel = name.starts_with(['A', 'E', 'I', 'O', 'U']);
    format!("{} {name}", if vowel { "an" } else { "a" })
}

/// The kinds the service serves, handed to it by the composition root
/// (`main.rs`, through [`crate::registry`]): those the kinds' wing registers
/// ([`crate::kind::Register`]), then kinds of the service's own (`check`:
/// answers checked against another job). The OpenAPI document is made from
/// it once. Cheap to clone.
#[derive(Clone)]
pub struct Registry(Arc<Inner>);

struct Inner {
    kinds: Vec<&'static dyn AnyKind>,
    document: OnceLock<(Value, Bytes)>,
}

/// The registry being built: [`crate::kind::Register`] adds each kind.
pub struct Builder(Vec<&'static dyn AnyKind>);

impl Register for Builder {
    fn kind<K: Kind>(&mut self) {
        // A zero-sized value: leaking it allocates nothing.
        self.0.push(Box::leak(Box::new(Registered::<K>(PhantomData))));
    }
}

impl Registry {
    /// The kinds `register` adds, in the order of the documentation, then `more`.
    pub fn new(register: impl FnOnce(&mut Builder), more: &[&'static dyn AnyKind]) -> Self {
        let mut builder = Builder(Vec::new());
        register(&mut builder);
        builder.0.extend(more);
        Self(Arc::new(Inner { kinds: builder.0, document: OnceLock::new() }))
    }

    /// Every kind, in the order of the documentation.
    pub fn iter(&self) -> impl Iterator<Item = &'static dyn AnyKind> + '_ {
        self.0.kinds.iter().copied()
    }

    /// The kind of this name.
    pub fn find(&self, name: &str) -> Option<&'static dyn AnyKind> {
        self.iter().find(|k| k.name() == name)
    }

    /// The kinds' names, for messages.
    pub fn names(&self) -> Vec<&'static str> {
        self.iter().map(|k| k.name()).collect()
    }

    /// The OpenAPI document as served at `/openapi.json` ([`super::document`]),
    /// made once, and its text.
    pub fn document(&self) -> &(Value, Bytes) {
        self.0.document.get_or_init(|| super::document(self))
    }

    /// The OpenAPI document as a value.
    pub fn openapi(&self) -> Value {
        self.document().0.clone()
    }

    /// The OpenAPI document's text, as served and as `cargo run -- openapi` prints it.
    pub fn openapi_json(&self) -> &str {
        std::str::from_utf8(&self.document().1).unwrap_or_default()
    }
}

/// The key of a template's statement quantities in its job's result
/// (`templates/statement.rs`), and of where each comes from beside them.
pub const STATEMENT: &str = "statement";
pub const STATEMENT_FROM: &str = "statement_from";

/// The pointer (as tokens) whose unit `/statement/NAME` has, if it is one.
fn statement_source(result: &Value, pointer: &[&str]) -> Option<Vec<String>> {
    match pointer {
        [STATEMENT, name] => {
            let of = result[STATEMENT_FROM][*name].as_str()?;
            Some(of.split('/').skip(1).map(|t| t.replace("~1", "/").replace("~0", "~")).collect())
        }
        _ => None,
    }
}
