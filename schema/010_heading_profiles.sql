-- towdb schema, migration 10: linear heading profiles (documented in
-- schema/README.md, "heading_profiles"), which the query uses to interpolate
-- between stored headings (query.h EQ-QUERY-11).
--   heading_profiles   one row per line of cases that differ only in heading
--                      (same tug, tow, line, length, speed, sea and mean
--                      tension): the linear model's dynamic-tension standard
--                      deviation on a uniform heading grid (simulation EQ-CASE-3)
--   cases.profile_id   the profile of the case's line; NULL when none is stored
--                      (a line of one heading, a sea with swell, a build that
--                      has not reached its profile stage yet)
CREATE TABLE heading_profiles (
  profile_id          INTEGER PRIMARY KEY,
  profile_key         BLOB NOT NULL UNIQUE,
  mean_tension_lbf    REAL NOT NULL CHECK (mean_tension_lbf > 0),
  heading_first_deg   REAL NOT NULL CHECK (heading_first_deg >= 0),
  heading_step_deg    REAL NOT NULL CHECK (heading_step_deg > 0),
  headings            INTEGER NOT NULL CHECK (headings >= 2),
  sigma_kips_f32      BLOB NOT NULL CHECK (length(sigma_kips_f32) = 4 * headings),
  build_id            INTEGER REFERENCES builds (build_id)
);
ALTER TABLE cases ADD COLUMN profile_id INTEGER REFERENCES heading_profiles (profile_id);
