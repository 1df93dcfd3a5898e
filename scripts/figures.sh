#!/usr/bin/env bash
# The figure gallery (docs/figures.md): every figure each insmc command
# writes, from fixed seeds and small studies, copied as PNG into OUT_DIR
# (default docs/figures). The tests run it into a folder of their own and
# check every figure (tests/cli/figure_gallery_test.cpp), SVG and PNG.
#   scripts/figures.sh [OUT_DIR] [INSMC] [--svg]
# INSMC defaults to the release build (scripts/build.sh build/release);
# --svg copies each figure's SVG beside its PNG.
# Needs python3 for the synthetic IMU recording the noise figures show.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$(mkdir -p "${1:-$root/docs/figures}" && cd "${1:-$root/docs/figures}" && pwd)"
insmc="${2:-$root/build/release/apps/insmc}"
[[ -x "$insmc" ]] || { echo "figures: no insmc at $insmc (build it with scripts/build.sh build/release)" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"

# The Monte Carlo envelope and a sweep (run), Figure 3.2 (tables), the error
# budget (covariance), the break-even ranking (rank).
"$insmc" run --samples 4000 --seed 7 --quiet --out run
"$insmc" run --samples 1000 --seed 7 --scheme 5.2 --bound gyro_drift=2meru,5meru,10meru,20meru --quiet --out sweep
"$insmc" tables --out tables >/dev/null
"$insmc" covariance --scheme none,5.1.1,5.4 --quiet --out covariance
"$insmc" rank --samples 1000 --seed 7 --system 1 --scheme 5.1.2,5.4 --quiet --out rank

# compensate on a simulated fleet of two units, with a limit drawn.
"$insmc" simulate --runs 10 --seed 7 --scheme 5.3 --out fleet.csv
"$insmc" compensate --records fleet.csv --limit horizontal@84min=2nmi --units nmi --out compensate >/dev/null || true

# The diagnosis on records with a withheld effect, and a quick validation.
"$insmc" simulate --runs 20 --seed 7 --effect velocity_random_walk --out gap.csv
"$insmc" gap --records gap.csv --seed 7 --out gap >/dev/null
"$insmc" gap-validate --effect velocity_random_walk --effect sway --magnitudes 30 --null-files 4 --seeds 1 \
  --out validate >/dev/null

# noise on a synthetic static recording: 1 h at 10 Hz, white noise, a bias
# random walk on the x gyro, z down (sensor frame, gyros in deg/s, g).
python3 - <<'EOF'
import math, random
r = random.Random(7)
dt, n = 0.1, 36000
arw = 0.3 / 60 / math.sqrt(dt)          # deg/s per sample for 0.3 deg/sqrt(h)
vrw = 0.05 / 60 / math.sqrt(dt) / 9.80665
walk = 0.0
with open("imu.csv", "w") as f:
    f.write("gyro_x_dps,gyro_y_dps,gyro_z_dps,acc_x_g,acc_y_g,acc_z_g\n")
    for k in range(n):
        walk += 2e-6 * r.gauss(0, 1)
        f.write("%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n" % (
            0.01 + walk + arw * r.gauss(0, 1), arw * r.gauss(0, 1), arw * r.gauss(0, 1),
            vrw * r.gauss(0, 1), vrw * r.gauss(0, 1), -1.0 + vrw * r.gauss(0, 1)))
EOF
"$insmc" noise --input imu.csv --rate 10Hz --datasheet gyro_arw=0.3degprth --out noise >/dev/null

for f in */*.png; do cp "$f" "$out/"; done
if [[ "${3:-}" == "--svg" ]]; then for f in */*.svg; do cp "$f" "$out/"; done; fi
echo "$(ls "$out" | grep -c '[.]png$') figures in $out" >&2
