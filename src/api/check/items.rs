//! The items of a check: each answer read (a number in SI, or `"VALUE
//! UNIT"`, a decimal comma allowed), judged against the reference result by
//! the tolerance rules ([`crate::engine::grading`]), and its feedback, which
//! names the slip a wrong answer matches.

use super::{CheckItem, ToleranceDto};
use crate::api::kind::AnyKind;
use crate::api::tables;
use crate::engine::grading::{self, Measure, Rule, Slip, Tolerance, Verdict};
use crate::engine::variants::round_sig;
use crate::i18n::{Lang, Msg};
use crate::kind::DIMENSIONLESS;
use crate::kind::problem::FieldError;
use crate::kind::quantity::unit_msg;
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
    let at_pointer = format!("/{}", pointer.trim_start_matches('/'));
    let value = tables::at(result, &tokens).ok_or_else(|| {
        FieldError::said(at, Msg::new("check-no-value").arg("kind", kind.name()).arg("pointer", &at_pointer))
    })?;
    let x = value.as_f64().ok_or_else(|| {
        FieldError::said(at, Msg::new("check-not-graded").arg("pointer", &at_pointer).arg("value", clipped(value)))
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
        said: Msg::new("check-no-answer"),
    };
    let g = match read(asked.answer, unit) {
        Ok(g) => g,
        Err(why) => {
            item.said(Msg::new("check-unread").arg("name", name).with("why", why));
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
    let said = feedback(name, given, e, unit, &verdict, t, reveal);
    item.said(match slip {
        Some(s) => Msg::new("check-with-slip").with("feedback", said).with("slip", slip_text(s, name, &others)),
        None => said,
    });
    item
}

impl CheckItem {
    /// The item's feedback said by `msg` (stored in English, read in the asker's language).
    fn said(&mut self, msg: Msg) {
        self.feedback = msg.render(Lang::En);
        self.said = msg;
    }
}

/// ` kg*m^2` after a number; nothing for a pure number.
fn suffix(unit: &str) -> String {
    if unit == DIMENSIONLESS { String::new() } else { format!(" {unit}") }
}

/// A value in SI to five figures, with its unit: `353.52 kg*m^2`.
fn value(x: f64, unit: &str) -> Msg {
    Msg::new("check-value").num("value", round_sig(x, 5)).arg("unit", suffix(unit))
}

/// The answer as the student wrote it, with its SI value when it had a unit:
/// `260 slug*ft^2 = 352.51 kg*m^2`, `353.5 kg*m^2`.
fn given_text(answer: &Value, g: f64, unit: &str) -> Msg {
    let written = answer.as_str().map(str::trim).filter(|t| crate::units::number(t).is_none());
    match written {
        Some(text) if text != value(g, unit).render(Lang::En) => {
            Msg::new("check-given").arg("text", text).with("si", value(g, unit))
        }
        _ => value(g, unit),
    }
}

fn values(others: &[(String, f64)]) -> Vec<f64> {
    others.iter().map(|(_, x)| *x).collect()
}

/// An answer in SI: a number, or a quantity string of the expected unit's dimension.
fn read(answer: &Value, unit: &str) -> Result<f64, Msg> {
    let text = match answer {
        Value::Number(n) => return n.as_f64().ok_or_else(|| Msg::new("check-not-a-number").arg("value", n)),
        Value::String(s) if s.trim().is_empty() => return Err(Msg::new("check-no-answer")),
        Value::String(s) => s.clone(),
        Value::Null => return Err(Msg::new("check-no-answer")),
        other => return Err(Msg::new("check-not-a-number").arg("value", other)),
    };
    let dim = if unit == DIMENSIONLESS { Dim::NONE } else { parse_unit(unit).map_or(Dim::NONE, |(_, d)| d) };
    parse_as(&text, dim).map_err(|e| match e {
        UnitError::WrongDimension { found, .. } => {
            Msg::new("check-wrong-dimension").arg("text", &text).arg("found", found).arg("unit", unit)
        }
        e => Msg::new("check-unreadable").arg("text", &text).with("why", unit_msg(&e)),
    })
}

/// Which slips apply to a unit: degrees where radians, rpm where rad/s.
fn measure(unit: &str) -> Measure {
    let dim = parse_unit(unit).map_or(Dim::NONE, |(_, d)| d);
    Measure { angular: dim.0[3] == 1, angular_speed: dim == Dim::ANGULAR_SPEED }
}

fn rule_text(v: &Verdict, t: &Tolerance, unit: &str) -> Msg {
    match v.rule {
        Rule::ZeroLevel => Msg::new("check-rule-zero-level").with("value", value(t.zero_level, unit)),
        Rule::Absolute => Msg::new("check-rule-absolute").with("value", value(t.absolute, unit)),
        Rule::Relative => Msg::new("check-rule-relative").num("percent", round_sig(t.relative * 100.0, 5)),
        Rule::SigFigs => Msg::new("check-rule-sigfigs").count("count", t.sigfigs.unwrap_or_default() as usize),
    }
}

fn feedback(name: &str, given: Msg, e: f64, unit: &str, v: &Verdict, t: &Tolerance, reveal: bool) -> Msg {
    let (within, expected) = (rule_text(v, t, unit), value(e, unit));
    let said = |id| Msg::new(id).arg("name", name).with("within", within);
    match (v.pass, reveal) {
        (true, true) => said("check-correct-revealed").with("given", given).with("expected", expected),
        (true, false) => said("check-correct"),
        (false, true) => {
            let off = match v.relative_error {
                Some(r) => Msg::new("check-off").num("percent", round_sig(r * 100.0, 5)),
                None => Msg::new("text-nothing"),
            };
            said("check-wrong-revealed").with("given", given).with("expected", expected).with("off", off)
        }
        (false, false) => said("check-wrong").with("given", given),
    }
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
fn slip_text(s: Slip, name: &str, others: &[(String, f64)]) -> Msg {
    match s {
        Slip::OtherValue(i) => {
            let other = others[i].0.trim_start_matches('/');
            Msg::new("check-slip-other-value").arg("other", other).arg("name", name)
        }
        Slip::OppositeSign if name.contains("reactions/") => Msg::new("check-slip-reaction-sign"),
        Slip::OppositeSign => Msg::new("check-slip-sign"),
        Slip::Degrees => Msg::new("check-slip-degrees"),
        Slip::Rpm => Msg::new("check-slip-rpm"),
        Slip::TwoPi { times: true } => Msg::new("check-slip-times-2pi"),
        Slip::TwoPi { times: false } => Msg::new("check-slip-over-2pi"),
        Slip::PowerOfTen(k) => Msg::new("check-slip-power-of-ten").arg("k", k),
    }
}

/// Longest array whose items are each a candidate slip; the items of a
/// longer one (a series over the cycle, a table of steps) are not, unless
/// the answer is in the same item.
const SHORT_LIST: usize = 10;

/// A reference's numbers that may be near an answer, found once for every
/// answer checked against it: those in no item of a long series (an array
/// of more than [`SHORT_LIST`] items). The items of a long series are read
/// only for an answer inside them ([`others`]), so a 12 MB result costs
/// the few numbers of its summary, not its million samples.
pub struct Nearby {
    short: Vec<Number>,
}

/// A number of a result, with its tokens and unit.
struct Number {
    tokens: Vec<String>,
    value: f64,
    unit: Option<String>,
}

impl Nearby {
    pub fn new(kind: &dyn AnyKind, result: &Value) -> Self {
        let mut short = Vec::new();
        numbers(kind, result, result, &mut Vec::new(), &mut short);
        Self { short }
    }
}

/// The numbers under `v` (at `path`) in document order, not going into the
/// items of a long series; a result's `messages` hold none.
fn numbers(kind: &dyn AnyKind, root: &Value, v: &Value, path: &mut Vec<String>, out: &mut Vec<Number>) {
    let mut child = |key: &str, item: &Value, path: &mut Vec<String>| {
        path.push(key.to_string());
        numbers(kind, root, item, path, out);
        path.pop();
    };
    match v {
        Value::Object(map) => {
            let top = path.is_empty();
            map.iter().filter(|(k, _)| !top || *k != "messages").for_each(|(k, item)| child(k, item, path))
        }
        Value::Array(items) if items.len() <= SHORT_LIST => {
            items.iter().enumerate().for_each(|(i, item)| child(&i.to_string(), item, path))
        }
        Value::Array(_) => {}
        Value::Number(n) => {
            let tokens: Vec<&str> = path.iter().map(String::as_str).collect();
            let unit = kind.unit(root, &tokens);
            out.push(Number { tokens: path.clone(), value: n.as_f64().unwrap_or(f64::NAN), unit });
        }
        _ => {}
    }
}

/// The result's other numbers in `unit`, the nearest to `pointer` first:
/// those sharing all but its last two tokens (siblings and cousins, e.g. the
/// other reaction of the same step, `/inertia_approximate` for
/// `/inertia_exact`, `/flywheel_inertia/exact` for it), not inside another
/// item of a long series: a value matched by chance in a table is no slip a
/// student makes. The numbers of the items `pointer` is inside are read here.
pub fn others(nearby: &Nearby, kind: &dyn AnyKind, result: &Value, pointer: &str, unit: &str) -> Vec<(String, f64)> {
    let own = tables::tokens(pointer);
    let mut inside = Vec::new();
    for i in 0..own.len() {
        let long = tables::at(result, &own[..i]).and_then(Value::as_array).is_some_and(|a| a.len() > SHORT_LIST);
        if let Some(item) = tables::at(result, &own[..=i]).filter(|_| long) {
            numbers(kind, result, item, &mut own[..=i].to_vec(), &mut inside);
        }
    }
    let mut near: Vec<((std::cmp::Reverse<usize>, usize), String, f64)> = nearby
        .short
        .iter()
        .chain(&inside)
        .filter(|n| n.unit.as_deref() == Some(unit) && n.value.is_finite() && n.tokens != own)
        .filter_map(|n| {
            let shared = own.iter().zip(&n.tokens).take_while(|(a, b)| a == b).count();
            // Nearest first: most tokens shared, then the same depth (siblings before cousins).
            let rank = (std::cmp::Reverse(shared), n.tokens.len().abs_diff(own.len()));
            (shared + 2 >= own.len().min(n.tokens.len())).then(|| (rank, tables::pointer(&n.tokens), n.value))
        })
        .collect();
    near.sort_by_key(|(rank, ..)| *rank);
    near.into_iter().map(|(_, p, x)| (p, x)).collect()
}

/// A value in a message: its JSON, cut after 60 characters (a whole table is no help).
fn clipped(value: &Value) -> String {
    let text = value.to_string();
    match text.char_indices().nth(60) {
        Some((i, _)) => format!("{}…", &text[..i]),
        None => text,
    }
}
