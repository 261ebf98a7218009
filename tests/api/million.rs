//! What a million jobs would show (issue 46): the filtered lists read the
//! whole table (their one query was planned on the table's order), each
//! list reserved 48 MiB of answer memory for its whole run, the SQLite log
//! grew without bound under lists that follow one another, and the
//! retention scanned the table at every sweep. The plans are SQLite's own
//! (`EXPLAIN QUERY PLAN`); PostgreSQL's are checked in `postgres.rs`.

use crate::helpers::TestApp;
use axum::http::StatusCode;
use bytes::Bytes;
use mechdyn::api::{Admission, Capacity};
use mechdyn::store::{BY_AGE, Filter, NTH_NEWEST, NewJob, Store, list_sql};
use std::time::{Duration, Instant};

/// A job of `kind` labelled `label`, its result `bytes` long.
pub fn job(k: usize, kind: &str, label: Option<&str>, bytes: usize) -> NewJob {
    let result = format!("{{\"x\":\"{}\"}}", crate::helpers::noise(bytes.saturating_sub(8), k as u64));
    NewJob {
        id: format!("00000000-0000-4000-8000-{k:012}"),
        kind: kind.into(),
        created_at: mechdyn::api::create::now_rfc3339(),
        request: Bytes::from_static(b"{}"),
        result: Bytes::from(result),
        engine_us: 1,
        engine_version: "test".into(),
        request_key: None,
        label: label.map(String::from),
    }
}

/// The plan SQLite makes of `sql`, one line per step.
async fn plan(db: &str, sql: &str) -> String {
    let pool = sqlx::SqlitePool::connect(db).await.unwrap();
    let rows: Vec<(i64, i64, i64, String)> =
        sqlx::query_as(sqlx::AssertSqlSafe(format!("EXPLAIN QUERY PLAN {sql}"))).fetch_all(&pool).await.unwrap();
    rows.into_iter().map(|r| r.3).collect::<Vec<_>>().join("; ")
}

/// Every list's query reads its index — the label's, the kind's, the
/// table's order when unfiltered — and the retention's the creation time's:
/// none scans the table.
#[tokio::test]
async fn the_lists_and_the_retention_read_their_indexes() {
    let dir = tempfile::tempdir().unwrap();
    let db = format!("sqlite://{}", dir.path().join("jobs.db").display());
    let _store = Store::open(&db).await.unwrap();
    let (kind, label) = (Some("flywheel"), Some("ana"));
    let cases = [
        (Filter { kind, label: None }, "jobs_kind_seq"),
        (Filter { kind: None, label }, "jobs_label"),
        (Filter { kind, label }, "jobs_label"),
    ];
    for (filter, index) in cases {
        let (sizes, rows) = list_sql(&filter);
        for sql in [sizes, rows] {
            let p = plan(&db, sql).await;
            assert!(p.contains(&format!("USING INDEX {index}")), "{sql}: {p}");
        }
    }
    let (sizes, _) = list_sql(&Filter::default());
    let p = plan(&db, sizes).await;
    assert!(p.contains("USING INTEGER PRIMARY KEY") || p.contains("SCAN jobs") && !p.contains("TEMP B-TREE"), "{p}");
    for sql in [BY_AGE, NTH_NEWEST] {
        let p = plan(&db, sql).await;
        assert!(p.contains("jobs_created_at"), "{sql}: {p}");
    }
}

/// A list reserves the memory its page holds, once its sizes are known:
/// with 100 MiB of the answers' 128 MiB held by others, a labelled page of
/// small jobs answers at once (it waited for 48 MiB, then answered 503).
#[tokio::test]
async fn a_list_reserves_what_its_page_holds() {
    let admission = Admission::new(Capacity { wait: Duration::from_secs(2), ..Capacity::default() });
    let held = admission.memory(100 << 20).await.unwrap();
    let app = TestApp::new().await.reopened(|s| mechdyn::api::AppState { admission, ..s }).await;
    let posted = app.post("/v1/flywheel?label=ana", &crate::helpers::request("p103_slider")).await;
    assert_eq!(posted.status, StatusCode::CREATED, "{}", posted.text);
    let started = Instant::now();
    let r = app.get("/v1/jobs?label=ana").await;
    assert_eq!(r.status, StatusCode::OK, "{}", r.text);
    assert_eq!(r.json()["items"].as_array().unwrap().len(), 1);
    assert!(started.elapsed() < Duration::from_secs(1), "the list waited {:?} for memory", started.elapsed());
    drop(held);
}

/// Four clients listing a label's jobs one page after another while jobs of
/// 100 kB are stored for 6 s: the log stays within its bound of 64 MiB (it
/// grew without one: readers always in it kept it from restarting), and
/// both the lists and the writes went on.
#[tokio::test(flavor = "multi_thread", worker_threads = 4)]
async fn the_log_stays_bounded_under_lists_that_follow_one_another() {
    let dir = tempfile::tempdir().unwrap();
    let db = format!("sqlite://{}", dir.path().join("jobs.db").display());
    let store = Store::open(&db).await.unwrap();
    let log = dir.path().join("jobs.db-wal");
    let until = Instant::now() + Duration::from_secs(6);
    let writers: Vec<_> = (0..4)
        .map(|w| {
            let store = store.clone();
            tokio::spawn(async move {
                let mut k = w;
                while Instant::now() < until {
                    store.insert(job(k, "flywheel", Some("ana"), 100_000)).await.unwrap();
                    k += 4;
                }
                k / 4
            })
        })
        .collect();
    let readers: Vec<_> = (0..4)
        .map(|_| {
            let store = store.clone();
            tokio::spawn(async move {
                let (mut pages, filter) = (0, Filter { kind: None, label: Some("ana") });
                while Instant::now() < until {
                    let plan = store.list_plan(&filter, None, 100, 16 << 20).await.unwrap();
                    store.list_rows(&filter, &plan).await.unwrap();
                    pages += 1;
                }
                pages
            })
        })
        .collect();
    let mut largest = 0;
    while Instant::now() < until {
        largest = largest.max(std::fs::metadata(&log).map_or(0, |m| m.len()));
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
    let written: usize = futures_join(writers).await.into_iter().sum();
    let pages: usize = futures_join(readers).await.into_iter().sum();
    eprintln!("{written} jobs of 100 kB written, {pages} pages listed, the log at most {} MiB", largest >> 20);
    assert!(written > 200 && pages > 20, "{written} jobs, {pages} pages");
    assert!(largest <= 64 << 20, "the log reached {} MiB", largest >> 20);
}

async fn futures_join<T>(tasks: Vec<tokio::task::JoinHandle<T>>) -> Vec<T> {
    let mut out = Vec::new();
    for t in tasks {
        out.push(t.await.unwrap());
    }
    out
}
