-- A label stored with a job (`?label=` on a POST, e.g. a student's id),
-- listed and filtered by `GET /v1/jobs?label=`.
ALTER TABLE jobs ADD COLUMN label TEXT;

CREATE INDEX jobs_label ON jobs (label, seq) WHERE label IS NOT NULL;

-- Idempotency-Key of a POST: the request's fingerprint (SHA-256 of method,
-- path and query, content type and body) and its answer: the job it stored
-- (answered again as a GET of the job answers it) or the answer's bytes.
CREATE TABLE idempotency (
    key          TEXT PRIMARY KEY,
    fingerprint  TEXT NOT NULL,
    created_at   TEXT NOT NULL,
    status       INTEGER NOT NULL,
    content_type TEXT,
    job_id       TEXT,
    body         BLOB
);

CREATE INDEX idempotency_created_at ON idempotency (created_at);
