//! A whole class graded in one request: a CSV with a row per student
//! (`student`, the student's parameters or `variant`, and answer columns
//! named by pointer, optionally `pointer [unit]`), answered with a CSV of
//! `student`, `score`, then per answer `POINTER pass` and `POINTER
//! relative_error`, then `feedback` and `error`. Each row stands alone: a
//! bad row says why in `error` and the others are graded. Students with the
//! same parameters share one stored reference job.

use super::{CheckOutput, CheckRequest, ToleranceDto, grade_with};
use crate::api::AppState;
use crate::api::json::RawBody;
use crate::api::read;
use crate::api::tables;
use crate::api::tables::Csv;
use crate::api::templates::table::{self, Column, Sheet, bad, bad_cell, parameters_of, ragged, read_csv, said};
use crate::api::templates::{RESERVED, Template, Want, find, job_for, texts, variants};
use crate::i18n::Msg;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::problem::{Problem, ReadErrors};
use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::{HeaderMap, header};
use axum::response::{IntoResponse, Response};
use serde_json::Value;
use std::collections::{BTreeMap, HashMap, HashSet};
use std::sync::{Arc, OnceLock};

/// The query names of a grade: the tolerance and `reveal`.
pub const QUERY: &[&str] = &["relative", "absolute", "sigfigs", "zero_level", "reveal", "label", "decimal"];

/// The tolerance and `reveal` of a grade's query.
pub fn options(q: &HashMap<String, String>) -> Result<(ToleranceDto, bool), ApiError> {
    let number = |name: &str| -> Result<Option<f64>, ApiError> {
        q.get(name)
            .map(|v| {
                crate::units::number(v)
                    .filter(|x| x.is_finite() && *x >= 0.0)
                    .ok_or_else(|| bad(name, Msg::new("field-finite-not-negative")))
            })
            .transpose()
    };
    let sigfigs = q
        .get("sigfigs")
        .map(|v| {
            v.trim()
                .parse::<u32>()
                .ok()
                .filter(|n| super::SIGFIGS.contains(n))
                .ok_or_else(|| bad("sigfigs", Msg::new("check-sigfigs")))
        })
        .transpose()?;
    let reveal = match q.get("reveal").map(|v| v.trim().to_ascii_lowercase()).as_deref() {
        None | Some("true") | Some("1") => true,
        Some("false") | Some("0") => false,
        Some(_) => return Err(bad("reveal", Msg::new("query-true-false"))),
    };
    let t = ToleranceDto {
        relative: number("relative")?,
        absolute: number("absolute")?,
        sigfigs,
        zero_level: number("zero_level")?,
    };
    Ok((t, reveal))
}

/// The columns of a class CSV.
struct Layout {
    student: usize,
    variant: Option<usize>,
    /// Answer columns: index, pointer (as written, without `/`), unit of bare numbers.
    answers: Vec<(usize, String, Option<String>)>,
}

fn layout(t: &Template, header: &[Column]) -> Result<Layout, ApiError> {
    let find = |name: &str| header.iter().position(|(_, n, _)| n == name);
    let student = find("student").ok_or_else(|| bad_cell(Some(1), None, Msg::new("class-student-column")))?;
    let variant = find("variant");
    let answers: Vec<(usize, String, Option<String>)> = header
        .iter()
        .enumerate()
        .filter(|(i, (_, n, _))| {
            *i != student && Some(*i) != variant && (n.starts_with('/') || !t.parameters.contains_key(n))
        })
        .map(|(i, (_, n, u))| (i, n.trim_start_matches('/').to_string(), u.clone()))
        .collect();
    if answers.is_empty() {
        return Err(bad_cell(Some(1), None, Msg::new("class-answers-none")));
    }
    if let Some((_, n, _)) = answers.iter().find(|(_, n, _)| RESERVED.contains(&n.as_str())) {
        return Err(bad_cell(Some(1), Some(n), Msg::new("class-reserved")));
    }
    Ok(Layout { student, variant, answers })
}

/// The graded class of `body` (CSV text) for template `t`.
pub async fn class(
    state: &AppState,
    t: &Template,
    q: &HashMap<String, String>,
    body: &[u8],
) -> Result<String, ApiError> {
    let (tolerance, reveal) = options(q)?;
    let Sheet { header, rows, lines, delimiter } = read_csv(body)?;
    let l = layout(t, &header)?;
    if l.variant.is_some() {
        variants::drawable(t).map_err(|why| bad_cell(Some(1), Some("variant"), why))?;
    }
    let params: Vec<Column> = header
        .iter()
        .enumerate()
        .filter(|(i, _)| *i != l.student && Some(*i) != l.variant && !l.answers.iter().any(|a| a.0 == *i))
        .map(|(_, c)| c.clone())
        .collect();
    let decimal = crate::api::tables::Decimal::asked(q)?;
    let mut out = Csv::new(decimal.unwrap_or(crate::api::tables::Decimal::as_sent(delimiter)));
    let mut head = vec!["student".to_string(), "score".to_string()];
    for (_, name, _) in &l.answers {
        head.extend([format!("{name} pass"), format!("{name} relative_error")]);
    }
    head.extend(["feedback".to_string(), "error".to_string()]);
    out.record(&head)?;
    let (mut seen, mut students) = (References::default(), HashSet::new());
    // The rows share one job's budget ([`table::spent`]).
    let deadline = state.limits.deadline();
    for (row, &line) in rows.iter().zip(&lines) {
        let student = row.get(l.student).cloned().unwrap_or_default();
        let refused = ragged(&header, row, line, delimiter)
            .map(|m| m.text())
            .or_else(|| deadline.expired().then(|| table::spent(state).text()))
            .or_else(|| student.is_empty().then(|| Msg::new("class-row-no-student").count("row", line).text()))
            .or_else(|| {
                let twice = !students.insert(student.clone());
                twice.then(|| Msg::new("class-student-twice").arg("student", &student).text())
            });
        if let Some(why) = refused {
            out.record(failed(&l, &student, &why))?;
            continue;
        }
        let cells = match graded(state, t, &l, (&params, &header), row, (tolerance, reveal), &mut seen).await {
            Ok(cells) => cells,
            Err(e @ (ApiError::Saturated { .. } | ApiError::StorageFull(_) | ApiError::Unavailable(_))) => {
                return Err(e);
            }
            Err(ApiError::Invalid(errors))
                if errors.iter().all(|f| f.pointer.as_deref().is_some_and(|p| p.starts_with("/answers/"))) =>
            {
                return Err(column_errors(errors));
            }
            Err(e) => failed(&l, &student, &said(&e)),
        };
        out.record(&cells)?;
    }
    out.text()
}

/// An answer column the result has no number for: the same in every row, so
/// one 400 naming the column.
fn column_errors(errors: Vec<FieldError>) -> ApiError {
    let named = errors.into_iter().map(|f| {
        let column = f
            .pointer
            .as_deref()
            .unwrap_or_default()
            .trim_start_matches("/answers/")
            .replace("~1", "/")
            .replace("~0", "~");
        FieldError { pointer: None, row: Some(1), column: Some(column), ..f }
    });
    ApiError::BadTable(named.collect())
}

/// A row that could not be graded: its student and why.
fn failed(l: &Layout, student: &str, why: &str) -> Vec<String> {
    let mut cells = vec![student.to_string(), String::new()];
    cells.extend(std::iter::repeat_n(String::new(), 2 * l.answers.len() + 1));
    cells.push(why.to_string());
    cells
}

/// The reference results read so far in one grade, by their parameters:
/// students sharing a variant share one read and parse of its job. Bounded:
/// forgotten once they held [`REFERENCE_BYTES`] of stored JSON (a parsed
/// tree takes about eight times its text).
#[derive(Default)]
struct References {
    results: HashMap<Vec<(String, String)>, Reference>,
    bytes: usize,
}

/// A reference job's id, its result parsed, and its scalars once flattened (for slips).
type Reference = (String, Arc<Value>, Arc<OnceLock<super::items::Nearby>>);

/// Stored JSON of the references kept parsed at once in a grade.
const REFERENCE_BYTES: usize = 4 << 20;

/// One student's row graded.
async fn graded(
    state: &AppState,
    t: &Template,
    l: &Layout,
    (params, header): (&[Column], &[Column]),
    row: &[String],
    (tolerance, reveal): (ToleranceDto, bool),
    seen: &mut References,
) -> Result<Vec<String>, ApiError> {
    let mut given: HashMap<String, String> = HashMap::new();
    let variant = l.variant.map(|i| row[i].trim()).filter(|v| !v.is_empty());
    let own_parameters = header.iter().zip(row).any(|(c, cell)| params.contains(c) && !cell.is_empty());
    match (l.variant, variant, own_parameters) {
        (_, Some(_), true) => return Err(bad("variant", Msg::new("class-variant-and-parameters"))),
        (Some(_), None, false) => return Err(bad("variant", Msg::new("class-variant-none"))),
        _ => {}
    }
    if let Some(v) = variant {
        let seed = v
            .parse::<u64>()
            .ok()
            .filter(|v| *v <= variants::MAX_SEED)
            .ok_or_else(|| bad("variant", Msg::new("class-variant-number").arg("text", v)))?;
        given.extend(texts(&variants::draw(t, seed)));
    }
    let own: Vec<String> =
        header.iter().zip(row).map(|(c, cell)| if params.contains(c) { cell.clone() } else { String::new() }).collect();
    given.extend(parameters_of(header, &own));
    let mut asked: Vec<(String, String)> = given.clone().into_iter().collect();
    asked.sort();
    let (job, result, flat) = match seen.results.get(&asked) {
        Some(found) => found.clone(),
        None => {
            let (job, _reserved) = job_for(state, t, &given, Want::Job).await?;
            let mut result: Value =
                serde_json::from_slice(&job.result).map_err(|e| ApiError::Internal(format!("stored result: {e}")))?;
            crate::api::templates::statement::add(&t.statement, &mut result);
            if seen.bytes + job.result.len() > REFERENCE_BYTES {
                *seen = References::default();
            }
            seen.bytes += job.result.len();
            seen.results.entry(asked).or_insert((job.id, Arc::new(result), Arc::default())).clone()
        }
    };
    let answers: BTreeMap<String, Value> = l
        .answers
        .iter()
        .map(|(i, name, unit)| {
            let cell = row[*i].trim();
            let bare = crate::units::number(cell).is_some();
            let text = match unit {
                Some(u) if bare => format!("{cell} {u}"),
                _ => cell.to_string(),
            };
            (name.clone(), Value::String(text))
        })
        .collect();
    let request = CheckRequest { answers, tolerance: Some(tolerance), reveal: Some(reveal), ..CheckRequest::default() };
    let kind = state.kinds.find(&t.kind).ok_or_else(|| ApiError::Internal(format!("template kind {}", t.kind)))?;
    // Off the async workers: a failing answer's slips read every scalar of the result.
    let graded = tokio::task::spawn_blocking(move || grade_with(&request, kind, &result, Some(job), &flat));
    let graded = graded.await.map_err(|e| ApiError::Internal(format!("grading task: {e}")))?;
    let CheckOutput::Mechdyn(c) = graded? else {
        return Err(ApiError::Internal("a grade's check is in the mechdyn format".into()));
    };
    let mut cells = vec![row[l.student].clone(), format!("{}", c.score)];
    let by_pointer: HashMap<&str, _> = c.items.iter().map(|i| (i.pointer.trim_start_matches('/'), i)).collect();
    for (_, name, _) in &l.answers {
        let item = by_pointer.get(name.as_str());
        cells.push(item.map(|i| i.pass.to_string()).unwrap_or_default());
        cells.push(item.and_then(|i| i.relative_error).map(tables::number_text).unwrap_or_default());
    }
    cells.push(c.items.iter().map(|i| i.said.text()).collect::<Vec<_>>().join(" "));
    cells.push(String::new());
    Ok(cells)
}

/// Grades a class: one row per student (`student`, the student's
/// parameters or `variant`, answer columns named by pointer, optionally
/// `pointer [unit]` for bare numbers); answers CSV with `student`, `score`,
/// per answer `POINTER pass` and `POINTER relative_error`, `feedback` and
/// `error` (a row that cannot be graded says why; the others are graded).
#[utoipa::path(post, path = "/v1/templates/{id}/grade", operation_id = "post_template_grade", tag = "grading",
    params(("id" = String, Path, description = "Template id"),
        ("relative" = Option<f64>, Query, minimum = 0, description = "Relative tolerance (default 0.01)"),
        ("absolute" = Option<f64>, Query, minimum = 0, description = "Absolute tolerance, SI (default 0)"),
        ("sigfigs" = Option<u32>, Query, minimum = 1, maximum = 15, description = "Significant figures (PrairieLearn's rule), 1 to 15, replacing `relative`"),
        ("zero_level" = Option<f64>, Query, minimum = 0, description = "Below it (SI) an expected value is compared absolutely (default 1e-12)"),
        ("reveal" = Option<bool>, Query, description = "Whether the feedback shows expected values (default true)"),
        ("decimal" = Option<crate::api::tables::DecimalMark>, Query, description = "`point` (default) or `comma`: the CSV's numbers with a decimal comma, its columns separated by `;`")),
    request_body(description = "CSV: `student`, parameter columns or `variant`, answer columns named by pointer",
        content((String = "text/csv", example = "student,variant,inertia_exact [kg*m^2],omega_max\nana,1,459.6,6.4\nben,2,512,6.39\n"))),
    responses(
        (status = 200, description = "A row per student", body = String, content_type = "text/csv",
            example = "student,score,inertia_exact pass,inertia_exact relative_error,feedback,error\nana,1,true,0.0009,...,\n"),
        (status = 400, description = "No student column, no answer column, a malformed CSV or query", body = Problem, content_type = "application/problem+json"),
        (status = 413, description = "The body is larger than the limit on a request body", body = Problem, content_type = "application/problem+json"),
        (status = 415, description = "Not text/csv", body = Problem, content_type = "application/problem+json"),
        ReadErrors,
    ))]
pub async fn grade(
    State(state): State<AppState>,
    Path(id): Path<String>,
    headers: HeaderMap,
    q: Result<Query<HashMap<String, String>>, QueryRejection>,
    RawBody(body): RawBody,
) -> Result<Response, ApiError> {
    let q = read::query(q, QUERY)?;
    let mime = table::mime(&headers);
    if !(mime.starts_with("text/csv") || mime.starts_with("text/plain")) {
        return Err(ApiError::UnsupportedTable);
    }
    let t = find(&state, &id).await?;
    let text = class(&state, &t, &q, &body).await?;
    Ok(([(header::CONTENT_TYPE, "text/csv; charset=utf-8")], text).into_response())
}
