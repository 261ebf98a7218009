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
        let quoted = |s: &str| s.replace('`', "\"");
        let said = match (e.strip_prefix("one of "), e.split_once(" or ")) {
            (Some(list), _) => Msg::new("json-variant-one-of").arg("expected", quoted(list)),
            (None, Some((a, b))) => Msg::new("json-variant-either").arg("a", quoted(a)).arg("b", quoted(b)),
            (None, None) => Msg::new("json-variant").arg("expected", quoted(e)),
        };
        return said.arg("got", quoted(got));
    }
    Msg::new("text-as-is").arg("why", message.replace('`', "\""))
}

/// What the service's own readers expect (their visitors' `expecting`
/// writes the catalogue's id, so that serde's message carries it here).
const EXPECTING: [&str; 9] = [
    "json-expect-quantity",
    "json-expect-function",
    "json-expect-program",
    "json-expect-inputs",
    "json-expect-track",
    "json-expect-point",
    "json-expect-length",
    "json-expect-fewer",
    "json-expect-inertia",
];

/// What serde expected, in words.
fn expected_words(expected: &str) -> Msg {
    let e = expected.trim();
    if let Some(id) = EXPECTING.iter().find(|id| **id == e) {
        return Msg::new(id);
    }
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
pub fn malformed(e: &serde_json::Error, raw: &[u8]) -> Msg {
    let text = String::from_utf8_lossy(raw);
    let (line, column) = (e.line(), e.column());
    let near: String = text
        .lines()
        .nth(line.saturating_sub(1))
        .map(|l| l.chars().skip(column.saturating_sub(1)).take(24).collect())
        .unwrap_or_default();
    let cause = e.to_string();
    let cause = cause.split(" at line ").next().unwrap_or(&cause);
    let before: String = text
        .lines()
        .nth(line.saturating_sub(1))
        .map(|l| l.chars().take(column.saturating_sub(1)).collect())
        .unwrap_or_default();
    let hint = match near.trim_start() {
        _ if let Some(written) = decimal_comma(&before, &near) => {
            let dot = written.replace(',', ".");
            Msg::new("json-hint-decimal-comma").arg("dot", dot).arg("comma", written)
        }
        n if ["NaN", "Infinity", "-Infinity", "inf", "nan"].iter().any(|w| n.starts_with(w)) => {
            Msg::new("json-hint-nan")
        }
        n if n.starts_with('\'') => Msg::new("json-hint-quotes"),
        _ if cause == "trailing comma" => Msg::new("text-nothing"),
        n if n.starts_with('}') || n.starts_with(']') => Msg::new("json-hint-comma"),
        _ => Msg::new("text-nothing"),
    };
    let at = match near.is_empty() {
        true => Msg::new("json-at"),
        false => Msg::new("json-at-near").arg("near", near),
    };
    let at = at.count("line", line).count("column", column);
    Msg::new("json-syntax").with("cause", syntax(cause)).with("at", at).with("hint", hint)
}

/// A decimal comma inside a JSON number (`"mu": 0,1`): a digit, a comma
/// and a digit where the parse stopped; the number as written (`0,1`, its
/// sign and every digit either side), so that the hint shows the asker's
/// own number written with a point (a fixed `0.5` read as the value to
/// write sent a student's 0,05 ten times too large).
fn decimal_comma(before: &str, near: &str) -> Option<String> {
    let digit = |c: char| c.is_ascii_digit();
    // Digits of the fraction the parse had already passed (`0,4|5`), then the comma.
    let whole = before.trim_end_matches(digit);
    let passed = &before[whole.len()..];
    let whole = if passed.is_empty() { whole.trim_end() } else { whole };
    let whole = whole.strip_suffix(',')?.trim_end();
    let integer = &whole[whole.trim_end_matches(digit).len()..];
    let sign = if whole[..whole.len() - integer.len()].ends_with('-') { "-" } else { "" };
    let rest = if passed.is_empty() { near.trim_start() } else { near };
    let fraction: String = passed.chars().chain(rest.chars().take_while(|c| digit(*c))).collect();
    (!integer.is_empty() && !fraction.is_empty()).then(|| format!("{sign}{integer},{fraction}"))
}

/// serde_json's syntax error, as the catalogue words it.
fn syntax(cause: &str) -> Msg {
    let id = match cause {
        "EOF while parsing a list" => "json-eof-list",
        "EOF while parsing an object" => "json-eof-object",
        "EOF while parsing a string" => "json-eof-string",
        "EOF while parsing a value" => "json-eof-value",
        "expected `:`" => "json-expected-colon",
        "expected `,` or `]`" => "json-expected-comma-bracket",
        "expected `,` or `}`" => "json-expected-comma-brace",
        "expected value" => "json-expected-value",
        "expected ident" => "json-expected-ident",
        "invalid escape" => "json-invalid-escape",
        "invalid number" => "json-invalid-number",
        "number out of range" => "json-number-out-of-range",
        "key must be a string" => "json-key-not-string",
        "trailing comma" => "json-trailing-comma",
        "trailing characters" => "json-trailing-characters",
        "recursion limit exceeded" => "json-too-deep",
        c if c.starts_with("control character") => "json-control-character",
        // A typed body's error (a wrong type, an unknown name), or one unknown here.
        _ => return plain(cause),
    };
    Msg::new(id)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::Lang;

    /// The number a decimal comma split, as written, wherever the parse
    /// stopped in it; none where the comma parts two numbers or a key.
    #[test]
    fn a_decimal_comma_is_shown_with_the_asker_s_own_number() {
        let cases = [
            (r#"{"irregularity": 0,"#, "05}", Some("0,05")),
            (r#"{"irregularity": 0, "#, "05}", Some("0,05")),
            (r#"{"e": -12,"#, "375, ", Some("-12,375")),
            (r#"{"e": 1,2"#, "5}", Some("1,25")),
            (r#"{"e": 1, "#, "\"f\": 2}", None),
            (r#"{"e": "a","#, "2}", None),
        ];
        for (before, near, want) in cases {
            assert_eq!(decimal_comma(before, near).as_deref(), want, "{before}|{near}");
        }
        let raw = br#"{"irregularity": 0,05}"#;
        let e = serde_json::from_slice::<serde_json::Value>(raw).unwrap_err();
        let said = malformed(&e, raw).render(Lang::Es);
        assert!(said.contains("escriba 0.05, o el texto \"0,05\""), "{said}");
        assert!(malformed(&e, raw).render(Lang::En).contains("write 0.05, or the text \"0,05\""));
    }

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
        assert_eq!(
            m.render(Lang::En),
            "expected value at line 1, column 18, near `NaN}`; NaN and Infinity are not JSON numbers: give a finite number"
        );
        assert_eq!(
            m.render(Lang::Es),
            "se esperaba un valor en la línea 1, columna 18, junto a `NaN}`; NaN e Infinity no son números de JSON: \
             dé un número finito"
        );
    }

    /// Each syntax error serde_json gives for a broken body has its words in the catalogue.
    #[test]
    fn every_usual_syntax_error_is_worded() {
        let bodies: [&[u8]; 11] = [
            b"[1, 2",
            b"{\"a\": 1",
            b"\"abc",
            b"",
            b"{\"a\" 1}",
            b"[1 2]",
            b"{\"a\": 1 \"b\": 2}",
            b"{\"a\": x}",
            b"[1,]",
            b"{1: 2}",
            b"[1] 2",
        ];
        for raw in bodies {
            let e = serde_json::from_slice::<serde_json::Value>(raw).unwrap_err();
            let m = malformed(&e, raw);
            let cause = e.to_string();
            let cause = cause.split(" at line ").next().unwrap();
            assert_ne!(syntax(cause).id(), "text-as-is", "{cause}");
            assert!(m.render(Lang::En).starts_with(cause), "{}", m.render(Lang::En));
        }
    }
}
