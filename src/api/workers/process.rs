//! One worker process and its pipes, driven with the system's blocking
//! calls: a job written in one call, its reply awaited with `poll` until
//! the job's deadline, the process killed and reaped. Its standard error is
//! read line by line by a thread of its own, into the service's log, its
//! last lines kept for the error that ends it.

use super::wire;
use std::collections::VecDeque;
use std::io::{self, BufRead, BufReader, Read};
use std::os::fd::AsFd;
use std::os::unix::process::CommandExt;
use std::path::Path;
use std::process::{Child, ChildStdin, ChildStdout, Command, ExitStatus, Stdio};
use std::sync::{Arc, Mutex, OnceLock, mpsc};
use std::time::Instant;

/// What a worker writes on its standard error when an allocation fails
/// (Rust's handler of a failed allocation, before it aborts).
const OUT_OF_MEMORY: &str = "memory allocation of";

/// Lines of a worker's standard error kept for the log, and characters of each.
const LAST_LINES: usize = 40;
const LINE_CHARS: usize = 400;

/// What a worker wrote on its standard error: whether an allocation
/// failed, and its last lines (a panic's message and backtrace).
#[derive(Default)]
pub struct Said {
    pub out_of_memory: bool,
    pub last: VecDeque<String>,
}

/// One worker process and its pipes.
pub struct Worker {
    child: Child,
    stdin: ChildStdin,
    stdout: ChildStdout,
    /// What its standard error said.
    said: Arc<Mutex<Said>>,
    /// The thread reading its standard error.
    listening: Option<std::thread::JoinHandle<()>>,
}

/// How a worker answered a job.
pub enum Answer {
    Reply(wire::Reply, Vec<u8>),
    /// No answer by the deadline.
    Late,
}

impl Worker {
    /// `program worker` with `args`, its three pipes open.
    pub fn spawn(program: &Path, args: &[String]) -> io::Result<Self> {
        let mut command = Command::new(program);
        // Named so in `ps` (the program may be /proc/self/exe).
        command.arg0("mechdyn").arg("worker").args(args);
        command.stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped());
        let mut child = spawned(command)?;
        let (Some(stdin), Some(stdout), Some(stderr)) = (child.stdin.take(), child.stdout.take(), child.stderr.take())
        else {
            let _ = child.kill();
            let _ = child.wait();
            return Err(io::Error::other("a worker without its pipes"));
        };
        let said = Arc::new(Mutex::new(Said::default()));
        let (pid, heard) = (child.id(), said.clone());
        let listening =
            std::thread::Builder::new().name("worker-stderr".into()).spawn(move || listen(stderr, pid, &heard))?;
        Ok(Self { child, stdin, stdout, said, listening: Some(listening) })
    }

    /// Sends a job, its parts in one write where the pipe takes them (the
    /// worker then wakes once for it).
    pub fn send(&mut self, job: &wire::Job, request: &[u8]) -> io::Result<()> {
        wire::write(&mut &self.stdin, job, request)
    }

    /// The reply to the job sent (a result of at most `max` bytes), or
    /// [`Answer::Late`] where none has come by `deadline`.
    pub fn reply(&mut self, max: usize, deadline: Instant) -> io::Result<Answer> {
        let mut input = BufReader::with_capacity(16 << 10, Deadlined { pipe: &self.stdout, deadline });
        let header = match part(&mut input, wire::MAX_PART) {
            Err(e) if e.kind() == io::ErrorKind::TimedOut => return Ok(Answer::Late),
            header => header?,
        };
        let reply: wire::Reply = serde_json::from_slice(&header).map_err(io::Error::other)?;
        match part(&mut input, max) {
            Err(e) if e.kind() == io::ErrorKind::TimedOut => Ok(Answer::Late),
            body => Ok(Answer::Reply(reply, body?)),
        }
    }

    /// Kills the worker and waits for it.
    pub fn kill(mut self) {
        let _ = self.child.kill();
        let _ = self.finish();
    }

    /// Waits for the worker to end, and for what it wrote on its standard
    /// error; what it said, and how it ended.
    pub fn finish(&mut self) -> (io::Result<ExitStatus>, Said) {
        let status = self.child.wait();
        if let Some(listening) = self.listening.take() {
            let _ = listening.join();
        }
        (status, std::mem::take(&mut *self.said.lock().unwrap_or_else(|e| e.into_inner())))
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        // A worker dropped without `kill` or `finish` (the pool let go of it): not left running.
        if self.listening.is_some() {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
    }
}

/// `command` started by a thread that lasts as long as the process: a
/// worker's parent-death signal fires when the *thread* that started it ends
/// (prctl(2)), and a blocking pool's threads end after some seconds idle —
/// a worker started from one was killed with it, and left unreaped.
fn spawned(command: Command) -> io::Result<Child> {
    type Order = (Command, mpsc::Sender<io::Result<Child>>);
    static SPAWNER: OnceLock<Option<mpsc::Sender<Order>>> = OnceLock::new();
    let spawner = SPAWNER.get_or_init(|| {
        let (orders, taken) = mpsc::channel::<Order>();
        let serve = move || {
            for (mut command, answer) in taken {
                let _ = answer.send(command.spawn());
            }
        };
        std::thread::Builder::new().name("worker-spawner".into()).spawn(serve).ok().map(|_| orders)
    });
    let gone = || io::Error::other("the thread that starts workers could not be started");
    let (answer, answered) = mpsc::channel();
    spawner.as_ref().ok_or_else(gone)?.send((command, answer)).map_err(|_| gone())?;
    answered.recv().map_err(|_| gone())?
}

/// A part of a frame: its length's prefix, then its bytes (at most `max`).
fn part(input: &mut impl Read, max: usize) -> io::Result<Vec<u8>> {
    let mut prefix = [0u8; 4];
    input.read_exact(&mut prefix)?;
    let n = wire::length(prefix)?;
    if n > max {
        return Err(io::Error::other(format!("a reply of {n} bytes, over the {max} allowed")));
    }
    let mut buf = vec![0u8; n];
    input.read_exact(&mut buf)?;
    Ok(buf)
}

/// A pipe read until a deadline: each read waits (`poll`) at most until
/// then, and past it fails with `TimedOut`.
struct Deadlined<'a> {
    pipe: &'a ChildStdout,
    deadline: Instant,
}

impl Read for Deadlined<'_> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        use rustix::event::{PollFd, PollFlags, Timespec, poll};
        loop {
            let left = self.deadline.saturating_duration_since(Instant::now());
            if left.is_zero() {
                return Err(io::ErrorKind::TimedOut.into());
            }
            let timeout = Timespec { tv_sec: left.as_secs() as i64, tv_nsec: i64::from(left.subsec_nanos()) };
            let mut fds = [PollFd::new(&self.pipe, PollFlags::IN)];
            match poll(&mut fds, Some(&timeout)) {
                Ok(0) | Err(rustix::io::Errno::INTR) => continue,
                Ok(_) => return Ok(rustix::io::read(self.pipe.as_fd(), buf)?),
                Err(e) => return Err(e.into()),
            }
        }
    }
}

/// A worker's standard error read line by line (each in the service's log
/// at `debug`), its last lines kept, a failed allocation noted.
fn listen(stderr: std::process::ChildStderr, pid: u32, said: &Mutex<Said>) {
    for line in BufReader::new(stderr).lines() {
        let Ok(mut line) = line else { break };
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
