-- A result of 4 KB or more stored zstd-compressed (src/store/packed.rs), its
-- `result` text then empty; NULL for a result stored as text (every job
-- stored before this column, and every short result).
ALTER TABLE jobs ADD COLUMN result_zstd BYTEA;
