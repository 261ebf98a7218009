//! Positions a mechanism cannot reach, said in the user's own terms: the
//! input value in the unit the request wrote it in, the step, and a pointer
//! to the field that asked for it (`/input/start` for the first position,
//! `/input/end` for one further along the range).

use crate::engine::EngineError;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::quantity::Quantity;
use crate::kind::{engine_error, engine_failure};
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
        Self { at, unit, steps: positions.len(), start }
    }

    /// `value` (SI) in the written unit, to 6 significant digits; radians
    /// also in degrees.
    pub fn value(&self, si: f64) -> String {
        let shown = format!("{} {}", six_digits(si / self.unit.1), self.unit.0);
        if self.unit.0 == "rad" { format!("{shown} = {} deg", six_digits(si.to_degrees())) } else { shown }
    }

    /// [`Self::value`] as a message, for a warning in the asker's language.
    pub fn said(&self, si: f64) -> crate::i18n::Msg {
        let six = |v: f64| six_digits(v).parse().unwrap_or(v);
        let value = six(si / self.unit.1);
        match self.unit.0 == "rad" {
            true => crate::i18n::Msg::new("warning-at-angle").num("value", value).num("degrees", six(si.to_degrees())),
            false => crate::i18n::Msg::new("warning-at-value").num("value", value).arg("unit", &self.unit.0),
        }
    }

    /// An engine error as the answer, positions quoted as written.
    pub fn explain(&self, e: EngineError) -> ApiError {
        let (step, input, head, tail) = match &e {
            EngineError::NewtonDiverged { step, input, residual, joint } => (
                *step,
                *input,
                "the mechanism cannot be assembled",
                format!(
                    "the loop through {joint} does not close (Newton-Raphson ends {residual:.1e} short); check \
                     start, end and the lengths (a non-Grashof crank, say, cannot make a full turn)"
                ),
            ),
            EngineError::Singular { step, input } => (
                *step,
                *input,
                "the mechanism is at a singular position",
                "a dead centre or toggle the input cannot pass (the constraint Jacobian loses rank)".into(),
            ),
            EngineError::FrictionDiverged { step, input } => (
                *step,
                *input,
                "joint friction does not settle",
                "the friction coefficients are too large for the mechanism to be driven there (self-locking)".into(),
            ),
            EngineError::Unactuated { step, input, actuators } => (
                *step,
                *input,
                "the actuators cannot drive the inputs",
                format!(
                    "moving the inputs does not move {actuators} there, so its effort would be carried by the \
                     joints; name in \"actuators\" a joint the input's motion moves"
                ),
            ),
            EngineError::Locked { .. } => return ApiError::Invalid(vec![engine_error(e, "/mechanism")]),
            _ => return engine_failure(e, &self.at),
        };
        let (field, which) = if step == 0 { ("start", ", the start") } else { ("end", "") };
        let pointer = match e {
            EngineError::Unactuated { .. } => "/actuators".to_string(),
            _ => format!("{}/{field}", self.at),
        };
        let at = if step == 0 { self.start } else { input };
        let mut message =
            format!("{head} at input {} (step {} of {}{which}): {tail}", self.value(at), step + 1, self.steps);
        if step == 0 && input != self.start {
            message += &format!(
                "; on the way there from the drawn configuration (input \"reference\") it stops closing at {}",
                self.value(input)
            );
        }
        ApiError::Invalid(vec![FieldError::at(pointer, message)])
    }
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
