//! What a result says about itself in words — its `warnings` and how its
//! accuracy was estimated — written from the catalogue, so that a result
//! computed once is read in the asker's language.
//!
//! A result stores its texts in English and, beside them, `messages`: the
//! catalogue's message each text was written from, by JSON pointer into the
//! result (`/warnings/0`, `/accuracy/method`). Read in another language,
//! the texts are written again from their messages ([`localise`],
//! [`localise_bytes`]); a client may also match a warning by its id.

use crate::i18n::{self, Lang, Msg};
use serde::de::{MapAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize};
use serde_json::Value;
use serde_json::value::RawValue;
use std::collections::BTreeMap;
use utoipa::ToSchema;

/// A result's warnings and the messages its texts were written from.
/// Flattened into each kind's result.
#[derive(Clone, Debug, Default, Serialize, Deserialize, ToSchema)]
pub struct Notes {
    /// What to know before trusting the numbers: a condition met on the
    /// way (a tolerance nearly spent, a geometry nearly singular, a law
    /// of design broken), in the asker's language.
    pub warnings: Vec<String>,
    /// The catalogue's message each text of this result was written from,
    /// by JSON pointer into the result (`/warnings/0`, `/accuracy/method`):
    /// match a warning by its `id`; the texts themselves are in the
    /// language asked for (`Accept-Language`, `?lang=`).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    #[schema(value_type = BTreeMap<String, i18n::MessageDoc>)]
    pub messages: BTreeMap<String, Msg>,
}

impl Notes {
    /// Adds a warning said by `msg`.
    pub fn warn(&mut self, msg: Msg) {
        self.messages.insert(format!("/warnings/{}", self.warnings.len()), msg.clone());
        self.warnings.push(msg.render(Lang::En));
    }

    /// Says warning `i` again, with `msg`.
    pub fn reword(&mut self, i: usize, msg: Msg) {
        if let Some(text) = self.warnings.get_mut(i) {
            *text = msg.render(Lang::En);
            self.messages.insert(format!("/warnings/{i}"), msg);
        }
    }

    /// The stored text at `pointer` said by `msg`: English, its message kept.
    pub fn say(&mut self, pointer: &str, msg: Msg) -> String {
        let text = msg.render(Lang::En);
        self.messages.insert(pointer.to_string(), msg);
        text
    }
}

impl Extend<Msg> for Notes {
    fn extend<I: IntoIterator<Item = Msg>>(&mut self, msgs: I) {
        msgs.into_iter().for_each(|m| self.warn(m));
    }
}

/// Writes the texts of a result tree in the language of the request being
/// answered from the messages it stored (stored in English: nothing to do
/// in English, or for a result without messages).
pub fn localise(result: &mut Value) {
    let lang = i18n::current();
    if lang == Lang::En {
        return;
    }
    let Some(messages) = result.get("messages").cloned() else { return };
    let Ok(messages) = serde_json::from_value::<BTreeMap<String, Msg>>(messages) else { return };
    for (pointer, msg) in messages {
        if let Some(text @ Value::String(_)) = result.pointer_mut(&pointer) {
            *text = Value::String(msg.render(lang));
        }
    }
}

/// [`localise`] on a stored result's bytes without parsing its tree: only
/// the members its messages point into are read and written again (a large
/// result's samples are copied as they are). None: the bytes stand as they are.
pub fn localise_bytes(result: &[u8]) -> Option<Vec<u8>> {
    if i18n::current() == Lang::En {
        return None;
    }
    // Borrowed from the stored bytes: the one copy made is the answer.
    let Members(members) = serde_json::from_slice(result).ok()?;
    let messages = members.iter().find(|(k, _)| *k == "messages")?.1.get();
    let messages: BTreeMap<String, Msg> = serde_json::from_str(messages).ok()?;
    let mut touched = serde_json::Map::new();
    for pointer in messages.keys() {
        let first = pointer.trim_start_matches('/').split('/').next().unwrap_or("");
        if let Some((name, raw)) = members.iter().find(|(k, _)| *k == first) {
            touched.insert(name.to_string(), serde_json::from_str(raw.get()).ok()?);
        }
    }
    let mut tree = Value::Object(touched);
    tree["messages"] = serde_json::to_value(&messages).ok()?;
    localise(&mut tree);
    let mut out = Vec::with_capacity(result.len() + result.len() / 8);
    out.push(b'{');
    for (i, (name, raw)) in members.iter().enumerate() {
        if i > 0 {
            out.push(b',');
        }
        out.extend(serde_json::to_vec(name).ok()?);
        out.push(b':');
        match tree.get(*name).filter(|_| *name != "messages") {
            Some(said) => out.extend(said.to_string().as_bytes()),
            None => out.extend(raw.get().as_bytes()),
        }
    }
    out.push(b'}');
    Some(out)
}

/// A JSON object's members in their order, each value as its text, borrowed
/// (a result's member names are plain words: no escapes to undo).
struct Members<'a>(Vec<(&'a str, &'a RawValue)>);

impl<'de> Deserialize<'de> for Members<'de> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Each;
        impl<'de> Visitor<'de> for Each {
            type Value = Members<'de>;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a JSON object")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Members<'de>, A::Error> {
                let mut members = Vec::new();
                while let Some(member) = map.next_entry::<&'de str, &'de RawValue>()? {
                    members.push(member);
                }
                Ok(Members(members))
            }
        }
        deserializer.deserialize_map(Each)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stored() -> Vec<u8> {
        let mut notes = Notes::default();
        notes.warn(Msg::new("detail-invalid").count("count", 2));
        let method = notes.say("/accuracy/method", Msg::new("field-finite"));
        // Written as a kind's result is, its members in the struct's order.
        let text = |v| serde_json::to_string(v).unwrap();
        format!(
            "{{\"samples\":[[1.5,2.5]],\"accuracy\":{{\"estimated_relative_error\":1e-12,\"method\":{}}},\"warnings\":{},\"messages\":{}}}",
            text(&serde_json::json!(method)),
            text(&serde_json::json!(notes.warnings)),
            text(&serde_json::to_value(&notes.messages).unwrap())
        )
        .into_bytes()
    }

    /// Stored in English; read in Spanish, the texts are the catalogue's
    /// Spanish and every other byte of the result is as it was.
    #[test]
    fn a_result_read_in_spanish_says_its_texts_in_spanish() {
        let bytes = stored();
        assert_eq!(localise_bytes(&bytes), None, "English: the bytes as stored");
        let spanish = i18n::within_sync(Lang::Es, || localise_bytes(&bytes)).unwrap();
        let mut tree: Value = serde_json::from_slice(&bytes).unwrap();
        i18n::within_sync(Lang::Es, || localise(&mut tree));
        assert_eq!(serde_json::from_slice::<Value>(&spanish).unwrap(), tree, "both ways agree");
        assert_eq!(tree["warnings"][0], Msg::new("detail-invalid").count("count", 2).render(Lang::Es));
        assert_eq!(tree["accuracy"]["method"], Msg::new("field-finite").render(Lang::Es));
        assert_ne!(tree["warnings"][0], Msg::new("detail-invalid").count("count", 2).render(Lang::En));
        let original: Value = serde_json::from_slice(&bytes).unwrap();
        assert_eq!(tree["samples"], original["samples"]);
        assert_eq!(tree["messages"], original["messages"]);
        let text = String::from_utf8(spanish).unwrap();
        assert!(text.starts_with("{\"samples\":[[1.5,2.5]],\"accuracy\":"), "the members in their order: {text}");
    }
}
