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

#[cfg(debug_assertions)]
mod faults;
pub mod serve;
pub mod wire;

use crate::i18n::Msg;
use crate::kind::Limits;
use crate::kind::problem::ApiError;
use bytes::Bytes;
use std::path::PathBuf;
use std::process::Stdio;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;
use tokio::io::{AsyncBufReadExt, AsyncReadExt, AsyncWriteExt, BufReader};
use tokio::process::{Child, ChildStdin, ChildStdout, Command};

/// How long past its budget a job's worker is given to answer before it is killed.
pub const GRACE: Duration = Duration::from_millis(500);

/// The priority (`nice`) of the workers of requests without the token: the
/// token holders' jobs take the cores first.
pub const ANONYMOUS_NICE: i32 = 10;

/// What a worker writes on its standard error when an allocation fails
/// (Rust's handler of a failed allocation, before it aborts).
const OUT_OF_MEMORY: &str = "memory allocation of";

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
    /// within `limits`: its result, or the error it ended with.
    pub async fn run(&self, kind: &str, request: &[u8], limits: &Limits, share: Share) -> Result<Computed, ApiError> {
        let mut worker = self.take(share)?;
        let job = wire::Job::new(kind, limits);
        let bound = limits.budget.saturating_add(GRACE);
        match tokio::time::timeout(bound, worker.exchange(&job, request, limits.result_bytes)).await {
            Ok(Ok((wire::Reply::Done { micros }, result))) => {
                self.give_back(worker, share);
                Ok((result.into(), Duration::from_micros(micros)))
            }
            Ok(Ok((wire::Reply::Failed(failure), _))) => {
                self.give_back(worker, share);
                Err(failure.into())
            }
            Ok(Err(e)) => Err(self.ended(worker, kind, &e).await),
            Err(_) => {
                worker.kill().await;
                self.count(Stop::Budget);
                tracing::warn!(kind, budget = limits.budget.as_secs_f64(), "a job's worker was killed at its budget");
                Err(over_budget(limits.budget))
            }
        }
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
    async fn ended(&self, mut worker: Worker, kind: &str, e: &std::io::Error) -> ApiError {
        let status = worker.finish().await;
        let said = std::mem::take(&mut *worker.said.lock().unwrap_or_else(|e| e.into_inner()));
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
        let mut command = Command::new(&settings.program);
        command.arg("worker").arg("--parent").arg(std::process::id().to_string());
        if let Some(bytes) = settings.memory {
            command.arg("--job-memory-bytes").arg(bytes.to_string());
        }
        if share == Share::Anonymous {
            command.arg("--nice").arg(ANONYMOUS_NICE.to_string());
        }
        command.stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped()).kill_on_drop(true);
        let mut child = command.spawn()?;
        let (Some(stdin), Some(stdout), Some(stderr)) = (child.stdin.take(), child.stdout.take(), child.stderr.take())
        else {
            return Err(std::io::Error::other("a worker without its pipes"));
        };
        let said = Arc::new(Mutex::new(Said::default()));
        let listening = tokio::spawn(listen(stderr, child.id(), said.clone()));
        Ok(Worker { child, stdin, stdout: BufReader::new(stdout), said, listening })
    }
}

/// The 422 of a job whose worker was killed at its budget.
pub fn over_budget(budget: Duration) -> ApiError {
    let stopped = Msg::new("progress-stopped");
    ApiError::OverBudget(Msg::new("detail-over-budget").num("seconds", budget.as_secs_f64()).with("progress", stopped))
}

/// What a worker wrote on its standard error: whether an allocation
/// failed, and its last lines (a panic's message and backtrace).
#[derive(Default)]
struct Said {
    out_of_memory: bool,
    last: std::collections::VecDeque<String>,
}

/// Lines of a worker's standard error kept for the log, and characters of each.
const LAST_LINES: usize = 40;
const LINE_CHARS: usize = 400;

/// A worker's standard error read line by line (each in the service's log
/// at `debug`), its last lines kept, a failed allocation noted.
async fn listen(stderr: tokio::process::ChildStderr, pid: Option<u32>, said: Arc<Mutex<Said>>) {
    let mut lines = BufReader::new(stderr).lines();
    while let Ok(Some(mut line)) = lines.next_line().await {
        tracing::debug!(worker = pid, "{line}");
        line.truncate(line.floor_char_boundary(LINE_CHARS));
        let mut said = said.lock().unwrap_or_else(|e| e.into_inner());
        said.out_of_memory |= line.starts_with(OUT_OF_MEMORY);
        if said.last.len() == LAST_LINES {
            said.last.pop_front();
        }
        said.last.push_back(line);
    }
}

/// One worker process and its pipes.
struct Worker {
    child: Child,
    stdin: ChildStdin,
    stdout: BufReader<ChildStdout>,
    /// What its standard error said.
    said: Arc<Mutex<Said>>,
    /// The task reading its standard error.
    listening: tokio::task::JoinHandle<()>,
}

impl Worker {
    /// Sends a job and reads the reply (a result of at most `max` bytes).
    async fn exchange(
        &mut self,
        job: &wire::Job,
        request: &[u8],
        max: usize,
    ) -> std::io::Result<(wire::Reply, Vec<u8>)> {
        self.stdin.write_all(&wire::head(job, request.len())?).await?;
        self.stdin.write_all(request).await?;
        self.stdin.flush().await?;
        let header = self.part(wire::MAX_PART).await?;
        let reply: wire::Reply = serde_json::from_slice(&header).map_err(std::io::Error::other)?;
        let body = self.part(max).await?;
        Ok((reply, body))
    }

    async fn part(&mut self, max: usize) -> std::io::Result<Vec<u8>> {
        let mut prefix = [0u8; 4];
        self.stdout.read_exact(&mut prefix).await?;
        let n = wire::length(prefix)?;
        if n > max {
            return Err(std::io::Error::other(format!("a reply of {n} bytes, over the {max} allowed")));
        }
        let mut buf = vec![0u8; n];
        self.stdout.read_exact(&mut buf).await?;
        Ok(buf)
    }

    /// Kills the worker and waits for it.
    async fn kill(mut self) {
        let _ = self.child.start_kill();
        let _ = self.finish().await;
    }

    /// Waits for the worker to end, and for what it wrote on its standard error.
    async fn finish(&mut self) -> std::io::Result<std::process::ExitStatus> {
        let status = tokio::time::timeout(Duration::from_secs(5), self.child.wait()).await;
        let _ = tokio::time::timeout(Duration::from_secs(1), &mut self.listening).await;
        status.unwrap_or_else(|_| Err(std::io::Error::other("the worker did not end")))
    }
}
