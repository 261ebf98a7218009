//! The group-commit writer: the jobs waiting on the channel (up to
//! [`MAX_BATCH`] of them and [`MAX_BATCH_BYTES`]) go into one multi-row
//! INSERT; each caller gets its seq once that has committed, or the error.
//!
//! When the batch fails because the storage is full, every job in it fails
//! with [`StoreError::Full`] (nothing was written; the next batch tries
//! again, so writes resume when space returns). On any other failure the
//! jobs are inserted one by one in an explicit transaction, so a bad row
//! fails alone. The transaction is plain `BEGIN`/`COMMIT`/`ROLLBACK` on one
//! connection: SQLite may roll a transaction back by itself after an I/O
//! error, and a rollback that finds nothing to undo is harmless here, where
//! sqlx's own transaction bookkeeping would be left out of step.

use super::{Pending, StoreError};
use sqlx::SqliteConnection;
use sqlx::sqlite::SqlitePool;
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

const INSERT: &str = "INSERT INTO jobs (id, kind, created_at, request, result, engine_us, engine_version, bytes, \
                      request_key, label) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)";

pub async fn write_batches(pool: SqlitePool, mut queue: mpsc::Receiver<Pending>, commits: Arc<AtomicU64>) {
    let mut waiting = Vec::with_capacity(MAX_BATCH);
    while queue.recv_many(&mut waiting, MAX_BATCH).await > 0 {
        while !waiting.is_empty() {
            let take = within_bytes(&waiting);
            let batch: Vec<Pending> = waiting.drain(..take).collect();
            write(&pool, batch, &commits).await;
        }
    }
}

/// How many of the first jobs fit in [`MAX_BATCH_BYTES`] (one at least).
fn within_bytes(jobs: &[Pending]) -> usize {
    let mut total = 0;
    let fit = jobs.iter().take_while(|(j, _)| {
        total += j.bytes();
        total <= MAX_BATCH_BYTES
    });
    fit.count().max(1)
}

/// One batch in one transaction; each caller answered.
async fn write(pool: &SqlitePool, batch: Vec<Pending>, commits: &AtomicU64) {
    let outcome = match insert_together(pool, &batch).await {
        Ok(seqs) => Ok(seqs.into_iter().map(Ok).collect()),
        Err(StoreError::Full) => Err(StoreError::Full),
        // One bad row fails the whole statement: insert them one by one.
        Err(_) => insert_all(pool, &batch).await,
    };
    match outcome {
        Ok(seqs) => {
            commits.fetch_add(1, Ordering::Relaxed);
            for ((_, reply), seq) in batch.into_iter().zip(seqs) {
                let _ = reply.send(seq);
            }
        }
        Err(e) => {
            tracing::warn!(error = %e, jobs = batch.len(), "jobs not stored");
            for (_, reply) in batch {
                let _ = reply.send(Err(e.clone()));
            }
        }
    }
}

/// The text of a job's JSON (checked UTF-8 when the job was made).
fn text(b: &bytes::Bytes) -> &str {
    std::str::from_utf8(b).unwrap_or("null")
}

/// The whole batch as one multi-row INSERT (one statement: one round trip to
/// SQLite's connection thread, and atomic): each job's seq, in batch order.
async fn insert_together(pool: &SqlitePool, batch: &[Pending]) -> Result<Vec<i64>, StoreError> {
    let rows = vec!["(?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"; batch.len()].join(", ");
    let sql = format!(
        "INSERT INTO jobs (id, kind, created_at, request, result, engine_us, engine_version, bytes, request_key, label) \
         VALUES {rows} \
         RETURNING id, seq"
    );
    // Safe: the text is the fixed columns and one placeholder group per job; every value is bound.
    let mut query = sqlx::query_as::<_, (String, i64)>(sqlx::AssertSqlSafe(sql));
    for (j, _) in batch {
        query = query.bind(&j.id).bind(&j.kind).bind(&j.created_at).bind(text(&j.request)).bind(text(&j.result));
        query = query.bind(j.engine_us).bind(&j.engine_version).bind(j.bytes() as i64).bind(&j.request_key);
        query = query.bind(&j.label);
    }
    // RETURNING gives the rows in no promised order: match them by id.
    let seqs: std::collections::HashMap<String, i64> = query.fetch_all(pool).await?.into_iter().collect();
    let missing = || StoreError::Unavailable("a stored job was not returned".into());
    batch.iter().map(|(j, _)| seqs.get(&j.id).copied().ok_or_else(missing)).collect()
}

/// One transaction, row by row: each job's seq, or why its own insert failed.
async fn insert_all(pool: &SqlitePool, batch: &[Pending]) -> Result<Vec<Result<i64, StoreError>>, StoreError> {
    let mut conn = pool.acquire().await?;
    sqlx::query("BEGIN IMMEDIATE").execute(&mut *conn).await?;
    match insert_rows(&mut conn, batch).await {
        Ok(seqs) => match sqlx::query("COMMIT").execute(&mut *conn).await {
            Ok(_) => Ok(seqs),
            Err(e) => Err(rollback(&mut conn, e.into()).await),
        },
        Err(e) => Err(rollback(&mut conn, e).await),
    }
}

/// The rows of the batch inside the open transaction.
async fn insert_rows(
    conn: &mut SqliteConnection,
    batch: &[Pending],
) -> Result<Vec<Result<i64, StoreError>>, StoreError> {
    let mut seqs = Vec::with_capacity(batch.len());
    for (j, _) in batch {
        let done = sqlx::query(INSERT)
            .bind(&j.id)
            .bind(&j.kind)
            .bind(&j.created_at)
            .bind(text(&j.request))
            .bind(text(&j.result))
            .bind(j.engine_us)
            .bind(&j.engine_version)
            .bind(j.bytes() as i64)
            .bind(&j.request_key)
            .bind(&j.label)
            .execute(&mut *conn)
            .await;
        match done {
            Ok(d) => seqs.push(Ok(d.last_insert_rowid())),
            // A row the schema refuses fails alone; anything else ends the transaction.
            Err(e) if is_constraint(&e) => seqs.push(Err(StoreError::Unavailable(e.to_string()))),
            Err(e) => return Err(e.into()),
        }
    }
    Ok(seqs)
}

/// SQLITE_CONSTRAINT (19): this row breaks a rule of the schema (a duplicate id).
fn is_constraint(e: &sqlx::Error) -> bool {
    matches!(e, sqlx::Error::Database(db) if db.code().and_then(|c| c.parse::<i32>().ok()).is_some_and(|c| c & 0xff == 19))
}

/// Undoes the open transaction, if SQLite has not already; `e` is the cause.
async fn rollback(conn: &mut SqliteConnection, e: StoreError) -> StoreError {
    let _ = sqlx::query("ROLLBACK").execute(&mut *conn).await;
    e
}
