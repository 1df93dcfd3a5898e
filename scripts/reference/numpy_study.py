#!/usr/bin/env python3
"""The uncompensated Monte Carlo study written in NumPy, as a user would.

Reads the uncertainty catalogue (`insmc params --format csv`) and the linear
map of every output that depends on the uncertainties alone (`insmc
covariance --scheme none --out DIR` writes DIR/sensitivity.csv), draws the
uncertainties from NumPy's Philox generator, pushes them through the map in
blocks, and prints, per output, the RMS with its delta-method interval, the
mean, min, max and (horizontal) the CEP50 and CEP95 from the kept radial
errors: the statistics `insmc run --scheme none` writes, from an independent
random stream. It is the reference of `scripts/bench-numpy.sh`
(docs/performance.md).

usage: numpy_study.py PARAMS_CSV SENSITIVITY_CSV SAMPLES [SEED]
"""
import csv
import json
import math
import sys

import numpy as np

BLOCK = 1 << 16  # samples per block: 43 uncertainties x 65536 = 22 MB of draws


def read_params(path):
    bounds, names = [], []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            kind = row["distribution"]
            names.append(row["name"])
            if kind == "uniform":
                bounds.append(float(row["bound_si"]))
            elif kind == "zero":
                bounds.append(0.0)
            else:
                sys.exit(f"numpy_study.py: parameter {row['name']}: distribution {kind} is not drawn here "
                         "(uniform and zero only)")
    return names, np.array(bounds)


def read_map(path, names):
    keys, rows = [], []
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        for row in reader:
            keys.append((row["scheme"], row["system"], row["t_min"], row["component"]))
            rows.append([float(row[n]) for n in names])
    return keys, np.array(rows)


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    names, bounds = read_params(sys.argv[1])
    keys, m = read_map(sys.argv[2], names)
    samples = int(float(sys.argv[3]))
    seed = int(sys.argv[4]) if len(sys.argv) == 5 else 1
    index = {k: i for i, k in enumerate(keys)}
    # Outputs: x, y, z and the horizontal radial error per (scheme, system, time).
    groups = sorted({k[:3] for k in keys}, key=lambda g: (g[0], g[1], float(g[2])))
    axes = [(g, a) for g in groups for a in ("x", "y", "z", "horizontal")]
    n_out = len(axes)
    s1, s2, s4 = np.zeros(n_out), np.zeros(n_out), np.zeros(n_out)
    lo, hi = np.full(n_out, np.inf), np.full(n_out, -np.inf)
    radial = {g: np.empty(samples, dtype=np.float32) for g in groups}
    rng = np.random.Generator(np.random.Philox(seed))
    mt = m.T.copy()
    done = 0
    while done < samples:
        n = min(BLOCK, samples - done)
        x = (2.0 * rng.random((n, len(bounds))) - 1.0) * bounds
        y = x @ mt
        values = []
        for g in groups:
            for a in ("x", "y", "z"):
                values.append(y[:, index[g + (a,)]])
            r = np.hypot(y[:, index[g + ("north",)]], y[:, index[g + ("east",)]])
            radial[g][done:done + n] = r
            values.append(r)
        v = np.stack(values)
        v2 = v * v
        s1 += v.sum(axis=1)
        s2 += v2.sum(axis=1)
        s4 += (v2 * v2).sum(axis=1)
        lo = np.minimum(lo, v.min(axis=1))
        hi = np.maximum(hi, v.max(axis=1))
        done += n
    z = 1.959963984540054
    out = []
    for i, (g, a) in enumerate(axes):
        m2, m4 = s2[i] / samples, s4[i] / samples
        half = z * math.sqrt(max(0.0, m4 - m2 * m2) / samples)
        row = {"scheme": g[0], "system": int(g[1]), "t_min": float(g[2]), "axis": a, "n": samples,
               "rms_m": math.sqrt(m2), "rms_lo_m": math.sqrt(max(0.0, m2 - half)),
               "rms_hi_m": math.sqrt(m2 + half), "mean_m": s1[i] / samples, "min_m": lo[i], "max_m": hi[i]}
        if a == "horizontal":
            r = radial[g]
            k50, k95 = math.ceil(0.50 * samples) - 1, math.ceil(0.95 * samples) - 1
            part = np.partition(r, (k50, k95))
            row["cep50_m"], row["cep95_m"] = float(part[k50]), float(part[k95])
        out.append(row)
    json.dump(out, sys.stdout)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
