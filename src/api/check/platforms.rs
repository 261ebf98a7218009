//! A check's result as a course platform's results document, so that an
//! external grader writes it as it is:
//! - PrairieLearn's external grader `results.json`: `gradable`, `score`
//!   (0 to 1), `message`, `output`, `tests` (`name`, `description`,
//!   `points`, `max_points`, `message`, `output`);
//! - Gradescope's autograder `results.json`: `score` and `max_score` (points),
//!   `output`, `visibility`, `stdout_visibility`, `tests` (`name`, `number`,
//!   `score`, `max_score`, `status` passed|failed, `output`, `visibility`).
//!
//! Each answer is one test worth one point. The texts are in the asker's
//! language; `messages` (mechdyn's, which the platforms ignore) names the
//! catalogue's message of each.

use super::CheckResult;
use crate::i18n::{Lang, Msg};
use serde::Serialize;
use std::collections::BTreeMap;
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
    /// mechdyn's: the message each text was written from, by JSON pointer
    /// (a platform ignores it; the texts are in the asker's language).
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    #[schema(value_type = BTreeMap<String, crate::i18n::MessageDoc>)]
    pub messages: BTreeMap<String, Msg>,
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
    /// As [`PrairieLearn::messages`].
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    #[schema(value_type = BTreeMap<String, crate::i18n::MessageDoc>)]
    pub messages: BTreeMap<String, Msg>,
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
fn summary(c: &CheckResult) -> Msg {
    Msg::new("check-summary")
        .count("passed", c.passed)
        .count("total", c.total)
        .arg("version", env!("CARGO_PKG_VERSION"))
}

/// The messages of a platform's document: the summary at `summary`, each
/// answer's feedback at `/tests/N/{feedback}`.
fn messages(c: &CheckResult, summary_at: &str, feedback: &str) -> BTreeMap<String, Msg> {
    let each = c.items.iter().enumerate().map(|(n, i)| (format!("/tests/{n}/{feedback}"), i.said.clone()));
    each.chain([(summary_at.to_string(), summary(c))]).collect()
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
    PrairieLearn {
        gradable: true,
        score: c.score,
        message: summary(c).render(Lang::En),
        output: String::new(),
        tests,
        messages: messages(c, "/message", "message"),
    }
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
        output: summary(c).render(Lang::En),
        visibility: "visible",
        stdout_visibility: "hidden",
        tests,
        messages: messages(c, "/output", "output"),
    }
}
