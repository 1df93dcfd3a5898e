#!/usr/bin/env bash
# Times every command that reads record files (gap, compensate) on files of
# three layout families, 20 runs, 15 min test + 90 min navigation each:
#   own      as `insmc simulate` writes them,
#   foreign  the foreign writer's fixed conventions (simulate --layout foreign),
#   fuzzed   conventions drawn at random per file (simulate --layout fuzzed:
#            spacings 1-60 s, each run's own dropouts, resolution, short runs,
#            header keys), the family no writer of ours shares assumptions with,
#   own-matched  per fuzzed file, the own layout at the nearest spacing of f
#            (a divisor of the test run) with the pulses (or continuous
#            outputs) and r resolution the diagnosis read in it, and each
#            fuzzed file's CPU per row over its twin's: what the layout
#            costs with the spacing and the counting held,
# plus any record files given after the options (other software's files).
#   scripts/time-records.sh [--files N] [--repeat K] [--insmc PATH] [FILE...]
# N files per family (default 5), seeds 1..N; each command K times
# (default 1), the run of least CPU kept (the machines are noisy) and the
# largest peak memory. Prints per family the median
# and the worst case of wall time, CPU time, CPU per 1000 rows and peak
# memory (docs/gap.md "Cost"), and writes the cases to time-records.csv in
# the current folder.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
files=5
repeat=1
insmc=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --files) files=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --insmc) insmc=$2; shift 2 ;;
    *) break ;;
  esac
done
[[ "$files" =~ ^[1-9][0-9]?$ ]] || { echo "time-records: --files must be 1 to 99, got '$files'" >&2; exit 2; }
[[ "$repeat" =~ ^[1-9]$ ]] || { echo "time-records: --repeat must be 1 to 9, got '$repeat'" >&2; exit 2; }
if [[ -z "$insmc" ]]; then
  bash "$root/scripts/install-deps.sh"
  bash "$root/scripts/build.sh" "$root/build/release" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF
  insmc=$root/build/release/apps/insmc
fi
exec python3 "$root/scripts/reference/time_records.py" "$insmc" "$files" "$repeat" "$@"
