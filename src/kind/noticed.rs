//! What reading a request noticed and did not refuse — a bare number where
//! degrees look meant — said as a warning of its result, or beside the
//! errors of a refused request at the fields they concern.
//!
//! Gathered on the thread that reads the request, around [`super::compute`]
//! ([`gather`]): a reader anywhere below notices ([`notice`]) without a list
//! threaded through every kind's conversion. Outside a gathering, nothing
//! is kept.

use crate::i18n::Msg;
use std::cell::RefCell;
use std::f64::consts::TAU;

/// Most things noticed in one request (a table of bare angles is one mistake).
const MOST: usize = 5;

thread_local! {
    static NOTICED: RefCell<Option<Vec<(String, Msg)>>> = const { RefCell::new(None) };
}

/// Runs `f`, and what it noticed, by pointer, in the order noticed.
pub fn gather<T>(f: impl FnOnce() -> T) -> (T, Vec<(String, Msg)>) {
    /// Puts back the gathering this one is inside (a check's reference
    /// computes inside the check), even when `f` unwinds.
    struct Restore(Option<Option<Vec<(String, Msg)>>>);
    impl Drop for Restore {
        fn drop(&mut self) {
            if let Some(outer) = self.0.take() {
                NOTICED.set(outer);
            }
        }
    }
    let mut restore = Restore(Some(NOTICED.replace(Some(Vec::new()))));
    let out = f();
    let noticed = NOTICED.replace(restore.0.take().unwrap_or_default()).unwrap_or_default();
    (out, noticed)
}

/// Notes `msg` about the field at `pointer` (once a field, at most [`MOST`]).
pub fn notice(pointer: &str, msg: Msg) {
    NOTICED.with_borrow_mut(|noticed| {
        if let Some(list) = noticed
            && list.len() < MOST
            && !list.iter().any(|(p, _)| p == pointer)
        {
            list.push((pointer.to_string(), msg));
        }
    });
}

/// A bare number read as an angle in radians that looks written in
/// degrees: more than a turn, in whole or half units (`90`, `720`, `22.5`).
pub fn bare_angle(value: f64, pointer: &str) {
    if value.abs() > TAU && (2.0 * value).fract() == 0.0 {
        notice(pointer, Msg::new("field-bare-angle").num("value", value).fig("degrees", value.to_degrees()));
    }
}

/// A bare number read as a length in metres that looks written in
/// millimetres: `above` m or more (a size no such part has), in whole or
/// half units (`25`, `12.5`).
pub fn bare_length(value: f64, above: f64, pointer: &str) {
    if value.abs() >= above && (2.0 * value).fract() == 0.0 {
        notice(pointer, Msg::new("field-bare-length").num("value", value));
    }
}

/// Whether what was noticed at `pointer` concerns an error at `other`: the
/// error is in the object the noticed field belongs to (a dimension's
/// `value` and its `angle`), or inside the field.
pub fn related(pointer: &str, other: &str) -> bool {
    let inside = |a: &str, b: &str| a.strip_prefix(b).is_some_and(|rest| rest.is_empty() || rest.starts_with('/'));
    let parent = pointer.rsplit_once('/').map_or("", |(p, _)| p);
    inside(other, if parent.is_empty() { pointer } else { parent }) || inside(pointer, other)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degrees_written_bare_are_noticed_once_a_field() {
        let ((), noticed) = gather(|| {
            for (v, at) in [(720.0, "/a"), (720.0, "/a"), (22.5, "/b"), (3.0, "/c"), (7.1, "/d"), (-90.0, "/e")] {
                bare_angle(v, at);
            }
        });
        let at: Vec<&str> = noticed.iter().map(|(p, _)| p.as_str()).collect();
        assert_eq!(at, ["/a", "/b", "/e"], "a turn or less, or a value not in whole or half units, is radians");
        // Outside a gathering nothing is kept.
        bare_angle(720.0, "/a");
        assert!(NOTICED.with_borrow(|n| n.is_none()));
    }

    #[test]
    fn a_gathering_inside_another_keeps_its_own() {
        let ((inner, ()), outer) = gather(|| {
            bare_angle(90.0, "/outer");
            let inner = gather(|| bare_angle(90.0, "/inner")).1;
            (inner, ())
        });
        assert_eq!(inner[0].0, "/inner");
        assert_eq!(outer.len(), 1);
        assert_eq!(outer[0].0, "/outer");
    }

    #[test]
    fn fields_are_related_along_their_pointers() {
        assert!(related("/input/end", "/input"));
        assert!(related("/input/end", "/input/steps"), "a sibling");
        assert!(related("/mechanism/dimensions/4/value", "/mechanism/dimensions/4/angle"));
        assert!(!related("/mechanism/dimensions/4/value", "/mechanism/dimensions/5/angle"));
        assert!(related("/a", "/a"));
        assert!(!related("/inputs/end", "/input"));
        assert!(!related("/b", "/a"));
    }
}
