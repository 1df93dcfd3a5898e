#!/usr/bin/env bash
# The one sanitizer build, build/sanitize: clang with AddressSanitizer,
# UndefinedBehaviorSanitizer and libFuzzer's coverage in every object. The
# test suite runs in it once more (scripts/test.sh) and the fuzz targets of
# the readers are built in it (scripts/fuzz.sh): one build serves both.
# Warnings are not errors here (clang's set differs); the g++ build of
# scripts/test.sh is the -Werror one.
#   scripts/build-sanitize.sh [TARGET...]   (default: everything, tests included)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# A tree configured with another compiler (g++, as this build once was)
# cannot switch: start it anew.
cache=$root/build/sanitize/CMakeCache.txt
if [[ -f $cache ]] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++' "$cache"; then rm -rf "$root/build/sanitize"; fi
INSMC_BUILD_TARGETS="$*" bash "$root/scripts/build.sh" "$root/build/sanitize" \
  -DCMAKE_CXX_COMPILER=clang++ -DINSMC_FUZZ=ON -DBUILD_TESTING=ON -DINSMC_WERROR=OFF -DINSMC_PCH=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1"
