//! Why an expression was refused ([`Fault`]), as the catalogue says it: a
//! student's `sen(phi)` is answered in Spanish too, naming the functions
//! the language has.

use crate::engine::expr::{Arity, FUNCTIONS, Fault, Tok};
use crate::i18n::Msg;

/// A fault of an expression in words.
pub fn fault_msg(f: &Fault) -> Msg {
    match f {
        Fault::TooLong { length, max } => Msg::new("expr-too-long").count("length", *length).count("max", *max),
        Fault::MalformedNumber(text) => Msg::new("expr-malformed-number").arg("text", text),
        Fault::UnexpectedCharacter(c) => Msg::new("expr-unexpected-character").arg("char", c),
        Fault::Empty => Msg::new("expr-empty"),
        Fault::AfterEnd(t) => Msg::new("expr-after-end").with("token", token(t)),
        Fault::TooDeep(max) => Msg::new("expr-too-deep").count("max", *max),
        Fault::EndsEarly => Msg::new("expr-ends-early"),
        Fault::Unexpected(t) => Msg::new("expr-unexpected").with("token", token(t)),
        Fault::NeedsParentheses(name) => Msg::new("expr-needs-parentheses").arg("name", name),
        Fault::UnknownName { name, variables, constants } => {
            let variables = match variables.is_empty() {
                true => Msg::new("expr-none"),
                false => Msg::new("text-as-is").arg("why", variables.join(", ")),
            };
            Msg::new("expr-unknown-name")
                .arg("name", name)
                .with("variables", variables)
                .arg("constants", constants.join(", "))
        }
        Fault::Arity { name, takes, got } => {
            let takes = match takes {
                Arity::One => Msg::new("expr-takes-one"),
                Arity::Two => Msg::new("expr-takes-two"),
                Arity::AtLeastTwo => Msg::new("expr-takes-at-least-two"),
            };
            Msg::new("expr-arity").arg("name", name).with("takes", takes).count("got", *got)
        }
        Fault::UnknownFunction(name) => Msg::new("expr-unknown-function").arg("name", name).arg("known", FUNCTIONS),
        Fault::Expected(op) => Msg::new("expr-expected").arg("op", op),
    }
}

/// The number written with a decimal comma ("0,05") where a comma the
/// expression could not read stands between two digits: what a Spanish
/// sheet writes, to be said as such rather than as a stray comma.
pub fn decimal_comma<'a>(src: &'a str, f: &Fault) -> Option<&'a str> {
    // A comma after a whole expression (`2 + 0,5`), where a value was
    // expected, where a parenthesis was to close (`1/(0,5 - t)`), or one
    // that made a function of one argument take two (`cos(phi - 0,35)`).
    let split_argument = matches!(f, Fault::Arity { takes: Arity::One, .. });
    if !split_argument
        && !matches!(f, Fault::AfterEnd(Tok::Op(',')) | Fault::Unexpected(Tok::Op(',')) | Fault::Expected(_))
    {
        return None;
    }
    let b = src.as_bytes();
    let at = (1..b.len().saturating_sub(1))
        .find(|&i| b[i] == b',' && b[i - 1].is_ascii_digit() && b[i + 1].is_ascii_digit())?;
    let number = |c: u8| c.is_ascii_digit() || c == b'.' || c == b',';
    let start = (0..at).rev().take_while(|&i| number(b[i])).last().unwrap_or(at);
    let end = (at + 1..b.len()).take_while(|&i| number(b[i])).last().map_or(at + 1, |i| i + 1);
    Some(&src[start..end])
}

fn token(t: &Tok) -> Msg {
    match t {
        Tok::Num(v) => Msg::new("expr-token-number").num("value", *v),
        Tok::Name(n) => Msg::new("expr-token-name").arg("name", n),
        Tok::Op(c) => Msg::new("expr-token-operator").arg("op", c),
    }
}
