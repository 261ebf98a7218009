//! The items of a check: each answer read (a number in SI, or `"VALUE
//! UNIT"`, a decimal comma allowed), judged against the reference result by
//! the tolerance rules ([`crate::engine::grading`]), and its feedback, which
//! names the slip a wrong answer matches.

use super::{CheckItem, ToleranceDto};
use crate::api::kind::AnyKind;
use crate::api::tables::{self, Scalar};
use crate::engine::grading::{self, Measure, Rule, Slip, Tolerance, Verdict};
use crate::engine::variants::round_sig;
use crate::kind::DIMENSIONLESS;
use crate::kind::problem::FieldError;
use crate::units::{Dim, UnitError, parse_as, parse_unit};
use serde_json::Value;

/// One answer to judge: its pointer into the result, the answer as given,
/// its tolerance.
pub struct Asked<'a> {
    pub pointer: &'a str,
    pub answer: &'a Value,
    pub tolerance: Tolerance,
}

/// The tolerance of an answer: the defaults, then the request's, then the answer's own.
pub fn tolerance(general: Option<&ToleranceDto>, own: Option<&ToleranceDto>) -> Tolerance {
    let mut t = Tolerance::default();
    for dto in [general, own].into_iter().flatten() {
        t.relative = dto.relative.unwrap_or(t.relative);
        t.absolute = dto.absolute.unwrap_or(t.absolute);
        t.sigfigs = dto.sigfigs.or(t.sigfigs);
        t.zero_level = dto.zero_level.unwrap_or(t.zero_level);
    }
    t
}

/// The expected number at `pointer` of `result` and its unit, or why an
/// instructor's pointer names none (an error at `at`).
pub fn expected(kind: &dyn AnyKind, result: &Value, pointer: &str, at: &str) -> Result<(f64, String), FieldError> {
    let tokens = tables::tokens(pointer);
    let value = tables::at(result, &tokens).ok_or_else(|| {
        FieldError::at(at, format!("the {} result has no value at /{}", kind.name(), pointer.trim_start_matches('/')))
    })?;
    let x = value.as_f64().ok_or_else(|| {
        FieldError::at(
            at,
            format!(
                "/{} is not a number ({}): only numbers are graded",
                pointer.trim_start_matches('/'),
                clipped(value)
            ),
        )
    })?;
    let refs: Vec<&str> = tokens.iter().map(String::as_str).collect();
    Ok((x, kind.unit(result, &refs).unwrap_or_else(|| DIMENSIONLESS.into())))
}

/// Judges one answer against `e` (in `unit`); `others` gives the result's
/// other numbers in the same unit, nearest first, for the slips (asked for
/// only when the answer fails).
pub fn judge(
    asked: &Asked,
    e: f64,
    unit: &str,
    others: impl FnOnce() -> Vec<(String, f64)>,
    reveal: bool,
) -> CheckItem {
    let name = asked.pointer.trim_start_matches('/');
    let mut item = CheckItem {
        pointer: format!("/{name}"),
        answer: asked.answer.clone(),
        given: None,
        expected: reveal.then_some(e),
        unit: unit.to_string(),
        relative_error: None,
        pass: false,
        slip: None,
        feedback: String::new(),
    };
    let g = match read(asked.answer, unit) {
        Ok(g) => g,
        Err(why) => {
            item.feedback = format!("{name}: {why}.");
            return item;
        }
    };
    let t = &asked.tolerance;
    let verdict = grading::judge(g, e, t);
    (item.given, item.pass) = (Some(g), verdict.pass);
    item.relative_error = verdict.relative_error.filter(|_| reveal);
    let others = if verdict.pass { Vec::new() } else { others() };
    let slip = (!verdict.pass).then(|| grading::slip(g, e, t, measure(unit), &values(&others))).flatten();
    item.slip = slip.map(|s| slip_name(s, &others));
    let given = given_text(asked.answer, g, unit);
    item.feedback = feedback(name, &given, e, unit, &verdict, t, slip.map(|s| slip_text(s, name, &others)), reveal);
    item
}

/// ` kg*m^2` after a number; nothing for a pure number.
fn suffix(unit: &str) -> String {
    if unit == DIMENSIONLESS { String::new() } else { format!(" {unit}") }
}

/// The answer as the student wrote it, with its SI value when it had a unit:
/// `260 slug*ft^2 = 352.51 kg*m^2`, `353.5 kg*m^2`.
fn given_text(answer: &Value, g: f64, unit: &str) -> String {
    let si = format!("{}{}", short(g), suffix(unit));
    match answer.as_str().map(str::trim) {
        Some(text) if crate::units::number(text).is_none() && text != si => {
            format!("{text} = {si}")
        }
        _ => si,
    }
}

fn values(others: &[(String, f64)]) -> Vec<f64> {
    others.iter().map(|(_, x)| *x).collect()
}

/// An answer in SI: a number, or a quantity string of the expected unit's dimension.
fn read(answer: &Value, unit: &str) -> Result<f64, String> {
    let text = match answer {
        Value::Number(n) => return n.as_f64().ok_or_else(|| "not a number".to_string()),
        Value::String(s) if s.trim().is_empty() => return Err("no answer".into()),
        Value::String(s) => s.clone(),
        Value::Null => return Err("no answer".into()),
        other => return Err(format!("{other} is not a number")),
    };
    let dim = if unit == DIMENSIONLESS { Dim::NONE } else { parse_unit(unit).map_or(Dim::NONE, |(_, d)| d) };
    parse_as(&text, dim).map_err(|e| match e {
        UnitError::WrongDimension { found, .. } => format!("'{text}' is in {found}, where the answer is in {unit}"),
        e => format!("'{text}' is not a number or a quantity ({})", e.to_string().trim_end_matches('.')),
    })
}

/// Which slips apply to a unit: degrees where radians, rpm where rad/s.
fn measure(unit: &str) -> Measure {
    let dim = parse_unit(unit).map_or(Dim::NONE, |(_, d)| d);
    Measure { angular: dim.0[3] == 1, angular_speed: dim == Dim::ANGULAR_SPEED }
}

/// Five significant digits, for people: `353.52`, `-1000`, `1.5e-7`.
fn short(x: f64) -> String {
    let x = round_sig(x, 5);
    if x == 0.0 || (1e-4..1e9).contains(&x.abs()) { format!("{x}") } else { format!("{x:e}") }
}

fn rule_text(v: &Verdict, t: &Tolerance, unit: &str) -> String {
    let unit = suffix(unit);
    match v.rule {
        Rule::ZeroLevel => format!("±{}{unit} (the zero level)", short(t.zero_level)),
        Rule::Absolute => format!("±{}{unit}", short(t.absolute)),
        Rule::Relative => format!("{} %", short(t.relative * 100.0)),
        Rule::SigFigs => format!("{} significant figures", t.sigfigs.unwrap_or_default()),
    }
}

#[allow(clippy::too_many_arguments)]
fn feedback(
    name: &str,
    given: &str,
    e: f64,
    unit: &str,
    v: &Verdict,
    t: &Tolerance,
    slip: Option<String>,
    reveal: bool,
) -> String {
    let within = rule_text(v, t, unit);
    let expected = format!("{}{}", short(e), suffix(unit));
    let mut text = match (v.pass, reveal) {
        (true, true) => format!("{name}: correct ({given}, within {within} of {expected})."),
        (true, false) => format!("{name}: correct (within {within})."),
        (false, true) => {
            let off = v.relative_error.map(|r| format!(", {} % off", short(r * 100.0))).unwrap_or_default();
            format!("{name}: {given} is not within {within} of the expected {expected}{off}.")
        }
        (false, false) => format!("{name}: {given} is not within {within} of the expected value."),
    };
    if let Some(s) = slip {
        text.push(' ');
        text.push_str(&s);
    }
    text
}

/// The slip's name in the item (`other_value:/inertia_approximate`, `opposite_sign`, ...).
fn slip_name(s: Slip, others: &[(String, f64)]) -> String {
    match s {
        Slip::OtherValue(i) => format!("other_value:{}", others[i].0),
        Slip::OppositeSign => "opposite_sign".into(),
        Slip::Degrees => "degrees".into(),
        Slip::Rpm => "rpm".into(),
        Slip::TwoPi { times: true } => "times_2pi".into(),
        Slip::TwoPi { times: false } => "over_2pi".into(),
        Slip::PowerOfTen(k) => format!("power_of_ten:{k}"),
    }
}

/// What a student reads of a slip.
fn slip_text(s: Slip, name: &str, others: &[(String, f64)]) -> String {
    match s {
        Slip::OtherValue(i) => {
            let other = others[i].0.trim_start_matches('/');
            format!("It matches {other} of the result: that value was given for {name}?")
        }
        Slip::OppositeSign if name.contains("reactions/") => {
            "It has the opposite sign: the reaction on the other body of the joint? (The result gives the force on \
             the joint's second body.)"
                .into()
        }
        Slip::OppositeSign => "It has the opposite sign.".into(),
        Slip::Degrees => "It matches the value in degrees: radians are expected.".into(),
        Slip::Rpm => "It matches the value in rpm: rad/s are expected (1 rpm = 2π/60 rad/s).".into(),
        Slip::TwoPi { times: true } => "It is 2π times the expected value.".into(),
        Slip::TwoPi { times: false } => "It is the expected value divided by 2π.".into(),
        Slip::PowerOfTen(k) => format!("It is 10^{k} times the expected value: a unit prefix (mm for m, kN for N)?"),
    }
}

/// Longest array whose items are each a candidate slip; the items of a
/// longer one (a series over the cycle, a table of steps) are not, unless
/// the answer is in the same item.
const SHORT_LIST: usize = 10;

/// The result's other numbers in `unit`, the nearest to `pointer` first:
/// those sharing all but its last two tokens (siblings and cousins, e.g. the
/// other reaction of the same step, `/inertia_approximate` for
/// `/inertia_exact`, `/flywheel_inertia/exact` for it), not inside another
/// item of a long series: a value matched by chance in a table is no slip a
/// student makes.
pub fn others(flat: &[Scalar], result: &Value, pointer: &str, unit: &str) -> Vec<(String, f64)> {
    let own = tables::tokens(pointer);
    let mut near: Vec<((std::cmp::Reverse<usize>, usize), String, f64)> = flat
        .iter()
        .filter(|s| s.unit.as_deref() == Some(unit))
        .filter_map(|s| {
            let tokens = tables::tokens(&s.pointer);
            let shared = own.iter().zip(&tokens).take_while(|(a, b)| a == b).count();
            let near =
                shared + 2 >= own.len().min(tokens.len()) && tokens != own && !in_series(result, &tokens, shared);
            // Nearest first: most tokens shared, then the same depth (siblings before cousins).
            let rank = (std::cmp::Reverse(shared), tokens.len().abs_diff(own.len()));
            Some((rank, s.pointer.clone(), s.value.as_f64()?)).filter(|_| near)
        })
        .collect();
    near.sort_by_key(|(rank, ..)| *rank);
    near.into_iter().map(|(_, p, x)| (p, x)).collect()
}

/// Whether `tokens`, past their first `shared`, go through an item of an
/// array longer than [`SHORT_LIST`].
fn in_series(result: &Value, tokens: &[String], shared: usize) -> bool {
    (shared..tokens.len())
        .any(|i| tables::at(result, &tokens[..i]).and_then(Value::as_array).is_some_and(|a| a.len() > SHORT_LIST))
}

/// A value in a message: its JSON, cut after 60 characters (a whole table is no help).
fn clipped(value: &Value) -> String {
    let text = value.to_string();
    match text.char_indices().nth(60) {
        Some((i, _)) => format!("{}…", &text[..i]),
        None => text,
    }
}
