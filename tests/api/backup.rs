//! `mechdyn backup FILE`: a consistent copy of the SQLite database taken
//! while the real service runs and a client keeps writing, restored by
//! starting the service on the copy: every job acknowledged before the
//! backup began is read from the copy byte for byte as from the live one.

use crate::crash::{flywheel_job, free_port, http, start};
use std::process::Command;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

fn backup(database: &str, file: &std::path::Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_mechdyn"))
        .args(["backup", file.to_str().unwrap()])
        .env("DATABASE_URL", database)
        .output()
        .unwrap()
}

fn post(port: u16, k: usize) -> String {
    let (status, text) = http(port, "POST", "/v1/flywheel", &flywheel_job(k)).unwrap();
    assert_eq!(status, 201, "{text}");
    serde_json::from_str::<serde_json::Value>(&text).unwrap()["id"].as_str().unwrap().to_string()
}

#[test]
fn a_backup_taken_while_the_service_writes_restores_every_job() {
    let dir = tempfile::tempdir().unwrap();
    let live = format!("sqlite://{}", dir.path().join("live.db").display());
    let port = free_port();
    let service = start(&live, port);
    let before: Vec<String> = (0..40).map(|k| post(port, k)).collect();

    // A client keeps writing while the copy is taken.
    let (stop, during) = (Arc::new(AtomicBool::new(false)), Arc::new(Mutex::new(Vec::new())));
    let writer = {
        let (stop, during) = (stop.clone(), during.clone());
        std::thread::spawn(move || {
            for k in 1000.. {
                if stop.load(Ordering::SeqCst) {
                    return;
                }
                during.lock().unwrap().push(post(port, k));
            }
        })
    };
    std::thread::sleep(Duration::from_millis(200));
    let copy = dir.path().join("copy.db");
    let out = backup(&live, &copy);
    stop.store(true, Ordering::SeqCst);
    writer.join().unwrap();
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{said}{}", String::from_utf8_lossy(&out.stderr));
    assert!(said.contains("SQLite's integrity check: ok"), "{said}");
    assert!(!during.lock().unwrap().is_empty(), "the client wrote during the backup");

    // Restored: the service started on the copy answers every job as the live one does.
    let restored_port = free_port();
    let restored = start(&format!("sqlite://{}", copy.display()), restored_port);
    for id in &before {
        let path = format!("/v1/jobs/{id}");
        let (live_status, live_body) = http(port, "GET", &path, "").unwrap();
        let (status, body) = http(restored_port, "GET", &path, "").unwrap();
        assert_eq!((live_status, status), (200, 200), "{id}: {body}");
        assert_eq!(body, live_body, "{id}: the same bytes from the copy");
    }
    // The copy is a snapshot: it holds the jobs before it and some of those written during it, all whole.
    // "backed up URL to FILE (N jobs and M templates, B bytes; …)"
    let jobs: usize = said.split(" (").nth(1).and_then(|s| s.split(' ').next()).unwrap().parse().unwrap();
    let written = before.len() + during.lock().unwrap().len();
    assert!((before.len()..=written).contains(&jobs), "{jobs} jobs in the copy of {written}");
    for mut child in [service, restored] {
        child.kill().unwrap();
        child.wait().unwrap();
    }
}

/// A backup never overwrites a file, and names the tool for PostgreSQL.
#[test]
fn a_backup_refuses_an_existing_file_and_a_postgresql_url() {
    let dir = tempfile::tempdir().unwrap();
    let live = format!("sqlite://{}", dir.path().join("live.db").display());
    let port = free_port();
    let mut service = start(&live, port);
    post(port, 1);
    let taken = dir.path().join("taken.db");
    std::fs::write(&taken, b"keep me").unwrap();
    let out = backup(&live, &taken);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("exists: a backup never overwrites a file"));
    assert_eq!(std::fs::read(&taken).unwrap(), b"keep me");
    let out = backup("postgres://mechdyn@127.0.0.1:1/mechdyn", &dir.path().join("pg.db"));
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("pg_dump"), "{}", String::from_utf8_lossy(&out.stderr));
    service.kill().unwrap();
    service.wait().unwrap();
}
