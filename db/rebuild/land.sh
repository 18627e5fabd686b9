#!/usr/bin/env bash
# The mechanical steps of landing the finished 0.4.0 rebuild (README.md here, "To land"),
# run from the root of the flip-0.4.0 worktree with its towdb built (build/cli/towdb):
#   bash db/rebuild/land.sh next.sqlite [OUT]
# Refuses (exit 2) unless every case is done. Writes the compacted database to
# db/towdb.sqlite, runs the no-op build, the stored audit (300 questions, seed 6,
# 400 days: about 12 min on 2 cores), the database's answers at the thesis's inputs,
# the README's question, and packs the archive; every measurement goes to OUT
# (default ../landing-out) for the documents. The documents and the merge stay manual.
set -euo pipefail
db=${1:?usage: land.sh FINISHED.sqlite [OUT]}
out=${2:-../landing-out}
towdb=./build/cli/towdb
mkdir -p "$out"

left=$(sqlite3 "file:$db?mode=ro" "SELECT count(*) FROM cases WHERE status <> 'done'")
if [ "$left" != 0 ]; then
  echo "land: $left cases of $db are not done; resume the build first" >&2
  exit 2
fi
# Every line of this grid has a heading and a speed profile (build 18: all 41,976 cases use one).
unprofiled=$(sqlite3 "file:$db?mode=ro" \
  "SELECT count(*) FROM cases WHERE profile_id IS NULL OR speed_profile_id IS NULL")
if [ "$unprofiled" != 0 ]; then
  echo "land: $unprofiled cases of $db lack a profile; the profile stage has not finished: resume the build" >&2
  exit 2
fi
"$towdb" status --db "$db" | tee "$out/status-rebuild.txt"

# Compacted as every bundled database is (db/README.md, "Storage").
rm -f "$out/v.sqlite"
sqlite3 "$db" "VACUUM INTO '$out/v.sqlite'"
sqlite3 "$out/v.sqlite" "PRAGMA page_size = 16384; VACUUM; PRAGMA journal_mode = DELETE;" > /dev/null
check=$(sqlite3 "$out/v.sqlite" "PRAGMA integrity_check")
if [ "$check" != ok ]; then
  echo "land: integrity_check of the compacted database: $check" >&2
  exit 2
fi
cp "$out/v.sqlite" db/towdb.sqlite

# Nothing to compute: records the repository's sweep path in the builds table.
"$towdb" build --sweep db/sweeps/bundled.toml --db db/towdb.sqlite --threads 2 | tee "$out/noop-build.txt"

"$towdb" audit --db db/towdb.sqlite --draws 300 --seed 6 --days 400 --threads 2 --json \
  --plot "$out/audit.png" > "$out/audit.json"
python3 db/rebuild/audit_parts.py "$out/audit.json" | tee "$out/audit-parts.md"
"$towdb" status --db db/towdb.sqlite | tee "$out/status.txt"

readme_question=(--db db/towdb.sqlite --tug T-ATF --tow FFG7 --speed-kt 7 --wind-kt 30 --heading-deg 150
                 --line fiber --length-ft 1200)
"$towdb" query "${readme_question[@]}" | tee "$out/readme-query.txt"
"$towdb" query "${readme_question[@]}" --json > "$out/readme-query.json"

"$towdb" validate --database db/towdb.sqlite --cases tests/data/validation/appendix_c_calibration.csv \
  --out "$out/validate-database" --no-plot | tee "$out/validate-database.txt"

bash scripts/pack-db.sh | tee "$out/pack.txt"
echo "land: measurements in $out; now the documents (README.md here, 'To land')"
