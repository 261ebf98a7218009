//! A run the engine cannot make, as the answer: a 422 at the field it
//! comes from in the catalogue's words, or a spent budget.

use crate::engine::dynamics::{DynamicsError, Failure, Start};
use crate::engine::numeric::ode::OdeError;
use crate::i18n::Msg;
use crate::kind::problem::{ApiError, FieldError};
use crate::kind::refused::engine_msg;

/// A failed integration as a 422 at the field it comes from; a spent budget
/// as such, naming the 8th-order method where the 5th-order one ran.
pub(super) fn invalid(e: DynamicsError, dopri5: bool) -> ApiError {
    let pointer = match e {
        DynamicsError::NonPositiveInertia { .. } => "/reduced_inertia",
        DynamicsError::Initial { .. } => "/machine/input",
        DynamicsError::Budget { seconds, t, steps } => {
            let hint = if dopri5 { "dynamics-budget-dop853" } else { "text-nothing" };
            let said = Msg::new("dynamics-budget").num("seconds", seconds).fig("t", t).count("steps", steps);
            return ApiError::OverBudget(said.with("hint", Msg::new(hint)));
        }
        DynamicsError::Integration { .. } => "",
    };
    ApiError::Invalid(vec![FieldError::said(pointer, msg(&e))])
}

/// A dynamics error as the catalogue says it, its reason too (the time of
/// a failed integration said once, to four significant figures).
fn msg(e: &DynamicsError) -> Msg {
    match e {
        DynamicsError::NonPositiveInertia { phi } => Msg::new("dynamics-inertia-not-positive").num("phi", *phi),
        DynamicsError::Integration { t, reason } => {
            Msg::new("dynamics-integration").fig("t", *t).with("reason", failure(reason))
        }
        // Answered as a spent budget, never as a field's error.
        DynamicsError::Budget { .. } => Msg::new("text-as-is").arg("why", e),
        DynamicsError::Initial { reason } => Msg::new("dynamics-initial").with("reason", start(reason)),
    }
}

fn failure(reason: &Failure) -> Msg {
    match reason {
        Failure::Ode(OdeError::StepTooSmall { .. }) => Msg::new("dynamics-step-too-small"),
        Failure::Ode(OdeError::TooManySteps { steps }) => Msg::new("dynamics-too-many-steps").count("steps", *steps),
        Failure::Ode(OdeError::NotFinite { .. }) => Msg::new("dynamics-not-finite"),
        Failure::SingularMotion => Msg::new("dynamics-singular-motion"),
    }
}

fn start(reason: &Start) -> Msg {
    match reason {
        Start::Engine(e) => engine_msg(e),
        Start::SingularInputs => Msg::new("dynamics-start-singular"),
        Start::Dof { dof, inputs } => Msg::new("dynamics-start-dof").count("dof", *dof).count("inputs", *inputs),
        Start::MovesNoMass => Msg::new("dynamics-start-no-mass"),
    }
}
