//! The answers of a template's parts kept in memory: a sheet recalculates
//! every `WEBSERVICE()` cell at once, and each asks for one number of a job
//! already computed. Without this, every GET finds the job by its key, reads
//! its whole result (57 KB for P.103) and parses it for one number; with it,
//! a part asked before costs about what a health check does
//! (docs/BENCHMARKS.md).
//!
//! An answer is keyed by what decides it: the request's key (the template's
//! request with the parameters put in, hashed with the engine's version —
//! so a template stored again under the same name cannot be answered from
//! the old one), the pointer, the unit, the decimal mark and JSON or text.
//! It is bounded by bytes (quick_cache's weighted S3-FIFO), so memory stays
//! bounded under any mix of parameters.

use bytes::Bytes;
use quick_cache::Weighter;
use quick_cache::sync::Cache;

/// What decides a part's answer.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct PartKey {
    /// The request's key ([`super::apply::keyed`]).
    pub request: String,
    pub pointer: String,
    pub unit: Option<String>,
    pub decimal: bool,
    pub json: bool,
    /// A text part (a warning) is said in the asker's language.
    pub lang: crate::i18n::Lang,
}

/// A part's answer: its content type and body.
pub type Answer = (&'static str, Bytes);

/// Default bound of the answers kept, bytes.
pub const DEFAULT_BYTES: u64 = 8 << 20;

#[derive(Clone)]
struct BySize;

impl Weighter<PartKey, Answer> for BySize {
    fn weight(&self, key: &PartKey, answer: &Answer) -> u64 {
        let unit = key.unit.as_ref().map_or(0, String::len);
        (key.request.len() + key.pointer.len() + unit + answer.1.len() + 96) as u64
    }
}

/// The answers kept, shared by every handler of a replica.
#[derive(Clone)]
pub struct Answers(std::sync::Arc<Cache<PartKey, Answer, BySize>>);

impl Default for Answers {
    fn default() -> Self {
        Self::with_bytes(DEFAULT_BYTES)
    }
}

impl Answers {
    /// At most `bytes` of keys and answers kept.
    pub fn with_bytes(bytes: u64) -> Self {
        let items = (bytes / 256).max(16) as usize;
        Self(std::sync::Arc::new(Cache::with_weighter(items, bytes, BySize)))
    }

    pub fn get(&self, key: &PartKey) -> Option<Answer> {
        self.0.get(key)
    }

    pub fn keep(&self, key: PartKey, answer: Answer) {
        self.0.insert(key, answer);
    }

    /// Bytes held now (keys and answers), for tests and metrics.
    pub fn weight(&self) -> u64 {
        self.0.weight()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// However many parts are asked, the answers kept stay within their bound.
    #[test]
    fn the_answers_kept_are_bounded_by_bytes() {
        let answers = Answers::with_bytes(64 << 10);
        for i in 0..10_000 {
            let key = PartKey {
                request: format!("{i:064}"),
                pointer: "inertia_exact".into(),
                unit: None,
                decimal: false,
                json: false,
                lang: crate::i18n::Lang::En,
            };
            answers.keep(key, ("text/plain; charset=utf-8", Bytes::from(format!("{}", i as f64 * 0.1))));
        }
        assert!(answers.weight() <= 64 << 10, "{} bytes", answers.weight());
        assert!(answers.weight() > 32 << 10, "the bound is used: {} bytes", answers.weight());
    }
}
