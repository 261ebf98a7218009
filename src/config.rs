//! Command line and environment settings.

use crate::api::Capacity;
use crate::api::pace::Pace;
use crate::api::retention::Policy;
use crate::api::serve::Bounds;
use crate::kind::limits::{Limits, MAX_EXPRESSION_DEPTH};
use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::time::Duration;

/// Default database: a SQLite file under ./data, created on first start.
pub const DEFAULT_DATABASE: &str = "sqlite://data/mechdyn.db";
/// Default listen address.
pub const DEFAULT_ADDR: &str = "127.0.0.1:8080";
/// Default address of the operator's listener: loopback, so a container's
/// health check reaches it and nothing outside does until it is asked to.
pub const DEFAULT_OPERATOR_ADDR: &str = "127.0.0.1:9464";
/// File descriptors kept for everything but the service's connections: the
/// database, the operator's listener, logs, the runtime.
pub const RESERVED_FILES: u64 = 256;
/// Connections of the operator's listener.
pub const OPERATOR_CONNECTIONS: usize = 64;
/// The most connections held by default, however many descriptors: a held
/// connection costs 10 to 19 KiB of memory (docs/SOAK.md), some 300 MiB at this cap.
pub const MAX_DEFAULT_CONNECTIONS: usize = 16_384;

#[derive(Parser, Debug)]
#[command(name = "mechdyn", version, about = "Machine-dynamics calculation service")]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Address to listen on (serve) or to probe (healthcheck).
    #[arg(long, env = "MECHDYN_ADDR", default_value = DEFAULT_ADDR, global = true)]
    pub addr: String,
    /// Database URL: sqlite://PATH (a file of this service's own) or postgres://USER:PASSWORD@HOST:PORT/DB (a server several replicas share).
    #[arg(long, env = "DATABASE_URL", default_value = DEFAULT_DATABASE, global = true)]
    pub database: String,
    /// Largest accepted request body, bytes.
    #[arg(long, env = "MECHDYN_MAX_BODY_BYTES", default_value_t = crate::api::DEFAULT_BODY_LIMIT, global = true)]
    pub max_body_bytes: usize,
    /// When set, every POST and DELETE must carry `Authorization: Bearer <token>` (401 without it), and so must every read of stored jobs unless --public-jobs (a browser signs in once at /signin).
    #[arg(long, env = "MECHDYN_API_TOKEN", hide_env_values = true, global = true)]
    pub api_token: Option<String>,
    /// Origins allowed to call the API from a browser (CORS), comma-separated; `*` for any.
    #[arg(long, env = "MECHDYN_CORS_ORIGINS", value_delimiter = ',', global = true)]
    pub cors_origins: Vec<String>,
    /// Wall-clock compute budget of a job, seconds (a job over it is stopped and answered 422).
    #[arg(long, env = "MECHDYN_JOB_SECONDS", default_value_t = Limits::default().budget.as_secs_f64(), value_parser = positive_seconds, global = true)]
    pub job_seconds: f64,
    /// Most input positions of a kinetostatics job.
    #[arg(long, env = "MECHDYN_MAX_STEPS", default_value_t = Limits::default().steps, value_parser = at_least_one, global = true)]
    pub max_steps: usize,
    /// Most result samples of a flywheel or dynamics job.
    #[arg(long, env = "MECHDYN_MAX_SAMPLES", default_value_t = Limits::default().samples, value_parser = at_least_one, global = true)]
    pub max_samples: usize,
    /// Most rows of a table function.
    #[arg(long, env = "MECHDYN_MAX_TABLE_ROWS", default_value_t = Limits::default().table_rows, value_parser = at_least_one, global = true)]
    pub max_table_rows: usize,
    /// Most segments of a piecewise function.
    #[arg(long, env = "MECHDYN_MAX_SEGMENTS", default_value_t = Limits::default().segments, value_parser = at_least_one, global = true)]
    pub max_segments: usize,
    /// Most characters of an expression.
    #[arg(long, env = "MECHDYN_MAX_EXPRESSION_LENGTH", default_value_t = Limits::default().expression_length, value_parser = at_least_one, global = true)]
    pub max_expression_length: usize,
    /// Most levels of nesting of an expression, 1 to 256.
    #[arg(long, env = "MECHDYN_MAX_EXPRESSION_DEPTH", default_value_t = Limits::default().expression_depth, value_parser = depth, global = true)]
    pub max_expression_depth: usize,
    /// Largest result of a job as JSON, bytes (a request whose result would be larger is answered 422 saying what fits).
    #[arg(long, env = "MECHDYN_MAX_RESULT_BYTES", default_value_t = Limits::default().result_bytes, value_parser = at_least_one, global = true)]
    pub max_result_bytes: usize,
    /// Jobs computing at once, each in a worker process of its own (default: the number of cores).
    #[arg(long, env = "MECHDYN_JOBS", default_value_t = Capacity::default().jobs, value_parser = at_least_one, global = true)]
    pub jobs: usize,
    /// Jobs waiting to compute; beyond them a POST is answered 503 with Retry-After.
    #[arg(long, env = "MECHDYN_QUEUE", default_value_t = Capacity::default().queue, global = true)]
    pub queue: usize,
    /// Longest wait in the queue for a job to start computing, seconds (then 503 with Retry-After).
    #[arg(long, env = "MECHDYN_QUEUE_SECONDS", default_value_t = Capacity::default().queue_wait.as_secs_f64(), value_parser = positive_seconds, global = true)]
    pub queue_seconds: f64,
    /// Bytes of answers carrying jobs held in memory at once (at least the largest result plus the largest body).
    #[arg(long, env = "MECHDYN_ANSWER_MEMORY_BYTES", default_value_t = Capacity::default().memory, value_parser = at_least_one, global = true)]
    pub answer_memory_bytes: usize,
    /// Bytes of request bodies being received at once (a POST's announced length, or the body limit); beyond them a POST waits, then is answered 503.
    #[arg(long, env = "MECHDYN_BODY_MEMORY_BYTES", default_value_t = Capacity::default().bodies, value_parser = at_least_one, global = true)]
    pub body_memory_bytes: usize,
    /// The slowest a client may send a body or take an answer, bytes per second (after the grace); a slower one gets 408, or its connection closed.
    #[arg(long, env = "MECHDYN_CLIENT_MIN_RATE", default_value_t = Pace::default().rate, value_parser = clap::value_parser!(u64).range(1..), global = true)]
    pub client_min_rate: u64,
    /// Seconds a client may keep the service waiting before the minimal rate applies.
    #[arg(long, env = "MECHDYN_CLIENT_GRACE_SECONDS", default_value_t = Pace::default().grace.as_secs_f64(), value_parser = positive_seconds, global = true)]
    pub client_grace_seconds: f64,
    /// Largest size of the SQLite database, bytes; beyond it POSTs are answered 507 (default: the disk's free space).
    #[arg(long, env = "MECHDYN_MAX_DATABASE_BYTES", global = true)]
    pub max_database_bytes: Option<u64>,
    /// When a SQLite commit is on disk: `full` (a job answered 201 survives a power loss: an fsync per commit, shared by the jobs committed together) or `normal` (it survives a crash of the process; a power loss may take the last commits).
    #[arg(long, env = "MECHDYN_SQLITE_SYNCHRONOUS", default_value = "full", value_parser = ["full", "normal"], global = true)]
    pub sqlite_synchronous: String,
    /// Seconds a start waits for a PostgreSQL server that does not answer yet (then the service stops).
    #[arg(long, env = "MECHDYN_DATABASE_WAIT_SECONDS", default_value_t = 30.0, value_parser = positive_seconds, global = true)]
    pub database_wait_seconds: f64,
    /// Jobs POSTed with `Prefer: respond-async` this replica computes at once (0: it only queues them, for other replicas; default: the number of cores).
    #[arg(long, env = "MECHDYN_ASYNC_WORKERS", default_value_t = crate::api::deferred::Settings::default().workers, global = true)]
    pub async_workers: usize,
    /// Jobs POSTed with `Prefer: respond-async` waiting at most (over every replica); beyond them such a POST is answered 503.
    #[arg(long, env = "MECHDYN_ASYNC_QUEUE", default_value_t = crate::api::deferred::Settings::default().max_queued, value_parser = clap::value_parser!(i64).range(1..), global = true)]
    pub async_queue: i64,
    /// Seconds a replica's claim on a deferred job lasts unless renewed (a replica that dies leaves its jobs to others after it).
    #[arg(long, env = "MECHDYN_ASYNC_LEASE_SECONDS", default_value_t = 30.0, value_parser = positive_seconds, global = true)]
    pub async_lease_seconds: f64,
    /// Delete jobs older than this many days (fractions allowed; default: keep them).
    #[arg(long, env = "MECHDYN_RETENTION_DAYS", value_parser = positive_days, global = true)]
    pub retention_days: Option<f64>,
    /// Keep only the newest this many jobs (default: keep them all).
    #[arg(long, env = "MECHDYN_RETENTION_JOBS", value_parser = clap::value_parser!(u64).range(1..), global = true)]
    pub retention_jobs: Option<u64>,
    /// Seconds a connection may take to send a request head (from its start, or from the head's first byte on a kept-alive connection); then it is closed.
    #[arg(long, env = "MECHDYN_HEADER_SECONDS", default_value_t = 10.0, value_parser = positive_seconds, global = true)]
    pub header_seconds: f64,
    /// Seconds a kept-alive connection may stay idle between requests; then it is closed.
    #[arg(long, env = "MECHDYN_IDLE_SECONDS", default_value_t = 60.0, value_parser = positive_seconds, global = true)]
    pub idle_seconds: f64,
    /// Most connections held at once; beyond them a new one is answered 503 at once (default: below the file descriptors the process may open).
    #[arg(long, env = "MECHDYN_MAX_CONNECTIONS", value_parser = at_least_one, global = true)]
    pub max_connections: Option<usize>,
    /// Address of the operator's listener (/healthz, /readyz, /metrics, with connections of their own, reachable while the service's are all taken); `off` for none. The default is used only if it can be bound.
    #[arg(long, env = "MECHDYN_OPERATOR_ADDR", default_value = DEFAULT_OPERATOR_ADDR, global = true)]
    pub operator_addr: String,
    /// Compute jobs on the service's own threads instead of worker processes: a job is then stopped only where the engine reads its deadline, and a crash in one ends the service (for measurements and debugging).
    #[arg(long, env = "MECHDYN_IN_PROCESS", global = true, value_parser = clap::builder::BoolishValueParser::new())]
    pub in_process: bool,
    /// Most memory a job's worker process may take, bytes (the operating system's limit on its data; a job past it is answered 422). Default: half the machine's memory (or its container's) shared among the workers, at least 256 MiB.
    #[arg(long, env = "MECHDYN_JOB_MEMORY_BYTES", value_parser = clap::value_parser!(u64).range(1..), global = true)]
    pub job_memory_bytes: Option<u64>,
    /// Jobs computing at once for requests without the token (a spreadsheet's GET of a template's value), of a service with one; beyond them such a request waits, then is answered 503.
    #[arg(long, env = "MECHDYN_ANONYMOUS_JOBS", default_value_t = Capacity::default().anonymous_jobs, value_parser = at_least_one, global = true)]
    pub anonymous_jobs: usize,
    /// The compute budget of a job for a request without the token, seconds (at most --job-seconds).
    #[arg(long, env = "MECHDYN_ANONYMOUS_JOB_SECONDS", default_value_t = Capacity::default().anonymous_seconds.as_secs_f64(), value_parser = positive_seconds, global = true)]
    pub anonymous_job_seconds: f64,
    /// Stored jobs readable without the token (a public demonstration): the job list, each job, its parts, CSV, plots and page. Without it, a service with a token keeps them to the token's holders.
    #[arg(long, env = "MECHDYN_PUBLIC_JOBS", global = true, value_parser = clap::builder::BoolishValueParser::new())]
    pub public_jobs: bool,
    /// Seconds between the retention's sweeps (the first runs at start).
    #[arg(long, env = "MECHDYN_RETENTION_INTERVAL_SECONDS", default_value_t = 60.0, value_parser = positive_seconds, global = true)]
    pub retention_interval_seconds: f64,
}

impl Cli {
    /// The limits on one request.
    pub fn limits(&self) -> Limits {
        Limits {
            budget: Duration::from_secs_f64(self.job_seconds),
            steps: self.max_steps,
            samples: self.max_samples,
            table_rows: self.max_table_rows,
            segments: self.max_segments,
            expression_length: self.max_expression_length,
            expression_depth: self.max_expression_depth,
            result_bytes: self.max_result_bytes,
            started: None,
        }
    }

    /// The sizes of admission control, checked against the limits: the
    /// answer memory must hold the largest answer.
    pub fn capacity(&self) -> Result<Capacity, String> {
        let largest = self.max_result_bytes.saturating_add(self.max_body_bytes);
        if self.answer_memory_bytes < largest {
            return Err(format!(
                "--answer-memory-bytes ({}) must be at least --max-result-bytes + --max-body-bytes ({largest})",
                self.answer_memory_bytes
            ));
        }
        Ok(Capacity {
            jobs: self.jobs,
            queue: self.queue,
            memory: self.answer_memory_bytes,
            queue_wait: Duration::from_secs_f64(self.queue_seconds),
            bodies: self.body_memory_bytes,
            anonymous_jobs: self.anonymous_jobs,
            anonymous_seconds: Duration::from_secs_f64(self.anonymous_job_seconds),
            ..Capacity::default()
        })
    }

    /// The limit on a job's worker: as given, or half the memory of the
    /// machine (or of its container) shared among the workers of every
    /// share, at least 256 MiB; None where the memory cannot be read.
    pub fn job_memory(&self) -> Option<u64> {
        self.job_memory_bytes.or_else(|| {
            let workers = (self.jobs + self.anonymous_jobs) as u64;
            machine_memory().map(|total| (total / 2 / workers.max(1)).max(256 << 20))
        })
    }

    /// The bounds of the service's connections, its cap from `files` (the
    /// descriptors the process may open) unless given.
    pub fn bounds(&self, files: Option<u64>) -> Bounds {
        let reserve = RESERVED_FILES + OPERATOR_CONNECTIONS as u64;
        let below =
            files.map_or(Bounds::default().max, |n| usize::try_from(n.saturating_sub(reserve)).unwrap_or(usize::MAX));
        Bounds {
            header: Duration::from_secs_f64(self.header_seconds),
            idle: Duration::from_secs_f64(self.idle_seconds),
            max: self.max_connections.unwrap_or(below.clamp(16, MAX_DEFAULT_CONNECTIONS)),
        }
    }

    /// The operator's listener's address, None when `off`.
    pub fn operator(&self) -> Option<&str> {
        Some(self.operator_addr.trim()).filter(|a| !a.eq_ignore_ascii_case("off") && !a.is_empty())
    }

    /// The pace a client must keep sending a body and taking an answer.
    pub fn pace(&self) -> Pace {
        Pace { rate: self.client_min_rate, grace: Duration::from_secs_f64(self.client_grace_seconds) }
    }
}

impl Cli {
    /// How jobs POSTed with `Prefer: respond-async` are run.
    pub fn deferred(&self) -> crate::api::deferred::Settings {
        crate::api::deferred::Settings {
            workers: self.async_workers,
            max_queued: self.async_queue,
            lease: Duration::from_secs_f64(self.async_lease_seconds),
        }
    }

    /// The retention of stored jobs.
    pub fn retention(&self) -> Policy {
        Policy {
            max_age: self.retention_days.map(|d| Duration::from_secs_f64(d * 86_400.0)),
            max_jobs: self.retention_jobs,
            interval: Duration::from_secs_f64(self.retention_interval_seconds),
        }
    }
}

/// The memory the service may use: the machine's (`MemTotal`), or its
/// container's where that is less (cgroup v2's `memory.max`).
pub fn machine_memory() -> Option<u64> {
    let meminfo = std::fs::read_to_string("/proc/meminfo").ok()?;
    let kib = meminfo.lines().find_map(|l| l.strip_prefix("MemTotal:"))?.trim().trim_end_matches("kB").trim();
    let total = kib.parse::<u64>().ok()?.saturating_mul(1024);
    let container =
        std::fs::read_to_string("/sys/fs/cgroup/memory.max").ok().and_then(|t| t.trim().parse::<u64>().ok());
    Some(container.map_or(total, |c| c.min(total)))
}

fn positive_days(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v > 0.0 && v <= 1e6 => Ok(v),
        _ => Err(format!("{s:?} is not a number of days in (0, 1000000]")),
    }
}

fn depth(s: &str) -> Result<usize, String> {
    match s.parse::<usize>() {
        Ok(n) if (1..=MAX_EXPRESSION_DEPTH).contains(&n) => Ok(n),
        _ => Err(format!("{s:?} is not a nesting depth from 1 to {MAX_EXPRESSION_DEPTH}")),
    }
}

fn at_least_one(s: &str) -> Result<usize, String> {
    match s.parse::<usize>() {
        Ok(n) if n >= 1 => Ok(n),
        _ => Err(format!("{s:?} is not a whole number of at least 1")),
    }
}

fn positive_seconds(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v > 0.0 && v <= 86_400.0 => Ok(v),
        _ => Err(format!("{s:?} is not a number of seconds in (0, 86400]")),
    }
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Run the HTTP service (the default).
    Serve,
    /// Exit 0 when the service answers GET /healthz with 200 on --operator-addr, or where that does not answer on --addr (for container health checks).
    Healthcheck,
    /// Print the OpenAPI document.
    Openapi,
    /// Compute jobs for the service that started this process, read from standard input (not run by hand).
    #[command(hide = true)]
    Worker {
        /// The service's process id: the worker ends if it is not its parent.
        #[arg(long)]
        parent: Option<u32>,
        /// The worker's priority (nice), 0 to 19.
        #[arg(long, default_value_t = 0, value_parser = clap::value_parser!(i32).range(0..=19))]
        nice: i32,
    },
    /// Write a consistent copy of the SQLite database (--database) to FILE
    /// while the service runs (SQLite's VACUUM INTO), and check it.
    Backup {
        /// The copy: a new file (an existing one is never overwritten).
        file: PathBuf,
    },
    /// Solve a request file without a server and print the result (same validation as the API).
    Solve {
        /// Job kind: flywheel, kinetostatics, dynamics, gears, gear_train, equivalent_masses, rotor or check.
        kind: String,
        /// Request JSON file ("-" for standard input).
        file: PathBuf,
        /// Print only the value at this JSON pointer of the result (e.g. inertia_exact), as GET .../result/{pointer} answers it.
        #[arg(long)]
        value: Option<String>,
        /// Convert that value to this unit (e.g. slug*ft^2).
        #[arg(long, requires = "value")]
        unit: Option<String>,
    },
    /// Check answers without a server: a POST /v1/check body in, the check's result out.
    Check {
        /// The check's JSON ("-" for standard input).
        file: PathBuf,
    },
    /// Grade a class without a server: print the CSV POST /v1/templates/{id}/grade answers.
    Grade {
        /// A built-in template's id, or a template's JSON file.
        template: String,
        /// The class CSV ("-" for standard input).
        class: PathBuf,
        /// Relative tolerance (default 0.01).
        #[arg(long)]
        relative: Option<String>,
        /// Absolute tolerance, SI (default 0).
        #[arg(long)]
        absolute: Option<String>,
        /// Significant figures (PrairieLearn's rule), replacing the relative tolerance.
        #[arg(long)]
        sigfigs: Option<String>,
        /// Below it (SI) an expected value is compared absolutely (default 1e-12).
        #[arg(long)]
        zero_level: Option<String>,
        /// Whether the feedback shows expected values: true (default) or false.
        #[arg(long)]
        reveal: Option<String>,
    },
}

#[cfg(test)]
mod tests {
    use super::*;

    /// No flags and no environment: the limits are the service's defaults.
    #[test]
    fn without_flags_the_limits_are_the_defaults() {
        let cli = Cli::try_parse_from(["mechdyn"]).unwrap();
        if std::env::vars().all(|(k, _)| !k.starts_with("MECHDYN_")) {
            assert_eq!(cli.limits(), Limits::default());
        }
        let cli = Cli::try_parse_from(["mechdyn", "--max-steps", "7", "--max-expression-depth", "256"]).unwrap();
        assert_eq!((cli.limits().steps, cli.limits().expression_depth), (7, 256));
        assert!(Cli::try_parse_from(["mechdyn", "--max-expression-depth", "257"]).is_err());
        assert!(Cli::try_parse_from(["mechdyn", "--max-segments", "0"]).is_err());
    }
}
