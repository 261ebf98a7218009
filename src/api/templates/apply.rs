//! A template's parameters put into its request: a value from a query
//! string or a table cell (a number in the parameter's unit, or a quantity
//! string such as `300 rpm`), checked against its range, then the request's
//! key, under which the job it gives is stored and found again.

use super::model::{Parameter, Template};
use crate::i18n::Msg;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::unit_msg;
use crate::units::{Dim, number, parse_quantity, parse_unit};
use serde_json::Value;
use sha2::{Digest, Sha256};
use std::collections::{BTreeMap, HashMap};

/// The template's request with `given` parameters set (the others, and
/// those given empty, at their defaults); unknown names and bad values are
/// a 400 naming each.
pub fn request_for(t: &Template, given: &HashMap<String, String>, ignore: &[&str]) -> Result<Value, ApiError> {
    let mut request = t.request.clone();
    let mut errors = Vec::new();
    // In the names' order: the same query gives its errors in the same order.
    let ordered: std::collections::BTreeMap<&String, &String> = given.iter().collect();
    for (name, text) in ordered.into_iter().filter(|(k, _)| !ignore.contains(&k.as_str())) {
        let Some(p) = t.parameters.get(name) else {
            let known: Vec<&str> = t.parameters.keys().map(String::as_str).collect();
            let msg = Msg::new("parameter-unknown").arg("name", name).arg("template", &t.id);
            errors.push(FieldError::parameter_said(name, msg.arg("known", known.join(", "))));
            continue;
        };
        // An empty value (a sheet's empty cell sent as `F=`) is the default.
        if text.trim().is_empty() {
            continue;
        }
        match value_for(p, text) {
            Ok(v) => match request.pointer_mut(&p.pointer) {
                Some(slot) => *slot = integral(p, slot, text).unwrap_or(v),
                None => {
                    let why = Msg::new("parameter-pointer-missing").arg("pointer", &p.pointer);
                    errors.push(FieldError::parameter_said(name, why))
                }
            },
            Err(why) => errors.push(FieldError::parameter_said(name, why)),
        }
    }
    if !errors.is_empty() {
        return Err(ApiError::BadQuery(errors));
    }
    let names: Vec<&str> = t.parameters.keys().map(String::as_str).collect();
    let pointers: Vec<&str> = t.parameters.values().map(|p| p.pointer.as_str()).collect();
    super::derived::apply(&names, &pointers, &t.derived, &mut request).map_err(ApiError::Invalid)?;
    Ok(request)
}

/// Parameters given as JSON (a study's row, a drawn variant, a check's
/// `parameters`) as the texts a query string would carry them in.
pub fn texts(parameters: &BTreeMap<String, Value>) -> HashMap<String, String> {
    parameters.iter().map(|(k, v)| (k.clone(), crate::kind::cell(v))).collect()
}

/// The JSON value of a parameter given as `text`: SI when the parameter has
/// a unit, else the number, or the quantity string for the field to read.
pub fn value_for(p: &Parameter, text: &str) -> Result<Value, Msg> {
    let text = text.trim();
    let (factor, dim) = match &p.unit {
        Some(u) => {
            parse_unit(u).map_err(|e| Msg::new("parameter-own-unit").arg("unit", u).with("why", unit_msg(&e)))?
        }
        None => (1.0, Dim::NONE),
    };
    let si = match number(text) {
        Some(x) if x.is_finite() => {
            checked(p, x, text)?;
            x * factor
        }
        Some(_) => return Err(Msg::new("parameter-finite")),
        None => {
            let q = parse_quantity(text)
                .map_err(|e| Msg::new("parameter-not-quantity").arg("text", text).with("why", unit_msg(&e)))?;
            if p.unit.is_none() {
                return checked(p, q.si, text).map(|()| Value::String(text.into()));
            }
            if q.dim != dim {
                let msg = Msg::new("parameter-dimension").arg("text", text).arg("found", q.dim.si_name());
                return Err(msg.arg("expected", dim.si_name()));
            }
            checked(p, q.si / factor, text)?;
            q.si
        }
    };
    Ok(serde_json::Number::from_f64(si).map_or(Value::Null, Value::Number))
}

/// An integer written as one (`72`) for a parameter without a unit where
/// the template has an integer (a count of steps): the integer, so that a
/// field that wants one gets it (not 72.0).
fn integral(p: &Parameter, default: &Value, text: &str) -> Option<Value> {
    let integer = p.unit.is_none() && (default.is_i64() || default.is_u64());
    integer.then(|| text.trim().parse::<i64>().ok().map(Value::from)).flatten()
}

/// `x` (in the parameter's unit) within its range and choices.
fn checked(p: &Parameter, x: f64, text: &str) -> Result<(), Msg> {
    let unit = p.unit.as_deref().map(|u| format!(" {u}")).unwrap_or_default();
    if let Some(min) = p.min.filter(|m| x < *m) {
        return Err(Msg::new("parameter-below").arg("text", text).num("min", min).arg("unit", unit));
    }
    if let Some(max) = p.max.filter(|m| x > *m) {
        return Err(Msg::new("parameter-above").arg("text", text).num("max", max).arg("unit", unit));
    }
    if let Some(choices) = &p.choices {
        let listed = choices.iter().any(|c| c.as_f64() == Some(x) || c.as_str() == Some(text));
        if !listed {
            let all: Vec<String> = choices.iter().map(|c| c.to_string()).collect();
            return Err(Msg::new("parameter-not-choice").arg("text", text).arg("choices", all.join(", ")));
        }
    }
    Ok(())
}

/// The request as stored (canonical JSON: keys in order) and its key.
pub fn keyed(kind: &str, request: &Value) -> (Vec<u8>, String) {
    let bytes = serde_json::to_vec(request).unwrap_or_default();
    let mut hash = Sha256::new();
    for part in [kind.as_bytes(), b"\0", env!("CARGO_PKG_VERSION").as_bytes(), b"\0", &bytes] {
        hash.update(part);
    }
    let key = hash.finalize().iter().map(|b| format!("{b:02x}")).collect();
    (bytes, key)
}

/// Errors of a computed template request: those at a parameter's pointer
/// also name the parameter.
pub fn named(t: &Template, e: ApiError) -> ApiError {
    let name = |errors: Vec<FieldError>| -> Vec<FieldError> {
        errors
            .into_iter()
            .map(|mut f| {
                let at = f.pointer.clone().unwrap_or_default();
                f.parameter = t.parameters.iter().find(|(_, p)| at.starts_with(&p.pointer)).map(|(n, _)| n.clone());
                f
            })
            .collect()
    };
    match e {
        ApiError::Invalid(errors) => ApiError::Invalid(name(errors)),
        other => other,
    }
}
