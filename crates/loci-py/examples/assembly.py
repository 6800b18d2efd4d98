"""A door on a hinge, opened 60 degrees, with loci.Assembly."""

import loci

AXIS = {"type": "axis", "point": [0, 0, 0], "direction": [0, 0, 1]}
FACE = {"type": "face", "point": [0, 0, 0], "normal": [1, 0, 0]}

asm = loci.Assembly()
asm.add_component("frame", grounded=True, references={"hinge": AXIS, "jamb": FACE})
asm.add_component("door", position=(0.2, 0.1, 0.0), references={"hinge": AXIS, "face": FACE})
asm.add_mate("revolute", "frame.hinge", "door.hinge", id="hinge")

# With only the hinge, the door turns freely: one degree of freedom.
free = asm.solve()
print(free)
for c in free.components:
    print(c["name"], c["dof"], c["motions"])
assert free.dof == 1

asm.add_mate("angle", "frame.jamb", "door.face", value=60.0, id="open")
result = asm.solve()
print(result)
assert result.ok and result.dof == 0
translation, rotation = asm.pose("door")
print("door at", translation, "turned by", rotation)
print("measured angle:", asm.measure_angle("open"))

# The stepped mode moves one mate at a time, for animation.
converged, iterations = asm.solve_stepped()
print("stepped:", converged, len(iterations), "passes")
