"""SolveSpace's own Python tests (its repository's ``python/tests/test.py``), run against
``loci.slvs``: the same sketches, built with the same calls, must give the same numbers."""

from math import radians

import pytest

import loci.slvs as slvs


def solved(g: int) -> None:
    result = slvs.solve_sketch(g, False)
    assert isinstance(result, dict)
    assert result["result"] == slvs.ResultFlag.OKAY


def value(e: slvs.Slvs_Entity, i: int) -> float:
    return slvs.get_param_value(e["param"][i])


def test_crank_rocker() -> None:
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
    solved(g)
    assert value(p2, 0) == pytest.approx(39.54852, abs=1e-4)
    assert value(p2, 1) == pytest.approx(61.91009, abs=1e-4)


def test_involute() -> None:
    r = 10
    angle = 45
    slvs.clear_sketch()
    g = 1
    wp = slvs.add_base_2d(g)
    p0 = slvs.add_point_2d(g, 0, 0, wp)
    slvs.dragged(g, p0, wp)
    p1 = slvs.add_point_2d(g, 0, 10, wp)
    slvs.distance(g, p0, p1, r, wp)
    line0 = slvs.add_line_2d(g, p0, p1, wp)
    p2 = slvs.add_point_2d(g, 10, 10, wp)
    line1 = slvs.add_line_2d(g, p1, p2, wp)
    slvs.distance(g, p1, p2, r * radians(angle), wp)
    slvs.perpendicular(g, line0, line1, wp, False)
    p3 = slvs.add_point_2d(g, 10, 0, wp)
    slvs.dragged(g, p3, wp)
    line_base = slvs.add_line_2d(g, p0, p3, wp)
    slvs.angle(g, line0, line_base, angle, wp, False)
    solved(g)
    assert value(p2, 0) == pytest.approx(12.62467, abs=1e-4)
    assert value(p2, 1) == pytest.approx(1.51746, abs=1e-4)


def test_jansen_linkage() -> None:
    slvs.clear_sketch()
    g = 1
    wp = slvs.add_base_2d(g)
    p0 = slvs.add_point_2d(g, 0, 0, wp)
    slvs.dragged(g, p0, wp)
    p1 = slvs.add_point_2d(g, 0, 20, wp)
    slvs.distance(g, p0, p1, 15, wp)
    line0 = slvs.add_line_2d(g, p0, p1, wp)
    p2 = slvs.add_point_2d(g, -38, -7.8, wp)
    slvs.dragged(g, p2, wp)
    p3 = slvs.add_point_2d(g, -50, 30, wp)
    p4 = slvs.add_point_2d(g, -70, -15, wp)
    slvs.distance(g, p2, p3, 41.5, wp)
    slvs.distance(g, p3, p4, 55.8, wp)
    slvs.distance(g, p2, p4, 40.1, wp)
    p5 = slvs.add_point_2d(g, -50, -50, wp)
    p6 = slvs.add_point_2d(g, -10, -90, wp)
    p7 = slvs.add_point_2d(g, -20, -40, wp)
    slvs.distance(g, p5, p6, 65.7, wp)
    slvs.distance(g, p6, p7, 49.0, wp)
    slvs.distance(g, p5, p7, 36.7, wp)
    slvs.distance(g, p1, p3, 50, wp)
    slvs.distance(g, p1, p7, 61.9, wp)
    p8 = slvs.add_point_2d(g, 20, 0, wp)
    line_base = slvs.add_line_2d(g, p0, p8, wp)
    slvs.angle(g, line0, line_base, 45, wp, False)
    solved(g)
    assert value(p8, 0) == pytest.approx(18.93036, abs=1e-4)
    assert value(p8, 1) == pytest.approx(13.63778, abs=1e-4)


def test_nut_cracker() -> None:
    h0, b0, r0, n1, n2, l0 = 0.5, 0.75, 0.25, 1.5, 2.3, 3.25
    slvs.clear_sketch()
    g = 1
    wp = slvs.add_base_2d(g)
    p0 = slvs.add_point_2d(g, 0, 0, wp)
    slvs.dragged(g, p0, wp)
    p1 = slvs.add_point_2d(g, 2, 2, wp)
    p2 = slvs.add_point_2d(g, 2, 0, wp)
    line0 = slvs.add_line_2d(g, p0, p2, wp)
    slvs.horizontal(g, line0, wp)
    line1 = slvs.add_line_2d(g, p1, p2, wp)
    p3 = slvs.add_point_2d(g, b0 / 2, h0, wp)
    slvs.dragged(g, p3, wp)
    slvs.distance(g, p3, line1, r0, wp)
    slvs.distance(g, p0, p1, n1, wp)
    slvs.distance(g, p1, p2, n2, wp)
    solved(g)
    x = value(p2, 0)
    assert x - b0 / 2 == pytest.approx(1.01576, abs=1e-4)
    assert l0 - r0 - b0 / 2 == pytest.approx(2.625, abs=1e-4)


def test_pydemo() -> None:
    """The 2D demo of SolveSpace's library: a workplane in group 1, geometry in group 2."""
    slvs.clear_sketch()
    g1, g2 = 1, 2
    p101 = slvs.add_point_3d(g1, 0, 0, 0)
    w, vx, vy, vz = slvs.make_quaternion(1, 0, 0, 0, 1, 0)
    n102 = slvs.add_normal_3d(g1, w, vx, vy, vz)
    wp200 = slvs.add_workplane(g1, p101, n102)
    p301 = slvs.add_point_2d(g2, 10, 20, wp200)
    p302 = slvs.add_point_2d(g2, 20, 10, wp200)
    l400 = slvs.add_line_2d(g2, p301, p302, wp200)
    p303 = slvs.add_point_2d(g2, 100, 120, wp200)
    p304 = slvs.add_point_2d(g2, 120, 110, wp200)
    p305 = slvs.add_point_2d(g2, 115, 115, wp200)
    a401 = slvs.add_arc(g2, n102, p303, p304, p305, wp200)
    p306 = slvs.add_point_2d(g2, 200, 200, wp200)
    d307 = slvs.add_distance(g2, 30, wp200)
    c402 = slvs.add_circle(g2, n102, p306, d307, wp200)
    slvs.distance(g2, p301, p302, 30, wp200)
    slvs.distance(g2, p101, l400, 10, wp200)
    slvs.vertical(g2, l400, wp200)
    slvs.distance(g2, p301, p101, 15, wp200)
    slvs.equal(g2, a401, c402, wp200)
    slvs.diameter(g2, a401, 17 * 2)
    slvs.solve_sketch(g1, False)
    g2result = slvs.solve_sketch(g2, False)
    assert isinstance(g2result, dict)
    assert g2result["result"] == slvs.ResultFlag.OKAY
    expected = {
        "p301": (p301, 10, 11.18030),
        "p302": (p302, 10, -18.81966),
        "p303": (p303, 101.11418, 119.04153),
        "p304": (p304, 116.47661, 111.76171),
        "p305": (p305, 117.40922, 114.19676),
        "p306": (p306, 200, 200),
    }
    for name, (p, x, y) in expected.items():
        assert (value(p, 0), value(p, 1)) == (
            pytest.approx(x, abs=1e-4),
            pytest.approx(y, abs=1e-4),
        ), name
    assert value(d307, 0) == pytest.approx(17, abs=1e-4)
    assert g2result["dof"] == 6
