#!/usr/bin/env bash
# insmc beside a NumPy implementation of the same uncompensated paper-level
# study (scripts/reference/numpy_study.py), timed in the same run, rounds
# interleaved, best of each (docs/performance.md#against-numpy):
#   scripts/bench-numpy.sh [SAMPLES] [ROUNDS]      defaults 1e7 and 3
# Installs NumPy with OpenBLAS (run single-threaded, as the reference),
# builds the release insmc, writes the catalogue (insmc params) and the map
# (insmc covariance's sensitivity.csv) for NumPy to read, then prints each
# program's wall and CPU time, their ratios, and how far the two studies'
# RMS agree (independent random streams: each difference over its standard
# error).
set -euo pipefail
cd "$(dirname "$0")/.."
samples=${1:-1e7}
rounds=${2:-3}
[[ "$rounds" =~ ^[1-9][0-9]?$ ]] || { echo "bench-numpy: ROUNDS must be 1 to 99, got '$rounds'" >&2; exit 2; }
bash scripts/install-deps.sh --numpy
bash scripts/build.sh build/release -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF
insmc=build/release/apps/insmc
python=/usr/bin/python3  # Debian's, with Debian's NumPy
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$insmc" params --format csv >"$work/params.csv"
"$insmc" covariance --fidelity paper --scheme none --quiet --out "$work/map"
cores=$(nproc)  # before OMP_NUM_THREADS, which nproc obeys
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
TIMEFORMAT='%R %U %S'
for ((r = 1; r <= rounds; ++r)); do
  { time "$insmc" run --fidelity paper --scheme none --samples "$samples" --grid-step 42min --quiet \
      --out "$work/run" >/dev/null; } 2>>"$work/insmc.times"
  { time "$python" scripts/reference/numpy_study.py "$work/params.csv" "$work/map/sensitivity.csv" "$samples" \
      >"$work/numpy.json"; } 2>>"$work/numpy.times"
done
"$python" - "$work" "$samples" "$cores" <<'PY'
import csv, json, math, sys
work, samples, cores = sys.argv[1], sys.argv[2], sys.argv[3]
def best(path):
    rows = [tuple(map(float, line.split())) for line in open(path) if line.strip()]
    wall, user, sys_ = min(rows)
    return wall, user + sys_, len(rows)
iw, ic, n = best(f"{work}/insmc.times")
nw, nc, _ = best(f"{work}/numpy.times")
print(f"uncompensated paper-level study, {samples} samples, best of {n} interleaved rounds, {cores} cores")
print("| program | wall [s] | CPU [s] |")
print("|---|---:|---:|")
print(f"| insmc run (all cores) | {iw:.2f} | {ic:.2f} |")
print(f"| NumPy (OpenBLAS, 1 thread) | {nw:.2f} | {nc:.2f} |")
print(f"NumPy / insmc: {nw / iw:.2f} in wall time, {nc / ic:.2f} per CPU second")
mine = {}
for row in csv.DictReader(open(f"{work}/run/envelope.csv")):
    mine[(row["scheme"], int(row["system"]), float(row["t_min"]), row["axis"])] = row
worst = 0.0
for o in json.load(open(f"{work}/numpy.json")):
    m = mine[(o["scheme"], o["system"], o["t_min"], o["axis"])]
    se = lambda lo, hi: (hi - lo) / (2 * 1.959963984540054)
    z = (float(m["rms_m"]) - o["rms_m"]) / math.hypot(se(float(m["rms_lo_m"]), float(m["rms_hi_m"])),
                                                       se(o["rms_lo_m"], o["rms_hi_m"]))
    worst = max(worst, abs(z))
print(f"agreement: the largest |RMS difference| / standard error over the outputs: {worst:.2f}")
PY
