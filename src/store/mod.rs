//! Jobs in SQLite or PostgreSQL (sqlx; [`backend`]): nothing here knows
//! about HTTP or the engine; jobs go in and come out as JSON text (shared
//! [`Bytes`], so the text stored is the text served, never copied) with
//! their metadata.
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
//!
//! Two rules keep every acknowledged write committed:
//! - A statement that writes is run to its end (`execute`, `fetch_all`),
//!   never `fetch_one` or `fetch_optional`: SQLite commits a statement
//!   outside a transaction when it ends, and sqlx ends a statement read for
//!   one row by resetting it, dropping that commit's error (SQLITE_FULL on a
//!   full disk: a row answered, nothing stored).
//! - An explicit transaction runs on a connection [`held`] for it, which
//!   goes back to the pool only once its `COMMIT` has succeeded.

pub(crate) mod backend;
pub mod backup;
mod health;
mod held;
mod idempotency;
mod list;
mod migrations;
mod packed;
mod queue;
mod retention;
mod rows;
mod url;
mod wal;
mod writer;

pub use idempotency::{Answer, KEEP};
pub use list::{Filter, Plan, list_sql};
pub use queue::{Claimed, Queued, Waiting};
pub use retention::{BY_AGE, NTH_NEWEST, Retention};
pub use url::{Backend, SchemeError, check_scheme, redact};

use backend::{Db, on_pool};
use bytes::Bytes;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use tokio::sync::{mpsc, oneshot};

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
    /// The database refused a value it was given (PostgreSQL's class 22,
    /// data exception; SQLite's SQLITE_TOOBIG): the request's to mend,
    /// not a condition to retry.
    #[error("the database refused a value: {0}")]
    Refused(String),
}

impl From<sqlx::Error> for StoreError {
    fn from(e: sqlx::Error) -> Self {
        backend::classify(e)
    }
}

/// Where a job is: waiting to be computed, computing, or ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    Queued,
    Running,
    Done,
    Failed,
}

impl Status {
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Queued => "queued",
            Self::Running => "running",
            Self::Done => "done",
            Self::Failed => "failed",
        }
    }
}

/// The status stored as text (a job stored before statuses is done).
impl From<String> for Status {
    fn from(text: String) -> Self {
        match text.as_str() {
            "queued" => Self::Queued,
            "running" => Self::Running,
            "failed" => Self::Failed,
            _ => Self::Done,
        }
    }
}

/// A stored job.
#[derive(Clone, Debug, PartialEq)]
pub struct JobRow {
    /// Its place in the store (from 1); 0 for a job answered without being
    /// stored ([`NewJob::unstored`]).
    pub seq: i64,
    pub id: String,
    pub kind: String,
    pub created_at: String,
    /// The request body as sent (JSON text).
    pub request: Bytes,
    /// The result as served (JSON text; `null` until the job is done).
    pub result: Bytes,
    pub engine_us: i64,
    pub engine_version: String,
    /// The label a client stored with the job (`?label=`).
    pub label: Option<String>,
    pub status: Status,
    /// Why a failed job failed: a problem+json document (JSON text).
    pub problem: Option<Bytes>,
}

/// What a list of jobs shows of each, without its request and result.
#[derive(Clone, Debug)]
pub struct JobSummary {
    pub id: String,
    pub kind: String,
    pub created_at: String,
    pub engine_us: i64,
    pub label: Option<String>,
    /// Bytes of its request and result together.
    pub bytes: i64,
    pub status: Status,
}

/// A job as the database returns it (`rows.rs` reads it).
pub(crate) struct Row {
    seq: i64,
    id: String,
    kind: String,
    created_at: String,
    request: String,
    result: String,
    engine_us: i64,
    engine_version: String,
    label: Option<String>,
    status: Status,
    problem: Option<String>,
    result_zstd: Option<Vec<u8>>,
}

/// A row's result expanded where it was stored compressed ([`packed`]).
impl TryFrom<Row> for JobRow {
    type Error = StoreError;

    fn try_from(r: Row) -> Result<Self, StoreError> {
        let Row {
            seq, id, kind, created_at, request, result, engine_us, engine_version, label, status, problem, ..
        } = r;
        let result = packed::unpack(result, r.result_zstd)?;
        let (request, problem) = (request.into(), problem.map(Bytes::from));
        Ok(Self { seq, id, kind, created_at, request, result, engine_us, engine_version, label, status, problem })
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
    /// The job as a row that no database holds (seq 0), for an answer that stores nothing.
    pub fn unstored(self) -> JobRow {
        self.stored(0)
    }

    fn stored(self, seq: i64) -> JobRow {
        let NewJob { id, kind, created_at, request, result, engine_us, engine_version, label, .. } = self;
        let (status, problem) = (Status::Done, None);
        JobRow { seq, id, kind, created_at, request, result, engine_us, engine_version, label, status, problem }
    }

    /// Bytes of the request and the result together.
    pub fn bytes(&self) -> usize {
        self.request.len() + self.result.len()
    }
}

/// A job handed to the writer, with its result compressed where it is
/// stored so ([`packed`]), and where to send its seq.
type Pending = ((NewJob, Option<Vec<u8>>), oneshot::Sender<Result<i64, StoreError>>);

/// How the database is opened.
#[derive(Clone, Debug)]
pub struct Options {
    /// Largest size of the database file, bytes (SQLite's `max_page_count`);
    /// beyond it inserts fail with [`StoreError::Full`]. None: the disk's.
    /// PostgreSQL refuses it (its server limits its own space).
    pub max_bytes: Option<u64>,
    /// How long a start waits for a PostgreSQL server that does not answer.
    pub wait: std::time::Duration,
    /// Whether a SQLite commit survives a power loss (`synchronous=FULL`:
    /// the log is synced at every commit) or only a crash of the process
    /// (`NORMAL`: synced at checkpoints). PostgreSQL's server decides its own.
    pub power_safe: bool,
}

impl Default for Options {
    fn default() -> Self {
        Self { max_bytes: None, wait: std::time::Duration::from_secs(30), power_safe: true }
    }
}

#[derive(Clone)]
pub struct Store {
    db: Db,
    writer: mpsc::Sender<Pending>,
    /// Transactions the writer has committed.
    commits: Arc<AtomicU64>,
    /// The last write that failed, until one commits ([`Store::writable`]).
    writes: Arc<health::Writes>,
}

impl Store {
    /// Opens the database at `url` (a SQLite file is created with its folder
    /// if needed, in WAL mode) and applies the migrations.
    pub async fn open(url: &str) -> Result<Self, sqlx::Error> {
        Self::open_with(url, &Options::default()).await
    }

    /// [`Store::open`] with options. A URL of another scheme than `sqlite:`
    /// or `postgres:` is refused (see [`url::check_scheme`]).
    pub async fn open_with(url: &str, options: &Options) -> Result<Self, sqlx::Error> {
        let backend = url::check_scheme(url).map_err(|e| sqlx::Error::Configuration(Box::new(e)))?;
        let db = Db::open(url, backend, options).await?;
        let (writer, queue) = mpsc::channel(writer::QUEUE);
        let (commits, writes) = (Arc::new(AtomicU64::new(0)), Arc::new(health::Writes::default()));
        // The log's keeper lives as long as the writer, which ends with the last of the store's clones.
        let (alive, ended) = oneshot::channel::<()>();
        if let Db::Sqlite(pool) = &db {
            wal::spawn(pool.clone(), ended);
        }
        let writing = writer::write_batches(db.clone(), queue, commits.clone(), writes.clone());
        tokio::spawn(async move {
            writing.await;
            drop(alive);
        });
        Ok(Self { db, writer, commits, writes })
    }

    /// How many transactions the writer has committed (jobs ≥ commits under load).
    pub fn commits(&self) -> u64 {
        self.commits.load(Ordering::Relaxed)
    }

    /// Inserts a job; its transaction has committed when this returns.
    pub async fn insert(&self, job: NewJob) -> Result<JobRow, StoreError> {
        let stopped = || StoreError::Unavailable("the store's writer has stopped".into());
        let (reply, stored) = oneshot::channel();
        // Compressed here, on the caller's task, not on the one writer's.
        let zstd = packed::pack(&job.result).zstd;
        self.writer.send(((job.clone(), zstd), reply)).await.map_err(|_| stopped())?;
        let seq = stored.await.map_err(|_| stopped())??;
        Ok(job.stored(seq))
    }

    /// The id of the newest job stored under `key` whose request is
    /// `request`, byte for byte (the key only narrows the search; only
    /// requests are compared, and no result is read).
    pub async fn find_by_key(&self, key: &str, request: &[u8]) -> Result<Option<String>, StoreError> {
        let candidates: Vec<(String, String)> =
            on_pool!(&self.db, pool => sqlx::query_as(SELECT_BY_KEY).bind(key).fetch_all(pool).await?);
        Ok(candidates.into_iter().find(|(_, r)| r.as_bytes() == request).map(|(id, _)| id))
    }

    /// Stores a template's JSON under `id`; false when the id is taken.
    pub async fn insert_template(&self, id: &str, created_at: &str, body: &str) -> Result<bool, StoreError> {
        let sql = "INSERT INTO templates (id, created_at, body) VALUES ($1, $2, $3) ON CONFLICT DO NOTHING";
        let done = on_pool!(&self.db, pool => {
            sqlx::query(sql).bind(id).bind(created_at).bind(body).execute(pool).await.map(|d| d.rows_affected())
        });
        Ok(self.noted(done.map_err(StoreError::from), body.len(), |n| *n > 0)? == 1)
    }

    /// A stored template's JSON.
    pub async fn template(&self, id: &str) -> Result<Option<String>, StoreError> {
        if !findable(id) {
            return Ok(None);
        }
        let sql = "SELECT body FROM templates WHERE id = $1";
        Ok(on_pool!(&self.db, pool => sqlx::query_scalar(sql).bind(id).fetch_optional(pool).await?))
    }

    /// Every stored template's JSON, oldest first.
    pub async fn templates(&self) -> Result<Vec<String>, StoreError> {
        let sql = "SELECT body FROM templates ORDER BY created_at, id";
        Ok(on_pool!(&self.db, pool => sqlx::query_scalar(sql).fetch_all(pool).await?))
    }

    pub async fn get(&self, id: &str) -> Result<Option<JobRow>, StoreError> {
        if !findable(id) {
            return Ok(None);
        }
        let row: Option<Row> =
            on_pool!(&self.db, pool => sqlx::query_as(SELECT_ROW).bind(id).fetch_optional(pool).await?);
        row.map(JobRow::try_from).transpose()
    }

    /// The newest `limit` jobs without their request and result (a page's list).
    pub async fn recent(&self, limit: i64) -> Result<Vec<JobSummary>, StoreError> {
        let sql = "SELECT id, kind, created_at, engine_us, label, bytes, status FROM jobs ORDER BY seq DESC LIMIT $1";
        Ok(on_pool!(&self.db, pool => sqlx::query_as(sql).bind(limit).fetch_all(pool).await?))
    }

    /// Bytes of a job's request and result together, without loading them.
    pub async fn size(&self, id: &str) -> Result<Option<usize>, StoreError> {
        if !findable(id) {
            return Ok(None);
        }
        let sql = "SELECT bytes FROM jobs WHERE id = $1";
        let bytes: Option<i64> =
            on_pool!(&self.db, pool => sqlx::query_scalar(sql).bind(id).fetch_optional(pool).await?);
        Ok(bytes.map(|b| usize::try_from(b).unwrap_or(0)))
    }

    /// The database's kind.
    pub fn backend(&self) -> Backend {
        self.db.backend()
    }

    /// Whether the database answers a query (within the pool's wait for a
    /// connection); the error says why not.
    pub async fn check(&self) -> Result<(), StoreError> {
        on_pool!(&self.db, pool => {
            sqlx::query("SELECT 1").execute(pool).await?;
        });
        Ok(())
    }

    /// Closes the database's connections: every later use fails (a service
    /// stopping; the tests' database gone away).
    pub async fn close(&self) {
        on_pool!(&self.db, pool => pool.close().await);
    }

    /// When a SQLite commit reaches the disk, as SQLite reports it on a
    /// connection of the pool: 2 (FULL, at every commit) or 1 (NORMAL, at
    /// checkpoints). PostgreSQL's server has its own settings.
    pub async fn synchronous(&self) -> Result<i64, StoreError> {
        match &self.db {
            Db::Sqlite(pool) => Ok(sqlx::query_scalar("PRAGMA synchronous").fetch_one(pool).await?),
            Db::Postgres(_) => Err(StoreError::Unavailable("synchronous is SQLite's".into())),
        }
    }

    /// SQLite's own check of the file (`PRAGMA integrity_check`): "ok" or
    /// what is wrong. A PostgreSQL server checks its own pages.
    pub async fn integrity(&self) -> Result<String, StoreError> {
        match &self.db {
            Db::Sqlite(pool) => Ok(sqlx::query_scalar("PRAGMA integrity_check").fetch_one(pool).await?),
            Db::Postgres(_) => Err(StoreError::Unavailable("integrity_check is SQLite's".into())),
        }
    }
}

/// Whether a row's key can be `key`: no stored text holds a NUL byte
/// (PostgreSQL's text cannot, and the ids stored are UUIDs and slugs), so
/// a key with one finds nothing without asking the database (which would
/// refuse it).
pub(crate) fn findable(key: &str) -> bool {
    !key.contains('\0')
}

/// The columns of a [`Row`].
macro_rules! row_columns {
    () => {
        "seq, id, kind, created_at, request, result, engine_us, engine_version, label, status, problem, result_zstd"
    };
}
pub(crate) use row_columns;

const SELECT_ROW: &str = concat!("SELECT ", row_columns!(), " FROM jobs WHERE id = $1");
const SELECT_BY_KEY: &str =
    "SELECT id, request FROM jobs WHERE request_key = $1 AND status = 'done' ORDER BY seq DESC LIMIT 8";
