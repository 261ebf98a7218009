//! `/v1/templates`: problems with parameters. A spreadsheet's
//! `WEBSERVICE()` reads one number of the job a template gives for its
//! parameters (`GET /v1/templates/{id}/result/{pointer}?F=1200`); the same
//! parameters find the stored job again instead of computing it; a whole
//! parameter study is one `POST .../table` of CSV ([`table`]).

mod answers;
mod apply;
mod derived;
mod model;
pub mod statement;
pub mod table;
pub mod variants;

pub use answers::{Answers, PartKey};
pub use apply::{request_for, texts};
pub use model::{LIBRARY_FILES, NewTemplate, Parameter, RESERVED, Template, TemplateList, builtin};
pub use table::{TableRequest, TableResponse, TableRow, study};
pub use variants::{MAX_SEED, Variant, Variants, draw, drawable};

use super::AppState;
use super::body::Chunks;
use super::create::Destination;
use super::job::job_chunks;
use super::json::{JsonBody, RawBody};
use super::kind::AnyKind;
use super::parts;
use super::read;
use super::tables::Decimal;
use crate::kind::problem::{ApiError, FieldError, Problem, ReadErrors};
use crate::store::JobRow;
use axum::body::Body;
use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::{HeaderMap, StatusCode, header};
use axum::response::{IntoResponse, Response};
use std::collections::HashMap;

/// The template of this id: a built-in one, or one a client stored.
pub async fn find(state: &AppState, id: &str) -> Result<Template, ApiError> {
    if let Some(t) = builtin().iter().find(|t| t.id == id) {
        return Ok(t.clone());
    }
    let missing = || ApiError::NoTemplate(id.to_string());
    let body = state.store.template(id).await?.ok_or_else(missing)?;
    serde_json::from_str(&body).map_err(|e| ApiError::Internal(format!("stored template {id}: {e}")))
}

/// What a request wants of a template's job.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Want {
    /// The job itself (its id, its page): a new one is stored, which needs
    /// the API token where the service has one (401 without).
    Job,
    /// Its values only: for a request that may not store a new job, the job
    /// is computed and answered without being stored.
    Values,
}

/// The job `t` gives for `given` parameters: the stored one when these
/// parameters were asked before (same engine version), else computed and
/// stored under the request's key (see [`Want`]); with the memory of its
/// row reserved.
pub async fn job_for(
    state: &AppState,
    t: &Template,
    given: &HashMap<String, String>,
    want: Want,
) -> Result<Held, ApiError> {
    let request = apply::request_for(t, given, RESERVED)?;
    let kind = state.kinds.find(&t.kind).ok_or_else(|| ApiError::Internal(format!("template kind {}", t.kind)))?;
    stored_job(state, kind, &request, want).await.map_err(|e| apply::named(t, e))
}

/// A job row with the memory it takes reserved (released when dropped).
pub type Held = (JobRow, tokio::sync::OwnedSemaphorePermit);

/// The job of `request` of `kind`: the stored one of the same request and
/// engine version (its memory reserved before it is read), else computed
/// and stored under the request's key (see [`Want`]).
pub async fn stored_job(
    state: &AppState,
    kind: &dyn AnyKind,
    request: &serde_json::Value,
    want: Want,
) -> Result<Held, ApiError> {
    let (bytes, key) = apply::keyed(kind.name(), request);
    if let Some(id) = state.store.find_by_key(&key, &bytes).await? {
        return read::load(state, &id, read::READ_MEMORY_FACTOR).await;
    }
    let to = match (super::create::may_store(), want) {
        (true, _) => Destination::New { key: Some(key) },
        (false, Want::Values) => Destination::Unstored,
        (false, Want::Job) => return Err(ApiError::Unauthorized),
    };
    kind.job(state, bytes.into(), to).await
}

/// Lists the templates: the built-in ones (the course's problems), then those clients stored;
/// titles and descriptions in Spanish for a Spanish asker (`?lang=es`, `Accept-Language: es`).
#[utoipa::path(get, path = "/v1/templates", operation_id = "list_templates", tag = "templates",
    responses((status = 200, description = "Every template", body = TemplateList)))]
pub async fn list(State(state): State<AppState>) -> Result<axum::Json<TemplateList>, ApiError> {
    let mut items = builtin().to_vec();
    for body in state.store.templates().await? {
        items.extend(serde_json::from_str::<Template>(&body).ok());
    }
    let lang = crate::i18n::current();
    Ok(axum::Json(TemplateList { items: items.into_iter().map(|t| t.in_language(lang)).collect() }))
}

/// Reads a template: its kind, request, and parameters with their units and ranges (its title
/// and descriptions in Spanish for a Spanish asker).
#[utoipa::path(get, path = "/v1/templates/{id}", operation_id = "get_template", tag = "templates",
    params(("id" = String, Path, description = "Template id, e.g. `p103-slider-flywheel`")),
    responses((status = 200, description = "The template", body = Template), ReadErrors))]
pub async fn get(State(state): State<AppState>, Path(id): Path<String>) -> Result<axum::Json<Template>, ApiError> {
    Ok(axum::Json(find(&state, &id).await?.in_language(crate::i18n::current())))
}

/// The job a template gives for its parameters (`?NAME=VALUE&...`, the
/// others at their defaults): the stored one when asked before, else computed and stored.
#[utoipa::path(get, path = "/v1/templates/{id}/job", operation_id = "get_template_job", tag = "templates",
    params(("id" = String, Path, description = "Template id"),
        ("parameters" = Option<HashMap<String, String>>, Query, style = Form, explode,
            description = "The template's parameters, e.g. `F=1200&eps=0.03`: a number in the parameter's unit, or a quantity (`300 rpm`)")),
    responses(
        (status = 200, description = "The job", body = super::job::Job),
        (status = 400, description = "An unknown parameter or a value out of its range", body = Problem, content_type = "application/problem+json"),
        (status = 401, description = "The service has an API token, these parameters' job is not stored yet, and \
            the request does not carry the token (it would store a new job)", body = Problem, content_type = "application/problem+json"),
        (status = 422, description = "These parameters do not give a valid problem", body = Problem, content_type = "application/problem+json"),
        ReadErrors,
        crate::kind::problem::PrivateErrors,
    ))]
pub async fn job(
    State(state): State<AppState>,
    Path(id): Path<String>,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Response, ApiError> {
    let q = parameters(q)?;
    let t = find(&state, &id).await?;
    let (row, reserved) = job_for(&state, &t, &q, Want::Job).await?;
    let mut body = Chunks::default();
    job_chunks(&row, &mut body);
    let location = format!("/v1/jobs/{}", row.id);
    Ok((
        [(header::CONTENT_TYPE, "application/json".to_string()), (header::CONTENT_LOCATION, location)],
        super::body::guarded(Body::new(body), reserved),
    )
        .into_response())
}

/// One part of the result of the job a template gives for its parameters,
/// as `/v1/jobs/{id}/result/{pointer}` answers it: what a spreadsheet's
/// `=WEBSERVICE(".../v1/templates/p103-slider-flywheel/result/inertia_exact?F=1200")` reads.
///
/// Where the service has an API token and the request does not carry it,
/// a job not stored yet is computed and answered without being stored.
#[utoipa::path(get, path = "/v1/templates/{id}/result/{pointer}", operation_id = "get_template_result_part", tag = "templates",
    params(("id" = String, Path, description = "Template id"),
        ("pointer" = String, Path, description = "JSON pointer into the result without its leading `/`, e.g. `inertia_exact`"),
        ("unit" = Option<String>, Query, description = "Convert a number to this unit, e.g. `slug*ft^2`"),
        ("decimal" = Option<super::tables::DecimalMark>, Query, description = "`point` (default) or `comma`: `0,628…` for a sheet in a Spanish locale"),
        ("errors" = Option<String>, Query, description = "`text`: an error answered as 200 `text/plain`, one line in the asker's language, its own status in the `Mechdyn-Status` header (a spreadsheet's WEBSERVICE() shows only #VALUE! for a 4xx)"),
        ("parameters" = Option<HashMap<String, String>>, Query, style = Form, explode,
            description = "The template's parameters, e.g. `F=1200&eps=0.03`")),
    responses(
        (status = 200, description = "The value alone (text/plain), or JSON for an object or array",
            content((String = "text/plain", example = "353.5214273220119"), (serde_json::Value = "application/json"))),
        (status = 400, description = "An unknown parameter, a value out of its range, or a unit of the wrong dimension",
            body = Problem, content_type = "application/problem+json"),
        (status = 422, description = "These parameters do not give a valid problem", body = Problem, content_type = "application/problem+json"),
        ReadErrors,
    ))]
pub async fn result(
    State(state): State<AppState>,
    Path((id, pointer)): Path<(String, String)>,
    headers: HeaderMap,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Response, ApiError> {
    let q = parameters(q)?;
    let t = find(&state, &id).await?;
    let request = apply::request_for(&t, &q, RESERVED)?;
    let kind = state.kinds.find(&t.kind).ok_or_else(|| ApiError::Internal(format!("template kind {}", t.kind)))?;
    let key = PartKey {
        request: apply::keyed(kind.name(), &request).1,
        pointer: pointer.trim_start_matches('/').to_string(),
        unit: q.get("unit").filter(|u| !u.trim().is_empty()).cloned(),
        decimal: Decimal::of(&q)? == Decimal::Comma,
        json: read::wants(&headers, None, "application/json"),
        lang: crate::i18n::current(),
    };
    if let Some((mime, body)) = state.answers.get(&key) {
        return Ok(([(header::CONTENT_TYPE, mime)], body).into_response());
    }
    let (row, mut reserved) =
        stored_job(&state, kind, &request, Want::Values).await.map_err(|e| apply::named(&t, e))?;
    // The row is held (read factor); the parsed tree takes the rest of a part's memory.
    let tree = row.result.len().saturating_mul(read::CSV_MEMORY_FACTOR - read::READ_MEMORY_FACTOR);
    reserved.merge(state.admission.memory(tree).await?);
    let mut result =
        serde_json::from_slice(&row.result).map_err(|e| ApiError::Internal(format!("stored result: {e}")))?;
    crate::kind::notes::localise(&mut result);
    statement::add(&t.statement, &mut result);
    let (mime, text) = parts::text(&state.kinds, &row, &result, &pointer, &q, &headers)?;
    let body = bytes::Bytes::from(text);
    // Kept only of a stored job (an unstored row has no sequence number):
    // the next request with the token then finds it stored, as it would
    // without the answers kept.
    if row.seq > 0 {
        state.answers.keep(key, (mime, body.clone()));
    }
    Ok(([(header::CONTENT_TYPE, mime)], body).into_response())
}

fn parameters(q: Result<Query<HashMap<String, String>>, QueryRejection>) -> Result<HashMap<String, String>, ApiError> {
    let Query(q) = q.map_err(|e| ApiError::BadQuery(vec![FieldError::parameter("", e.body_text())]))?;
    if q.contains_key("") {
        return Err(ApiError::BadQuery(vec![FieldError::parameter_said(
            "",
            crate::i18n::Msg::new("parameter-nameless"),
        )]));
    }
    Ok(q)
}

/// Creates a template: `request` is solved once (a template that cannot be
/// solved is refused with the usual 422, its pointers under `/request`).
#[utoipa::path(post, path = "/v1/templates", operation_id = "create_template", tag = "templates", request_body = NewTemplate,
    responses(
        (status = 201, description = "Template stored", body = Template,
            headers(("Location" = String, description = "/v1/templates/{id}"))),
        (status = 409, description = "A template of this name exists", body = Problem, content_type = "application/problem+json"),
        crate::kind::problem::PostErrors,
    ))]
pub async fn create(State(state): State<AppState>, body: JsonBody<NewTemplate>) -> Result<Response, ApiError> {
    let JsonBody { value, unknown, .. } = body;
    let t = model::checked(&state.kinds, value, unknown)?;
    if builtin().iter().any(|b| b.id == t.id) {
        return Err(ApiError::Conflict(crate::i18n::Msg::new("template-builtin").arg("id", &t.id)));
    }
    let (bytes, key) = apply::keyed(&t.kind, &t.request);
    let kind = state.kinds.find(&t.kind).ok_or_else(|| ApiError::Internal(format!("kind {}", t.kind)))?;
    let (_solved, _reserved) =
        kind.job(&state, bytes.into(), Destination::New { key: Some(key) }).await.map_err(model::under_request)?;
    let text = serde_json::to_string(&t).map_err(|e| ApiError::Internal(e.to_string()))?;
    if !state.store.insert_template(&t.id, &super::create::now_rfc3339(), &text).await? {
        return Err(ApiError::Conflict(crate::i18n::Msg::new("template-exists").arg("id", &t.id)));
    }
    let location = format!("/v1/templates/{}", t.id);
    let headers = [(header::CONTENT_TYPE, "application/json".to_string()), (header::LOCATION, location)];
    Ok((StatusCode::CREATED, headers, text).into_response())
}

/// A parameter study: one variant per row of a CSV (or JSON) table.
#[utoipa::path(post, path = "/v1/templates/{id}/table", operation_id = "post_template_table", tag = "templates",
    params(("id" = String, Path, description = "Template id"),
        ("values" = Option<String>, Query, description = "Comma-separated JSON pointers of the values to answer per row, e.g. `inertia_exact,energy_fluctuation`"),
        ("decimal" = Option<super::tables::DecimalMark>, Query, description = "`point` (default) or `comma`: the CSV answer's numbers with a decimal comma, its columns separated by `;`")),
    request_body(description = "CSV: a header row of parameter names (optionally `name [unit]`), a row per variant; or JSON",
        content((String = "text/csv", example = "F,eps\n1000,0.03\n1200,0.03\n"), (TableRequest = "application/json"))),
    responses(
        (status = 200, description = "A row per variant: the inputs, the values, the job and the error (empty, or why that row failed)",
            content((String = "text/csv", example = "F,eps,inertia_exact,job,error\n1000,0.03,...\n"), (TableResponse = "application/json"))),
        (status = 400, description = "An unknown column, a malformed table or `values`", body = Problem, content_type = "application/problem+json"),
        (status = 413, description = "The body is larger than the limit on a request body", body = Problem, content_type = "application/problem+json"),
        (status = 415, description = "Neither text/csv nor application/json", body = Problem, content_type = "application/problem+json"),
        ReadErrors,
    ))]
pub async fn table(
    State(state): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
    RawBody(body): RawBody,
) -> Result<Response, ApiError> {
    let q = read::query(q, &["values", "label", "decimal"])?;
    let t = find(&state, &id).await?;
    let (text, csv) = study(&state, &t, &headers, (q.get("values"), Decimal::asked(&q)?), &body).await?;
    let mime = if csv { "text/csv; charset=utf-8" } else { "application/json" };
    Ok(([(header::CONTENT_TYPE, mime)], text).into_response())
}

/// Seeded variants: per-student parameter sets with their reference values.
///
/// Variant `v` is the single draw with seed `v` (the generator: SplitMix64
/// seeded with `v`, one draw per parameter in name order, mapped onto the
/// parameter's `choices` or `min`/`max`/`step` grid; see docs/grading.md), so the
/// same template and seed give the same parameters everywhere and forever.
#[utoipa::path(get, path = "/v1/templates/{id}/variants", operation_id = "get_template_variants", tag = "grading",
    params(("id" = String, Path, description = "Template id"),
        ("seed" = Option<u64>, Query, description = "The first variant, 0 to 2^63 − 1 (default 1); the last, seed + count − 1, at most 2^63 − 1 too", maximum = 9223372036854775807_u64),
        ("count" = Option<u64>, Query, description = "How many, 1 to 1000 (default 10)", minimum = 1, maximum = 1000),
        ("values" = Option<String>, Query, description = "Comma-separated pointers of the reference values to answer, e.g. `inertia_exact`"),
        ("format" = Option<super::tables::Format>, Query, description = "`json` (default) or `csv`; the same as `Accept: text/csv`"),
        ("decimal" = Option<super::tables::DecimalMark>, Query, description = "`point` (default) or `comma`: the CSV's numbers with a decimal comma, its columns separated by `;`")),
    responses(
        (status = 200, description = "The variants",
            content((Variants = "application/json"), (String = "text/csv", example = "variant,F [N*m],inertia_exact\n1,650,459.58\n"))),
        (status = 400, description = "An invalid seed, count or values", body = Problem, content_type = "application/problem+json"),
        ReadErrors,
    ))]
pub async fn variants(
    State(state): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Response, ApiError> {
    let q = read::query(q, &["seed", "count", "values", "format", "decimal"])?;
    let decimal = Decimal::of(&q)?;
    read::format_checked(&q)?;
    let number = |name: &str, default: u64| {
        q.get(name).map_or(Ok(default), |v| {
            v.trim().parse::<u64>().map_err(|_| table::bad(name, crate::i18n::Msg::new("field-whole-not-negative")))
        })
    };
    let (seed, count) = (number("seed", 1)?, number("count", 10)?);
    let values = q.get("values").map_or_else(Vec::new, |v| table::pointer_list(v));
    let t = find(&state, &id).await?;
    let list = variants::list(&state, &t, seed, count, &values).await?;
    if read::wants(&headers, q.get("format"), "text/csv") {
        return Ok(([(header::CONTENT_TYPE, "text/csv; charset=utf-8")], variants::csv(&t, &list, &values, decimal)?)
            .into_response());
    }
    Ok(axum::Json(list).into_response())
}
