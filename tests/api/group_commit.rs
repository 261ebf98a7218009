//! Group commit: concurrent jobs share transactions, and every job is
//! committed — visible to another connection — when its insert (and so its
//! `201`) returns.

use crate::helpers::request;
use axum::body::Body;
use axum::http::{Request, StatusCode};
use http_body_util::BodyExt;
use mechdyn::api::{Admission, AppState, Capacity, Settings, router};
use mechdyn::store::{NewJob, Store};
use tokio::task::JoinSet;
use tower::ServiceExt;

fn job(k: usize) -> NewJob {
    NewJob {
        id: format!("job-{k}"),
        kind: "flywheel".into(),
        created_at: "2026-11-23T00:00:00.000000Z".into(),
        request: format!("{{\"k\": {k}}}").into(),
        result: "{}".into(),
        engine_us: 1,
        engine_version: "test".into(),
        request_key: None,
        label: None,
    }
}

/// A fresh SQLite file's URL, in a folder kept while the test runs.
fn sqlite() -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let url = format!("sqlite://{}/jobs.db", dir.path().display());
    (dir, url)
}

#[tokio::test(flavor = "current_thread")]
async fn waiting_jobs_are_committed_together() {
    let (_dir, url) = sqlite();
    committed_together(&url).await;
}

/// 64 inserts handed over before the writer runs (one thread: the spawned
/// tasks all run before the writer they wake) go into one transaction;
/// each comes back with its own seq, and a second connection reads them all.
pub async fn committed_together(url: &str) {
    let store = Store::open(url).await.unwrap();
    let mut tasks = JoinSet::new();
    for k in 0..64 {
        let store = store.clone();
        tasks.spawn(async move { store.insert(job(k)).await.unwrap() });
    }
    let rows = tasks.join_all().await;
    let mut seqs: Vec<i64> = rows.iter().map(|row| row.seq).collect();
    seqs.sort_unstable();
    seqs.dedup();
    assert_eq!(seqs.len(), 64, "one seq per job");
    assert_eq!(store.commits(), 1, "64 waiting jobs, one transaction");
    let other = Store::open(url).await.unwrap();
    for row in rows {
        let stored = other.get(&row.id).await.unwrap().expect("committed");
        assert_eq!(stored, row, "the row returned to the caller is the row stored");
    }
}

#[tokio::test(flavor = "current_thread")]
async fn one_bad_insert_does_not_sink_its_batch() {
    let (_dir, url) = sqlite();
    bad_insert_alone(&url).await;
}

/// A failing insert (a duplicate id) fails alone; the jobs beside it in the
/// same transaction are stored.
pub async fn bad_insert_alone(url: &str) {
    let store = Store::open(url).await.unwrap();
    store.insert(job(0)).await.unwrap();
    let mut tasks = JoinSet::new();
    for k in [1, 0, 2] {
        let store = store.clone();
        tasks.spawn(async move { (k, store.insert(job(k)).await.is_ok()) });
    }
    let mut outcomes = tasks.join_all().await;
    outcomes.sort_unstable();
    assert_eq!(outcomes, vec![(0, false), (1, true), (2, true)]);
    assert_eq!(store.commits(), 2, "the three went into one transaction");
    assert!(store.get("job-2").await.unwrap().is_some());
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn concurrent_posts_are_all_stored_before_their_201() {
    let (_dir, url) = sqlite();
    stored_before_201(&url).await;
}

/// 96 concurrent POSTs through the router: every one is a 201 whose job
/// another connection reads at once.
pub async fn stored_before_201(url: &str) {
    let store = Store::open(url).await.unwrap();
    // Room for all 96 at once (the default queue would answer some 503).
    let admission = Admission::new(Capacity { queue: 96, ..Capacity::default() });
    let app = router(AppState { admission, ..crate::helpers::state(store.clone()) }, &Settings::default());
    let other = Store::open(url).await.unwrap();
    let body = request("p113_pulley").to_string();
    let mut tasks = JoinSet::new();
    for _ in 0..96 {
        let (app, other, body) = (app.clone(), other.clone(), body.clone());
        tasks.spawn(async move {
            let post = Request::post("/v1/flywheel").header("content-type", "application/json").body(Body::from(body));
            let res = app.oneshot(post.unwrap()).await.unwrap();
            assert_eq!(res.status(), StatusCode::CREATED);
            let bytes = res.into_body().collect().await.unwrap().to_bytes();
            let job: serde_json::Value = serde_json::from_slice(&bytes).unwrap();
            let id = job["id"].as_str().unwrap().to_string();
            // Read at once by another connection: committed before the 201.
            assert!(other.get(&id).await.unwrap().is_some(), "{id} not committed at its 201");
        });
    }
    tasks.join_all().await;
    let plan = other.list_plan(&Default::default(), None, 1000, usize::MAX).await.unwrap();
    assert_eq!(other.list_rows(&Default::default(), &plan).await.unwrap().len(), 96);
}
