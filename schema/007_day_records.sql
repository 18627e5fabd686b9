-- towdb schema, migration 7: a case may store its daily maxima without the
-- per-day slack time and snatch count (documented in schema/README.md,
-- "case_days"), so that a database kept to a size budget spends its bytes on
-- cases; the case's slack fraction and snatch rate stay in results.
--   slack_snatch_stored  1: slack_time_s and snatch_events hold every day
--                        (NULL = zero on every day, as in schema 4);
--                        0: they were not stored (both NULL), the sweep
--                        file's day_records = "maxima"
ALTER TABLE case_days ADD COLUMN slack_snatch_stored INTEGER NOT NULL DEFAULT 1
  CHECK (slack_snatch_stored IN (0, 1) AND
         (slack_snatch_stored = 1 OR (slack_time_s IS NULL AND snatch_events IS NULL)));
