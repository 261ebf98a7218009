//! Past a request's first structural error (a field of the wrong type, a
//! required field left out) to the ones after it, so that a 422 lists
//! every such field, not only the first serde meets.
//!
//! Where a field is wrong, the reader sets it aside in the request's tree
//! and reads it again: a member is first removed (where the request may
//! leave it out, that is enough), then replaced by a stand-in of each JSON
//! type in turn until one reads. A stand-in only lets the reading go on:
//! a request with an error is refused whole, and an error inside a
//! stand-in (an object's own missing fields) is not the client's and is
//! not reported.

use serde_json::Value;

/// What may stand where a field was wrong, tried in this order after the
/// member's removal.
fn stand_in(k: usize) -> Option<Value> {
    [
        Value::String("?".into()),
        Value::from(0),
        Value::Bool(false),
        Value::Array(Vec::new()),
        Value::Object(Default::default()),
    ]
    .into_iter()
    .nth(k)
}

/// The fields set aside so far, each with how many ways of setting it
/// aside were tried.
#[derive(Default)]
pub struct SetAside(Vec<(String, usize)>);

impl SetAside {
    /// Whether `pointer` lies inside a stand-in (or is one already set aside).
    pub fn covers(&self, pointer: &str) -> bool {
        self.0.iter().any(|(p, _)| inside(pointer, p))
    }

    /// Sets the field at `pointer` aside in `value` the next way not yet
    /// tried for it (the one set aside whose stand-in `pointer` lies in,
    /// where it does): false when every way was tried, or the field's
    /// place cannot be found.
    pub fn next(&mut self, value: &mut Value, pointer: &str) -> bool {
        let at = match self.0.iter().position(|(p, _)| inside(pointer, p)) {
            Some(i) => i,
            None => {
                self.0.push((pointer.to_string(), 0));
                self.0.len() - 1
            }
        };
        let (pointer, tried) = &mut self.0[at];
        let Some((parent, key)) = split(pointer) else { return false };
        loop {
            let k = *tried;
            *tried += 1;
            let Some(place) = value.pointer_mut(&parent) else { return false };
            if k == 0 {
                // Removed: an object's member that is there (an array's
                // element is not, or the elements after it would shift).
                if let Value::Object(members) = place
                    && members.remove(&key).is_some()
                {
                    return true;
                }
                continue;
            }
            let Some(s) = stand_in(k - 1) else { return false };
            return match place {
                Value::Object(members) => {
                    members.insert(key, s);
                    true
                }
                Value::Array(items) => match key.parse::<usize>().ok().and_then(|i| items.get_mut(i)) {
                    Some(v) => {
                        *v = s;
                        true
                    }
                    None => false,
                },
                _ => false,
            };
        }
    }
}

/// `pointer` is `of` or lies inside it.
fn inside(pointer: &str, of: &str) -> bool {
    pointer == of || pointer.strip_prefix(of).is_some_and(|rest| rest.starts_with('/'))
}

/// The parent's pointer and the last token, unescaped (RFC 6901).
fn split(pointer: &str) -> Option<(String, String)> {
    let (parent, key) = pointer.rsplit_once('/')?;
    Some((parent.to_string(), key.replace("~1", "/").replace("~0", "~")))
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    /// A member is removed first, then given a string, a number, … in
    /// turn; an array's element only stand-ins; a pointer inside a
    /// stand-in moves its field on, and is covered.
    #[test]
    fn a_field_is_set_aside_one_way_after_another() {
        let mut value = json!({"a": {"b~c": 1, "d": [5, 6]}});
        let mut aside = SetAside::default();
        assert!(aside.next(&mut value, "/a/b~0c"));
        assert_eq!(value, json!({"a": {"d": [5, 6]}}));
        assert!(aside.next(&mut value, "/a/b~0c"));
        assert_eq!(value["a"]["b~c"], json!("?"));
        assert!(aside.next(&mut value, "/a/b~0c/inner"), "inside the stand-in: the field's next way");
        assert_eq!(value["a"]["b~c"], json!(0));
        assert!(aside.covers("/a/b~0c/x") && !aside.covers("/a/b~0cd"));
        assert!(aside.next(&mut value, "/a/d/1"));
        assert_eq!(value["a"]["d"], json!([5, "?"]));
        for _ in 0..4 {
            assert!(aside.next(&mut value, "/a/d/1"));
        }
        assert_eq!(value["a"]["d"], json!([5, {}]));
        assert!(!aside.next(&mut value, "/a/d/1"), "every way tried");
        assert!(!aside.next(&mut value, "/nowhere/x"));
    }
}
