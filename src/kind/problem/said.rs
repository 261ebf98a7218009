//! What each error says (its problem document's `detail`), as a message of
//! the catalogue; in English it is also the error's `Display`.

use super::ApiError;
use crate::i18n::{Lang, Msg};
use crate::store::Status;

impl ApiError {
    /// The detail of this error as the catalogue says it.
    pub fn msg(&self) -> Msg {
        match self {
            Self::MalformedJson(why) => Msg::new("detail-malformed-json").with("why", why.clone()),
            Self::UnsupportedMediaType => Msg::new("detail-unsupported-media-type"),
            Self::UnsupportedTable => Msg::new("detail-unsupported-table"),
            Self::PayloadTooLarge(limit) => Msg::new("detail-payload-too-large").arg("limit", limit),
            Self::Invalid(errors) => Msg::new("detail-invalid").count("count", errors.len()),
            Self::BadQuery(_) => Msg::new("detail-bad-query"),
            Self::BadTable(errors) => Msg::new("detail-bad-table").count("count", errors.len()),
            Self::NotFound(id) => Msg::new("detail-not-found").arg("id", id),
            Self::NoPart { id, pointer } => Msg::new("detail-no-part").arg("id", id).arg("pointer", pointer),
            Self::NoPlot { id, name, known } => listed("detail-no-plot", "detail-no-plot-none", id, name, known),
            Self::NoFile { id, name, known } => listed("detail-no-file", "detail-no-file-none", id, name, known),
            Self::NoSolution { id, kind } => Msg::new("detail-no-solution").arg("id", id).arg("kind", kind),
            Self::NoTemplate(id) => Msg::new("detail-no-template").arg("id", id),
            Self::Conflict(why) | Self::OverBudget(why) | Self::RequestTimeout(why) => why.clone(),
            Self::InProgress(key) => Msg::new("detail-in-progress").arg("key", key),
            Self::NotDone { id, status: Status::Failed } => Msg::new("detail-failed").arg("id", id),
            Self::NotDone { id, status } => Msg::new("detail-not-done").arg("id", id).arg("status", status.as_str()),
            Self::Interrupted(times) => Msg::new("detail-interrupted").arg("times", times),
            Self::NoRoute => Msg::new("detail-no-route"),
            Self::MethodNotAllowed => Msg::new("detail-method-not-allowed"),
            Self::ResultTooLarge { limit, .. } => Msg::new("detail-result-too-large").arg("limit", limit),
            Self::Saturated { reason, retry_after } => {
                Msg::new("detail-saturated").with("reason", reason.clone()).arg("seconds", retry_after)
            }
            Self::StorageFull(what) => Msg::new("detail-storage-full").arg("what", what),
            Self::Unavailable(_) => Msg::new("detail-unavailable"),
            Self::Unauthorized => Msg::new("detail-unauthorized"),
            Self::PrivateJobs => Msg::new("detail-private-jobs"),
            Self::LengthRequired => Msg::new("detail-length-required"),
            Self::Internal(_) => Msg::new("detail-internal"),
            Self::JobMemory(limit) => Msg::new("detail-job-memory").num("mib", (*limit as f64 / 1048576.0).round()),
            Self::ComputeFailed => Msg::new("detail-compute-failed"),
        }
    }
}

/// "job 'j' has no plot 'p' (its plots: a, b)", or "(it has none)".
fn listed(some: &'static str, none: &'static str, id: &str, name: &str, known: &[String]) -> Msg {
    let msg = if known.is_empty() { Msg::new(none) } else { Msg::new(some).arg("known", known.join(", ")) };
    msg.arg("id", id).arg("name", name)
}

impl std::fmt::Display for ApiError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.msg().render(Lang::En))
    }
}

impl std::error::Error for ApiError {}
