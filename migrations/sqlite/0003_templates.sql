-- Jobs computed for a template's parameters carry a key of their request
-- (SHA-256 of kind, engine version and the request's canonical JSON), so a
-- repeated GET of the same parameters finds the stored job instead of
-- computing it again. NULL for jobs POSTed directly.
ALTER TABLE jobs ADD COLUMN request_key TEXT;

CREATE INDEX jobs_request_key ON jobs (request_key) WHERE request_key IS NOT NULL;

-- Templates created by clients (the built-in ones ship with the binary):
-- the whole template as JSON, as answered by GET /v1/templates/{id}.
CREATE TABLE templates (
    id         TEXT PRIMARY KEY,
    created_at TEXT NOT NULL,
    body       TEXT NOT NULL
);
