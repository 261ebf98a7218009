//! `constants`: named values a request's expressions may read (a load's
//! amplitude `F`, a length `r`), so that a lab or a template varies one
//! number instead of rewriting formulas. Each is a number (SI) or a
//! `"VALUE UNIT"` quantity, read in SI.

use super::quantity::{Errors, QUANTITY_MAX_LENGTH, Quantity, unit_msg};
use crate::engine::expr::is_reserved;
use crate::i18n::Msg;
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
        e.say("/constants", Msg::new("constants-too-many").arg("max", MAX_CONSTANTS).arg("has", constants.len()));
        return;
    }
    let mut values = Vec::new();
    for (name, q) in constants {
        let at = format!("/constants/{}", name.replace('~', "~0").replace('/', "~1"));
        if let Err(why) = valid_name(name) {
            e.say(&at, why);
            continue;
        }
        let value = match q {
            Quantity::Number(v) => Ok(*v),
            Quantity::Text(s) if s.chars().count() > QUANTITY_MAX_LENGTH => {
                Err(Msg::new("field-at-most-characters").arg("max", QUANTITY_MAX_LENGTH))
            }
            Quantity::Text(s) => units::parse_quantity(s).map(|q| q.si).map_err(|err| unit_msg(&err)),
        };
        match value {
            Ok(v) if v.is_finite() => values.push((name.clone(), v)),
            Ok(_) => e.say(&at, Msg::new("field-finite")),
            Err(why) => e.say(&at, why),
        }
    }
    e.constants = values;
}

fn valid_name(name: &str) -> Result<(), Msg> {
    let mut chars = name.chars();
    let first_ok = chars.next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_');
    if !first_ok || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(Msg::new("constants-not-name").arg("name", name));
    }
    if name.len() > MAX_NAME {
        return Err(Msg::new("constants-name-length").arg("max", MAX_NAME));
    }
    if is_reserved(name) {
        return Err(Msg::new("constants-reserved").arg("name", name));
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
