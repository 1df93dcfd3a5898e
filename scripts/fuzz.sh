#!/usr/bin/env bash
# Fuzzes every input reader, the option parser and the commands that write
# records (tests/fuzz: records, imu, bounds, config, checkpoint with its
# accumulator state, quantity, run_json, options, import_imu, simulate) for
# SECONDS each with libFuzzer, AddressSanitizer and
# UndefinedBehaviorSanitizer. Quiet on success (a line of executions per
# target with -v); on a crash prints the crash input (kept under
# build/sanitize/crashes/<target>/) and exits 1.
#   scripts/fuzz.sh SECONDS [-v]
# Installs clang, libclang-rt-14-dev (libFuzzer) and ccache from Debian's
# archive if missing (as root), builds the fuzz targets in the sanitizer
# build (scripts/build-sanitize.sh, ccache), and runs each target on a copy
# of its corpus (tests/fuzz/corpus/<target> + regressions/<target>): the
# repository's corpus is never written.
set -euo pipefail
seconds=${1:?usage: scripts/fuzz.sh SECONDS [-v]}
verbose=${2:-}
root=$(cd "$(dirname "$0")/.." && pwd)
targets=(records imu bounds config checkpoint quantity run_json options import_imu simulate)
# INSMC_FUZZ_TARGETS="records imu" fuzzes those alone (a long campaign split over cores).
if [[ -n ${INSMC_FUZZ_TARGETS:-} ]]; then read -r -a targets <<<"$INSMC_FUZZ_TARGETS"; fi

packages=(clang libclang-rt-14-dev ccache cmake make libeigen3-dev libtbb-dev libboost-program-options-dev
          libboost-dev libfmt-dev nlohmann-json3-dev)
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then missing+=("$p"); fi
done
if [[ ${#missing[@]} -gt 0 ]]; then
  if [[ $(id -u) -ne 0 ]]; then
    echo "fuzz: missing Debian packages: ${missing[*]}; run as root to install them" >&2
    exit 1
  fi
  log=$(mktemp)
  if ! { DEBIAN_FRONTEND=noninteractive apt-get update -q &&
         DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"; } >"$log" 2>&1; then
    cat "$log" >&2
    echo "fuzz: apt-get failed installing: ${missing[*]}" >&2
    exit 1
  fi
  rm -f "$log"
fi

build=$root/build/sanitize
fuzz_targets=()
for t in "${targets[@]}"; do fuzz_targets+=("fuzz_$t"); done
bash "$root/scripts/build-sanitize.sh" "${fuzz_targets[@]}"

work=$(mktemp -d)
# The targets' scratch files (megabytes each), in memory where /dev/shm is;
# removed here too, since a fuzzer may exit without running destructors.
scratch=$(mktemp -d -p /dev/shm 2>/dev/null || mktemp -d)
export INSMC_FUZZ_SCRATCH=$scratch
trap 'rm -rf "$work" "$scratch"' EXIT
failed=0
for t in "${targets[@]}"; do
  corpus=$work/$t/corpus
  mkdir -p "$corpus" "$work/$t/artifacts"
  for kind in corpus regressions; do
    src=$root/tests/fuzz/$kind/$t
    if [[ -d $src ]] && compgen -G "$src/*" >/dev/null; then cp "$src"/* "$corpus"/; fi
  done
  # A crash is anything but a normal return: a sanitizer report, an abort,
  # an exception other than InputError, more than 5 s on one input (600 s
  # for import_imu: with its raw-noise stage on, the fit of six channels on a
  # recording no model fits, as a periodic byte pattern is, tries every
  # shorter range of levels, 90 s under the fuzzer's comparison tracing on
  # its 100 Hz seed, 2 s without it) or more than 2 GB of memory.
  timeout=5
  [[ $t == import_imu ]] && timeout=600
  if ! "$build/fuzz_$t" "$corpus" -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 \
       -artifact_prefix="$work/$t/artifacts/" -print_final_stats=1 >"$work/$t/log" 2>&1; then
    kept=$build/crashes/$t
    mkdir -p "$kept"
    echo "fuzz: fuzz_$t crashed; the last lines of its log:" >&2
    tail -n 40 "$work/$t/log" >&2
    for crash in "$work/$t/artifacts"/*; do
      [[ -e $crash ]] || continue
      cp "$crash" "$kept/"
      echo "fuzz: crash input: $kept/$(basename "$crash") (replay: $build/fuzz_$t $kept/$(basename "$crash"))" >&2
    done
    cp "$work/$t/log" "$kept/log"
    failed=1
  elif [[ $verbose == -v ]]; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$t/log")
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$work/$t/log")
    echo "fuzz_$t: $runs executions in $seconds s ($rate/s), no crash"
  fi
done
exit $failed
