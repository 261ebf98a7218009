//! A wall-clock compute budget, checked by the long loops of the engine
//! (kinematic sweeps, kinetostatic steps, the flywheel's phases and the
//! machine functions they evaluate), so a job over its budget stops with
//! [`EngineError::BudgetExceeded`] instead of running on.

use super::EngineError;
use std::time::{Duration, Instant};

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

    /// No budget.
    pub fn none() -> Self {
        Self { start: Instant::now(), budget: None }
    }

    /// The budget in seconds (infinite for none).
    pub fn seconds(&self) -> f64 {
        self.budget.map_or(f64::INFINITY, |b| b.as_secs_f64())
    }

    pub fn expired(&self) -> bool {
        self.budget.is_some_and(|b| self.start.elapsed() > b)
    }

    /// `Err(BudgetExceeded)` once expired; `progress` says how far the work got.
    pub fn check(&self, progress: impl FnOnce() -> String) -> Result<(), EngineError> {
        if self.expired() { Err(self.exceeded(progress())) } else { Ok(()) }
    }

    /// The error of this budget, with what was done when it ran out.
    pub fn exceeded(&self, progress: String) -> EngineError {
        EngineError::BudgetExceeded { seconds: self.budget.map_or(f64::INFINITY, |b| b.as_secs_f64()), progress }
    }

    /// `e`, or the budget's error if the budget ran out (a machine function
    /// over budget answers NaN, which would otherwise read as bad input).
    pub fn explain(&self, e: EngineError, progress: impl FnOnce() -> String) -> EngineError {
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
        assert!(matches!(d.check(|| "step 3".into()), Err(EngineError::BudgetExceeded { .. })));
        assert!(Deadline::none().check(String::new).is_ok());
        assert!(!Deadline::after(Duration::from_secs(3600)).expired());
    }
}
