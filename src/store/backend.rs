//! The two databases a store may use, opened, and their failures sorted.
//!
//! - **SQLite** (the default): one file of this service's own, in WAL mode,
//!   synced at every commit unless told otherwise (`synchronous`), with an
//!   optional size cap (`max_page_count`).
//! - **PostgreSQL**: a server that several replicas share. At start the
//!   service waits for it (a container's database may start after it), and
//!   the migrations run under sqlx's advisory lock, so replicas starting
//!   together apply them once.
//!
//! Every query is written once, with `$1, $2, …` placeholders (sqlx's
//! SQLite driver reads `$N` as the N-th argument), and run on either pool
//! by [`on_pool!`], which type-checks the same code against each driver:
//! no query is translated at run time, and no value is copied through an
//! intermediate row type.

use super::migrations::{POSTGRES, SQLITE};
use super::url::Backend;
use super::{Options, StoreError};
use sqlx::postgres::{PgConnectOptions, PgPool, PgPoolOptions};
use sqlx::sqlite::{SqliteConnectOptions, SqliteJournalMode, SqlitePool, SqlitePoolOptions, SqliteSynchronous};
use std::str::FromStr;
use std::time::{Duration, Instant};

/// Connections a store keeps open.
const CONNECTIONS: u32 = 8;
/// How long a SQLite statement waits for the database's lock (store/wal.rs says it again in SQL).
pub const BUSY: Duration = Duration::from_secs(10);
/// Longest wait for a connection of the pool: a query while the database
/// is away fails after it (a readiness probe's answer comes within it).
const ACQUIRE: Duration = Duration::from_secs(5);

/// A pool of connections to one of the two databases.
#[derive(Clone, Debug)]
pub enum Db {
    Sqlite(SqlitePool),
    Postgres(PgPool),
}

/// Runs `$body` with `$pool` bound to the store's pool, whichever its
/// database: the same code, compiled once for each driver.
macro_rules! on_pool {
    ($db:expr, $pool:ident => $body:expr) => {
        match $db {
            $crate::store::backend::Db::Sqlite($pool) => $body,
            $crate::store::backend::Db::Postgres($pool) => $body,
        }
    };
}
pub(crate) use on_pool;

impl Db {
    /// Opens the database at `url` and applies the migrations.
    pub async fn open(url: &str, backend: Backend, options: &Options) -> Result<Self, sqlx::Error> {
        match backend {
            Backend::Sqlite => sqlite(url, options).await.map(Self::Sqlite),
            Backend::Postgres if options.max_bytes.is_some() => Err(sqlx::Error::Configuration(
                "--max-database-bytes (MECHDYN_MAX_DATABASE_BYTES) caps a SQLite file; a PostgreSQL server's \
                 space is its own to limit"
                    .into(),
            )),
            Backend::Postgres => postgres(url, options.wait).await.map(Self::Postgres),
        }
    }

    pub fn backend(&self) -> Backend {
        match self {
            Self::Sqlite(_) => Backend::Sqlite,
            Self::Postgres(_) => Backend::Postgres,
        }
    }
}

/// The SQLite file at `url` (its folder created), in WAL mode, migrated.
async fn sqlite(url: &str, options: &Options) -> Result<SqlitePool, sqlx::Error> {
    let mut connect = SqliteConnectOptions::from_str(url)?
        .create_if_missing(true)
        .journal_mode(SqliteJournalMode::Wal)
        .synchronous(if options.power_safe { SqliteSynchronous::Full } else { SqliteSynchronous::Normal })
        .busy_timeout(BUSY)
        .foreign_keys(true)
        // A checkpoint runs inside the commit that crosses the mark and holds up
        // the jobs waiting behind it: every 100 pages (not SQLite's 1000) those
        // pauses are short. Measured at 64 connections, flywheel jobs: p99
        // 20.3–22.9 ms at 1000 pages, 16.3–16.7 ms at 100; a checkpoint beside the
        // writer instead (PASSIVE) never resets a log that is always being
        // written, and it grew by 100 MB/s.
        .pragma("wal_autocheckpoint", "100")
        .pragma("journal_size_limit", super::wal::LIMIT.to_string());
    if let Some(max) = options.max_bytes {
        // SQLite's default page size, 4096 bytes (set before the first table).
        connect = connect.page_size(4096).pragma("max_page_count", (max / 4096).max(1).to_string());
    }
    let file = connect.get_filename();
    if let Some(dir) = file.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| sqlx::Error::Configuration(Box::new(e)))?;
    }
    let pool = SqlitePoolOptions::new().max_connections(CONNECTIONS).connect_with(connect).await?;
    SQLITE.run(&pool).await?;
    super::wal::at_open(&pool).await?;
    Ok(pool)
}

/// The PostgreSQL database at `url`, waited for up to `wait` while its
/// server does not answer, migrated.
async fn postgres(url: &str, wait: Duration) -> Result<PgPool, sqlx::Error> {
    let connect = PgConnectOptions::from_str(url)?;
    let started = Instant::now();
    let pool = loop {
        let options = PgPoolOptions::new().max_connections(CONNECTIONS).acquire_timeout(ACQUIRE);
        let left = wait.saturating_sub(started.elapsed()).max(Duration::from_millis(100));
        let error = match tokio::time::timeout(left, options.connect_with(connect.clone())).await {
            Ok(Ok(pool)) => break pool,
            Ok(Err(e @ (sqlx::Error::Io(_) | sqlx::Error::PoolTimedOut))) => e.to_string(),
            Ok(Err(e)) => return Err(e),
            Err(_) => "no connection yet".to_string(),
        };
        if started.elapsed() >= wait {
            let why = format!("the PostgreSQL server did not answer within {} s: {error}", wait.as_secs_f64());
            return Err(sqlx::Error::Configuration(why.into()));
        }
        tracing::warn!(%error, "the PostgreSQL server does not answer yet; trying again");
        tokio::time::sleep(Duration::from_millis(500)).await;
    };
    POSTGRES.run(&pool).await?;
    Ok(pool)
}

/// Why a statement failed, sorted: the storage full, a value refused, or anything else.
pub fn classify(e: sqlx::Error) -> StoreError {
    if is_full(&e) {
        StoreError::Full
    } else if is_refused(&e) {
        StoreError::Refused(e.as_database_error().map_or_else(|| e.to_string(), |d| d.message().to_string()))
    } else {
        StoreError::Unavailable(e.to_string())
    }
}

/// A value the database refused: PostgreSQL's class 22 (data exception:
/// a NUL byte in text, a number out of range), SQLite's SQLITE_TOOBIG (18).
pub fn is_refused(e: &sqlx::Error) -> bool {
    match code(e) {
        Some(Code::Sqlite(c)) => c == 18,
        Some(Code::Postgres(state)) => state.starts_with("22"),
        None => false,
    }
}

/// The error's code: PostgreSQL's SQLSTATE (five characters, its class
/// first), or SQLite's primary result code (the low byte of an extended one).
enum Code<'a> {
    Postgres(&'a str),
    Sqlite(i32),
}

fn code(e: &sqlx::Error) -> Option<Code<'_>> {
    let db = e.as_database_error()?;
    if let Some(pg) = db.try_downcast_ref::<sqlx::postgres::PgDatabaseError>() {
        return Some(Code::Postgres(pg.code()));
    }
    db.code()?.parse::<i32>().ok().map(|c| Code::Sqlite(c & 0xff))
}

/// The storage is full: SQLite's SQLITE_FULL (13: the disk or
/// `max_page_count`), PostgreSQL's class 53, insufficient resources (53100
/// disk_full among them).
pub fn is_full(e: &sqlx::Error) -> bool {
    match code(e) {
        Some(Code::Sqlite(c)) => c == 13,
        Some(Code::Postgres(state)) => state.starts_with("53"),
        None => false,
    }
}

/// This row broke a rule of the schema (a duplicate id): SQLite's
/// SQLITE_CONSTRAINT (19), PostgreSQL's class 23 (integrity constraint violation).
pub fn is_constraint(e: &sqlx::Error) -> bool {
    match code(e) {
        Some(Code::Sqlite(c)) => c == 19,
        Some(Code::Postgres(state)) => state.starts_with("23"),
        None => false,
    }
}
