//! A stored result as text for spreadsheets: one value in a unit of the
//! client's choice, every scalar flattened with its unit, and the CSV of a
//! kind's table or of those values, with angles in degrees on request.
//! Written once for every kind through the registry ([`AnyKind`]).

use super::kind::AnyKind;
use crate::i18n::Msg;
use crate::kind::cell;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::unit_msg;
use crate::kind::{DIMENSIONLESS, Table};
use crate::units::{Dim, parse_unit};
use serde::Serialize;
use serde_json::Value;
use utoipa::ToSchema;

/// One scalar of a result.
#[derive(Serialize, ToSchema)]
pub struct Scalar {
    /// JSON pointer relative to `result`, e.g. `/inertia_exact`.
    pub pointer: String,
    /// A number, string, boolean or null.
    pub value: Value,
    /// The unit of a number (`1`: dimensionless); null for a text, a flag or a name.
    pub unit: Option<String>,
}

/// Every scalar of a result, flattened.
#[derive(Serialize, ToSchema)]
pub struct Values {
    pub values: Vec<Scalar>,
}

/// How angles are written, `?angles=` (the OpenAPI document's enum).
#[derive(ToSchema)]
#[schema(rename_all = "lowercase")]
#[allow(dead_code)]
pub enum AngleUnit {
    Rad,
    Deg,
}

/// `?format=` of the values.
#[derive(ToSchema)]
#[schema(rename_all = "lowercase")]
#[allow(dead_code)]
pub enum Format {
    Json,
    Csv,
}

/// `?decimal=` of a text answer (the OpenAPI document's enum).
#[derive(ToSchema)]
#[schema(rename_all = "lowercase")]
#[allow(dead_code)]
pub enum DecimalMark {
    Point,
    Comma,
}

/// How a text answer writes its numbers: `?decimal=comma` for a sheet in a
/// Spanish locale, where `.` separates thousands — `0,628…`, and a CSV's
/// columns separated by `;`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Decimal {
    #[default]
    Point,
    Comma,
}

impl Decimal {
    /// `?decimal=point|comma` of a read's query (a point without it), 400 otherwise.
    pub fn of(q: &std::collections::HashMap<String, String>) -> Result<Self, ApiError> {
        Ok(Self::asked(q)?.unwrap_or(Self::Point))
    }

    /// `?decimal=point|comma` of a read's query, if given; 400 otherwise.
    pub fn asked(q: &std::collections::HashMap<String, String>) -> Result<Option<Self>, ApiError> {
        match q.get("decimal").map(|t| t.trim().to_ascii_lowercase()).as_deref() {
            None => Ok(None),
            Some("point") => Ok(Some(Self::Point)),
            Some("comma") => Ok(Some(Self::Comma)),
            Some(_) => Err(ApiError::BadQuery(vec![FieldError::parameter_said("decimal", Msg::new("query-decimal"))])),
        }
    }

    /// The mark of a CSV answer to a CSV sent with `delimiter`, unless the
    /// query says: a `;`-separated sheet (a European spreadsheet's) is
    /// answered in its own way, `;` and decimal commas.
    pub fn as_sent(delimiter: u8) -> Self {
        if delimiter == b';' { Self::Comma } else { Self::Point }
    }

    /// A cell or a plain answer as this mark writes it: a number's decimal
    /// point as a comma; any other text as it is.
    pub fn written(self, text: String) -> String {
        let number = self == Self::Comma && text.contains('.') && text.parse::<f64>().is_ok();
        if number { text.replacen('.', ",", 1) } else { text }
    }

    fn delimiter(self) -> u8 {
        if self == Self::Comma { b';' } else { b',' }
    }
}

/// How angle columns and values are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Angles {
    Rad,
    Deg,
}

impl Angles {
    /// `?angles=rad|deg`, 400 otherwise.
    pub fn parse(text: Option<&String>) -> Result<Self, FieldError> {
        match text.map(|t| t.trim().to_ascii_lowercase()).as_deref() {
            None | Some("rad") => Ok(Self::Rad),
            Some("deg") => Ok(Self::Deg),
            Some(_) => Err(FieldError::parameter_said("angles", Msg::new("query-angles"))),
        }
    }
}

/// RFC 6901 tokens of a pointer (without its leading `/`), unescaped.
pub fn tokens(pointer: &str) -> Vec<String> {
    let pointer = pointer.strip_prefix('/').unwrap_or(pointer);
    pointer.split('/').map(|t| t.replace("~1", "/").replace("~0", "~")).collect()
}

/// The part of `v` at the RFC 6901 `tokens`: keys, and array indexes
/// written without leading zeros.
pub fn at<'a>(v: &'a Value, tokens: &[String]) -> Option<&'a Value> {
    tokens.iter().try_fold(v, |v, token| match v {
        Value::Object(map) => map.get(token),
        Value::Array(items) if token == "0" || !token.starts_with('0') => items.get(token.parse::<usize>().ok()?),
        _ => None,
    })
}

/// The JSON pointer of `tokens`.
pub fn pointer(tokens: &[String]) -> String {
    tokens.iter().map(|t| format!("/{}", escape(t))).collect()
}

fn escape(token: &str) -> String {
    token.replace('~', "~0").replace('/', "~1")
}

/// Every scalar of `result` in document order, with its unit.
pub fn flatten(kind: &dyn AnyKind, result: &Value) -> Vec<Scalar> {
    let mut out = Vec::new();
    let mut path = Vec::new();
    walk(kind, result, result, &mut path, &mut out);
    out
}

fn walk(kind: &dyn AnyKind, root: &Value, v: &Value, path: &mut Vec<String>, out: &mut Vec<Scalar>) {
    let mut child = |key: String, item: &Value, path: &mut Vec<String>| {
        path.push(key);
        walk(kind, root, item, path, out);
        path.pop();
    };
    match v {
        // A result's `messages` say how its texts were written: no values of it.
        Value::Object(map) if path.is_empty() => {
            map.iter().filter(|(k, _)| *k != "messages").for_each(|(k, item)| child(k.clone(), item, path))
        }
        Value::Object(map) => map.iter().for_each(|(k, item)| child(k.clone(), item, path)),
        Value::Array(items) => items.iter().enumerate().for_each(|(i, item)| child(i.to_string(), item, path)),
        scalar => {
            let tokens: Vec<&str> = path.iter().map(String::as_str).collect();
            let unit = if scalar.is_number() { kind.unit(root, &tokens) } else { None };
            let pointer = self::pointer(path);
            out.push(Scalar { pointer, value: scalar.clone(), unit });
        }
    }
}

/// `value` (in `unit`, the field's own) converted to `target`; the errors
/// name the query parameter `unit`.
pub fn convert(value: f64, unit: Option<&str>, target: &str, pointer: &str) -> Result<f64, ApiError> {
    let bad = |why: Msg| ApiError::BadQuery(vec![FieldError::parameter_said("unit", why)]);
    let Some(unit) = unit else {
        return Err(bad(Msg::new("unit-part-no-unit").arg("pointer", pointer)));
    };
    let own = if unit == DIMENSIONLESS { Ok((1.0, Dim::NONE)) } else { parse_unit(unit) };
    let Ok((own_factor, own_dim)) = own else {
        return Err(bad(Msg::new("unit-part-no-single-unit").arg("pointer", pointer).arg("unit", unit)));
    };
    let (factor, dim) = match target.trim() {
        "1" => (1.0, Dim::NONE),
        t => parse_unit(t).map_err(|e| bad(Msg::new("unit-target").arg("target", target).with("why", unit_msg(&e))))?,
    };
    if dim != own_dim {
        let (found, expected) = (dim.si_name(), own_dim.si_name());
        let said = match expected == unit {
            true => Msg::new("unit-part-in").arg("target", target).arg("found", found).arg("pointer", pointer),
            false => Msg::new("unit-part-in-of").arg("target", target).arg("found", found).arg("pointer", pointer),
        };
        return Err(bad(said.arg("unit", unit).arg("expected", expected)));
    }
    Ok(value * own_factor / factor)
}

/// A number as a spreadsheet reads it: shortest round-trip form (`353.5214273220119`, `1e-7`).
pub fn number_text(x: f64) -> String {
    serde_json::Number::from_f64(x).map_or_else(String::new, |n| n.to_string())
}

/// The CSV of a kind's table, angle columns (`…_rad`) in degrees on request.
pub fn table_csv(table: Table, (angles, decimal): (Angles, Decimal)) -> Result<String, ApiError> {
    let (mut header, mut rows) = table;
    if angles == Angles::Deg {
        let columns: Vec<usize> = (0..header.len()).filter(|&c| header[c].ends_with("_rad")).collect();
        for &c in &columns {
            header[c] = format!("{}_deg", header[c].trim_end_matches("_rad"));
            for row in &mut rows {
                if let Some(x) = row.get(c).and_then(|cell| cell.parse::<f64>().ok()) {
                    row[c] = number_text(x.to_degrees());
                }
            }
        }
    }
    write_csv(std::iter::once(header).chain(rows), decimal)
}

/// The CSV `pointer,value,unit` of every scalar, angles in degrees on request.
pub fn values_csv(values: Vec<Scalar>, (angles, decimal): (Angles, Decimal)) -> Result<String, ApiError> {
    let header = ["pointer", "value", "unit"].map(String::from).to_vec();
    let rows = values.into_iter().map(|s| {
        let (value, unit) = match (s.value.as_f64(), s.unit.as_deref()) {
            (Some(x), Some("rad")) if angles == Angles::Deg => (number_text(x.to_degrees()), "deg".to_string()),
            (_, unit) => (cell(&s.value), unit.unwrap_or_default().to_string()),
        };
        vec![s.pointer, value, unit]
    });
    write_csv(std::iter::once(header).chain(rows), decimal)
}

fn write_csv(records: impl Iterator<Item = Vec<String>>, decimal: Decimal) -> Result<String, ApiError> {
    let mut out = Csv::new(decimal);
    for record in records {
        out.record(record)?;
    }
    out.text()
}

/// A CSV answer for a spreadsheet to open. A text cell that a spreadsheet
/// would take for a formula — beginning with `=`, `+`, `-`, `@`, a tab or a
/// carriage return, such as a student's name `=HYPERLINK(…)` — is written
/// with a `'` before it, as OWASP recommends against CSV injection; a
/// number (`-3.5`) is written as it is, with a decimal comma and `;`
/// between the columns where the client asked for [`Decimal::Comma`].
pub struct Csv(csv::Writer<Vec<u8>>, Decimal);

impl Default for Csv {
    fn default() -> Self {
        Self::new(Decimal::Point)
    }
}

impl Csv {
    /// An empty CSV whose numbers are written with `decimal`.
    pub fn new(decimal: Decimal) -> Self {
        Self(csv::WriterBuilder::new().delimiter(decimal.delimiter()).from_writer(Vec::new()), decimal)
    }

    /// One row.
    pub fn record<S: AsRef<str>>(&mut self, cells: impl IntoIterator<Item = S>) -> Result<(), ApiError> {
        let decimal = self.1;
        let cells = cells.into_iter().map(|c| decimal.written(inert(c.as_ref())));
        self.0.write_record(cells).map_err(|e| ApiError::Internal(format!("CSV: {e}")))
    }

    /// The rows written, as text.
    pub fn text(self) -> Result<String, ApiError> {
        let bytes = self.0.into_inner().map_err(|e| ApiError::Internal(format!("CSV: {e}")))?;
        String::from_utf8(bytes).map_err(|e| ApiError::Internal(format!("CSV: {e}")))
    }
}

/// `cell` as a spreadsheet will not evaluate it (see [`Csv`]).
fn inert(cell: &str) -> String {
    let formula = cell.starts_with(['=', '+', '-', '@', '\t', '\r']);
    if formula && cell.trim().parse::<f64>().is_err() { format!("'{cell}") } else { cell.to_string() }
}

/// The CSV of a stored result: its kind's table, or its values when the
/// kind has none (never an empty body).
pub fn result_csv(kind: Option<&dyn AnyKind>, result: &Value, style: (Angles, Decimal)) -> Result<String, ApiError> {
    let Some(kind) = kind else { return Err(ApiError::Internal("a stored job of an unknown kind".into())) };
    match kind.table(result) {
        Some(table) if !table.1.is_empty() => table_csv(table, style),
        _ => values_csv(flatten(kind, result), style),
    }
}
