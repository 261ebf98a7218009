//! Jobs in SQLite (sqlx): nothing here knows about HTTP or the engine; jobs
//! go in and come out as JSON text with their metadata.
//!
//! Group commit: one writer task takes the jobs of concurrent requests off
//! a channel and inserts all that are waiting in one statement (a multi-row
//! INSERT; row by row in one transaction if that fails, so a bad row fails
//! alone), then answers each caller. [`Store::insert`] returns only once the
//! transaction holding its job has committed, so a job is stored before its
//! `201` as before, and under load one commit serves many jobs (SQLite does
//! a few thousand commits a second here; the batch amortises them).

use sqlx::sqlite::{SqliteConnectOptions, SqliteJournalMode, SqlitePool, SqlitePoolOptions, SqliteSynchronous};
use std::str::FromStr;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;
use tokio::sync::{mpsc, oneshot};

/// Most jobs in one transaction.
const MAX_BATCH: usize = 256;
/// Jobs waiting for the writer before callers wait to hand theirs over.
const QUEUE: usize = 4096;

/// The migrations of `migrations/`, embedded in the binary.
pub static MIGRATOR: sqlx::migrate::Migrator = sqlx::migrate!("./migrations");

/// A stored job.
#[derive(Clone, Debug, PartialEq, sqlx::FromRow)]
pub struct JobRow {
    pub seq: i64,
    pub id: String,
    pub kind: String,
    pub created_at: String,
    pub request: String,
    pub result: String,
    pub engine_us: i64,
    pub engine_version: String,
}

/// A job to store (its `seq` is assigned by the database).
pub struct NewJob {
    pub id: String,
    pub kind: String,
    pub created_at: String,
    pub request: String,
    pub result: String,
    pub engine_us: i64,
    pub engine_version: String,
}

impl NewJob {
    fn stored(self, seq: i64) -> JobRow {
        let NewJob { id, kind, created_at, request, result, engine_us, engine_version } = self;
        JobRow { seq, id, kind, created_at, request, result, engine_us, engine_version }
    }
}

/// A job handed to the writer, with where to send its stored row.
type Pending = (NewJob, oneshot::Sender<Result<JobRow, String>>);

#[derive(Clone)]
pub struct Store {
    pool: SqlitePool,
    writer: mpsc::Sender<Pending>,
    /// Transactions the writer has committed.
    commits: Arc<AtomicU64>,
}

impl Store {
    /// Opens (creating the file and its folder if needed) the database at
    /// `url`, in WAL mode, and applies the migrations.
    pub async fn open(url: &str) -> Result<Self, sqlx::Error> {
        let options = SqliteConnectOptions::from_str(url)?
            .create_if_missing(true)
            .journal_mode(SqliteJournalMode::Wal)
            .synchronous(SqliteSynchronous::Normal)
            .busy_timeout(Duration::from_secs(10))
            .foreign_keys(true);
        let file = options.get_filename();
        if let Some(dir) = file.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(|e| sqlx::Error::Configuration(Box::new(e)))?;
        }
        let pool = SqlitePoolOptions::new().max_connections(8).connect_with(options).await?;
        MIGRATOR.run(&pool).await?;
        let (writer, queue) = mpsc::channel(QUEUE);
        let commits = Arc::new(AtomicU64::new(0));
        tokio::spawn(write_batches(pool.clone(), queue, commits.clone()));
        Ok(Self { pool, writer, commits })
    }

    /// How many transactions the writer has committed (jobs ≥ commits under load).
    pub fn commits(&self) -> u64 {
        self.commits.load(Ordering::Relaxed)
    }

    /// Inserts a job; its transaction has committed when this returns.
    pub async fn insert(&self, job: NewJob) -> Result<JobRow, sqlx::Error> {
        let stopped = || sqlx::Error::PoolClosed;
        let (reply, stored) = oneshot::channel();
        self.writer.send((job, reply)).await.map_err(|_| stopped())?;
        stored.await.map_err(|_| stopped())?.map_err(sqlx::Error::Protocol)
    }

    pub async fn get(&self, id: &str) -> Result<Option<JobRow>, sqlx::Error> {
        sqlx::query_as("SELECT * FROM jobs WHERE id = ?").bind(id).fetch_optional(&self.pool).await
    }

    /// Up to `limit` jobs, newest first, of one kind or all, older than `before` (a seq).
    pub async fn list(&self, kind: Option<&str>, before: Option<i64>, limit: i64) -> Result<Vec<JobRow>, sqlx::Error> {
        sqlx::query_as("SELECT * FROM jobs WHERE (?1 IS NULL OR kind = ?1) AND seq < ?2 ORDER BY seq DESC LIMIT ?3")
            .bind(kind)
            .bind(before.unwrap_or(i64::MAX))
            .bind(limit)
            .fetch_all(&self.pool)
            .await
    }

    /// Whether the database answers.
    pub async fn ping(&self) -> bool {
        sqlx::query("SELECT 1").execute(&self.pool).await.is_ok()
    }
}

/// The writer: every job waiting (up to [`MAX_BATCH`]) goes into one
/// transaction; each caller gets its row once that has committed, or the error.
async fn write_batches(pool: SqlitePool, mut queue: mpsc::Receiver<Pending>, commits: Arc<AtomicU64>) {
    let mut batch = Vec::with_capacity(MAX_BATCH);
    while queue.recv_many(&mut batch, MAX_BATCH).await > 0 {
        let outcome = match insert_together(&pool, &batch).await {
            Ok(seqs) => Ok(seqs.into_iter().map(Ok).collect()),
            // One bad row fails the whole statement: insert them one by one.
            Err(_) => insert_all(&pool, &batch).await,
        };
        match outcome {
            Ok(seqs) => {
                commits.fetch_add(1, Ordering::Relaxed);
                for ((job, reply), seq) in batch.drain(..).zip(seqs) {
                    let _ = reply.send(seq.map(|seq| job.stored(seq)).map_err(|e| e.to_string()));
                }
            }
            Err(e) => {
                let message = format!("commit failed: {e}");
                for (_, reply) in batch.drain(..) {
                    let _ = reply.send(Err(message.clone()));
                }
            }
        }
    }
}

/// The whole batch as one multi-row INSERT (one statement: one round trip to
/// SQLite's connection thread, and atomic): each job's seq, in batch order.
async fn insert_together(pool: &SqlitePool, batch: &[Pending]) -> Result<Vec<i64>, sqlx::Error> {
    let rows = vec!["(?, ?, ?, ?, ?, ?, ?)"; batch.len()].join(", ");
    let sql = format!(
        "INSERT INTO jobs (id, kind, created_at, request, result, engine_us, engine_version) VALUES {rows} \
         RETURNING id, seq"
    );
    // Safe: the text is the fixed columns and one placeholder group per job; every value is bound.
    let mut query = sqlx::query_as::<_, (String, i64)>(sqlx::AssertSqlSafe(sql));
    for (j, _) in batch {
        query = query.bind(&j.id).bind(&j.kind).bind(&j.created_at).bind(&j.request).bind(&j.result);
        query = query.bind(j.engine_us).bind(&j.engine_version);
    }
    // RETURNING gives the rows in no promised order: match them by id.
    let seqs: std::collections::HashMap<String, i64> = query.fetch_all(pool).await?.into_iter().collect();
    batch.iter().map(|(j, _)| seqs.get(&j.id).copied().ok_or_else(|| sqlx::Error::RowNotFound)).collect()
}

/// One transaction, row by row: each job's seq, or why its own insert failed.
async fn insert_all(pool: &SqlitePool, batch: &[Pending]) -> Result<Vec<Result<i64, sqlx::Error>>, sqlx::Error> {
    let mut tx = pool.begin().await?;
    let mut seqs = Vec::with_capacity(batch.len());
    for (j, _) in batch {
        let done = sqlx::query(
            "INSERT INTO jobs (id, kind, created_at, request, result, engine_us, engine_version) \
             VALUES (?, ?, ?, ?, ?, ?, ?)",
        )
        .bind(&j.id)
        .bind(&j.kind)
        .bind(&j.created_at)
        .bind(&j.request)
        .bind(&j.result)
        .bind(j.engine_us)
        .bind(&j.engine_version)
        .execute(&mut *tx)
        .await;
        seqs.push(done.map(|d| d.last_insert_rowid()));
    }
    tx.commit().await?;
    Ok(seqs)
}
