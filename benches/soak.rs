//! Bounded soak: `cargo bench --bench soak` (SOAK_SECONDS, default 180;
//! FLOOD_SECONDS, default 90). The release service on a fresh SQLite file,
//! 64 connections of `wrk` on loopback sending a mix of every job kind and
//! reads for the whole run, its resident memory sampled every 5 s; then the
//! flood (`soak/flood.rs`): on a fresh service, the largest jobs the limits
//! allow from 64 and from 256 connections; then the faults
//! (`soak/faults.rs`): SIGKILL under writers, slow clients, the full-disk
//! cycle, the cost of syncing every commit; then the deployment example
//! (`soak/balancer.rs`): one and three replicas on PostgreSQL behind
//! HAProxy, and their recovery from a SIGKILL and a database outage
//! (BALANCER_SECONDS, default 20; SOAK_ONLY=balancer measures this part
//! alone). Writes docs/SOAK.md: throughput,
//! latency, answers by status and socket errors, panics and "database is
//! locked" in the service's log, and memory over time and at its peak. No
//! assertions: benchmarks are not tests.

#[allow(dead_code)]
#[path = "work_precision/http.rs"]
mod http;

#[path = "soak/flood.rs"]
mod flood;

#[path = "soak/faults.rs"]
mod faults;

#[path = "soak/balancer.rs"]
mod balancer;

#[path = "soak/attacks.rs"]
mod attacks;

#[path = "soak/million.rs"]
mod million;

// The tests' attacker on connections, shared as a file.
#[allow(dead_code)]
#[path = "../tests/api/attack.rs"]
mod attack;

// The tests' own PostgreSQL server, HAProxy and HTTP helpers, shared as files.
#[allow(dead_code)]
#[path = "../tests/api/wire.rs"]
mod wire;

#[allow(dead_code)]
#[path = "../tests/api/pg_server.rs"]
mod pg_server;

#[path = "../tests/api/haproxy.rs"]
mod haproxy;

use serde_json::Value;
use std::fmt::Write as _;
use std::process::Command;
use std::time::{Duration, Instant};

const CONNECTIONS: u32 = 64;

pub fn fixture(path: &str) -> Value {
    // Requests live in the problem library; reference cases and seeds with the tests.
    let folder = if path.starts_with("requests/") { "library" } else { "tests/fixtures" };
    let full = format!("{}/{folder}/{path}", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(full).expect("fixture")).expect("fixture JSON")
}

/// P.103's flywheel, exact inertia only: a light job, so that the service
/// around it shows (the balancer, the database, the connections).
pub fn light() -> Value {
    let mut body = fixture("requests/p103_slider.json");
    body["check"] = false.into();
    body["samples"] = 0.into();
    body
}

/// The example of a schema in the committed OpenAPI document.
fn example(schema: &str) -> Value {
    let path = format!("{}/openapi/openapi.json", env!("CARGO_MANIFEST_DIR"));
    let doc: Value = serde_json::from_str(&std::fs::read_to_string(path).expect("openapi.json")).expect("JSON");
    doc["components"]["schemas"][schema]["example"].clone()
}

/// The mix: (method, path, body), sent in turn by every connection.
fn mix() -> Vec<(&'static str, &'static str, Option<Value>)> {
    let mut k1 = fixture("requests/k1_offset_slider_crank.json");
    k1["input"]["steps"] = 36.into();
    vec![
        ("POST", "/v1/flywheel", Some(fixture("requests/p103_slider.json"))),
        ("POST", "/v1/flywheel", Some(fixture("requests/p107_two_stroke.json"))),
        ("POST", "/v1/kinetostatics", Some(k1)),
        ("POST", "/v1/dynamics", Some(fixture("requests/d1_scotch_yoke_machine.json"))),
        ("POST", "/v1/rotor", Some(example("RotorRequest"))),
        ("POST", "/v1/gears/geometry", Some(example("GearRequest"))),
        ("POST", "/v1/gears/train", Some(example("TrainRequest"))),
        ("POST", "/v1/equivalent-masses", Some(example("EquivalentRequest"))),
        ("GET", "/v1/jobs?limit=20", None),
        ("GET", "/healthz", None),
    ]
}

fn lua(mix: &[(&str, &str, Option<Value>)]) -> String {
    let mut s = String::from("local reqs = {\n");
    for (method, path, body) in mix {
        let body = body.as_ref().map_or("nil".into(), |b| format!("[==[{b}]==]"));
        let _ = writeln!(s, "  {{\"{method}\", \"{path}\", {body}}},");
    }
    s + "}\nlocal n = 0\nrequest = function()\n  n = n + 1\n  local r = reqs[(n % #reqs) + 1]\n  \
         if r[3] then\n    return wrk.format(r[1], r[2], {[\"Content-Type\"] = \"application/json\"}, r[3])\n  \
         end\n  return wrk.format(r[1], r[2])\nend\n"
}

fn main() {
    let seconds: u64 = std::env::var("SOAK_SECONDS").ok().and_then(|s| s.parse().ok()).unwrap_or(180);
    if Command::new("wrk").arg("--version").output().is_err() {
        println!("soak skipped: `wrk` is not installed (`apt-get install wrk`)");
        return;
    }
    match std::env::var("SOAK_ONLY").as_deref() {
        Ok("balancer") => return only(balancer::HEADING, balancer::report),
        Ok("attacks") => return only(attacks::HEADING, attacks::report),
        Ok("million") => return only(million::HEADING, million::report),
        _ => {}
    }
    let service = http::start().expect("the service starts");
    let script = tempfile::NamedTempFile::new().expect("temp file");
    std::fs::write(script.path(), lua(&mix())).expect("write the wrk script");
    let (idle, _) = service.memory();
    let mut wrk = Command::new("wrk")
        .args(["-t", "2", "-c", &CONNECTIONS.to_string(), "-d", &format!("{seconds}s"), "--latency", "-s"])
        .arg(script.path())
        .arg(format!("http://{}/", service.addr))
        .stdout(std::process::Stdio::piped())
        .spawn()
        .expect("wrk");
    let start = Instant::now();
    let mut samples = Vec::new();
    while wrk.try_wait().expect("wrk").is_none() {
        std::thread::sleep(Duration::from_secs(5));
        samples.push((start.elapsed().as_secs(), service.memory().0));
    }
    let out = wrk.wait_with_output().expect("wrk output");
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    let (end, peak) = service.memory();
    let log = service.log();
    drop(service);
    let faults = faults::sigkill() + &faults::slow_clients() + &faults::full_disk() + &faults::durability();
    let faults = faults + &balancer::report() + &attacks::report() + &million::report();
    let report = report(seconds, &text, idle, &samples, end, peak, &log) + &flood_report() + &faults;
    println!("{report}");
    let path = format!("{}/docs/SOAK.md", env!("CARGO_MANIFEST_DIR"));
    std::fs::write(&path, report).expect("write docs/SOAK.md");
    println!("wrote {path}");
}

/// `SOAK_ONLY=balancer|attacks|million`: that section of docs/SOAK.md
/// measured again (added at the end if it is not there), the rest kept.
fn only(heading: &str, report: fn() -> String) {
    let path = format!("{}/docs/SOAK.md", env!("CARGO_MANIFEST_DIR"));
    let before = std::fs::read_to_string(&path).unwrap_or_default();
    let report = report();
    println!("{report}");
    let text = match before.find(heading) {
        Some(start) => {
            let rest = &before[start + heading.len()..];
            let end = rest.find("\n## ").map_or(before.len(), |e| start + heading.len() + e);
            format!("{}\n{}\n{}", before[..start].trim_end(), report.trim(), &before[end..])
        }
        None => format!("{}\n{report}", before.trim_end()),
    };
    std::fs::write(&path, text).expect("write docs/SOAK.md");
    println!("wrote {path}");
}

/// What the flood at 256 connections shows about reads and writes.
const READS: &str = "Reads take no job slot, only answer memory (3 times the job; a CSV 12 times, the whole budget for a 16 MB result): under 256 connections they crowd it, and the jobs, which reserve their largest result before computing, mostly wait their turn out and are answered 503.";

/// The flood at 64 and 256 connections, on a fresh service.
fn flood_report() -> String {
    let seconds: u64 = std::env::var("FLOOD_SECONDS").ok().and_then(|s| s.parse().ok()).unwrap_or(90);
    let service = http::start().expect("the service starts");
    let (requests, said) = flood::requests(&service.addr, fixture);
    let mut s = format!(
        "\n## Flood of the largest jobs\n\nOn a fresh service with the default limits (16 MiB per result, as many \
         jobs computing as cores, 64 waiting, 128 MiB of answers in flight), `wrk` sends in turn the largest jobs \
         of three kinds and reads of large results, first from 64 connections (the queue holds them all), then \
         from 256 (beyond jobs + queue: the rest are refused 503 with Retry-After at once). The bound to meet: \
         resident memory at most 1 GiB; every answer a 201, a 200 or a 503 with Retry-After.\n\n{said}"
    );
    for connections in [64, 256] {
        s += &flood::run(&service, &requests, connections, seconds);
    }
    let log = service.log();
    let count = |needle: &str| log.lines().filter(|l| l.contains(needle)).count();
    let _ = writeln!(s, "Panics in the log: {}; errors in the log: {}.", count("panicked"), count("ERROR"));
    let _ = writeln!(s, "\n{READS}");
    s
}

/// Resident memory gained over each quarter of the run, MiB: flat memory
/// gains nothing in the last quarters.
fn quarters(samples: &[(u64, f64)]) -> String {
    let n = samples.len();
    if n < 8 {
        return "too few samples".into();
    }
    let at = |k: usize| samples[(k * (n - 1)) / 4].1;
    (0..4).map(|k| format!("{:+.1}", at(k + 1) - at(k))).collect::<Vec<_>>().join(", ") + " MiB"
}

fn report(seconds: u64, wrk: &str, idle: f64, samples: &[(u64, f64)], end: f64, peak: f64, log: &str) -> String {
    let field = |prefix: &str| {
        wrk.lines().find_map(|l| l.trim().strip_prefix(prefix).map(|v| v.trim().to_string())).unwrap_or_default()
    };
    let warm = samples.iter().find(|(t, _)| *t >= 20).map_or(f64::NAN, |s| s.1);
    let count = |needle: &str| log.lines().filter(|l| l.contains(needle)).count();
    let mut s = format!(
        "# Soak\n\n`cargo bench --bench soak` (SOAK_SECONDS={seconds}): the release service on a fresh SQLite file, \
         {CONNECTIONS} connections of `wrk` on loopback for {seconds} s, each sending in turn: two flywheel jobs \
         (P.103 with the check and table, P.107), a 36-step kinetostatics job (K1), a dynamics job (D1, the scotch \
         yoke as a mechanism), a rotor, gear geometry, gear train and equivalent-masses job, `GET /v1/jobs?limit=20` \
         and `GET /healthz`. Service and `wrk` share the machine's two cores.\n\n\
         | measure | value |\n|---|---|\n"
    );
    let rows = [
        ("requests", field("Requests/sec:").parse::<f64>().map_or("?".into(), |r| format!("{r:.0} per second"))),
        ("latency p50 / p99", format!("{} / {}", field("50%"), field("99%"))),
        ("non-2xx answers", field("Non-2xx or 3xx responses:").parse::<u64>().unwrap_or(0).to_string()),
        ("socket errors", field("Socket errors:")),
        ("panics in the log", count("panicked").to_string()),
        ("\"database is locked\" in the log", count("database is locked").to_string()),
        ("errors in the log", count("ERROR").to_string()),
        ("resident memory idle", format!("{idle:.1} MiB")),
        ("after 20 s of load", format!("{warm:.1} MiB")),
        ("at the end", format!("{end:.1} MiB")),
        ("peak (VmHWM)", format!("{peak:.1} MiB")),
        ("growth over each quarter of the run", quarters(samples)),
    ];
    for (what, value) in rows {
        let value = if value.is_empty() { "none".to_string() } else { value };
        let _ = writeln!(s, "| {what} | {value} |");
    }
    let _ = writeln!(s, "\nResident memory every 5 s (MiB):\n");
    let series: Vec<String> = samples.iter().map(|(t, m)| format!("{t} s: {m:.1}")).collect();
    let _ = writeln!(s, "{}", series.join(", "));
    let _ = writeln!(s, "\nwrk's own summary:\n\n```\n{}\n```", wrk.trim());
    s
}
