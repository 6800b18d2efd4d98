"""Solves many systems through SolveSpace's Python binding (PyPI `slvs`), one after another.

usage: python slvs_batch.py SYSTEMS.txt

SYSTEMS.txt holds systems as libslvs records (loci-bench's slvs::to_records), each headed by
a line `S id`. For each system one line is printed, and flushed at once so that a crash inside
SolveSpace loses only the system it happened on:

    R id result dof | failed constraint handles | param=value ...

with the file's own handles (every parameter of the solved group, whatever the result), or
`X id message` when the binding refuses the input.
"""
import sys

import slvs

POINT_3D, POINT_2D, NORMAL_3D, NORMAL_2D, DISTANCE = 50000, 50001, 60000, 60001, 70000
WORKPLANE, LINE, CUBIC, CIRCLE, ARC = 80000, 80001, 80002, 80003, 80004


def systems(path):
    """Yields (id, group, params, entities, constraints) for each system of the file."""
    cur = None
    with open(path) as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == "S":
                if cur:
                    yield cur
                cur = [t[1], 2, {}, [], []]
            elif t[0] == "G":
                cur[1] = int(t[1])
            elif t[0] == "P":
                cur[2][int(t[1])] = float(t[3])
            elif t[0] == "E":
                cur[3].append([int(x) for x in t[1:]])
            elif t[0] == "C":
                cur[4].append([int(t[1]), int(t[2]), int(t[3]), int(t[4]), float(t[5])]
                              + [int(x) for x in t[6:]])
    if cur:
        yield cur


def solve(group, params, entities, constraints):
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
    ours = {}
    for h, g, typ, wp, val, pa, pb, ea, eb, ec, ed, other, other2 in constraints:
        get = lambda x: ents[x] if x else none
        c = slvs.add_constraint(g, typ, ents[wp], val, get(pa), get(pb), get(ea), get(eb), get(ec), get(ed), other, other2)
        ours[c["h"]] = h
    res, failed = slvs.solve_sketch(group, True)
    values = []
    for h, g, typ, *_rest in entities:
        if g != group:
            continue
        own = [q for q in _rest[-4:] if q]
        for j, ph in enumerate(own):
            values.append((ph, slvs.get_param_value(ents[h]["param"][j])))
    return res, [ours.get(f, 0) for f in failed], values


def main():
    for sid, group, params, entities, constraints in systems(sys.argv[1]):
        try:
            res, failed, values = solve(group, params, entities, constraints)
        except Exception as e:  # the binding refused the input: report and go on
            print(f"X {sid} {type(e).__name__}: {e}".replace("\n", " "), flush=True)
            continue
        fl = " ".join(str(f) for f in failed)
        vs = " ".join(f"{h}={v!r}" for h, v in values)
        print(f"R {sid} {res['result']} {res['dof']} | {fl} | {vs}", flush=True)


if __name__ == "__main__":
    main()
