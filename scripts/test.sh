#!/usr/bin/env bash
# README command 2: installs what is missing, builds insmc with its tests
# (warnings are errors) and runs the whole suite, then once more under
# AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --test
jobs=$(nproc)

run_suite() {  # run_suite BUILD_DIR TIMEOUT: quiet on success, full log on failure
  local log="$1-ctest.log"
  if ! ctest --test-dir "$1" -j "$jobs" --output-on-failure --timeout "$2" >"$log" 2>&1; then
    cat "$log"
    echo "tests failed in $1 (log: $log)" >&2
    exit 1
  fi
  grep -E "tests passed|Total Test time" "$log"
}

bash scripts/build.sh build/test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DINSMC_WERROR=ON
run_suite build/test 900
bash scripts/build.sh build/sanitize -DCMAKE_BUILD_TYPE=Debug -DINSMC_WERROR=ON -DINSMC_SANITIZE=ON
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 run_suite build/sanitize 1800
