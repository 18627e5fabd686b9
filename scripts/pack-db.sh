#!/usr/bin/env bash
# Packs db/towdb.sqlite into db/towdb.sqlite.tar.xz, the form in which the repository
# stores the bundled database (db/README.md, "Storage"); the build extracts it again
# (db/CMakeLists.txt). Run it after a rebuild of the bundled database, then commit the
# archive. The archive is reproducible: fixed member time, owner and order.
set -euo pipefail
cd "$(dirname "$0")/../db"
if [ ! -f towdb.sqlite ]; then
  echo "pack-db: db/towdb.sqlite not found (build it first: db/README.md)" >&2
  exit 2
fi
# A build leaves the file in WAL mode; the bundled file keeps a rollback journal, so that it
# can be read from a read-only folder (db/README.md, "Storage").
sqlite3 towdb.sqlite "PRAGMA journal_mode = DELETE;" > /dev/null
tmp=towdb.sqlite.tar.xz.tmp
trap 'rm -f "$tmp"' EXIT
tar --sort=name --mtime='2026-01-01 00:00Z' --owner=0 --group=0 --numeric-owner \
    --format=gnu -cf - towdb.sqlite | xz -9e --threads=1 > "$tmp"
mv "$tmp" towdb.sqlite.tar.xz
trap - EXIT
# The file is what the archive holds: keep it the newer, so that the next build does not
# extract it again (db/extract.cmake compares the two times).
touch towdb.sqlite
echo "pack-db: db/towdb.sqlite.tar.xz $(stat -c %s towdb.sqlite.tar.xz) bytes" \
     "(db/towdb.sqlite $(stat -c %s towdb.sqlite) bytes)"
