//! A check's result as a course platform's results document, so that an
//! external grader writes it as it is:
//! - PrairieLearn's external grader `results.json`: `gradable`, `score`
//!   (0 to 1), `message`, `output`, `tests` (`name`, `description`,
//!   `points`, `max_points`, `message`, `output`);
//! - Gradescope's autograder `results.json`: `score` and `max_score` (points),
//!   `output`, `visibility`, `stdout_visibility`, `tests` (`name`, `number`,
//!   `score`, `max_score`, `status` passed|failed, `output`, `visibility`).
//!
//! Each answer is one test worth one point.

use super::CheckResult;
use serde::Serialize;
use utoipa::ToSchema;

/// PrairieLearn's external-grader results document.
#[derive(Serialize, ToSchema)]
pub struct PrairieLearn {
    /// Whether the submission could be graded (false: a format error, no points).
    pub gradable: bool,
    /// Share of the points earned, 0 to 1.
    pub score: f64,
    /// Shown to the student above the tests.
    pub message: String,
    pub output: String,
    pub tests: Vec<PrairieLearnTest>,
}

#[derive(Serialize, ToSchema)]
pub struct PrairieLearnTest {
    /// The answer's pointer into the result.
    pub name: String,
    pub description: String,
    pub points: f64,
    pub max_points: f64,
    /// The answer's feedback.
    pub message: String,
    pub output: String,
}

/// Gradescope's autograder results document.
#[derive(Serialize, ToSchema)]
pub struct Gradescope {
    /// Points earned (one per answer that passes).
    pub score: f64,
    pub max_score: f64,
    pub output: String,
    /// `visible`: the student sees the tests at once.
    pub visibility: &'static str,
    pub stdout_visibility: &'static str,
    pub tests: Vec<GradescopeTest>,
}

#[derive(Serialize, ToSchema)]
pub struct GradescopeTest {
    pub name: String,
    /// "1", "2", ...: the answers' order.
    pub number: String,
    pub score: f64,
    pub max_score: f64,
    /// `passed` or `failed`.
    pub status: &'static str,
    /// The answer's feedback.
    pub output: String,
    pub visibility: &'static str,
}

/// The summary line of a check.
fn summary(c: &CheckResult) -> String {
    format!("{} of {} answers within tolerance (checked by mechdyn {}).", c.passed, c.total, env!("CARGO_PKG_VERSION"))
}

pub fn prairielearn(c: &CheckResult) -> PrairieLearn {
    let tests = c
        .items
        .iter()
        .map(|i| PrairieLearnTest {
            name: i.pointer.clone(),
            description: format!("{} ({})", i.pointer.trim_start_matches('/'), i.unit),
            points: if i.pass { 1.0 } else { 0.0 },
            max_points: 1.0,
            message: i.feedback.clone(),
            output: String::new(),
        })
        .collect();
    PrairieLearn { gradable: true, score: c.score, message: summary(c), output: String::new(), tests }
}

pub fn gradescope(c: &CheckResult) -> Gradescope {
    let tests = c
        .items
        .iter()
        .enumerate()
        .map(|(n, i)| GradescopeTest {
            name: i.pointer.clone(),
            number: (n + 1).to_string(),
            score: if i.pass { 1.0 } else { 0.0 },
            max_score: 1.0,
            status: if i.pass { "passed" } else { "failed" },
            output: i.feedback.clone(),
            visibility: "visible",
        })
        .collect();
    Gradescope {
        score: c.passed as f64,
        max_score: c.total as f64,
        output: summary(c),
        visibility: "visible",
        stdout_visibility: "hidden",
        tests,
    }
}
