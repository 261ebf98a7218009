-- Every computation is a job: the request as the client sent it, the result
-- as served, how long the engine took, and which engine computed it.
CREATE TABLE jobs (
    -- Insertion order; the cursor of the jobs list (newest first).
    seq            INTEGER PRIMARY KEY AUTOINCREMENT,
    -- Public id: a random UUID (unguessable).
    id             TEXT    NOT NULL UNIQUE,
    -- flywheel, kinetostatics, dynamics, rotor.
    kind           TEXT    NOT NULL,
    -- RFC 3339 UTC time of creation.
    created_at     TEXT    NOT NULL,
    -- Request body, exactly as sent (JSON text).
    request        TEXT    NOT NULL,
    -- Result as served (JSON text).
    result         TEXT    NOT NULL,
    -- Engine wall time in microseconds.
    engine_us      INTEGER NOT NULL,
    -- Version of mechdyn that computed the result.
    engine_version TEXT    NOT NULL
);

CREATE INDEX jobs_kind_seq ON jobs (kind, seq);
