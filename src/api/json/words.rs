//! serde's messages in the words of a JSON user: "expected a number, got
//! the text \"abc\"" rather than "invalid type: string \"abc\", expected
//! f64", and a malformed body pointed at where it goes wrong.

/// A structural error of serde (wrong type, wrong length, unknown name) said plainly.
pub fn plain(message: &str) -> String {
    if let Some(rest) = message.strip_prefix("invalid type: ")
        && let Some((got, expected)) = rest.split_once(", expected ")
    {
        return format!("expected {}, got {}", expected_words(expected), got_words(got));
    }
    if let Some(rest) = message.strip_prefix("invalid length ")
        && let Some((n, expected)) = rest.split_once(", expected ")
    {
        return format!("expected {}, got {n} item(s)", expected_words(expected));
    }
    if let Some(rest) = message.strip_prefix("invalid value: ")
        && let Some((got, expected)) = rest.split_once(", expected ")
    {
        return format!("expected {}, got {}", expected_words(expected), got_words(got));
    }
    message.replace('`', "\"")
}

/// What serde expected, in words.
fn expected_words(expected: &str) -> String {
    let e = expected.trim();
    let words = match e {
        "f64" | "f32" => "a number",
        "u8" | "u16" | "u32" | "u64" | "usize" => "a whole number, 0 or more",
        "i8" | "i16" | "i32" | "i64" | "isize" => "a whole number",
        "a boolean" | "bool" => "true or false",
        "a string" | "a borrowed string" => "a text in quotes",
        "a sequence" => "an array [...]",
        "a map" => "an object {...}",
        _ if e.starts_with("struct ") || e.starts_with("an object") => "an object {...} with named fields",
        _ if e.starts_with("an array of length ") => return format!("an array of {} numbers", &e[19..]),
        _ if e.starts_with("a tuple of size ") => return format!("an array of {} items", &e[16..]),
        _ => return e.replace('`', "\""),
    };
    words.into()
}

/// What the client sent, in words.
fn got_words(got: &str) -> String {
    let g = got.trim();
    match g {
        "sequence" => "an array".into(),
        "map" => "an object".into(),
        "unit value" | "null" => "null".into(),
        _ => {
            if let Some(s) = g.strip_prefix("string ") {
                format!("the text {s}")
            } else if let Some(v) = g.strip_prefix("floating point `").or_else(|| g.strip_prefix("integer `")) {
                format!("the number {}", v.trim_end_matches('`'))
            } else if let Some(v) = g.strip_prefix("boolean `") {
                v.trim_end_matches('`').into()
            } else {
                g.replace('`', "\"")
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

    #[test]
    fn serde_jargon_becomes_plain_words() {
        assert_eq!(
            plain("invalid type: sequence, expected struct FlywheelRequest with 13 elements"),
            "expected an object {...} with named fields, got an array"
        );
        assert_eq!(plain("invalid type: string \"abc\", expected f64"), "expected a number, got the text \"abc\"");
        assert_eq!(
            plain("invalid type: floating point `1.5`, expected usize"),
            "expected a whole number, 0 or more, got the number 1.5"
        );
        assert_eq!(
            plain("unknown variant `hinge`, expected one of `revolute`, `prismatic`"),
            "unknown variant \"hinge\", expected one of \"revolute\", \"prismatic\""
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
