//! A template's derived values: fields of its request that follow its
//! parameters (a bar's I_G = m(2L)²/12 as its mass m changes), each an
//! expression of the parameters' names, read in SI where the parameters
//! put them, and written into the request after them.

use crate::engine::expr::Expr;
use crate::i18n::Msg;
use crate::kind::problem::FieldError;
use serde_json::Value;
use std::collections::BTreeMap;

/// Most derived values of one template.
pub const MAX_DERIVED: usize = 100;

/// Sets every `derived` value in `request`, its parameters (`names`)
/// already set there at their `pointers`.
pub fn apply(
    names: &[&str],
    pointers: &[&str],
    derived: &BTreeMap<String, String>,
    request: &mut Value,
) -> Result<(), Vec<FieldError>> {
    let values: Vec<f64> = pointers.iter().map(|p| si(request.pointer(p)).unwrap_or(f64::NAN)).collect();
    let mut errors = Vec::new();
    for (pointer, source) in derived {
        let value = Expr::compile(source, names).map(|e| e.eval(&values));
        match (value, request.pointer_mut(pointer)) {
            (Ok(v), Some(slot)) if v.is_finite() => {
                *slot = serde_json::Number::from_f64(v).map_or(Value::Null, Value::Number)
            }
            (Ok(v), Some(_)) => {
                errors.push(FieldError::said(pointer, Msg::new("template-derived-finite").num("value", v)))
            }
            (Err(e), _) => errors.push(FieldError::said(pointer, expression_msg(&e))),
            (_, None) => {
                errors.push(FieldError::said(pointer, Msg::new("template-pointer-missing").arg("pointer", pointer)))
            }
        }
    }
    if errors.is_empty() { Ok(()) } else { Err(errors) }
}

/// A new template's derived values checked: each pointer in the request,
/// each expression of its parameters' names (errors under `/derived`).
pub fn errors(derived: &BTreeMap<String, String>, parameters: &[&str], request: &Value) -> Vec<FieldError> {
    let mut errors = Vec::new();
    if derived.len() > MAX_DERIVED {
        errors.push(FieldError::said("/derived", Msg::new("template-derived-too-many").count("max", MAX_DERIVED)));
    }
    for (pointer, source) in derived {
        let at = format!("/derived/{}", crate::kind::problem::escape(pointer));
        if request.pointer(pointer).is_none() {
            errors.push(FieldError::said(&at, Msg::new("template-pointer-missing").arg("pointer", pointer)));
        }
        if let Err(e) = Expr::compile(source, parameters) {
            errors.push(FieldError::said(&at, expression_msg(&e)));
        }
    }
    errors
}

fn expression_msg(e: &crate::engine::expr::ExprError) -> Msg {
    Msg::new("template-derived-expression").with("why", crate::kind::expression::fault_msg(&e.fault))
}

/// A parameter's value in SI: a number, or a quantity's text.
fn si(v: Option<&Value>) -> Option<f64> {
    match v? {
        Value::Number(n) => n.as_f64(),
        Value::String(s) => crate::units::parse_quantity(s).ok().map(|q| q.si),
        _ => None,
    }
}
