//! A consistent copy of the SQLite database while the service runs
//! (`mechdyn backup FILE`): SQLite's `VACUUM INTO` writes the database as
//! one read transaction sees it — every job committed before it began, none
//! half-written — into a new, compacted file, without stopping the writer
//! (WAL mode: readers and the writer do not wait for each other). The copy
//! is then opened and checked (`PRAGMA integrity_check`) and its jobs
//! counted. A PostgreSQL database is copied by its server's tools
//! (`pg_dump`; docs/operators.md).

use super::url::{Backend, check_scheme};
use sqlx::sqlite::SqliteConnectOptions;
use sqlx::{ConnectOptions, Connection};
use std::path::Path;
use std::str::FromStr;
use std::time::Duration;

/// What a backup wrote.
#[derive(Debug)]
pub struct Copied {
    pub jobs: i64,
    pub templates: i64,
    pub bytes: u64,
}

/// Copies the SQLite database at `url` into `file`, which must not exist
/// (a backup never overwrites one), and checks the copy.
pub async fn backup(url: &str, file: &Path) -> Result<Copied, String> {
    match check_scheme(url).map_err(|e| e.to_string())? {
        Backend::Postgres => {
            return Err("a PostgreSQL database is copied by its server's tools: pg_dump --format=custom \
                        (docs/operators.md); `mechdyn backup` copies a SQLite file"
                .into());
        }
        Backend::Sqlite => {}
    }
    if file.exists() {
        return Err(format!("{} exists: a backup never overwrites a file", file.display()));
    }
    let target = file.to_str().ok_or_else(|| format!("{}: not a UTF-8 path", file.display()))?;
    let source = SqliteConnectOptions::from_str(url).map_err(|e| e.to_string())?;
    if !source.get_filename().exists() {
        return Err(format!("no database at {}", source.get_filename().display()));
    }
    // The service's writer may hold the write lock for a commit: wait for it.
    let mut db = source.busy_timeout(Duration::from_secs(30)).connect().await.map_err(|e| e.to_string())?;
    sqlx::query("VACUUM INTO ?").bind(target).execute(&mut db).await.map_err(|e| format!("VACUUM INTO: {e}"))?;
    db.close().await.map_err(|e| e.to_string())?;
    check(file).await
}

/// Opens the copy read-only: SQLite's integrity check, its jobs and templates counted.
async fn check(file: &Path) -> Result<Copied, String> {
    let mut copy =
        SqliteConnectOptions::new().filename(file).read_only(true).connect().await.map_err(|e| e.to_string())?;
    let integrity: String =
        sqlx::query_scalar("PRAGMA integrity_check").fetch_one(&mut copy).await.map_err(|e| e.to_string())?;
    if integrity != "ok" {
        return Err(format!("the copy at {} fails SQLite's integrity check: {integrity}", file.display()));
    }
    let jobs = sqlx::query_scalar("SELECT count(*) FROM jobs").fetch_one(&mut copy).await.map_err(|e| e.to_string())?;
    let templates =
        sqlx::query_scalar("SELECT count(*) FROM templates").fetch_one(&mut copy).await.map_err(|e| e.to_string())?;
    copy.close().await.map_err(|e| e.to_string())?;
    let bytes = std::fs::metadata(file).map_err(|e| e.to_string())?.len();
    Ok(Copied { jobs, templates, bytes })
}
