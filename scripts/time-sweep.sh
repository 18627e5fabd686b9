#!/usr/bin/env bash
# Times a full sweep build (by default the bundled database's sweep, db/sweeps/bundled.toml)
# and prints what docs/performance.md records: wall time, CPU time, cases per hour and peak
# memory, with the machine it ran on.
#
#   scripts/time-sweep.sh [--sweep FILE] [--threads N] [--towdb PATH] [--db PATH] [--resume]
#
# The database goes to a temporary file unless --db is given; with --resume the timing
# covers only the cases that were still missing.
set -euo pipefail

sweep=db/sweeps/bundled.toml
threads=$(nproc)
towdb=./build/cli/towdb
db=""
resume=""
while [ $# -gt 0 ]; do
  case "$1" in
    --sweep) sweep="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --towdb) towdb="$2"; shift 2 ;;
    --db) db="$2"; shift 2 ;;
    --resume) resume="--resume"; shift ;;
    *) echo "time-sweep.sh: unknown argument '$1' (allowed: --sweep FILE, --threads N, --towdb PATH, --db PATH, --resume)" >&2
       exit 2 ;;
  esac
done
if [ ! -x "$towdb" ]; then
  echo "time-sweep.sh: --towdb '$towdb' is not an executable (build first: cmake --build build)" >&2
  exit 2
fi
if [ ! -f "$sweep" ]; then
  echo "time-sweep.sh: --sweep '$sweep' does not exist" >&2
  exit 2
fi
cleanup=""
if [ -z "$db" ]; then
  db=$(mktemp -d)/sweep.sqlite
  cleanup=$(dirname "$db")
fi
log=$(mktemp)
trap 'rm -f "$log"; [ -n "$cleanup" ] && rm -rf "$cleanup"' EXIT

echo "machine: $(uname -m), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo)"
echo "sweep:   $sweep ($threads threads)"
rc=0
/usr/bin/time -v "$towdb" build --sweep "$sweep" --db "$db" --threads "$threads" $resume 2> "$log" || rc=$?
wall=$(grep 'Elapsed (wall clock)' "$log" | awk '{print $NF}')
user=$(grep 'User time' "$log" | awk '{print $NF}')
sys=$(grep 'System time' "$log" | awk '{print $NF}')
rss_kb=$(grep 'Maximum resident set size' "$log" | awk '{print $NF}')
cases=$("$towdb" status --db "$db" --json | grep -o '"results": *[0-9]*' | grep -o '[0-9]*$' || echo "?")
echo "wall:    $wall (h:mm:ss or m:ss)"
echo "cpu:     user ${user} s, system ${sys} s"
echo "memory:  peak RSS $((rss_kb / 1024)) MiB"
echo "results: ${cases} stored"
if [ "$rc" -ne 0 ]; then
  echo "towdb build exited with $rc (failed cases: towdb status --db $db)"
  grep -v -E '^\s+(Command being timed|User time|System time|Percent of CPU|Elapsed|Average|Maximum resident|Major|Minor|Voluntary|Involuntary|Swaps|File system|Socket|Signals|Page size|Exit status)' "$log" >&2 || true
fi
exit "$rc"
