"""Runs one benchmark problem through SolveSpace's Python binding (PyPI `slvs`).

usage: python slvs_runner.py PROBLEM.txt REPS BUDGET_S OUT.json

PROBLEM.txt holds libslvs records (see loci-bench's slvs::to_records). Each repetition clears
the sketch and adds every entity and constraint through the binding (timed as the build), then
calls solve_sketch (timed as the solve); repetitions stop early once the solves add up to
BUDGET_S seconds. OUT.json receives {status, detail, build_ms, solve_ms, points}.
"""
import json
import sys
import time

import slvs

POINT_3D, POINT_2D, NORMAL_3D, NORMAL_2D, DISTANCE = 50000, 50001, 60000, 60001, 70000
WORKPLANE, LINE, CUBIC, CIRCLE, ARC = 80000, 80001, 80002, 80003, 80004


def read(path):
    params, entities, constraints, out, group = {}, [], [], [], 2
    with open(path) as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == "G":
                group = int(t[1])
            elif t[0] == "P":
                params[int(t[1])] = float(t[3])
            elif t[0] == "E":
                entities.append([int(x) for x in t[1:]])
            elif t[0] == "C":
                constraints.append([int(t[1]), int(t[2]), int(t[3]), int(t[4]), float(t[5])] + [int(x) for x in t[6:]])
            elif t[0] == "O":
                out = [int(x) for x in t[1:]]
    return params, entities, constraints, out, group


def build(params, entities, constraints):
    """Adds everything through the binding; returns our entity handle -> binding entity."""
    slvs.clear_sketch()
    ents = {0: slvs.E_FREE_IN_3D}
    for h, g, typ, wp, p0, p1, p2, p3, nm, dist, q0, q1, q2, q3 in entities:
        w = ents[wp]
        if typ == POINT_3D:
            e = slvs.add_point_3d(g, params[q0], params[q1], params[q2])
        elif typ == POINT_2D:
            e = slvs.add_point_2d(g, params[q0], params[q1], w)
        elif typ == NORMAL_3D:
            e = slvs.add_normal_3d(g, params[q0], params[q1], params[q2], params[q3])
        elif typ == NORMAL_2D:
            e = slvs.add_normal_2d(g, w)
        elif typ == DISTANCE:
            e = slvs.add_distance(g, params[q0], w)
        elif typ == WORKPLANE:
            e = slvs.add_workplane(g, ents[p0], ents[nm])
        elif typ == LINE:
            e = slvs.add_line_3d(g, ents[p0], ents[p1]) if wp == 0 else slvs.add_line_2d(g, ents[p0], ents[p1], w)
        elif typ == ARC:
            e = slvs.add_arc(g, ents[nm], ents[p0], ents[p1], ents[p2], w)
        elif typ == CIRCLE:
            e = slvs.add_circle(g, ents[nm], ents[p0], ents[dist], w)
        else:
            raise ValueError(f"entity type {typ} not supported by this runner")
        ents[h] = e
    none = slvs.E_NONE
    for h, g, typ, wp, val, pa, pb, ea, eb, ec, ed, other, other2 in constraints:
        get = lambda x: ents[x] if x else none
        slvs.add_constraint(g, typ, ents[wp], val, get(pa), get(pb), get(ea), get(eb), get(ec), get(ed), other, other2)
    return ents


def main():
    path, reps, budget, out_path = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
    params, entities, constraints, out, group = read(path)
    build_ms, solve_ms, spent, res, ents = [], [], 0.0, None, {}
    for _ in range(reps):
        t0 = time.perf_counter()
        ents = build(params, entities, constraints)
        t1 = time.perf_counter()
        res, _failed = slvs.solve_sketch(group, True)
        t2 = time.perf_counter()
        build_ms.append((t1 - t0) * 1e3)
        solve_ms.append((t2 - t1) * 1e3)
        spent += t2 - t1
        if spent > budget:
            break
    code = res["result"]
    status, detail = {
        0: ("ok", "okay"),
        1: ("failed", "inconsistent"),
        2: ("failed", "did not converge"),
        3: ("refused", "too many unknowns"),
        4: ("ok", "redundant okay"),
    }.get(code, ("failed", f"result {code}"))
    points = []
    for h in out:
        e = ents[h]
        n = 3 if e["type"] == POINT_3D else 2
        xyz = [slvs.get_param_value(e["param"][j]) for j in range(n)]
        points.append(xyz + [0.0] * (3 - n))
    with open(out_path, "w") as f:
        json.dump({"status": status, "detail": f"{detail} (dof {res['dof']})", "build_ms": build_ms,
                   "solve_ms": solve_ms, "points": points}, f)


if __name__ == "__main__":
    main()
