-- towdb schema, migration 2: the sweep cell of a case (documented in
-- schema/README.md, "cases" additions of schema version 2).
--   condition_key     identity of the sweep cell that made the case (sweep
--                     label, vessels, nominal speed, sea, heading, towline,
--                     mean-tension label): an incremental build replaces a
--                     case whose inputs changed in place instead of keeping a
--                     stale twin (generator/sweep/sweep.hpp EQ-SWEEP-5).
--   nominal_speed_kt  the sweep's tow speed before the 125,000 lbf speed
--                     reduction (thesis ch. 5); equals speed_kt when none.
ALTER TABLE cases ADD COLUMN condition_key TEXT;
ALTER TABLE cases ADD COLUMN nominal_speed_kt REAL CHECK (nominal_speed_kt IS NULL OR nominal_speed_kt > 0);
CREATE UNIQUE INDEX cases_by_condition_key ON cases (condition_key);
