//! Jobs in SQLite (sqlx): nothing here knows about HTTP or the engine; jobs
//! go in and come out as JSON text with their metadata.

use sqlx::sqlite::{SqliteConnectOptions, SqliteJournalMode, SqlitePool, SqlitePoolOptions, SqliteSynchronous};
use std::str::FromStr;
use std::time::Duration;

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
pub struct NewJob<'a> {
    pub id: &'a str,
    pub kind: &'a str,
    pub created_at: &'a str,
    pub request: &'a str,
    pub result: &'a str,
    pub engine_us: i64,
    pub engine_version: &'a str,
}

#[derive(Clone)]
pub struct Store {
    pool: SqlitePool,
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
        Ok(Self { pool })
    }

    /// Inserts a job; it is committed when this returns.
    pub async fn insert(&self, j: &NewJob<'_>) -> Result<(), sqlx::Error> {
        sqlx::query(
            "INSERT INTO jobs (id, kind, created_at, request, result, engine_us, engine_version) \
             VALUES (?, ?, ?, ?, ?, ?, ?)",
        )
        .bind(j.id)
        .bind(j.kind)
        .bind(j.created_at)
        .bind(j.request)
        .bind(j.result)
        .bind(j.engine_us)
        .bind(j.engine_version)
        .execute(&self.pool)
        .await?;
        Ok(())
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
