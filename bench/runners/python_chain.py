"""The Python-side cost benchmark's runner (`loci-bench python`): builds and solves an
n-segment chain through one Python API and prints one JSON line with the timings.

    python python_chain.py API N REPS

API is `sketch` (loci.Sketch), `slvs` (loci.slvs) or `pypi-slvs` (SolveSpace's own slvs
module). The chain is the one bench/src/python.rs builds in Rust: points P0..Pn with P0
fixed, segment 0 horizontal, every segment's length given and every segment perpendicular to
the next: a staircase, unique near the start. Each repetition builds and solves afresh; the best
build and the best solve are reported, with the largest constraint error and where Pn ends.
"""

import json
import math
import sys
import time


def exact_points(n):
    """The answer: a staircase whose even segments run along +x (5, 6 or 7 long) and odd
    ones along +y or -y (3 or 4 long, up then down, so it stays near the x axis)."""
    pts = [(0.0, 0.0)]
    x = y = 0.0
    for i in range(n):
        if i % 2 == 0:
            x += 5.0 + (i // 2) % 3
        else:
            y += (3.0 + (i // 2) % 2) * (1 if (i // 2) % 2 == 0 else -1)
        pts.append((x, y))
    return pts


def start_points(n):
    """Where the chain starts: every point but the first moved by up to 0.25."""
    return [
        (x + 0.25 * math.sin(1.3 * k), y + 0.25 * math.cos(0.7 * k)) if k else (x, y)
        for k, (x, y) in enumerate(exact_points(n))
    ]


def dist(a, b):
    return math.hypot(a[0] - b[0], a[1] - b[1])


def lengths(n):
    pts = exact_points(n)
    return [dist(pts[i], pts[i + 1]) for i in range(n)]


def run_sketch(n):
    import loci

    seg, at = lengths(n), start_points(n)
    t0 = time.perf_counter()
    s = loci.Sketch()
    pts = [s.add_point(x, y) for x, y in at]
    lines = [s.add_line(pts[i], pts[i + 1]) for i in range(n)]
    s.fix(pts[0])
    s.horizontal(lines[0])
    for i in range(n):
        s.length(lines[i], seg[i])
    for i in range(1, n):
        s.perpendicular(lines[i - 1], lines[i])
    t1 = time.perf_counter()
    r = s.solve()
    t2 = time.perf_counter()
    xy = s.xy  # every point at once, in the order added
    coords = [(float(x), float(y)) for x, y in xy]
    return t1 - t0, t2 - t1, r.outcome, coords


def run_slvs(n, slvs):
    seg, at = lengths(n), start_points(n)
    t0 = time.perf_counter()
    slvs.clear_sketch()
    wp = slvs.add_base_2d(1)
    g = 2
    pts = [slvs.add_point_2d(g, x, y, wp) for x, y in at]
    lines = [slvs.add_line_2d(g, pts[i], pts[i + 1], wp) for i in range(n)]
    slvs.dragged(g, pts[0], wp)
    slvs.horizontal(g, lines[0], wp)
    for i in range(n):
        slvs.distance(g, pts[i], pts[i + 1], seg[i], wp)
    for i in range(1, n):
        slvs.perpendicular(g, lines[i - 1], lines[i], wp)
    t1 = time.perf_counter()
    r = slvs.solve_sketch(g, False)
    t2 = time.perf_counter()
    flag = r["result"]
    outcome = {0: "okay", 1: "inconsistent", 2: "did_not_converge", 3: "too_many_unknowns",
               4: "redundant_okay"}.get(int(flag), str(flag))
    v = slvs.get_param_value
    coords = [(v(p["param"][0]), v(p["param"][1])) for p in pts]
    return t1 - t0, t2 - t1, outcome, coords


def main():
    api, n, reps = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    if api == "sketch":
        run = run_sketch
    elif api == "slvs":
        import loci.slvs as mod

        def run(n):
            return run_slvs(n, mod)
    elif api == "pypi-slvs":
        import slvs as theirs

        def run(n):
            return run_slvs(n, theirs)
    else:
        raise SystemExit(f"unknown API {api}")
    best_build = best_solve = float("inf")
    for _ in range(reps):
        build, solve, outcome, coords = run(n)
        best_build, best_solve = min(best_build, build), min(best_solve, solve)
    seg = lengths(n)

    def dot(i):
        a, b, c = coords[i - 1], coords[i], coords[i + 1]
        u, v = (b[0] - a[0], b[1] - a[1]), (c[0] - b[0], c[1] - b[1])
        return abs(u[0] * v[0] + u[1] * v[1]) / (math.hypot(*u) * math.hypot(*v))

    err = max(
        [abs(dist(coords[i], coords[i + 1]) - seg[i]) for i in range(n)]
        + [dot(i) for i in range(1, n)]
        + [abs(coords[1][1] - coords[0][1])]
    )
    print(json.dumps({
        "api": api, "n": n, "build_s": best_build, "solve_s": best_solve,
        "outcome": outcome, "max_error": err, "end": coords[-1],
    }))


if __name__ == "__main__":
    main()
