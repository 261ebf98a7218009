//! The `mechdyn` binary: the HTTP service and its command-line helpers.

use clap::Parser;
use mechdyn::api::{self, AppState};
use mechdyn::config::{Cli, Command};
use mechdyn::store::{self, Store};
use std::io::{IsTerminal, Read, Write};
use std::process::ExitCode;
use tracing_subscriber::EnvFilter;

/// mimalloc returns freed memory to the system soon after; glibc's malloc
/// keeps it in per-thread arenas (up to 64 MiB each), and a flood of the
/// largest jobs held 1.5 GiB resident for a live set under half that
/// (docs/SOAK.md: 0.79 GiB peak with mimalloc).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    let cli = Cli::parse();
    // The kinds the service serves: the kinds' wing, then the service's own check.
    let kinds = mechdyn::registry();
    match &cli.command {
        None | Some(Command::Serve) => serve(&cli, kinds),
        Some(Command::Healthcheck) => healthcheck(cli.operator(), &cli.addr),
        Some(Command::Openapi) => match writeln!(std::io::stdout().lock(), "{}", kinds.openapi_json()) {
            // `mechdyn openapi | head` closes the pipe early: not a failure.
            Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => fail(&format!("cannot write: {e}")),
            _ => ExitCode::SUCCESS,
        },
        Some(Command::Backup { file }) => backup(&cli.database, file),
        Some(Command::Worker { parent, nice }) => {
            let options = api::workers::serve::Options { parent: *parent, memory: cli.job_memory_bytes, nice: *nice };
            match api::workers::serve::run(kinds, &options) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => fail(&format!("worker: {e}")),
            }
        }
        Some(Command::Solve { kind, file, value, unit }) => {
            offline(file, |raw| mechdyn::offline::solve(&kinds, kind, raw, value.as_deref(), unit.as_ref()))
        }
        Some(Command::Check { file }) => offline(file, |raw| mechdyn::offline::check(&kinds, raw)),
        Some(Command::Grade { template, class, relative, absolute, sigfigs, zero_level, reveal }) => {
            let t = match mechdyn::offline::template(template) {
                Ok(t) => t,
                Err(e) => return fail(&e),
            };
            let options = [("relative", relative), ("absolute", absolute), ("sigfigs", sigfigs)];
            let options = options.into_iter().chain([("zero_level", zero_level), ("reveal", reveal)]);
            let query = options.filter_map(|(k, v)| Some((k.to_string(), v.clone()?))).collect();
            offline(class, |csv| mechdyn::offline::grade(&kinds, &t, &query, csv.as_bytes()).map(String::into_bytes))
        }
    }
}

fn serve(cli: &Cli, kinds: mechdyn::api::kind::Registry) -> ExitCode {
    tracing_subscriber::fmt()
        .with_ansi(std::io::stdout().is_terminal())
        .with_env_filter(EnvFilter::try_from_default_env().unwrap_or_else(|_| EnvFilter::new("info")))
        .init();
    let workers = cli.capacity().map_or(1, |c| c.workers());
    let runtime = tokio::runtime::Builder::new_multi_thread().worker_threads(workers).enable_all().build();
    let runtime = match runtime {
        Ok(r) => r,
        Err(e) => return fail(&format!("cannot start the runtime: {e}")),
    };
    let ran = runtime.block_on(run(cli, kinds));
    // A deferred job still computing was put back in the queue: its thread is not waited for.
    runtime.shutdown_timeout(std::time::Duration::from_millis(500));
    match ran {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail(&e),
    }
}

async fn run(cli: &Cli, kinds: mechdyn::api::kind::Registry) -> Result<(), String> {
    let shown = store::redact(&cli.database);
    store::check_scheme(&cli.database).map_err(|e| e.to_string())?;
    let capacity = cli.capacity()?;
    let wait = std::time::Duration::from_secs_f64(cli.database_wait_seconds);
    let power_safe = cli.sqlite_synchronous == "full";
    let options = store::Options { max_bytes: cli.max_database_bytes, wait, power_safe };
    let store = Store::open_with(&cli.database, &options)
        .await
        .map_err(|e| format!("database {shown}: {}", e.to_string().replace(&cli.database, &shown)))?;
    let deferred = api::deferred::Deferred::new(cli.deferred());
    let admission = api::Admission::new(capacity);
    let mut state = AppState { limits: cli.limits(), admission, deferred, ..AppState::new(store, kinds) };
    if !cli.in_process {
        state = state.with_workers(workers(cli)?);
    }
    if let Some(pool) = &state.workers {
        pool.warm(api::workers::Share::Holder, cli.jobs)?;
    }
    let settings = api::Settings {
        body_limit: cli.max_body_bytes,
        api_token: cli.api_token.clone().filter(|t| !t.is_empty()),
        public_jobs: cli.public_jobs,
        cors_origins: cli.cors_origins.iter().map(|o| o.trim().to_string()).filter(|o| !o.is_empty()).collect(),
        pace: cli.pace(),
    };
    api::retention::spawn(state.clone(), cli.retention());
    api::watchdog::spawn(state.clone());
    let runner = api::deferred::spawn(state.clone());
    let app = api::router(state.clone(), &settings);
    let listener = api::serve::bind(&cli.addr).await.map_err(|e| format!("bind {}: {e}", cli.addr))?;
    let local = listener.local_addr().map_err(|e| e.to_string())?;
    let bounds = cli.bounds(api::serve::open_files());
    let operator = operator(cli, &state, bounds).await?;
    tracing::info!(addr = %local, database = %shown, connections = bounds.max, "mechdyn listening; docs at http://{local}/docs");
    let (stop, stopped) = tokio::sync::watch::channel(false);
    let stopping = async move {
        shutdown_signal().await;
        let _ = stop.send(true);
        // The deferred jobs this replica computes go back to the queue first.
        if let Some(runner) = runner {
            runner.stop().await;
        }
    };
    let metrics = state.metrics.clone();
    // Every connection takes its answers at the client's minimal pace, or is closed.
    let served = api::serve::serve((listener, "service"), app, (bounds, cli.pace(), metrics), stopping);
    match operator {
        Some(op) => {
            let mut stopped = stopped;
            let stop = async move {
                let _ = stopped.wait_for(|s| *s).await;
            };
            let (listener, settings) = op;
            tokio::join!(served, api::serve::serve(listener, api::operator_router(state.clone()), settings, stop));
        }
        None => served.await,
    }
    tracing::info!("stopped");
    Ok(())
}

/// The worker processes' settings: this very binary (the running one,
/// whatever has replaced its file since), each under the limit on a job's
/// memory; the token holders' workers started now.
fn workers(cli: &Cli) -> Result<api::workers::Settings, String> {
    let program = std::path::PathBuf::from("/proc/self/exe");
    let program = if program.exists() { program } else { std::env::current_exe().map_err(|e| e.to_string())? };
    let memory = cli.job_memory();
    tracing::info!(workers = cli.jobs, memory, "jobs compute in worker processes");
    Ok(api::workers::Settings { program, memory })
}

/// The operator's listener (its connections and bounds), bound at
/// `--operator-addr`: None when `off`, or when the default cannot be bound
/// (another service has it: said, and the service goes on); an address asked
/// for that cannot be bound stops the start.
async fn operator(
    cli: &Cli,
    state: &AppState,
    bounds: api::serve::Bounds,
) -> Result<Option<api::serve::Operator>, String> {
    let Some(addr) = cli.operator() else { return Ok(None) };
    let listener = match api::serve::bind(addr).await {
        Ok(l) => l,
        Err(e) if addr == mechdyn::config::DEFAULT_OPERATOR_ADDR => {
            tracing::warn!(addr, error = %e, "the operator's listener is not bound: /healthz, /readyz and /metrics only on the service's");
            return Ok(None);
        }
        Err(e) => return Err(format!("bind the operator's listener {addr}: {e}")),
    };
    let local = listener.local_addr().map_err(|e| e.to_string())?;
    tracing::info!(addr = %local, "the operator's endpoints (/healthz, /readyz, /metrics) also on their own listener");
    let bounds = api::serve::Bounds { max: mechdyn::config::OPERATOR_CONNECTIONS, ..bounds };
    Ok(Some(((listener, "operator"), (bounds, cli.pace(), state.metrics.clone()))))
}

/// Resolves on SIGINT (Ctrl-C) or SIGTERM (docker stop).
async fn shutdown_signal() {
    let ctrl_c = async {
        let _ = tokio::signal::ctrl_c().await;
    };
    #[cfg(unix)]
    let term = async {
        match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
            Ok(mut s) => {
                s.recv().await;
            }
            Err(_) => std::future::pending::<()>().await,
        }
    };
    #[cfg(not(unix))]
    let term = std::future::pending::<()>();
    tokio::select! { () = ctrl_c => {}, () = term => {} }
    tracing::info!("shutting down: finishing requests in flight");
}

/// `mechdyn backup FILE`: the copy written and checked, what it holds said.
fn backup(database: &str, file: &std::path::Path) -> ExitCode {
    let runtime = match tokio::runtime::Builder::new_current_thread().enable_all().build() {
        Ok(r) => r,
        Err(e) => return fail(&format!("cannot start the runtime: {e}")),
    };
    match runtime.block_on(store::backup::backup(database, file)) {
        Ok(c) => {
            let what = format!("{} jobs and {} templates, {} bytes", c.jobs, c.templates, c.bytes);
            println!(
                "backed up {} to {} ({what}; SQLite's integrity check: ok)",
                store::redact(database),
                file.display()
            );
            ExitCode::SUCCESS
        }
        Err(e) => fail(&format!("backup of {}: {e}", store::redact(database))),
    }
}

/// A plain TCP `GET /healthz`, on the operator's listener (its connections
/// are free while the service's are all taken) or, where it does not answer,
/// on the service's; 0.0.0.0 is probed on loopback.
fn healthcheck(operator: Option<&str>, addr: &str) -> ExitCode {
    let probe = |addr: &str| -> std::io::Result<bool> {
        let target = addr.replace("0.0.0.0", "127.0.0.1").replace("[::]", "[::1]");
        let mut s = std::net::TcpStream::connect(&target)?;
        s.set_read_timeout(Some(std::time::Duration::from_secs(3)))?;
        let request = format!("GET {} HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n", api::HEALTH_PATH);
        s.write_all(request.as_bytes())?;
        let mut head = [0u8; 12];
        s.read_exact(&mut head)?;
        Ok(head.starts_with(b"HTTP/1.1 200"))
    };
    let healthy = operator.into_iter().chain([addr]).map(probe).find_map(Result::ok);
    if healthy == Some(true) { ExitCode::SUCCESS } else { ExitCode::FAILURE }
}

/// Runs an offline command on the text of `file` (`-`: standard input):
/// its output and a newline on stdout, or the problem on stderr (exit 2).
fn offline(
    file: &std::path::Path,
    run: impl FnOnce(String) -> Result<Vec<u8>, mechdyn::kind::problem::ApiError>,
) -> ExitCode {
    let mut raw = String::new();
    let read = if file.as_os_str() == "-" {
        std::io::stdin().read_to_string(&mut raw).map(|_| ())
    } else {
        std::fs::read_to_string(file).map(|s| raw = s)
    };
    if let Err(e) = read {
        return fail(&format!("cannot read {}: {e}", file.display()));
    }
    match run(raw) {
        Ok(out) => {
            let mut stdout = std::io::stdout().lock();
            let newline = if out.ends_with(b"\n") { &b""[..] } else { b"\n" };
            let _ = stdout.write_all(&out).and_then(|()| stdout.write_all(newline));
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{}", serde_json::to_string_pretty(&e.problem()).unwrap_or_default());
            ExitCode::from(2)
        }
    }
}

fn fail(message: &str) -> ExitCode {
    eprintln!("mechdyn: {message}");
    ExitCode::FAILURE
}
