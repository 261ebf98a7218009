//! A parameter study in one request: a table of variants (CSV from a
//! spreadsheet, or JSON), each row the template's job for that row's
//! parameters, answered with the values asked for. A row that fails carries
//! its error; the others are still computed.

use super::model::Template;
use super::{RESERVED, Want, job_for};
use crate::api::AppState;
use crate::api::json::words::malformed;
use crate::api::tables::{Csv, Decimal, at, tokens};
use crate::i18n::Msg;
use crate::kind::cell;
use crate::kind::problem::{ApiError, FieldError};
use axum::http::{HeaderMap, header};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::collections::{BTreeMap, HashMap};
use utoipa::ToSchema;

/// Most variants in one study.
pub const MAX_ROWS: usize = 1000;

/// A study as JSON.
#[derive(Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
#[schema(example = json!({"rows": [{"F": 1000}, {"F": "1.2 kN*m", "eps": "3 %"}], "values": ["inertia_exact"]}))]
pub struct TableRequest {
    /// One object of parameters per variant (a number in the parameter's unit, or a quantity string).
    #[schema(max_items = 1000)]
    pub rows: Vec<BTreeMap<String, Value>>,
    /// JSON pointers into the result of the values to answer.
    pub values: Vec<String>,
}

/// One variant of a study.
#[derive(Serialize, ToSchema)]
pub struct TableRow {
    pub parameters: BTreeMap<String, Value>,
    /// The values asked for, by pointer (as given).
    pub values: BTreeMap<String, Value>,
    /// The job's id, when it was computed.
    pub job: Option<String>,
    /// Why this row failed, or which values its job's result does not have
    /// (with the job's warnings); null when every value is there.
    pub error: Option<String>,
}

/// A study's answer as JSON.
#[derive(Serialize, ToSchema)]
pub struct TableResponse {
    pub rows: Vec<TableRow>,
}

/// The study of `body` for template `t`: the answer's text and whether it is CSV.
pub async fn study(
    state: &AppState,
    t: &Template,
    headers: &HeaderMap,
    (values, decimal): (Option<&String>, Option<Decimal>),
    body: &[u8],
) -> Result<(String, bool), ApiError> {
    let mime = mime(headers);
    if mime.starts_with("application/json") {
        let request: TableRequest =
            serde_json::from_slice(body).map_err(|e| ApiError::MalformedJson(malformed(&e, body)))?;
        let pointers: Vec<String> =
            if request.values.is_empty() { values.map_or_else(Vec::new, |v| pointer_list(v)) } else { request.values };
        let rows = request.rows.iter().map(super::texts).collect();
        let results = run(state, t, rows, (&pointers, Want::Job)).await?;
        let rows = request.rows.into_iter().zip(results).map(|(parameters, (values, job, error))| {
            let values = pointers.iter().cloned().zip(values).collect();
            TableRow { parameters, values, job, error }
        });
        let answer = TableResponse { rows: rows.collect() };
        return Ok((serde_json::to_string(&answer).map_err(|e| ApiError::Internal(e.to_string()))?, false));
    }
    if !(mime.starts_with("text/csv") || mime.starts_with("text/plain")) {
        return Err(ApiError::UnsupportedTable);
    }
    let pointers: Vec<String> = values.map_or_else(Vec::new, |v| pointer_list(v));
    let sheet = read_csv(body)?;
    even(&sheet)?;
    let Sheet { header, rows, delimiter, .. } = sheet;
    let unknown: Vec<FieldError> = header
        .iter()
        .filter(|(_, name, _)| !t.parameters.contains_key(name) || RESERVED.contains(&name.as_str()))
        .map(|(_, name, _)| unknown_column(t, name))
        .collect();
    if !unknown.is_empty() {
        return Err(ApiError::BadTable(unknown));
    }
    let given = rows.iter().map(|r| parameters_of(&header, r)).collect();
    let results = run(state, t, given, (&pointers, Want::Job)).await?;
    let mut out = Csv::new(decimal.unwrap_or(Decimal::as_sent(delimiter)));
    let names = pointers.iter().map(|p| p.trim_start_matches('/').to_string());
    let head = header.iter().map(|(raw, _, _)| raw.clone()).chain(names).chain(["job".into(), "error".into()]);
    out.record(head)?;
    for (row, (values, job, error)) in rows.iter().zip(results) {
        let record = row
            .iter()
            .cloned()
            .chain(values.iter().map(cell))
            .chain([job.unwrap_or_default(), error.unwrap_or_default()]);
        out.record(record)?;
    }
    Ok((out.text()?, true))
}

/// `values=a,/b, c` as pointers, as written (a leading `/` optional).
pub fn pointer_list(list: &str) -> Vec<String> {
    list.split(',').map(|p| p.trim().to_string()).filter(|p| !p.is_empty()).collect()
}

/// The body's content type, lower-case (empty without one).
pub fn mime(headers: &HeaderMap) -> String {
    headers.get(header::CONTENT_TYPE).and_then(|v| v.to_str().ok()).unwrap_or("").to_ascii_lowercase()
}

pub fn bad(parameter: &str, msg: Msg) -> ApiError {
    ApiError::BadQuery(vec![FieldError::parameter_said(parameter, msg)])
}

/// A header cell `name [unit]`: (as written, name, unit).
pub type Column = (String, String, Option<String>);

/// A CSV body read: its header, its data rows, the row each has in the
/// sheet (as a spreadsheet counts them: the header is row 1), and the
/// separator it was written with.
pub struct Sheet {
    pub header: Vec<Column>,
    pub rows: Vec<Vec<String>>,
    pub lines: Vec<usize>,
    pub delimiter: u8,
}

/// A CSV body's error, at its row and column where it has them.
pub fn bad_cell(row: Option<usize>, column: Option<&str>, msg: Msg) -> ApiError {
    ApiError::BadTable(vec![FieldError::cell(row, column, msg)])
}

/// The header and rows of a CSV (`,`, or `;` or tab when the header has no
/// comma: a European spreadsheet's export). Rows may be ragged here;
/// [`even`] refuses them where every row must be whole.
pub fn read_csv(body: &[u8]) -> Result<Sheet, ApiError> {
    let text = std::str::from_utf8(body).map_err(|_| bad_cell(None, None, Msg::new("csv-not-utf8")))?;
    let first = text.lines().next().unwrap_or("");
    let delimiter = if first.contains(',') {
        b','
    } else if first.contains(';') {
        b';'
    } else if first.contains('\t') {
        b'\t'
    } else {
        b','
    };
    let mut reader =
        csv::ReaderBuilder::new().delimiter(delimiter).trim(csv::Trim::All).flexible(true).from_reader(text.as_bytes());
    let header: Vec<Column> = reader
        .headers()
        .map_err(|e| bad_cell(Some(1), None, Msg::new("csv-header").arg("why", e)))?
        .iter()
        .map(|h| match h.split_once('[') {
            Some((name, unit)) => {
                (h.to_string(), name.trim().to_string(), Some(unit.trim_end_matches(']').trim().to_string()))
            }
            None => (h.to_string(), h.to_string(), None),
        })
        .collect();
    let (mut rows, mut lines) = (Vec::new(), Vec::new());
    // A record's line from its byte offset, past the blank lines before it
    // (which csv's position, in lines and in bytes, counts into the record).
    let mut counted = (0, 1);
    let mut line_at = |byte: u64| {
        let mut byte = (byte as usize).min(text.len());
        byte += text.as_bytes()[byte..].iter().take_while(|b| matches!(b, b'\n' | b'\r')).count();
        let (from, line) = counted;
        counted = (byte, line + text.as_bytes()[from.min(byte)..byte].iter().filter(|&&b| b == b'\n').count());
        counted.1
    };
    for record in reader.records() {
        let record = record.map_err(|e| {
            let line = e.position().map(|p| line_at(p.byte()));
            bad_cell(line, None, Msg::new("csv-unreadable").arg("why", e))
        })?;
        if record.iter().all(str::is_empty) {
            continue;
        }
        lines.push(record.position().map_or(rows.len() + 2, |p| line_at(p.byte())));
        rows.push(record.iter().map(String::from).collect());
        if rows.len() > MAX_ROWS {
            return Err(bad_cell(None, None, Msg::new("csv-too-many-rows").count("max", MAX_ROWS)));
        }
    }
    Ok(Sheet { header, rows, lines, delimiter })
}

/// Why a row has not one cell per column, if it has not (`line`: its row
/// in the sheet); one cell too many in a `,`-separated CSV is most often a
/// decimal comma, and said so.
pub fn ragged(header: &[Column], row: &[String], line: usize, delimiter: u8) -> Option<Msg> {
    let comma = row.len() > header.len() && delimiter == b',';
    let id = if comma { "csv-ragged-comma" } else { "csv-ragged" };
    let msg = Msg::new(id).arg("row", line).arg("cells", row.len()).arg("columns", header.len());
    (row.len() != header.len()).then_some(msg)
}

/// Every row whole, or a 400 naming each that is not, by its row.
fn even(sheet: &Sheet) -> Result<(), ApiError> {
    let Sheet { header, rows, lines, delimiter } = sheet;
    let said = |(r, &line): (&Vec<String>, &usize)| {
        Some(FieldError::cell(Some(line), None, ragged(header, r, line, *delimiter)?))
    };
    let uneven = rows.iter().zip(lines).filter_map(said);
    let errors: Vec<FieldError> = uneven.take(20).collect();
    if errors.is_empty() { Ok(()) } else { Err(ApiError::BadTable(errors)) }
}

/// A CSV row's parameters: a cell under `name [unit]` is the quantity `cell unit`; empty cells keep the default.
pub fn parameters_of(header: &[Column], row: &[String]) -> HashMap<String, String> {
    header
        .iter()
        .zip(row)
        .filter(|(_, c)| !c.is_empty())
        .map(|((_, name, unit), c)| (name.clone(), unit.as_ref().map_or_else(|| c.clone(), |u| format!("{c} {u}"))))
        .collect()
}

/// Every row's values, job and error, in order.
pub async fn run(
    state: &AppState,
    t: &Template,
    rows: Vec<HashMap<String, String>>,
    (pointers, want): (&[String], Want),
) -> Result<Vec<(Vec<Value>, Option<String>, Option<String>)>, ApiError> {
    if pointers.is_empty() {
        return Err(bad("values", Msg::new("query-values-none")));
    }
    if rows.len() > MAX_ROWS {
        return Err(bad("body", Msg::new("csv-too-many-rows").count("max", MAX_ROWS)));
    }
    let unknown: Vec<FieldError> = rows
        .iter()
        .flat_map(|r| r.keys())
        .filter(|k| !t.parameters.contains_key(*k) || RESERVED.contains(&k.as_str()))
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .map(|k| unknown_parameter(t, k))
        .collect();
    if !unknown.is_empty() {
        return Err(ApiError::BadQuery(unknown));
    }
    let mut out = Vec::with_capacity(rows.len());
    // The rows' new jobs share one job's budget; past it the rest are left for
    // the next request (those done are stored, and found again at once).
    let deadline = state.limits.deadline();
    for given in rows {
        if deadline.expired() {
            out.push((vec![Value::Null; pointers.len()], None, Some(spent(state).text())));
            continue;
        }
        out.push(match job_for(state, t, &given, want).await {
            Ok((row, _reserved)) => {
                let mut result: Value = serde_json::from_slice(&row.result).unwrap_or_default();
                crate::kind::notes::localise(&mut result);
                super::statement::add(&t.statement, &mut result);
                let found: Vec<Option<&Value>> = pointers.iter().map(|p| at(&result, &tokens(p))).collect();
                let error = absent(&result, pointers, &found);
                // A job answered unstored (seq 0: `NewJob::unstored`) has no id to name.
                let id = (row.seq > 0).then_some(row.id);
                (found.into_iter().map(|v| v.cloned().unwrap_or(Value::Null)).collect(), id, error)
            }
            Err(e @ (ApiError::Saturated { .. } | ApiError::StorageFull(_) | ApiError::Unavailable(_))) => {
                return Err(e);
            }
            Err(e) => (vec![Value::Null; pointers.len()], None, Some(said(&e))),
        });
    }
    Ok(out)
}

/// Why a row of a table, study, variants or class was not computed: the
/// request's budget (one job's) went on the rows before it.
pub fn spent(state: &AppState) -> Msg {
    Msg::new("rows-budget-spent").num("seconds", state.limits.budget.as_secs_f64())
}

pub fn unknown_parameter(t: &Template, name: &str) -> FieldError {
    FieldError::parameter_said(name, no_parameter(t, name))
}

/// A CSV column that names no parameter of `t`, by its header.
pub fn unknown_column(t: &Template, name: &str) -> FieldError {
    FieldError::cell(Some(1), Some(name), no_parameter(t, name))
}

fn no_parameter(t: &Template, name: &str) -> Msg {
    let known = t.parameters.keys().map(String::as_str).collect::<Vec<_>>().join(", ");
    Msg::new("parameter-unknown").arg("name", name).arg("template", &t.id).arg("known", known)
}

/// What a row's `error` says where its job's result has no value at some
/// of the pointers: which, and the job's warnings (often the reason, e.g. an
/// end angle not reached, so no end event).
fn absent(result: &Value, pointers: &[String], found: &[Option<&Value>]) -> Option<String> {
    let missing: Vec<&str> = pointers.iter().zip(found).filter(|(_, v)| v.is_none()).map(|(p, _)| p.as_str()).collect();
    if missing.is_empty() {
        return None;
    }
    let warnings: Vec<&str> = result["warnings"].as_array().into_iter().flatten().filter_map(Value::as_str).collect();
    let why = if warnings.is_empty() { String::new() } else { format!(" (its warnings: {})", warnings.join("; ")) };
    Some(format!("this job's result has no {}{why}", missing.join(", ")))
}

/// An error in one line for a table's `error` cell.
pub fn said(e: &ApiError) -> String {
    let p = e.problem();
    let fields: Vec<String> = p
        .errors
        .iter()
        .map(|f| {
            let at = f.parameter.clone().or_else(|| f.pointer.clone()).or_else(|| f.column.clone());
            format!("{}: {}", at.unwrap_or_default(), f.message)
        })
        .collect();
    if fields.is_empty() { p.detail } else { fields.join("; ") }
}

#[cfg(test)]
mod tests {
    use super::{absent, at, tokens};
    use serde_json::json;

    /// A dynamics result whose end angle was not reached has no end event:
    /// the row names the missing value and gives the job's warning.
    #[test]
    fn a_missing_value_is_named_with_the_jobs_warnings() {
        let result = json!({"events": [{"t": 0.5}], "warnings": ["the angle 12.57 rad was not reached within 60 s"]});
        let pointers = ["events/0/t".to_string(), "/events/1/t".to_string()];
        let found: Vec<_> = pointers.iter().map(|p| at(&result, &tokens(p))).collect();
        assert_eq!(
            absent(&result, &pointers, &found).as_deref(),
            Some(
                "this job's result has no /events/1/t (its warnings: the angle 12.57 rad was not reached within 60 s)"
            )
        );
        assert_eq!(absent(&result, &pointers[..1], &found[..1]), None);
    }
}

#[cfg(test)]
mod sheet {
    use super::*;

    /// Each row is named by its row in the sheet (the header is row 1),
    /// blank lines and quoted line breaks counted, as a spreadsheet shows them.
    #[test]
    fn rows_are_counted_as_the_sheet_counts_them() {
        let body = "F;eps\n500;0,04\n\n600;0,03\n\"7\n00\";1\n;\n800;1\n";
        let sheet = read_csv(body.as_bytes()).map_err(|e| e.to_string()).unwrap();
        assert_eq!(sheet.lines, [2, 4, 5, 8]);
        assert_eq!(sheet.delimiter, b';');
    }
}
