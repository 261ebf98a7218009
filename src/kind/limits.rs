//! What one request may ask, each limit configurable (flags and environment
//! variables in `config.rs`); beyond a limit the request is refused 422 with
//! a pointer to the field, and a job over its compute budget is stopped.
//! The OpenAPI document states the defaults.

use crate::engine::Deadline;
use std::time::{Duration, Instant};

/// Deepest expression nesting that may be configured: the parser recurses
/// once per level, on the blocking pool's 2 MiB thread stacks.
pub const MAX_EXPRESSION_DEPTH: usize = 256;

/// Limits on one request (sent with each job to the worker that computes
/// it, its start left out: the budget counts from the worker's start).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Limits {
    /// Wall-clock compute budget of a job.
    pub budget: Duration,
    /// Input positions of a kinetostatics job.
    pub steps: usize,
    /// Result samples of a flywheel or dynamics job.
    pub samples: usize,
    /// Rows of a table function.
    pub table_rows: usize,
    /// Segments of a piecewise function.
    pub segments: usize,
    /// Characters of an expression.
    pub expression_length: usize,
    /// Levels of nesting of an expression (at most [`MAX_EXPRESSION_DEPTH`]).
    pub expression_depth: usize,
    /// Bytes of a job's result as JSON (and of a page of the jobs list).
    pub result_bytes: usize,
    /// When the job's computation began (its budget counts from then); None
    /// until [`Limits::started`].
    #[serde(skip)]
    pub started: Option<Instant>,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            budget: Duration::from_secs(20),
            steps: 100_000,
            samples: 100_000,
            table_rows: 100_000,
            segments: 1_000,
            expression_length: 2_000,
            expression_depth: 64,
            result_bytes: 16 << 20,
            started: None,
        }
    }
}

impl Limits {
    /// These limits for a job that begins now (or began already: a check's
    /// reference computes within the check's budget).
    pub fn started(&self) -> Self {
        Self { started: Some(self.started.unwrap_or_else(Instant::now)), ..self.clone() }
    }

    /// The last step or sample any job may have (a drawing's `?step=` at most).
    pub fn last_step(&self) -> usize {
        self.steps.max(self.samples).saturating_sub(1)
    }

    /// The job's budget from its start: every conversion and engine loop reads it.
    pub fn deadline(&self) -> Deadline {
        Deadline::from(self.started.unwrap_or_else(Instant::now), self.budget)
    }
}
