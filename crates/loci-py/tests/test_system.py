"""``loci.System``: the SolveSpace model from Python."""

import math
import threading
from pathlib import Path

import numpy as np
import pytest

import loci


def two_points(d: float = 10.0) -> "tuple[loci.System, int, int, int]":
    s = loci.System()
    wp = s.add_xy_workplane(group=1)
    a = s.add_point_2d(1.0, 2.0, workplane=wp, group=2)
    b = s.add_point_2d(9.0, 3.0, workplane=wp, group=2)
    s.add_constraint("pt_pt_distance", group=2, workplane=wp, pt_a=a, pt_b=b, value=d)
    s.add_constraint("horizontal", group=2, workplane=wp, pt_a=a, pt_b=b)
    return s, wp, a, b


def xy(s: loci.System, e: int) -> "tuple[float, float]":
    u, v = s.entity(e)["params"]
    return s.value(u), s.value(v)


def test_solve_reaches_the_constraints_and_reads_back() -> None:
    s, wp, a, b = two_points()
    r = s.solve(2)
    assert r.ok and r.outcome == "okay" and bool(r)
    assert r.dof == 2 and r.failed == [] and r.residual <= 1e-9
    (x1, y1), (x2, y2) = xy(s, a), xy(s, b)
    assert abs(x2 - x1) == pytest.approx(10.0, abs=1e-9)
    assert y1 == pytest.approx(y2, abs=1e-12)
    assert "SolveResult(group=2, outcome=\"okay\", dof=2" in repr(r)


def test_perturbed_start_comes_back_and_satisfied_start_stays() -> None:
    s, wp, a, b = two_points()
    s.solve(2)
    before = s.values.copy()
    again = s.solve(2)
    assert again.ok and again.iterations <= 1
    assert np.array_equal(s.values, before)
    pu = s.entity(b)["params"][1]
    s.set_value(pu, s.value(pu) + 0.7)
    assert s.solve(2).ok
    (x1, y1), (x2, y2) = xy(s, a), xy(s, b)
    assert math.hypot(x2 - x1, y2 - y1) == pytest.approx(10.0, abs=1e-9)
    assert y1 == pytest.approx(y2, abs=1e-12)


def test_dragged_parameters_move_least() -> None:
    s, wp, a, b = two_points()
    pa = s.entity(a)["params"]
    r = s.solve(2, dragged=pa)
    assert r.ok
    ax, ay = xy(s, a)
    bx, by = xy(s, b)
    moved_a = math.hypot(ax - 1.0, ay - 2.0)
    moved_b = math.hypot(bx - 9.0, by - 3.0)
    assert moved_a < 0.01 * moved_b
    assert bx - ax == pytest.approx(10.0, abs=1e-9) and by == pytest.approx(ay, abs=1e-12)


def test_inconsistent_is_a_result_naming_the_conflict() -> None:
    s, wp, a, b = two_points()
    c = s.add_constraint("pt_pt_distance", group=2, workplane=wp, pt_a=a, pt_b=b, value=12.0)
    start = s.values.copy()
    r = s.solve(2)
    assert not r.ok and r.outcome == "inconsistent"
    assert sorted(r.failed) == [1, c]
    assert np.array_equal(s.values, start)
    d = s.check(2)
    assert d.outcome == "inconsistent" and d.conflicting == [[c, 1]]
    assert d.to_dict()["conflicting"][0]["verified"] is True
    assert "conflicting=[[3, 1]]" in repr(d)


def test_check_counts_freedom_and_redundancy() -> None:
    s, wp, a, b = two_points()
    s.add_constraint("horizontal", group=2, workplane=wp, pt_a=a, pt_b=b)
    d = s.check(2)
    assert d.ok and d.outcome == "redundant_okay"
    assert d.dof == 2 and d.unknowns == 4 and d.rank == 2
    assert d.redundant == [[3, 2]]


def test_errors_are_typed_and_name_the_object() -> None:
    assert issubclass(loci.ModelError, loci.LociError)
    assert issubclass(loci.SolveError, loci.LociError)
    assert issubclass(loci.FileError, loci.LociError)
    s, wp, a, b = two_points()
    with pytest.raises(loci.SolveError, match="group 7 does not exist"):
        s.solve(7)
    s.add_constraint("pt_pt_distance", group=2, workplane=wp, pt_a=a, pt_b=999, value=1)
    with pytest.raises(loci.ModelError, match="constraint 3: pt_b refers to entity 999"):
        s.solve(2)
    with pytest.raises(loci.ModelError, match="not a constraint type"):
        s.add_constraint("no_such_thing", group=2)
    with pytest.raises(loci.ModelError, match="defined twice"):
        s.add_param(1.0, handle=1)
    with pytest.raises(loci.ModelError, match="entity of type \"point_in_2d\""):
        s.add_entity("point_in_2d", group=2, params=[1])
    with pytest.raises(KeyError):
        s.value(12345)


def test_generic_entities_and_constraints_by_code() -> None:
    s = loci.System()
    wp = s.add_xy_workplane(group=1)
    u = s.add_param(3.0, group=2)
    v = s.add_param(4.0, group=2)
    p = s.add_entity("point_in_2d", group=2, workplane=wp, params=[u, v])
    origin = s.entity(wp)["origin"]
    # 100001 is SolveSpace's PT_PT_DISTANCE.
    s.add_constraint(100001, group=2, workplane=wp, pt_a=origin, pt_b=p, value=10.0)
    assert s.solve(2).ok
    assert math.hypot(s.value(u), s.value(v)) == pytest.approx(10.0, abs=1e-9)
    assert s.value(u) / s.value(v) == pytest.approx(0.75, abs=1e-9)
    assert s.constraint(1)["type"] == "pt_pt_distance"
    assert [e["type"] for e in s.entities][-1] == "point_in_2d"
    assert s.groups == [1, 2]


def test_signed_angle_turns_a_line_over_and_solvespace_angle_keeps_its_turn() -> None:
    # Line A along +x (group 1), line B from the origin drawn 25 degrees counter-clockwise.
    for signed, want in [(False, 30.0), (True, -30.0)]:
        s = loci.System()
        wp = s.add_xy_workplane(group=1)
        o = s.add_point_2d(0.0, 0.0, workplane=wp, group=1)
        a = s.add_line(o, s.add_point_2d(4.0, 0.0, workplane=wp, group=1), workplane=wp, group=1)
        b_end = s.add_point_2d(2.5, 1.2, workplane=wp, group=2)
        b = s.add_line(o, b_end, workplane=wp, group=2)
        s.add_constraint("angle", group=2, workplane=wp, entity_a=a, entity_b=b, value=-30.0,
                         signed=signed)
        s.add_constraint("pt_pt_distance", group=2, workplane=wp, pt_a=o, pt_b=b_end, value=3.0)
        assert s.solve(2).ok
        u, v = xy(s, b_end)
        assert math.degrees(math.atan2(v, u)) == pytest.approx(want, abs=1e-6)
        assert s.constraints[0].get("signed", False) == signed
        # Solved again from its answer, nothing moves.
        again = s.solve(2)
        assert again.ok and again.iterations == 0


def test_numpy_bulk_values_100k() -> None:
    s = loci.System()
    n = 100_000
    for i in range(n):
        s.add_param(float(i), group=2)
    vals = s.values
    assert vals.dtype == np.float64 and vals.shape == (n,)
    assert np.array_equal(vals, np.arange(n, dtype=float))
    s.values = vals * 2.0
    assert s.value(n) == 2.0 * (n - 1)
    handles = s.param_handles
    assert handles.dtype == np.uint32 and handles[0] == 1
    s.set_values(handles[::2], np.zeros(n // 2))
    got = s.get_values(handles[:4])
    assert list(got) == [0.0, 2.0, 0.0, 6.0]
    with pytest.raises(ValueError):
        s.values = np.zeros(3)


def test_json_round_trip(tmp_path: Path) -> None:
    s, wp, a, b = two_points()
    s.solve(2)
    f = tmp_path / "two.json"
    s.save(f)
    t = loci.load(f)
    assert isinstance(t, loci.System)
    assert np.array_equal(t.values, s.values)
    assert t.to_json() == s.to_json()
    assert loci.System.from_json(s.to_json()).constraints == s.constraints
    # Handles continue after the largest read.
    assert t.add_param(0.0, group=3) == len(s.params) + 1


def test_load_examples(examples: Path) -> None:
    tri = loci.load(examples / "triangle.json")
    assert isinstance(tri, loci.System)
    r = tri.solve(2)
    assert r.ok
    with pytest.raises(loci.FileError):
        loci.loads("{ not json")


def test_load_slvs_file() -> None:
    root = Path(__file__).resolve().parents[3]
    f = sorted((root / "crates/loci/tests/data").glob("*.slvs"))[0]
    s = loci.load(f)
    assert isinstance(s, loci.System)
    assert len(s.params) > 0


def test_solves_run_in_threads() -> None:
    # The GIL is released during solves: threads each solving their own system all finish
    # with the right answer.
    systems = [two_points(5.0 + i)[0] for i in range(4)]
    results: "list[loci.SolveResult]" = []

    def run(s: loci.System) -> None:
        results.append(s.solve(2))

    threads = [threading.Thread(target=run, args=(s,)) for s in systems]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(results) == 4 and all(r.ok for r in results)


def test_repr_and_copy() -> None:
    import copy

    s, wp, a, b = two_points()
    assert repr(s) == "System(params=11, entities=5, constraints=2, groups=[1, 2])"
    t = copy.deepcopy(s)
    t.set_value(8, 100.0)
    assert s.value(8) != 100.0


def test_solvespace_angles_end_where_solvespace_does() -> None:
    # Jansen's linkage as SolveSpace's own test draws it (10 degrees of freedom): p8 (params 24
    # and 25) ends where SolveSpace's Newton path does only with its form of the 2D angle.
    root = Path(__file__).resolve().parents[3]
    drawn = loci.load(root / "crates/loci/tests/data/bugs/jansen_linkage.json")
    assert isinstance(drawn, loci.System)
    text = drawn.to_json()
    ends = {}
    for angles in (False, True):
        s = loci.System.from_json(text)
        r = s.solve(1, nearest=False, solvespace_angles=angles)
        assert r.ok
        ends[angles] = (s.value(24), s.value(25))
    assert ends[True] == (pytest.approx(18.93036, abs=1e-5), pytest.approx(13.63778, abs=1e-5))
    assert ends[False] == (pytest.approx(19.35966, abs=1e-5), pytest.approx(14.03307, abs=1e-5))
