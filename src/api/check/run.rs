//! A check run: its reference found (a template's job, a request's job,
//! both stored and reused under their request key, or a stored job), its
//! answers graded off the async workers, and the check stored as a job of
//! kind `check`. Also the check's place in the registry ([`CheckKind`]):
//! its route and document, its table and units.

use super::{CheckOutput, CheckRequest, at, grade, table, validate};
use crate::api::create::Destination;
use crate::api::json::{JsonBody, parse};
use crate::api::kind::{self, AnyKind, StoredJob};
use crate::api::templates::{self, Held, RESERVED, Template};
use crate::api::{AppState, create, job, read};
use crate::i18n::Msg;
use crate::kind::limits::Limits;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::{Table, json_bytes, unit_in};
use crate::store::JobRow;
use axum::extract::State;
use axum::http::HeaderMap;
use axum::response::Response;
use bytes::Bytes;
use serde_json::Value;
use std::collections::HashMap;
use utoipa::{PartialSchema, ToSchema};
use utoipa_axum::router::UtoipaMethodRouter;

/// `check` in the registry.
pub struct CheckKind;

/// The registry's entry.
pub static CHECK: CheckKind = CheckKind;

const UNITS: &[(&str, &str)] = &[
    ("/score", "1"),
    ("/passed", "1"),
    ("/total", "1"),
    ("/items/*/relative_error", "1"),
    ("/max_score", "1"),
    ("/tests/*/points", "1"),
    ("/tests/*/max_points", "1"),
    ("/tests/*/score", "1"),
    ("/tests/*/max_score", "1"),
];

/// `POST /v1/check`: the answers checked, stored as a job of kind `check`.
pub async fn post(
    State(state): State<AppState>,
    headers: HeaderMap,
    body: JsonBody<CheckRequest>,
) -> Result<Response, ApiError> {
    if crate::api::deferred::wanted(&headers) {
        return crate::api::deferred::accept(&state, CHECK.name(), body.raw, body.unknown).await;
    }
    let (row, reserved) = check_job(&state, body, Destination::POSTED).await?;
    Ok(create::created(&row, reserved))
}

/// The check of `body`, computed and stored at `to`.
pub async fn check_job(
    state: &AppState,
    body: JsonBody<CheckRequest>,
    to: Destination,
) -> Result<(JobRow, tokio::sync::OwnedSemaphorePermit), ApiError> {
    let JsonBody { value: r, raw, mut unknown } = body;
    unknown.extend(validate(&r));
    if !unknown.is_empty() {
        return Err(ApiError::Invalid(unknown));
    }
    // The reference's memory stays reserved until the check is stored.
    let (kind, (reference, _reserved), template) = reference(state, &r).await?;
    let (result, id) = (reference.result.clone(), reference.id.clone());
    let grading = move |_: &Limits| {
        let mut result: Value =
            serde_json::from_slice(&result).map_err(|e| ApiError::Internal(format!("stored result: {e}")))?;
        if let Some(t) = &template {
            templates::statement::add(&t.statement, &mut result);
        }
        grade(&r, kind, &result, Some(id))
    };
    create::compute_and_store(state, create::Work::own(CHECK.name(), grading), raw, to).await
}

/// The reference job of a check: stored, or computed and stored; and its
/// template, when it has one (its statement's quantities are graded too).
async fn reference(
    state: &AppState,
    r: &CheckRequest,
) -> Result<(&'static dyn AnyKind, Held, Option<Template>), ApiError> {
    if let Some(id) = &r.job {
        let (row, reserved) = read::load(state, id, read::READ_MEMORY_FACTOR).await.map_err(|e| match e {
            ApiError::NotFound(_) => {
                ApiError::Invalid(vec![FieldError::said("/job", Msg::new("detail-not-found").arg("id", id))])
            }
            e => e,
        })?;
        read::done(&row).map_err(|e| ApiError::Invalid(vec![FieldError::said("/job", e.msg())]))?;
        return Ok((gradable(&state.kinds, &row.kind, "/job")?, (row, reserved), None));
    }
    if let Some(id) = &r.template {
        let t = templates::find(state, id).await.map_err(|e| no_template(e, id))?;
        let kind = gradable(&state.kinds, &t.kind, "/template")?;
        if r.variant.is_some() {
            templates::drawable(&t).map_err(|why| ApiError::Invalid(vec![FieldError::said("/variant", why)]))?;
        }
        let row = templates::job_for(state, &t, &given(&t, r), templates::Want::Job).await.map_err(under_parameters)?;
        return Ok((kind, row, Some(t)));
    }
    let (kind, request) = kind_request(&state.kinds, r)?;
    let row =
        templates::stored_job(state, kind, request, templates::Want::Job).await.map_err(|e| e.under("/request"))?;
    Ok((kind, row, None))
}

/// The kind of a reference: any but `check`.
fn gradable(kinds: &kind::Registry, name: &str, field: &str) -> Result<&'static dyn AnyKind, ApiError> {
    match kinds.find(name).filter(|k| k.name() != CHECK.name()) {
        Some(k) => Ok(k),
        None => {
            let known: Vec<&str> = kinds.names().into_iter().filter(|n| *n != CHECK.name()).collect();
            let why = Msg::new("check-kind-unknown").arg("name", name).arg("known", known.join(", "));
            Err(ApiError::Invalid(vec![FieldError::said(field, why)]))
        }
    }
}

fn kind_request<'a>(
    kinds: &kind::Registry,
    r: &'a CheckRequest,
) -> Result<(&'static dyn AnyKind, &'a Value), ApiError> {
    let kind = gradable(kinds, r.kind.as_deref().unwrap_or_default(), "/kind")?;
    Ok((kind, r.request.as_ref().unwrap_or(&Value::Null)))
}

/// The template's parameters of a check: as given, or its variant's.
fn given(t: &Template, r: &CheckRequest) -> HashMap<String, String> {
    match (r.variant, &r.parameters) {
        (Some(v), _) => templates::texts(&templates::draw(t, v)),
        (None, Some(p)) => templates::texts(p),
        (None, None) => HashMap::new(),
    }
}

fn no_template(e: ApiError, id: &str) -> ApiError {
    match e {
        ApiError::NoTemplate(_) => {
            ApiError::Invalid(vec![FieldError::said("/template", Msg::new("check-template-unknown").arg("id", id))])
        }
        e => e,
    }
}

/// A template's parameter errors (named in a query elsewhere) at `/parameters/NAME`.
fn under_parameters(e: ApiError) -> ApiError {
    match e {
        ApiError::BadQuery(errors) => ApiError::Invalid(
            errors
                .into_iter()
                .map(|f| {
                    let here = at("parameters", f.parameter.as_deref().unwrap_or_default());
                    FieldError { pointer: Some(here), parameter: None, ..f }
                })
                .collect(),
        ),
        e => e,
    }
}

/// The check without a store (the document's example): built-in templates
/// and requests are solved here; a stored job cannot be read.
fn solve_offline(raw: String, limits: &Limits, kinds: &kind::Registry) -> Result<Vec<u8>, ApiError> {
    let JsonBody { value: r, mut unknown, .. } = parse::<CheckRequest>(raw)?;
    unknown.extend(validate(&r));
    if !unknown.is_empty() {
        return Err(ApiError::Invalid(unknown));
    }
    let (kind, request) = match (&r.template, &r.job) {
        (_, Some(_)) => {
            return Err(ApiError::Invalid(vec![FieldError::said("/job", Msg::new("check-job-offline"))]));
        }
        (Some(id), _) => {
            let t = templates::builtin()
                .iter()
                .find(|t| &t.id == id)
                .ok_or_else(|| no_template(ApiError::NoTemplate(id.clone()), id))?;
            let request = templates::request_for(t, &given(t, &r), RESERVED).map_err(under_parameters)?;
            (gradable(kinds, &t.kind, "/template")?, request)
        }
        (None, None) => kind_request(kinds, &r).map(|(k, v)| (k, v.clone()))?,
    };
    let result = kind.solve(request.to_string(), limits, kinds).map_err(|e| e.under("/request"))?;
    let result: Value = serde_json::from_slice(&result).map_err(|e| ApiError::Internal(e.to_string()))?;
    json_bytes(&grade(&r, kind, &result, None)?).map_err(|e| ApiError::Internal(e.to_string()))
}

impl AnyKind for CheckKind {
    fn name(&self) -> &'static str {
        "check"
    }
    fn title(&self) -> String {
        crate::i18n::say("kind-check")
    }
    fn path(&self) -> &'static str {
        "/v1/check"
    }
    fn route(&self) -> UtoipaMethodRouter<AppState> {
        let mut schemas = Vec::new();
        CheckRequest::schemas(&mut schemas);
        CheckOutput::schemas(&mut schemas);
        schemas.push((CheckRequest::name().into(), CheckRequest::schema()));
        schemas.push((CheckOutput::name().into(), CheckOutput::schema()));
        schemas.push((format!("JobOf_{}", CheckOutput::name()), job::JobOf::<CheckOutput>::schema()));
        let summary = "Checks students' answers against the engine's: each within a tolerance (relative, absolute, \
significant figures, zero level), with feedback naming the common slip a wrong answer matches; in the service's \
format or as PrairieLearn's or Gradescope's results document.";
        let names = (CheckRequest::name().to_string(), CheckOutput::name().to_string());
        let paths = kind::operation_for(self.path(), "create_check", "grading", summary, names);
        (schemas, paths, axum::routing::post(post))
    }
    fn solve(&self, raw: String, limits: &Limits, kinds: &kind::Registry) -> Result<Vec<u8>, ApiError> {
        solve_offline(raw, limits, kinds)
    }
    fn job<'a>(&'a self, state: &'a AppState, request: Bytes, to: Destination) -> StoredJob<'a> {
        Box::pin(async move { check_job(state, parse::<CheckRequest>(request)?, to).await })
    }
    fn request_schema(&self) -> String {
        CheckRequest::name().into()
    }
    fn result_schema(&self) -> String {
        CheckOutput::name().into()
    }
    fn units(&self) -> &'static [(&'static str, &'static str)] {
        UNITS
    }
    fn table(&self, result: &Value) -> Option<Table> {
        table(result)
    }
    /// An item's numbers are in its `unit`.
    fn unit(&self, result: &Value, pointer: &[&str]) -> Option<String> {
        match pointer {
            ["items", i, "given" | "expected" | "answer"] => {
                result["items"].get(i.parse::<usize>().ok()?)?["unit"].as_str().map(String::from)
            }
            _ => unit_in(UNITS, pointer).map(String::from),
        }
    }
    /// A check has no curve.
    fn plots(&self, job: &crate::kind::plots::Job) -> Vec<crate::api::plots::Listed> {
        (crate::kind::plots::NONE.list)(job)
    }
    fn plot(
        &self,
        job: &crate::kind::plots::Job,
        name: &str,
        o: &crate::kind::plots::Options,
    ) -> crate::kind::plots::Drawn {
        (crate::kind::plots::NONE.draw)(job, name, o)
    }
}
