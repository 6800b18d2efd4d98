"""The assembly benchmark's revolute chain through CadQuery's assembly solver (PyPI `cadquery`).

usage: python cadquery_assembly.py START.json REPS OUT.json

The same chain as loci-bench's: link 0 fixed, each link carrying a pivot vertex at its origin,
a tip vertex one unit along its x axis, a hinge edge along its z axis and an arm edge along
its x axis; each joint is CadQuery's `Point` constraint (tip on the next pivot), an `Axis`
constraint of 0 degrees (hinges parallel) and an `Axis` constraint of 30 degrees (arms).
START.json holds loci's starting pose of every link (`[tx, ty, tz, w, x, y, z]` per link, link
0 at the answer), given to CadQuery as each part's location. Only `Assembly.solve()` is timed
(it builds and runs CadQuery's IPOPT problem). The answer is then measured the same way as
loci's: the largest pivot gap, and the largest hinge and arm angle errors in degrees.
OUT.json receives {status, solve_ms, build_ms, pivot_gap, hinge_deg, arm_deg}.
"""
import json
import math
import sys
import time

import cadquery as cq
from OCP.gp import gp_Quaternion, gp_Trsf, gp_Vec


def location(pose):
    t = gp_Trsf()
    w, x, y, z = pose[3:]
    t.SetRotation(gp_Quaternion(x, y, z, w))
    t.SetTranslationPart(gp_Vec(*pose[:3]))
    return cq.Location(t)


def build(poses):
    pivot = cq.Vertex.makeVertex(0, 0, 0)
    tip = cq.Vertex.makeVertex(1, 0, 0)
    hinge = cq.Edge.makeLine(cq.Vector(0, 0, 0), cq.Vector(0, 0, 1))
    arm = cq.Edge.makeLine(cq.Vector(0, 0, 0), cq.Vector(1, 0, 0))
    part = cq.Compound.makeCompound([pivot, tip, hinge, arm])
    assy = cq.Assembly()
    for i, pose in enumerate(poses):
        assy.add(part, name=f"link{i}", loc=location(pose))
    assy.constrain("link0", "Fixed")
    for i in range(1, len(poses)):
        a, b = f"link{i - 1}", f"link{i}"
        assy.constrain(a, tip, b, pivot, "Point")
        assy.constrain(a, hinge, b, hinge, "Axis", 0)
        assy.constrain(a, arm, b, arm, "Axis", 30)
    return assy


def measure(assy, n):
    def world(i, p):
        return assy.children[i].loc * cq.Location(cq.Vector(*p))

    def point(i, p):
        v = world(i, p).toTuple()[0]
        return v

    def direction(i, d):
        o, e = point(i, (0, 0, 0)), point(i, d)
        return [e[k] - o[k] for k in range(3)]

    def angle(u, v):
        c = sum(u[k] * v[k] for k in range(3)) / math.sqrt(sum(x * x for x in u) * sum(x * x for x in v))
        return math.degrees(math.acos(max(-1.0, min(1.0, c))))

    gap = hinge = arm = 0.0
    for i in range(1, n):
        t, p = point(i - 1, (1, 0, 0)), point(i, (0, 0, 0))
        gap = max(gap, math.dist(t, p))
        hinge = max(hinge, angle(direction(i - 1, (0, 0, 1)), direction(i, (0, 0, 1))))
        arm = max(arm, abs(angle(direction(i - 1, (1, 0, 0)), direction(i, (1, 0, 0))) - 30.0))
    return gap, hinge, arm


def main():
    start, reps, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    with open(start) as f:
        poses = json.load(f)
    best_solve, best_build, status, measured = float("inf"), float("inf"), "ok", (math.nan,) * 3
    for _ in range(reps):
        t0 = time.perf_counter()
        assy = build(poses)
        t1 = time.perf_counter()
        try:
            assy.solve()
        except Exception as e:  # CadQuery raises on a failed IPOPT run
            status = f"error: {type(e).__name__}: {e}"[:200]
        t2 = time.perf_counter()
        best_build = min(best_build, (t1 - t0) * 1e3)
        best_solve = min(best_solve, (t2 - t1) * 1e3)
        if status == "ok":
            measured = measure(assy, len(poses))
    gap, hinge, arm = measured
    with open(out, "w") as f:
        json.dump(
            {"status": status, "solve_ms": best_solve, "build_ms": best_build,
             "pivot_gap": gap, "hinge_deg": hinge, "arm_deg": arm},
            f,
        )


if __name__ == "__main__":
    main()
