//! Command line and environment settings.

use clap::{Parser, Subcommand};
use std::path::PathBuf;

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
