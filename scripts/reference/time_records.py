"""The timing table of scripts/time-records.sh: each command on each file,
its wall time, CPU time (user + system of the process and its threads) and
peak resident memory from wait4, one at a time."""
import csv
import os
import statistics
import subprocess
import sys
import tempfile
import time

insmc, files, extra = sys.argv[1], int(sys.argv[2]), sys.argv[3:]


def measure(args, refusal_allowed=False):
    start = time.monotonic()
    proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
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


cases = []
with tempfile.TemporaryDirectory() as work:
    inputs = []
    for family in ("own", "foreign", "fuzzed"):
        for seed in range(1, files + 1):
            path = os.path.join(work, f"{family}_{seed}.csv")
            subprocess.run([insmc, "simulate", "--runs", "20", "--seed", str(seed), "--layout", family,
                            "--test-duration", "15min", "--nav-duration", "90min", "--out", path], check=True,
                           stdout=subprocess.DEVNULL)
            inputs.append((family, path))
    inputs += [("given", p) for p in extra]
    for family, path in inputs:
        rows = data_rows(path)
        for command in (["gap", "--records", path, "--format", "json"],
                        ["compensate", "--records", path, "--format", "json"]):
            wall, cpu, mb, refused = measure([insmc] + command, refusal_allowed=command[0] == "compensate")
            cases.append({"family": family, "file": os.path.basename(path), "command": command[0], "rows": rows,
                          "refused": refused,
                          "wall_s": wall, "cpu_s": cpu, "cpu_s_per_1000_rows": 1000.0 * cpu / rows, "peak_mb": mb})

with open("time-records.csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(cases[0].keys()))
    w.writeheader()
    w.writerows(cases)

print("| command | family | files (refused) | rows (median) | wall s median / max | CPU s median / max "
      "| CPU s per 1000 rows median / max | peak MB median / max |")
print("|---|---|---:|---:|---:|---:|---:|---:|")
for command in ("gap", "compensate"):
    for family in ("own", "foreign", "fuzzed", "given"):
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
