#!/usr/bin/env bash
# README command 2: installs what is missing, builds insmc with its tests
# (g++, warnings are errors) and runs the whole suite; then the sanitizer
# build (clang with AddressSanitizer and UndefinedBehaviorSanitizer,
# scripts/build-sanitize.sh) runs the suite's code paths once more and
# fuzzes every input reader and the option parser for 10 s each on the same
# build (scripts/fuzz.sh); then the MPI variant (-DINSMC_MPI=ON) runs its
# tests under mpirun (label mpi). Quiet on success: one line per stage with
# its time.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --test
jobs=$(nproc)
stage_start=$SECONDS

stage_done() {  # stage_done NAME: the stage's wall time
  echo "$1: $((SECONDS - stage_start)) s"
  stage_start=$SECONDS
}

run_suite() {  # run_suite BUILD_DIR TIMEOUT [ctest options]: quiet on success, full log on failure
  local dir=$1 timeout=$2 log="$1-ctest.log"
  shift 2
  if ! ctest --test-dir "$dir" -j "$jobs" --output-on-failure --no-tests=error --timeout "$timeout" "$@" >"$log" 2>&1; then
    cat "$log"
    echo "tests failed in $dir (log: $log)" >&2
    exit 1
  fi
  grep -E "tests passed" "$log"
}

# Line tables only (-g1): backtraces name file and line, and the builds are
# a third faster than with full debug information.
bash scripts/build.sh build/test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DINSMC_WERROR=ON \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG"
stage_done "build (g++, -Werror)"
run_suite build/test 900
stage_done "suite"

# Under the sanitizers, the code paths rather than the repetitions: left out
# are the statistical studies (label statistical) and the end-to-end studies
# that run the same code many times (the diagnosis's null files and
# validation, the raw rankings, the real-data commands, the noise fit's
# coverage, the kill and two-writer loops of the output sets, the long and
# huge inputs, rank's studies, the golden studies, the truth level at each
# thread count, the benchmark, the figure gallery, the progress lines on a
# terminal); the code each drives runs under the
# sanitizers in the unit tests and the short end-to-end cases of the same
# commands.
sanitizer_skip='^(GapValidate[.]|RealDataDocs[.]|RawRanking[.]|NoiseFit[.](WhiteAndRandomWalk|GaussMarkovCorrelationTime|WhiteGaussMarkov)|GapLinearNull[.]|GapImportedNull[.]|GapImportedNoise[.]|GapLikelihood[.]|Outputs[.](ASigkill|OfTwoRuns)'
sanitizer_skip+='|HostileFiles[.]InputsLarger|Rank[.]|Plots[.]Rank|Checkpoint[.]Sigterm|SchemeErrorsGolden[.]'
sanitizer_skip+='|Cli[.](TruthFidelity|BenchJson)|Compensate[.]TheVerdict|HostileInput[.]ValuesAtTheEdges'
sanitizer_skip+='|Gap[.]FilterWindows|FigureGallery[.]Every|Progress[.]|WorkBudget[.](TheGreedySearch|TheNullCalibration)'
sanitizer_skip+='|Gap[.](AnEffectAfterAScheme|RecordsOfOtherSoftware|AWithheld|RecordsOfTheModelItself|ScreeningWithout))'
bash scripts/build-sanitize.sh
stage_done "build (clang, sanitizers)"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 run_suite build/sanitize 1800 -LE statistical \
  -E "$sanitizer_skip"
stage_done "suite under the sanitizers"
bash scripts/fuzz.sh 10
stage_done "fuzzing"
# A passed stage's tree goes (ccache keeps its objects for the next run):
# the three trees and the cache together outgrew a CI machine's disk.
rm -rf build/sanitize

# The MPI variant: insmc and its MPI tests only (the rest is the same code as
# build/test), run serially (each test starts up to 3 ranks on the cores).
INSMC_BUILD_TARGETS="insmc cli_mpi_test" bash scripts/build.sh build/mpi -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DINSMC_WERROR=ON -DINSMC_MPI=ON "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG"
jobs=1 run_suite build/mpi 600 -L mpi
stage_done "MPI"
rm -rf build/mpi
