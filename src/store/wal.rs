//! SQLite's log (the WAL) kept bounded. A checkpoint copies the log into
//! the database, but the log starts again from its beginning only once no
//! reader still reads an old snapshot of it; with lists following one
//! another a reader always did, the automatic checkpoints could never
//! restart it, and it grew without bound (735 MB after 15 s of two listing
//! clients at 10⁶ jobs) and stayed on disk across restarts. So:
//! - `journal_size_limit` ([`LIMIT`]): a log restarted is cut to that size;
//! - at open, a `TRUNCATE` checkpoint empties a log left from before;
//! - five times a second, a log past half the limit is checkpointed with
//!   `TRUNCATE` (`RESTART`, then cut to nothing), waiting at most [`WAIT`]
//!   for the readers of older snapshots to finish (each read is one short
//!   statement, on its index). While it waits it holds off new writes, so
//!   the wait is short; where it cannot finish it is tried again at the next look.

use sqlx::SqlitePool;
use std::path::PathBuf;
use std::time::Duration;

/// The log's bound: `journal_size_limit`, and twice the size that starts a checkpoint.
pub const LIMIT: u64 = 64 << 20;
/// The longest a checkpoint waits for readers and the writer (the most it
/// holds a write up): 100 ms (SQL text, as PRAGMA takes no parameter).
const WAIT: &str = "PRAGMA busy_timeout = 100";
/// Every other statement's wait: [`super::backend::BUSY`].
const BUSY: &str = "PRAGMA busy_timeout = 10000";
/// How often the log's size is looked at (a writer at 50 MB/s adds 10 MB between looks).
const EVERY: Duration = Duration::from_millis(200);

/// Empties a log left from before.
pub(super) async fn at_open(pool: &SqlitePool) -> Result<(), sqlx::Error> {
    checkpoint(pool, BUSY).await.map(drop)
}

/// Looks after the log of `pool`'s database until `ended` (the store's writer has ended).
pub(super) fn spawn(pool: SqlitePool, mut ended: tokio::sync::oneshot::Receiver<()>) {
    let mut log = pool.connect_options().get_filename().as_os_str().to_owned();
    log.push("-wal");
    let log = PathBuf::from(log);
    tokio::spawn(async move {
        let mut tick = tokio::time::interval(EVERY);
        tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
        loop {
            tokio::select! {
                _ = &mut ended => return,
                _ = tick.tick() => {}
            }
            let size = std::fs::metadata(&log).map_or(0, |m| m.len());
            if size > LIMIT / 2 {
                let started = std::time::Instant::now();
                let done = checkpoint(&pool, WAIT).await;
                let ms = started.elapsed().as_secs_f64() * 1e3;
                match done {
                    Ok(true) => tracing::debug!(size, ms, "the log was checkpointed and emptied"),
                    Ok(false) => tracing::debug!(size, ms, "the log's readers were still reading: tried again"),
                    Err(e) => tracing::warn!(error = %e, "the log could not be checkpointed"),
                }
            }
        }
    });
}

/// A `TRUNCATE` checkpoint waiting at most as `wait` says: whether it emptied the log.
async fn checkpoint(pool: &SqlitePool, wait: &'static str) -> Result<bool, sqlx::Error> {
    let mut conn = pool.acquire().await?;
    sqlx::query(wait).execute(&mut *conn).await?;
    // Run to its end (fetch_all), as every statement that writes here is.
    let done: Result<Vec<(i64, i64, i64)>, _> =
        sqlx::query_as("PRAGMA wal_checkpoint(TRUNCATE)").fetch_all(&mut *conn).await;
    sqlx::query(BUSY).execute(&mut *conn).await?;
    // (busy, log frames, frames checkpointed): busy 0 when it restarted the log.
    Ok(done?.first().is_some_and(|(busy, ..)| *busy == 0))
}
