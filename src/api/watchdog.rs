//! The watchdog over the compute budget. Every job computing is listed,
//! with its kind and start, for as long as its computation runs — which,
//! once it holds a compute slot, is until the engine returns, whether or
//! not its client is still there. The engine stops a job at its budget
//! (every long loop reads the deadline), so a job still computing well
//! past it — its budget again, and [`GRACE`] more — has escaped: a bug.
//! The watchdog looks every second, logs each such job as an error once
//! and counts it in `mechdyn_jobs_overrun_total{kind}`;
//! `mechdyn_jobs_overrunning` says how many are past it now. A job is not
//! killed (a thread cannot be, safely): it is made seen.

use super::AppState;
use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Beyond twice its budget, this much more: a job is then reported.
pub const GRACE: Duration = Duration::from_secs(5);

/// How long a job may compute before it is reported: its budget twice, and [`GRACE`].
pub fn limit(budget: Duration) -> Duration {
    budget.saturating_mul(2).saturating_add(GRACE)
}

/// The jobs computing now, shared by the service's handlers.
#[derive(Clone, Default)]
pub struct Watchdog(Arc<Mutex<Running>>);

#[derive(Default)]
struct Running {
    next: u64,
    jobs: HashMap<u64, Entry>,
}

struct Entry {
    kind: &'static str,
    started: Instant,
    reported: bool,
}

/// A job listed while it computes; dropping it takes the job off the list.
pub struct Computing {
    dog: Watchdog,
    id: u64,
}

impl Drop for Computing {
    fn drop(&mut self) {
        self.dog.lock().jobs.remove(&self.id);
    }
}

/// What one look found: the jobs newly past the limit (each reported once)
/// and how many are past it now.
#[derive(Debug, Default, PartialEq)]
pub struct Overdue {
    pub new: Vec<(&'static str, Duration)>,
    pub over: usize,
}

impl Watchdog {
    fn lock(&self) -> std::sync::MutexGuard<'_, Running> {
        self.0.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Lists a job of `kind` that starts computing now.
    pub fn start(&self, kind: &'static str) -> Computing {
        self.started(kind, Instant::now())
    }

    fn started(&self, kind: &'static str, started: Instant) -> Computing {
        let mut running = self.lock();
        let id = running.next;
        running.next += 1;
        running.jobs.insert(id, Entry { kind, started, reported: false });
        Computing { dog: self.clone(), id }
    }

    /// Jobs computing now.
    pub fn computing(&self) -> usize {
        self.lock().jobs.len()
    }

    /// The jobs computing for longer than `limit` at `now`.
    pub fn look(&self, limit: Duration, now: Instant) -> Overdue {
        let mut found = Overdue::default();
        for e in self.lock().jobs.values_mut() {
            let elapsed = now.saturating_duration_since(e.started);
            if elapsed > limit {
                found.over += 1;
                if !e.reported {
                    e.reported = true;
                    found.new.push((e.kind, elapsed));
                }
            }
        }
        found
    }
}

/// Looks every second for jobs past [`limit`] of the service's budget.
pub fn spawn(state: AppState) {
    let limit = limit(state.limits.budget);
    state.metrics.kinds(state.kinds.iter().map(|k| k.name()));
    tokio::spawn(async move {
        let mut tick = tokio::time::interval(Duration::from_secs(1));
        tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
        loop {
            tick.tick().await;
            let found = state.watchdog.look(limit, Instant::now());
            for (kind, elapsed) in &found.new {
                let (seconds, budget) = (elapsed.as_secs_f64(), state.limits.budget.as_secs_f64());
                tracing::error!(kind, seconds, budget, "a job has computed past its compute budget: it escaped it");
                state.metrics.overrun(kind);
            }
            state.metrics.overrunning(found.over);
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A job past the limit is reported once, stays counted while it runs,
    /// and leaves the list when its computation ends; one within it is not.
    #[test]
    fn a_job_past_its_limit_is_reported_once_until_it_ends() {
        let dog = Watchdog::default();
        let now = Instant::now();
        let limit = limit(Duration::from_secs(1));
        assert_eq!(limit, Duration::from_secs(7));
        let Some(long_ago) = now.checked_sub(Duration::from_secs(8)) else { return };
        let escaped = dog.started("dynamics", long_ago);
        let _fresh = dog.started("flywheel", now);
        assert_eq!(dog.computing(), 2);
        let first = dog.look(limit, now);
        assert_eq!(first.over, 1);
        assert_eq!(first.new.len(), 1);
        assert_eq!(first.new[0].0, "dynamics");
        assert!(first.new[0].1 >= Duration::from_secs(8));
        assert_eq!(dog.look(limit, now), Overdue { new: Vec::new(), over: 1 }, "reported once");
        drop(escaped);
        assert_eq!(dog.look(limit, now), Overdue::default());
        assert_eq!(dog.computing(), 1);
    }
}
