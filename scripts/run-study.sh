#!/usr/bin/env bash
# README command 1: installs what is missing, builds insmc (Release) and runs
# the default Monte Carlo study on the built-in Table 3.1 defaults, printing
# the summary of the envelope (horizontal RMS per scheme and system) and
# writing the full tables to results/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh build/release -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF
./build/release/apps/insmc run --out results "$@"
echo "files: results/envelope.csv envelope_grid.csv envelope.md envelope.svg envelope.png envelope.gp run.json" >&2
