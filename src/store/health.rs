//! Whether the store's writes commit. A write that fails for want of
//! storage or of the database marks the store failing, with the size of
//! that write (a value the database refused is the request's, and marks
//! nothing); a write that commits something clears the mark. While it is
//! set, [`Store::writable`] (readiness) makes a write of that size itself —
//! a row of `write_probe` filled, then emptied, each committed — so a
//! replica that no client writes to while it is unready learns when space
//! returns. (A write of that size passing does not promise that a larger
//! one will.)

use super::backend::on_pool;
use super::{Store, StoreError};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};

/// The largest write a probe makes, bytes.
const PROBE_MAX: usize = 1 << 20;
/// The smallest: a page of SQLite's.
const PROBE_MIN: usize = 4096;

/// The last write that failed (its size and why), until one commits.
#[derive(Debug, Default)]
pub(crate) struct Writes {
    failing: Mutex<Option<(usize, StoreError)>>,
    /// A probe is under way (one at a time).
    probing: AtomicBool,
}

impl Writes {
    fn set(&self, failing: Option<(usize, StoreError)>) {
        *self.failing.lock().unwrap_or_else(|e| e.into_inner()) = failing;
    }

    fn failing(&self) -> Option<(usize, StoreError)> {
        self.failing.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    /// A write of about `bytes` failed with `error`: marked where the
    /// storage or the database failed, not where a value was refused.
    pub fn failed(&self, bytes: usize, error: &StoreError) {
        if matches!(error, StoreError::Full | StoreError::Unavailable(_)) {
            self.set(Some((bytes, error.clone())));
        }
    }

    /// A write committed something.
    pub fn committed(&self) {
        self.set(None);
    }
}

impl Store {
    /// `outcome` of a write of about `bytes`, noted: a failure marks the
    /// store failing; a success clears the mark where `wrote` says that
    /// something was written (a write that changed no row proves nothing).
    pub(crate) fn noted<T>(
        &self,
        outcome: Result<T, StoreError>,
        bytes: usize,
        wrote: fn(&T) -> bool,
    ) -> Result<T, StoreError> {
        match &outcome {
            Ok(done) if wrote(done) => self.writes.committed(),
            Ok(_) => {}
            Err(e) => self.writes.failed(bytes, e),
        }
        outcome
    }

    /// Whether writes commit: Ok unless the last write failed and a probe
    /// write of its size still fails (the error says why). The probe runs
    /// in a task of its own, one at a time: a caller that stops waiting
    /// (readiness answers within 1 s) does not cut it short, so on a slow
    /// disk it still ends, and clears the mark for the next caller.
    pub async fn writable(&self) -> Result<(), StoreError> {
        let Some((bytes, error)) = self.writes.failing() else { return Ok(()) };
        if self.writes.probing.swap(true, Ordering::AcqRel) {
            return Err(error);
        }
        let store = self.clone();
        let probe = tokio::spawn(async move {
            let outcome = store.probe(bytes.clamp(PROBE_MIN, PROBE_MAX)).await;
            store.writes.probing.store(false, Ordering::Release);
            store.noted(outcome, bytes, |()| true)
        });
        probe.await.unwrap_or_else(|e| Err(StoreError::Unavailable(format!("the probe write: {e}"))))
    }

    /// A row of `bytes` written to `write_probe`, then emptied, each committed.
    async fn probe(&self, bytes: usize) -> Result<(), StoreError> {
        let fill = "INSERT INTO write_probe (id, filler) VALUES (1, $1) \
                    ON CONFLICT (id) DO UPDATE SET filler = excluded.filler";
        let empty = "UPDATE write_probe SET filler = NULL WHERE id = 1";
        let filler = incompressible(bytes);
        on_pool!(&self.db, pool => {
            sqlx::query(fill).bind(&filler).execute(pool).await?;
            sqlx::query(empty).execute(pool).await?;
        });
        Ok(())
    }
}

/// `n` bytes that no page compression shrinks (xorshift64), so that the
/// probe takes the space it stands for.
fn incompressible(n: usize) -> Vec<u8> {
    let mut x = 0x9E37_79B9_7F4A_7C15_u64;
    (0..n)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 56) as u8
        })
        .collect()
}
