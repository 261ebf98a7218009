//! Crash safety: the real binary on a real SQLite file, POSTed to by several
//! clients, killed with SIGKILL at random moments, restarted; every job that
//! got its 201 must be readable with the same result, and SQLite's
//! `PRAGMA integrity_check` must say ok.

use serde_json::Value;
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

const KILLS: usize = 8;
const CLIENTS: usize = 4;

pub use crate::wire::{free_port, http, http_with};

/// Starts the service on `db` and waits until /healthz answers.
pub fn start(db: &str, port: u16) -> Child {
    start_with(db, port, &[])
}

/// [`start`] with more environment variables.
pub fn start_with(db: &str, port: u16, env: &[(&str, &str)]) -> Child {
    start_logged(db, port, &[("RUST_LOG", "warn")].iter().chain(env).copied().collect::<Vec<_>>(), None)
}

/// [`start_with`], its log (standard output and error) written to `log`.
pub fn start_logged(db: &str, port: u16, env: &[(&str, &str)], log: Option<std::fs::File>) -> Child {
    let (stdout, stderr) = match log {
        Some(file) => (Stdio::from(file.try_clone().unwrap()), Stdio::from(file)),
        None => (Stdio::null(), Stdio::null()),
    };
    // No operator's listener unless asked for: the tests' services would
    // contend for its default port (and a probe of it find another's).
    let child = Command::new(env!("CARGO_BIN_EXE_mechdyn"))
        .env("MECHDYN_OPERATOR_ADDR", "off")
        .envs(env.iter().copied())
        .env("DATABASE_URL", db)
        .env("MECHDYN_ADDR", format!("127.0.0.1:{port}"))
        .stdout(stdout)
        .stderr(stderr)
        .spawn()
        .unwrap();
    let started = Instant::now();
    while !matches!(http(port, "GET", "/healthz", ""), Ok((200, _))) {
        assert!(started.elapsed() < Duration::from_secs(30), "the service did not start");
        std::thread::sleep(Duration::from_millis(10));
    }
    child
}

/// A flywheel job (P.103, no check) whose answer depends on `k` (the
/// irregularity), so every acknowledged result is distinguishable.
pub fn flywheel_job(k: usize) -> String {
    let mut b = crate::helpers::request("p103_slider");
    b["irregularity"] = (0.01 + 0.0001 * (k % 500) as f64).into();
    b["check"] = false.into();
    b.to_string()
}

/// Clients POST until the service dies; returns every (id, result) acknowledged with 201.
fn load_until_killed(port: u16, child: &mut Child, delay: Duration) -> Vec<(String, Value)> {
    let acknowledged = Arc::new(Mutex::new(Vec::new()));
    let stop = Arc::new(AtomicBool::new(false));
    let clients: Vec<_> = (0..CLIENTS)
        .map(|c| {
            let (acknowledged, stop) = (acknowledged.clone(), stop.clone());
            std::thread::spawn(move || {
                for k in (c..).step_by(CLIENTS) {
                    match http(port, "POST", "/v1/flywheel", &flywheel_job(k)) {
                        // A body cut short by the kill is not an acknowledgement.
                        Ok((201, text)) => match serde_json::from_str::<Value>(&text) {
                            Ok(job) => {
                                let id = job["id"].as_str().unwrap().to_string();
                                acknowledged.lock().unwrap().push((id, job["result"].clone()));
                            }
                            Err(_) if stop.load(Ordering::SeqCst) => return,
                            Err(e) => panic!("a 201 that is not a job ({e}): {text}"),
                        },
                        Ok((status, text)) => panic!("unexpected {status}: {text}"),
                        Err(_) if stop.load(Ordering::SeqCst) => return,
                        Err(e) => panic!("the service failed before it was killed: {e}"),
                    }
                }
            })
        })
        .collect();
    std::thread::sleep(delay);
    stop.store(true, Ordering::SeqCst);
    child.kill().unwrap(); // SIGKILL on Unix
    child.wait().unwrap();
    for c in clients {
        c.join().unwrap();
    }
    Arc::try_unwrap(acknowledged).unwrap().into_inner().unwrap()
}

#[test]
fn every_acknowledged_job_survives_sigkill() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("jobs.db");
    let db = format!("sqlite://{}", path.display());
    let mut seed = uuid::Uuid::new_v4().as_u128() as u64 | 1;
    let mut acknowledged = Vec::new();
    for round in 0..KILLS {
        // xorshift64: a kill 50 to 400 ms after the clients start.
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        let delay = Duration::from_millis(50 + seed % 350);
        let port = free_port();
        let mut child = start(&db, port);
        let got = load_until_killed(port, &mut child, delay);
        eprintln!("round {round}: killed after {delay:?}, {} jobs acknowledged", got.len());
        acknowledged.extend(got);
    }
    assert!(acknowledged.len() > KILLS, "too few jobs to test anything: {}", acknowledged.len());

    let port = free_port();
    let mut child = start(&db, port);
    for (id, result) in &acknowledged {
        let (status, text) = http(port, "GET", &format!("/v1/jobs/{id}"), "").unwrap();
        assert_eq!(status, 200, "acknowledged job {id} lost after SIGKILL: {text}");
        let job: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(&job["result"], result, "job {id} changed");
    }
    child.kill().unwrap();
    child.wait().unwrap();
    eprintln!("{KILLS} kills survived, {} acknowledged jobs all readable", acknowledged.len());

    let check = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap().block_on(async {
        use sqlx::Connection;
        let mut c = sqlx::SqliteConnection::connect(&db).await.unwrap();
        sqlx::query_scalar::<_, String>("PRAGMA integrity_check").fetch_one(&mut c).await.unwrap()
    });
    assert_eq!(check, "ok");
}
