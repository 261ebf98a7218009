//! Jobs deleted: one by its id (`DELETE /v1/jobs/{id}`), or those past the
//! retention's age or count, a batch at a time so that no transaction holds
//! the database for long. The answers kept under an idempotency key for a
//! job go with it: a retry of that POST computes the job again instead of
//! answering with a job that is gone.

use super::backend::on_pool;
use super::held::Held;
use super::{Store, StoreError};
use std::time::{Duration, Instant};

/// Rows deleted per statement of a sweep: each statement holds SQLite's one
/// writer while it runs (a few ms; docs/SOAK.md measures the stall).
const BATCH: i64 = 100;
/// The pause after each statement, at least as long as it took: the jobs
/// being stored take the database meanwhile (a sweep deleting 10⁵ jobs in
/// one go held every POST behind it for most of a second).
const PAUSE: Duration = Duration::from_millis(20);

/// Which stored jobs are kept; None keeps every one.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Retention<'a> {
    /// Jobs created before this time (RFC 3339, as `created_at`) are deleted.
    pub created_before: Option<&'a str>,
    /// Only the newest this many jobs are kept.
    pub newest: Option<i64>,
}

impl Store {
    /// Deletes the job `id`: whether there was one.
    pub async fn delete(&self, id: &str) -> Result<bool, StoreError> {
        if !super::findable(id) {
            return Ok(false);
        }
        let done: Result<u64, StoreError> = on_pool!(&self.db, pool => async {
            // Closed, not given back, unless it commits (see `held`).
            let mut held = Held::acquire(pool).await?;
            sqlx::query("BEGIN").execute(held.conn()).await?;
            let done = sqlx::query("DELETE FROM jobs WHERE id = $1").bind(id).execute(held.conn()).await?;
            sqlx::query("DELETE FROM idempotency WHERE job_id = $1").bind(id).execute(held.conn()).await?;
            sqlx::query("COMMIT").execute(held.conn()).await?;
            held.release();
            Ok(done.rows_affected())
        }
        .await);
        Ok(self.noted(done, 0, |n| *n > 0)? == 1)
    }

    /// Deletes the jobs `r` does not keep: how many, by age and by count.
    pub async fn expire(&self, r: &Retention<'_>) -> Result<(u64, u64), StoreError> {
        let mut by_age = 0;
        if let Some(before) = r.created_before {
            by_age = self.delete_batches(BY_AGE, before).await?;
        }
        let mut by_count = 0;
        if let Some(newest) = r.newest {
            // The creation time of the newest N-th job, read off the index (the
            // table's order read every row's page: 0.5 s of CPU a sweep at 10^6).
            let offset = newest.max(1) - 1;
            let started = Instant::now();
            let last_kept: Option<String> =
                on_pool!(&self.db, pool => sqlx::query_scalar(NTH_NEWEST).bind(offset).fetch_optional(pool).await?);
            tracing::debug!(ms = started.elapsed().as_secs_f64() * 1e3, "retention: the newest N's cut found");
            if let Some(at) = last_kept {
                by_count = self.delete_batches(BY_AGE, &at).await?;
            }
        }
        if by_age + by_count > 0 {
            let sql = "DELETE FROM idempotency WHERE job_id IS NOT NULL AND job_id NOT IN (SELECT id FROM jobs)";
            on_pool!(&self.db, pool => {
                sqlx::query(sql).execute(pool).await?;
            });
        }
        Ok((by_age, by_count))
    }

    /// Runs the DELETE `sql` (its parameters `before` and the batch size)
    /// until it deletes nothing: the rows deleted.
    async fn delete_batches(&self, sql: &'static str, before: &str) -> Result<u64, StoreError> {
        let mut total = 0;
        loop {
            let started = Instant::now();
            let done = on_pool!(&self.db, pool => sqlx::query(sql).bind(before).bind(BATCH).execute(pool).await?.rows_affected());
            total += done;
            tracing::debug!(done, ms = started.elapsed().as_secs_f64() * 1e3, "retention: a batch deleted");
            if done == 0 {
                return Ok(total);
            }
            tokio::time::sleep(PAUSE.max(started.elapsed())).await;
        }
    }
}

/// A batch of the jobs created before $1, oldest first, on the index of the
/// creation time (a sweep with nothing to delete reads nothing; without it,
/// each sweep scanned the table inside its write). Jobs waiting or computing
/// are never swept: they are kept until they end. The newest N are those
/// created at or after the N-th newest's time (ties kept: never fewer).
pub const BY_AGE: &str = "DELETE FROM jobs WHERE seq IN (SELECT seq FROM jobs WHERE created_at < $1 \
                          AND status IN ('done', 'failed') ORDER BY created_at LIMIT $2)";
pub const NTH_NEWEST: &str = "SELECT created_at FROM jobs ORDER BY created_at DESC LIMIT 1 OFFSET $1";
