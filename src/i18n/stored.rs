//! A message as a result stores it: `{"id": "…", "args": {"name": value}}`,
//! so that a result computed once is read later in any language. A text
//! argument is a JSON string, a number a JSON float (`3.0`), a count a JSON
//! integer (for the catalogue's plural forms), a number said to four
//! figures `{"figures": x}`, a number written with a decimal point
//! `{"written": "1.0e-3"}`, a message within a message an object of the
//! same shape, a list of messages an array of them.

use super::{Arg, Msg};
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use serde_json::{Map, Value};
use std::borrow::Cow;
use utoipa::ToSchema;

/// A message of the catalogue as a result stores it (for the OpenAPI
/// document; [`Msg`] is what the code holds).
#[derive(ToSchema)]
#[schema(example = json!({"id": "warning-cam-pressure-translating", "args": {"max": 34.2, "at": 118.5, "limit": 30.0}}))]
#[allow(dead_code)]
pub struct MessageDoc {
    /// The message's id in the catalogue.
    id: String,
    /// Its arguments by name: a text, a number, a count (an integer), or a
    /// message of the same shape.
    #[schema(value_type = Object)]
    args: (),
}

impl Msg {
    fn to_value(&self) -> Value {
        let args: Map<String, Value> = self.args.iter().map(|(name, arg)| (name.to_string(), arg.to_value())).collect();
        let mut out = Map::new();
        out.insert("id".into(), Value::from(self.id.as_ref()));
        out.insert("args".into(), Value::Object(args));
        Value::Object(out)
    }

    fn of_value(value: &Value) -> Option<Msg> {
        let id = value.get("id")?.as_str()?.to_string();
        let mut args = Vec::new();
        for (name, arg) in value.get("args").and_then(Value::as_object).into_iter().flatten() {
            args.push((Cow::Owned(name.clone()), Arg::of_value(arg)?));
        }
        Some(Msg { id: Cow::Owned(id), args })
    }
}

impl Arg {
    fn to_value(&self) -> Value {
        match self {
            Arg::Text(t) => Value::from(t.as_str()),
            // JSON has no NaN or infinity: such a number is stored as its text.
            Arg::Number(x) if !x.is_finite() => Value::from(x.to_string()),
            Arg::Number(x) => Value::from(*x),
            Arg::Figures(x) if !x.is_finite() => Value::from(x.to_string()),
            Arg::Figures(x) => serde_json::json!({ "figures": x }),
            Arg::Written(text) => serde_json::json!({ "written": text }),
            Arg::Count(n) => Value::from(*n),
            Arg::Said(inner) => inner.to_value(),
            Arg::List(items) => Value::Array(items.iter().map(Msg::to_value).collect()),
        }
    }

    fn of_value(value: &Value) -> Option<Arg> {
        Some(match value {
            Value::String(t) => Arg::Text(t.clone()),
            Value::Number(n) if n.is_u64() => Arg::Count(usize::try_from(n.as_u64()?).ok()?),
            Value::Number(n) => Arg::Number(n.as_f64()?),
            Value::Object(o) if o.len() == 1 && o.contains_key("figures") => Arg::Figures(o["figures"].as_f64()?),
            Value::Object(o) if o.len() == 1 && o.contains_key("written") => {
                Arg::Written(o["written"].as_str()?.into())
            }
            Value::Object(_) => Arg::Said(Box::new(Msg::of_value(value)?)),
            Value::Array(items) => Arg::List(items.iter().map(Msg::of_value).collect::<Option<_>>()?),
            _ => return None,
        })
    }
}

impl Serialize for Msg {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        self.to_value().serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Msg {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let value = Value::deserialize(deserializer)?;
        Msg::of_value(&value).ok_or_else(|| D::Error::custom("a message is {\"id\": text, \"args\": {name: value}}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::Lang;

    /// A stored message renders as the one it was stored from, in both
    /// languages: a count stays a count (its plural), a number a number
    /// (its decimal comma), a message within stays one.
    #[test]
    fn a_message_stored_and_read_back_is_the_same() {
        let m = Msg::new("detail-invalid").count("count", 3);
        let inner = Msg::new("parameter-below").arg("text", "-3").num("min", 2.0).arg("unit", " N*m");
        let nested = Msg::new("unit-wrong-dimension").with("found", Msg::new("unit-none")).with("expected", inner);
        let figures = Msg::new("parameter-below").arg("text", "x").fig("min", 34.234567).arg("unit", "°");
        let list = Msg::new("text-as-is").list("why", vec![Msg::new("unit-none"), Msg::new("field-finite")]);
        let written = Msg::new("text-value-unit").written("value", "1.000000e-3".into()).arg("unit", "m");
        assert_eq!(written.render(Lang::Es), "1,000000e-3 m");
        for msg in [m, nested, figures, list, written, Msg::new("field-finite").num("x", f64::NAN)] {
            let text = serde_json::to_string(&msg).unwrap();
            let back: Msg = serde_json::from_str(&text).unwrap();
            for lang in Lang::ALL {
                assert_eq!(back.render(lang), msg.render(lang), "{text}");
            }
        }
        let stored = serde_json::to_value(Msg::new("parameter-below").num("min", 2.0).count("n", 2)).unwrap();
        assert_eq!(stored["args"]["min"], serde_json::json!(2.0));
        assert!(stored["args"]["min"].is_f64() && stored["args"]["n"].is_u64());
        assert!(serde_json::from_str::<Msg>("{\"args\": {}}").is_err(), "a message has an id");
    }
}
