//! The deployment example measured for docs/SOAK.md: Debian's `haproxy`
//! with `deploy/haproxy.cfg` (the tests' [`Balancer`]) in front of one and
//! of three replicas of the release binary on one PostgreSQL server (the
//! tests' [`PgServer`]). Jobs/s and latency from `wrk` through the
//! balancer; then, under the same load on three replicas, the faults of
//! tests/api/balancer.rs with how long the balancer took to see each and
//! to take the replicas back. Figures only: the test holds the rules
//! (every acknowledged job kept, every request answered).

use crate::faults::{Binary, spawn};
use crate::haproxy::Balancer;
use crate::http::{Load, wrk_for};
use crate::pg_server::PgServer;
use crate::wire::free_port;
use std::fmt::Write as _;
use std::process::Command;
use std::time::{Duration, Instant};

const CONNECTIONS: u32 = 64;
/// This part's heading in docs/SOAK.md (it is the last part).
pub const HEADING: &str = "\n## Through the load balancer\n";
const ENV: [(&str, &str); 1] = [("MECHDYN_DATABASE_WAIT_SECONDS", "30")];

fn seconds() -> u64 {
    std::env::var("BALANCER_SECONDS").ok().and_then(|s| s.parse().ok()).unwrap_or(20)
}

/// A replica on `db` at its service's and operator's ports.
fn replica(db: &str, (port, operator): (u16, u16)) -> Binary {
    let operator = format!("127.0.0.1:{operator}");
    spawn(db, port, &[ENV[0], ("MECHDYN_OPERATOR_ADDR", &operator)], None)
}

/// `n` replicas on `db` and the balancer in front of them.
fn deployment(db: &str, n: usize) -> (Vec<(u16, u16)>, Vec<Binary>, Balancer) {
    let ports: Vec<(u16, u16)> = (0..n).map(|_| (free_port(), free_port())).collect();
    let replicas = ports.iter().map(|&p| replica(db, p)).collect();
    let lb = Balancer::start(&ports);
    (ports, replicas, lb)
}

fn row(s: &mut String, what: &str, load: &Result<Load, String>) {
    let _ = match load {
        Ok(l) => writeln!(
            s,
            "| {what} | {:.0} | {:.2} ms | {:.2} ms | {} | {} |",
            l.rate,
            l.p50,
            l.p99,
            l.non_2xx,
            if l.socket_errors.is_empty() { "none" } else { &l.socket_errors }
        ),
        Err(why) => writeln!(s, "| {what} | failed: {} | | | | |", why.lines().next().unwrap_or("")),
    };
}

pub fn report() -> String {
    let mut s = format!("{HEADING}\n");
    if Command::new("haproxy").arg("-v").output().is_err() {
        return s + "Skipped: `haproxy` (Debian's package) is not installed.\n";
    }
    let Some(server) = PgServer::start("soak") else {
        return s + "Skipped: PostgreSQL (Debian's package) is not installed.\n";
    };
    let runtime = tokio::runtime::Builder::new_current_thread().enable_all().build().expect("a runtime");
    let seconds = seconds();
    let _ = write!(
        s,
        "The deployment example (`deploy/haproxy.cfg`, Debian's HAProxy) in front of replicas of the release \
         binary on one PostgreSQL server (Debian's, fsync off), all on this machine's two cores with `wrk`: \
         {CONNECTIONS} connections POSTing light flywheel jobs (P.103, exact inertia only) for {seconds} s, each \
         run on a fresh database.\n\n\
         | replicas | jobs/s | p50 | p99 | non-2xx | socket errors |\n|---|---|---|---|---|---|\n"
    );
    for n in [1, 3] {
        let db = runtime.block_on(server.database());
        let (_ports, _replicas, lb) = deployment(&db, n);
        let load = wrk_for(&format!("127.0.0.1:{}", lb.port), "/v1/flywheel", &crate::light(), CONNECTIONS, seconds);
        row(&mut s, &n.to_string(), &load);
    }
    s += "\nThe replicas share this machine's two cores with HAProxy, PostgreSQL and wrk, so three give no more \
          jobs per second than one here: on one machine they are for availability, across machines for capacity.\n";
    let db = runtime.block_on(server.database());
    s + &faults(&server, &db)
}

/// `fault` run while `wrk` loads the balancer for `seconds`, starting 3 s in.
fn under_load<T>(lb: &Balancer, seconds: u64, fault: impl FnOnce() -> T) -> (T, Result<Load, String>) {
    let addr = format!("127.0.0.1:{}", lb.port);
    let load = std::thread::spawn(move || wrk_for(&addr, "/v1/flywheel", &crate::light(), CONNECTIONS, seconds));
    std::thread::sleep(Duration::from_secs(3));
    let seen = fault();
    (seen, load.join().expect("wrk"))
}

/// Three replicas under the same load: one SIGKILLed and started again 2 s
/// after the balancer had it out (15 s of load); then the database stopped
/// for 10 s (25 s of load).
fn faults(server: &PgServer, db: &str) -> String {
    let (ports, mut replicas, lb) = deployment(db, 3);
    let ((out, started, back), kill) = under_load(&lb, 15, || {
        drop(replicas.remove(1));
        let out = lb.wait_until(|up| up == 2, "the killed replica taken out");
        std::thread::sleep(Duration::from_secs(2));
        let restarted = Instant::now();
        replicas.insert(1, replica(db, ports[1]));
        let started = restarted.elapsed();
        lb.wait_until(|up| up == 3, "the restarted replica back");
        (out, started, restarted.elapsed())
    });
    let ((all_out, all_back), outage) = under_load(&lb, 25, || {
        server.stop();
        let all_out = lb.wait_until(|up| up == 0, "every replica out without its database");
        std::thread::sleep(Duration::from_secs(10).saturating_sub(all_out));
        let again = Instant::now();
        server.start_again();
        lb.wait_until(|up| up == 3, "every replica back with its database");
        (all_out, again.elapsed())
    });

    let mut s = format!(
        "\nThe faults, under the same load on three replicas: one replica killed with SIGKILL and started again 2 s \
         after the balancer had it out (15 s of load), then the database stopped for 10 s and started again (25 s \
         of load). The balancer checks /readyz every second, takes a replica out after 2 failures and back after 2 \
         successes.\n\n\
         | fault | the balancer had it out after | back after it was started again |\n|---|---|---|\n\
         | a replica killed (SIGKILL) | {out:.1?} | {back:.1?} (the process answered /healthz after {started:.1?}) |\n\
         | PostgreSQL stopped for 10 s | every replica out after {all_out:.1?} | every replica back after {all_back:.1?} |\n\n\
         | load through the fault | jobs/s | p50 | p99 | non-2xx | socket errors |\n|---|---|---|---|---|---|\n"
    );
    row(&mut s, "a replica killed, 15 s", &kill);
    row(&mut s, "the database away, 25 s", &outage);
    s + "\nWhen the replica is killed, the requests it held lose their answer: HAProxy answers them 502 or closes their connections (wrk's read errors), and a client \
         retries them safely with an Idempotency-Key. During the outage the non-2xx answers are 503 problem documents: the replicas' own (the database \
         unavailable) for the requests they held when it stopped, each after at most the pool's 5 s wait, then \
         HAProxy's (no replica ready), at once. wrk corrects its latencies for coordinated omission: the requests \
         a connection would have sent while it waited those 5 s count at the latencies they would have had, which \
         is the p99 of that run. tests/api/balancer.rs reads every acknowledged job back byte for byte.\n"
}
