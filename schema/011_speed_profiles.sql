-- towdb schema, migration 11: linear speed profiles (documented in
-- schema/README.md, "speed_profiles"), which the query uses to interpolate
-- between stored speeds (query.h EQ-QUERY-12).
--   speed_profiles           one row per line of cases that differ only in
--                            speed and in the mean tension that goes with it
--                            (same tug, tow, line, length, sea, heading and
--                            mean-tension label): the linear model's
--                            dynamic-tension standard deviation on a uniform
--                            speed grid (generator/sweep/build/speed_profiles.hpp
--                            EQ-SWEEP-9), binary16
--   cases.speed_profile_id   the profile of the case's line; NULL when none
--   cases_by_condition       dropped: no reader looks cases up by it (the query
--                            reads every case once; a build looks them up by
--                            case_key), and its 1.2 MB go to the profiles
CREATE TABLE speed_profiles (
  speed_profile_id    INTEGER PRIMARY KEY,
  profile_key         BLOB NOT NULL CHECK (length(profile_key) = 32),
  speed_first_kt      REAL NOT NULL CHECK (speed_first_kt > 0),
  speed_step_kt       REAL NOT NULL CHECK (speed_step_kt > 0),
  speeds              INTEGER NOT NULL CHECK (speeds >= 2),
  sigma_kips_f16      BLOB NOT NULL CHECK (length(sigma_kips_f16) = 2 * speeds),
  build_id            INTEGER REFERENCES builds (build_id)
);
ALTER TABLE cases ADD COLUMN speed_profile_id INTEGER REFERENCES speed_profiles (speed_profile_id);
DROP INDEX IF EXISTS cases_by_condition;
