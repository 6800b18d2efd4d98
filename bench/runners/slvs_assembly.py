"""The assembly benchmark's revolute chain through SolveSpace's Python binding (PyPI `slvs`).

usage: python slvs_assembly.py START.json REPS OUT.json

The same chain as loci-bench's: link 0 fixed, each link a pivot point, a tip point one unit
away and a hinge normal, written as 3D points, normals and constraints (SolveSpace's library
has no rigid parts): the tip is 1 from the pivot and the link normal to its hinge; each
joint holds the pivot on the previous tip (coincident), the hinges parallel (each link normal
to the other's hinge) and 30 degrees between the links. START.json holds loci's starting pose of every link (`[tx, ty, tz, w, x, y, z]`
per link, link 0 at the answer): the pivot, tip and hinge start where that pose puts them.
OUT.json receives {result, dof, solve_ms, build_ms, residual}.
"""
import json
import sys
import time

import slvs

COINCIDENT, PT_PT_DISTANCE, ANGLE, PARALLEL, PERPENDICULAR = 100000, 100001, 100024, 100025, 100026


def rotate(q, v):
    w, x, y, z = q
    u = (x, y, z)
    t = (2 * (u[1] * v[2] - u[2] * v[1]), 2 * (u[2] * v[0] - u[0] * v[2]), 2 * (u[0] * v[1] - u[1] * v[0]))
    c = (u[1] * t[2] - u[2] * t[1], u[2] * t[0] - u[0] * t[2], u[0] * t[1] - u[1] * t[0])
    return tuple(v[i] + w * t[i] + c[i] for i in range(3))


def build(poses):
    slvs.clear_sketch()
    free = slvs.E_FREE_IN_3D
    none = slvs.E_NONE
    links = []
    for i, pose in enumerate(poses):
        g = 1 if i == 0 else 2
        at, q = pose[:3], pose[3:]
        arm = rotate(q, (1.0, 0.0, 0.0))
        p = slvs.add_point_3d(g, *at)
        t = slvs.add_point_3d(g, *(at[k] + arm[k] for k in range(3)))
        nrm = slvs.add_normal_3d(g, *q)
        line = slvs.add_line_3d(g, p, t)
        if i > 0:
            slvs.add_constraint(2, PT_PT_DISTANCE, free, 1.0, p, t)
            slvs.add_constraint(2, PERPENDICULAR, free, 0.0, none, none, line, nrm)
            pl, pt, pn = links[-1]
            slvs.add_constraint(2, COINCIDENT, free, 0.0, pt, p)
            # Hinges parallel, written as each link normal to the other's hinge (the two links
            # are 30 degrees apart, so this holds exactly when the hinges are parallel):
            # SolveSpace's parallel on two free normals reported itself inconsistent.
            slvs.add_constraint(2, PERPENDICULAR, free, 0.0, none, none, line, pn)
            slvs.add_constraint(2, PERPENDICULAR, free, 0.0, none, none, pl, nrm)
            slvs.add_constraint(2, ANGLE, free, 30.0, none, none, pl, line)
        links.append((line, t, nrm))
    return links


def main():
    start, reps, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    with open(start) as f:
        poses = json.load(f)
    best_solve, best_build, res = float("inf"), float("inf"), None
    for _ in range(reps):
        t0 = time.perf_counter()
        build(poses)
        t1 = time.perf_counter()
        res = slvs.solve_sketch(2, False)
        t2 = time.perf_counter()
        best_build = min(best_build, (t1 - t0) * 1e3)
        best_solve = min(best_solve, (t2 - t1) * 1e3)
    with open(out, "w") as f:
        json.dump({"result": res["result"], "dof": res["dof"], "solve_ms": best_solve, "build_ms": best_build}, f)


if __name__ == "__main__":
    main()
