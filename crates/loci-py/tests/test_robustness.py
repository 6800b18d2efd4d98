"""Bad input never panics across the boundary: every wrong call on every layer raises a
`loci.LociError`, or `TypeError`, `KeyError`, `ValueError`, `OverflowError` (a negative
or huge handle) or `OSError`, never anything else
(a Rust panic would arrive as `pyo3_runtime.PanicException`, a `BaseException`)."""

import itertools
from typing import Any, Callable, List, Tuple

import numpy as np

import loci
import loci.slvs as slvs

OK_ERRORS = (loci.LociError, TypeError, KeyError, ValueError, OverflowError, OSError)

ONE_SHAPE = ["fix", "fix_shape", "horizontal", "vertical", "lock"]
ONE_SHAPE_VALUE = ["length", "radius", "diameter", "arc_sweep"]
TWO_SHAPES = [
    "coincident", "concentric", "parallel", "perpendicular", "equal_length", "equal_radius",
    "point_on_line", "point_on_circle", "midpoint", "collinear", "tangent", "symmetric_axis",
]
TWO_SHAPES_VALUE = ["distance", "angle", "point_line_distance"]
VALUES = (1.0, -1.0, 0.0, float("nan"), float("inf"), 1e300)


class Calls:
    """Makes calls, keeping those that raised anything but a typed error."""

    def __init__(self) -> None:
        self.bad: List[Tuple[Any, ...]] = []

    def __call__(self, f: Callable[..., Any], *a: Any, **k: Any) -> None:
        try:
            f(*a, **k)
        except OK_ERRORS:
            pass
        except BaseException as e:
            self.bad.append((getattr(f, "__name__", f), a, type(e).__name__, str(e)[:100]))


def test_sketch_wrong_calls() -> None:
    attempt = Calls()
    s = loci.Sketch()
    p = s.add_point(0, 0)
    q = s.add_point(3, 4)
    line = s.add_line(p, q)
    circle = s.add_circle((5, 5), 2.0)
    arc = s.add_arc((0, 10), (1, 10), (0, 11))
    cubic = s.add_cubic((0, 0), (1, 1), (2, 1), (3, 0))
    shapes: List[Any] = [p, q, line, circle, arc, cubic, 0, 99999]
    for m in ONE_SHAPE:
        for x in shapes:
            attempt(getattr(s, m), x)
    for m in ONE_SHAPE_VALUE:
        for x in shapes:
            for v in VALUES:
                attempt(getattr(s, m), x, v)
    for m in TWO_SHAPES:
        for x, y in itertools.product(shapes, repeat=2):
            attempt(getattr(s, m), x, y)
    for m in TWO_SHAPES_VALUE:
        for x, y in itertools.product(shapes, repeat=2):
            for v in VALUES:
                attempt(getattr(s, m), x, y, v)
    for x, y, z in itertools.product(shapes, repeat=3):
        attempt(s.symmetric, x, y, z)
    attempt(s.solve)
    for x in shapes:
        attempt(s.drag, x, (1.0, 2.0))
        attempt(s.drag, x, (float("nan"), 0.0))
        attempt(s.drag_path, x, [(1.0, 1.0), (2.0, 2.0)])
    for k in s.constraints:
        attempt(k.measure)
        attempt(setattr, k, "value", -5.0)
        repr(k)
    attempt(s.solve)
    # Remove every shape in turn; shapes and constraints left behind still answer.
    for x in list(s):
        attempt(s.remove, x)
        for y in shapes:
            if not isinstance(y, int):
                repr(y)
                attempt(getattr, y, "constraints")
        attempt(s.solve)
    for k in s.constraints:
        repr(k)
        attempt(k.measure)
    attempt(s.add_constraint, "tangent", a=1, b="x")
    attempt(s.add_constraint, "nope")
    attempt(setattr, s, "xy", np.zeros((3, 3)))
    assert attempt.bad == []


def test_files_system_and_assembly_wrong_calls() -> None:
    attempt = Calls()
    for text in ("[]", '{"sketch": 5}', '{"components": 3}', "", '{"params": [{"h": 0}]}'):
        attempt(loci.loads, text)
    attempt(loci.load, "/nonexistent.json")
    sy = loci.System()
    attempt(sy.add_entity, "line_segment", points=[1, 2, 3])
    attempt(sy.add_entity, "circle", center="x")
    attempt(sy.add_constraint, 5)
    attempt(sy.solve, 1)
    sy.add_param(1.0, group=1)
    attempt(sy.solve, 1, [55])
    attempt(sy.solve, 1, tolerance=-1.0)
    attempt(sy.solve, 1, max_iterations=0)
    attempt(sy.set_values, [1], np.zeros(2))
    attempt(sy.get_values, [-1])
    asm = loci.Assembly()
    attempt(asm.add_mate, "revolute", "a.b", "c.d")
    attempt(asm.solve)
    attempt(asm.solve_stepped)
    asm.add_component("a", rotation=(0, 0, 0, 0))
    attempt(asm.solve)
    attempt(asm.add_component, "b", position=(float("nan"), 0, 0))
    attempt(asm.solve)
    attempt(asm.solve_stepped)
    attempt(setattr, asm, "options", {"max_steps": -1})
    attempt(setattr, asm, "options", {"tolerance": "x"})
    assert attempt.bad == []


def test_slvs_wrong_calls() -> None:
    attempt = Calls()
    slvs.clear_sketch()
    wp = slvs.add_base_2d(1)
    p = slvs.add_point_2d(2, 0, 0, wp)
    q = slvs.add_point_2d(2, 1, 0, wp)
    line = slvs.add_line_2d(2, p, q, wp)
    ghost = dict(p, h=999, param=[998, 997, 0, 0])
    things: List[Any] = [wp, p, q, line, slvs.E_NONE, ghost]
    for x, y in itertools.product(things, repeat=2):
        for f in (slvs.coincident, slvs.equal, slvs.parallel, slvs.tangent, slvs.midpoint):
            attempt(f, 2, x, y, wp)
        attempt(slvs.distance, 2, x, y, 1.0, wp)
        attempt(slvs.add_line_2d, 2, x, y, wp)
    attempt(slvs.add_constraint, 2, 12345, wp, 0.0)
    attempt(slvs.solve_sketch, 2, True)
    attempt(slvs.get_param_value, 0)
    attempt(slvs.set_param_value, 10**9, 1.0)
    assert attempt.bad == []
