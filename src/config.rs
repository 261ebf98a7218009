//! Command line and environment settings.

use crate::api::limits::{Limits, MAX_EXPRESSION_DEPTH};
use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::time::Duration;

/// Default database: a SQLite file under ./data, created on first start.
pub const DEFAULT_DATABASE: &str = "sqlite://data/mechdyn.db";
/// Default listen address.
pub const DEFAULT_ADDR: &str = "127.0.0.1:8080";

#[derive(Parser, Debug)]
#[command(name = "mechdyn", version, about = "Machine-dynamics calculation service")]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Address to listen on (serve) or to probe (healthcheck).
    #[arg(long, env = "MECHDYN_ADDR", default_value = DEFAULT_ADDR, global = true)]
    pub addr: String,
    /// SQLite database URL.
    #[arg(long, env = "DATABASE_URL", default_value = DEFAULT_DATABASE, global = true)]
    pub database: String,
    /// Largest accepted request body, bytes.
    #[arg(long, env = "MECHDYN_MAX_BODY_BYTES", default_value_t = crate::api::DEFAULT_BODY_LIMIT, global = true)]
    pub max_body_bytes: usize,
    /// When set, every POST must carry `Authorization: Bearer <token>` (401 without it).
    #[arg(long, env = "MECHDYN_API_TOKEN", hide_env_values = true, global = true)]
    pub api_token: Option<String>,
    /// Origins allowed to call the API from a browser (CORS), comma-separated; `*` for any.
    #[arg(long, env = "MECHDYN_CORS_ORIGINS", value_delimiter = ',', global = true)]
    pub cors_origins: Vec<String>,
    /// Wall-clock compute budget of a job, seconds (a job over it is stopped and answered 422).
    #[arg(long, env = "MECHDYN_JOB_SECONDS", default_value_t = 20.0, value_parser = positive_seconds, global = true)]
    pub job_seconds: f64,
    /// Most input positions of a kinetostatics job [default: 100000].
    #[arg(long, env = "MECHDYN_MAX_STEPS", value_parser = at_least_one, global = true)]
    pub max_steps: Option<usize>,
    /// Most result samples of a flywheel or dynamics job [default: 100000].
    #[arg(long, env = "MECHDYN_MAX_SAMPLES", value_parser = at_least_one, global = true)]
    pub max_samples: Option<usize>,
    /// Most rows of a table function [default: 100000].
    #[arg(long, env = "MECHDYN_MAX_TABLE_ROWS", value_parser = at_least_one, global = true)]
    pub max_table_rows: Option<usize>,
    /// Most segments of a piecewise function [default: 1000].
    #[arg(long, env = "MECHDYN_MAX_SEGMENTS", value_parser = at_least_one, global = true)]
    pub max_segments: Option<usize>,
    /// Most characters of an expression [default: 2000].
    #[arg(long, env = "MECHDYN_MAX_EXPRESSION_LENGTH", value_parser = at_least_one, global = true)]
    pub max_expression_length: Option<usize>,
    /// Most levels of nesting of an expression, 1 to 256 [default: 64].
    #[arg(long, env = "MECHDYN_MAX_EXPRESSION_DEPTH", value_parser = clap::value_parser!(u16).range(1..=MAX_EXPRESSION_DEPTH as i64), global = true)]
    pub max_expression_depth: Option<u16>,
}

impl Cli {
    /// The limits on one request: the defaults, with those given replaced.
    pub fn limits(&self) -> Limits {
        let d = Limits::default();
        Limits {
            budget: Duration::from_secs_f64(self.job_seconds),
            steps: self.max_steps.unwrap_or(d.steps),
            samples: self.max_samples.unwrap_or(d.samples),
            table_rows: self.max_table_rows.unwrap_or(d.table_rows),
            segments: self.max_segments.unwrap_or(d.segments),
            expression_length: self.max_expression_length.unwrap_or(d.expression_length),
            expression_depth: self.max_expression_depth.map_or(d.expression_depth, usize::from),
        }
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
    /// Exit 0 when the service at --addr answers GET /healthz with 200 (for container health checks).
    Healthcheck,
    /// Print the OpenAPI document.
    Openapi,
    /// Solve a request file without a server and print the result (same validation as the API).
    Solve {
        /// Job kind: flywheel, kinetostatics, dynamics, gears, gear_train, equivalent_masses or rotor.
        kind: String,
        /// Request JSON file ("-" for standard input).
        file: PathBuf,
    },
}
