//! Parts of a stored job's result: one value by JSON pointer, answered as
//! plain text for a spreadsheet's `WEBSERVICE()` in a unit of the client's
//! choice, and every scalar with its unit (`/values`, JSON or CSV).

use super::AppState;
use super::body::guarded;
use super::kind;
use super::read::{query, result_tree, wants};
use super::tables::{self, AngleUnit, Angles, Decimal, DecimalMark, Format, Values};
use crate::kind::problem::{ApiError, FieldError, PrivateErrors, Problem, ReadErrors};
use crate::store::JobRow;
use axum::body::Body;
use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::{HeaderMap, header};
use axum::response::{IntoResponse, Response};
use serde_json::Value;
use std::collections::HashMap;

/// One part of a job's result, by JSON pointer.
///
/// A number, text, flag or null is answered alone as `text/plain` (numbers
/// in shortest round-trip form), unless `Accept: application/json` asks for
/// JSON; an object or an array is answered as JSON. `?unit=` converts a
/// number to another unit of its dimension (`?unit=slug*ft^2`).
#[utoipa::path(get, path = "/v1/jobs/{id}/result/{pointer}", operation_id = "get_job_result_part", tag = "jobs",
    params(
        ("id" = String, Path, description = "Job id"),
        ("pointer" = String, Path, description = "JSON pointer into the result without its leading `/`: \
            `inertia_exact`, `flywheel_inertia/exact`, `steps/90/driving` (RFC 6901: `~1` for a `/` in a key, `~0` for `~`)"),
        ("unit" = Option<String>, Query, description = "Convert a number to this unit, e.g. `slug*ft^2`, `rpm`, `deg`, `%`"),
        ("decimal" = Option<DecimalMark>, Query, description = "`point` (default) or `comma`: `0,628…` for a sheet in a Spanish locale"),
        ("errors" = Option<String>, Query, description = "`text`: an error answered as 200 `text/plain`, one line in the asker's language, its own status in the `Mechdyn-Status` header (a spreadsheet's WEBSERVICE() shows only #VALUE! for a 4xx)"),
    ),
    responses(
        (status = 200, description = "The value alone (text/plain), or JSON for an object or array or with `Accept: application/json`",
            content((String = "text/plain", example = "353.5214273220119"), (serde_json::Value = "application/json"))),
        (status = 400, description = "A unit of the wrong dimension, a part without a unit, or an unknown query parameter",
            body = Problem, content_type = "application/problem+json",
            example = json!({"type": "/problems/invalid-query", "title": "Invalid query parameters", "status": 400,
                "detail": "invalid query parameters",
                "errors": [{"parameter": "unit", "message": "'rpm' is a unit of rad/s; the part at /inertia_exact is in kg*m^2"}]})),
        ReadErrors,
        PrivateErrors,
    ))]
pub async fn part(
    State(state): State<AppState>,
    Path((id, pointer)): Path<(String, String)>,
    headers: HeaderMap,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Response, ApiError> {
    let q = query(q, &["unit", "decimal"])?;
    let (row, result, _reserved) = result_tree(&state, &id).await?;
    let (mime, text) = text(&state.kinds, &row, &result, &pointer, &q, &headers)?;
    Ok(([(header::CONTENT_TYPE, mime)], text).into_response())
}

/// The part of `result` (of job `row`) at `pointer`, converted to the
/// query's `unit` and written with its `decimal` mark, as [`part`] answers
/// it: its content type and text.
pub fn text(
    kinds: &kind::Registry,
    row: &JobRow,
    result: &Value,
    pointer: &str,
    q: &HashMap<String, String>,
    headers: &HeaderMap,
) -> Result<(&'static str, String), ApiError> {
    let decimal = Decimal::of(q)?;
    let unit = q.get("unit").filter(|u| !u.trim().is_empty());
    let Some(value) = value_at(kinds.find(&row.kind), result, pointer, unit)? else {
        let pointer = format!("/{}", pointer.trim_start_matches('/'));
        return Err(ApiError::NoPart { id: row.id.clone(), pointer });
    };
    Ok(text_of(&value, wants(headers, None, "application/json"), decimal))
}

/// The part of `result` (of `kind`) at `pointer` (leading `/` optional),
/// converted to `unit`; None when there is none.
pub fn value_at(
    kind: Option<&dyn kind::AnyKind>,
    result: &Value,
    pointer: &str,
    unit: Option<&String>,
) -> Result<Option<Value>, ApiError> {
    let tokens = tables::tokens(pointer);
    let pointer = format!("/{}", pointer.trim_start_matches('/'));
    let Some(value) = tables::at(result, &tokens) else { return Ok(None) };
    let value = match (unit, value.as_f64()) {
        (Some(target), Some(x)) => {
            let refs: Vec<&str> = tokens.iter().map(String::as_str).collect();
            let unit = kind.and_then(|k| k.unit(result, &refs));
            Value::from(tables::convert(x, unit.as_deref(), target, &pointer)?)
        }
        (Some(_), None) => {
            let message = crate::i18n::Msg::new("unit-part-not-number").arg("pointer", &pointer);
            return Err(ApiError::BadQuery(vec![FieldError::parameter_said("unit", message)]));
        }
        (None, _) => value.clone(),
    };
    Ok(Some(value))
}

/// A part as its answer's type and text: a scalar alone as text (numbers in
/// shortest round-trip form), an object or array (or any, when `json`) as JSON.
/// With a decimal comma (a sheet in a Spanish locale), an array of scalars
/// is text too, its items separated by `; ` (JSON has no decimal comma).
pub fn text_of(value: &Value, json: bool, decimal: Decimal) -> (&'static str, String) {
    let scalars = |v: &Vec<Value>| v.iter().all(|x| !x.is_object() && !x.is_array());
    match value {
        Value::Array(items) if !json && decimal == Decimal::Comma && scalars(items) => {
            let texts: Vec<String> = items.iter().map(|x| scalar(x, decimal)).collect();
            ("text/plain; charset=utf-8", texts.join("; "))
        }
        _ if json || value.is_object() || value.is_array() => ("application/json", value.to_string()),
        _ => ("text/plain; charset=utf-8", scalar(value, decimal)),
    }
}

/// A scalar's text: a number in shortest round-trip form, with `decimal`'s mark.
fn scalar(value: &Value, decimal: Decimal) -> String {
    let text = match value.as_f64() {
        Some(x) if !value.is_i64() && !value.is_u64() => tables::number_text(x),
        _ => crate::kind::cell(value),
    };
    decimal.written(text)
}

/// Every scalar of a job's result with its unit.
///
/// JSON `{"values": [{"pointer", "value", "unit"}]}`, or CSV
/// `pointer,value,unit` with `Accept: text/csv` (or `?format=csv`);
/// `?angles=deg` gives angles in degrees.
#[utoipa::path(get, path = "/v1/jobs/{id}/values", operation_id = "get_job_values", tag = "jobs",
    params(
        ("id" = String, Path, description = "Job id"),
        ("format" = Option<Format>, Query, description = "`json` (default) or `csv`; the same as `Accept: text/csv`"),
        ("angles" = Option<AngleUnit>, Query, description = "`rad` (default) or `deg`"),
        ("decimal" = Option<DecimalMark>, Query, description = "`point` (default) or `comma`: the CSV's numbers with a decimal comma, its columns separated by `;`"),
    ),
    responses(
        (status = 200, description = "Every scalar of the result",
            content((Values = "application/json"), (String = "text/csv", example = "pointer,value,unit\n/inertia_exact,353.5214273220119,kg*m^2\n"))),
        (status = 400, description = "An invalid query parameter", body = Problem, content_type = "application/problem+json"),
        ReadErrors,
        PrivateErrors,
    ))]
pub async fn values(
    State(state): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Response, ApiError> {
    let q = query(q, &["format", "angles", "decimal"])?;
    super::read::format_checked(&q)?;
    let csv = wants(&headers, q.get("format"), "text/csv");
    values_of(&state, &id, &q, csv).await
}

/// Every scalar of a job's result with its unit, as CSV `pointer,value,unit`
/// (what `/values` answers with `Accept: text/csv`, at a path of its own for
/// clients generated from the document, which read one content type an answer).
#[utoipa::path(get, path = "/v1/jobs/{id}/values.csv", operation_id = "get_job_values_csv", tag = "jobs",
    params(
        ("id" = String, Path, description = "Job id"),
        ("angles" = Option<AngleUnit>, Query, description = "`rad` (default) or `deg`"),
        ("decimal" = Option<DecimalMark>, Query, description = "`point` (default) or `comma`: numbers with a decimal comma, columns separated by `;`"),
    ),
    responses(
        (status = 200, description = "Every scalar of the result",
            content((String = "text/csv", example = "pointer,value,unit\n/inertia_exact,353.5214273220119,kg*m^2\n"))),
        (status = 400, description = "An invalid query parameter", body = Problem, content_type = "application/problem+json"),
        ReadErrors,
        PrivateErrors,
    ))]
pub async fn values_csv(
    State(state): State<AppState>,
    Path(id): Path<String>,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
) -> Result<Response, ApiError> {
    values_of(&state, &id, &query(q, &["angles", "decimal"])?, true).await
}

async fn values_of(state: &AppState, id: &str, q: &HashMap<String, String>, csv: bool) -> Result<Response, ApiError> {
    let angles = Angles::parse(q.get("angles")).map_err(|e| ApiError::BadQuery(vec![e]))?;
    let decimal = Decimal::of(q)?;
    let (row, result, reserved) = result_tree(state, id).await?;
    let kind = state.kinds.find(&row.kind).ok_or_else(|| ApiError::Internal(format!("stored kind {}", row.kind)))?;
    let (mime, text) = tokio::task::spawn_blocking(move || {
        let mut values = tables::flatten(kind, &result);
        if csv {
            return tables::values_csv(values, (angles, decimal)).map(|t| ("text/csv; charset=utf-8", t));
        }
        if angles == Angles::Deg {
            for s in values.iter_mut().filter(|s| s.unit.as_deref() == Some("rad")) {
                s.value = s.value.as_f64().map_or(Value::Null, |x| x.to_degrees().into());
                s.unit = Some("deg".into());
            }
        }
        let text = serde_json::to_string(&Values { values }).map_err(|e| ApiError::Internal(e.to_string()))?;
        Ok(("application/json", text))
    })
    .await
    .map_err(|e| ApiError::Internal(format!("values task: {e}")))??;
    Ok(([(header::CONTENT_TYPE, mime)], guarded(Body::from(text), reserved)).into_response())
}
