//! Admission control: what bounds the service's memory under any load.
//!
//! - **Bodies** (`bodies` bytes): a POST's body, while it is read, holds
//!   its announced length (the body limit when it has none), waiting up to
//!   `wait` for it (then 503). Bodies are read at a minimal pace
//!   ([`super::pace`]), so a client that trickles one holds its share for
//!   seconds, not for ever, and holds no slot meanwhile.
//! - **Slots** (`jobs + queue`): every POST takes one once its body has
//!   been read, and keeps it until its answer has been sent. With none free
//!   the POST is answered 503 at once, with `Retry-After`. This bounds the
//!   whole bodies held (slots × body limit).
//!   Anything else that computes a job — a GET of a template's job not
//!   stored yet, a deferred job — takes a slot for its computation
//!   ([`Admission::slot`]), so no route bypasses the bound.
//! - **Compute** (`jobs`, default the number of cores): a job computes, and
//!   its result is serialised, only while it holds one; the others wait in
//!   the queue, at most `queue_wait` (then 503). This bounds the engine's
//!   working sets, and how long a client waits for a job to start.
//! - **Memory** (`memory` bytes): every answer that carries a job (a POST's,
//!   a read, a page of the list, a CSV) reserves its size before it is built
//!   or loaded and keeps it until it has been sent. Waiting longer than
//!   `wait` for it is a 503 with `Retry-After`. A POST reserves the largest
//!   result before it computes, and keeps only what its result takes after:
//!   a job never computes to be refused for want of memory.
//!
//! - **Inline** (`inline`, default the number of cores): a job of a kind
//!   whose recent jobs computed in under [`INLINE_US`] on average computes
//!   on the async worker that read its request, holding one of these as
//!   well as its compute slot; the others go to the blocking pool. The
//!   hand-over to a pool thread and back costs more than such a job
//!   (measured: 5 100 against 8 500 flywheel jobs/s). The service runs one
//!   async worker more than `inline` ([`Capacity::workers`]), so one always
//!   stays free of computing: reads and health checks are answered even
//!   while jobs that were expected short run long.
//!
//! - **Anonymous** (`anonymous_jobs`, default 1): where the service has a
//!   token, a computation for a request without it (a spreadsheet's GET of
//!   a template's value for new parameters) takes one of these instead of
//!   a slot and a compute permit, within a budget of its own
//!   (`anonymous_seconds`, default 2 s), on workers of its own at a lower
//!   priority ([`super::workers::Share`]): it never waits for, nor holds, a
//!   token holder's place. With none free, at most [`ANONYMOUS_WAITING`]
//!   such requests wait for each, each as long as those ahead may take; the
//!   others are answered 503 at once.
//!
//! `Retry-After` is the time the jobs ahead would take at the recent mean
//! time per job (an exponential average), at least 1 s.

use crate::i18n::Msg;
use crate::kind::Limits;
use crate::kind::problem::ApiError;
use std::collections::HashMap;
use std::future::Future;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;
use tokio::sync::{OwnedSemaphorePermit, Semaphore};

/// The sizes of admission control.
#[derive(Clone, Debug, PartialEq)]
pub struct Capacity {
    /// Jobs computing at once.
    pub jobs: usize,
    /// Jobs waiting to compute, beyond which a POST is answered 503.
    pub queue: usize,
    /// Bytes of answers carrying jobs held at once.
    pub memory: usize,
    /// Longest wait for memory before a 503.
    pub wait: Duration,
    /// Longest wait in the queue for a job to start computing before a 503.
    pub queue_wait: Duration,
    /// Jobs computing at once on the async workers.
    pub inline: usize,
    /// Bytes of request bodies being read at once.
    pub bodies: usize,
    /// Computations at once for requests without the token (of a service with one).
    pub anonymous_jobs: usize,
    /// The compute budget of each of those.
    pub anonymous_seconds: Duration,
}

impl Capacity {
    /// The async workers the service runs: one more than may compute inline.
    pub fn workers(&self) -> usize {
        self.inline + 1
    }
}

tokio::task_local! {
    /// Set while a POST that holds its slot is answered.
    static HOLDING: ();
}

/// Requests without the token that wait for each place of their share;
/// beyond them such a request is answered 503 at once.
pub const ANONYMOUS_WAITING: usize = 4;

/// Mean compute time of a kind's recent jobs under which its next job
/// computes on the async worker, µs.
pub const INLINE_US: u64 = 1_000;

impl Default for Capacity {
    fn default() -> Self {
        let cores = std::thread::available_parallelism().map_or(2, |n| n.get());
        Self {
            jobs: cores,
            inline: cores,
            queue: 64,
            memory: 128 << 20,
            wait: Duration::from_secs(10),
            queue_wait: Duration::from_secs(30),
            bodies: 64 << 20,
            anonymous_jobs: 1,
            anonymous_seconds: Duration::from_secs(2),
        }
    }
}

#[derive(Clone)]
pub struct Admission {
    slots: Arc<Semaphore>,
    bodies: Arc<Semaphore>,
    compute: Arc<Semaphore>,
    memory: Arc<Semaphore>,
    capacity: Capacity,
    /// Exponential mean of a job's compute time, µs.
    mean_job_us: Arc<AtomicU64>,
    inline: Arc<Semaphore>,
    /// Exponential mean of the compute time of each kind's jobs, µs.
    kind_us: Arc<Mutex<HashMap<&'static str, u64>>>,
    anonymous: Arc<Semaphore>,
    anonymous_waiting: Arc<AtomicUsize>,
}

impl Default for Admission {
    fn default() -> Self {
        Self::new(Capacity::default())
    }
}

impl Admission {
    pub fn new(capacity: Capacity) -> Self {
        let jobs = capacity.jobs.max(1);
        let inline = capacity.inline.min(jobs);
        Self {
            slots: Arc::new(Semaphore::new(jobs + capacity.queue)),
            bodies: Arc::new(Semaphore::new(capacity.bodies.clamp(1, Semaphore::MAX_PERMITS))),
            compute: Arc::new(Semaphore::new(jobs)),
            memory: Arc::new(Semaphore::new(capacity.memory.clamp(1, Semaphore::MAX_PERMITS))),
            anonymous: Arc::new(Semaphore::new(capacity.anonymous_jobs)),
            anonymous_waiting: Arc::default(),
            capacity,
            mean_job_us: Arc::new(AtomicU64::new(10_000)),
            inline: Arc::new(Semaphore::new(inline)),
            kind_us: Default::default(),
        }
    }

    pub fn capacity(&self) -> &Capacity {
        &self.capacity
    }

    /// A slot for a POST, or None when every job slot and queue place is taken.
    pub fn enter(&self) -> Option<OwnedSemaphorePermit> {
        self.slots.clone().try_acquire_owned().ok()
    }

    /// Runs `answer` as a request that holds a slot (a POST once admitted).
    pub async fn holding<F: Future>(answer: F) -> F::Output {
        HOLDING.scope((), answer).await
    }

    /// A slot for a computation: none inside a request that holds one (a
    /// POST), else one of the free slots (a GET of a template's new job, a
    /// deferred job), or the 503 of a saturated service.
    pub fn slot(&self) -> Result<Option<OwnedSemaphorePermit>, ApiError> {
        if HOLDING.try_with(|()| ()).is_ok() {
            return Ok(None);
        }
        self.enter().map(Some).ok_or_else(|| self.saturated("saturated-slots"))
    }

    /// The right to compute, once a job ahead has finished (waiting at most `queue_wait`).
    pub async fn compute(&self) -> Result<OwnedSemaphorePermit, ApiError> {
        match tokio::time::timeout(self.capacity.queue_wait, self.compute.clone().acquire_owned()).await {
            Ok(Ok(permit)) => Ok(permit),
            Ok(Err(_)) => Err(self.saturated("saturated-stopping")),
            Err(_) => Err(self.saturated("saturated-queue")),
        }
    }

    /// The right to compute for a request without the token, once those
    /// ahead of it have: at most [`ANONYMOUS_WAITING`] such requests wait for
    /// each place, each as long as those ahead may take (their budgets).
    pub async fn anonymous(&self) -> Result<OwnedSemaphorePermit, ApiError> {
        let budget = self.capacity.anonymous_seconds;
        let taken = || ApiError::Saturated {
            reason: Msg::new("saturated-anonymous"),
            retry_after: budget.as_secs_f64().ceil().max(1.0) as u64,
        };
        if let Ok(permit) = self.anonymous.clone().try_acquire_owned() {
            return Ok(permit);
        }
        let most = self.capacity.anonymous_jobs.saturating_mul(ANONYMOUS_WAITING);
        if self.anonymous_waiting.fetch_add(1, Ordering::Relaxed) >= most {
            self.anonymous_waiting.fetch_sub(1, Ordering::Relaxed);
            return Err(taken());
        }
        // Those ahead each take their budget at most, and the grace past it.
        let wait = budget.saturating_add(super::workers::GRACE).saturating_mul(ANONYMOUS_WAITING as u32);
        let waited = tokio::time::timeout(wait, self.anonymous.clone().acquire_owned()).await;
        self.anonymous_waiting.fetch_sub(1, Ordering::Relaxed);
        match waited {
            Ok(Ok(permit)) => Ok(permit),
            _ => Err(taken()),
        }
    }

    /// The limits a job of `share` computes within: a request without the
    /// token has its own budget, when that is the shorter.
    pub fn limits(&self, share: super::workers::Share, limits: &Limits) -> Limits {
        match share {
            super::workers::Share::Holder => limits.clone(),
            super::workers::Share::Anonymous => {
                Limits { budget: limits.budget.min(self.capacity.anonymous_seconds), ..limits.clone() }
            }
        }
    }

    /// Reserves `bytes` of answer memory (at most the whole budget), waiting
    /// up to `wait` for answers being sent to release theirs.
    pub async fn memory(&self, bytes: usize) -> Result<OwnedSemaphorePermit, ApiError> {
        let why = "saturated-memory";
        self.reserve(&self.memory, bytes, self.capacity.memory, why).await
    }

    /// Reserves `bytes` for a request body being read (at most the whole
    /// budget), waiting up to `wait` for bodies being read to finish.
    pub async fn body(&self, bytes: usize) -> Result<OwnedSemaphorePermit, ApiError> {
        self.reserve(&self.bodies, bytes, self.capacity.bodies, "saturated-bodies").await
    }

    /// `bytes` of `budget` (a semaphore of `total` bytes), waiting up to `wait`.
    async fn reserve(
        &self,
        budget: &Arc<Semaphore>,
        bytes: usize,
        total: usize,
        why: &'static str,
    ) -> Result<OwnedSemaphorePermit, ApiError> {
        let n = u32::try_from(bytes.clamp(1, total.max(1))).unwrap_or(u32::MAX);
        match tokio::time::timeout(self.capacity.wait, budget.clone().acquire_many_owned(n)).await {
            Ok(Ok(permit)) => Ok(permit),
            _ => Err(self.saturated(why)),
        }
    }

    /// Records a job's compute time, for the `Retry-After` estimate and
    /// its kind's mean.
    pub fn record(&self, kind: &'static str, elapsed: Duration) {
        let us = u64::try_from(elapsed.as_micros()).unwrap_or(u64::MAX);
        let mean = |old: u64| old - old / 8 + us / 8;
        self.mean_job_us.store(mean(self.mean_job_us.load(Ordering::Relaxed)), Ordering::Relaxed);
        let mut kinds = self.kind_us.lock().unwrap_or_else(|e| e.into_inner());
        kinds.entry(kind).and_modify(|m| *m = mean(*m)).or_insert(us);
    }

    /// The right to compute a job of `kind` on this async worker: when its
    /// kind's recent jobs were short and an inline place is free.
    pub fn inline(&self, kind: &'static str) -> Option<OwnedSemaphorePermit> {
        let short = self.kind_us.lock().unwrap_or_else(|e| e.into_inner()).get(kind).is_some_and(|us| *us < INLINE_US);
        short.then(|| self.inline.clone().try_acquire_owned().ok()).flatten()
    }

    /// Jobs computing now.
    pub fn computing(&self) -> usize {
        self.capacity.jobs.max(1) - self.compute.available_permits()
    }

    /// Jobs computing or waiting to.
    pub fn in_flight(&self) -> usize {
        self.capacity.jobs.max(1) + self.capacity.queue - self.slots.available_permits()
    }

    /// Seconds until a slot is likely free: the jobs ahead at the mean job time.
    pub fn retry_after(&self) -> u64 {
        let ahead = self.in_flight() as u64 / self.capacity.jobs.max(1) as u64;
        let us = self.mean_job_us.load(Ordering::Relaxed).saturating_mul(ahead.max(1));
        us.div_ceil(1_000_000).clamp(1, 60)
    }

    /// The 503 of a saturated service.
    pub fn saturated(&self, why: &'static str) -> ApiError {
        self.saturated_because(Msg::new(why))
    }

    /// The 503 of a saturated service, saying why.
    pub fn saturated_because(&self, why: Msg) -> ApiError {
        ApiError::Saturated { reason: why, retry_after: self.retry_after() }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A kind computes inline only once its recent jobs were short, never
    /// more of them at once than `inline`, and no longer once they are long.
    #[test]
    fn short_kinds_compute_inline_within_their_places() {
        let a = Admission::new(Capacity { inline: 1, ..Capacity::default() });
        assert!(a.inline("flywheel").is_none(), "no job of the kind seen yet");
        a.record("flywheel", Duration::from_micros(80));
        a.record("dynamics", Duration::from_millis(40));
        assert!(a.inline("dynamics").is_none(), "a long kind");
        let first = a.inline("flywheel").expect("a short kind");
        assert!(a.inline("flywheel").is_none(), "one place only");
        drop(first);
        assert!(a.inline("flywheel").is_some(), "the place is free again");
        // The mean moves by 1/8 of the difference per job: 20 jobs of 5 ms pass 1 ms.
        (0..20).for_each(|_| a.record("flywheel", Duration::from_millis(5)));
        assert!(a.inline("flywheel").is_none(), "the kind's jobs have become long");
        assert_eq!(Capacity { inline: 2, ..Capacity::default() }.workers(), 3, "one worker never computes");
    }
}
