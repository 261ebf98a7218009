//! Faults, measured on the release binary for docs/SOAK.md: SIGKILL under
//! writers, slow clients with the pace in force, the full-disk cycle with
//! deletes, and what syncing every commit costs. Figures only: the tests
//! (tests/api/crash.rs, slow_clients.rs, full_disk.rs) hold the rules.

use crate::http;
use crate::wire::{exchange, free_port};
use serde_json::Value;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::{Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// One exchange on a fresh connection (`extra`: header lines), the answer
/// awaited 60 s: the status and body, (0, "") when the connection failed.
fn call(port: u16, method: &str, path: &str, extra: &str, body: &str) -> (u16, String) {
    exchange(port, method, path, extra, body, Duration::from_secs(60)).unwrap_or((0, String::new()))
}

/// The release binary, killed (SIGKILL) when dropped.
pub struct Binary(Child);

impl Drop for Binary {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// The binary on `db` at `port` (through `nsenter` into the mount
/// namespace of process `ns` when given), once /healthz answers.
pub fn spawn(db: &str, port: u16, env: &[(&str, &str)], ns: Option<u32>) -> Binary {
    let bin = env!("CARGO_BIN_EXE_mechdyn");
    let mut command = match ns {
        Some(pid) => {
            let mut c = Command::new("nsenter");
            c.args(["-t", &pid.to_string(), "-m", bin]);
            c
        }
        None => Command::new(bin),
    };
    let child = command
        .env("DATABASE_URL", db)
        .env("MECHDYN_ADDR", format!("127.0.0.1:{port}"))
        .env("RUST_LOG", "error")
        .envs(env.iter().copied())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("the binary starts");
    let started = Instant::now();
    while call(port, "GET", "/healthz", "", "").0 != 200 && started.elapsed() < Duration::from_secs(30) {
        std::thread::sleep(Duration::from_millis(20));
    }
    Binary(child)
}

/// P.103 without the check and table, its irregularity set by `k` so
/// that every result differs.
fn light(k: usize) -> String {
    let mut b = crate::fixture("requests/p103_slider.json");
    b["irregularity"] = (0.01 + 0.0001 * (k % 500) as f64).into();
    b["check"] = false.into();
    b["samples"] = 0.into();
    b.to_string()
}

/// Answers counted by status, as `201: 40, 503: 2`.
fn tally(statuses: &[u16]) -> String {
    let mut by: BTreeMap<u16, usize> = BTreeMap::new();
    statuses.iter().for_each(|s| *by.entry(*s).or_default() += 1);
    by.iter().map(|(s, n)| format!("{s}: {n}")).collect::<Vec<_>>().join(", ")
}

/// Least, median and largest of some seconds.
fn spread(mut seconds: Vec<f64>) -> String {
    if seconds.is_empty() {
        return "none".into();
    }
    seconds.sort_by(f64::total_cmp);
    let at = |q: usize| seconds[(q * (seconds.len() - 1)) / 2];
    format!("{:.1} / {:.1} / {:.1} s", at(0), at(1), at(2))
}

/// Eight writers POST until the binary is killed, five times; then every
/// acknowledged job is read back.
pub fn sigkill() -> String {
    let dir = tempfile::tempdir().expect("a folder");
    let db = format!("sqlite://{}/jobs.db", dir.path().display());
    let (mut acknowledged, mut rounds) = (Vec::new(), Vec::new());
    for round in 0..5u64 {
        let port = free_port();
        let binary = spawn(&db, port, &[], None);
        let stop = Arc::new(AtomicBool::new(false));
        let acked = Arc::new(Mutex::new(Vec::new()));
        let writers: Vec<_> = (0..8)
            .map(|w| {
                let (stop, acked) = (stop.clone(), acked.clone());
                std::thread::spawn(move || {
                    for k in (w..).step_by(8).take_while(|_| !stop.load(Ordering::SeqCst)) {
                        if let (201, text) = call(port, "POST", "/v1/flywheel", "", &light(k)) {
                            let job: Value = serde_json::from_str(&text).unwrap_or_default();
                            acked
                                .lock()
                                .unwrap()
                                .push((job["id"].as_str().unwrap_or("").to_string(), job["result"].clone()));
                        }
                    }
                })
            })
            .collect();
        std::thread::sleep(Duration::from_millis(300 + 150 * round));
        stop.store(true, Ordering::SeqCst);
        drop(binary);
        writers.into_iter().for_each(|w| w.join().unwrap());
        let got = std::mem::take(&mut *acked.lock().unwrap());
        rounds.push(got.len());
        acknowledged.extend(got);
    }
    let port = free_port();
    let _binary = spawn(&db, port, &[], None);
    let (mut lost, mut changed) = (0, 0);
    for (id, result) in &acknowledged {
        match call(port, "GET", &format!("/v1/jobs/{id}"), "", "") {
            (200, text) if serde_json::from_str::<Value>(&text).unwrap_or_default()["result"] == *result => {}
            (200, _) => changed += 1,
            _ => lost += 1,
        }
    }
    let rounds: Vec<String> = rounds.iter().map(usize::to_string).collect();
    format!(
        "\n## SIGKILL under writers\n\nThe binary on one SQLite file, 8 clients POSTing flywheel jobs, killed with \
         SIGKILL 300 to 900 ms into each of 5 rounds, then started again and every acknowledged job read back.\n\n\
         | measure | value |\n|---|---|\n| jobs acknowledged (201) per round | {} |\n| acknowledged in all | {} |\n\
         | lost | {lost} |\n| read back with another result | {changed} |\n",
        rounds.join(", "),
        acknowledged.len()
    )
}

/// A POST whose body arrives at 5 bytes/s until it is answered: the
/// status and the seconds it took.
fn trickle(port: u16, body: &str) -> (u16, f64) {
    let Ok(mut s) = TcpStream::connect(("127.0.0.1", port)) else { return (0, 0.0) };
    let _ = s.set_read_timeout(Some(Duration::from_millis(200)));
    let head = format!(
        "POST /v1/flywheel HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: {}\r\n\r\n",
        body.len()
    );
    let started = Instant::now();
    let _ = s.write_all(head.as_bytes());
    for byte in body.as_bytes() {
        let _ = s.write_all(&[*byte]);
        let mut buf = [0u8; 64];
        match s.read(&mut buf) {
            Ok(0) => break,
            Ok(n) => {
                let status = String::from_utf8_lossy(&buf[..n]).get(9..12).and_then(|c| c.parse().ok()).unwrap_or(0);
                return (status, started.elapsed().as_secs_f64());
            }
            Err(_) => {}
        }
    }
    (0, started.elapsed().as_secs_f64())
}

/// `path` read at about 1 KB/s on a connection that buffers 4 KiB: the
/// seconds until the service let it go (None: still open after 120 s).
fn read_slowly(port: u16, path: &str) -> Option<f64> {
    let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().ok()?;
    let stream = rt.block_on(async {
        let socket = tokio::net::TcpSocket::new_v4().ok()?;
        socket.set_recv_buffer_size(4096).ok()?;
        socket.connect(([127, 0, 0, 1], port).into()).await.ok()
    })?;
    let mut s = stream.into_std().ok()?;
    s.set_nonblocking(false).ok()?;
    let _ = s.set_read_timeout(Some(Duration::from_secs(10)));
    let _ = write!(s, "GET {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
    let started = Instant::now();
    while started.elapsed() < Duration::from_secs(120) {
        let mut buf = [0u8; 100];
        if !matches!(s.read(&mut buf), Ok(n) if n > 0) {
            return Some(started.elapsed().as_secs_f64());
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    None
}

/// Another client's POSTs and list reads for `seconds`: their statuses.
fn meanwhile(port: u16, seconds: u64) -> (Vec<u16>, Vec<u16>) {
    let (mut posts, mut lists) = (Vec::new(), Vec::new());
    let started = Instant::now();
    for k in 0.. {
        if started.elapsed() >= Duration::from_secs(seconds) {
            break;
        }
        posts.push(call(port, "POST", "/v1/flywheel", "", &light(k)).0);
        lists.push(call(port, "GET", "/v1/jobs?limit=2", "", "").0);
    }
    (posts, lists)
}

/// Clients that trickle bodies, then clients that read a large answer a
/// kilobyte a second, against the default limits and pace.
pub fn slow_clients() -> String {
    let dir = tempfile::tempdir().expect("a folder");
    let port = free_port();
    let _binary = spawn(&format!("sqlite://{}/jobs.db", dir.path().display()), port, &[], None);
    let slots = 2 * std::thread::available_parallelism().map_or(2, |n| n.get()) + 64;
    let body = light(0);
    let tricklers: Vec<_> = (0..slots)
        .map(|_| {
            let body = body.clone();
            std::thread::spawn(move || trickle(port, &body))
        })
        .collect();
    std::thread::sleep(Duration::from_millis(500));
    let (posts, _) = meanwhile(port, 8);
    let trickled: Vec<(u16, f64)> = tricklers.into_iter().map(|t| t.join().unwrap()).collect();
    let mut large = crate::fixture("requests/p113_pulley.json");
    large["samples"] = 60_000.into();
    let (_, text) = call(port, "POST", "/v1/flywheel", "", &large.to_string());
    let size = text.len();
    let id = serde_json::from_str::<Value>(&text).unwrap_or_default()["id"].as_str().unwrap_or("").to_string();
    let readers: Vec<_> = (0..10)
        .map(|_| {
            let path = format!("/v1/jobs/{id}");
            std::thread::spawn(move || read_slowly(port, &path))
        })
        .collect();
    std::thread::sleep(Duration::from_millis(500));
    let (read_posts, lists) = meanwhile(port, 15);
    let readers: Vec<Option<f64>> = readers.into_iter().map(|r| r.join().unwrap()).collect();
    let statuses: Vec<u16> = trickled.iter().map(|t| t.0).collect();
    format!(
        "\n## Slow clients, with the pace in force\n\nThe defaults: a body must keep arriving, and an answer must be \
         taken, at 32 KiB/s once 5 s have passed; {slots} job slots (jobs + queue).\n\n\
         | measure | value |\n|---|---|\n\
         | bodies trickled at 5 bytes/s, one per slot ({slots}) | answered {} |\n\
         | time until each was let go (least / median / most) | {} |\n\
         | another client's POSTs meanwhile (8 s) | {} |\n\
         | clients reading a {:.1} MB job at 1 KB/s | 10, each let go after (least / median / most) {} ({} still open after 120 s) |\n\
         | another client's POSTs meanwhile (15 s) | {} |\n\
         | its jobs lists meanwhile | {} |\n",
        tally(&statuses),
        spread(trickled.iter().map(|t| t.1).collect()),
        tally(&posts),
        size as f64 / 1e6,
        spread(readers.iter().flatten().copied().collect()),
        readers.iter().filter(|r| r.is_none()).count(),
        tally(&read_posts),
        tally(&lists),
    )
}

/// A tmpfs of 3 MiB in a mount namespace of its own, 1 MiB of it ballast,
/// kept by a holder process (killed on drop); None without root.
struct SmallDisk(Child, tempfile::TempDir);

impl SmallDisk {
    fn new() -> Option<Self> {
        let folder = tempfile::tempdir().ok()?;
        let dir = folder.path().display().to_string();
        let script = format!(
            "mount -t tmpfs -o size=3m tmpfs {dir} && dd if=/dev/zero of={dir}/ballast bs=1k count=1024 \
             2>/dev/null && touch {dir}/ready && exec sleep 100000"
        );
        let holder = Command::new("unshare").args(["-m", "sh", "-c", &script]).stderr(Stdio::null()).spawn().ok()?;
        let disk = Self(holder, folder);
        let started = Instant::now();
        while !disk.run(&format!("test -f {dir}/ready")) {
            if started.elapsed() > Duration::from_secs(5) {
                return None;
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        Some(disk)
    }

    fn run(&self, command: &str) -> bool {
        let pid = self.0.id().to_string();
        let status =
            Command::new("nsenter").args(["-t", &pid, "-m", "sh", "-c", command]).stderr(Stdio::null()).status();
        status.is_ok_and(|s| s.success())
    }

    fn db(&self) -> String {
        format!("sqlite://{}/jobs.db", self.1.path().display())
    }
}

impl Drop for SmallDisk {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// The id and result of a job's answer.
fn job(text: &str) -> (String, Value) {
    let j: Value = serde_json::from_str(text).unwrap_or_default();
    (j["id"].as_str().unwrap_or("").to_string(), j["result"].clone())
}

/// Fill, delete, defer, free, write, SIGKILL, restart, on a real 3 MiB
/// filesystem: what each step answered and what the restart found.
pub fn full_disk() -> String {
    let Some(disk) = SmallDisk::new() else {
        return "\n## The full-disk cycle\n\nSkipped: this machine does not allow a tmpfs in a mount namespace (needs root).\n".into();
    };
    let mut body = crate::fixture("requests/p113_pulley.json");
    body["samples"] = 300.into();
    let body = body.to_string();
    let (port, ns) = (free_port(), Some(disk.0.id()));
    let binary = spawn(&disk.db(), port, &[], ns);
    let mut stored = Vec::new();
    let full = loop {
        match call(port, "POST", "/v1/flywheel", "", &body) {
            (201, text) if stored.len() < 2000 => stored.push(job(&text)),
            other => break other.0,
        }
    };
    let filled = stored.len();
    let ready_full = call(port, "GET", "/readyz", "", "");
    let mut deletes = Vec::new();
    let mut deleted = Vec::new();
    for (id, result) in stored.drain(..10.min(stored.len())).collect::<Vec<_>>() {
        let (status, _) = call(port, "DELETE", &format!("/v1/jobs/{id}"), "", "");
        deletes.push(status);
        if status == 204 { deleted.push(id) } else { stored.push((id, result)) }
    }
    let prefer = "Prefer: respond-async\r\n";
    let mut deferred = Vec::new();
    let (deferred_full, text) = call(port, "POST", "/v1/flywheel", prefer, &body);
    if deferred_full == 202 {
        deferred.push(job(&text).0);
    }
    disk.run(&format!("rm {}/ballast", disk.1.path().display()));
    let ready_freed = call(port, "GET", "/readyz", "", "").0;
    let mut after = Vec::new();
    for _ in 0..3 {
        let (status, text) = call(port, "POST", "/v1/flywheel", "", &body);
        after.push(status);
        if status == 201 {
            stored.push(job(&text))
        }
    }
    let (id, _) = stored.remove(0);
    let delete_freed = call(port, "DELETE", &format!("/v1/jobs/{id}"), "", "").0;
    if delete_freed == 204 {
        deleted.push(id)
    }
    let (deferred_freed, text) = call(port, "POST", "/v1/flywheel", prefer, &body);
    if deferred_freed == 202 {
        deferred.push(job(&text).0)
    }
    drop(binary);
    let port = free_port();
    let _binary = spawn(&disk.db(), port, &[], ns);
    let kept = stored
        .iter()
        .filter(|(id, r)| {
            let (status, text) = call(port, "GET", &format!("/v1/jobs/{id}"), "", "");
            status == 200 && job(&text).1 == *r
        })
        .count();
    let found = deferred.iter().filter(|id| call(port, "GET", &format!("/v1/jobs/{id}"), "", "").0 == 200).count();
    let gone = deleted.iter().filter(|id| call(port, "GET", &format!("/v1/jobs/{id}"), "", "").0 == 404).count();
    let reason: Value = serde_json::from_str(&ready_full.1).unwrap_or_default();
    format!(
        "\n## The full-disk cycle\n\nThe binary on a real 3 MiB tmpfs (1 MiB of it ballast) in a mount namespace of \
         its own: flywheel jobs of about 30 kB POSTed until the disk is full, ten of them deleted on the full disk, \
         one deferred, the ballast removed, three more stored, one deleted, one deferred, then SIGKILL and a \
         restart on the same files.\n\n\
         | step | answers |\n|---|---|\n\
         | POSTs until full | {} stored, then {full} |\n\
         | /readyz on the full disk | {} ({}) |\n\
         | ten DELETEs on the full disk | {} |\n\
         | a deferred POST on the full disk | {deferred_full} |\n\
         | /readyz once space returned | {ready_freed} |\n\
         | three POSTs, a DELETE, a deferred POST | {}; {delete_freed}; {deferred_freed} |\n\
         | after SIGKILL and restart: acknowledged jobs there, same result | {kept} of {} |\n\
         | deferred jobs answered 202 there | {found} of {} |\n\
         | jobs deleted with a 204 gone | {gone} of {} |\n",
        filled,
        ready_full.0,
        reason["reason"].as_str().unwrap_or(""),
        tally(&deletes),
        tally(&after),
        stored.len(),
        deferred.len(),
        deleted.len(),
    )
}

/// Light flywheel jobs from 64 connections with the log synced at every
/// commit and at checkpoints only, three runs each, alternating.
pub fn durability() -> String {
    let mut light = crate::fixture("requests/p103_slider.json");
    light["check"] = false.into();
    light["samples"] = 0.into();
    let mut s = String::from(
        "\n## What syncing every commit costs\n\nLight flywheel jobs (P.103, exact inertia only) from 64 connections \
         of `wrk`, 5 s a run, on a fresh SQLite file on this machine's disk: `--sqlite-synchronous full` (the \
         default: a 201 survives a power loss) against `normal` (it survives a crash of the process), alternating.\n\n\
         | setting | jobs/s | p50 | p99 |\n|---|---|---|---|\n",
    );
    for mode in ["full", "normal", "full", "normal", "full", "normal"] {
        let Ok(service) = http::start_with(&[("MECHDYN_SQLITE_SYNCHRONOUS", mode)]) else { continue };
        match http::wrk(&service, "/v1/flywheel", &light, 64) {
            Ok((rate, p50, p99, _)) => {
                let _ = writeln!(s, "| {mode} | {rate:.0} | {p50:.2} ms | {p99:.2} ms |");
            }
            Err(why) => {
                let _ = writeln!(s, "| {mode} | failed: {} | | |", why.lines().next().unwrap_or(""));
            }
        }
    }
    s
}
