//! `POST /v1/check`: students' answers checked by the engine. The reference
//! is a template's job for some parameters (or a seeded variant), the job of
//! a request, or a stored job; each answer (a number in SI or `"VALUE
//! UNIT"`) is judged by the tolerance rules of course platforms
//! ([`crate::engine::grading`]) with feedback naming the common slips. The
//! check is itself a job of kind `check`, its result in the service's own
//! format or a platform's results document ([`platforms`]).

pub mod class;
mod items;
mod platforms;
mod run;

pub use platforms::{Gradescope, PrairieLearn};
pub use run::{CHECK, CheckKind, check_job, post};

use crate::i18n::Msg;
use crate::kind::JobResult;
use crate::kind::Table;
use crate::kind::problem::escape;
use crate::kind::problem::{ApiError, FieldError};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::collections::BTreeMap;
use std::sync::OnceLock;
use utoipa::ToSchema;

/// The significant figures a tolerance may ask (the schema's and the query's bounds).
pub const SIGFIGS: std::ops::RangeInclusive<u32> = 1..=15;

/// Most answers in one check.
pub const MAX_ANSWERS: usize = 1000;

/// The body of `POST /v1/check`: one reference (`template`, `kind` with
/// `request`, or `job`) and the answers.
#[derive(Clone, Debug, Default, Deserialize, Serialize, ToSchema)]
#[schema(example = json!({
    "template": "p103-slider-flywheel", "parameters": {"F": 600},
    "answers": {"inertia_exact": "424 kg*m^2", "omega_max": 6.4, "energy_fluctuation": 1100},
    "tolerance": {"relative": 0.01}
}))]
pub struct CheckRequest {
    /// A template's id: the reference is its job for `parameters` (or `variant`).
    #[schema(max_length = 64)]
    pub template: Option<String>,
    /// The template's parameters by name: a number in the parameter's unit, or a quantity (`"300 rpm"`).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(value_type = Option<BTreeMap<String, crate::kind::quantity::Quantity>>)]
    pub parameters: Option<BTreeMap<String, Value>>,
    /// A seeded variant of the template (`GET /v1/templates/{id}/variants` lists them), 0 to 2^63 − 1.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(maximum = 9223372036854775807_u64)]
    pub variant: Option<u64>,
    /// The reference is the job of `request` of this kind.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kind: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(value_type = Option<Object>)]
    pub request: Option<Value>,
    /// The reference is this stored job.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub job: Option<String>,
    /// JSON pointer into the result (the leading `/` optional) → the answer:
    /// a number in SI or `"VALUE UNIT"` (e.g. `"260 slug*ft^2"`).
    #[schema(value_type = BTreeMap<String, crate::kind::quantity::Quantity>)]
    pub answers: BTreeMap<String, Value>,
    /// The answers the score counts (pointers): one missing from `answers`
    /// fails as "no answer", so a student gains nothing by leaving one out.
    /// Default: the answers given.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(max_items = 1000)]
    pub required: Option<Vec<String>>,
    /// For every answer; defaults: relative 0.01, absolute 0, no sigfigs, zero_level 1e-12.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<ToleranceDto>,
    /// Per answer (by its pointer), over `tolerance`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tolerances: Option<BTreeMap<String, ToleranceDto>>,
    /// Whether the feedback shows the expected value and the relative error (default true).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reveal: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub format: Option<CheckFormat>,
}

/// How close an answer must be (every field optional).
///
/// Passes when |given − expected| ≤ `absolute`, or ≤ `relative`·|expected|;
/// with `sigfigs` = n, the relative rule is replaced by PrairieLearn's
/// |given − expected| ≤ 0.51·10^(⌊log10|expected|⌋ − n + 1); when
/// |expected| ≤ `zero_level` (SI), passes iff |given − expected| ≤ `zero_level`.
#[derive(Clone, Copy, Debug, Default, Deserialize, Serialize, ToSchema)]
pub struct ToleranceDto {
    /// E.g. 0.01: within 1 % (353.52 accepts 349.98 to 357.06).
    #[schema(minimum = 0)]
    pub relative: Option<f64>,
    /// In the answer's SI unit, e.g. 0.5 (N·m).
    #[schema(minimum = 0)]
    pub absolute: Option<f64>,
    /// Significant figures, 1 to 15: 3 figures of 0.0004567 accept 0.000457, not 0.000456.
    #[schema(minimum = 1, maximum = 15)]
    pub sigfigs: Option<u32>,
    /// SI; an expected value this small is compared absolutely (a reaction passing through zero).
    #[schema(minimum = 0)]
    pub zero_level: Option<f64>,
}

/// The result's format: the service's own or a platform's results document.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "lowercase")]
pub enum CheckFormat {
    #[default]
    Mechdyn,
    Prairielearn,
    Gradescope,
}

/// One answer judged.
#[derive(Clone, Debug, Serialize, ToSchema)]
pub struct CheckItem {
    /// JSON pointer into the reference result.
    #[schema(example = "/inertia_exact")]
    pub pointer: String,
    /// The answer as given.
    #[schema(value_type = crate::kind::quantity::Quantity)]
    pub answer: Value,
    /// The answer in SI (`unit`); null when it could not be read.
    pub given: Option<f64>,
    /// The reference value in SI; null when `reveal` is false.
    pub expected: Option<f64>,
    /// SI unit of `given` and `expected` (`1`: dimensionless).
    #[schema(example = "kg*m^2")]
    pub unit: String,
    /// |given − expected| / |expected|; null when not revealed or expected is 0.
    pub relative_error: Option<f64>,
    pub pass: bool,
    /// The slip a wrong answer matches: `other_value:/POINTER`, `opposite_sign`,
    /// `degrees`, `rpm`, `times_2pi`, `over_2pi`, `power_of_ten:K`.
    pub slip: Option<String>,
    /// For the student: which quantity, how far off, the slip (in the
    /// asker's language; its message in the result's `messages`).
    pub feedback: String,
    #[serde(skip)]
    pub said: crate::i18n::Msg,
}

/// The result of a check (format `mechdyn`).
#[derive(Clone, Debug, Serialize, ToSchema)]
pub struct CheckResult {
    /// Share of the answers that pass, 0 to 1.
    pub score: f64,
    pub passed: usize,
    pub total: usize,
    pub items: Vec<CheckItem>,
    /// Id of the reference job: in the service's store, readable by anyone
    /// who can reach the API (`reveal` shapes the feedback only); offline,
    /// in that run's store in memory.
    pub job: Option<String>,
    /// The catalogue's message each feedback was written from, by JSON
    /// pointer (`/items/0/feedback`), as a kind's result has them.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    #[schema(value_type = BTreeMap<String, crate::i18n::MessageDoc>)]
    pub messages: BTreeMap<String, crate::i18n::Msg>,
}

/// A check's result in the format asked for.
#[derive(Serialize, ToSchema)]
#[serde(untagged)]
pub enum CheckOutput {
    Mechdyn(CheckResult),
    PrairieLearn(PrairieLearn),
    Gradescope(Gradescope),
}

impl JobResult for CheckOutput {}

impl CheckOutput {
    fn of(c: CheckResult, format: CheckFormat) -> Self {
        match format {
            CheckFormat::Mechdyn => Self::Mechdyn(c),
            CheckFormat::Prairielearn => Self::PrairieLearn(platforms::prairielearn(&c)),
            CheckFormat::Gradescope => Self::Gradescope(platforms::gradescope(&c)),
        }
    }
}

/// `/answers/KEY` and the like, escaped.
fn at(field: &str, key: &str) -> String {
    format!("/{field}/{}", escape(key))
}

/// The pointer of an answer's key, with its leading `/`.
fn pointer(key: &str) -> String {
    format!("/{}", key.trim_start_matches('/'))
}

/// The request's own errors (its reference is checked when it is resolved).
fn validate(r: &CheckRequest) -> Vec<FieldError> {
    let mut errors = Vec::new();
    let sources = [("/template", r.template.is_some()), ("/kind", r.kind.is_some()), ("/job", r.job.is_some())];
    let given: Vec<&str> = sources.iter().filter(|(_, g)| *g).map(|(f, _)| *f).collect();
    match given.as_slice() {
        [] => errors.push(FieldError::said("", Msg::new("check-reference-none"))),
        [_] => {}
        [_, more @ ..] => errors.extend(more.iter().map(|f| FieldError::said(*f, Msg::new("check-reference-more")))),
    }
    if r.kind.is_some() != r.request.is_some() {
        let (f, why) =
            if r.kind.is_some() { ("/request", "check-kind-alone") } else { ("/kind", "check-request-alone") };
        errors.push(FieldError::said(f, Msg::new(why)));
    }
    if r.template.is_none() {
        errors
            .extend(r.parameters.as_ref().map(|_| FieldError::said("/parameters", Msg::new("check-parameters-alone"))));
        errors.extend(r.variant.map(|_| FieldError::said("/variant", Msg::new("check-variant-alone"))));
    }
    if r.variant.is_some_and(|v| v > super::templates::MAX_SEED) {
        errors.push(FieldError::said("/variant", Msg::new("check-variant-range")));
    }
    if r.parameters.is_some() && r.variant.is_some() {
        errors.push(FieldError::said("/variant", Msg::new("check-parameters-and-variant")));
    }
    match r.answers.len() {
        0 => errors.push(FieldError::said("/answers", Msg::new("check-answers-none"))),
        n if n > MAX_ANSWERS => errors.push(FieldError::said(
            "/answers",
            Msg::new("check-answers-too-many").count("max", MAX_ANSWERS).count("count", n),
        )),
        _ => {}
    }
    errors.extend(tolerance_errors(r.tolerance.as_ref(), "/tolerance"));
    let mut answered = std::collections::BTreeSet::new();
    for key in r.answers.keys() {
        if !answered.insert(pointer(key)) {
            let twice = Msg::new("check-answered-twice").arg("pointer", pointer(key));
            errors.push(FieldError::said(at("answers", key), twice));
        }
    }
    if r.required.as_ref().is_some_and(|q| q.len() > MAX_ANSWERS) {
        errors.push(FieldError::said("/required", Msg::new("check-required-too-many").count("max", MAX_ANSWERS)));
    }
    for (key, t) in r.tolerances.iter().flatten() {
        let here = at("tolerances", key);
        if !answered.contains(&pointer(key)) {
            errors.push(FieldError::said(&here, Msg::new("check-tolerance-unanswered")));
        }
        errors.extend(tolerance_errors(Some(t), &here));
    }
    errors
}

fn tolerance_errors(t: Option<&ToleranceDto>, here: &str) -> Vec<FieldError> {
    let Some(t) = t else { return Vec::new() };
    let mut errors = Vec::new();
    for (name, v) in [("relative", t.relative), ("absolute", t.absolute), ("zero_level", t.zero_level)] {
        if v.is_some_and(|v| !(v.is_finite() && v >= 0.0)) {
            errors.push(FieldError::said(format!("{here}/{name}"), Msg::new("field-finite-not-negative")));
        }
    }
    if t.sigfigs.is_some_and(|n| !SIGFIGS.contains(&n)) {
        errors.push(FieldError::said(format!("{here}/sigfigs"), Msg::new("check-sigfigs")));
    }
    errors
}

/// Judges every answer of `r` against `result` (of `kind`, job `job`).
pub fn grade(
    r: &CheckRequest,
    kind: &dyn super::kind::AnyKind,
    result: &Value,
    job: Option<String>,
) -> Result<CheckOutput, ApiError> {
    grade_with(r, kind, result, job, &OnceLock::new())
}

/// [`grade`] with every scalar of the result flattened once for all the
/// checks against it (`flat`, filled when an answer first fails).
pub fn grade_with(
    r: &CheckRequest,
    kind: &dyn super::kind::AnyKind,
    result: &Value,
    job: Option<String>,
    flat: &OnceLock<items::Nearby>,
) -> Result<CheckOutput, ApiError> {
    let reveal = r.reveal.unwrap_or(true);
    let own: BTreeMap<String, &ToleranceDto> = r.tolerances.iter().flatten().map(|(k, t)| (pointer(k), t)).collect();
    let (mut judged, mut errors) = (Vec::new(), Vec::new());
    // A required answer not given is judged as no answer (null); errors at its place in `required`.
    let given: Vec<String> = r.answers.keys().map(|k| pointer(k)).collect();
    let asked = r.answers.iter().map(|(k, v)| (pointer(k), at("answers", k), v));
    let required =
        r.required.iter().flatten().enumerate().map(|(i, k)| (pointer(k), format!("/required/{i}"), &Value::Null));
    let missing: Vec<_> = required.filter(|(p, ..)| !given.contains(p)).collect();
    for (p, here, answer) in asked.chain(missing) {
        match items::expected(kind, result, &p, &here) {
            Err(e) => errors.push(e),
            Ok((e, unit)) => {
                let tolerance = items::tolerance(r.tolerance.as_ref(), own.get(&p).copied());
                let asked = items::Asked { pointer: &p, answer, tolerance };
                let nearby = || flat.get_or_init(|| items::Nearby::new(kind, result));
                let others = || items::others(nearby(), kind, result, &p, &unit);
                judged.push(items::judge(&asked, e, &unit, others, reveal));
            }
        }
    }
    if !errors.is_empty() {
        return Err(ApiError::Invalid(errors));
    }
    let passed = judged.iter().filter(|i| i.pass).count();
    let total = judged.len();
    let messages = judged.iter().enumerate().map(|(i, item)| (format!("/items/{i}/feedback"), item.said.clone()));
    let messages = messages.collect();
    let c = CheckResult { score: passed as f64 / total.max(1) as f64, passed, total, items: judged, job, messages };
    Ok(CheckOutput::of(c, r.format.unwrap_or_default()))
}

/// The table of a stored check (format `mechdyn`): one row per answer.
pub fn table(result: &Value) -> Option<Table> {
    let items = result.get("items")?.as_array()?;
    let columns = ["pointer", "answer", "given", "expected", "unit", "relative_error", "pass", "slip", "feedback"];
    let rows = items
        .iter()
        .map(|i| columns.iter().map(|c| i.get(*c).map_or_else(String::new, crate::kind::cell)).collect())
        .collect();
    Some((columns.iter().map(|c| c.to_string()).collect(), rows))
}
