-- towdb schema, migration 3: the calculated mean tension of a case's sweep
-- condition (documented in schema/README.md, "cases" additions of schema
-- version 3).
--   calculated_mean_tension_lbf  T_calc of EQ-SWEEP-1 at the case's own
--                     speed, wind and heading, as the sweep computed it; the
--                     case's mean_tension_lbf is a factor of it when its label
--                     is a "calculated" basis. The query interpolates along
--                     mean_tension_lbf / calculated_mean_tension_lbf, an axis
--                     that means the same at every grid node (EQ-QUERY-9).
--                     NULL where the sweep had no calculated value (a sea
--                     without a wind, a [[case]] entry, a database built
--                     before version 3).
ALTER TABLE cases ADD COLUMN calculated_mean_tension_lbf REAL
  CHECK (calculated_mean_tension_lbf IS NULL OR calculated_mean_tension_lbf > 0);
