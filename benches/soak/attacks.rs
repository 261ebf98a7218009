//! Connections as an attacker holds them, beside well-behaved clients
//! (issue 46): thousands of slow heads (a byte every 10 s, opened again as
//! the service closes them), thousands of idle keep-alives, and the cap
//! reached; the light flywheel POST measured by `wrk` meanwhile, the
//! operator's and the service's /healthz probed every second, and the
//! service's memory with the connections held. `SOAK_ONLY=attacks`.

use crate::http::{self, Service};
use crate::wire::{free_port, http as exchange};
use std::fmt::Write as _;
use std::io::Write as _;
use std::net::TcpStream;
use std::time::{Duration, Instant};

pub const HEADING: &str = "## Attacks on connections";

/// Connections an attacker holds: as many as the service's default cap
/// allows on this machine's 20 000 descriptors, with room for wrk's.
const HELD: usize = 15_000;

/// What the probes saw: answered 200 of asked, and the slowest answer (ms).
fn probe(port: u16, seconds: u64) -> (usize, usize, f64) {
    let (mut ok, mut slowest) = (0, 0f64);
    for _ in 0..seconds {
        let started = Instant::now();
        if matches!(exchange(port, "GET", "/healthz", ""), Ok((200, _))) {
            ok += 1;
        }
        slowest = slowest.max(started.elapsed().as_secs_f64() * 1e3);
        std::thread::sleep(Duration::from_secs(1).saturating_sub(started.elapsed()));
    }
    (ok, seconds as usize, slowest)
}

/// One attack: the siege held, wrk's 16 connections for 10 s, the probes,
/// memory: a table row.
fn under(service: &Service, operator: u16, hold: Hold, n: usize) -> String {
    let port: u16 = service.addr.rsplit(':').next().and_then(|p| p.parse().ok()).unwrap_or(0);
    let (before, _) = service.memory();
    let siege = Siege::start(port, n, hold, Duration::from_secs(10));
    let started = Instant::now();
    while siege.held() < n * 9 / 10 && started.elapsed() < Duration::from_secs(30) {
        std::thread::sleep(Duration::from_millis(200));
    }
    let (held, (during, _)) = (siege.held(), service.memory());
    let probes = std::thread::spawn(move || (probe(port, 10), probe(operator, 10)));
    let load = http::wrk_for(&service.addr, "/v1/flywheel", &crate::light(), 16, 10);
    let ((s_ok, s_n, s_slow), (o_ok, o_n, o_slow)) = probes.join().unwrap_or_default();
    let closed = siege.stop();
    let per = (during - before) * 1024.0 / held.max(1) as f64;
    let what = match hold {
        Hold::SlowHead => "slow heads",
        Hold::Idle => "idle keep-alives",
    };
    match load {
        Ok(l) => format!(
            "| {held} {what} | {:.0} | {:.2} ms | {} | {s_ok}/{s_n} (slowest {s_slow:.0} ms) | {o_ok}/{o_n} (slowest {o_slow:.0} ms) | {closed} | {:.0} MiB (+{per:.1} KiB each) |\n",
            l.rate, l.p99, l.non_2xx, during
        ),
        Err(why) => format!("| {held} {what} | wrk failed: {} | | | | | | |\n", why.lines().next().unwrap_or("")),
    }
}

pub fn report() -> String {
    crate::attack::more_files();
    let operator = free_port();
    let op = format!("127.0.0.1:{operator}");
    let mut s = format!(
        "\n{HEADING}\n\nThe release service with its default bounds (a head within 10 s, 60 s idle, at most \
         16 384 connections on this machine's 20 000 descriptors) and its operator's listener, started afresh \
         for each row; an attacker (a thread of the bench, on the same two cores) holds {HELD} connections, \
         each one the service closes opened again, while `wrk` POSTs P.103's light flywheel from 16 connections \
         for 10 s and /healthz is asked every second on both listeners. Before issue 46 the service held every \
         slow connection until its descriptors ran out, and then answered no one.\n\n| attack | jobs/s | p99 | \
         non-2xx | service /healthz | operator /healthz | closed by the service | memory |\n|---|---|---|---|---|---|---|---|\n"
    );
    let fresh = |env: &[(&str, &str)]| {
        let env: Vec<(&str, &str)> =
            [("MECHDYN_OPERATOR_ADDR", op.as_str())].into_iter().chain(env.iter().copied()).collect();
        http::start_with(&env).expect("the service starts")
    };
    let service = fresh(&[]);
    if let Ok(l) = http::wrk_for(&service.addr, "/v1/flywheel", &crate::light(), 16, 10) {
        let _ = writeln!(
            s,
            "| none | {:.0} | {:.2} ms | {} | | | | {:.0} MiB |",
            l.rate,
            l.p99,
            l.non_2xx,
            service.memory().0
        );
    }
    drop(service);
    s += &under(&fresh(&[]), operator, Hold::SlowHead, HELD);
    s += &under(&fresh(&[]), operator, Hold::Idle, HELD);
    // The cap reached: 2000 connections at most, 5000 wanted by the attacker.
    let row = under(&fresh(&[("MECHDYN_MAX_CONNECTIONS", "2000")]), operator, Hold::SlowHead, 5000);
    let _ = write!(s, "{}", row.replacen("| ", "| at a cap of 2000: ", 1));
    let _ = writeln!(
        s,
        "\nAt the cap, a client beyond it is answered 503 (a problem document) at once or its connection reset; \
         wrk counts those as non-2xx, and the service's own /healthz is among them while the attacker holds every \
         place: the operator's listener, with 64 connections of its own, is the one an orchestrator probes. \
         Memory is the service's resident set with the connections held; each one's share is the difference from \
         the fresh service, divided by the connections."
    );
    s
}

/// How an attacker holds its connections.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Hold {
    /// A head started and trickled a byte at a time, never ended.
    SlowHead,
    /// One request answered, then nothing: an idle keep-alive.
    Idle,
}

/// An attacker in a thread holding `n` connections to `port` as `hold`
/// says, trickling a byte into each slow head every `trickle`, and opening
/// again each one the service closes, until stopped.
pub struct Siege {
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
    held: std::sync::Arc<std::sync::atomic::AtomicUsize>,
    thread: std::thread::JoinHandle<usize>,
}

impl Siege {
    pub fn start(port: u16, n: usize, hold: Hold, trickle: Duration) -> Self {
        use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
        let (stop, held) = (std::sync::Arc::new(AtomicBool::new(false)), std::sync::Arc::new(AtomicUsize::new(0)));
        let (stop2, held2) = (stop.clone(), held.clone());
        let open = move || -> Option<TcpStream> {
            match hold {
                Hold::SlowHead => {
                    let mut s = TcpStream::connect(("127.0.0.1", port)).ok()?;
                    s.write_all(b"GET /healthz HTTP/1.1\r\nHost: x\r\nX-Slow: ").ok()?;
                    s.set_nonblocking(true).ok()?;
                    Some(s)
                }
                Hold::Idle => std::panic::catch_unwind(|| crate::attack::idle(port)).ok(),
            }
        };
        let thread = std::thread::spawn(move || {
            let mut conns: Vec<Option<TcpStream>> = (0..n).map(|_| None).collect();
            let (mut closed_count, mut last) = (0, Instant::now() - trickle);
            while !stop2.load(Ordering::Relaxed) {
                let trickling = hold == Hold::SlowHead && last.elapsed() >= trickle;
                for c in conns.iter_mut() {
                    let Some(s) = c.as_mut() else {
                        *c = open();
                        continue;
                    };
                    if crate::attack::closed(s) {
                        closed_count += 1;
                        *c = open();
                    } else if trickling {
                        let _ = s.write(b"a");
                    }
                }
                if trickling {
                    last = Instant::now();
                }
                held2.store(conns.iter().filter(|c| c.is_some()).count(), Ordering::Relaxed);
                std::thread::sleep(Duration::from_millis(100));
            }
            closed_count
        });
        Self { stop, held, thread }
    }

    /// Connections held now.
    pub fn held(&self) -> usize {
        self.held.load(std::sync::atomic::Ordering::Relaxed)
    }

    /// Stops and closes them all: how many the service had closed meanwhile.
    pub fn stop(self) -> usize {
        self.stop.store(true, std::sync::atomic::Ordering::Relaxed);
        self.thread.join().unwrap_or(0)
    }
}
