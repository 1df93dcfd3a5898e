#!/usr/bin/env bash
# Configures and builds one build tree quietly (the log is shown on failure).
#   scripts/build.sh DIR [cmake -D options...]
# INSMC_BUILD_TARGETS="t1 t2" builds only those targets (default: all).
set -euo pipefail
dir=$1; shift
root=$(cd "$(dirname "$0")/.." && pwd)
log="$dir.log"
mkdir -p "$(dirname "$dir")"
targets=()
for t in ${INSMC_BUILD_TARGETS:-}; do targets+=(--target "$t"); done
if ! { cmake -S "$root" -B "$dir" "$@" && cmake --build "$dir" -j "$(nproc)" "${targets[@]}"; } >"$log" 2>&1; then
  tail -n 60 "$log" >&2
  echo "build failed: see $log" >&2
  exit 1
fi
