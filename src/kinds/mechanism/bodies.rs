//! A body named in a request: its id among the mechanism's names, the
//! ground's other names, and the message for a name that is not there.

use crate::engine::model::BodyId;
use crate::i18n::Msg;

/// The id of a named body.
pub fn body_id(names: &[String], name: &str) -> Option<BodyId> {
    names.iter().position(|n| n == name).or_else(|| is_ground(name).then_some(0))
}

/// Whether `name` is one of the ground's names.
pub fn is_ground(name: &str) -> bool {
    GROUND_NAMES.iter().any(|g| g.eq_ignore_ascii_case(name.trim()))
}

/// What else the ground may be called (any case), where no body has that
/// name: the frame in a Spanish lab's words.
const GROUND_NAMES: [&str; 4] = ["ground", "bastidor", "tierra", "suelo"];

/// An unknown body's message, naming the bodies there are (the first ten).
pub fn unknown_body(names: &[String], name: &str) -> Msg {
    let mut known: Vec<&str> = names.iter().take(10).map(String::as_str).collect();
    if names.len() > 10 {
        known.push("…");
    }
    Msg::new("mechanism-unknown-body").arg("name", name).arg("known", known.join(", "))
}
