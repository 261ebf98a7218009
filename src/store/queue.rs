//! Jobs deferred by `Prefer: respond-async`. Each is stored `queued` before
//! its `202`; a replica claims the oldest waiting job for a lease
//! (`claimed_until`) that it renews while it computes, then stores the
//! result (`done`) or the problem (`failed`), each only while the claim is
//! still its own. A lease that lapses (its replica stopped) lets any
//! replica claim the job again, up to a number of attempts; beyond them
//! the job fails with the problem the caller gives.
//!
//! Claims are one statement: on PostgreSQL the waiting row is locked with
//! `FOR UPDATE SKIP LOCKED`, so replicas claiming at once take different
//! jobs; SQLite has one writer at a time.

use super::backend::{Db, on_pool};
use super::{JobRow, Row, Status, Store, StoreError, row_columns};
use bytes::Bytes;

/// A job to defer.
#[derive(Clone, Debug)]
pub struct Queued {
    pub id: String,
    pub kind: String,
    pub created_at: String,
    /// The request body as sent (JSON text).
    pub request: Bytes,
    pub label: Option<String>,
    pub engine_version: String,
}

/// A job claimed to compute.
#[derive(Clone, Debug, PartialEq)]
pub struct Claimed {
    pub id: String,
    pub kind: String,
    pub request: Bytes,
    /// Claims of this job so far, this one included.
    pub attempts: i64,
}

/// Deferred jobs not ended, in every replica's view.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Waiting {
    pub queued: i64,
    pub running: i64,
}

/// A job that waits: queued, or running on a lease that lapsed before $1.
macro_rules! claimable {
    () => {
        "status IN ('queued', 'running') AND (status = 'queued' OR claimed_until < $1) AND attempts < $2"
    };
}

/// $1 now, $2 the attempts allowed, $3 the claim, $4 its lease's end.
macro_rules! claim {
    ($lock:literal) => {
        concat!(
            "UPDATE jobs SET status = 'running', claimed_by = $3, claimed_until = $4, attempts = attempts + 1 \
             WHERE seq = (SELECT seq FROM jobs WHERE ",
            claimable!(),
            " ORDER BY seq LIMIT 1",
            $lock,
            ") AND ",
            claimable!(),
            " RETURNING id, kind, request, attempts"
        )
    };
}

impl Store {
    /// Stores `job` as queued (its result `null`); committed when this returns.
    pub async fn enqueue(&self, job: Queued) -> Result<JobRow, StoreError> {
        let sql = "INSERT INTO jobs (id, kind, created_at, request, result, engine_us, engine_version, bytes, label, \
                   status) VALUES ($1, $2, $3, $4, 'null', 0, $5, $6, $7, 'queued') RETURNING seq";
        let request = std::str::from_utf8(&job.request).unwrap_or("null");
        let bytes = job.request.len() as i64 + 4;
        let seq: Result<Vec<i64>, sqlx::Error> = on_pool!(&self.db, pool => {
            sqlx::query_scalar(sql)
                .bind(&job.id)
                .bind(&job.kind)
                .bind(&job.created_at)
                .bind(request)
                .bind(&job.engine_version)
                .bind(bytes)
                .bind(&job.label)
                .fetch_all(pool)
                .await
        });
        let seq = self.noted(seq.map_err(StoreError::from), job.request.len(), |_| true)?;
        let seq =
            seq.first().copied().ok_or_else(|| StoreError::Unavailable("the queued job was not returned".into()))?;
        let Queued { id, kind, created_at, request, label, engine_version } = job;
        let (result, status, problem) = (Bytes::from_static(b"null"), Status::Queued, None);
        Ok(JobRow { seq, id, kind, created_at, request, result, engine_us: 0, engine_version, label, status, problem })
    }

    /// Claims the oldest waiting job for `by` until `until` (`now` and both
    /// RFC 3339); first, the jobs whose lease lapsed after `max_attempts`
    /// claims fail with `interrupted` (a problem+json document).
    pub async fn claim(
        &self,
        now: &str,
        until: &str,
        by: &str,
        max_attempts: i64,
        interrupted: &str,
    ) -> Result<Option<Claimed>, StoreError> {
        // `status IN (…)` as the partial index `jobs_waiting` says it, so that SQLite uses the index.
        let give_up = "UPDATE jobs SET status = 'failed', problem = $3, claimed_by = NULL, claimed_until = NULL \
                       WHERE status IN ('queued', 'running') AND status = 'running' AND claimed_until < $1 \
                       AND attempts >= $2";
        on_pool!(&self.db, pool => {
            sqlx::query(give_up).bind(now).bind(max_attempts).bind(interrupted).execute(pool).await?;
        });
        let rows: Vec<(String, String, String, i64)> = match &self.db {
            Db::Sqlite(pool) => {
                let q = sqlx::query_as(claim!(""));
                q.bind(now).bind(max_attempts).bind(by).bind(until).fetch_all(pool).await?
            }
            Db::Postgres(pool) => {
                let q = sqlx::query_as(claim!(" FOR UPDATE SKIP LOCKED"));
                q.bind(now).bind(max_attempts).bind(by).bind(until).fetch_all(pool).await?
            }
        };
        Ok(rows.into_iter().next().map(|(id, kind, request, attempts)| Claimed {
            id,
            kind,
            request: request.into(),
            attempts,
        }))
    }

    /// Extends the claim `by` of job `id` to `until`: false where it is no longer `by`'s.
    pub async fn renew(&self, id: &str, by: &str, until: &str) -> Result<bool, StoreError> {
        let sql = "UPDATE jobs SET claimed_until = $1 WHERE id = $2 AND claimed_by = $3 AND status = 'running'";
        let done = on_pool!(&self.db, pool => {
            sqlx::query(sql).bind(until).bind(id).bind(by).execute(pool).await?.rows_affected()
        });
        Ok(done == 1)
    }

    /// Stores the result of job `id` claimed by `by` (its request and result
    /// together `bytes` long): the job done, or None where the claim is no
    /// longer `by`'s (the job deleted, or claimed again after a lapse).
    pub async fn complete(
        &self,
        (id, by): (&str, &str),
        result: &Bytes,
        engine_us: i64,
        bytes: i64,
    ) -> Result<Option<JobRow>, StoreError> {
        let sql = concat!(
            "UPDATE jobs SET status = 'done', result = $1, result_zstd = $2, engine_us = $3, bytes = $4, claimed_by = NULL, \
             claimed_until = NULL WHERE id = $5 AND claimed_by = $6 AND status = 'running' RETURNING ",
            row_columns!()
        );
        let packed = super::packed::pack(result);
        let rows: Result<Vec<Row>, sqlx::Error> = on_pool!(&self.db, pool => {
            let q = sqlx::query_as(sql).bind(packed.text).bind(packed.zstd.as_deref()).bind(engine_us).bind(bytes);
            q.bind(id).bind(by).fetch_all(pool).await
        });
        let rows = self.noted(rows.map_err(StoreError::from), result.len(), |r| !r.is_empty())?;
        rows.into_iter().next().map(JobRow::try_from).transpose()
    }

    /// Stores why job `id` claimed by `by` failed (`problem`, problem+json
    /// text): false where the claim is no longer `by`'s.
    pub async fn fail(&self, (id, by): (&str, &str), problem: &str, engine_us: i64) -> Result<bool, StoreError> {
        let sql = "UPDATE jobs SET status = 'failed', problem = $1, engine_us = $2, bytes = bytes + $3, \
                   claimed_by = NULL, claimed_until = NULL WHERE id = $4 AND claimed_by = $5 AND status = 'running'";
        let grown = problem.len() as i64;
        let done = on_pool!(&self.db, pool => {
            let q = sqlx::query(sql).bind(problem).bind(engine_us).bind(grown).bind(id).bind(by);
            q.execute(pool).await.map(|d| d.rows_affected())
        });
        Ok(self.noted(done.map_err(StoreError::from), problem.len(), |n| *n > 0)? == 1)
    }

    /// Puts job `id` claimed by `by` back in the queue, the claim not
    /// counted (its replica is stopping, or could not compute it now).
    pub async fn release(&self, (id, by): (&str, &str)) -> Result<bool, StoreError> {
        let sql = "UPDATE jobs SET status = 'queued', claimed_by = NULL, claimed_until = NULL, \
                   attempts = attempts - 1 WHERE id = $1 AND claimed_by = $2 AND status = 'running'";
        let done = on_pool!(&self.db, pool => sqlx::query(sql).bind(id).bind(by).execute(pool).await?.rows_affected());
        Ok(done == 1)
    }

    /// The deferred jobs queued and running.
    pub async fn waiting(&self) -> Result<Waiting, StoreError> {
        let sql = "SELECT status, COUNT(*) FROM jobs WHERE status IN ('queued', 'running') GROUP BY status";
        let counts: Vec<(String, i64)> = on_pool!(&self.db, pool => sqlx::query_as(sql).fetch_all(pool).await?);
        let count = |s: &str| counts.iter().find(|(status, _)| status == s).map_or(0, |(_, n)| *n);
        Ok(Waiting { queued: count("queued"), running: count("running") })
    }
}
