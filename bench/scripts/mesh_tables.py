#!/usr/bin/env python3
"""Tables for the truss and mesh families from several `loci-bench` runs.

usage: mesh_tables.py ONE_THREAD_DIR[,DIR...] TWO_THREAD_DIR[,DIR...]

Each DIR holds the benchmarks.json of one run of loci and ezpz (and, when the one-thread runs
have them, SolveSpace through its C library and PlaneGCS, each given a column). Times are the
medians over the runs of each run's median; the ratio is taken within each run (both solvers
timed in the same process on the same machine state), then its median over runs. A peer's cell
is its time when it solved the problem (or, on the inconsistent variant, reported it as such),
otherwise what it said.
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


PEERS = [("slvs_c", "SolveSpace"), ("plane_gcs", "PlaneGCS")]


def peer(runs, fam, var, size, solver):
    cells = [c for c in (cell(r, fam, var, size, solver) for r in runs) if c]
    if not cells:
        return "—"
    good = [c["solve_ms"] for c in cells
            if c["verdict"]["verdict"] in ("solved", "detected") and c.get("solve_ms")]
    if good:
        return ms(med(good))
    c = cells[0]
    v = c["verdict"]
    detail = v.get("detail", "") or c.get("detail", "")
    if v["verdict"] == "not_run":
        reason = v.get("reason", "")
        if "out of memory" in reason:
            return "not run (out of memory below)"
        if "refuses" in reason:
            return "not run (refused below)"
        return "over the limit" if "limit" in reason or "timeout" in reason else "—"
    if v["verdict"] == "timeout":
        return "over the limit"
    if v["verdict"] == "refused":
        return "refuses: " + detail.split(" (")[0]
    if "out of memory" in detail:
        return "out of memory"
    said = detail.replace("failed: ", "").split(" (")[0]
    t = f"{ms(c['solve_ms'])}, " if c.get("solve_ms") else ""
    return f"{t}fails: {said}" if said else c["verdict"]["verdict"]


def main():
    one, two = load(sys.argv[1]), load(sys.argv[2])
    fams = sorted({(c["family"], c["variant"]) for r in one for c in r},
                  key=lambda fv: (fv[0], ["solvable", "redundant", "inconsistent"].index(fv[1])))
    for fam, var in fams:
        sizes = sorted({c["size"] for r in one for c in r if (c["family"], c["variant"]) == (fam, var)})
        print(f"### {fam} / {var}\n")
        peers = [(k, name) for k, name in PEERS
                 if any(c["solver"] == k and (c["family"], c["variant"]) == (fam, var)
                        for r in one for c in r)]
        heads = "".join(f" {name} |" for _, name in peers)
        # A lattice of points has two unknowns a point; a sheet of profiles has its slots too.
        lattice = fam in ("truss", "mesh")
        unk = " unknowns |" if lattice else ""
        print(f"| size |{unk} ezpz |{heads} loci, 1 thread | ezpz / loci | loci, 2 threads "
              "| 2 / 1 threads (against ezpz's drift) |")
        print("| ---: |" + " ---: |" * (lattice + 1 + len(peers)) + " ---: | ---: | ---: | ---: |")
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
            # ezpz runs on one thread in both runs: its own change between them is the
            # machine's, which the normalised ratio takes out.
            e2 = med([(cell(r, fam, var, s, "ezpz") or {}).get("solve_ms") for r in two])
            if l2 and lo and ez and e2:
                t21 += f" ({(l2 / lo) / (e2 / ez):.2f})"
            rt = f"{ratio:.1f}×" if ratio else "—"
            cols = "".join(f" {peer(one, fam, var, s, k)} |" for k, _ in peers)
            lo_cell = ms(lo) if lo else peer(one, fam, var, s, "loci")
            l2_cell = ms(l2) if l2 else peer(two, fam, var, s, "loci")
            unk = f" {2 * s:,} |" if lattice else ""
            print(f"| {side}×{side} |{unk} {ms(ez)} |{cols} {lo_cell} | {rt} | {l2_cell} "
                  f"| {t21} |")
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
