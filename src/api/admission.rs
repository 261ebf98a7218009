//! Admission control: what bounds the service's memory under any load.
//!
//! - **Slots** (`jobs + queue`): every POST takes one before its body is
//!   read, and keeps it until its answer has been sent. With none free the
//!   POST is answered 503 at once, with `Retry-After`. This bounds the
//!   request bodies held (slots × body limit).
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
//! `Retry-After` is the time the jobs ahead would take at the recent mean
//! time per job (an exponential average), at least 1 s.

use super::problem::ApiError;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
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
}

impl Default for Capacity {
    fn default() -> Self {
        Self {
            jobs: std::thread::available_parallelism().map_or(2, |n| n.get()),
            queue: 64,
            memory: 128 << 20,
            wait: Duration::from_secs(10),
            queue_wait: Duration::from_secs(30),
        }
    }
}

#[derive(Clone)]
pub struct Admission {
    slots: Arc<Semaphore>,
    compute: Arc<Semaphore>,
    memory: Arc<Semaphore>,
    capacity: Capacity,
    /// Exponential mean of a job's compute time, µs.
    mean_job_us: Arc<AtomicU64>,
}

impl Default for Admission {
    fn default() -> Self {
        Self::new(Capacity::default())
    }
}

impl Admission {
    pub fn new(capacity: Capacity) -> Self {
        let jobs = capacity.jobs.max(1);
        Self {
            slots: Arc::new(Semaphore::new(jobs + capacity.queue)),
            compute: Arc::new(Semaphore::new(jobs)),
            memory: Arc::new(Semaphore::new(capacity.memory.clamp(1, Semaphore::MAX_PERMITS))),
            capacity,
            mean_job_us: Arc::new(AtomicU64::new(10_000)),
        }
    }

    pub fn capacity(&self) -> &Capacity {
        &self.capacity
    }

    /// A slot for a POST, or None when every job slot and queue place is taken.
    pub fn enter(&self) -> Option<OwnedSemaphorePermit> {
        self.slots.clone().try_acquire_owned().ok()
    }

    /// The right to compute, once a job ahead has finished (waiting at most `queue_wait`).
    pub async fn compute(&self) -> Result<OwnedSemaphorePermit, ApiError> {
        match tokio::time::timeout(self.capacity.queue_wait, self.compute.clone().acquire_owned()).await {
            Ok(Ok(permit)) => Ok(permit),
            Ok(Err(_)) => Err(self.saturated("the service is stopping")),
            Err(_) => Err(self.saturated("the jobs ahead in the queue did not finish in time")),
        }
    }

    /// Reserves `bytes` of answer memory (at most the whole budget), waiting
    /// up to `wait` for answers being sent to release theirs.
    pub async fn memory(&self, bytes: usize) -> Result<OwnedSemaphorePermit, ApiError> {
        let n = u32::try_from(bytes.clamp(1, self.capacity.memory.max(1))).unwrap_or(u32::MAX);
        let reserve = self.memory.clone().acquire_many_owned(n);
        match tokio::time::timeout(self.capacity.wait, reserve).await {
            Ok(Ok(permit)) => Ok(permit),
            _ => Err(self.saturated("too many large answers are being sent")),
        }
    }

    /// Records a job's compute time for the `Retry-After` estimate.
    pub fn record(&self, elapsed: Duration) {
        let us = u64::try_from(elapsed.as_micros()).unwrap_or(u64::MAX);
        let old = self.mean_job_us.load(Ordering::Relaxed);
        self.mean_job_us.store(old - old / 8 + us / 8, Ordering::Relaxed);
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
    pub fn saturated(&self, why: &str) -> ApiError {
        ApiError::Saturated { reason: why.into(), retry_after: self.retry_after() }
    }
}
