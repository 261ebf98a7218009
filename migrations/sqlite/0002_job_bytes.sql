-- The size of a job as served (request + result, bytes), so that a read can
-- reserve the memory of its answer before it loads it, and a page of the
-- jobs list can stop before it grows too large.
ALTER TABLE jobs ADD COLUMN bytes INTEGER NOT NULL DEFAULT 0;

UPDATE jobs SET bytes = length(CAST(request AS BLOB)) + length(CAST(result AS BLOB));
