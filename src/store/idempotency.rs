//! Answers kept under a client's `Idempotency-Key`, so that a retried POST
//! is answered again instead of computed and stored twice.

use super::backend::on_pool;
use super::{Store, StoreError};

/// The answer to a POST, kept under its key.
#[derive(Clone, Debug, PartialEq)]
pub struct Answer {
    /// SHA-256 of the request (method, path and query, content type, body).
    pub fingerprint: String,
    pub status: i64,
    pub content_type: Option<String>,
    /// The job the POST stored, answered again as its GET answers it.
    pub job_id: Option<String>,
    /// Else the answer's bytes.
    pub body: Option<Vec<u8>>,
}

/// How long a key is kept at least (the contract's 24 h, and a margin).
pub const KEEP: std::time::Duration = std::time::Duration::from_secs(7 * 24 * 3600);

impl Store {
    /// The answer kept under `key`.
    pub async fn answer(&self, key: &str) -> Result<Option<Answer>, StoreError> {
        let sql = "SELECT fingerprint, status, content_type, job_id, body FROM idempotency WHERE key = $1";
        Ok(on_pool!(&self.db, pool => sqlx::query_as(sql).bind(key).fetch_optional(pool).await?))
    }

    /// Keeps `answer` under `key` at `now` (the first one stays when two
    /// race) and forgets the keys kept before `forget_before` (both RFC 3339,
    /// as `created_at`: [`KEEP`] apart).
    pub async fn keep_answer(&self, key: &str, now: &str, forget_before: &str, a: &Answer) -> Result<(), StoreError> {
        let insert = "INSERT INTO idempotency (key, fingerprint, created_at, status, content_type, job_id, body) \
                      VALUES ($1, $2, $3, $4, $5, $6, $7) ON CONFLICT DO NOTHING";
        let forget = "DELETE FROM idempotency WHERE created_at < $1";
        let kept: Result<(), sqlx::Error> = on_pool!(&self.db, pool => async {
            sqlx::query(insert)
                .bind(key)
                .bind(&a.fingerprint)
                .bind(now)
                .bind(a.status)
                .bind(&a.content_type)
                .bind(&a.job_id)
                .bind(&a.body)
                .execute(pool)
                .await?;
            sqlx::query(forget).bind(forget_before).execute(pool).await?;
            Ok(())
        }
        .await);
        self.noted(kept.map_err(StoreError::from), a.body.as_ref().map_or(0, Vec::len), |()| true)
    }
}
