-- Jobs POSTed with `Prefer: respond-async` are stored before they are
-- computed, and any replica may compute them: a job is `queued`, then
-- `running` (claimed by one replica until `claimed_until`, renewed while it
-- computes; a claim that lapses is taken again, up to a number of
-- `attempts`), then `done` (its result stored) or `failed` (its `problem`,
-- a problem+json document, stored). Jobs answered at once are `done`.
-- A job not done has the result 'null'.
ALTER TABLE jobs ADD COLUMN status TEXT NOT NULL DEFAULT 'done';
ALTER TABLE jobs ADD COLUMN problem TEXT;
ALTER TABLE jobs ADD COLUMN claimed_by TEXT;
ALTER TABLE jobs ADD COLUMN claimed_until TEXT;
ALTER TABLE jobs ADD COLUMN attempts INTEGER NOT NULL DEFAULT 0;

CREATE INDEX jobs_waiting ON jobs (seq) WHERE status IN ('queued', 'running');
