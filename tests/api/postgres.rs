//! The service on a real PostgreSQL server ([`PgServer`]): the store's
//! scenarios of the other test files run again on it, and two replicas of
//! the real binary share one database, through the server's outage.

use crate::crash::{free_port, http, start_logged};
use crate::helpers::{TestApp, request};
use crate::pg_server::PgServer;
use axum::http::StatusCode;
use mechdyn::api::Settings;
use serde_json::Value;
use std::process::Child;
use std::time::{Duration, Instant};

/// Every scenario of the store that the SQLite tests run, on PostgreSQL:
/// jobs read back byte for byte, listed, paginated, filtered by kind and
/// label, after a restart; templates' jobs found again by their key, a
/// client's template; idempotency keys; a class graded; a job deleted; ids
/// and labels with a NUL byte; the retention; every 201 committed.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_store_behaves_on_postgres_as_on_sqlite() {
    let Some(server) = PgServer::start("the_store_behaves_on_postgres_as_on_sqlite") else { return };
    let plain = Settings::default();
    crate::jobs::a_post_returns_the_job_exactly_as_a_later_get_on(TestApp::on(&server.database().await, &plain).await)
        .await;
    crate::jobs::jobs_survive_a_restart_on(TestApp::on(&server.database().await, &plain).await).await;
    crate::jobs::the_list_is_newest_first_and_paginated_on(TestApp::on(&server.database().await, &plain).await).await;
    crate::class::labels_tag_jobs_and_filter_the_list_on(TestApp::on(&server.database().await, &plain).await).await;
    crate::class::a_retried_post_is_answered_once_on(TestApp::on(&server.database().await, &plain).await).await;
    crate::class::a_class_is_graded_in_one_request_on(TestApp::on(&server.database().await, &plain).await).await;
    let fresh = TestApp::on(&server.database().await, &plain).await;
    crate::templates::the_same_parameters_reuse_the_stored_job_on(fresh).await;
    let fresh = TestApp::on(&server.database().await, &plain).await;
    crate::templates::a_client_creates_a_template_and_uses_it_on(fresh).await;
    let token = crate::operations::with_token();
    crate::operations::a_deleted_job_is_gone_on(TestApp::on(&server.database().await, &token).await).await;
    crate::security::text_that_no_row_holds_on(TestApp::on(&server.database().await, &token).await).await;
    // A value the server refuses, should one get past the API's checks, is the request's to mend (a 422), not a 503.
    let store = mechdyn::store::Store::open(&server.database().await).await.unwrap();
    let refused = store.insert_template("a\0b", "2026-11-26T00:00:00.000000Z", "{}").await;
    assert!(matches!(refused, Err(mechdyn::store::StoreError::Refused(_))), "{refused:?}");
    crate::operations::the_retention_deletes_on(&server.database().await).await;
    crate::group_commit::stored_before_201(&server.database().await).await;
    let ready = TestApp::on(&server.database().await, &plain).await.get("/readyz").await;
    assert_eq!((ready.status, ready.json()["database"].as_str()), (StatusCode::OK, Some("postgres")));
}

/// Group commit on PostgreSQL: waiting jobs share one transaction, and a
/// failing row (a duplicate id) fails alone, its batch stored (one thread,
/// as the SQLite tests, so that every job waits before the writer runs).
#[tokio::test(flavor = "current_thread")]
async fn group_commit_on_postgres() {
    let Some(server) = PgServer::start("group_commit_on_postgres") else { return };
    crate::group_commit::committed_together(&server.database().await).await;
    crate::group_commit::bad_insert_alone(&server.database().await).await;
}

/// A replica of the real binary on `db`, with its log kept to read.
struct Replica {
    child: Child,
    port: u16,
    log: tempfile::NamedTempFile,
}

impl Replica {
    fn start(db: &str) -> Self {
        Self::start_with(db, &[])
    }

    fn start_with(db: &str, env: &[(&str, &str)]) -> Self {
        let log = tempfile::NamedTempFile::new().unwrap();
        let port = free_port();
        let env: Vec<(&str, &str)> = [("RUST_LOG", "info")].iter().chain(env).copied().collect();
        let child = start_logged(db, port, &env, Some(log.reopen().unwrap()));
        Self { child, port, log }
    }

    /// The value of one series of the replica's `/metrics` (0 where absent).
    fn metric(&self, series: &str) -> f64 {
        let text = http(self.port, "GET", "/metrics", "").unwrap().1;
        let line = text.lines().find(|l| l.starts_with(series) && l[series.len()..].starts_with(' '));
        line.map_or(0.0, |l| l[series.len()..].trim().parse().unwrap())
    }

    fn log(&self) -> String {
        std::fs::read_to_string(self.log.path()).unwrap_or_default()
    }
}

impl Drop for Replica {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn json(text: &str) -> Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("not JSON ({e}): {text}"))
}

/// Two replicas of the real binary started together on one new database
/// (the migrations run once, under sqlx's advisory lock): jobs POSTed to
/// both at once are each readable from either, byte for byte, and listed
/// once by both. When the server stops, both answer `/readyz` 503 (and
/// `/healthz` 200) and a POST 503; once it is back, they serve again
/// without a restart. No line of their logs holds the URL's password.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn two_replicas_share_one_database_and_ride_out_its_outage() {
    let Some(server) = PgServer::start("two_replicas_share_one_database_and_ride_out_its_outage") else { return };
    let db = server.database().await;
    let (a, b) = std::thread::scope(|s| {
        let a = s.spawn(|| Replica::start(&db));
        let b = s.spawn(|| Replica::start(&db));
        (a.join().unwrap(), b.join().unwrap())
    });
    let posted: Vec<(String, String)> = std::thread::scope(|s| {
        let clients: Vec<_> = (0..4)
            .map(|c| {
                let port = if c % 2 == 0 { a.port } else { b.port };
                s.spawn(move || {
                    (0..10)
                        .map(|k| {
                            let mut body = request("p103_slider");
                            body["irregularity"] = (0.01 + 0.001 * f64::from(c * 10 + k)).into();
                            let (status, job) = http(port, "POST", "/v1/flywheel", &body.to_string()).unwrap();
                            assert_eq!(status, 201, "{job}");
                            (json(&job)["id"].as_str().unwrap().to_string(), job)
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        clients.into_iter().flat_map(|c| c.join().unwrap()).collect()
    });
    for (id, job) in &posted {
        for replica in [&a, &b] {
            let (status, read) = http(replica.port, "GET", &format!("/v1/jobs/{id}"), "").unwrap();
            assert_eq!((status, &read), (200, job), "job {id} from the replica on port {}", replica.port);
        }
    }
    for replica in [&a, &b] {
        let mut listed = Vec::new();
        let mut next = Some("/v1/jobs?limit=100".to_string());
        while let Some(path) = next {
            let page = json(&http(replica.port, "GET", &path, "").unwrap().1);
            listed.extend(page["items"].as_array().unwrap().iter().map(|j| j["id"].as_str().unwrap().to_string()));
            next = page["next"].as_str().map(str::to_string);
        }
        let mut expected: Vec<String> = posted.iter().map(|(id, _)| id.clone()).collect();
        listed.sort();
        expected.sort();
        assert_eq!(listed, expected, "every job listed once");
    }

    server.stop();
    let body = request("p103_slider").to_string();
    for replica in [&a, &b] {
        let (status, ready) = http(replica.port, "GET", "/readyz", "").unwrap();
        assert_eq!(status, 503, "{ready}");
        assert!(json(&ready)["reason"].as_str().unwrap().starts_with("the database does not answer"), "{ready}");
        assert_eq!(http(replica.port, "GET", "/healthz", "").unwrap().0, 200);
        let (status, problem) = http(replica.port, "POST", "/v1/flywheel", &body).unwrap();
        assert_eq!(
            (status, json(&problem)["type"].as_str()),
            (503, Some("/problems/database-unavailable")),
            "{problem}"
        );
    }
    server.start_again();
    let started = Instant::now();
    for replica in [&a, &b] {
        while http(replica.port, "GET", "/readyz", "").unwrap().0 != 200 {
            assert!(started.elapsed() < Duration::from_secs(30), "not ready again within 30 s");
            std::thread::sleep(Duration::from_millis(100));
        }
        assert_eq!(http(replica.port, "POST", "/v1/flywheel", &body).unwrap().0, 201);
    }
    for replica in [&a, &b] {
        let log = replica.log();
        assert!(log.contains("mechdyn listening") && log.contains("postgres://mechdyn:***@127.0.0.1"), "{log}");
        assert!(!log.contains("s3cret"), "a password in the log: {log}");
    }
}

/// While the database is away, a POST waits for it at most once: the pool's
/// wait for a connection (5 s, `store::backend::ACQUIRE`) and the job's
/// computing. 24 clients POST to one replica for 8 s after the server
/// stopped; every answer is the 503 that says so, the slowest within 7.5 s.
/// (Before the writer answered the jobs that had come while a batch waited
/// with that batch, one that came just after a batch began waited for it
/// and then for its own: 10 s, past a client's usual timeout.)
#[test]
fn a_post_waits_for_an_absent_database_once() {
    let Some(server) = PgServer::start("a_post_waits_for_an_absent_database_once") else { return };
    let db = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap().block_on(server.database());
    let replica = Replica::start(&db);
    let body = request("p103_slider").to_string();
    assert_eq!(http(replica.port, "POST", "/v1/flywheel", &body).unwrap().0, 201);
    server.stop();
    let until = Instant::now() + Duration::from_secs(8);
    let answers: Vec<(u16, String, Duration)> = std::thread::scope(|s| {
        let clients: Vec<_> = (0..24)
            .map(|_| {
                s.spawn(|| {
                    let mut seen = Vec::new();
                    while Instant::now() < until {
                        let asked = Instant::now();
                        let (status, text) =
                            http(replica.port, "POST", "/v1/flywheel", &body).expect("an answer in 10 s");
                        seen.push((status, text, asked.elapsed()));
                    }
                    seen
                })
            })
            .collect();
        clients.into_iter().flat_map(|c| c.join().unwrap()).collect()
    });
    for (status, text, _) in &answers {
        assert_eq!((*status, json(text)["type"].as_str()), (503, Some("/problems/database-unavailable")), "{text}");
    }
    let slowest = answers.iter().map(|a| a.2).max().unwrap();
    assert!(slowest < Duration::from_millis(7500), "{} answers, the slowest after {slowest:.1?}", answers.len());
}

/// Jobs deferred on a replica that computes none (`MECHDYN_ASYNC_WORKERS=0`)
/// are computed by the two others on the same PostgreSQL database, each
/// job once (their `/metrics` count 12 jobs done between them), and read
/// back done from the first.
#[test]
fn any_replica_runs_a_queued_job_and_only_one_does() {
    let Some(server) = PgServer::start("any_replica_runs_a_queued_job_and_only_one_does") else { return };
    let runtime = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    let db = runtime.block_on(server.database());
    let front = Replica::start_with(&db, &[("MECHDYN_ASYNC_WORKERS", "0")]);
    let workers = [Replica::start(&db), Replica::start(&db)];
    let ids: Vec<String> = (0..12)
        .map(|k| {
            let mut body = request("p103_slider");
            body["irregularity"] = (0.02 + 0.001 * f64::from(k)).into();
            let (status, job) = crate::deferred::post_async_raw(front.port, "/v1/flywheel", &body.to_string());
            assert_eq!(status, 202, "{job}");
            json(&job)["id"].as_str().unwrap().to_string()
        })
        .collect();
    let started = Instant::now();
    for id in &ids {
        loop {
            let job = json(&http(front.port, "GET", &format!("/v1/jobs/{id}"), "").unwrap().1);
            if job["status"] == "done" {
                assert!(job["result"]["inertia_exact"].as_f64().unwrap() > 0.0, "{job}");
                break;
            }
            assert!(started.elapsed() < Duration::from_secs(60), "not done in 60 s: {job}");
            std::thread::sleep(Duration::from_millis(20));
        }
    }
    let done = r#"mechdyn_jobs_total{kind="flywheel",status="done"}"#;
    assert_eq!(front.metric(done), 0.0, "the front replica computes none");
    assert_eq!(workers.iter().map(|w| w.metric(done)).sum::<f64>(), 12.0, "each job computed once");
}

/// docs/operators.md's PostgreSQL backup, with Debian's client: `pg_dump
/// --format=custom` of the database while a replica serves it, restored by
/// `pg_restore` into a new database; a replica on the restored database
/// answers every job as the first does, byte for byte.
#[test]
fn a_pg_dump_restores_every_job() {
    let Some(server) = PgServer::start("a_pg_dump_restores_every_job") else { return };
    let runtime = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    let (db, restored_db) = (runtime.block_on(server.database()), runtime.block_on(server.database()));
    let live = Replica::start(&db);
    let ids: Vec<String> = (0..20)
        .map(|k| {
            let mut body = request("p103_slider");
            body["irregularity"] = (0.02 + 0.001 * f64::from(k)).into();
            let (status, job) = http(live.port, "POST", "/v1/flywheel", &body.to_string()).unwrap();
            assert_eq!(status, 201, "{job}");
            json(&job)["id"].as_str().unwrap().to_string()
        })
        .collect();
    let dump = tempfile::NamedTempFile::new().unwrap();
    let file = dump.path().to_str().unwrap();
    let run = |mut c: std::process::Command| {
        let out = c.output().unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    };
    let mut pg_dump = server.client("pg_dump");
    pg_dump.args(["--format=custom", "--file", file, "--dbname", &db]);
    run(pg_dump);
    let mut pg_restore = server.client("pg_restore");
    pg_restore.args(["--no-owner", "--dbname", &restored_db, file]);
    run(pg_restore);
    let restored = Replica::start(&restored_db);
    for id in &ids {
        let path = format!("/v1/jobs/{id}");
        let (live_status, live_body) = http(live.port, "GET", &path, "").unwrap();
        let (status, body) = http(restored.port, "GET", &path, "").unwrap();
        assert_eq!((live_status, status), (200, 200), "{id}: {body}");
        assert_eq!(body, live_body, "{id}: the same bytes from the restored database");
    }
}

/// On PostgreSQL the lists and the retention use their indexes too: with
/// 200 000 jobs analysed (most of one kind, 200 of another; 2 000 labels),
/// `EXPLAIN` of each list's two queries for the rarer kind or a label names
/// the kind's or the label's index, and of the retention's statements the
/// creation time's; none is a sequential scan. (For the common kind the
/// planner walks the table's order backwards, stopping at the page's end.)
#[tokio::test]
async fn the_lists_and_the_retention_use_their_indexes_on_postgres() {
    use mechdyn::store::{BY_AGE, Filter, NTH_NEWEST, list_sql};
    let Some(server) = PgServer::start("the_lists_and_the_retention_use_their_indexes_on_postgres") else { return };
    let db = server.database().await;
    let _store = mechdyn::store::Store::open(&db).await.unwrap();
    let pool = sqlx::PgPool::connect(&db).await.unwrap();
    let fill = "INSERT INTO jobs (id, kind, created_at, request, result, engine_us, engine_version, label, bytes) \
                SELECT 'j' || n, CASE WHEN n % 1000 = 0 THEN 'cams' ELSE 'flywheel' END, to_char(timestamp '2026-01-01' + n * interval '1 second', \
                'YYYY-MM-DD\"T\"HH24:MI:SS.US\"Z\"'), '{}', '{}', 1, 'test', 'label' || (n % 2000), 4 \
                FROM generate_series(1, 200000) AS n";
    sqlx::query(fill).execute(&pool).await.unwrap();
    sqlx::query("ANALYZE jobs").execute(&pool).await.unwrap();
    let explain = |sql: &str, binds: Vec<String>| {
        let pool = pool.clone();
        let sql = format!("EXPLAIN {sql}");
        async move {
            let mut q = sqlx::query_scalar::<_, String>(sqlx::AssertSqlSafe(sql));
            for b in binds {
                q = match b.parse::<i64>() {
                    Ok(n) => q.bind(n),
                    Err(_) => q.bind(b),
                };
            }
            q.fetch_all(&pool).await.unwrap().join("\n")
        }
    };
    let (kind, label) = (Some("cams"), Some("label7"));
    let cases = [
        (Filter { kind, label: None }, &["jobs_kind_seq"][..], vec!["cams"]),
        (Filter { kind: None, label }, &["jobs_label"][..], vec!["label7"]),
        (Filter { kind, label }, &["jobs_label", "jobs_kind_seq"][..], vec!["cams", "label7"]),
        (Filter { kind: Some("flywheel"), label: None }, &["jobs_pkey", "jobs_kind_seq"][..], vec!["flywheel"]),
    ];
    for (filter, indexes, values) in cases {
        let (sizes, rows) = list_sql(&filter);
        let seqs =
            |a: &str, b: &str| [a.to_string(), b.to_string()].into_iter().chain(values.iter().map(|v| v.to_string()));
        for (sql, binds) in
            [(sizes, seqs("9223372036854775807", "100").collect()), (rows, seqs("200000", "1").collect())]
        {
            let plan = explain(sql, binds).await;
            assert!(indexes.iter().any(|i| plan.contains(i)) && !plan.contains("Seq Scan"), "{sql}:\n{plan}");
        }
    }
    let old = "2026-01-01T00:00:10.000000Z".to_string();
    let plan = explain(BY_AGE, vec![old, "200".into()]).await;
    assert!(plan.contains("jobs_created_at") && !plan.contains("Seq Scan on jobs"), "{plan}");
    let plan = explain(NTH_NEWEST, vec!["9999".into()]).await;
    assert!(plan.contains("jobs_created_at") && !plan.contains("Seq Scan"), "{plan}");
}
