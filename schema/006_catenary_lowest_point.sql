-- towdb schema, migration 6: the static catenary's lowest point (documented in
-- schema/README.md, "towline_fits"), so that an answer can say how deep the
-- line hangs (water depth decides whether it drags on the bottom).
--   lowest_elevation_ft  elevation of the static catenary's lowest point above
--                        the still waterline (negative: below it) [ft]; NULL
--                        for fits written before this version until a build
--                        of the database fills it (towdb build --resume)
ALTER TABLE towline_fits ADD COLUMN lowest_elevation_ft REAL;
