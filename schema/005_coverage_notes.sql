-- towdb schema, migration 5: what a build's sweep leaves out, and why
-- (documented in schema/README.md, "coverage_notes"), so that a question the
-- database refuses can say why its data is absent.
--   build_id          the build that wrote the note; a build replaces the notes
--                     of earlier builds of the same sweep file
--   kind              'grid_note': a grid's coverage_note (the sweep author's
--                     words), one row per tug and tow pair of the grid;
--                     'skipped': a condition the sweep could not tow (EQ-SWEEP-3:
--                     the calculated mean tension stays above the limit down to
--                     the lowest speed), with the sweep's reason
--   sweep_label       the grid's label
--   tug_name, tow_name  canonical vessel names, as in cases
--   nominal_speed_kt, sea, heading_deg  the skipped condition (NULL for a
--                     grid note); sea as the sweep prints it ("wind_kt=30")
--   note              the text
CREATE TABLE coverage_notes (
  note_id           INTEGER PRIMARY KEY,
  build_id          INTEGER NOT NULL REFERENCES builds (build_id),
  kind              TEXT NOT NULL CHECK (kind IN ('grid_note', 'skipped')),
  sweep_label       TEXT NOT NULL DEFAULT '',
  tug_name          TEXT NOT NULL,
  tow_name          TEXT NOT NULL,
  nominal_speed_kt  REAL CHECK (nominal_speed_kt IS NULL OR nominal_speed_kt > 0),
  sea               TEXT,
  heading_deg       REAL,
  note              TEXT NOT NULL CHECK (length(note) > 0)
);
CREATE INDEX coverage_notes_by_vessels ON coverage_notes (tug_name, tow_name);
