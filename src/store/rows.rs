//! The store's rows read by column name, from either database: what sqlx's
//! derive `FromRow` writes, written here so that the build needs none of
//! sqlx's macros. Those macros compile sqlx's drivers, and SQLite's C
//! source, a second time for the compiler itself (ARCHITECTURE.md,
//! "Written here").

use super::idempotency::Answer;
use super::{JobSummary, Row, Status};
use sqlx::postgres::PgRow;
use sqlx::sqlite::SqliteRow;
use sqlx::{FromRow, Row as _};

/// `FromRow` for each database's row: every field read from the column of
/// its name; a status from its text ([`Status`]'s `From<String>`).
macro_rules! from_row {
    ($name:ident { $($field:ident),* } $(status $status:ident)?) => {
        from_row!(@one SqliteRow, $name { $($field),* } $($status)?);
        from_row!(@one PgRow, $name { $($field),* } $($status)?);
    };
    (@one $row:ty, $name:ident { $($field:ident),* } $($status:ident)?) => {
        impl<'r> FromRow<'r, $row> for $name {
            fn from_row(row: &'r $row) -> Result<Self, sqlx::Error> {
                Ok(Self {
                    $($field: row.try_get(stringify!($field))?,)*
                    $($status: Status::from(row.try_get::<String, _>(stringify!($status))?),)?
                })
            }
        }
    };
}

from_row!(Row { seq, id, kind, created_at, request, result, engine_us, engine_version, label, problem, result_zstd } status status);
from_row!(JobSummary { id, kind, created_at, engine_us, label, bytes } status status);
from_row!(Answer { fingerprint, status, content_type, job_id, body });
