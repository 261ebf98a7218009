//! The deployment example run with real processes: Debian's `haproxy` with
//! `deploy/haproxy.cfg` (the servers' addresses and the error file's path
//! made this test's) in front of three replicas of the binary on one
//! PostgreSQL server ([`PgServer`]). Clients POST through the balancer the
//! whole time; one replica is killed with SIGKILL and started again, then
//! the database is stopped for 10 s and started again. Every job
//! acknowledged (201) is read back through the balancer byte for byte; a
//! request is answered, never left hanging past the client's timeout;
//! during the outage it is a 503 problem document with its reason; the
//! balancer takes a replica out while its /readyz fails and back when it
//! is ready.
//!
//! Without haproxy the test says it is skipped, unless MECHDYN_REQUIRE_HAPROXY
//! is set (CI sets it).

use crate::crash::{flywheel_job, free_port, http, start_logged};
use crate::haproxy::Balancer;
use crate::pg_server::PgServer;
use std::collections::BTreeMap;
use std::process::{Child, Command};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

const CLIENTS: usize = 3;

/// What the clients got: every answer's status, and the acknowledged jobs' bodies.
#[derive(Default)]
struct Seen {
    statuses: BTreeMap<u16, usize>,
    /// Answers that never came (the client's 10 s timeout, a reset).
    lost: Vec<String>,
    /// The balancer's or a replica's errors without a problem document saying why.
    bare: Vec<String>,
    jobs: Vec<(String, String)>,
}

/// Clients POSTing through the balancer until `stop`.
fn clients(port: u16, stop: &Arc<AtomicBool>, seen: &Arc<Mutex<Seen>>) -> Vec<std::thread::JoinHandle<()>> {
    (0..CLIENTS)
        .map(|c| {
            let (stop, seen) = (stop.clone(), seen.clone());
            std::thread::spawn(move || {
                for k in (c..).step_by(CLIENTS) {
                    if stop.load(Ordering::SeqCst) {
                        return;
                    }
                    let answer = http(port, "POST", "/v1/flywheel", &flywheel_job(k));
                    let mut seen = seen.lock().unwrap();
                    match answer {
                        Ok((201, text)) => {
                            let job: serde_json::Value = serde_json::from_str(&text).unwrap();
                            seen.jobs.push((job["id"].as_str().unwrap().to_string(), text));
                            *seen.statuses.entry(201).or_default() += 1;
                        }
                        Ok((status, text)) => {
                            let said = serde_json::from_str::<serde_json::Value>(&text).ok();
                            if status >= 500 && !said.is_some_and(|p| p["detail"].is_string()) {
                                seen.bare.push(format!("{status} {text}"));
                            }
                            *seen.statuses.entry(status).or_default() += 1;
                            drop(seen);
                            std::thread::sleep(Duration::from_millis(50));
                        }
                        Err(e) => seen.lost.push(e.to_string()),
                    }
                }
            })
        })
        .collect()
}

#[test]
fn three_replicas_behind_haproxy_ride_out_a_kill_and_a_database_outage() {
    let test = "three_replicas_behind_haproxy_ride_out_a_kill_and_a_database_outage";
    if Command::new("haproxy").arg("-v").output().is_err() {
        assert!(std::env::var_os("MECHDYN_REQUIRE_HAPROXY").is_none(), "haproxy is required");
        eprintln!("skipped {test}: haproxy (Debian's package) is not installed");
        return;
    }
    let Some(server) = PgServer::start(test) else { return };
    let db = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap().block_on(server.database());
    let ports = [(free_port(), free_port()), (free_port(), free_port()), (free_port(), free_port())];
    let start = |(port, operator): (u16, u16)| {
        let operator = format!("127.0.0.1:{operator}");
        let env = [("RUST_LOG", "warn"), ("MECHDYN_DATABASE_WAIT_SECONDS", "30"), ("MECHDYN_OPERATOR_ADDR", &operator)];
        start_logged(&db, port, &env, None)
    };
    let mut replicas: Vec<Child> = ports.iter().map(|&p| start(p)).collect();
    let lb = Balancer::start(&ports);
    let (stop, seen) = (Arc::new(AtomicBool::new(false)), Arc::new(Mutex::new(Seen::default())));
    let load = clients(lb.port, &stop, &seen);
    std::thread::sleep(Duration::from_secs(2));

    // A replica killed: the balancer takes it out, and back once it is started again.
    replicas[1].kill().unwrap();
    replicas[1].wait().unwrap();
    lb.wait_until(|up| up == 2, "the killed replica taken out");
    std::thread::sleep(Duration::from_secs(2));
    replicas[1] = start(ports[1]);
    let back = lb.wait_until(|up| up == 3, "the restarted replica back");
    eprintln!("{test}: the restarted replica was back in the balancer after {back:.1?}");

    // The database away for 10 s: every replica out while it is, every one back after.
    server.stop();
    let out = lb.wait_until(|up| up == 0, "every replica out without its database");
    eprintln!("{test}: all replicas out {out:.1?} after the database stopped");
    std::thread::sleep(Duration::from_secs(10).saturating_sub(out));
    let restarted = Instant::now();
    server.start_again();
    lb.wait_until(|up| up == 3, "every replica back with its database");
    eprintln!("{test}: all replicas back {:.1?} after the database started again", restarted.elapsed());
    std::thread::sleep(Duration::from_secs(2));
    stop.store(true, Ordering::SeqCst);
    load.into_iter().for_each(|c| c.join().unwrap());

    let seen = Arc::try_unwrap(seen).ok().unwrap().into_inner().unwrap();
    eprintln!("{test}: answers by status {:?}", seen.statuses);
    assert!(seen.lost.is_empty(), "answers that never came: {:?}", seen.lost);
    assert!(seen.bare.is_empty(), "errors without their reason: {:?}", seen.bare);
    assert!(seen.statuses.get(&503).is_some_and(|n| *n > 0), "the outage was answered 503: {:?}", seen.statuses);
    let unexpected: Vec<&u16> = seen.statuses.keys().filter(|s| ![201, 502, 503].contains(*s)).collect();
    assert!(unexpected.is_empty(), "{:?}", seen.statuses);
    assert!(seen.jobs.len() > 20, "{} jobs acknowledged", seen.jobs.len());
    for (id, posted) in &seen.jobs {
        let (status, read) = http(lb.port, "GET", &format!("/v1/jobs/{id}"), "").unwrap();
        assert_eq!(status, 200, "{id}: {read}");
        assert_eq!(&read, posted, "{id}: read back through the balancer as acknowledged");
    }
    for mut r in replicas {
        let _ = r.kill();
        let _ = r.wait();
    }
}

/// HAProxy sends its error files as they are: each answer's Content-Length
/// must be its body's, or a client reads a cut document (or, without one, a
/// body ended only by the connection's close, which wrk and keep-alive
/// clients count as a read error); each is a problem document of its status.
#[test]
fn the_balancer_s_own_answers_say_their_length_and_are_problem_documents() {
    for status in [502, 503, 504] {
        let path = format!("{}/deploy/errors/{status}.http", env!("CARGO_MANIFEST_DIR"));
        let file = std::fs::read_to_string(path).unwrap();
        let (head, body) = file.split_once("\r\n\r\n").unwrap();
        assert!(head.starts_with(&format!("HTTP/1.1 {status} ")), "{head}");
        assert!(head.contains("Content-Type: application/problem+json"), "{head}");
        let length = head.lines().find_map(|l| l.strip_prefix("Content-Length: ")).expect("a Content-Length");
        assert_eq!(length.parse::<usize>().unwrap(), body.len(), "{body}");
        let problem: serde_json::Value = serde_json::from_str(body).unwrap();
        assert_eq!(problem["status"], status);
        assert!(problem["detail"].is_string());
    }
}

/// A replica killed while it computes a request's job: HAProxy answers the
/// client its 502 as a problem document (it sent its HTML page before).
/// One replica on SQLite behind the deployment's configuration.
#[test]
fn a_replica_killed_mid_request_is_answered_502_as_a_problem_document() {
    if Command::new("haproxy").arg("-v").output().is_err() {
        assert!(std::env::var_os("MECHDYN_REQUIRE_HAPROXY").is_none(), "haproxy is required");
        eprintln!("skipped: haproxy (Debian's package) is not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let db = format!("sqlite://{}", dir.path().join("jobs.db").display());
    let (port, operator) = (free_port(), free_port());
    let operator_addr = format!("127.0.0.1:{operator}");
    let env = [("MECHDYN_JOB_SECONDS", "30"), ("MECHDYN_OPERATOR_ADDR", operator_addr.as_str())];
    let mut replica = start_logged(&db, port, &env, None);
    let lb = Balancer::start(&[(port, operator)]);
    let (_, _, long) =
        crate::hostile::requests().into_iter().find(|(n, ..)| n.starts_with("the yoke for 1e5 s")).unwrap();
    let client = std::thread::spawn(move || http(lb.port, "POST", "/v1/dynamics", &long.to_string()));
    std::thread::sleep(Duration::from_secs(2));
    replica.kill().unwrap();
    replica.wait().unwrap();
    let (status, text) = client.join().unwrap().unwrap();
    assert_eq!(status, 502, "{text}");
    let problem: serde_json::Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"));
    assert_eq!(problem["type"], "/problems/replica-failed");
}
