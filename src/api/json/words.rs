//! serde's messages in the words of a JSON user: "expected a number, got
//! the text \"abc\"" rather than "invalid type: string \"abc\", expected
//! f64", and a malformed body pointed at where it goes wrong.

use crate::i18n::Msg;

/// A structural error of serde (wrong type, wrong length, unknown name)
/// said plainly, as the catalogue words it.
pub fn plain(message: &str) -> Msg {
    let expected = |got: Msg, e: &str| Msg::new("field-expected").with("expected", expected_words(e)).with("got", got);
    if let Some(rest) = message.strip_prefix("invalid type: ")
        && let Some((got, e)) = rest.split_once(", expected ")
    {
        return expected(got_words(got), e);
    }
    if let Some(rest) = message.strip_prefix("invalid length ")
        && let Some((n, e)) = rest.split_once(", expected ")
    {
        return expected(Msg::new("json-got-items").arg("n", n), e);
    }
    if let Some(rest) = message.strip_prefix("invalid value: ")
        && let Some((got, e)) = rest.split_once(", expected ")
    {
        return expected(got_words(got), e);
    }
    if let Some(rest) = message.strip_prefix("unknown variant ")
        && let Some((got, e)) = rest.split_once(", expected ")
    {
        let (id, e) = match e.strip_prefix("one of ") {
            Some(list) => ("json-variant-one-of", list),
            None => ("json-variant", e),
        };
        return Msg::new(id).arg("got", got.replace('`', "\"")).arg("expected", e.replace('`', "\""));
    }
    Msg::new("text-as-is").arg("why", message.replace('`', "\""))
}

/// What serde expected, in words.
fn expected_words(expected: &str) -> Msg {
    let e = expected.trim();
    let id = match e {
        "f64" | "f32" => "json-number",
        "u8" | "u16" | "u32" | "u64" | "usize" => "json-whole",
        "i8" | "i16" | "i32" | "i64" | "isize" => "json-integer",
        "a boolean" | "bool" => "json-bool",
        "a string" | "a borrowed string" => "json-text",
        "a sequence" => "json-array",
        "a map" => "json-object",
        _ if e.starts_with("struct ") || e.starts_with("an object") => "json-struct",
        _ if e.starts_with("an array of length ") => return Msg::new("json-array-of").arg("n", &e[19..]),
        _ if e.starts_with("a tuple of size ") => return Msg::new("json-tuple").arg("n", &e[16..]),
        _ => return Msg::new("text-as-is").arg("why", e.replace('`', "\"")),
    };
    Msg::new(id)
}

/// What the client sent, in words.
fn got_words(got: &str) -> Msg {
    let g = got.trim();
    match g {
        "sequence" => Msg::new("json-got-array"),
        "map" => Msg::new("json-got-object"),
        "unit value" | "null" => Msg::new("text-as-is").arg("why", "null"),
        _ => {
            if let Some(s) = g.strip_prefix("string ") {
                Msg::new("json-got-text").arg("text", s)
            } else if let Some(v) = g.strip_prefix("floating point `").or_else(|| g.strip_prefix("integer `")) {
                Msg::new("json-got-number").arg("value", v.trim_end_matches('`'))
            } else if let Some(v) = g.strip_prefix("boolean `") {
                Msg::new("text-as-is").arg("why", v.trim_end_matches('`'))
            } else {
                Msg::new("text-as-is").arg("why", g.replace('`', "\""))
            }
        }
    }
}

/// A body that is not JSON: where, what is there, and the usual cause.
pub fn malformed(e: &serde_json::Error, raw: &[u8]) -> String {
    let text = String::from_utf8_lossy(raw);
    let (line, column) = (e.line(), e.column());
    let near: String = text
        .lines()
        .nth(line.saturating_sub(1))
        .map(|l| l.chars().skip(column.saturating_sub(1)).take(24).collect())
        .unwrap_or_default();
    let cause = e.to_string();
    let cause = cause.split(" at line ").next().unwrap_or(&cause);
    let hint = match near.trim_start() {
        n if ["NaN", "Infinity", "-Infinity", "inf", "nan"].iter().any(|w| n.starts_with(w)) => {
            "; NaN and Infinity are not JSON numbers: give a finite number"
        }
        n if n.starts_with('\'') => "; JSON strings take double quotes",
        n if n.starts_with('}') || n.starts_with(']') => "; is there a comma before it?",
        _ => "",
    };
    if near.is_empty() {
        format!("{cause} at line {line}, column {column}{hint}")
    } else {
        format!("{cause} at line {line}, column {column}, near `{near}`{hint}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::Lang;

    #[test]
    fn serde_jargon_becomes_plain_words() {
        let en = |m: &str| plain(m).render(Lang::En);
        assert_eq!(
            en("invalid type: sequence, expected struct FlywheelRequest with 13 elements"),
            "expected an object {...} with named fields, got an array"
        );
        assert_eq!(en("invalid type: string \"abc\", expected f64"), "expected a number, got the text \"abc\"");
        assert_eq!(
            en("invalid type: floating point `1.5`, expected usize"),
            "expected a whole number, 0 or more, got the number 1.5"
        );
        assert_eq!(
            en("unknown variant `hinge`, expected one of `revolute`, `prismatic`"),
            "unknown variant \"hinge\", expected one of \"revolute\", \"prismatic\""
        );
        assert_eq!(
            plain("invalid type: string \"abc\", expected f64").render(Lang::Es),
            "se esperaba un número y llegó el texto \"abc\""
        );
        assert_eq!(
            plain("unknown variant `hinge`, expected one of `revolute`, `prismatic`").render(Lang::Es),
            "variante desconocida \"hinge\", se esperaba una de \"revolute\", \"prismatic\""
        );
    }

    #[test]
    fn a_nan_in_the_body_is_named() {
        let raw = b"{\"irregularity\": NaN}";
        let e = serde_json::from_slice::<serde_json::Value>(raw).unwrap_err();
        let m = malformed(&e, raw);
        assert!(m.contains("near `NaN}`") && m.contains("not JSON numbers"), "{m}");
    }
}
