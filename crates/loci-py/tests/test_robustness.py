"""Bad input never panics across the boundary: every wrong call on every layer raises a
`loci.LociError`, or `TypeError`, `KeyError`, `ValueError`, `OSError`, never anything else."""

import itertools
from typing import Any, Callable, List, Tuple

import loci

OK_ERRORS = (loci.LociError, TypeError, KeyError, ValueError, OSError)


def test_wrong_calls_raise_typed_errors() -> None:
    bad: List[Tuple[Any, ...]] = []

    def attempt(f: Callable[..., Any], *a: Any, **k: Any) -> None:
        try:
            f(*a, **k)
        except OK_ERRORS:
            pass
        except BaseException as e:  # a PanicException is a BaseException
            bad.append((getattr(f, "__name__", f), a, type(e).__name__, str(e)[:100]))

    s = loci.Sketch()
    p = s.add_point(0, 0); q = s.add_point(3, 4); r = s.add_point(5, 5)
    l = s.add_line(p, q); c = s.add_circle(r, 2.0); a = s.add_arc((0, 10), (1, 10), (0, 11))
    cu = s.add_cubic((0, 0), (1, 1), (2, 1), (3, 0))
    shapes = [p, q, l, c, a, cu, 0, 99999]
    one = ["fix", "fix_shape", "horizontal", "vertical", "lock"]
    onev = ["length", "radius", "diameter", "arc_sweep"]
    two = ["coincident", "concentric", "parallel", "perpendicular", "equal_length", "equal_radius",
           "point_on_line", "point_on_circle", "midpoint", "collinear", "tangent", "symmetric_axis"]
    twov = ["distance", "angle", "point_line_distance"]
    for m in one:
        for x in shapes: attempt(getattr(s, m), x)
    for m in onev:
        for x in shapes:
            for v in (1.0, -1.0, 0.0, float('nan'), 1e300): attempt(getattr(s, m), x, v)
    for m in two:
        for x, y in itertools.product(shapes, repeat=2): attempt(getattr(s, m), x, y)
    for m in twov:
        for x, y in itertools.product(shapes, repeat=2):
            for v in (1.0, 0.0, float('inf')): attempt(getattr(s, m), x, y, v)
    for x, y, z in itertools.product(shapes, repeat=3): attempt(s.symmetric, x, y, z)
    attempt(s.solve)
    for x in shapes:
        attempt(s.drag, x, (1.0, 2.0)); attempt(s.drag, x, (float('nan'), 0.0))
        attempt(s.drag_path, x, [(1.0, 1.0), (2.0, 2.0)])
    for k in s.constraints:
        attempt(lambda k=k: k.measure()); attempt(lambda k=k: setattr(k, 'value', -5.0)); repr(k)
    attempt(s.solve)
    for x in list(s):
        attempt(s.remove, x)
        for y in shapes:
                if not isinstance(y, int):
                    repr(y)
        attempt(s.solve)
    for k in s.constraints: repr(k); attempt(k.measure)
    attempt(s.add_constraint, "tangent", a=1, b="x")
    attempt(s.add_constraint, "nope")
    attempt(loci.loads, "[]"); attempt(loci.loads, '{"sketch": 5}'); attempt(loci.loads, '{"components": 3}')
    attempt(loci.load, "/nonexistent.json")
    sy = loci.System()
    attempt(sy.add_entity, "line_segment", points=[1, 2, 3])
    attempt(sy.add_constraint, 5)
    attempt(sy.solve, 1)
    sy.add_param(1.0, group=1)
    attempt(sy.solve, 1, [55])
    attempt(sy.solve, 1, tolerance=-1.0)
    attempt(sy.solve, 1, max_iterations=0)
    attempt(sy.set_values, [1], __import__('numpy').zeros(2))
    asm = loci.Assembly()
    attempt(asm.add_mate, "revolute", "a.b", "c.d")
    attempt(asm.solve); attempt(asm.solve_stepped)
    asm.add_component("a", rotation=(0, 0, 0, 0))
    attempt(asm.solve)
    attempt(asm.add_component, "b", position=(float('nan'), 0, 0))
    attempt(asm.solve); attempt(asm.solve_stepped)
    attempt(setattr, asm, "options", {"max_steps": -1})
    assert bad == []

