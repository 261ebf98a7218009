//! Jobs deleted: one by its id (`DELETE /v1/jobs/{id}`), or those past the
//! retention's age or count, a batch at a time so that no transaction holds
//! the database for long. The answers kept under an idempotency key for a
//! job go with it: a retry of that POST computes the job again instead of
//! answering with a job that is gone.

use super::backend::on_pool;
use super::held::Held;
use super::{Store, StoreError};

/// Rows deleted per statement of a sweep.
const BATCH: i64 = 1000;

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
            by_age = self.delete_batches(BY_AGE, Bound::Text(before)).await?;
        }
        let mut by_count = 0;
        if let Some(newest) = r.newest {
            let sql = "SELECT seq FROM jobs ORDER BY seq DESC LIMIT 1 OFFSET $1";
            let offset = newest.max(1) - 1;
            let last_kept: Option<i64> =
                on_pool!(&self.db, pool => sqlx::query_scalar(sql).bind(offset).fetch_optional(pool).await?);
            if let Some(seq) = last_kept {
                by_count = self.delete_batches(OLDER_THAN, Bound::Int(seq)).await?;
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

    /// Runs the DELETE `sql` (its parameters `value` and the batch size)
    /// until it deletes nothing: the rows deleted.
    async fn delete_batches(&self, sql: &'static str, value: Bound<'_>) -> Result<u64, StoreError> {
        let mut total = 0;
        loop {
            let done = on_pool!(&self.db, pool => match value {
                Bound::Text(t) => sqlx::query(sql).bind(t).bind(BATCH).execute(pool).await?,
                Bound::Int(i) => sqlx::query(sql).bind(i).bind(BATCH).execute(pool).await?,
            }
            .rows_affected());
            total += done;
            if done == 0 {
                return Ok(total);
            }
        }
    }
}

/// The first parameter of a sweep's DELETE.
#[derive(Clone, Copy)]
enum Bound<'a> {
    Text(&'a str),
    Int(i64),
}

/// Jobs waiting or computing are never swept: they are kept until they end.
const BY_AGE: &str = "DELETE FROM jobs WHERE seq IN (SELECT seq FROM jobs WHERE created_at < $1 \
                      AND status IN ('done', 'failed') ORDER BY seq LIMIT $2)";
const OLDER_THAN: &str = "DELETE FROM jobs WHERE seq IN (SELECT seq FROM jobs WHERE seq < $1 \
                          AND status IN ('done', 'failed') ORDER BY seq LIMIT $2)";
