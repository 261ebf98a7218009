//! A connection held for one explicit transaction, given back to the pool
//! only once its `COMMIT` has succeeded.
//!
//! After a failed statement a connection's state is not what its pool
//! believes: SQLite rolls a transaction back by itself on SQLITE_FULL or an
//! I/O error (so a later `ROLLBACK` fails and sqlx's own bookkeeping of the
//! transaction stays one level deep), and a `ROLLBACK TO` a savepoint leaves
//! the transaction open. Such a connection given back would run the next
//! caller's statements inside a transaction that never commits: acknowledged
//! writes lost at the next crash, and the database locked for every other
//! writer. So a held connection that did not commit — an error, or its
//! future dropped mid-way (a client gone) — is closed instead (closing rolls
//! back whatever is open) and the pool opens a fresh one.

use sqlx::pool::PoolConnection;
use sqlx::{Database, Pool};

pub(crate) struct Held<DB: Database> {
    /// Some until released to the pool or dropped.
    conn: Option<PoolConnection<DB>>,
}

impl<DB: Database> Held<DB> {
    /// A connection of `pool`, held until [`Held::release`].
    pub async fn acquire(pool: &Pool<DB>) -> Result<Self, sqlx::Error> {
        Ok(Self { conn: Some(pool.acquire().await?) })
    }

    /// The connection, to run statements on.
    pub fn conn(&mut self) -> &mut DB::Connection {
        self.conn.as_mut().expect("a held connection is there until released")
    }

    /// Gives the connection back to the pool: call only once the
    /// transaction has committed (the connection is in autocommit again).
    pub fn release(mut self) {
        drop(self.conn.take());
    }
}

impl<DB: Database> Drop for Held<DB> {
    fn drop(&mut self) {
        if let Some(conn) = self.conn.as_mut() {
            conn.close_on_drop();
        }
    }
}
