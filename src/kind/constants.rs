//! `constants`: named values a request's expressions may read (a load's
//! amplitude `F`, a length `r`), so that a lab or a template varies one
//! number instead of rewriting formulas. Each is a number (SI) or a
//! `"VALUE UNIT"` quantity, read in SI.

use super::quantity::{Errors, QUANTITY_MAX_LENGTH, Quantity};
use crate::engine::expr::is_reserved;
use crate::units;
use serde_json::Value;
use std::collections::{BTreeMap, BTreeSet};

/// The `constants` of a request.
pub type Constants = BTreeMap<String, Quantity>;

/// Most constants in one request.
pub const MAX_CONSTANTS: usize = 100;
/// Longest name of a constant.
const MAX_NAME: usize = 64;

/// The request's constants in SI, each error at `/constants/NAME`; they are
/// also set on `e`, so every expression it reads afterwards may use them.
pub fn read(constants: Option<&Constants>, e: &mut Errors) {
    let Some(constants) = constants else { return };
    if constants.len() > MAX_CONSTANTS {
        e.push("/constants", format!("at most {MAX_CONSTANTS} constants (has {})", constants.len()));
        return;
    }
    let mut values = Vec::new();
    for (name, q) in constants {
        let at = format!("/constants/{}", name.replace('~', "~0").replace('/', "~1"));
        if let Err(why) = valid_name(name) {
            e.push(&at, why);
            continue;
        }
        let value = match q {
            Quantity::Number(v) => Ok(*v),
            Quantity::Text(s) if s.chars().count() > QUANTITY_MAX_LENGTH => {
                Err(format!("must be at most {QUANTITY_MAX_LENGTH} characters"))
            }
            Quantity::Text(s) => units::parse_quantity(s).map(|q| q.si).map_err(|err| err.to_string()),
        };
        match value {
            Ok(v) if v.is_finite() => values.push((name.clone(), v)),
            Ok(_) => e.push(&at, "must be finite"),
            Err(why) => e.push(&at, why),
        }
    }
    e.constants = values;
}

fn valid_name(name: &str) -> Result<(), String> {
    let mut chars = name.chars();
    let first_ok = chars.next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_');
    if !first_ok || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(format!(
            "'{name}' is not a name: letters, digits and _, not starting with a digit (e.g. F, r_crank)"
        ));
    }
    if name.len() > MAX_NAME {
        return Err(format!("a name has at most {MAX_NAME} characters"));
    }
    if is_reserved(name) {
        return Err(format!("'{name}' is taken by the expressions (phi, t, omega, pi, e and the functions)"));
    }
    Ok(())
}

/// Warnings for the constants that no text of the request names (a
/// constant given and never read is most often a typo in a formula).
pub fn unused(request: &Value) -> Vec<crate::i18n::Msg> {
    let Some(constants) = request.get("constants").and_then(Value::as_object) else { return Vec::new() };
    let mut names = BTreeSet::new();
    let mut texts = Vec::new();
    if let Value::Object(fields) = request {
        texts.extend(fields.iter().filter(|(k, _)| *k != "constants").map(|(_, v)| v));
    }
    while let Some(v) = texts.pop() {
        match v {
            Value::String(s) => names.extend(s.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))),
            Value::Array(items) => texts.extend(items),
            Value::Object(fields) => texts.extend(fields.values()),
            _ => {}
        }
    }
    constants
        .keys()
        .filter(|k| !names.contains(k.as_str()))
        .map(|k| crate::i18n::Msg::new("warning-constant-unused").arg("name", k))
        .collect()
}
