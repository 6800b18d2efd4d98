"""The drag benchmark through SolveSpace's Python binding (PyPI `slvs`).

usage: python slvs_drag.py SKETCH SIZE STEPS

SKETCH is `four_bar` (a crank-rocker dragged by its crank through a full turn, beside fully
dimensioned rectangles) or `hinged` (a chain of rigid triangles, the first corner fixed, the
last dragged once round a circle of radius 1): the sketches of loci-bench's `drag` command,
built the same way. The binding has no dragged-parameter list, so each step puts the dragged
point at the target, holds it there with a where-dragged constraint and solves the group.
Prints one JSON object: shapes, first/median/worst step in ms (median and worst after the
first), steps after which a triangle turned over, and steps that did not solve.
"""
import json
import math
import sys
import time

import slvs

G = 2


def point(wp, x, y):
    return slvs.add_point_2d(G, x, y, wp)


def xy(p):
    return [slvs.get_param_value(p["param"][0]), slvs.get_param_value(p["param"][1])]


def line(wp, a, b, length=None):
    l = slvs.add_line_2d(G, a, b, wp)
    if length is not None:
        slvs.distance(G, a, b, length, wp)
    return l


def four_bar(wp, size, steps):
    a, d = point(wp, 0.0, 0.0), point(wp, 4.0, 0.0)
    b, c, e = point(wp, 1.0, 0.0), point(wp, 3.6667, 2.9814), point(wp, 1.588, 2.158)
    slvs.dragged(G, a, wp)
    slvs.dragged(G, d, wp)
    for p, q, v in [(a, b, 1.0), (b, c, 4.0), (d, c, 3.0), (b, e, 2.5), (c, e, 2.5)]:
        line(wp, p, q, v)
    n, k = 10, 0
    while n + 8 <= size:
        x0, y0 = 10.0 + 6.0 * (k % 40), 6.0 * (k // 40)
        q = [point(wp, x0 + ox, y0 + oy) for ox, oy in [(0, 0), (4, 0), (4, 2), (0, 2)]]
        ls = [line(wp, q[i], q[(i + 1) % 4]) for i in range(4)]
        slvs.dragged(G, q[0], wp)
        slvs.horizontal(G, ls[0], wp)
        slvs.horizontal(G, ls[2], wp)
        slvs.vertical(G, ls[1], wp)
        slvs.vertical(G, ls[3], wp)
        slvs.distance(G, q[0], q[1], 4.0, wp)
        slvs.distance(G, q[1], q[2], 2.0, wp)
        n, k = n + 8, k + 1
    path = [[math.cos(2 * math.pi * i / steps), math.sin(2 * math.pi * i / steps)] for i in range(1, steps + 1)]
    return n, b, path, [(b, c, e)]


def hinged(wp, size, steps):
    n = max((size - 1) // 5, 1)
    h = math.sqrt(3) / 2
    corner = point(wp, 0.0, 0.0)
    slvs.dragged(G, corner, wp)
    tris = []
    for i in range(n):
        apex = point(wp, i + 0.5, h if i % 2 == 0 else -h)
        nxt = point(wp, i + 1.0, 0.0)
        line(wp, corner, apex, 1.0)
        line(wp, apex, nxt, 1.0)
        line(wp, corner, nxt, 1.0)
        tris.append((corner, apex, nxt))
        corner = nxt
    end = [float(n), 0.0]
    path = [[end[0] - 1 + math.cos(2 * math.pi * i / steps), end[1] + math.sin(2 * math.pi * i / steps)]
            for i in range(1, steps + 1)]
    return 1 + 5 * n, corner, path, tris


def orientation(t):
    a, b, c = (xy(p) for p in t)
    return math.copysign(1.0, (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))


def main():
    kind, size, steps = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    slvs.clear_sketch()
    wp = slvs.add_base_2d(1)
    shapes, grip, path, tris = (four_bar if kind == "four_bar" else hinged)(wp, size, steps)
    first = slvs.solve_sketch(G, False)
    slvs.dragged(G, grip, wp)
    times, flipped, failed = [], 0, 0
    signs = [orientation(t) for t in tris]
    for target in path:
        t0 = time.perf_counter()
        slvs.set_param_value(grip["param"][0], target[0])
        slvs.set_param_value(grip["param"][1], target[1])
        r = slvs.solve_sketch(G, False)
        times.append((time.perf_counter() - t0) * 1e3)
        failed += r["result"] not in (0, 4)
        now = [orientation(t) for t in tris]
        flipped += any(a != b for a, b in zip(now, signs))
        signs = now
    rest = sorted(times[1:])
    print(json.dumps({"sketch": kind, "shapes": shapes, "steps": steps, "setup_result": first["result"],
                      "first_ms": times[0], "median_ms": rest[len(rest) // 2], "p99_ms": rest[(len(rest) * 99) // 100], "worst_ms": rest[-1],
                      "flipped": flipped, "failed": failed}))


if __name__ == "__main__":
    main()
