"""``loci.slvs`` offers the module API of PyPI ``slvs`` 3.3: names, signatures, dictionaries,
result codes. Where ``slvs`` itself is installed, the two are run side by side."""

import inspect
import math
from typing import Any, List, Tuple

import pytest

import loci
import loci.slvs as lslvs

# The public names of PyPI slvs 3.3.
SLVS_NAMES = [
    "ConstraintType", "E_FREE_IN_3D", "E_NONE", "ResultFlag", "add_arc", "add_base_2d",
    "add_circle", "add_constraint", "add_cubic", "add_distance", "add_line_2d", "add_line_3d",
    "add_normal_2d", "add_normal_3d", "add_point_2d", "add_point_3d", "add_workplane", "angle",
    "clear_sketch", "coincident", "diameter", "distance", "distance_proj", "dragged", "equal",
    "equal_angle", "equal_point_to_line", "get_param_value", "horizontal", "length_diff",
    "make_quaternion", "midpoint", "parallel", "perpendicular", "quaternion_n", "quaternion_u",
    "quaternion_v", "ratio", "same_orientation", "set_param_value", "solve_sketch", "symmetric",
    "symmetric_h", "symmetric_v", "tangent", "vertical",
]


def test_every_name_of_slvs_is_there() -> None:
    missing = [n for n in SLVS_NAMES if not hasattr(lslvs, n)]
    assert missing == []


def test_result_flags_and_types_have_slvs_values() -> None:
    assert [(f.name, int(f)) for f in lslvs.ResultFlag] == [
        ("OKAY", 0), ("INCONSISTENT", 1), ("DIDNT_CONVERGE", 2),
        ("TOO_MANY_UNKNOWNS", 3), ("REDUNDANT_OKAY", 4),
    ]
    assert lslvs.ConstraintType.POINTS_COINCIDENT == 100000
    assert lslvs.ConstraintType.ARC_LINE_DIFFERENCE == 100037
    assert len(lslvs.ConstraintType) == 38
    assert lslvs.EntityType.ARC_OF_CIRCLE == 80004


def test_entities_and_constraints_are_slvs_dictionaries() -> None:
    lslvs.clear_sketch()
    wp = lslvs.add_base_2d(1)
    # As slvs numbers them: the normal (params 1-4), the origin (5-7), then the workplane.
    assert wp == {"h": 3, "group": 1, "type": 80000, "wrkpl": 0, "point": [2, 0, 0, 0],
                  "normal": 1, "distance": 0, "param": [0, 0, 0, 0]}
    p = lslvs.add_point_2d(1, 1, 2, wp)
    assert p == {"h": 4, "group": 1, "type": 50001, "wrkpl": 3, "point": [0, 0, 0, 0],
                 "normal": 0, "distance": 0, "param": [8, 9, 0, 0]}
    q = lslvs.add_point_2d(1, 5, 2, wp)
    c = lslvs.distance(1, p, q, 10, wp)
    assert c == {"h": 1, "group": 1, "type": 100001, "wrkpl": 3, "valA": 10.0, "ptA": 4,
                 "ptB": 5, "entityA": 0, "entityB": 0, "entityC": 0, "entityD": 0,
                 "other": 0, "other2": 0}
    d = lslvs.dragged(1, p, wp)
    assert d["type"] == 100031 and d["ptA"] == 4
    r = lslvs.solve_sketch(1, True)
    assert r == ({"result": 0, "dof": 7, "nbad": 0}, [])
    assert lslvs.get_param_value(p["param"][0]) == 1.0
    assert lslvs.get_param_value(q["param"][0]) == pytest.approx(11.0, abs=1e-9)


def test_inconsistent_is_a_result_naming_the_constraints() -> None:
    lslvs.clear_sketch()
    wp = lslvs.add_base_2d(1)
    p = lslvs.add_point_2d(2, 0, 0, wp)
    q = lslvs.add_point_2d(2, 5, 0, wp)
    a = lslvs.distance(2, p, q, 10, wp)
    b = lslvs.distance(2, p, q, 12, wp)
    r = lslvs.solve_sketch(2, True)
    assert isinstance(r, tuple)
    assert r[0]["result"] == lslvs.ResultFlag.INCONSISTENT
    assert sorted(r[1]) == sorted([a["h"], b["h"]])
    # Nothing moved.
    assert lslvs.get_param_value(q["param"][0]) == 5.0
    plain = lslvs.solve_sketch(2, False)
    assert plain == {"result": 1, "dof": r[0]["dof"], "nbad": 2}


def test_redundant_but_consistent_is_redundant_okay() -> None:
    lslvs.clear_sketch()
    wp = lslvs.add_base_2d(1)
    p = lslvs.add_point_2d(2, 0, 0, wp)
    q = lslvs.add_point_2d(2, 5, 1, wp)
    line = lslvs.add_line_2d(2, p, q, wp)
    lslvs.horizontal(2, line, wp)
    lslvs.horizontal(2, line, wp)
    r = lslvs.solve_sketch(2, False)
    assert isinstance(r, dict)
    assert r["result"] == lslvs.ResultFlag.REDUNDANT_OKAY
    assert lslvs.get_param_value(q["param"][1]) == pytest.approx(lslvs.get_param_value(p["param"][1]))


def test_bad_arguments_raise_instead_of_aborting() -> None:
    lslvs.clear_sketch()
    wp = lslvs.add_base_2d(1)
    p = lslvs.add_point_2d(1, 0, 0, wp)
    with pytest.raises(loci.ModelError, match="invalid arguments for distance"):
        lslvs.distance(1, lslvs.E_NONE, lslvs.E_NONE, 3.0, wp)
    with pytest.raises(loci.ModelError, match="not a workplane"):
        lslvs.add_point_2d(1, 0, 0, p)
    with pytest.raises(loci.ModelError, match="param 999 does not exist"):
        lslvs.get_param_value(999)
    with pytest.raises(loci.LociError):
        lslvs.tangent(1, p, p, wp)


def test_quaternions() -> None:
    assert lslvs.make_quaternion(1, 0, 0, 0, 1, 0) == (1.0, 0.0, 0.0, 0.0)
    q = lslvs.make_quaternion(0, 1, 0, -1, 0, 0)  # turned 90 degrees about z
    assert lslvs.quaternion_u(*q) == pytest.approx((0, 1, 0))
    assert lslvs.quaternion_v(*q) == pytest.approx((-1, 0, 0))
    assert lslvs.quaternion_n(*q) == pytest.approx((0, 0, 1))
    s = math.sqrt(0.5)
    assert q == pytest.approx((s, 0, 0, s))


def test_signatures_match_slvs() -> None:
    """Where PyPI slvs is installed: every function takes the same parameters, by the same
    names, with defaults for the same ones, so keyword calls work unchanged too."""
    slvs = pytest.importorskip("slvs")
    compared = 0
    for name in SLVS_NAMES:
        theirs = getattr(slvs, name)
        if isinstance(theirs, type) or not callable(theirs):
            continue
        try:
            want = inspect.signature(theirs)
        except (TypeError, ValueError):
            continue
        got = inspect.signature(getattr(lslvs, name))

        def shape(sig: inspect.Signature) -> List[Tuple[str, bool]]:
            return [(p.name, p.default is inspect.Parameter.empty) for p in sig.parameters.values()]

        assert shape(got) == shape(want), name
        compared += 1
    assert compared >= 40


def build_sketch(m: Any) -> List[float]:
    """A sketch with every entity and most constraint helpers, through module ``m``."""
    m.clear_sketch()
    wp = m.add_base_2d(1)
    g = 2
    p0 = m.add_point_2d(g, 0, 0, wp)
    m.dragged(g, p0, wp)
    p1 = m.add_point_2d(g, 10, 1, wp)
    p2 = m.add_point_2d(g, 11, 9, wp)
    p3 = m.add_point_2d(g, 1, 10, wp)
    l01 = m.add_line_2d(g, p0, p1, wp)
    l12 = m.add_line_2d(g, p1, p2, wp)
    l23 = m.add_line_2d(g, p2, p3, wp)
    l30 = m.add_line_2d(g, p3, p0, wp)
    m.horizontal(g, l01, wp)
    m.vertical(g, l30, wp)
    m.parallel(g, l01, l23, wp)
    m.perpendicular(g, l01, l12, wp, False)
    m.distance(g, p0, p1, 20, wp)
    m.equal(g, l01, l30, wp)
    nm = m.add_normal_3d(1, *m.make_quaternion(1, 0, 0, 0, 1, 0))
    c = m.add_point_2d(g, 30, 5, wp)
    r = m.add_distance(g, 4, wp)
    circle = m.add_circle(g, nm, c, r, wp)
    m.diameter(g, circle, 6)
    m.coincident(g, c, l01, wp)
    m.distance(g, p0, c, 25, wp)
    mid = m.add_point_2d(g, 5, 12, wp)
    m.midpoint(g, mid, l23, wp)
    res = m.solve_sketch(g, False)
    assert res["result"] == 0, res
    out = [float(res["dof"])]
    for p in (p0, p1, p2, p3, c, mid):
        out += [m.get_param_value(p["param"][0]), m.get_param_value(p["param"][1])]
    out.append(m.get_param_value(r["param"][0]))
    return out


def test_same_answers_as_slvs() -> None:
    """A determined square with a circle on its base line and a midpoint: the same answer
    (and the same degrees of freedom) from both modules."""
    ours = build_sketch(lslvs)
    assert ours == pytest.approx(
        [0, 0, 0, 20, 0, 20, 20, 0, 20, 25, 0, 10, 20, 3], abs=1e-9
    )
    slvs = pytest.importorskip("slvs")
    theirs = build_sketch(slvs)
    assert ours == pytest.approx(theirs, abs=1e-6)


def build_tangent_arc(m: Any) -> List[float]:
    """A line and an arc tangent at their shared end, the arc's end straight above its
    centre: determined, through module ``m``."""
    m.clear_sketch()
    wp = m.add_base_2d(1)
    nm = m.add_normal_3d(1, *m.make_quaternion(1, 0, 0, 0, 1, 0))
    g = 2
    p0 = m.add_point_2d(g, 0, 0, wp)
    m.dragged(g, p0, wp)
    p1 = m.add_point_2d(g, 10, 0.5, wp)
    line = m.add_line_2d(g, p0, p1, wp)
    m.horizontal(g, line, wp)
    m.distance(g, p0, p1, 10, wp)
    c = m.add_point_2d(g, 10.5, 5, wp)
    start = m.add_point_2d(g, 10, 0.5, wp)  # where p1 is, so the tangent finds the shared end
    end = m.add_point_2d(g, 11, 11, wp)
    arc = m.add_arc(g, nm, c, start, end, wp)
    m.coincident(g, p1, start, wp)
    m.tangent(g, arc, line, wp)
    m.diameter(g, arc, 10)
    m.vertical(g, c, wp, end)
    res = m.solve_sketch(g, False)
    assert res["result"] == 0, res
    out = [float(res["dof"])]
    for p in (p1, c, start, end):
        out += [m.get_param_value(p["param"][0]), m.get_param_value(p["param"][1])]
    return out


def build_mirrors(m: Any) -> List[float]:
    """Angle, length difference, horizontal symmetry and a length ratio: determined."""
    m.clear_sketch()
    wp = m.add_base_2d(1)
    g = 2
    p0 = m.add_point_2d(g, 0, 0, wp)
    m.dragged(g, p0, wp)
    p1 = m.add_point_2d(g, 9, 0.5, wp)
    p2 = m.add_point_2d(g, 10, 6, wp)
    l1 = m.add_line_2d(g, p0, p1, wp)
    l2 = m.add_line_2d(g, p0, p2, wp)
    m.horizontal(g, l1, wp)
    m.distance(g, p0, p1, 10, wp)
    m.angle(g, l1, l2, 30, wp)
    m.length_diff(g, l2, l1, 2, wp)
    p3 = m.add_point_2d(g, -9, 5, wp)
    m.symmetric_h(g, p2, p3, wp)
    p4 = m.add_point_2d(g, -9, 11, wp)
    l3 = m.add_line_2d(g, p3, p4, wp)
    m.vertical(g, l3, wp)
    m.ratio(g, l3, l1, 0.5, wp)
    res = m.solve_sketch(g, False)
    assert res["result"] == 0, res
    out = [float(res["dof"])]
    for p in (p1, p2, p3, p4):
        out += [m.get_param_value(p["param"][0]), m.get_param_value(p["param"][1])]
    return out


def test_tangent_arc_same_as_slvs() -> None:
    ours = build_tangent_arc(lslvs)
    # Tangent to the horizontal line at (10, 0): the centre straight above, radius 5.
    assert ours == pytest.approx([0, 10, 0, 10, 5, 10, 0, 10, 10], abs=1e-9)
    slvs = pytest.importorskip("slvs")
    assert ours == pytest.approx(build_tangent_arc(slvs), abs=1e-6)


def test_mirrors_same_as_slvs() -> None:
    ours = build_mirrors(lslvs)
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    x2, y2 = 12 * c, 12 * s
    assert ours == pytest.approx([0, 10, 0, x2, y2, -x2, y2, -x2, y2 + 5], abs=1e-9)
    slvs = pytest.importorskip("slvs")
    assert ours == pytest.approx(build_mirrors(slvs), abs=1e-6)
