//! A full disk is a condition, not a bug: the real binary on a real, small
//! filesystem (a 3 MiB tmpfs in a mount namespace of its own, part of it
//! taken by a ballast file) answers 507 `/problems/storage-full` once the
//! disk is full, keeps serving reads and /healthz, loses no acknowledged
//! job, and stores jobs again once space returns (the ballast removed).
//! Also the size cap an operator can set (`--max-database-bytes`), and the
//! refusal of a database URL this version cannot serve.

use crate::helpers::request;
use crate::small_disk::SmallDisk;
use mechdyn::store::{NewJob, Options, Store, StoreError};
use serde_json::Value;
use std::process::Command;

/// One HTTP exchange with curl-like plainness: (status, body).
fn http(port: u16, method: &str, path: &str, body: &str) -> (u16, String) {
    crate::crash::http(port, method, path, body).unwrap_or((0, String::new()))
}

#[test]
fn a_full_disk_is_answered_507_and_writes_resume_when_space_returns() {
    let Some(disk) = SmallDisk::new(3 << 10, 1024) else {
        eprintln!("skipped: this machine does not allow a tmpfs in a mount namespace (needs root)");
        return;
    };
    let port = crate::crash::free_port();
    let _child = disk.start(port, &[]);
    let mut body = request("p113_pulley");
    body["samples"] = 2000.into();
    let body = body.to_string();
    let (mut stored, full) = crate::small_disk::fill(port, &body);
    assert_eq!(full.0, 507, "{}", full.1);
    let problem: Value = serde_json::from_str(&full.1).unwrap();
    assert_eq!(problem["type"], "/problems/storage-full", "{problem}");
    assert!(!stored.is_empty(), "some jobs fit before the disk filled");
    // Reads and the health check go on; no acknowledged job is lost.
    assert_eq!(http(port, "GET", "/healthz", "").0, 200);
    assert_eq!(http(port, "POST", "/v1/flywheel", &body).0, 507, "still full");
    let read_all = |stored: &[(String, Value)]| {
        for (id, result) in stored {
            let (status, text) = http(port, "GET", &format!("/v1/jobs/{id}"), "");
            assert_eq!(status, 200, "{id}: {text}");
            assert_eq!(&serde_json::from_str::<Value>(&text).unwrap()["result"], result, "{id}");
        }
    };
    read_all(&stored);
    // Space returns: the ballast goes; the next POST is stored.
    disk.free();
    let (status, text) = http(port, "POST", "/v1/flywheel", &body);
    assert_eq!(status, 201, "{text}");
    let job: Value = serde_json::from_str(&text).unwrap();
    stored.push((job["id"].as_str().unwrap().to_string(), job["result"].clone()));
    read_all(&stored);
    eprintln!("{} jobs stored before the disk was full, all read back; writes resumed", stored.len() - 1);
}

fn job(k: usize, bytes: usize) -> NewJob {
    NewJob {
        id: format!("job-{k}"),
        kind: "flywheel".into(),
        created_at: "2026-11-23T00:00:00.000000Z".into(),
        request: "{}".into(),
        result: format!("\"{}\"", crate::helpers::noise(bytes, k as u64)).into(),
        engine_us: 1,
        engine_version: "test".into(),
        request_key: None,
        label: None,
    }
}

/// The write-ahead log is checkpointed every 100 pages (SQLite's default is
/// 1000): while 8 MB of jobs (~6 MB compressed) are written one after another it stays within
/// 100 pages and one job's (4 KiB pages: ~420 KB plus a job); at the default
/// it would reach ~4 MB. The log file keeps its largest size, so its size
/// at the end bounds it throughout.
#[tokio::test]
async fn the_write_ahead_log_stays_near_a_hundred_pages() {
    let dir = tempfile::tempdir().unwrap();
    let url = format!("sqlite://{}/jobs.db", dir.path().display());
    let store = Store::open(&url).await.unwrap();
    for k in 0..400 {
        store.insert(job(k, 20_000)).await.unwrap();
    }
    let wal = std::fs::metadata(dir.path().join("jobs.db-wal")).unwrap().len();
    let bound = 100 * 4096 + 2 * 24 * 1024;
    assert!(wal <= bound, "the log grew to {wal} bytes (bound {bound})");
    // Letters and digits compress to ~¾ (6 bits a byte): ~6 MB stored.
    assert!(std::fs::metadata(dir.path().join("jobs.db")).unwrap().len() > 5_000_000, "the jobs reached the database");
}

/// `--max-database-bytes`: past the cap an insert fails as `Full` (the 507
/// of the API), the jobs before it stay readable, and the file stays sound.
#[tokio::test]
async fn the_database_size_cap_refuses_inserts_as_full() {
    let dir = tempfile::tempdir().unwrap();
    let url = format!("sqlite://{}/jobs.db", dir.path().display());
    let store = Store::open_with(&url, &Options { max_bytes: Some(256 << 10), ..Options::default() }).await.unwrap();
    let mut k = 0;
    let error = loop {
        match store.insert(job(k, 20_000)).await {
            Ok(_) => k += 1,
            Err(e) => break e,
        }
        assert!(k < 100, "256 KiB never filled up");
    };
    assert_eq!(error, StoreError::Full);
    assert!(k > 0);
    for i in 0..k {
        assert!(store.get(&format!("job-{i}")).await.unwrap().is_some(), "job-{i}");
    }
    assert_eq!(store.integrity().await.unwrap(), "ok");
}

/// A URL of a database mechdyn does not serve is refused at start with a
/// clear message, and neither the message nor the log holds its password.
#[test]
fn another_database_scheme_stops_the_service_at_start_without_its_password() {
    let out = Command::new(env!("CARGO_BIN_EXE_mechdyn"))
        .env("DATABASE_URL", "mysql://user:s3cret@db/mechdyn")
        .env("MECHDYN_ADDR", format!("127.0.0.1:{}", crate::crash::free_port()))
        .output()
        .unwrap();
    assert!(!out.status.success());
    let said = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(said.contains("scheme 'mysql'") && said.contains("SQLite") && said.contains("PostgreSQL"), "{said}");
    assert!(said.contains("mysql://user:***@db/mechdyn"), "{said}");
    assert!(!said.contains("s3cret"), "{said}");
}

/// A PostgreSQL server that does not answer within `--database-wait-seconds`
/// stops the service at start, saying so, its password in no line of the
/// log; `--max-database-bytes`, SQLite's cap, is refused with PostgreSQL.
#[test]
fn an_unreachable_postgres_server_stops_the_service_at_start_without_its_password() {
    let run = |env: &[(&str, &str)]| {
        let out = Command::new(env!("CARGO_BIN_EXE_mechdyn"))
            .env("DATABASE_URL", format!("postgres://user:s3cret@127.0.0.1:{}/mechdyn", crate::crash::free_port()))
            .env("MECHDYN_ADDR", format!("127.0.0.1:{}", crate::crash::free_port()))
            .env("MECHDYN_DATABASE_WAIT_SECONDS", "1")
            .envs(env.iter().copied())
            .output()
            .unwrap();
        assert!(!out.status.success());
        format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr))
    };
    let said = run(&[]);
    assert!(said.contains("the PostgreSQL server did not answer within 1 s"), "{said}");
    assert!(said.contains("postgres://user:***@127.0.0.1:"), "{said}");
    assert!(!said.contains("s3cret"), "{said}");
    let capped = run(&[("MECHDYN_MAX_DATABASE_BYTES", "1000000")]);
    assert!(capped.contains("--max-database-bytes") && capped.contains("SQLite"), "{capped}");
    assert!(!capped.contains("s3cret"), "{capped}");
}

/// A job answered 201 is on disk: SQLite syncs its log at every commit
/// (`synchronous=FULL`, 2) unless the operator asks for less (`NORMAL`, 1).
#[tokio::test]
async fn commits_are_synced_to_disk_unless_told_otherwise() {
    let dir = tempfile::tempdir().unwrap();
    let url = format!("sqlite://{}/jobs.db", dir.path().display());
    assert_eq!(Store::open(&url).await.unwrap().synchronous().await.unwrap(), 2, "FULL by default");
    let fast = Options { power_safe: false, ..Options::default() };
    assert_eq!(Store::open_with(&url, &fast).await.unwrap().synchronous().await.unwrap(), 1, "NORMAL when asked");
}

/// A swept kinetostatics job (K1 over 360 steps, the default outputs:
/// ~500 KB of JSON) is stored zstd-compressed in at most a third of its
/// result's bytes, and read back as the POST answered it, byte for byte:
/// the job, a part of its result and a page of the list, after a restart.
/// A flywheel job's short result (its inertia only) stays text (`result_zstd` NULL).
#[tokio::test]
async fn a_large_result_is_stored_in_a_third_of_its_bytes_and_read_back_as_answered() {
    let app = crate::helpers::TestApp::new().await;
    let mut body = request("k1_offset_slider_crank");
    body["input"]["steps"] = 360.into();
    let posted = app.post("/v1/kinetostatics", &body).await;
    assert_eq!(posted.status, 201, "{}", posted.text);
    let id = posted.json()["id"].as_str().unwrap().to_string();
    let result = serde_json::to_string(&posted.json()["result"]).unwrap();
    assert!(result.len() > 300_000, "{} bytes", result.len());
    let mut flywheel = request("p103_slider");
    (flywheel["check"], flywheel["samples"]) = (false.into(), 0.into());
    let short = app.post("/v1/flywheel", &flywheel).await.json()["id"].as_str().unwrap().to_string();
    let pool = sqlx::SqlitePool::connect(&app.url).await.unwrap();
    let sql = "SELECT length(CAST(result AS BLOB)), length(result_zstd) FROM jobs WHERE id = $1";
    let stored = |id: String| sqlx::query_as::<_, (i64, Option<i64>)>(sql).bind(id).fetch_one(&pool);
    let (text, zstd) = stored(id.clone()).await.unwrap();
    let zstd = zstd.expect("compressed") as usize;
    assert!(text == 0 && 3 * zstd <= result.len(), "{zstd} bytes stored for {}", result.len());
    let (text, zstd) = stored(short).await.unwrap();
    assert!(text > 0 && text < 4096 && zstd.is_none(), "{text} bytes of text");
    pool.close().await;
    let app = app.restart().await;
    assert!(app.get(&format!("/v1/jobs/{id}")).await.text == posted.text, "the job as the POST answered it");
    let part = app.get(&format!("/v1/jobs/{id}/result/summary/max_abs_driving")).await.json();
    assert_eq!(part, posted.json()["result"]["summary"]["max_abs_driving"], "a part of the result");
    let list = app.get("/v1/jobs?kind=kinetostatics").await.json();
    let listed = list["items"].as_array().and_then(|jobs| jobs.iter().find(|j| j["id"] == id.as_str()));
    assert!(serde_json::to_string(&listed.expect("listed")["result"]).unwrap() == result, "the list's page");
}
