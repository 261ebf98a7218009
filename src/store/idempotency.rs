//! Answers kept under a client's `Idempotency-Key`, so that a retried POST
//! is answered again instead of computed and stored twice.

use super::{Store, StoreError};

/// The answer to a POST, kept under its key.
#[derive(Clone, Debug, PartialEq, sqlx::FromRow)]
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
pub const KEEP_SECONDS: i64 = 7 * 24 * 3600;

impl Store {
    /// The answer kept under `key`.
    pub async fn answer(&self, key: &str) -> Result<Option<Answer>, StoreError> {
        let sql = "SELECT fingerprint, status, content_type, job_id, body FROM idempotency WHERE key = ?";
        Ok(sqlx::query_as(sql).bind(key).fetch_optional(&self.pool).await?)
    }

    /// Keeps `answer` under `key` (the first one stays when two race) and
    /// forgets keys older than [`KEEP_SECONDS`] before `now` (RFC 3339).
    pub async fn keep_answer(&self, key: &str, now: &str, answer: &Answer) -> Result<(), StoreError> {
        sqlx::query(
            "INSERT INTO idempotency (key, fingerprint, created_at, status, content_type, job_id, body) \
             VALUES (?, ?, ?, ?, ?, ?, ?) ON CONFLICT DO NOTHING",
        )
        .bind(key)
        .bind(&answer.fingerprint)
        .bind(now)
        .bind(answer.status)
        .bind(&answer.content_type)
        .bind(&answer.job_id)
        .bind(&answer.body)
        .execute(&self.pool)
        .await?;
        sqlx::query("DELETE FROM idempotency WHERE created_at < strftime('%Y-%m-%dT%H:%M:%fZ', ?, ?)")
            .bind(now)
            .bind(format!("-{KEEP_SECONDS} seconds"))
            .execute(&self.pool)
            .await?;
        Ok(())
    }
}
