//! The request-body extractor: 415 for a wrong content type, 413 over the
//! body limit, 400 for malformed JSON, 422 with a JSON pointer for every
//! unknown field, every field of the wrong type and every required field
//! left out (past the first, [`further`]). A name of the contract's lists
//! written in another case (`"DOPRI5"`) is read as the name it matches.

mod further;
mod strict;
pub(crate) mod words;

use crate::i18n::{Msg, names};
pub use crate::kind::problem::escape;
use crate::kind::problem::{ApiError, FieldError};
use axum::body::Body;
use axum::extract::{FromRequest, Request};
use axum::http::header;
use bytes::{Bytes, BytesMut};
use http_body::Body as _;
use http_body_util::BodyExt;
use serde::de::DeserializeOwned;
use std::collections::HashSet;

/// A JSON body: the typed request, the body as sent, and its unknown fields.
pub struct JsonBody<T> {
    pub value: T,
    /// The body exactly as the client sent it (stored with the job), UTF-8.
    pub raw: Bytes,
    /// Fields the schema does not know, as errors (reported with the others).
    pub unknown: Vec<FieldError>,
}

fn is_json(content_type: Option<&str>) -> bool {
    let Some(ct) = content_type else { return false };
    let essence = ct.split(';').next().unwrap_or("").trim().to_ascii_lowercase();
    essence == "application/json" || (essence.starts_with("application/") && essence.ends_with("+json"))
}

impl<S: Send + Sync, T: DeserializeOwned> FromRequest<S> for JsonBody<T> {
    type Rejection = ApiError;

    async fn from_request(req: Request, _: &S) -> Result<Self, Self::Rejection> {
        let content_type = req.headers().get(header::CONTENT_TYPE).and_then(|v| v.to_str().ok());
        if !is_json(content_type) {
            return Err(ApiError::UnsupportedMediaType);
        }
        let limit = req.extensions().get::<BodyLimit>().map_or(usize::MAX, |l| l.0);
        let raw = read_within(req.into_body(), limit).await?;
        if std::str::from_utf8(&raw).is_err() {
            return Err(ApiError::MalformedJson(Msg::new("json-not-utf8")));
        }
        parse(raw)
    }
}

/// A body of any type (a CSV), read within the body limit: over it, the
/// same 413 problem as a JSON body's (axum's `Bytes` answers plain text).
pub struct RawBody(pub Bytes);

impl<S: Send + Sync> FromRequest<S> for RawBody {
    type Rejection = ApiError;

    async fn from_request(req: Request, _: &S) -> Result<Self, Self::Rejection> {
        let limit = req.extensions().get::<BodyLimit>().map_or(usize::MAX, |l| l.0);
        Ok(Self(read_within(req.into_body(), limit).await?))
    }
}

/// The whole body if it is at most `limit` bytes; else 413 (the rest is
/// drained by [`super::body::drain_unread`], so that a client still sending
/// reads the answer).
pub async fn read_within(body: Body, limit: usize) -> Result<Bytes, ApiError> {
    let announced = body.size_hint().exact();
    if announced.is_some_and(|n| n > limit as u64) {
        return Err(ApiError::PayloadTooLarge(limit));
    }
    if announced.is_some() {
        // A body of a known length within the limit (admission read it whole): taken as it is, not copied.
        let read = body.collect().await.map_err(|e| ApiError::MalformedJson(Msg::new("json-unreadable").arg("why", e)));
        return Ok(read?.to_bytes());
    }
    let mut body = body;
    let mut buf = BytesMut::new();
    while let Some(frame) = body.frame().await {
        let frame = frame.map_err(|e| ApiError::MalformedJson(Msg::new("json-unreadable").arg("why", e)))?;
        if let Some(data) = frame.data_ref() {
            if buf.len() + data.len() > limit {
                return Err(ApiError::PayloadTooLarge(limit));
            }
            buf.extend_from_slice(data);
        }
    }
    Ok(buf.freeze())
}

/// Parses a body already read: the same rules as the extractor (used by the CLI too).
pub fn parse<T: DeserializeOwned>(raw: impl Into<Bytes>) -> Result<JsonBody<T>, ApiError> {
    let mut raw: Bytes = raw.into();
    // A UTF-8 byte order mark is not part of the JSON text: ignored, as RFC 8259 (8.1) allows, and not stored.
    if raw.starts_with(BOM) {
        raw = raw.slice(BOM.len()..);
    }
    let mut value: serde_json::Value =
        serde_json::from_slice(&raw).map_err(|e| ApiError::MalformedJson(words::malformed(&e, &raw)))?;
    let mut fixes = 0;
    let (mut errors, mut unknown, mut aside) = (Vec::new(), Vec::<FieldError>::new(), further::SetAside::default());
    // Readings past the first error: as many as READ_BUDGET bytes allow, at most MAX_READS.
    let mut reads = (READ_BUDGET / raw.len().max(1)).clamp(1, MAX_READS);
    loop {
        let (result, found) = read::<T>(&value);
        if unknown.is_empty() {
            unknown = found;
        } else {
            // A reading again meets the unknown fields before its error once more.
            let known: HashSet<Option<String>> = unknown.iter().map(|u| u.pointer.clone()).collect();
            unknown.extend(found.into_iter().filter(|f| !known.contains(&f.pointer)));
        }
        let e = match result {
            Ok(value) if errors.is_empty() => return Ok(JsonBody { value, raw, unknown }),
            Ok(_) => break,
            Err(e) if fixes < MAX_NAME_FIXES && as_listed(&mut value, &e) => {
                fixes += 1;
                continue;
            }
            Err(e) => e,
        };
        let error = type_error(&e);
        let at = error.pointer.clone().unwrap_or_default();
        if !aside.covers(&at) {
            errors.push(error);
        }
        reads -= 1;
        if reads == 0 || !aside.next(&mut value, &at) {
            break;
        }
    }
    unknown.extend(errors);
    Err(ApiError::Invalid(unknown))
}

/// `value` with every name of the contract's lists written otherwise (a
/// Spanish word, another case: `"espacial"`, `"junta cardán"`) written as
/// the name, as [`parse`] reads it: a stored request as its kind reads it
/// again (its plots, its worked solution), whatever words it was sent in.
pub fn canonical<T: DeserializeOwned>(value: &serde_json::Value) -> serde_json::Value {
    let mut value = value.clone();
    for _ in 0..MAX_NAME_FIXES {
        match read::<T>(&value).0 {
            Err(e) if as_listed(&mut value, &e) => {}
            _ => break,
        }
    }
    value
}

/// Bytes of request the readings past its first error may read in all,
/// and the most readings: each is a whole reading of the request.
const READ_BUDGET: usize = 4 << 20;
const MAX_READS: usize = 32;

/// The request in `value` and its unknown fields, each with the fields
/// its object has (where it was read as a struct: not inside a list of
/// objects named by their `type`, which serde reads through a copy).
fn read<T: DeserializeOwned>(value: &serde_json::Value) -> (Result<T, PathError>, Vec<FieldError>) {
    let mut unknown = Vec::new();
    let mut record = |path: serde_ignored::Path| unknown.push(ignored_pointer(&path));
    let (result, structs) = strict::fields_read(value, |value| {
        let strict = strict::Strict(value);
        serde_path_to_error::deserialize(serde_ignored::Deserializer::new(strict, &mut record))
    });
    let neighbours = |at: &str| {
        let parent = value.pointer(at.rsplit_once('/').map_or("", |(parent, _)| parent))?;
        let address = parent as *const serde_json::Value as usize;
        structs.iter().find(|(a, _)| *a == address).map(|(_, fields)| fields.join(", "))
    };
    let unknown = unknown
        .into_iter()
        .map(|at| {
            let said = match neighbours(&at) {
                Some(known) => Msg::new("field-unknown-known").arg("known", known),
                None => Msg::new("field-unknown"),
            };
            FieldError::said(at, said)
        })
        .collect();
    (result, unknown)
}

type PathError = serde_path_to_error::Error<serde_json::Error>;

/// Names of the contract's lists written otherwise that one request may
/// have read as the names they match (each is one more reading of it).
const MAX_NAME_FIXES: usize = 16;

/// Where `e` is a name unknown only as it is written (`"DOPRI5"` for
/// `dopri5`, `"Revolución"` for `revolute`, `"rodillo"` for `roller`: one
/// of the names listed is what it writes, [`names::read`]), that text in
/// `value` written as the name: true if it was. The text is at the error's
/// pointer, or is the one member there holding it (an object named by its
/// `type`).
fn as_listed(value: &mut serde_json::Value, e: &PathError) -> bool {
    use serde_json::Value;
    let message = e.inner().to_string();
    let Some((got, expected)) = message.strip_prefix("unknown variant `").and_then(|m| m.split_once("`, expected "))
    else {
        return false;
    };
    let listed: Vec<&str> = expected.split('`').skip(1).step_by(2).collect();
    let Some(name) = names::read(got, &listed) else { return false };
    let text = match value.pointer_mut(&pointer(e)) {
        Some(v @ Value::String(_)) => Some(v),
        Some(Value::Object(fields)) => {
            let mut holding = fields.values_mut().filter(|v| v.as_str() == Some(got));
            match (holding.next(), holding.next()) {
                (Some(v), None) => Some(v),
                _ => None,
            }
        }
        _ => None,
    };
    match text {
        Some(v) if v.as_str() == Some(got) => {
            *v = Value::String(name.to_string());
            true
        }
        _ => false,
    }
}

/// The UTF-8 byte order mark some editors and spreadsheets write first.
pub const BOM: &[u8] = b"\xEF\xBB\xBF";

/// The body limit in force, put in the request extensions by the router.
#[derive(Clone, Copy, Debug)]
pub struct BodyLimit(pub usize);

fn ignored_pointer(path: &serde_ignored::Path) -> String {
    use serde_ignored::Path;
    match path {
        Path::Root => String::new(),
        Path::Seq { parent, index } => format!("{}/{index}", ignored_pointer(parent)),
        Path::Map { parent, key } => format!("{}/{}", ignored_pointer(parent), escape(key)),
        Path::Some { parent } | Path::NewtypeStruct { parent } | Path::NewtypeVariant { parent } => {
            ignored_pointer(parent)
        }
    }
}

/// The JSON pointer to where `e` happened.
fn pointer(e: &PathError) -> String {
    use serde_path_to_error::Segment;
    e.path()
        .iter()
        .filter_map(|s| match s {
            Segment::Seq { index } => Some(format!("/{index}")),
            Segment::Map { key } => Some(format!("/{}", escape(key))),
            _ => None,
        })
        .collect()
}

/// A structural error (wrong type, missing field) with the pointer to its field.
fn type_error(e: &PathError) -> FieldError {
    let mut pointer = pointer(e);
    let message = e.inner().to_string();
    let message = message.split(" at line ").next().unwrap_or(&message).to_string();
    if let Some(field) = message.strip_prefix("missing field `").and_then(|m| m.strip_suffix('`')) {
        pointer = format!("{pointer}/{}", escape(field));
        return FieldError::said(pointer, Msg::new("field-missing"));
    }
    FieldError::said(pointer, words::plain(&message))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_content_types() {
        assert!(is_json(Some("application/json")));
        assert!(is_json(Some("application/json; charset=utf-8")));
        assert!(is_json(Some("application/problem+json")));
        assert!(!is_json(Some("text/plain")));
        assert!(!is_json(None));
    }

    #[test]
    fn pointers_escape_slash_and_tilde() {
        assert_eq!(escape("a/b~c"), "a~1b~0c");
    }
}
