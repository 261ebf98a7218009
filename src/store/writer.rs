//! The group-commit writer: the jobs waiting on the channel (up to
//! [`MAX_BATCH`] of them and [`MAX_BATCH_BYTES`]) go into one multi-row
//! INSERT; each caller gets its seq once that has committed, or the error.
//!
//! When the batch fails because the storage is full, every job in it fails
//! with [`StoreError::Full`] (nothing was written; the next batch tries
//! again, so writes resume when space returns). Where the database refuses
//! the statement for another reason, the jobs are inserted one by one in an
//! explicit transaction, so a bad row fails alone; where it cannot be
//! reached, every job fails at once (no second wait for a connection), and
//! so do the jobs that came while it waited: a job waits for the database
//! at most once, one pool's wait (5 s), however many come while it is away. The
//! transaction is plain `BEGIN`/`COMMIT` on a connection [`Held`] for it,
//! which goes back to the pool only once committed (closed otherwise: a
//! failed transaction's state is the database's to know, not the pool's).
//! On PostgreSQL a failed row would abort the transaction, so each row
//! there has a savepoint of its own.

use super::backend::{Db, classify, is_constraint, is_full, is_refused, on_pool};
use super::health::Writes;
use super::held::Held;
use super::{Pending, StoreError};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use tokio::sync::mpsc;

/// Most jobs in one transaction.
const MAX_BATCH: usize = 256;
/// Most bytes of jobs in one statement (one job at least): binding copies
/// each value twice (sqlx, then SQLite), so twelve 16 MB results waiting
/// together cost 400 MB of copies in one statement.
const MAX_BATCH_BYTES: usize = 32 << 20;
/// Jobs waiting for the writer before callers wait to hand theirs over.
pub const QUEUE: usize = 4096;

const COLUMNS: &str = "INSERT INTO jobs (id, kind, created_at, request, result, engine_us, engine_version, bytes, \
                       request_key, label, result_zstd) VALUES ";
/// The values of one job.
const ROW: usize = 11;

pub async fn write_batches(db: Db, mut queue: mpsc::Receiver<Pending>, commits: Arc<AtomicU64>, writes: Arc<Writes>) {
    let mut waiting = Vec::with_capacity(MAX_BATCH);
    while queue.recv_many(&mut waiting, MAX_BATCH).await > 0 {
        while !waiting.is_empty() {
            let take = within_bytes(&waiting);
            let batch: Vec<Pending> = waiting.drain(..take).collect();
            if let Some(away) = write(&db, batch, &commits, &writes).await {
                // The jobs that came while that batch waited for the database: the same answer
                // now, not a wait of their own on top of the one they sat through.
                waiting.extend(std::iter::from_fn(|| queue.try_recv().ok()));
                for (_, reply) in waiting.drain(..) {
                    let _ = reply.send(Err(away.clone()));
                }
            }
        }
    }
}

/// How many of the first jobs fit in [`MAX_BATCH_BYTES`] (one at least).
fn within_bytes(jobs: &[Pending]) -> usize {
    let mut total = 0;
    let fit = jobs.iter().take_while(|((j, _), _)| {
        total += j.bytes();
        total <= MAX_BATCH_BYTES
    });
    fit.count().max(1)
}

/// One batch in one transaction; each caller answered. The error where the
/// database could not be reached (not where it refused the statement).
async fn write(db: &Db, batch: Vec<Pending>, commits: &AtomicU64, writes: &Writes) -> Option<StoreError> {
    let (outcome, away) = match insert_together(db, &batch).await {
        Ok(seqs) => (Ok(seqs.into_iter().map(Ok).collect()), false),
        // The database refused the statement: one bad row fails it whole, so insert them one by one.
        Err(e) if matches!(e, sqlx::Error::Database(_)) && !is_full(&e) => (insert_all(db, &batch).await, false),
        // Full, or the database away (no second wait for a connection).
        Err(e) => (Err(classify(e)), true),
    };
    match outcome {
        Ok(seqs) => {
            commits.fetch_add(1, Ordering::Relaxed);
            writes.committed();
            for ((_, reply), seq) in batch.into_iter().zip(seqs) {
                let _ = reply.send(seq);
            }
            None
        }
        Err(e) => {
            tracing::warn!(error = %e, jobs = batch.len(), "jobs not stored");
            // The smallest job of the batch: readiness probes with a write that size.
            writes.failed(batch.iter().map(|((j, _), _)| j.bytes()).min().unwrap_or(0), &e);
            for (_, reply) in batch {
                let _ = reply.send(Err(e.clone()));
            }
            (away && matches!(e, StoreError::Unavailable(_))).then_some(e)
        }
    }
}

/// The text of a job's JSON (checked UTF-8 when the job was made).
fn text(b: &bytes::Bytes) -> &str {
    std::str::from_utf8(b).unwrap_or("null")
}

/// `$1, …, $10` for the first job, `$11, …` for the next: `rows` groups.
fn placeholders(rows: usize) -> String {
    let group =
        |r: usize| format!("({})", (1..=ROW).map(|c| format!("${}", r * ROW + c)).collect::<Vec<_>>().join(", "));
    (0..rows).map(group).collect::<Vec<_>>().join(", ")
}

/// Binds a job's values, in [`COLUMNS`]' order, to a query of either backend.
/// A result compressed ([`super::packed`]) is bound as empty text and its bytes.
macro_rules! bind_job {
    ($query:expr, ($j:expr, $zstd:expr)) => {
        $query
            .bind(&$j.id)
            .bind(&$j.kind)
            .bind(&$j.created_at)
            .bind(text(&$j.request))
            .bind(if $zstd.is_some() { "" } else { text(&$j.result) })
            .bind($j.engine_us)
            .bind(&$j.engine_version)
            .bind($j.bytes() as i64)
            .bind(&$j.request_key)
            .bind(&$j.label)
            .bind($zstd.as_deref())
    };
}

/// The whole batch as one multi-row INSERT (one statement: one round trip to
/// the database, and atomic): each job's seq, in batch order.
async fn insert_together(db: &Db, batch: &[Pending]) -> Result<Vec<i64>, sqlx::Error> {
    let sql = format!("{COLUMNS}{} RETURNING id, seq", placeholders(batch.len()));
    // Safe: the text is the fixed columns and one placeholder group per job; every value is bound.
    let returned: Vec<(String, i64)> = on_pool!(db, pool => {
        let mut query = sqlx::query_as(sqlx::AssertSqlSafe(sql));
        for ((j, zstd), _) in batch {
            query = bind_job!(query, (j, zstd));
        }
        query.fetch_all(pool).await?
    });
    // RETURNING gives the rows in no promised order: match them by id.
    let seqs: std::collections::HashMap<String, i64> = returned.into_iter().collect();
    let missing = || sqlx::Error::Protocol("a stored job was not returned".into());
    batch.iter().map(|((j, _), _)| seqs.get(&j.id).copied().ok_or_else(missing)).collect()
}

/// One transaction, row by row: each job's seq, or why its own insert failed.
async fn insert_all(db: &Db, batch: &[Pending]) -> Result<Vec<Result<i64, StoreError>>, StoreError> {
    let sql = format!("{COLUMNS}{} RETURNING seq", placeholders(1));
    let (begin, savepoint) = match db {
        Db::Sqlite(_) => ("BEGIN IMMEDIATE", false),
        Db::Postgres(_) => ("BEGIN", true),
    };
    on_pool!(db, pool => {
        // Closed, not given back, unless it commits (see `held`).
        let mut held = Held::acquire(pool).await?;
        sqlx::query(begin).execute(held.conn()).await?;
        let mut seqs = Vec::with_capacity(batch.len());
        for ((j, zstd), _) in batch {
            if savepoint {
                sqlx::query("SAVEPOINT job").execute(held.conn()).await?;
            }
            let query = bind_job!(sqlx::query_scalar(sqlx::AssertSqlSafe(sql.clone())), (j, zstd));
            match query.fetch_all(held.conn()).await {
                Ok(seq) => seqs.push(seq.first().copied().ok_or_else(|| StoreError::Unavailable("no seq returned".into()))),
                // A row the schema or the database refuses fails alone; anything else ends the transaction.
                Err(e) if is_constraint(&e) || is_refused(&e) => {
                    if savepoint {
                        sqlx::query("ROLLBACK TO SAVEPOINT job").execute(held.conn()).await?;
                    }
                    seqs.push(Err(classify(e)));
                }
                Err(e) => return Err(e.into()),
            }
        }
        sqlx::query("COMMIT").execute(held.conn()).await?;
        held.release();
        Ok(seqs)
    })
}
