//! Why the engine cannot answer a problem (a mechanism, a cycle), as the catalogue
//! says it: its errors' variants, each a message with its numbers.

use crate::engine::variants::round_sig;
use crate::engine::{EngineError, Phase, Progress};
use crate::i18n::Msg;

/// An error of the engine (a mechanism that cannot be moved, a function
/// out of range) as the catalogue says it.
pub fn engine_msg(e: &EngineError) -> Msg {
    match e {
        EngineError::NotFinite { function, phi } => {
            Msg::new("mechanism-not-finite").arg("function", function).num("phi", *phi)
        }
        EngineError::NegativeInertia { function, phi, value } => {
            Msg::new("mechanism-negative-inertia").arg("function", function).num("value", *value).num("phi", *phi)
        }
        EngineError::NotSteady { net_work, largest_area } => {
            Msg::new("mechanism-not-steady").num("net_work", *net_work).num("largest_area", *largest_area)
        }
        EngineError::NewtonDiverged { step, input, residual, joint } => Msg::new("mechanism-newton")
            .num("input", *input)
            .arg("step", step)
            .arg("joint", joint)
            .num("residual", round_sig(*residual, 2)),
        EngineError::Locked { grubler } => Msg::new("mechanism-locked").arg("grubler", grubler),
        EngineError::Singular { step, input } => Msg::new("mechanism-singular").arg("step", step).num("input", *input),
        EngineError::SingularCycle { input, count } => {
            Msg::new("mechanism-singular-cycle").num("input", *input).count("count", *count)
        }
        EngineError::DofMismatch { dof, inputs } => {
            Msg::new("mechanism-dof").count("dof", *dof).count("inputs", *inputs)
        }
        EngineError::FrictionDiverged { step, input, limit } => {
            Msg::new("mechanism-friction").num("input", *input).arg("step", step).written("percent", percent(*limit))
        }
        EngineError::Unactuated { step, input, actuators } => {
            Msg::new("mechanism-unactuated").arg("actuators", actuators).num("input", *input).arg("step", step)
        }
        EngineError::NotFiniteResult => Msg::new("mechanism-not-finite-result"),
        // Answered as a spent budget, never as a field's error.
        EngineError::BudgetExceeded { seconds, progress } => budget_msg(*seconds, progress),
    }
}

/// A fraction as a percentage to one decimal (`96.0`; `Msg::written`
/// gives it the language's decimal mark).
pub fn percent(fraction: f64) -> String {
    format!("{:.1}", 100.0 * fraction)
}

/// A spent compute budget: its seconds, and how far the engine had got.
fn budget_msg(seconds: f64, progress: &Progress) -> Msg {
    Msg::new("detail-over-budget").num("seconds", seconds).with("progress", progress_msg(progress))
}

fn progress_msg(progress: &Progress) -> Msg {
    let phase = |p: &Phase| match p {
        Phase::Sampling => "progress-flywheel-sampling",
        Phase::Work => "progress-flywheel-work",
        Phase::Crossings => "progress-flywheel-crossings",
        Phase::Exact => "progress-flywheel-exact",
        Phase::TimeCheck => "progress-flywheel-time-check",
        Phase::Table => "progress-flywheel-table",
    };
    match progress {
        Progress::Flywheel(p) => Msg::new(phase(p)),
        Progress::Late => Msg::new("progress-late"),
        Progress::AssemblingMachine => Msg::new("progress-assembling-machine"),
        Progress::Assembled { step, of } => Msg::new("progress-assembled").count("step", *step).count("of", *of),
        Progress::Candidates { joint, of } => Msg::new("progress-candidates").count("joint", *joint).count("of", *of),
        Progress::CamSize { tried } => Msg::new("progress-cam-size").count("tried", *tried),
        Progress::Reading => Msg::new("progress-reading"),
        Progress::Friction { step } => Msg::new("progress-friction").count("step", *step),
        Progress::Approach { step, of } => Msg::new("progress-approach").count("step", *step).count("of", *of),
        Progress::CamLift { angle, of } => Msg::new("progress-cam-lift").count("angle", *angle).count("of", *of),
    }
}
