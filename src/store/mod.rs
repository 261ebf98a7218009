//! Jobs in SQLite (sqlx): nothing here knows about HTTP or the engine; jobs
//! go in and come out as JSON text (shared [`Bytes`], so the text stored is
//! the text served, never copied) with their metadata.
//!
//! Group commit (`writer.rs`): one writer task takes the jobs of concurrent
//! requests off a channel and inserts all that are waiting in one statement,
//! then answers each caller. [`Store::insert`] returns only once the
//! transaction holding its job has committed, so a job is stored before its
//! `201`, and under load one commit serves many jobs.
//!
//! Failures are sorted for the caller ([`StoreError`]): a full disk (or the
//! configured size cap) is [`StoreError::Full`], a condition the service
//! reports and recovers from when space returns; anything else the database
//! cannot do is [`StoreError::Unavailable`].

mod idempotency;
mod retention;
mod url;
mod writer;

pub use idempotency::Answer;
pub use retention::Retention;
pub use url::{SchemeError, check_scheme, redact};

use bytes::Bytes;
use sqlx::sqlite::{SqliteConnectOptions, SqliteJournalMode, SqlitePool, SqlitePoolOptions, SqliteSynchronous};
use std::str::FromStr;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;
use tokio::sync::{mpsc, oneshot};

/// The migrations of `migrations/`, embedded in the binary.
pub static MIGRATOR: sqlx::migrate::Migrator = sqlx::migrate!("./migrations");

/// Why the store could not do what it was asked.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum StoreError {
    /// The disk (or the database's configured size cap) is full: nothing was
    /// written; reads still work, and writes do again once space returns.
    #[error("the database's storage is full")]
    Full,
    /// The database could not be used (I/O error, closed, misconfigured).
    #[error("database unavailable: {0}")]
    Unavailable(String),
}

impl From<sqlx::Error> for StoreError {
    fn from(e: sqlx::Error) -> Self {
        if is_full(&e) { Self::Full } else { Self::Unavailable(e.to_string()) }
    }
}

/// SQLITE_FULL (13): the disk, or `max_page_count`, is full.
fn is_full(e: &sqlx::Error) -> bool {
    match e {
        sqlx::Error::Database(db) => {
            db.code().and_then(|c| c.parse::<i32>().ok()).is_some_and(|c| c & 0xff == 13)
                || db.message().contains("database or disk is full")
        }
        _ => false,
    }
}

/// A stored job.
#[derive(Clone, Debug, PartialEq)]
pub struct JobRow {
    pub seq: i64,
    pub id: String,
    pub kind: String,
    pub created_at: String,
    /// The request body as sent (JSON text).
    pub request: Bytes,
    /// The result as served (JSON text).
    pub result: Bytes,
    pub engine_us: i64,
    pub engine_version: String,
    /// The label a client stored with the job (`?label=`).
    pub label: Option<String>,
}

/// What a list of jobs shows of each, without its request and result.
#[derive(Clone, Debug, sqlx::FromRow)]
pub struct JobSummary {
    pub id: String,
    pub kind: String,
    pub created_at: String,
    pub engine_us: i64,
    pub label: Option<String>,
    /// Bytes of its request and result together.
    pub bytes: i64,
}

/// A job as SQLite returns it.
#[derive(sqlx::FromRow)]
struct Row {
    seq: i64,
    id: String,
    kind: String,
    created_at: String,
    request: String,
    result: String,
    engine_us: i64,
    engine_version: String,
    label: Option<String>,
}

impl From<Row> for JobRow {
    fn from(r: Row) -> Self {
        let Row { seq, id, kind, created_at, request, result, engine_us, engine_version, label } = r;
        let (request, result) = (request.into(), result.into());
        Self { seq, id, kind, created_at, request, result, engine_us, engine_version, label }
    }
}

/// A job to store (its `seq` is assigned by the database). `request` and
/// `result` must be UTF-8 JSON text.
#[derive(Clone, Debug)]
pub struct NewJob {
    pub id: String,
    pub kind: String,
    pub created_at: String,
    pub request: Bytes,
    pub result: Bytes,
    pub engine_us: i64,
    pub engine_version: String,
    /// The key of a job computed for a template's parameters
    /// ([`Store::find_by_key`]); None for a job POSTed directly.
    pub request_key: Option<String>,
    /// A client's label (`?label=`, e.g. a student's id).
    pub label: Option<String>,
}

impl NewJob {
    fn stored(self, seq: i64) -> JobRow {
        let NewJob { id, kind, created_at, request, result, engine_us, engine_version, label, .. } = self;
        JobRow { seq, id, kind, created_at, request, result, engine_us, engine_version, label }
    }

    /// Bytes of the request and the result together.
    pub fn bytes(&self) -> usize {
        self.request.len() + self.result.len()
    }
}

/// A page of the jobs list.
#[derive(Debug)]
pub struct Page {
    pub rows: Vec<JobRow>,
    /// Bytes of their requests and results together.
    pub bytes: usize,
    /// Whether the page stopped at its size in bytes (more jobs follow).
    pub cut: bool,
}

/// Which jobs a list holds: of one kind, of one label (None: any).
#[derive(Clone, Copy, Debug, Default)]
pub struct Filter<'a> {
    pub kind: Option<&'a str>,
    pub label: Option<&'a str>,
}

/// A job handed to the writer, with where to send its seq.
type Pending = (NewJob, oneshot::Sender<Result<i64, StoreError>>);

/// How the database is opened.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// Largest size of the database file, bytes (SQLite's `max_page_count`);
    /// beyond it inserts fail with [`StoreError::Full`]. None: the disk's.
    pub max_bytes: Option<u64>,
}

#[derive(Clone)]
pub struct Store {
    pool: SqlitePool,
    writer: mpsc::Sender<Pending>,
    /// Transactions the writer has committed.
    commits: Arc<AtomicU64>,
}

impl Store {
    /// Opens (creating the file and its folder if needed) the SQLite
    /// database at `url`, in WAL mode, and applies the migrations.
    pub async fn open(url: &str) -> Result<Self, sqlx::Error> {
        Self::open_with(url, &Options::default()).await
    }

    /// [`Store::open`] with options. A URL of another scheme than `sqlite:`
    /// is refused (see [`url::check_scheme`]).
    pub async fn open_with(url: &str, options: &Options) -> Result<Self, sqlx::Error> {
        url::check_scheme(url).map_err(|e| sqlx::Error::Configuration(Box::new(e)))?;
        let mut connect = SqliteConnectOptions::from_str(url)?
            .create_if_missing(true)
            .journal_mode(SqliteJournalMode::Wal)
            .synchronous(SqliteSynchronous::Normal)
            .busy_timeout(Duration::from_secs(10))
            .foreign_keys(true)
            // A checkpoint runs inside the commit that crosses the mark and holds up
            // the jobs waiting behind it: every 100 pages (not SQLite's 1000) those
            // pauses are short. Measured at 64 connections, flywheel jobs: p99
            // 20.3–22.9 ms at 1000 pages, 16.3–16.7 ms at 100; a checkpoint beside the
            // writer instead (PASSIVE) never resets a log that is always being
            // written, and it grew by 100 MB/s.
            .pragma("wal_autocheckpoint", "100");
        if let Some(max) = options.max_bytes {
            // SQLite's default page size, 4096 bytes (set before the first table).
            connect = connect.page_size(4096).pragma("max_page_count", (max / 4096).max(1).to_string());
        }
        let file = connect.get_filename();
        if let Some(dir) = file.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(|e| sqlx::Error::Configuration(Box::new(e)))?;
        }
        let pool = SqlitePoolOptions::new().max_connections(8).connect_with(connect).await?;
        MIGRATOR.run(&pool).await?;
        let (writer, queue) = mpsc::channel(writer::QUEUE);
        let commits = Arc::new(AtomicU64::new(0));
        tokio::spawn(writer::write_batches(pool.clone(), queue, commits.clone()));
        Ok(Self { pool, writer, commits })
    }

    /// How many transactions the writer has committed (jobs ≥ commits under load).
    pub fn commits(&self) -> u64 {
        self.commits.load(Ordering::Relaxed)
    }

    /// Inserts a job; its transaction has committed when this returns.
    pub async fn insert(&self, job: NewJob) -> Result<JobRow, StoreError> {
        let stopped = || StoreError::Unavailable("the store's writer has stopped".into());
        let (reply, stored) = oneshot::channel();
        self.writer.send((job.clone(), reply)).await.map_err(|_| stopped())?;
        let seq = stored.await.map_err(|_| stopped())??;
        Ok(job.stored(seq))
    }

    /// The id of the newest job stored under `key` whose request is
    /// `request`, byte for byte (the key only narrows the search; only
    /// requests are compared, and no result is read).
    pub async fn find_by_key(&self, key: &str, request: &[u8]) -> Result<Option<String>, StoreError> {
        let candidates: Vec<(String, String)> = sqlx::query_as(SELECT_BY_KEY).bind(key).fetch_all(&self.pool).await?;
        Ok(candidates.into_iter().find(|(_, r)| r.as_bytes() == request).map(|(id, _)| id))
    }

    /// Stores a template's JSON under `id`; false when the id is taken.
    pub async fn insert_template(&self, id: &str, created_at: &str, body: &str) -> Result<bool, StoreError> {
        let done = sqlx::query("INSERT INTO templates (id, created_at, body) VALUES (?, ?, ?) ON CONFLICT DO NOTHING")
            .bind(id)
            .bind(created_at)
            .bind(body)
            .execute(&self.pool)
            .await?;
        Ok(done.rows_affected() == 1)
    }

    /// A stored template's JSON.
    pub async fn template(&self, id: &str) -> Result<Option<String>, StoreError> {
        Ok(sqlx::query_scalar("SELECT body FROM templates WHERE id = ?").bind(id).fetch_optional(&self.pool).await?)
    }

    /// Every stored template's JSON, oldest first.
    pub async fn templates(&self) -> Result<Vec<String>, StoreError> {
        Ok(sqlx::query_scalar("SELECT body FROM templates ORDER BY created_at, id").fetch_all(&self.pool).await?)
    }

    pub async fn get(&self, id: &str) -> Result<Option<JobRow>, StoreError> {
        let row: Option<Row> = sqlx::query_as(SELECT_ROW).bind(id).fetch_optional(&self.pool).await?;
        Ok(row.map(JobRow::from))
    }

    /// The newest `limit` jobs without their request and result (a page's list).
    pub async fn recent(&self, limit: i64) -> Result<Vec<JobSummary>, StoreError> {
        Ok(sqlx::query_as("SELECT id, kind, created_at, engine_us, label, bytes FROM jobs ORDER BY seq DESC LIMIT ?")
            .bind(limit)
            .fetch_all(&self.pool)
            .await?)
    }

    /// Bytes of a job's request and result together, without loading them.
    pub async fn size(&self, id: &str) -> Result<Option<usize>, StoreError> {
        let bytes: Option<i64> =
            sqlx::query_scalar("SELECT bytes FROM jobs WHERE id = ?").bind(id).fetch_optional(&self.pool).await?;
        Ok(bytes.map(|b| usize::try_from(b).unwrap_or(0)))
    }

    /// Up to `limit` jobs, newest first, of one kind or all (and of one
    /// label or any), older than `before` (a seq), stopping before their
    /// requests and results together exceed `max_bytes` (one job at least).
    pub async fn list(
        &self,
        filter: &Filter<'_>,
        before: Option<i64>,
        limit: i64,
        max_bytes: usize,
    ) -> Result<Page, StoreError> {
        let sizes: Vec<(i64, i64)> = sqlx::query_as(
            "SELECT seq, bytes FROM jobs WHERE (?1 IS NULL OR kind = ?1) AND (?4 IS NULL OR label = ?4) AND seq < ?2 \
             ORDER BY seq DESC LIMIT ?3",
        )
        .bind(filter.kind)
        .bind(before.unwrap_or(i64::MAX))
        .bind(limit)
        .bind(filter.label)
        .fetch_all(&self.pool)
        .await?;
        let (mut total, mut last, mut cut) = (0usize, None, false);
        for (i, &(seq, bytes)) in sizes.iter().enumerate() {
            let bytes = usize::try_from(bytes).unwrap_or(0);
            if i > 0 && total + bytes > max_bytes {
                cut = true;
                break;
            }
            (total, last) = (total + bytes, Some(seq));
        }
        let Some(last) = last else { return Ok(Page { rows: Vec::new(), bytes: 0, cut }) };
        let rows: Vec<Row> = sqlx::query_as(
            "SELECT seq, id, kind, created_at, request, result, engine_us, engine_version, label FROM jobs \
             WHERE (?1 IS NULL OR kind = ?1) AND (?4 IS NULL OR label = ?4) AND seq < ?2 AND seq >= ?3 \
             ORDER BY seq DESC",
        )
        .bind(filter.kind)
        .bind(before.unwrap_or(i64::MAX))
        .bind(last)
        .bind(filter.label)
        .fetch_all(&self.pool)
        .await?;
        Ok(Page { rows: rows.into_iter().map(JobRow::from).collect(), bytes: total, cut })
    }

    /// The database's kind, as its URL's scheme names it.
    pub fn backend(&self) -> &'static str {
        "sqlite"
    }

    /// Whether the database answers a query (within the pool's wait for a
    /// connection); the error says why not.
    pub async fn check(&self) -> Result<(), StoreError> {
        sqlx::query("SELECT 1").execute(&self.pool).await?;
        Ok(())
    }

    /// Closes the database's connections: every later use fails (a service
    /// stopping; the tests' database gone away).
    pub async fn close(&self) {
        self.pool.close().await;
    }

    /// SQLite's own check of the file (`PRAGMA integrity_check`): "ok" or what is wrong.
    pub async fn integrity(&self) -> Result<String, StoreError> {
        Ok(sqlx::query_scalar("PRAGMA integrity_check").fetch_one(&self.pool).await?)
    }
}

const SELECT_ROW: &str =
    "SELECT seq, id, kind, created_at, request, result, engine_us, engine_version, label FROM jobs WHERE id = ?";
const SELECT_BY_KEY: &str = "SELECT id, request FROM jobs WHERE request_key = ? ORDER BY seq DESC LIMIT 8";
