//! The worker's side: `mechdyn worker`, started by the service
//! ([`super::Pool`]), reads jobs from its standard input and writes each
//! reply to its standard output ([`super::wire`]), one job at a time, until
//! the service closes its input or dies (the worker is then killed with it:
//! the parent's death signal). It computes as the service would in-process:
//! the kind's strict reading of the request, its computation within the
//! job's limits, the result's JSON within the limit on a result.
//!
//! Before the first job it puts itself under the limits the service asks:
//! the operating system's limit on its data (a failed allocation then ends
//! it, and the service answers the job 422 `/problems/job-memory`), and a
//! lower priority for the jobs of requests without the token.

use super::wire::{self, Reply};
use crate::api::kind::Registry;
use bytes::Bytes;
use std::io;
use std::time::Instant;

/// The stack of the thread that computes: what a job may recurse into (an
/// expression's parser, a mechanism's search), the same whatever the
/// system's default for a process's first thread.
const STACK: usize = 8 << 20;

/// What the service asks of a worker when it starts it.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// The service's process id: the worker ends if it is no longer its parent.
    pub parent: Option<u32>,
    /// The limit on the worker's data, bytes.
    pub memory: Option<u64>,
    /// Its priority, 0 (the service's) to 19 (the lowest).
    pub nice: i32,
}

/// Serves jobs until the service closes the worker's input.
pub fn run(kinds: Registry, options: &Options) -> Result<(), String> {
    use rustix::process::{Resource, Rlimit, Signal};
    // Killed with the service, whatever ends it.
    rustix::process::set_parent_process_death_signal(Some(Signal::KILL)).map_err(|e| format!("prctl: {e}"))?;
    let parent = rustix::process::getppid().map(|p| p.as_raw_pid().unsigned_abs());
    if options.parent.is_some_and(|p| Some(p) != parent) {
        return Err("the service that started this worker has ended".into());
    }
    if options.nice != 0 {
        rustix::process::setpriority_process(None, options.nice).map_err(|e| format!("the priority: {e}"))?;
    }
    let memory = options.memory;
    let computing = std::thread::Builder::new().name("job".into()).stack_size(STACK).spawn(move || {
        // Once the thread's stack is mapped: the limit counts it, and would refuse it.
        if let Some(bytes) = memory {
            let limit = Rlimit { current: Some(bytes), maximum: Some(bytes) };
            rustix::process::setrlimit(Resource::Data, limit).map_err(|e| format!("the memory limit: {e}"))?;
        }
        serve(&kinds).map_err(|e| format!("the service's pipe: {e}"))
    });
    match computing.map_err(|e| format!("the job's thread: {e}"))?.join() {
        Ok(served) => served,
        // The panic's message is on standard error already; the exit code tells the service.
        Err(_) => std::process::exit(101),
    }
}

/// Each job read, computed and answered, until the input ends.
fn serve(kinds: &Registry) -> io::Result<()> {
    let (mut input, mut output) = (io::stdin().lock(), wire::Unbuffered(io::stdout()));
    while let Some((header, body)) = wire::read(&mut input)? {
        let job: wire::Job = serde_json::from_slice(&header).map_err(io::Error::other)?;
        #[cfg(debug_assertions)]
        super::faults::inject(&body);
        let started = Instant::now();
        let computed = match kinds.find(&job.kind) {
            Some(kind) => kind.run(Bytes::from(body), &job.limits),
            None => Err(crate::kind::problem::ApiError::Internal(format!("no kind '{}'", job.kind))),
        };
        let micros = u64::try_from(started.elapsed().as_micros()).unwrap_or(u64::MAX);
        match computed {
            Ok(result) => wire::write(&mut output, &Reply::Done { micros }, &result)?,
            Err(e) => wire::write(&mut output, &Reply::Failed(e.into()), &[])?,
        }
    }
    Ok(())
}
