-- towdb schema, migration 8: the daily maxima may be stored as IEEE 754
-- binary16 (documented in schema/README.md, "case_days"), 2 bytes a day
-- instead of 4, so that a database kept to a size budget spends its bytes on
-- cases (the sweep file's maxima_precision = "binary16").
--   maxima_bytes  4: max_dynamic_kips holds binary32 values (every earlier
--                 version); 2: binary16 values, each the binary16 nearest to
--                 the binary32 value (round to nearest, ties to even)
-- SQLite cannot change a table's CHECK constraints, so the table is rebuilt
-- with the same rows (maxima_bytes = 4, the new column last) in the
-- migration's transaction.
CREATE TABLE case_days_v8 (
  case_id             INTEGER PRIMARY KEY REFERENCES cases (case_id) ON DELETE CASCADE,
  days                INTEGER NOT NULL CHECK (days >= 1),
  max_dynamic_kips    BLOB NOT NULL,
  slack_time_s        BLOB CHECK (slack_time_s IS NULL OR (typeof(slack_time_s) = 'blob' AND length(slack_time_s) = 4 * days)),
  snatch_events       BLOB CHECK (snatch_events IS NULL OR (typeof(snatch_events) = 'blob' AND length(snatch_events) = 4 * days)),
  slack_snatch_stored INTEGER NOT NULL DEFAULT 1
    CHECK (slack_snatch_stored IN (0, 1) AND
           (slack_snatch_stored = 1 OR (slack_time_s IS NULL AND snatch_events IS NULL))),
  maxima_bytes        INTEGER NOT NULL DEFAULT 4 CHECK (maxima_bytes IN (2, 4)),
  CHECK (typeof(max_dynamic_kips) = 'blob' AND length(max_dynamic_kips) = maxima_bytes * days)
);
INSERT INTO case_days_v8 (case_id, days, max_dynamic_kips, slack_time_s, snatch_events, slack_snatch_stored, maxima_bytes)
  SELECT case_id, days, max_dynamic_kips, slack_time_s, snatch_events, slack_snatch_stored, 4 FROM case_days;
DROP TABLE case_days;
ALTER TABLE case_days_v8 RENAME TO case_days;
