//! The contract between the calculation kinds (`crate::kinds`) and the
//! service (`crate::api`): what a kind is ([`Kind`]) and the types both
//! wings share — problems and field errors ([`problem`]), quantities and
//! Functions as read from the wire ([`quantity`], [`function_read`],
//! [`function_csv`], [`constants`]), the limits a request is checked
//! against ([`limits`]), tables, and charts as data ([`chart`], [`plots`]).
//! A kind is written against this module only; the service reaches every
//! kind through it and the registry it is handed, never by a kind's name.

pub mod chart;
pub mod constants;
pub mod expression;
pub mod free_body_chart;
pub mod function_csv;
pub mod function_read;
pub mod isometric_view;
pub mod limits;
pub mod notes;
pub mod noticed;
pub mod plots;
pub mod problem;
pub mod quantity;
pub mod refused;
pub mod solution;

use crate::engine::Progress;
use crate::i18n::Msg;
pub use limits::Limits;
use problem::{ApiError, FieldError};
use serde::Serialize;
use serde::de::DeserializeOwned;
use serde_json::Value;
use std::collections::HashSet;
use std::io;
use utoipa::ToSchema;

/// A table of a result: the header (names with units, e.g. `angle_rad`)
/// and the rows, as text.
pub type Table = (Vec<String>, Vec<Vec<String>>);

/// The unit of a dimensionless number (a ratio, a count, an error estimate).
pub const DIMENSIONLESS: &str = "1";

/// One calculation kind of the service.
pub trait Kind: Send + Sync + 'static {
    /// The jobs' `kind`, e.g. `flywheel`.
    const NAME: &'static str;
    /// The catalogue's message naming the kind for people (`kind-flywheel`:
    /// "flywheel", "volante").
    const TITLE: &'static str;
    /// Path of the POST that creates its jobs.
    const PATH: &'static str;
    /// `operationId` of that POST.
    const OPERATION_ID: &'static str;
    /// OpenAPI tag.
    const TAG: &'static str;
    /// What the POST computes, in one line.
    const SUMMARY: &'static str;
    /// Units of the result's numbers: a JSON pointer pattern (`*` stands for
    /// any index or key) and the unit, [`DIMENSIONLESS`] for a pure number.
    const UNITS: &'static [(&'static str, &'static str)];
    /// Its plots: how a stored job lists them and draws one ([`plots::NONE`]: no curve).
    const PLOTS: plots::Plots = plots::NONE;
    type Request: DeserializeOwned + ToSchema + Send + 'static;
    type Result: JobResult + ToSchema + Send + 'static;

    /// Validates (`unknown`: the body's unknown fields, reported with the
    /// conversion's errors) and computes a request within `limits`.
    fn compute(request: &Self::Request, unknown: Vec<FieldError>, limits: &Limits) -> Result<Self::Result, ApiError>;

    /// The main table of a stored result, for CSV; None when it has none.
    fn table(_result: &Value) -> Option<Table> {
        None
    }

    /// The files a job of this kind offers besides its JSON and CSV
    /// (`GET /v1/jobs/{id}/{name}`), each with its content type.
    const FILES: &'static [(&'static str, &'static str)] = &[];

    /// File `name` (one of [`Kind::FILES`]) made from a stored result.
    fn file(_result: &Value, _name: &str) -> Option<Vec<u8>> {
        None
    }

    /// Whether [`Kind::file`] makes file `name` of a stored result; a kind
    /// whose files are costly to make answers without making them.
    fn has_file(result: &Value, name: &str) -> bool {
        Self::file(result, name).is_some()
    }

    /// Its worked solution at a step (`GET /v1/jobs/{id}/solution`): every
    /// moving body's free body; None for a kind without bodies.
    const SOLUTION: Option<solution::Solve> = None;

    /// Whether a stored result has a worked solution (a kind whose results
    /// may have no bodies, a run in reduced form, says so).
    fn has_solution(_result: &Value) -> bool {
        Self::SOLUTION.is_some()
    }

    /// The unit of the number at `pointer` (split into tokens) of `result`.
    /// Kinds whose units depend on the request (a force or a torque drives
    /// a mechanism) override this and fall back to [`unit_in`].
    fn unit(_result: &Value, pointer: &[&str]) -> Option<String> {
        unit_in(Self::UNITS, pointer).map(String::from)
    }
}

/// What a registry does with each kind: the kinds' wing lists its kinds
/// through this (`crate::kinds::register`), and the service keeps each
/// without its types.
pub trait Register {
    fn kind<K: Kind>(&mut self);
}

/// Computes a request of kind `K` as every way in does (the POST, the CLI):
/// [`Kind::compute`], then the warnings of the request as sent (`raw`),
/// such as constants no expression reads.
pub fn compute<K: Kind>(
    request: &K::Request,
    unknown: Vec<FieldError>,
    raw: &[u8],
    limits: &Limits,
) -> Result<K::Result, ApiError> {
    let limits = &limits.started();
    let (computed, noticed) = noticed::gather(|| K::compute(request, unknown, limits));
    let mut result = computed.map_err(|e| match e {
        // Refused as invalid once the budget had run out: the reading was stopped by it.
        ApiError::Invalid(_) if limits.deadline().expired() => {
            ApiError::OverBudget(refused::engine_msg(&limits.deadline().exceeded(Progress::Reading)))
        }
        ApiError::Invalid(errors) => ApiError::Invalid(beside(errors, noticed.clone())),
        e => e,
    })?;
    if let Some(notes) = result.notes() {
        let sent = serde_json::from_slice::<Value>(raw).unwrap_or_default();
        notes.extend(crate::kind::constants::unused(&sent));
        let at = |(pointer, msg): (String, Msg)| Msg::new("warning-at-field").arg("pointer", pointer).with("said", msg);
        notes.extend(noticed.into_iter().map(at));
    }
    Ok(result)
}

/// A refusal's errors and, each at its field, what the reading noticed
/// about the fields they concern (a bare 360 read as radians beside "the
/// sweep is too long"), and the same slip noticed elsewhere (a cam
/// program's bare 120, 180 and 300 beside its 360: a trial put right only
/// the field named, and was refused again for the next).
fn beside(mut errors: Vec<FieldError>, noticed: Vec<(String, Msg)>) -> Vec<FieldError> {
    let concerns = |p: &str| errors.iter().any(|e| e.pointer.as_deref().is_some_and(|q| noticed::related(p, q)));
    let slips: HashSet<String> =
        noticed.iter().filter(|(p, _)| concerns(p)).map(|(_, msg)| msg.id().to_string()).collect();
    let kept: Vec<FieldError> = noticed
        .into_iter()
        .filter(|(_, msg)| slips.contains(msg.id()))
        .map(|(p, msg)| FieldError::said(p, msg))
        .collect();
    errors.extend(kept);
    errors
}

/// The unit of `pointer` in a table of patterns.
pub fn unit_in(units: &'static [(&'static str, &'static str)], pointer: &[&str]) -> Option<&'static str> {
    units.iter().find(|(pattern, _)| matches(pattern, pointer)).map(|(_, u)| *u)
}

fn matches(pattern: &str, pointer: &[&str]) -> bool {
    let tokens: Vec<&str> = pattern.split('/').skip(1).collect();
    tokens.len() == pointer.len() && tokens.iter().zip(pointer).all(|(p, t)| *p == "*" || p == t)
}

/// What sets the size of a result: the request field that says how many rows
/// it has, how many it has, and what else the user can ask less of.
pub struct Rows {
    /// JSON pointer of the field in the request, e.g. `/input/steps`.
    pub field: String,
    /// Rows the result has (or would have).
    pub count: usize,
    /// The catalogue's id of what else shrinks it (`size-also-outputs`:
    /// fewer outputs).
    pub also: &'static str,
}

/// A job's result: serialisable, and saying which request field sets its size.
pub trait JobResult: Serialize {
    fn rows(&self) -> Option<Rows> {
        None
    }
    /// The result's `warnings` and `messages`, for the kinds that have them.
    fn notes(&mut self) -> Option<&mut notes::Notes> {
        None
    }
}

/// How the size of a result too large is known.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SizeBy {
    /// Written out.
    Measured,
    /// Estimated before computing, from rows computed.
    About,
    /// A least size before computing (every number as short as it can be):
    /// the rows that would fit are then at most those said.
    AtLeast,
}

/// The 422 of a result of `bytes` over `limit`, saying how many rows would fit.
pub fn too_large(bytes: usize, limit: usize, rows: Option<Rows>, sized: SizeBy) -> ApiError {
    let id = match sized {
        SizeBy::Measured => "size-would-be",
        SizeBy::About => "size-would-be-about",
        SizeBy::AtLeast => "size-would-be-at-least",
    };
    let size = Msg::new(id).with("size", human(bytes)).count("bytes", bytes).with("limit", human(limit));
    let error = match rows {
        Some(Rows { field, count, also }) if count > 0 => {
            let per_row = bytes as f64 / count as f64;
            let fit = ((limit as f64 * 0.95) / per_row).floor() as usize;
            let name = field.rsplit('/').next().unwrap_or("rows").to_string();
            let advice = if sized == SizeBy::AtLeast { "size-advice-at-most" } else { "size-advice" };
            let advice = Msg::new(advice).with("each", human(per_row as usize)).arg("name", name).count("fit", fit);
            let said =
                Msg::new("size-too-large").with("size", size).with("advice", advice.with("also", Msg::new(also)));
            FieldError::said(field, said)
        }
        _ => FieldError::said("", size),
    };
    ApiError::ResultTooLarge { limit, errors: vec![error] }
}

/// The result as JSON bytes, or a 422 when it would exceed `limit` bytes.
pub fn serialized<R: JobResult + ?Sized>(result: &R, limit: usize) -> Result<bytes::Bytes, ApiError> {
    let mut out = JsonBuffer::new(limit);
    match write_json(&mut out, result) {
        Ok(()) => {
            // The buffer grew by doubling: give back the unused half before it is held in flight.
            out.buf.shrink_to_fit();
            Ok(out.buf.into())
        }
        Err(e) if e.is_io() => {
            drop(out);
            Err(too_large(json_len(result), limit, result.rows(), SizeBy::Measured))
        }
        Err(e) => Err(ApiError::Internal(format!("result: {e}"))),
    }
}

/// Bytes for people: 16 MiB, 140.2 MB (140,2 MB in Spanish).
fn human(bytes: usize) -> Msg {
    let tenths = |x: f64| (x * 10.0).round() / 10.0;
    let (n, unit) = match bytes {
        b if b >= 1 << 20 && b % (1 << 20) == 0 => ((b >> 20) as f64, "MiB"),
        b if b >= 1_000_000 => (tenths(b as f64 / 1e6), "MB"),
        b if b >= 1_000 => (tenths(b as f64 / 1e3), "kB"),
        b => (b as f64, "B"),
    };
    Msg::new("text-value-unit").num("value", n).arg("unit", unit)
}

/// Bytes of `value` as JSON ([`write_json`]), counted without keeping them.
pub fn json_len<T: Serialize + ?Sized>(value: &T) -> usize {
    let mut count = Counter(0);
    write_json(&mut count, value).map_or(usize::MAX, |()| count.0)
}

/// `value` as a result's JSON: serde_json's compact form, but every zero
/// written 0.0 whatever its sign (a reaction's moment about its own pin
/// came out -0.0 by rounding, and a sheet showed "-0").
pub fn write_json<W: io::Write, T: Serialize + ?Sized>(writer: W, value: &T) -> serde_json::Result<()> {
    value.serialize(&mut serde_json::Serializer::with_formatter(writer, Unsigned))
}

/// [`write_json`] into a new buffer.
pub fn json_bytes<T: Serialize + ?Sized>(value: &T) -> serde_json::Result<Vec<u8>> {
    let mut out = JsonBuffer::new(usize::MAX);
    write_json(&mut out, value).map(|()| out.buf)
}

/// The bytes [`write_json`] writes, refused (an I/O error) beyond `limit`.
/// serde_json writes a token at a time — a quote, a colon, a number's
/// digits — so each write is short: a single byte is pushed and
/// `write_all` is this buffer's own, so that no token goes through
/// `write`'s retry loop and no byte through the C library's memcpy (K1's
/// 598 KB answer: 1.69 → 1.00 ms, 2026-11-29).
pub struct JsonBuffer {
    pub buf: Vec<u8>,
    limit: usize,
}

impl JsonBuffer {
    pub fn new(limit: usize) -> Self {
        Self { buf: Vec::new(), limit }
    }
}

impl io::Write for JsonBuffer {
    #[inline]
    fn write(&mut self, data: &[u8]) -> io::Result<usize> {
        self.write_all(data).map(|()| data.len())
    }
    #[inline]
    fn write_all(&mut self, data: &[u8]) -> io::Result<()> {
        if self.buf.len().saturating_add(data.len()) > self.limit {
            return Err(io::Error::other("over the limit on a result"));
        }
        match data {
            [byte] => self.buf.push(*byte),
            _ => self.buf.extend_from_slice(data),
        }
        Ok(())
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

/// The compact formatter with zeros unsigned.
struct Unsigned;

impl serde_json::ser::Formatter for Unsigned {
    fn write_f64<W: ?Sized + io::Write>(&mut self, writer: &mut W, value: f64) -> io::Result<()> {
        // -0.0 + 0.0 is +0.0; every other value is unchanged.
        serde_json::ser::CompactFormatter.write_f64(writer, value + 0.0)
    }
}

/// Counts bytes written, keeps none.
struct Counter(usize);

impl io::Write for Counter {
    fn write(&mut self, data: &[u8]) -> io::Result<usize> {
        self.0 += data.len();
        Ok(data.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

/// A scalar as a CSV cell or a plain answer: text without quotes, null empty.
pub fn cell(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        Value::Null => String::new(),
        other => other.to_string(),
    }
}

/// The `key` of each item of the list `list` of the first row that has
/// it: the names of a table's repeated columns (joints, bodies).
pub fn names(rows: &[Value], list: &str, key: &str) -> Vec<String> {
    let first = rows.iter().find_map(|r| r[list].as_array());
    first.into_iter().flatten().filter_map(|item| item[key].as_str().map(String::from)).collect()
}

/// The `fields` of each of `n` items of a list as cells (empty where the list is null).
pub fn list(v: &Value, n: usize, fields: &[&str]) -> Vec<String> {
    match v.as_array() {
        Some(items) => items.iter().flat_map(|item| fields.iter().map(|f| cell(&item[*f]))).collect(),
        None => vec![String::new(); n * fields.len()],
    }
}

/// Columns of a list's items: where in the item (a pointer), and the column's name.
pub type Columns = &'static [(&'static str, &'static str)];

/// The cells at `fields` (pointers) of each of `n` items of a list (empty where the list is null).
pub fn items(v: &Value, n: usize, fields: Columns) -> Vec<String> {
    match v.as_array() {
        Some(list) => list
            .iter()
            .flat_map(|item| fields.iter().map(|(at, _)| item.pointer(at).map(cell).unwrap_or_default()))
            .collect(),
        None => vec![String::new(); n * fields.len()],
    }
}

/// An engine error as a field error. Engine labels are JSON pointers; errors
/// without a field of their own point at `fallback`.
pub fn engine_error(e: crate::engine::EngineError, fallback: &str) -> FieldError {
    use crate::engine::EngineError as E;
    let pointer = match &e {
        E::NotFinite { function, .. } | E::NegativeInertia { function, .. } => function.clone(),
        E::NotSteady { .. }
        | E::NewtonDiverged { .. }
        | E::Singular { .. }
        | E::SingularCycle { .. }
        | E::FrictionDiverged { .. }
        | E::DofMismatch { .. }
        | E::Unactuated { .. }
        | E::Locked { .. }
        | E::BudgetExceeded { .. } => fallback.into(),
        E::NotFiniteResult => String::new(),
    };
    FieldError::said(pointer, refused::engine_msg(&e))
}

/// An engine error as the API's answer: over budget, or a 422 at its field.
pub fn engine_failure(e: crate::engine::EngineError, fallback: &str) -> ApiError {
    match e {
        crate::engine::EngineError::BudgetExceeded { .. } => ApiError::OverBudget(refused::engine_msg(&e)),
        e => ApiError::Invalid(vec![engine_error(e, fallback)]),
    }
}

/// The converted problem, or every error: the body's unknown fields first,
/// then those of the conversion.
pub fn validated<T>(mut unknown: Vec<FieldError>, converted: Result<T, Vec<FieldError>>) -> Result<T, ApiError> {
    match converted {
        Ok(p) if unknown.is_empty() => Ok(p),
        Ok(_) => Err(ApiError::Invalid(unknown)),
        Err(more) => {
            unknown.extend(more);
            Err(ApiError::Invalid(unknown))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    /// The buffer writes what serde_json's own writer writes (every token
    /// length: one-byte punctuation, short and long strings and numbers,
    /// escapes), and refuses the first token that would pass the limit.
    #[test]
    fn the_json_buffer_writes_serde_json_s_bytes_within_its_limit() {
        let value = json!({"a": [1.5, -2.25e-300, 0.1, 12345678901234567890u64, true, null],
            "name with \"quotes\" and é": "x".repeat(100), "": {"nested": [[], {}]}});
        let want = serde_json::to_vec(&value).expect("serde_json");
        assert_eq!(json_bytes(&value).expect("written"), want);
        let mut exact = JsonBuffer::new(want.len());
        assert!(write_json(&mut exact, &value).is_ok(), "{} bytes fit a limit of as many", want.len());
        let mut short = JsonBuffer::new(want.len() - 1);
        let refused = write_json(&mut short, &value).expect_err("one byte over");
        assert!(refused.is_io() && short.buf.len() < want.len(), "{refused}");
    }
}
