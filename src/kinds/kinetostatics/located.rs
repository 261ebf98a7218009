//! Positions a mechanism cannot reach, said in the user's own terms: the
//! input value in the unit the request wrote it in, the step, and a pointer
//! to the field that asked for it (`/input/start` for the first position,
//! `/input/end` for one further along the range).

use crate::engine::EngineError;
use crate::engine::variants::round_sig;
use crate::i18n::Msg;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::Quantity;
use crate::kind::refused::{engine_msg, percent};
use crate::kinds::mechanism::InputDto;
use crate::units::{self, Dim};

/// How the first input was written: where it is and in which unit.
#[derive(Clone, Debug)]
pub struct Written {
    /// Pointer of the input object (`/input` or `/input/0`).
    pub at: String,
    /// The unit of its `start` (or `end`) as written, with its SI factor.
    pub unit: (String, f64),
    pub steps: usize,
    /// The first position, SI.
    pub start: f64,
    /// The input is a length (a slider's, a point's, an arc's).
    pub prismatic: bool,
}

impl Written {
    pub fn new(input: Option<&InputDto>, at: String, prismatic: bool, positions: &[Vec<[f64; 3]>]) -> Self {
        let dim = if prismatic { Dim::LENGTH } else { Dim::ANGLE };
        let si = if prismatic { "m" } else { "rad" };
        let unit = input
            .into_iter()
            .flat_map(|i| [&i.start, &i.end])
            .flatten()
            .find_map(|q| written_unit(q, dim))
            .unwrap_or_else(|| (si.to_string(), 1.0));
        let start = positions.first().and_then(|p| p.first()).map_or(0.0, |i| i[0]);
        Self { at, unit, steps: positions.len(), start, prismatic }
    }

    /// `si` in the written unit, to 6 significant digits (radians also in
    /// degrees), as the catalogue says it, its numbers in the asker's language.
    pub fn said(&self, si: f64) -> Msg {
        let shown = |v: f64| six_digits(v).parse().unwrap_or(v);
        match self.unit.0.as_str() {
            "rad" => Msg::new("kinetostatics-value-rad").num("value", shown(si)).num("degrees", shown(si.to_degrees())),
            unit => Msg::new("text-value-unit").num("value", shown(si / self.unit.1)).arg("unit", unit),
        }
    }

    /// An engine error as the answer, positions quoted as written.
    pub fn explain(&self, e: EngineError) -> ApiError {
        let (step, input, what, why) = match &e {
            EngineError::NewtonDiverged { step, input, residual, joint } => (
                *step,
                *input,
                "kinetostatics-not-assembled",
                Msg::new("kinetostatics-loop").arg("joint", joint).num("residual", round_sig(*residual, 2)).with(
                    "why",
                    Msg::new(if self.prismatic { "kinetostatics-loop-slider" } else { "kinetostatics-loop-crank" }),
                ),
            ),
            EngineError::Singular { step, input } => {
                (*step, *input, "kinetostatics-singular", Msg::new("kinetostatics-dead-centre"))
            }
            EngineError::FrictionDiverged { step, input, limit } => (
                *step,
                *input,
                "kinetostatics-friction",
                Msg::new("kinetostatics-self-locking").written("percent", percent(*limit)),
            ),
            EngineError::Unactuated { step, input, actuators } => (
                *step,
                *input,
                "kinetostatics-unactuated",
                Msg::new("kinetostatics-unactuated-why").arg("actuators", actuators),
            ),
            EngineError::BudgetExceeded { .. } => return ApiError::OverBudget(engine_msg(&e)),
            EngineError::Locked { .. } => return ApiError::Invalid(vec![refused(&e, "/mechanism")]),
            _ => return ApiError::Invalid(vec![refused(&e, &self.at)]),
        };
        let (field, id) = if step == 0 { ("start", "kinetostatics-at-start") } else { ("end", "kinetostatics-at") };
        let pointer = match e {
            EngineError::Unactuated { .. } => "/actuators".to_string(),
            _ => format!("{}/{field}", self.at),
        };
        let at = if step == 0 { self.start } else { input };
        let mut msg = Msg::new(id)
            .with("what", Msg::new(what))
            .with("value", self.said(at))
            .arg("step", step + 1)
            .arg("steps", self.steps)
            .with("why", why);
        if step == 0 && input != self.start {
            msg = Msg::new("kinetostatics-on-the-way").with("said", msg).with("value", self.said(input));
        }
        ApiError::Invalid(vec![FieldError::said(pointer, msg)])
    }
}

/// An engine error without a position of its own as a field error: at the
/// function it names, else at `fallback`.
fn refused(e: &EngineError, fallback: &str) -> FieldError {
    let pointer = match e {
        EngineError::NotFinite { function, .. } | EngineError::NegativeInertia { function, .. } => function.clone(),
        EngineError::NotFiniteResult => String::new(),
        _ => fallback.to_string(),
    };
    FieldError::said(pointer, engine_msg(e))
}

/// A number to 6 significant digits, without trailing zeros.
fn six_digits(v: f64) -> String {
    let decimals = 5usize.saturating_sub(v.abs().log10().floor().max(0.0) as usize);
    let digits = format!("{v:.decimals$}");
    if digits.contains('.') { digits.trim_end_matches('0').trim_end_matches('.').to_string() } else { digits }
}

/// The unit of a quantity string, when it is one of dimension `dim`.
fn written_unit(q: &Quantity, dim: Dim) -> Option<(String, f64)> {
    let Quantity::Text(s) = q else { return None };
    let number = units::parse_quantity(s).ok()?;
    let unit = s.trim().trim_start_matches(|c: char| c.is_ascii_digit() || "+-.eE".contains(c)).trim();
    let factor = units::unit_factor(unit, dim).ok()?;
    (number.dim == dim && !unit.is_empty()).then(|| (unit.to_string(), factor))
}
