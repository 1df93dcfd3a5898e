#!/bin/bash
# The climbs of `insmc run` and `insmc gap` (scripts/call-climbs/climbs.py):
# builds insmc with -finstrument-functions into build/climbs (-O0, so that
# no call is inlined away), runs a small study and a small diagnosis, and
# prints each command's calls from a lower level into a higher one.
#   bash scripts/call-climbs/run.sh            (from the clone's root)
set -euo pipefail
root=$(pwd)
build=$root/build/climbs
mkdir -p "$build"
g++ -std=c++20 -O2 -fPIC -c scripts/call-climbs/call_edges.cpp -o "$build/call_edges.o"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DINSMC_WERROR=OFF \
  "-DCMAKE_CXX_FLAGS_DEBUG=-O0 -g1 -finstrument-functions -finstrument-functions-exclude-file-list=/usr/include" \
  "-DCMAKE_EXE_LINKER_FLAGS=$build/call_edges.o -ldl" > "$build/configure.log"
cmake --build "$build" --target insmc -j "$(nproc)" > "$build/build.log"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
insmc=$build/apps/insmc
"$insmc" simulate --runs 5 --seed 3 --test-duration 15min --nav-duration 30min --out "$work/records.csv"
echo "## insmc run --samples 400 --seed 3 --out DIR"
INSMC_CALL_EDGES=$work/run.edges "$insmc" run --samples 400 --seed 3 --out "$work/run" --quiet
python3 scripts/call-climbs/climbs.py "$root" "$work/run.edges"
echo
echo "## insmc gap --records (5 runs of 45 min) --format json"
INSMC_CALL_EDGES=$work/gap.edges "$insmc" gap --records "$work/records.csv" --format json --calibration-runs 50 > /dev/null
python3 scripts/call-climbs/climbs.py "$root" "$work/gap.edges"
