//! The retention of stored jobs: a task that deletes, at start and then at
//! every interval, the jobs older than the maximum age and those beyond the
//! newest maximum count (either or both may be set; neither: every job is
//! kept). Several replicas on one database may each run it: a sweep
//! deletes what is there to delete, and nothing twice.

use super::AppState;
use crate::store::Retention;
use std::time::Duration;
use time::OffsetDateTime;

/// What the operator keeps.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Policy {
    /// Jobs older than this are deleted.
    pub max_age: Option<Duration>,
    /// Only the newest this many jobs are kept.
    pub max_jobs: Option<u64>,
    /// Time between sweeps.
    pub interval: Duration,
}

impl Policy {
    /// Whether the policy deletes anything at all.
    pub fn deletes(&self) -> bool {
        self.max_age.is_some() || self.max_jobs.is_some()
    }
}

/// One sweep at `now`: the jobs the policy does not keep deleted (and
/// counted in the metrics); how many.
pub async fn sweep(state: &AppState, policy: &Policy, now: OffsetDateTime) -> Result<u64, crate::store::StoreError> {
    let before = policy.max_age.map(|age| super::create::rfc3339(now - age));
    let newest = policy.max_jobs.map(|n| i64::try_from(n).unwrap_or(i64::MAX));
    let (by_age, by_count) = state.store.expire(&Retention { created_before: before.as_deref(), newest }).await?;
    state.metrics.deleted("age", by_age);
    state.metrics.deleted("count", by_count);
    if by_age + by_count > 0 {
        tracing::info!(by_age, by_count, "retention: jobs deleted");
    }
    Ok(by_age + by_count)
}

/// Sweeps at start and then at every interval, for as long as the service runs.
pub fn spawn(state: AppState, policy: Policy) {
    if !policy.deletes() {
        return;
    }
    tokio::spawn(async move {
        let mut every = tokio::time::interval(policy.interval);
        every.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
        loop {
            every.tick().await;
            if let Err(e) = sweep(&state, &policy, OffsetDateTime::now_utc()).await {
                tracing::warn!(error = %e, "retention: the sweep failed; it runs again at the next interval");
            }
        }
    });
}
