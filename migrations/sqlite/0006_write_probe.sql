-- Readiness's own write: while the store's writes fail (a full disk), a
-- readiness probe writes a row as large as the write that failed, then
-- empties it, each committed, to learn whether writes commit again.
CREATE TABLE write_probe (
    id INTEGER PRIMARY KEY,
    filler BLOB
);
