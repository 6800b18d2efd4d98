"""A script written for SolveSpace's `slvs` module, run by loci: only the import changes."""

import loci.slvs as slvs  # was: import slvs

slvs.clear_sketch()
g = 1
wp = slvs.add_base_2d(g)
p0 = slvs.add_point_2d(g, 0, 0, wp)
slvs.dragged(g, p0, wp)
p1 = slvs.add_point_2d(g, 90, 0, wp)
slvs.dragged(g, p1, wp)
line0 = slvs.add_line_2d(g, p0, p1, wp)
p2 = slvs.add_point_2d(g, 20, 20, wp)
p3 = slvs.add_point_2d(g, 0, 10, wp)
p4 = slvs.add_point_2d(g, 30, 20, wp)
slvs.distance(g, p2, p3, 40, wp)
slvs.distance(g, p2, p4, 40, wp)
slvs.distance(g, p3, p4, 70, wp)
slvs.distance(g, p0, p3, 35, wp)
slvs.distance(g, p1, p4, 70, wp)
line1 = slvs.add_line_2d(g, p0, p3, wp)
slvs.angle(g, line0, line1, 45, wp, False)

result = slvs.solve_sketch(g, False)
assert isinstance(result, dict)
assert result["result"] == slvs.ResultFlag.OKAY
x = slvs.get_param_value(p2["param"][0])
y = slvs.get_param_value(p2["param"][1])
print(f"crank rocker: p2 = ({x:.5f}, {y:.5f})")  # about (39.5485, 61.9101), as with slvs

# What loci adds: the sketch as a loci.System, to diagnose or save as JSON.
sys = slvs.to_system()
print(sys.check(g))
