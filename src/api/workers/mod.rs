//! Jobs computed in worker processes, so that the service can stop any of
//! them from outside. A worker is this same binary run as `mechdyn worker`
//! ([`serve`]), talking over its standard input and output ([`wire`]); it
//! computes one job at a time, the kind's own reading, computation and
//! JSON, and answers the bytes the service stores.
//!
//! - **Budget**: a job is given to one idle worker (or a new one); if no
//!   answer comes within its budget and [`GRACE`], the worker is killed and
//!   the job answered 422 `/problems/compute-budget`. The engine's own
//!   checks of the deadline still stop a job first, saying how far it got;
//!   the kill is the guarantee that no loop can escape.
//! - **Memory**: each worker runs under the operating system's limit on
//!   its data (`--job-memory-bytes`, `RLIMIT_DATA`); a job that passes it
//!   ends its worker, and is answered 422 `/problems/job-memory`.
//! - **Crashes**: a worker that ends otherwise — a panic, an abort, a stack
//!   overflow — is answered 500 `/problems/compute-failed` for its job
//!   alone; what it wrote on its standard error is in the service's log.
//!
//! A worker that answered goes back to the idle ones of its share; one that
//! was killed or ended is replaced by a new one when the next job needs it.
//! Jobs of requests without the token ([`Share::Anonymous`]) have workers of
//! their own, run at a lower priority, so that they never hold a token
//! holder's. How many compute at once is admission control's
//! ([`super::admission`]); the pool only keeps the workers.
//!
//! The exchange with a worker blocks its thread ([`process`]): it runs where
//! the service ran a computation in-process — on the async worker that read
//! the request where its kind's jobs are short, on the blocking pool
//! otherwise — so that a light job costs the service one write and one read
//! of a pipe and no hand-over between tasks. Each wakeup of a thread costs
//! some 30 µs on a virtual machine (a pipe's round trip between two
//! processes took 68 µs here, `perf bench sched pipe`), and awaiting the
//! worker's answer on the runtime's own I/O took four of them a job.

#[cfg(debug_assertions)]
mod faults;
mod process;
pub mod serve;
pub mod wire;

use crate::i18n::Msg;
use crate::kind::Limits;
use crate::kind::problem::ApiError;
use bytes::Bytes;
use process::{Answer, Worker};
use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// How long past its budget a job's worker is given to answer before it is killed.
pub const GRACE: Duration = Duration::from_millis(500);

/// The priority (`nice`) of the workers of requests without the token: the
/// token holders' jobs take the cores first.
pub const ANONYMOUS_NICE: i32 = 10;

/// Whose job a worker computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Share {
    /// A request with the token, or any request of a service without one.
    Holder,
    /// A request without the token, of a service that has one.
    Anonymous,
}

/// Why a worker was stopped, for `/metrics`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stop {
    Budget,
    Memory,
    Crash,
}

impl Stop {
    pub const ALL: [Stop; 3] = [Stop::Budget, Stop::Memory, Stop::Crash];

    pub fn as_str(self) -> &'static str {
        match self {
            Stop::Budget => "budget",
            Stop::Memory => "memory",
            Stop::Crash => "crash",
        }
    }
}

/// How the workers are started.
#[derive(Clone, Debug)]
pub struct Settings {
    /// The binary a worker runs (`mechdyn`; `/proc/self/exe` for the
    /// service's own, whatever has replaced its file since it started).
    pub program: PathBuf,
    /// The limit on each worker's data, bytes (None: no limit).
    pub memory: Option<u64>,
}

/// The workers, shared by the service's handlers. Cheap to clone.
#[derive(Clone)]
pub struct Pool(Arc<Inner>);

struct Inner {
    settings: Settings,
    idle: Mutex<[Vec<Worker>; 2]>,
    stopped: [AtomicU64; 3],
}

/// A job's result from a worker: its JSON and the worker's compute time.
pub type Computed = (Bytes, Duration);

impl Pool {
    pub fn new(settings: Settings) -> Self {
        Self(Arc::new(Inner { settings, idle: Mutex::default(), stopped: Default::default() }))
    }

    /// Starts `n` workers of `share` now, so that the first jobs do not wait for them.
    pub fn warm(&self, share: Share, n: usize) -> Result<(), String> {
        for _ in 0..n {
            let worker = self.spawn(share).map_err(|e| format!("cannot start a worker: {e}"))?;
            self.give_back(worker, share);
        }
        Ok(())
    }

    /// Workers stopped since the service started, by reason.
    pub fn stopped(&self, reason: Stop) -> u64 {
        self.0.stopped[reason as usize].load(Ordering::Relaxed)
    }

    /// The job of `kind` for `request`, computed by a worker of `share`
    /// within `limits`: its result, or the error it ended with. Blocking:
    /// its caller's thread waits, at most the budget and [`GRACE`].
    pub fn run(&self, kind: &str, request: &[u8], limits: &Limits, share: Share) -> Result<Computed, ApiError> {
        let job = wire::Job::new(kind, limits);
        let deadline = Instant::now() + limits.budget.saturating_add(GRACE);
        let mut worker = self.sent(share, &job, request)?;
        match worker.reply(limits.result_bytes, deadline) {
            Ok(Answer::Reply(wire::Reply::Done { micros }, result)) => {
                self.give_back(worker, share);
                Ok((result.into(), Duration::from_micros(micros)))
            }
            Ok(Answer::Reply(wire::Reply::Failed(failure), _)) => {
                self.give_back(worker, share);
                Err(failure.into())
            }
            Ok(Answer::Late) => {
                worker.kill();
                self.count(Stop::Budget);
                tracing::warn!(kind, budget = limits.budget.as_secs_f64(), "a job's worker was killed at its budget");
                Err(over_budget(limits.budget))
            }
            Err(e) => Err(self.ended(worker, kind, &e)),
        }
    }

    /// A worker of `share` that took `job`: an idle one, or a new one where
    /// the idle one had ended meanwhile (its input closed to the job).
    fn sent(&self, share: Share, job: &wire::Job, request: &[u8]) -> Result<Worker, ApiError> {
        let mut worker = self.take(share)?;
        if let Err(e) = worker.send(job, request) {
            tracing::warn!(error = %e, "an idle worker had ended: a new one takes its job");
            worker.kill();
            worker = self.spawn(share).map_err(|e| ApiError::Internal(format!("cannot start a worker: {e}")))?;
            worker.send(job, request).map_err(|e| ApiError::Internal(format!("a new worker: {e}")))?;
        }
        Ok(worker)
    }

    fn take(&self, share: Share) -> Result<Worker, ApiError> {
        if let Some(w) = self.lock()[share as usize].pop() {
            return Ok(w);
        }
        self.spawn(share).map_err(|e| ApiError::Internal(format!("cannot start a worker: {e}")))
    }

    fn give_back(&self, worker: Worker, share: Share) {
        self.lock()[share as usize].push(worker);
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, [Vec<Worker>; 2]> {
        self.0.idle.lock().unwrap_or_else(|e| e.into_inner())
    }

    fn count(&self, stop: Stop) {
        self.0.stopped[stop as usize].fetch_add(1, Ordering::Relaxed);
    }

    /// A worker that stopped answering (`e`) before its budget: why, as its job's error.
    fn ended(&self, mut worker: Worker, kind: &str, e: &std::io::Error) -> ApiError {
        let (status, said) = worker.finish();
        if said.out_of_memory {
            self.count(Stop::Memory);
            tracing::warn!(kind, limit = self.0.settings.memory, "a job's worker ran out of its memory");
            return ApiError::JobMemory(self.0.settings.memory.unwrap_or_default());
        }
        self.count(Stop::Crash);
        let last = Vec::from(said.last).join("\n");
        tracing::error!(kind, ?status, error = %e, "a job's worker ended without answering; its last words:\n{last}");
        ApiError::ComputeFailed
    }

    fn spawn(&self, share: Share) -> std::io::Result<Worker> {
        let settings = &self.0.settings;
        let mut args = vec!["--parent".to_string(), std::process::id().to_string()];
        if let Some(bytes) = settings.memory {
            args.extend(["--job-memory-bytes".into(), bytes.to_string()]);
        }
        if share == Share::Anonymous {
            args.extend(["--nice".into(), ANONYMOUS_NICE.to_string()]);
        }
        Worker::spawn(&settings.program, &args)
    }
}

/// The 422 of a job whose worker was killed at its budget.
pub fn over_budget(budget: Duration) -> ApiError {
    let stopped = Msg::new("progress-stopped");
    ApiError::OverBudget(Msg::new("detail-over-budget").num("seconds", budget.as_secs_f64()).with("progress", stopped))
}
