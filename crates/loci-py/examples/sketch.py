"""A bracket sketched with loci.Sketch: a plate with a rounded end and a hole, dimensioned,
solved, dragged and saved."""

import tempfile
from pathlib import Path

import loci

s = loci.Sketch()

# The outline, drawn roughly: the solver puts it where the dimensions say.
a = s.add_point(0, 0)
b = s.add_point(48, 1)
c = s.add_point(49, 22)
d = s.add_point(1, 19)
bottom = s.add_line(a, b)
right = s.add_line(b, c)
top = s.add_line(c, d)
left = s.add_line(d, a)
hole = s.add_circle((40, 10), 3)

s.fix(a)
s.horizontal(bottom)
s.horizontal(top)
s.vertical(left)
s.vertical(right)
s.length(bottom, 50)
height = s.length(left, 20)
s.diameter(hole, 8)
s.distance(hole.center, b, 12)
s.point_line_distance(hole.center, bottom, -10)  # 10 above the bottom edge

result = s.solve()
print(result)
assert result.ok
for shape in s:
    print(shape)

# A dimension is a property: change it and solve again.
height.value = 30
assert s.solve().ok
print(f"height now {left.length:.3f}")

# An arm hinged at the top right corner: dragging its end swings it about the corner,
# keeping its length (a soft constraint: nothing dimensions it).
arm = s.add_line(c, (70, 30))
step = s.drag(arm.b, (50, 60))
print(step, arm)
assert step.reached and abs(arm.length - 20) < 1e-9

# Every point's coordinates at once, as a NumPy array.
print(s.xy.shape)

with tempfile.TemporaryDirectory() as tmp:
    path = Path(tmp) / "bracket.json"
    s.save(path)
    again = loci.load(path)
    assert isinstance(again, loci.Sketch)
    print(again)
