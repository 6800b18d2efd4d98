#!/usr/bin/env python3
"""Tables for the truss and mesh families from several `loci-bench` runs.

usage: mesh_tables.py ONE_THREAD_DIR[,DIR...] TWO_THREAD_DIR[,DIR...]

Each DIR holds the benchmarks.json of one run of loci and ezpz. Times are the medians over
the runs of each run's median; the ratio is taken within each run (both solvers timed in
the same process on the same machine state), then its median over runs.
"""
import json
import math
import statistics
import sys


def load(dirs):
    runs = []
    for d in dirs.split(","):
        with open(f"{d}/benchmarks.json") as f:
            runs.append(json.load(f)["cells"])
    return runs


def cell(run, fam, var, size, solver):
    for c in run:
        if (c["family"], c["variant"], c["size"], c["solver"]) == (fam, var, size, solver):
            return c
    return None


def ms(x):
    if x is None:
        return "—"
    if x >= 1000:
        return f"{x / 1000:.2f} s"
    if x >= 10:
        return f"{x:.1f} ms"
    if x >= 1:
        return f"{x:.2f} ms"
    return f"{x:.3f} ms"


def med(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def main():
    one, two = load(sys.argv[1]), load(sys.argv[2])
    fams = sorted({(c["family"], c["variant"]) for r in one for c in r},
                  key=lambda fv: (fv[0], ["solvable", "redundant", "inconsistent"].index(fv[1])))
    for fam, var in fams:
        sizes = sorted({c["size"] for r in one for c in r if (c["family"], c["variant"]) == (fam, var)})
        print(f"### {fam} / {var}\n")
        print("| size | unknowns | ezpz | loci, 1 thread | ratio | loci, 2 threads | 2 / 1 threads |")
        print("| ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
        pts = []
        for s in sizes:
            side = round(math.sqrt(s))
            ez = med([(cell(r, fam, var, s, "ezpz") or {}).get("solve_ms") for r in one])
            lo = med([(cell(r, fam, var, s, "loci") or {}).get("solve_ms") for r in one])
            ratios = []
            for r in one:
                a, b = cell(r, fam, var, s, "ezpz"), cell(r, fam, var, s, "loci")
                if a and b and a.get("solve_ms") and b.get("solve_ms"):
                    ratios.append(a["solve_ms"] / b["solve_ms"])
            ratio = med(ratios)
            l2 = med([(cell(r, fam, var, s, "loci") or {}).get("solve_ms") for r in two])
            t21 = f"{l2 / lo:.2f}" if l2 and lo else "—"
            rt = f"{ratio:.1f}×" if ratio else "—"
            print(f"| {side}×{side} | {2 * s:,} | {ms(ez)} | {ms(lo)} | {rt} | {ms(l2)} | {t21} |")
            if lo and s >= 400:
                pts.append((math.log(s), math.log(lo)))
        if len(pts) >= 2:
            mx = sum(p[0] for p in pts) / len(pts)
            my = sum(p[1] for p in pts) / len(pts)
            k = sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)
            print(f"\nloci's time grows as N^{k:.2f} (least squares on log time against log N, "
                  f"N = points, from 20×20 up).\n")
        else:
            print()


main()
