//! A database of a million jobs (issue 46), made quickly by SQL: the
//! filtered page, lists beside POSTs, the SQLite log's size over the run,
//! and the retention's sweeps beside POSTs. `SOAK_ONLY=million`
//! (MILLION_JOBS sets the count, 10⁶ by default).

use crate::http::{self, Service};
use crate::wire::http as exchange;
use std::fmt::Write as _;
use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

pub const HEADING: &str = "## At a million jobs";

/// Students whose jobs carry their label: every tenth job, 20 each at 10⁶.
const STUDENTS: usize = 5000;

/// `n` jobs in the SQLite file `db`, 2 s apart over the last weeks, one in
/// a hundred a cam, one in ten labelled by a student, each with the
/// request and the result of a real flywheel job: the seconds it took.
fn make(db: &str, n: usize) -> f64 {
    let started = Instant::now();
    let runtime = tokio::runtime::Builder::new_current_thread().enable_all().build().expect("runtime");
    let service = http::start_on(Some(db), &[]).expect("the service starts");
    let (_, text) = exchange(port(&service), "POST", "/v1/flywheel", &crate::light().to_string()).expect("a job");
    drop(service);
    let job: serde_json::Value = serde_json::from_str(&text).expect("a job");
    let (request, result) = (job["request"].to_string(), job["result"].to_string());
    runtime.block_on(async {
        let pool = sqlx::SqlitePool::connect(db).await.expect("the database");
        let fill = "WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 FROM n WHERE i < $1) \
                    INSERT INTO jobs (id, kind, created_at, request, result, engine_us, engine_version, label, bytes) \
                    SELECT printf('00000000-0000-4000-8000-%012d', i), \
                    CASE WHEN i % 100 = 0 THEN 'cams' ELSE 'flywheel' END, \
                    strftime('%Y-%m-%dT%H:%M:%S', unixepoch('now') - 2 * ($1 - i), 'unixepoch') || '.000000Z', \
                    $2, $3, 100, 'bench', CASE WHEN i % 10 = 0 THEN 'student-' || (i / 10 % $4) END, $5 FROM n";
        let bytes = (request.len() + result.len()) as i64;
        sqlx::query(fill)
            .bind(n as i64)
            .bind(&request)
            .bind(&result)
            .bind(STUDENTS as i64)
            .bind(bytes)
            .execute(&pool)
            .await
            .expect("the jobs made");
        sqlx::query("PRAGMA wal_checkpoint(TRUNCATE)").execute(&pool).await.expect("checkpoint");
        pool.close().await;
    });
    started.elapsed().as_secs_f64()
}

/// The path of the k-th page asked.
type PathOf = Box<dyn Fn(usize) -> String>;

/// The jobs the service's retention has deleted.
fn deleted(service: &Service) -> f64 {
    let (_, metrics) = exchange(port(service), "GET", "/metrics", "").unwrap_or_default();
    let counts = metrics.lines().filter(|l| l.starts_with("mechdyn_jobs_deleted_total"));
    counts.filter_map(|l| l.rsplit(' ').next()?.parse::<f64>().ok()).fold(0.0, |a, b| a + b)
}

/// The jobs in the SQLite file `db` now.
fn count(db: &str) -> usize {
    let runtime = tokio::runtime::Builder::new_current_thread().enable_all().build().expect("runtime");
    runtime.block_on(async {
        let pool = sqlx::SqlitePool::connect(db).await.expect("the database");
        let n: i64 = sqlx::query_scalar("SELECT count(*) FROM jobs").fetch_one(&pool).await.expect("a count");
        pool.close().await;
        usize::try_from(n).unwrap_or(0)
    })
}

fn port(service: &Service) -> u16 {
    service.addr.rsplit(':').next().and_then(|p| p.parse().ok()).unwrap_or(0)
}

/// `count` GETs of `path(k)` one after another: p50, p99 and the slowest (ms).
fn pages(port: u16, count: usize, path: impl Fn(usize) -> String) -> (f64, f64, f64) {
    let mut ms: Vec<f64> = (0..count)
        .map(|k| {
            let started = Instant::now();
            let (status, _) = exchange(port, "GET", &path(k), "").expect("a page");
            assert_eq!(status, 200);
            started.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    ms.sort_by(f64::total_cmp);
    (ms[count / 2], ms[count * 99 / 100], ms[count - 1])
}

/// Four clients listing students' pages one after another until stopped: pages read.
fn listers(port: u16, stop: &Arc<AtomicBool>) -> Vec<std::thread::JoinHandle<usize>> {
    (0..4)
        .map(|c| {
            let stop = stop.clone();
            std::thread::spawn(move || {
                let mut k = c;
                while !stop.load(Ordering::Relaxed) {
                    let _ = exchange(port, "GET", &format!("/v1/jobs?label=student-{}&limit=20", k % STUDENTS), "");
                    k += 4;
                }
                k / 4
            })
        })
        .collect()
}

/// The largest size the log of `db` reached while `run` ran (sampled every 100 ms), MiB.
fn log_during<T>(db_file: &Path, run: impl FnOnce() -> T) -> (T, f64) {
    let log = db_file.with_extension("db-wal");
    let (stop, largest) = (Arc::new(AtomicBool::new(false)), Arc::new(AtomicUsize::new(0)));
    let sampler = {
        let (stop, largest) = (stop.clone(), largest.clone());
        std::thread::spawn(move || {
            while !stop.load(Ordering::Relaxed) {
                let size = std::fs::metadata(&log).map_or(0, |m| m.len() as usize);
                largest.fetch_max(size, Ordering::Relaxed);
                std::thread::sleep(Duration::from_millis(100));
            }
        })
    };
    let out = run();
    stop.store(true, Ordering::Relaxed);
    let _ = sampler.join();
    (out, largest.load(Ordering::Relaxed) as f64 / (1 << 20) as f64)
}

fn load_row(s: &mut String, what: &str, load: &Result<http::Load, String>, extra: &str) {
    let _ = match load {
        Ok(l) => writeln!(
            s,
            "| {what} | {:.0} | {:.2} ms | {:.2} ms | {:.0} ms | {} | {extra} |",
            l.rate, l.p50, l.p99, l.max, l.non_2xx
        ),
        Err(why) => writeln!(s, "| {what} | failed: {} | | | | | |", why.lines().next().unwrap_or("")),
    };
}

pub fn report() -> String {
    let n: usize = std::env::var("MILLION_JOBS").ok().and_then(|s| s.parse().ok()).unwrap_or(1_000_000);
    let dir = tempfile::tempdir().expect("temp dir");
    let file = dir.path().join("jobs.db");
    let db = format!("sqlite://{}", file.display());
    let made = make(&db, n);
    let size = std::fs::metadata(&file).map_or(0.0, |m| m.len() as f64 / 1e9);
    let mut s = format!(
        "\n{HEADING}\n\nA SQLite file of {n} jobs ({size:.1} GB: P.103's light flywheel job each, one in a hundred of \
         kind `cams`, one in ten labelled by one of {STUDENTS} students, created 2 s apart), made by one SQL \
         statement in {made:.0} s; the release service on it, `wrk` on loopback sharing the two cores. Targets \
         (issue 46): a filtered page ≤ 10 ms; POSTs beside four listing clients ≥ ½ their rate alone; the log \
         ≤ 64 MB; a retention sweep's stall ≤ 20 ms.\n\n"
    );
    let service = http::start_on(Some(&db), &[]).expect("the service starts");
    let p = port(&service);
    let _ = writeln!(
        s,
        "| page (`GET /v1/jobs?…`, one after another, 200 each) | p50 | p99 | slowest |\n|---|---|---|---|"
    );
    let rows: [(&str, PathOf); 4] = [
        (
            "`label=student-K&limit=20`",
            Box::new(|k| format!("/v1/jobs?label=student-{}&limit=20", (k * 37) % STUDENTS)),
        ),
        ("`kind=cams&limit=20`", Box::new(|_| "/v1/jobs?kind=cams&limit=20".into())),
        (
            "`kind=cams&label=student-K`",
            Box::new(|k| format!("/v1/jobs?kind=cams&label=student-{}", (k * 37) % STUDENTS)),
        ),
        ("`limit=20` (no filter)", Box::new(|_| "/v1/jobs?limit=20".into())),
    ];
    for (what, path) in rows {
        let (p50, p99, max) = pages(p, 200, path);
        let _ = writeln!(s, "| {what} | {p50:.2} ms | {p99:.2} ms | {max:.2} ms |");
    }
    let _ = writeln!(
        s,
        "\n| POSTs of the light flywheel, 16 connections, 15 s | jobs/s | p50 | p99 | slowest | non-2xx | the log at most |\n|---|---|---|---|---|---|---|"
    );
    let (alone, log) = log_during(&file, || http::wrk_for(&service.addr, "/v1/flywheel", &crate::light(), 16, 15));
    load_row(&mut s, "alone", &alone, &format!("{log:.1} MiB"));
    let stop = Arc::new(AtomicBool::new(false));
    let clients = listers(p, &stop);
    let (beside, log) = log_during(&file, || http::wrk_for(&service.addr, "/v1/flywheel", &crate::light(), 16, 15));
    stop.store(true, Ordering::Relaxed);
    let listed: usize = clients.into_iter().map(|c| c.join().unwrap_or(0)).sum();
    load_row(
        &mut s,
        &format!("beside four listing clients ({:.0} pages/s)", listed as f64 / 15.0),
        &beside,
        &format!("{log:.1} MiB"),
    );
    if let (Ok(a), Ok(b)) = (&alone, &beside) {
        let _ = writeln!(s, "\nBeside the lists the POSTs keep {:.0} % of their rate alone.", 100.0 * b.rate / a.rate);
    }
    drop(service);
    // The retention: nothing old (a sweep a second finds nothing); the newest
    // N kept, N the jobs there are (each sweep deletes the jobs added since);
    // then 100 000 fewer (a first sweep deletes them, in batches).
    let _ = writeln!(
        s,
        "\n| POSTs beside the retention's sweeps (every 1 s), 16 connections, 15 s | jobs/s | p50 | p99 | slowest | non-2xx | jobs deleted |\n|---|---|---|---|---|---|---|"
    );
    let there = count(&db);
    let (steady, fewer) = (there.to_string(), there.saturating_sub(100_000).to_string());
    let cases = [
        ("`--retention-days 3650` (nothing old)", ("MECHDYN_RETENTION_DAYS", "3650")),
        (
            "`--retention-jobs N`, N the jobs there were (those added since deleted)",
            ("MECHDYN_RETENTION_JOBS", steady.as_str()),
        ),
        ("`--retention-jobs N − 10⁵` (a first sweep of 10⁵ jobs and more)", ("MECHDYN_RETENTION_JOBS", fewer.as_str())),
    ];
    for (what, rule) in cases {
        let service = http::start_on(Some(&db), &[rule, ("MECHDYN_RETENTION_INTERVAL_SECONDS", "1")]).expect("starts");
        let started = Instant::now();
        let load = http::wrk_for(&service.addr, "/v1/flywheel", &crate::light(), 16, 15);
        let mut deleted = deleted(&service);
        // The first sweep of a large excess is counted when it ends: waited for.
        while deleted == 0.0 && rule.1 == fewer && started.elapsed() < Duration::from_secs(180) {
            std::thread::sleep(Duration::from_secs(1));
            deleted = self::deleted(&service);
        }
        let took = if rule.1 == fewer {
            format!(" (the first sweep ended {:.0} s after the start)", started.elapsed().as_secs_f64())
        } else {
            String::new()
        };
        load_row(&mut s, what, &load, &format!("{deleted:.0}{took}"));
    }
    let _ = writeln!(
        s,
        "\nA sweep's stall is what it adds to the slowest POST: the sweeps delete 100 jobs a statement on the \
         index of the creation time, pausing at least 20 ms between statements for the jobs being stored, and \
         find the newest N's cut off that index."
    );
    s
}
