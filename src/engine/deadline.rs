//! A wall-clock compute budget, checked by the long loops of the engine
//! (kinematic sweeps, kinetostatic steps, the flywheel's phases and the
//! machine functions they evaluate), so a job over its budget stops with
//! [`EngineError::BudgetExceeded`] instead of running on, saying how far it
//! got ([`Progress`], a value the service words in the asker's language).

use super::EngineError;
use std::fmt;
use std::time::{Duration, Instant};

/// How far a computation had got when its budget ran out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Progress {
    /// The flywheel's solution, stopped in this phase.
    Flywheel(Phase),
    /// The flywheel's solution, complete but past the budget.
    Late,
    /// A flywheel's machine (its reduced values from a mechanism) being assembled.
    AssemblingMachine,
    /// A kinematic sweep: the mechanism assembled at `step` of `of` positions.
    Assembled { step: usize, of: usize },
    /// A mechanism's candidate inputs: the joint reached, of those that can drive it.
    Candidates { joint: usize, of: usize },
    /// A cam's smallest base radius: the radii tried so far.
    CamSize { tried: usize },
    /// The mechanism moved from its drawing towards the first position: `step` of `of`.
    Approach { step: usize, of: usize },
    /// The friction of the joints iterated at position `step`.
    Friction { step: usize },
    /// A cam's lift evaluated at `angle` of `of` angles.
    CamLift { angle: usize, of: usize },
    /// The request was being read (a sketch assembled, contacts placed, inputs laid out).
    Reading,
}

/// The phases of the flywheel's solution, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// Sampling M* and I* over the cycle.
    Sampling,
    /// Integrating the work of each torque.
    Work,
    /// Locating the crossings and lobes of M*.
    Crossings,
    /// Finding the exact (Wittenbauer) inertia.
    Exact,
    /// Checking by time integration.
    TimeCheck,
    /// Sampling the table.
    Table,
}

impl fmt::Display for Progress {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let phase = |p: &Phase| match p {
            Phase::Sampling => "sampling M* and I*",
            Phase::Work => "integrating the work of each torque",
            Phase::Crossings => "locating the crossings and lobes of M*",
            Phase::Exact => "finding the exact inertia",
            Phase::TimeCheck => "checking by time integration",
            Phase::Table => "sampling the table",
        };
        match self {
            Self::Flywheel(p) => write!(f, "stopped while {}", phase(p)),
            Self::Late => f.write_str("the solution was complete but late"),
            Self::AssemblingMachine => f.write_str("while assembling the machine"),
            Self::Assembled { step, of } => write!(f, "the mechanism was assembled at {step} of {of} positions"),
            Self::Candidates { joint, of } => write!(f, "the inputs were sought at joint {joint} of {of}"),
            Self::CamSize { tried } => write!(f, "{tried} base radii had been tried"),
            Self::Approach { step, of } => write!(f, "the mechanism had moved {step} of {of} steps from its drawing"),
            Self::Friction { step } => write!(f, "the friction was being iterated at position {step}"),
            Self::CamLift { angle, of } => write!(f, "the lift had been evaluated at {angle} of {of} angles"),
            Self::Reading => f.write_str("while the request was being read"),
        }
    }
}

/// When a computation must stop; [`Deadline::none`] never expires.
#[derive(Clone, Copy, Debug)]
pub struct Deadline {
    start: Instant,
    budget: Option<Duration>,
}

impl Deadline {
    /// A budget counted from now.
    pub fn after(budget: Duration) -> Self {
        Self { start: Instant::now(), budget: Some(budget) }
    }

    /// A budget counted from `start`.
    pub fn from(start: Instant, budget: Duration) -> Self {
        Self { start, budget: Some(budget) }
    }

    /// No budget.
    pub fn none() -> Self {
        Self { start: Instant::now(), budget: None }
    }

    /// The budget in seconds (infinite for none).
    pub fn seconds(&self) -> f64 {
        self.budget.map_or(f64::INFINITY, |b| b.as_secs_f64())
    }

    /// Seconds since the budget's start.
    pub fn elapsed(&self) -> f64 {
        self.start.elapsed().as_secs_f64()
    }

    pub fn expired(&self) -> bool {
        self.budget.is_some_and(|b| self.start.elapsed() > b)
    }

    /// `Err(BudgetExceeded)` once expired; `progress` says how far the work got.
    pub fn check(&self, progress: impl FnOnce() -> Progress) -> Result<(), EngineError> {
        if self.expired() { Err(self.exceeded(progress())) } else { Ok(()) }
    }

    /// The error of this budget, with what was done when it ran out.
    pub fn exceeded(&self, progress: Progress) -> EngineError {
        EngineError::BudgetExceeded { seconds: self.budget.map_or(f64::INFINITY, |b| b.as_secs_f64()), progress }
    }

    /// `e`, or the budget's error if the budget ran out (a machine function
    /// over budget answers NaN, which would otherwise read as bad input).
    pub fn explain(&self, e: EngineError, progress: impl FnOnce() -> Progress) -> EngineError {
        if self.expired() { self.exceeded(progress()) } else { e }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_zero_budget_expires_and_none_never_does() {
        let d = Deadline::after(Duration::ZERO);
        std::thread::sleep(Duration::from_millis(1));
        let late = d.check(|| Progress::Late);
        assert!(matches!(late, Err(EngineError::BudgetExceeded { progress: Progress::Late, .. })));
        assert!(Deadline::none().check(|| Progress::Late).is_ok());
        assert!(!Deadline::after(Duration::from_secs(3600)).expired());
    }
}
