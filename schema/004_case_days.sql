-- towdb schema, migration 4: every simulated day of a case in one row
-- (documented in schema/README.md, "case_days"). Replaces daily_maxima (one
-- row per day, about 22 bytes a day) with little-endian packed arrays (4 bytes
-- a day, slack and snatch arrays only where the line went slack), so that a
-- grid dense enough for interpolation fits the bundled database's size.
--   days              number of days; every array holds this many values
--   max_dynamic_kips  float32 each: the day's maximum dynamic tension
--   slack_time_s      float32 each: time the line was slack that day;
--                     NULL when it was never slack on any day
--   snatch_events     uint32 each: slack-to-taut events that day; NULL when
--                     there were none on any day
-- The rows of daily_maxima are packed into it and daily_maxima is dropped by
-- the migration's second step (generator/store/packed_days.cpp): SQL has no
-- float32 encoder.
CREATE TABLE case_days (
  case_id           INTEGER PRIMARY KEY REFERENCES cases (case_id) ON DELETE CASCADE,
  days              INTEGER NOT NULL CHECK (days >= 1),
  max_dynamic_kips  BLOB NOT NULL CHECK (typeof(max_dynamic_kips) = 'blob' AND length(max_dynamic_kips) = 4 * days),
  slack_time_s      BLOB CHECK (slack_time_s IS NULL OR (typeof(slack_time_s) = 'blob' AND length(slack_time_s) = 4 * days)),
  snatch_events     BLOB CHECK (snatch_events IS NULL OR (typeof(snatch_events) = 'blob' AND length(snatch_events) = 4 * days))
);
