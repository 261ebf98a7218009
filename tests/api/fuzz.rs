//! Property tests: whatever a client sends, the expression parser, the unit
//! parser and the request validation give a value or a clean error, never a
//! panic (proptest reports a panic as a failure, with the input shrunk).

use crate::helpers::request;
use mechdyn::api::json;
use mechdyn::engine::expr::Expr;
use mechdyn::kind::Kind;
use mechdyn::kind::Limits;
use mechdyn::kind::problem::ApiError;
use mechdyn::kinds::{flywheel, kinetostatics};
use mechdyn::units::{Dim, parse_as, parse_quantity};
use proptest::prelude::*;
use serde_json::Value;
use std::time::Duration;

/// Pieces of expressions: every operator, function and constant the parser
/// knows, some it does not, and numbers at the edges of f64.
const EXPR_TOKENS: &[&str] = &[
    "phi", "t", "x", "pi", "e", "0", "1", "2.5", "1e308", "1e-320", "1e", ".", "+", "-", "*", "/", "^", "(", ")", ",",
    " ", "sin", "cos", "tan", "asin", "sqrt", "exp", "ln", "log10", "abs", "sign", "floor", "min", "max", "atan2",
    "if", "<", "=", "**", "é", "\u{0}",
];

/// Pieces of quantities: numbers, units, prefixes and their operators.
const UNIT_TOKENS: &[&str] = &[
    "1", "-3.5", "1e400", "1e-400", "nan", "inf", " ", "kg", "m", "s", "N", "J", "W", "rpm", "deg", "rad", "ft", "lbf",
    "slug", "in", "mm", "k", "*", "/", "^", "-2", "2", "0.5", "(", ")", "·", "²", "%", "kgf", "hp", "",
];

fn soup(tokens: &'static [&'static str], max: usize) -> impl Strategy<Value = String> {
    prop::collection::vec(prop::sample::select(tokens), 0..max).prop_map(|t| t.concat())
}

fn try_expression(source: &str) {
    if let Ok(e) = Expr::compile(source, &["phi", "t"]) {
        for phi in [0.0, -1.5, 1e300, f64::NAN] {
            let _ = e.eval(&[phi, 0.25]);
        }
        let _ = e.derivative(0).eval(&[0.3, 0.0]);
        let _ = e.constant();
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn any_text_compiles_or_is_refused(source in "\\PC{0,200}") {
        try_expression(&source);
    }

    #[test]
    fn any_token_soup_compiles_or_is_refused(source in soup(EXPR_TOKENS, 60)) {
        try_expression(&source);
    }

    #[test]
    fn any_quantity_text_parses_or_is_refused(text in prop_oneof![soup(UNIT_TOKENS, 12), "\\PC{0,60}"]) {
        let _ = parse_quantity(&text);
        let _ = parse_as(&text, Dim::INERTIA);
    }
}

/// Nesting far beyond the limit in every form the grammar recurses on is
/// refused, not a stack overflow.
#[test]
fn deep_nesting_is_refused_not_overflowed() {
    let n = 100_000;
    for source in [
        format!("{}phi{}", "(".repeat(n), ")".repeat(n)),
        format!("{}phi", "-".repeat(n)),
        format!("phi{}", "^phi".repeat(n / 4)),
        format!("{}phi{}", "sin(".repeat(n), ")".repeat(n)),
        format!("{}phi{}", "max(1,".repeat(n), ")".repeat(n)),
    ] {
        assert!(Expr::compile(&source, &["phi"]).is_err(), "{}…", &source[..20]);
    }
}

/// Values a spreadsheet or a fuzzer may put anywhere in a request.
fn odd_value() -> impl Strategy<Value = Value> {
    prop_oneof![
        Just(Value::Null),
        Just(Value::Bool(true)),
        any::<f64>().prop_map(|x| serde_json::json!(x)),
        prop::sample::select(vec![0.0, -1.0, 1e300, -1e-300, 1e-9, 7.0]).prop_map(|x| serde_json::json!(x)),
        any::<i64>().prop_map(|x| serde_json::json!(x)),
        prop::sample::select(vec!["", "ground", "crank", "O", "1 kg", "-2 m", "1e9 rpm", "phi", "sin(phi)/0", "x"])
            .prop_map(|s| serde_json::json!(s)),
        Just(serde_json::json!([])),
        Just(serde_json::json!({})),
        (any::<f64>(), any::<f64>()).prop_map(|(a, b)| serde_json::json!([a, b])),
    ]
}

/// Every JSON pointer in `v` (containers and leaves).
fn pointers(v: &Value, at: String, out: &mut Vec<String>) {
    match v {
        Value::Object(m) => m.iter().for_each(|(k, x)| pointers(x, format!("{at}/{}", json::escape(k)), out)),
        Value::Array(a) => a.iter().enumerate().for_each(|(i, x)| pointers(x, format!("{at}/{i}"), out)),
        _ => {}
    }
    out.push(at);
}

/// Numbers at the edges: zero, negative, huge, tiny, and any f64.
fn odd_number() -> impl Strategy<Value = Value> {
    prop_oneof![
        prop::sample::select(vec![0.0, -1.0, 1e300, -1e-300, 1e-9, 7.0, 0.5]).prop_map(|x| serde_json::json!(x)),
        any::<f64>().prop_map(|x| serde_json::json!(x)),
    ]
}

/// How a field is changed.
#[derive(Clone, Debug)]
enum Edit {
    /// A number for a number, a string for a string (what a half-filled row does).
    SameKind(Value, Value),
    Any(Value),
    Remove,
}

fn edit() -> impl Strategy<Value = Edit> {
    let text = prop::sample::select(vec!["", "ground", "crank", "O", "2 kg", "-2 m", "1e9 rpm", "90 deg", "x"]);
    prop_oneof![
        6 => (odd_number(), text.prop_map(|s| serde_json::json!(s))).prop_map(|(n, t)| Edit::SameKind(n, t)),
        1 => odd_value().prop_map(Edit::Any),
        1 => Just(Edit::Remove),
    ]
}

/// A fixture with 1 to 4 of its fields changed by an [`Edit`].
fn mutated(fixture: &'static str) -> impl Strategy<Value = String> {
    let base = request(fixture);
    let mut all = Vec::new();
    pointers(&base, String::new(), &mut all);
    let all: Vec<String> = all.into_iter().filter(|p| !p.is_empty()).collect();
    prop::collection::vec((prop::sample::select(all), edit()), 1..5).prop_map(move |edits| {
        let mut v = base.clone();
        for (pointer, edit) in edits {
            let (parent, key) = pointer.rsplit_once('/').unwrap();
            if let (Edit::Remove, Some(Value::Object(m))) = (&edit, v.pointer_mut(parent)) {
                m.remove(key);
            } else if let Some(slot) = v.pointer_mut(&pointer) {
                *slot = match (edit, &*slot) {
                    (Edit::SameKind(n, _), Value::Number(_)) => n,
                    (Edit::SameKind(_, t), Value::String(_)) => t,
                    (Edit::Any(x), _) => x,
                    _ => continue,
                };
            }
        }
        v.to_string()
    })
}

/// The default limits with a 2 s budget.
fn limits() -> Limits {
    Limits { budget: Duration::from_secs(2), ..Limits::default() }
}

/// Solved, or refused as the client's fault (an internal error is a bug).
fn solved<T>(r: Result<T, ApiError>) -> bool {
    match r {
        Ok(_) => true,
        Err(ApiError::Internal(e)) => panic!("an internal error for client input: {e}"),
        Err(_) => false,
    }
}

/// Runs `cases` mutations of `fixture` through `solve` (which must not
/// panic); returns how many were solved, refused at parsing, refused later.
fn run_mutations(fixture: &'static str, cases: u32, solve: impl Fn(String) -> Option<bool>) -> [usize; 3] {
    let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig::with_cases(cases));
    let counts = std::cell::RefCell::new([0usize; 3]);
    runner
        .run(&mutated(fixture), |body| {
            counts.borrow_mut()[match solve(body) {
                Some(true) => 0,
                None => 1,
                Some(false) => 2,
            }] += 1;
            Ok(())
        })
        .unwrap();
    counts.into_inner()
}

/// Mutated K1 mechanisms: solved, or refused with an error. Some must be
/// solved and some refused after parsing, or the test would only exercise
/// the JSON layer.
#[test]
fn any_mutated_mechanism_is_solved_or_refused() {
    let [solved, unparsed, refused] = run_mutations("k1_offset_slider_crank", 300, |body| {
        let b = json::parse::<kinetostatics::KinetostaticsRequest>(body).ok()?;
        Some(solved(kinetostatics::Kinetostatics::compute(&b.value, b.unknown, &limits())))
    });
    eprintln!("kinetostatics: {solved} solved, {unparsed} refused at parsing, {refused} refused by validation");
    assert!(solved > 0 && refused > 0, "{solved} solved, {refused} refused");
}

/// The same for the flywheel of P.103 with its slider-crank as the machine.
#[test]
fn any_mutated_machine_flywheel_is_solved_or_refused() {
    let [solved, unparsed, refused] = run_mutations("p103_slider_machine", 200, |body| {
        let b = json::parse::<flywheel::FlywheelRequest>(body).ok()?;
        Some(solved(flywheel::Flywheel::compute(&b.value, b.unknown, &limits())))
    });
    eprintln!("machine flywheel: {solved} solved, {unparsed} refused at parsing, {refused} refused by validation");
    assert!(solved > 0 && refused > 0, "{solved} solved, {refused} refused");
}
