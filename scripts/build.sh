#!/usr/bin/env bash
# Configures and builds one build tree quietly (the log is shown on failure).
#   scripts/build.sh DIR [cmake -D options...]
# INSMC_BUILD_TARGETS="t1 t2" builds only those targets (default: all).
# With ccache installed (scripts/install-deps.sh --test) every compile goes
# through it: a rebuild of an unchanged file is a cache hit, in any clone.
set -euo pipefail
dir=$1; shift
root=$(cd "$(dirname "$0")/.." && pwd)
log="$dir.log"
mkdir -p "$(dirname "$dir")"
targets=()
for t in ${INSMC_BUILD_TARGETS:-}; do targets+=(--target "$t"); done
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Paths relative to the clone and the working directory left out of the
  # hash: CI's clone lives in a new folder each time. The precompiled
  # headers are cacheable only with pch_defines,time_macros.
  export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
  export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
  # A whole test run (scripts/test.sh) caches well under a gigabyte: room
  # for a few generations, not ccache's default 5 GB on a small disk.
  export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-2G}
fi
if ! { cmake -S "$root" -B "$dir" "${launcher[@]}" "$@" && cmake --build "$dir" -j "$(nproc)" "${targets[@]}"; } >"$log" 2>&1; then
  tail -n 60 "$log" >&2
  echo "build failed: see $log" >&2
  exit 1
fi
