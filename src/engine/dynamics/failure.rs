//! Why a motion cannot be computed, as values: the service words them in
//! the asker's language; `Display` gives the engine's English.

use crate::engine::EngineError;
use crate::engine::numeric::ode::OdeError;

/// Why the motion cannot be computed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DynamicsError {
    #[error("the reduced inertia is not positive at phi = {phi} rad")]
    NonPositiveInertia { phi: f64 },
    #[error("the integration failed at t = {t} s: {reason}")]
    Integration { t: f64, reason: Failure },
    #[error(
        "the compute budget of {seconds} s ran out at t = {t} s of simulated time after {steps} steps; \
         the motion is too fast for the tolerance (a stiff spring?) or the run too long: \
         ask for a shorter run or a looser tolerance"
    )]
    Budget { seconds: f64, t: f64, steps: usize },
    #[error("the initial state cannot be assembled: {reason}")]
    Initial { reason: Start },
}

/// Why the integration failed at a time.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Failure {
    /// The integrator's own failure.
    #[error("{0}")]
    Ode(OdeError),
    /// The equations of motion have no solution there.
    #[error("the equations of motion are singular here (a singular position)")]
    SingularMotion,
}

/// Why the initial state cannot be assembled.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Start {
    /// The mechanism does not close at the initial inputs.
    #[error("{0}")]
    Engine(EngineError),
    #[error("the start is a singular position of the inputs (a dead centre or toggle)")]
    SingularInputs,
    #[error("the mechanism has {dof} degree(s) of freedom but {inputs} input(s) name its coordinates")]
    Dof { dof: usize, inputs: usize },
    #[error(
        "the equations of motion are singular at the start: some motion of the inputs moves no mass \
         (bodies without mass or inertia where the motion needs them)"
    )]
    MovesNoMass,
}
