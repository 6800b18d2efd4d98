"""``loci.Sketch``: shapes, user and soft constraints, dragging, files."""

import math
import threading
from pathlib import Path

import numpy as np
import pytest

import loci


def test_line_of_given_length_horizontal() -> None:
    s = loci.Sketch()
    a = s.add_point(0, 0)
    b = s.add_point(9, 1)
    line = s.add_line(a, b)
    s.fix(a)
    s.horizontal(line)
    s.length(line, 10)
    r = s.solve()
    assert r.ok and r.failed == [] and r.residual <= 1e-9
    (p, q) = line.coords
    assert p + q == pytest.approx((0, 0, 10, 0), abs=1e-9)
    assert line.length == pytest.approx(10, abs=1e-12)
    assert b.xy == pytest.approx((10, 0), abs=1e-9)
    assert (b.x, b.y) == b.xy
    assert line.a == a and line.b == b and hash(line.a) == hash(a)
    assert repr(b) == "Point(#101, x=10.000000, y=0.000000)"


def test_iteration_over_shapes_and_constraints() -> None:
    s = loci.Sketch()
    line = s.add_line((0, 0), (4, 0))
    c = s.add_circle((2, 3), 1.5)
    arc = s.add_arc((0, 5), (1, 5), (0, 6))
    kinds = [sh.kind for sh in s]
    assert kinds == ["point", "point", "line", "point", "circle", "point", "point", "point", "arc"]
    assert len(s) == 9 and len(s.points) == 6
    k1 = s.horizontal(line)
    k2 = s.radius(c, 2.0)
    assert s.constraints == [k1, k2]
    assert k2.type == "radius" and k2.value == 2.0 and not k2.reference
    assert [f for f, _ in k2.shapes] == ["shape"]
    assert c.constraints == [k2]
    assert arc.radius == pytest.approx(1.0) and arc.sweep == pytest.approx(90.0)
    assert isinstance(arc.center, loci.Point) and arc.start.xy == (1, 5)


def test_soft_constraints_keep_lengths_the_user_did_not_set() -> None:
    s = loci.Sketch()
    a = s.add_point(0, 0)
    b = s.add_point(3, 4)
    line = s.add_line(a, b)
    s.fix(a)
    assert s.soft_constraints == [("line_length", line.handle)]
    b.xy = (6, 8)
    s.horizontal(line)
    r = s.solve()
    assert r.ok and r.kept == [("line_length", line.handle)]
    assert line.length == pytest.approx(10.0, abs=1e-9)
    assert b.xy == pytest.approx((10, 0), abs=1e-9)


def test_value_edit_and_measure() -> None:
    s = loci.Sketch()
    line = s.add_line((0, 0), (5, 0))
    s.fix(line.a)
    s.horizontal(line)
    k = s.length(line, 5)
    ref = s.length(line, 1.0, reference=True)
    assert s.solve().ok
    k.value = 7.5
    assert k.value == 7.5
    assert k.measure() == (pytest.approx(5.0), pytest.approx(2.5))
    assert s.solve().ok
    assert line.length == pytest.approx(7.5, abs=1e-9)
    assert ref.reference and ref.measure()[0] == pytest.approx(7.5, abs=1e-9)


def test_conflict_is_a_result_naming_the_user_constraints() -> None:
    s = loci.Sketch()
    line = s.add_line((0, 0), (5, 1))
    s.fix(line.a)
    h = s.horizontal(line)
    v = s.vertical(line)
    k = s.length(line, 5)
    r = s.solve()
    assert not r.ok and r.outcome == "inconsistent"
    # Horizontal and vertical together make the line a point, which its length forbids.
    assert sorted(r.failed) == sorted([h.id, v.id, k.id])
    assert line.coords == ((0, 0), (5, 1))
    # The diagnosis names core constraints; each maps back to the user constraint that wrote it.
    d = s.check()
    assert d.outcome == "inconsistent"
    named = {s.constraint_of(c) for conflict in d.conflicting for c in conflict}
    assert named == {h, v, k}
    assert s.constraint_of(10_000) is None


def test_drag_moves_the_free_end_on_its_circle() -> None:
    s = loci.Sketch()
    a = s.add_point(0, 0)
    b = s.add_point(5, 0)
    crank = s.add_line(a, b)
    s.fix(a)
    s.length(crank, 5)
    assert s.solve().ok
    step = s.drag(b, (0, 10))
    assert step.outcome == "okay" and step.reached
    assert b.xy == pytest.approx((0, 5), abs=1e-6)
    assert crank.length == pytest.approx(5, abs=1e-9)
    path = [(5 * math.cos(t), 5 * math.sin(t)) for t in np.linspace(1.6, 3.0, 8)]
    steps = s.drag_path(b, path)
    assert len(steps) == 8 and all(st.reached for st in steps)
    assert b.xy == pytest.approx(path[-1], abs=1e-6)


def test_errors() -> None:
    s = loci.Sketch()
    p = s.add_point(0, 0)
    c = s.add_circle((1, 1), 1.0)
    with pytest.raises(loci.ModelError, match="line"):
        s.horizontal(c)
    with pytest.raises(loci.ModelError):
        s.length(p, float("nan"))
    with pytest.raises(TypeError):
        s.horizontal("not a shape")  # type: ignore[arg-type]
    removed_shapes, _ = s.remove(c)
    assert c.handle in removed_shapes
    with pytest.raises(loci.ModelError, match="not a circle"):
        c.radius
    assert "removed" in repr(c)


def test_numpy_coordinates() -> None:
    s = loci.Sketch()
    for i in range(1000):
        s.add_point(float(i), 0.0)
    xy = s.xy
    assert xy.shape == (1000, 2) and xy[999, 0] == 999.0
    s.xy = xy + np.array([0.0, 1.0])
    assert s.points[5].xy == (5.0, 1.0)


def test_four_bar_file(examples: Path, tmp_path: Path) -> None:
    s = loci.load(examples / "sketches" / "four_bar.json")
    assert isinstance(s, loci.Sketch)
    assert s.solve().ok
    crank = s["crank"]
    assert isinstance(crank, loci.Line) and crank.length == pytest.approx(1.0, abs=1e-9)
    assert s["coupler"].length == pytest.approx(4.0, abs=1e-9)
    assert s.constraint("#3").value == 1
    f = tmp_path / "out.json"
    s.save(f)
    t = loci.load(f)
    assert isinstance(t, loci.Sketch)
    assert np.allclose(t.xy, s.xy)
    assert t["rocker"].length == pytest.approx(3.0, abs=1e-9)


def test_system_and_check() -> None:
    s = loci.Sketch()
    line = s.add_line((0, 0), (5, 0))
    s.fix(line.a)
    s.horizontal(line)
    d = s.check()
    assert d.dof == 1
    sys = s.system
    assert isinstance(sys, loci.System) and sys.groups == [1, 2]


def test_the_gil_is_released_while_a_solve_runs() -> None:
    # A 20,000-segment staircase (the Python benchmark's chain) takes tens of milliseconds to
    # solve. While it does, the main thread keeps running Python code: it ticks all through
    # the middle half of the solve. Were the GIL held during the solve, no tick could fall
    # there (the solving thread would hold it from the call to the return).
    import sys
    import time

    n = 20_000
    exact = [(0.0, 0.0)]
    for i in range(n):
        x, y = exact[-1]
        exact.append((x + 5.0, y) if i % 2 == 0 else (x, y + (3.0 if (i // 2) % 2 == 0 else -3.0)))
    s = loci.Sketch()
    pts = [
        s.add_point(x + (0.25 * math.sin(1.3 * k) if k else 0.0), y + (0.25 * math.cos(0.7 * k) if k else 0.0))
        for k, (x, y) in enumerate(exact)
    ]
    lines = [s.add_line(pts[i], pts[i + 1]) for i in range(n)]
    s.fix(pts[0])
    s.horizontal(lines[0])
    for i in range(n):
        s.length(lines[i], 5.0 if i % 2 == 0 else 3.0)
    for i in range(1, n):
        s.perpendicular(lines[i - 1], lines[i])
    window: "list[float]" = []

    def solve() -> None:
        window.append(time.perf_counter())
        s.solve()
        window.append(time.perf_counter())

    old = sys.getswitchinterval()
    sys.setswitchinterval(1e-4)
    try:
        worker = threading.Thread(target=solve)
        ticks: "list[float]" = []
        worker.start()
        while worker.is_alive():
            ticks.append(time.perf_counter())
        worker.join()
    finally:
        sys.setswitchinterval(old)
    t0, t1 = window
    assert t1 - t0 > 0.002, f"the solve took {t1 - t0:.4f} s: too short to tell"
    lo, hi = t0 + 0.25 * (t1 - t0), t1 - 0.25 * (t1 - t0)
    inside = sum(1 for t in ticks if lo < t < hi)
    assert inside >= 10, f"{inside} ticks in the middle of a {t1 - t0:.3f} s solve"
