"""The timing table of scripts/time-records.sh: each command on each file,
its wall time, CPU time (user + system of the process and its threads) and
peak resident memory from wait4, one at a time; with a repeat count, each
command runs that many times and the run of least CPU is kept (what other
work on the machine adds is never negative), with the largest peak memory
of them all."""
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

insmc, files, repeat, extra = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4:]


def measure(args, refusal_allowed=False, out_path=os.devnull):
    """Wall and CPU of the run of least CPU, the largest peak of them all."""
    runs = [measure_once(args, refusal_allowed, out_path) for _ in range(repeat)]
    wall, cpu, _, refused = min(runs, key=lambda run: run[1])
    return wall, cpu, max(run[2] for run in runs), refused


def measure_once(args, refusal_allowed=False, out_path=os.devnull):
    start = time.monotonic()
    with open(out_path, "wb") as out:
        proc = subprocess.Popen(args, stdout=out, stderr=subprocess.PIPE)
        _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    err = proc.stderr.read().decode(errors="replace").strip()
    code = os.waitstatus_to_exitcode(status)
    # compensate refuses (exit 2) a file with a run holding less than half of
    # its recorded test rows (docs/compensate.md): counted, not timed.
    if code not in (0, 1) and not (refusal_allowed and code == 2):
        sys.exit(f"time-records: {' '.join(args)} exited {code}: {err}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0, code == 2


def data_rows(path):
    rows, header_seen = 0, False
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            if header_seen:
                rows += 1
            header_seen = True
    return rows


def f_spacing_s(path):
    """The nominal spacing of a file's f records: the median step between
    consecutive f rows of each run (dropouts lengthen a few steps only)."""
    last, steps = {}, []
    with open(path) as f:
        header = None
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            cells = line.rstrip("\n").split(",")
            if header is None:
                header = {name: i for i, name in enumerate(cells)}
                continue
            if cells[header["f_x"]] == "":
                continue
            run, t = cells[header["run"]], float(cells[header["t_s"]])
            if run in last:
                steps.append(t - last[run])
            last[run] = t
    return statistics.median(steps) if steps else None


TEST_DURATION_S = 900  # the files' test run, 15 min


def matched_interval_s(spacing):
    """The filter interval of the own layout nearest a spacing: a divisor of
    the test run (the own writer's f and r every interval)."""
    divisors = [d for d in range(1, TEST_DURATION_S + 1) if TEST_DURATION_S % d == 0 and d <= 60]
    return min(divisors, key=lambda d: abs(d - spacing))


def simulate(path, seed, layout, *extra_args):
    subprocess.run([insmc, "simulate", "--runs", "20", "--seed", str(seed), "--layout", layout,
                    "--test-duration", "15min", "--nav-duration", "90min", "--out", path, *extra_args], check=True,
                   stdout=subprocess.DEVNULL)


def site_value(gap_json_path, key):
    """A site value the diagnosis used (stated or inferred), from gap.json."""
    with open(gap_json_path) as f:
        return json.load(f)["site"][key]["value"]


cases = []
pairs = []  # (fuzzed file, its own-layout twin, the fuzzed file's f spacing, the twin's interval)


def time_file(family, path, work):
    rows = data_rows(path)
    for command in ("gap", "compensate"):
        out = os.path.join(work, "out.json")
        wall, cpu, mb, refused = measure([insmc, command, "--records", path, "--format", "json"],
                                         refusal_allowed=command == "compensate", out_path=out)
        cases.append({"family": family, "file": os.path.basename(path), "command": command, "rows": rows,
                      "refused": refused,
                      "wall_s": wall, "cpu_s": cpu, "cpu_s_per_1000_rows": 1000.0 * cpu / rows, "peak_mb": mb})
        if command == "gap":
            site = {key: site_value(out, key) for key in ("dv_pulse_mps", "position_resolution_m")}
    return site


with tempfile.TemporaryDirectory() as work:
    for family in ("own", "foreign", "fuzzed"):
        for seed in range(1, files + 1):
            path = os.path.join(work, f"{family}_{seed}.csv")
            simulate(path, seed, family)
            site = time_file(family, path, work)
            if family == "fuzzed":
                # The same runs' length on the own layout at the fuzzed
                # file's spacing of f, with its pulses (or continuous
                # outputs) and its resolution of r as the diagnosis read
                # them: the cost per row of a layout against the own
                # layout's, not against another spacing's or another
                # counting's (the model's size is set by the runs' duration,
                # docs/gap.md "Speed").
                spacing = f_spacing_s(path)
                if spacing is None:  # no run with two f records: no spacing to match
                    continue
                interval = matched_interval_s(spacing)
                twin = os.path.join(work, f"own-matched_{seed}.csv")
                simulate(twin, seed, "own", "--filter-interval", f"{interval}s",
                         "--dv-pulse", f"{site['dv_pulse_mps']:.9g}mps",
                         "--position-resolution", f"{site['position_resolution_m']:.9g}m")
                time_file("own-matched", twin, work)
                pairs.append((os.path.basename(path), os.path.basename(twin), spacing, interval, site["dv_pulse_mps"]))
    for path in extra:
        time_file("given", path, work)

with open("time-records.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(cases[0].keys()))
    w.writeheader()
    w.writerows(cases)

print("| command | family | files (refused) | rows (median) | wall s median / max | CPU s median / max "
      "| CPU s per 1000 rows median / max | peak MB median / max |")
print("|---|---|---:|---:|---:|---:|---:|---:|")
for command in ("gap", "compensate"):
    for family in ("own", "foreign", "fuzzed", "own-matched", "given"):
        every = [x for x in cases if x["family"] == family and x["command"] == command]
        c = [x for x in every if not x["refused"]]
        if not c:
            if every:
                print(f"| {command} | {family} | {len(every)} ({len(every)}) | | | | | |")
            continue
        def mm(key, fmt="{:.1f}"):
            v = [x[key] for x in c]
            return f"{fmt.format(statistics.median(v))} / {fmt.format(max(v))}"
        print(f"| {command} | {family} | {len(every)} ({len(every) - len(c)}) | {statistics.median(x['rows'] for x in c):.0f} | {mm('wall_s')} "
              f"| {mm('cpu_s')} | {mm('cpu_s_per_1000_rows', '{:.2f}')} | {mm('peak_mb', '{:.0f}')} |")

# Each fuzzed file's CPU per row over its own-layout twin's at the nearest
# spacing: what the layout (dropouts per run, conventions) costs, the
# spacing held.
if pairs:
    def gap_case(name):
        return next(x for x in cases if x["file"] == name and x["command"] == "gap")
    print()
    print("| fuzzed file | its f spacing s | own twin's interval s | pulse m/s (0: continuous) | rows fuzzed / own "
          "| gap CPU s per 1000 rows fuzzed / own | ratio |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    ratios = []
    for fuzzed, twin, spacing, interval, pulse in pairs:
        a, b = gap_case(fuzzed), gap_case(twin)
        ratio = a["cpu_s_per_1000_rows"] / b["cpu_s_per_1000_rows"]
        ratios.append(ratio)
        print(f"| {fuzzed} | {spacing:g} | {interval} | {pulse:.4g} | {a['rows']} / {b['rows']} | "
              f"{a['cpu_s_per_1000_rows']:.2f} / {b['cpu_s_per_1000_rows']:.2f} | {ratio:.2f} |")
    print(f"\nCPU per row of a fuzzed layout over the own layout's at its spacing and counting: median {statistics.median(ratios):.2f}, "
          f"worst {max(ratios):.2f}")
