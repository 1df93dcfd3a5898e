#!/usr/bin/env python3
"""Climbs of a command's call walk: the calls it made (call_edges.cpp) from a
lower level of the code into a higher one (a callback, a virtual call, a
function of apps/ called from the library), by the levels of
montecarlo/README.md and the layering test (tests/unit/montecarlo/layering_test.cpp).

    climbs.py SOURCE_ROOT EDGES_FILE

Prints the distinct calls up, by folder pair and by function pair."""
import collections
import os
import subprocess
import sys

# Bottom to top. A folder's level is that of its longest prefix here.
LEVELS = [
    ("lib/", 0),
    ("montecarlo/report/", 1),
    ("montecarlo/study/random/", 2), ("montecarlo/study/kernels/", 2),
    ("montecarlo/study/sampler/", 3),
    ("montecarlo/study/model/", 4),
    ("montecarlo/study/aggregate/", 5),
    ("montecarlo/study/engine/", 6),
    ("montecarlo/study/write/", 7),
    ("montecarlo/study/run/", 8),
    ("montecarlo/study/rank/", 9), ("montecarlo/study/check/", 9), ("montecarlo/study/bench/", 9),
    ("montecarlo/records/runs/", 10),
    ("montecarlo/records/compensate/", 11), ("montecarlo/records/noise/", 11),
    ("montecarlo/records/gap/metric/", 12), ("montecarlo/records/gap/candidates/", 13),
    ("montecarlo/records/gap/diagnosis_options.", 14), ("montecarlo/records/gap/diagnosis_results.", 15),
    ("montecarlo/records/gap/null/", 16), ("montecarlo/records/gap/fit/", 17),
    ("montecarlo/records/gap/where/", 18), ("montecarlo/records/gap/ranking/", 19),
    ("montecarlo/records/gap/diagnosis.", 20), ("montecarlo/records/gap/report/", 21),
    ("montecarlo/records/gap/validation/", 22),
    ("tables/", 23),
    ("apps/", 30),
]


def place(path, root):
    """(folder, level) of a source path, or None outside the project."""
    if not path.startswith(root):
        return None
    rel = path[len(root):].lstrip("/")
    best = None
    for prefix, level in LEVELS:
        if rel.startswith(prefix) and (best is None or len(prefix) > len(best[0])):
            best = (prefix, level)
    if best is None:
        return None
    folder = os.path.dirname(rel) + "/"
    return folder, best[1]


def symbolize(obj, addresses):
    """{address: (function, file)} by addr2line."""
    addresses = sorted(set(addresses))
    out = subprocess.run(["addr2line", "-f", "-C", "-e", obj], input="\n".join(hex(a) for a in addresses),
                         capture_output=True, text=True, check=True).stdout.splitlines()
    result = {}
    for i, a in enumerate(addresses):
        fn, loc = out[2 * i], out[2 * i + 1]
        result[a] = (fn, loc.rsplit(":", 1)[0])
    return result


def main():
    root, edges_file = os.path.realpath(sys.argv[1]), sys.argv[2]
    edges = []
    wanted = collections.defaultdict(set)
    with open(edges_file) as f:
        for line in f:
            fobj, foff, sobj, soff = line.split()
            fn, site = int(foff, 16), int(soff, 16) - 1  # the call instruction, before the return address
            edges.append((fobj, fn, sobj, site))
            wanted[fobj].add(fn)
            wanted[sobj].add(site)
    names = {obj: symbolize(obj, addrs) for obj, addrs in wanted.items()}
    calls = 0
    up_folders = collections.Counter()
    up_functions = set()
    example = {}
    for fobj, fn, sobj, site in edges:
        callee_fn, callee_file = names[fobj][fn]
        caller_fn, caller_file = names[sobj][site]
        callee, caller = place(callee_file, root), place(caller_file, root)
        if callee is None or caller is None:
            continue
        calls += 1
        if callee[1] > caller[1]:
            pair = (caller[0], callee[0])
            key = (caller_fn, callee_fn)
            if key not in up_functions:
                up_functions.add(key)
                up_folders[pair] += 1
                example.setdefault(pair, key)
    print(f"distinct calls inside the project: {calls}")
    print(f"calls up (a callee at a higher level than its caller): {len(up_functions)} function pairs, "
          f"{len(up_folders)} folder pairs")
    for (lower, higher), n in sorted(up_folders.items(), key=lambda kv: (-kv[1], kv[0])):
        caller_fn, callee_fn = example[(lower, higher)]
        print(f"  {lower} -> {higher}: {n} (e.g. {caller_fn[:70]} -> {callee_fn[:70]})")


if __name__ == "__main__":
    main()
