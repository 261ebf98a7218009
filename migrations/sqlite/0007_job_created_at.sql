-- The retention deletes by age (`--retention-days`) and finds the cut of
-- the newest N (`--retention-jobs`) through this index: a sweep reads the
-- jobs it deletes, not the table (at 10^6 jobs it scanned it every minute).
CREATE INDEX jobs_created_at ON jobs (created_at);
