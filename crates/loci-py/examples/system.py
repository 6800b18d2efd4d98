"""The SolveSpace model with loci.System: groups, handles, a conflict named, NumPy values."""

import numpy as np

import loci

s = loci.System()
wp = s.add_xy_workplane(group=1)  # group 1: constants
a = s.add_point_2d(1.0, 2.0, workplane=wp, group=2)
b = s.add_point_2d(9.0, 3.0, workplane=wp, group=2)
s.add_constraint("pt_pt_distance", group=2, workplane=wp, pt_a=a, pt_b=b, value=10.0)
s.add_constraint("horizontal", group=2, workplane=wp, pt_a=a, pt_b=b)

r = s.solve(2, dragged=s.entity(a)["params"])
print(r)
assert r.ok

extra = s.add_constraint("pt_pt_distance", group=2, workplane=wp, pt_a=a, pt_b=b, value=12.0)
bad = s.solve(2)
print(bad)  # inconsistent: a result, not an exception
assert not bad.ok and extra in bad.failed
print(s.check(2))
s.remove_constraint(extra)

values: np.ndarray = s.values
s.values = values + 0.5
assert s.solve(2).ok
print(dict(zip(s.param_handles.tolist(), s.values.round(6).tolist())))

try:
    s.solve(9)
except loci.SolveError as e:
    print("SolveError:", e)
