//! A template's quantities in its statement's terms (contract, part five,
//! "One problem, one set of numbers"): where a statement prints a
//! magnitude — a resisting torque C_r, the work a load absorbs — the
//! template names it, positive, beside the signed field it comes from
//! (`balance_torque` is the torque that drives, so C_r = −balance_torque).
//! A template job's values then hold `/statement/NAME`, read, tabled and
//! graded as any other value, in the unit of the field it comes from.

use crate::api::kind::{STATEMENT as KEY, STATEMENT_FROM as FROM};
use crate::i18n::Msg;
use crate::kind::problem::FieldError;
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};
use std::collections::BTreeMap;
use utoipa::ToSchema;

/// One of a statement's quantities: `sign` × the result's number at `of`.
#[derive(Clone, Debug, Serialize, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct Stated {
    /// JSON pointer into the job's result, e.g. `/balance_torque`.
    #[schema(example = "/balance_torque", max_length = 1000)]
    pub of: String,
    /// +1 (default) or −1: a resisting torque is −`balance_torque`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schema(example = -1)]
    pub sign: Option<f64>,
    /// The value the statement's solution prints, in the field's SI unit
    /// (built-in templates: graded against the job by the tests).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub printed: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schema(max_length = 2000)]
    pub description: Option<String>,
    /// Why the printed number is wrong, where it is (it then fails a check).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[schema(max_length = 2000)]
    pub wrong: Option<String>,
}

/// Most quantities of one template.
pub const MAX_STATED: usize = 100;

/// A template's quantities (its `statement`) added to its job's
/// `result`: each `sign` × the number at `of` (absent where the result has
/// no number there).
pub fn add(statement: &BTreeMap<String, Stated>, result: &mut Value) {
    if statement.is_empty() || !result.is_object() {
        return;
    }
    let (mut values, mut from) = (Map::new(), Map::new());
    for (name, s) in statement {
        if let Some(x) = result.pointer(&s.of).and_then(Value::as_f64) {
            values.insert(name.clone(), Value::from(s.sign.unwrap_or(1.0) * x));
            from.insert(name.clone(), Value::from(s.of.clone()));
        }
    }
    result[KEY] = Value::Object(values);
    result[FROM] = Value::Object(from);
}

/// A new template's quantities checked: each a pointer into a result, a
/// sign of ±1 (errors under `/statement`).
pub fn errors(statement: &BTreeMap<String, Stated>) -> Vec<FieldError> {
    let mut errors = Vec::new();
    if statement.len() > MAX_STATED {
        errors.push(FieldError::said("/statement", Msg::new("template-statement-too-many").count("max", MAX_STATED)));
    }
    for (name, s) in statement {
        let at = format!("/statement/{}", crate::kind::problem::escape(name));
        if !s.of.starts_with('/') {
            errors.push(FieldError::said(format!("{at}/of"), Msg::new("template-statement-pointer")));
        }
        if s.sign.is_some_and(|x| x != 1.0 && x != -1.0) {
            errors.push(FieldError::said(format!("{at}/sign"), Msg::new("template-statement-sign")));
        }
    }
    errors
}
