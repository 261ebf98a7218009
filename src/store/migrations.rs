//! The two schemas' migrations, embedded in the binary and handed to
//! sqlx's [`Migrator`] as its `migrate!` macro would hand them: each file's
//! version and description from its name (`0001_jobs.sql`: 1, "jobs"), its
//! SQL, and SHA-384 of it as the checksum that a database which applied it
//! keeps. A new file in `migrations/` is listed here too (a test fails
//! otherwise).

use sqlx::migrate::{Migration, MigrationType, Migrator};
use sqlx::{AssertSqlSafe, SqlSafeStr};
use std::sync::LazyLock;

/// Each file of `migrations/<dir>/`, by name, with its text.
macro_rules! embedded {
    ($dir:literal: $($file:literal),* $(,)?) => {
        &[$(($file, include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/migrations/", $dir, "/", $file)))),*]
    };
}

/// `$then!(dir: file, …)` with every migration's file, in order: both
/// folders hold the same names.
macro_rules! with_files {
    ($then:ident, $dir:literal) => {
        $then!($dir: "0001_jobs.sql", "0002_job_bytes.sql", "0003_templates.sql", "0004_grading.sql",
            "0005_async_jobs.sql", "0006_write_probe.sql", "0007_job_created_at.sql", "0008_result_zstd.sql")
    };
}

/// The SQLite schema.
pub static SQLITE: LazyLock<Migrator> = LazyLock::new(|| migrator(with_files!(embedded, "sqlite")));

/// The PostgreSQL schema: the same tables and columns.
pub static POSTGRES: LazyLock<Migrator> = LazyLock::new(|| migrator(with_files!(embedded, "postgres")));

/// The migrator of `files` (name, SQL), each as sqlx reads a file of a
/// migrations folder (`sqlx::migrate::resolve_blocking`).
fn migrator(files: &[(&str, &'static str)]) -> Migrator {
    Migrator::with_migrations(files.iter().map(|&(name, sql)| migration(name, sql)).collect())
}

fn migration(name: &str, sql: &'static str) -> Migration {
    let (version, rest) = name.split_once('_').expect("a migration is named <version>_<description>.sql");
    let version = version.parse().expect("a migration's version is an integer");
    let description = rest.trim_end_matches(".sql").replace('_', " ");
    let no_tx = sql.starts_with("-- no-transaction");
    Migration::new(version, description.into(), MigrationType::Simple, AssertSqlSafe(sql).into_sql_str(), no_tx)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each embedded migration is sqlx's own reading of its file (version,
    /// description, checksum, transaction), and every file is embedded: a
    /// database migrated by the `migrate!` macro's build opens with this one.
    #[test]
    fn the_embedded_migrations_are_the_folders_as_sqlx_reads_them() {
        for (dir, migrator) in [("sqlite", &*SQLITE), ("postgres", &*POSTGRES)] {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("migrations").join(dir);
            let mut read: Vec<Migration> =
                sqlx::migrate::resolve_blocking(&path).expect("the folder").into_iter().map(|(m, _)| m).collect();
            read.sort();
            assert_eq!(read.len(), migrator.migrations.len(), "{dir}: a file of the folder is not embedded");
            for (a, b) in read.iter().zip(migrator.iter()) {
                assert_eq!((a.version, &a.description, a.no_tx), (b.version, &b.description, b.no_tx), "{dir}");
                assert_eq!(a.checksum, b.checksum, "{dir}: {}", a.description);
                assert_eq!(a.migration_type, b.migration_type, "{dir}");
            }
        }
    }
}
