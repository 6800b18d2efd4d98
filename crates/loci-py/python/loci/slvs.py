"""A drop-in for SolveSpace's ``slvs`` Python module (PyPI ``slvs`` 3.3), backed by loci.

A script written for ``slvs`` runs unchanged after ``import loci.slvs as slvs``: the same
functions with the same arguments, entities and constraints as the same dictionaries, the
same handles (numbered from 1 for parameters, entities and constraints alike), the same
``ResultFlag`` values and result fields. As in ``slvs``, there is one sketch per process;
``clear_sketch()`` empties it.

Differences (see ``docs/python.md``):

* Bad arguments raise :class:`loci.ModelError` (a :class:`loci.LociError`) instead of
  aborting the interpreter.
* ``mark_dragged(point)`` works (in ``slvs`` 3.3 it always aborts): the point's parameters
  move as little as possible in later solves.
* ``mark_dragged`` takes at most two 2D points (four parameters), as libslvs's arrays do.
* ``to_system()`` gives the sketch as a :class:`loci.System` (to check or save it).
"""

from __future__ import annotations

import math
from enum import IntEnum
from typing import List, Sequence, Set, Tuple, TypedDict, Union

from ._loci import ModelError, SlvsModel, System

__all__ = [
    "ConstraintType",
    "EntityType",
    "ResultFlag",
    "E_NONE",
    "E_FREE_IN_3D",
    "Slvs_Entity",
    "Slvs_Constraint",
    "Slvs_SolveResult",
    "quaternion_u",
    "quaternion_v",
    "quaternion_n",
    "make_quaternion",
    "add_base_2d",
    "add_point_2d",
    "add_point_3d",
    "add_normal_2d",
    "add_normal_3d",
    "add_distance",
    "add_line_2d",
    "add_line_3d",
    "add_cubic",
    "add_arc",
    "add_circle",
    "add_workplane",
    "add_constraint",
    "coincident",
    "distance",
    "equal",
    "equal_angle",
    "equal_point_to_line",
    "ratio",
    "symmetric",
    "symmetric_h",
    "symmetric_v",
    "midpoint",
    "horizontal",
    "vertical",
    "diameter",
    "same_orientation",
    "angle",
    "perpendicular",
    "parallel",
    "tangent",
    "distance_proj",
    "length_diff",
    "dragged",
    "mark_dragged",
    "clear_sketch",
    "solve_sketch",
    "get_param_value",
    "set_param_value",
    "to_system",
]


class ConstraintType(IntEnum):
    """The constraint type codes of SolveSpace's library."""

    POINTS_COINCIDENT = 100000
    PT_PT_DISTANCE = 100001
    PT_PLANE_DISTANCE = 100002
    PT_LINE_DISTANCE = 100003
    PT_FACE_DISTANCE = 100004
    PT_IN_PLANE = 100005
    PT_ON_LINE = 100006
    PT_ON_FACE = 100007
    EQUAL_LENGTH_LINES = 100008
    LENGTH_RATIO = 100009
    EQ_LEN_PT_LINE_D = 100010
    EQ_PT_LN_DISTANCES = 100011
    EQUAL_ANGLE = 100012
    EQUAL_LINE_ARC_LEN = 100013
    SYMMETRIC = 100014
    SYMMETRIC_HORIZ = 100015
    SYMMETRIC_VERT = 100016
    SYMMETRIC_LINE = 100017
    AT_MIDPOINT = 100018
    HORIZONTAL = 100019
    VERTICAL = 100020
    DIAMETER = 100021
    PT_ON_CIRCLE = 100022
    SAME_ORIENTATION = 100023
    ANGLE = 100024
    PARALLEL = 100025
    PERPENDICULAR = 100026
    ARC_LINE_TANGENT = 100027
    CUBIC_LINE_TANGENT = 100028
    EQUAL_RADIUS = 100029
    PROJ_PT_DISTANCE = 100030
    WHERE_DRAGGED = 100031
    CURVE_CURVE_TANGENT = 100032
    LENGTH_DIFFERENCE = 100033
    ARC_ARC_LEN_RATIO = 100034
    ARC_LINE_LEN_RATIO = 100035
    ARC_ARC_DIFFERENCE = 100036
    ARC_LINE_DIFFERENCE = 100037


class EntityType(IntEnum):
    """The entity type codes of SolveSpace's library."""

    POINT_IN_3D = 50000
    POINT_IN_2D = 50001
    NORMAL_IN_3D = 60000
    NORMAL_IN_2D = 60001
    DISTANCE = 70000
    WORKPLANE = 80000
    LINE_SEGMENT = 80001
    CUBIC = 80002
    CIRCLE = 80003
    ARC_OF_CIRCLE = 80004


class ResultFlag(IntEnum):
    """How a solve ended, with SolveSpace's codes."""

    OKAY = 0
    INCONSISTENT = 1
    DIDNT_CONVERGE = 2
    TOO_MANY_UNKNOWNS = 3
    REDUNDANT_OKAY = 4


class Slvs_Entity(TypedDict):
    """An entity, as ``slvs`` returns it."""

    h: int
    group: int
    type: int
    wrkpl: int
    point: List[int]
    normal: int
    distance: int
    param: List[int]


class Slvs_Constraint(TypedDict):
    """A constraint, as ``slvs`` returns it."""

    h: int
    group: int
    type: int
    wrkpl: int
    valA: float
    ptA: int
    ptB: int
    entityA: int
    entityB: int
    entityC: int
    entityD: int
    other: int
    other2: int


class Slvs_SolveResult(TypedDict):
    """The result of ``solve_sketch``."""

    result: int
    dof: int
    nbad: int


def _none_entity() -> Slvs_Entity:
    return {
        "h": 0,
        "group": 0,
        "type": 0,
        "wrkpl": 0,
        "point": [0, 0, 0, 0],
        "normal": 0,
        "distance": 0,
        "param": [0, 0, 0, 0],
    }


E_NONE: Slvs_Entity = _none_entity()
"""No entity."""
E_FREE_IN_3D: Slvs_Entity = _none_entity()
"""No workplane: a constraint free in 3D."""

_P3, _P2 = EntityType.POINT_IN_3D.value, EntityType.POINT_IN_2D.value
_N3, _N2 = EntityType.NORMAL_IN_3D.value, EntityType.NORMAL_IN_2D.value
_DIST, _WP = EntityType.DISTANCE.value, EntityType.WORKPLANE.value
_LINE, _CUBIC = EntityType.LINE_SEGMENT.value, EntityType.CUBIC.value
_CIRCLE, _ARC = EntityType.CIRCLE.value, EntityType.ARC_OF_CIRCLE.value

# The one sketch of the process, as in slvs: libslvs's arrays, kept natively.
_m = SlvsModel()
_dragged: Set[int] = set()


def _entity(
    h: int,
    group: int,
    type_: int,
    wrkpl: int = 0,
    point: Tuple[int, int, int, int] = (0, 0, 0, 0),
    normal: int = 0,
    distance: int = 0,
    param: Sequence[int] = (0, 0, 0, 0),
) -> Slvs_Entity:
    return {
        "h": h,
        "group": group,
        "type": type_,
        "wrkpl": wrkpl,
        "point": list(point),
        "normal": normal,
        "distance": distance,
        "param": list(param),
    }


def _is_point(e: Slvs_Entity) -> bool:
    return e["type"] in (_P3, _P2)


def _is_line(e: Slvs_Entity) -> bool:
    return e["type"] == _LINE


def _is_round(e: Slvs_Entity) -> bool:
    return e["type"] in (_CIRCLE, _ARC)


def _is_wp(e: Slvs_Entity) -> bool:
    return e["type"] == _WP


def _free(wp: Slvs_Entity) -> bool:
    return wp["h"] == 0


def _want_wp(wp: Slvs_Entity) -> None:
    if not (_is_wp(wp)):
        raise ModelError(f"workplane argument is entity {wp['h']}, not a workplane")


def _want_p2(p: Slvs_Entity, name: str) -> None:
    if not (p["type"] == _P2):
        raise ModelError(f"{name} argument is entity {p['h']}, not a 2d point")


# ---------------------------------------------------------------- quaternions


def quaternion_u(qw: float, qx: float, qy: float, qz: float) -> Tuple[float, float, float]:
    """The first basis vector (u) of the frame the quaternion turns the axes into."""
    return (
        qw * qw + qx * qx - qy * qy - qz * qz,
        2.0 * (qw * qz + qx * qy),
        2.0 * (qx * qz - qw * qy),
    )


def quaternion_v(qw: float, qx: float, qy: float, qz: float) -> Tuple[float, float, float]:
    """The second basis vector (v) of the frame the quaternion turns the axes into."""
    return (
        2.0 * (qx * qy - qw * qz),
        qw * qw - qx * qx + qy * qy - qz * qz,
        2.0 * (qw * qx + qy * qz),
    )


def quaternion_n(qw: float, qx: float, qy: float, qz: float) -> Tuple[float, float, float]:
    """The normal (u x v) of the frame the quaternion turns the axes into."""
    return (
        2.0 * (qw * qy + qx * qz),
        2.0 * (qy * qz - qw * qx),
        qw * qw - qx * qx - qy * qy + qz * qz,
    )


def make_quaternion(
    ux: float, uy: float, uz: float, vx: float, vy: float, vz: float
) -> Tuple[float, float, float, float]:
    """The unit quaternion (w, x, y, z) turning the x and y axes into ``u`` and ``v``."""
    nx, ny, nz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
    t = 1.0 + ux + vy + nz
    if t > 1e-4:
        s = 2.0 * math.sqrt(t)
        q = (s / 4.0, (vz - ny) / s, (nx - uz) / s, (uy - vx) / s)
    elif ux > vy and ux > nz:
        s = 2.0 * math.sqrt(1.0 + ux - vy - nz)
        q = ((vz - ny) / s, s / 4.0, (uy + vx) / s, (nx + uz) / s)
    elif vy > nz:
        s = 2.0 * math.sqrt(1.0 - ux + vy - nz)
        q = ((nx - uz) / s, (uy + vx) / s, s / 4.0, (vz + ny) / s)
    else:
        s = 2.0 * math.sqrt(1.0 - ux - vy + nz)
        q = ((uy - vx) / s, (nx + uz) / s, (vz + ny) / s, s / 4.0)
    n = math.sqrt(sum(a * a for a in q))
    return (q[0] / n, q[1] / n, q[2] / n, q[3] / n)


# ---------------------------------------------------------------- entities


def _add(
    grouph: int,
    type_: int,
    wrkpl: int = 0,
    point: Tuple[int, int, int, int] = (0, 0, 0, 0),
    normal: int = 0,
    distance: int = 0,
    values: Tuple[float, ...] = (),
) -> Slvs_Entity:
    h, param = _m.add_entity(grouph, type_, wrkpl, point, normal, distance, values)
    return _entity(h, grouph, type_, wrkpl, point, normal, distance, param)


def add_point_2d(grouph: int, u: float, v: float, workplane: Slvs_Entity) -> Slvs_Entity:
    """A point at (u, v) in workplane ``workplane``."""
    if workplane["type"] != _WP:
        _want_wp(workplane)
    w = workplane["h"]
    h, pu, pv = _m.add_point_2d(grouph, w, u, v)
    return {
        "h": h,
        "group": grouph,
        "type": _P2,
        "wrkpl": w,
        "point": [0, 0, 0, 0],
        "normal": 0,
        "distance": 0,
        "param": [pu, pv, 0, 0],
    }


def add_point_3d(grouph: int, x: float, y: float, z: float) -> Slvs_Entity:
    """A point at (x, y, z)."""
    return _add(grouph, _P3, values=(x, y, z))


def add_normal_2d(grouph: int, workplane: Slvs_Entity) -> Slvs_Entity:
    """The normal of workplane ``workplane``."""
    _want_wp(workplane)
    return _add(grouph, _N2, workplane["h"])


def add_normal_3d(grouph: int, qw: float, qx: float, qy: float, qz: float) -> Slvs_Entity:
    """An orientation as the unit quaternion (qw, qx, qy, qz)."""
    return _add(grouph, _N3, values=(qw, qx, qy, qz))


def add_distance(grouph: int, value: float, workplane: Slvs_Entity) -> Slvs_Entity:
    """A distance entity (a circle's radius) of value ``value``."""
    _want_wp(workplane)
    return _add(grouph, _DIST, workplane["h"], values=(value,))


def add_line_2d(grouph: int, ptA: Slvs_Entity, ptB: Slvs_Entity, workplane: Slvs_Entity) -> Slvs_Entity:
    """A line segment between two 2D points in ``workplane``."""
    if workplane["type"] != _WP or ptA["type"] != _P2 or ptB["type"] != _P2:
        _want_wp(workplane)
        _want_p2(ptA, "ptA")
        _want_p2(ptB, "ptB")
    w, a, b = workplane["h"], ptA["h"], ptB["h"]
    h = _m.add_line(grouph, w, a, b)
    return {
        "h": h,
        "group": grouph,
        "type": _LINE,
        "wrkpl": w,
        "point": [a, b, 0, 0],
        "normal": 0,
        "distance": 0,
        "param": [0, 0, 0, 0],
    }


def add_line_3d(grouph: int, ptA: Slvs_Entity, ptB: Slvs_Entity) -> Slvs_Entity:
    """A line segment between two 3D points."""
    if not (ptA["type"] == _P3):
        raise ModelError(f"ptA argument is entity {ptA['h']}, not a 3d point")
    if not (ptB["type"] == _P3):
        raise ModelError(f"ptB argument is entity {ptB['h']}, not a 3d point")
    return _add(grouph, _LINE, 0, (ptA["h"], ptB["h"], 0, 0))


def add_cubic(
    grouph: int,
    ptA: Slvs_Entity,
    ptB: Slvs_Entity,
    ptC: Slvs_Entity,
    ptD: Slvs_Entity,
    workplane: Slvs_Entity,
) -> Slvs_Entity:
    """A cubic Bezier through four 2D control points in ``workplane``."""
    _want_wp(workplane)
    for p, n in ((ptA, "ptA"), (ptB, "ptB"), (ptC, "ptC"), (ptD, "ptD")):
        _want_p2(p, n)
    return _add(grouph, _CUBIC, workplane["h"], (ptA["h"], ptB["h"], ptC["h"], ptD["h"]))


def add_arc(
    grouph: int,
    normal: Slvs_Entity,
    center: Slvs_Entity,
    start: Slvs_Entity,
    end: Slvs_Entity,
    workplane: Slvs_Entity,
) -> Slvs_Entity:
    """An arc about ``center``, counter-clockwise from ``start`` to ``end``, in ``workplane``."""
    _want_wp(workplane)
    if not (normal["type"] == _N3):
        raise ModelError(f"normal argument is entity {normal['h']}, not a 3d normal")
    _want_p2(center, "center")
    _want_p2(start, "start")
    _want_p2(end, "end")
    return _add(grouph, _ARC, workplane["h"], (center["h"], start["h"], end["h"], 0), normal["h"])


def add_circle(
    grouph: int,
    normal: Slvs_Entity,
    center: Slvs_Entity,
    radius: Slvs_Entity,
    workplane: Slvs_Entity,
) -> Slvs_Entity:
    """A circle about ``center`` whose radius is the distance entity ``radius``, in ``workplane``."""
    _want_wp(workplane)
    if not (normal["type"] == _N3):
        raise ModelError(f"normal argument is entity {normal['h']}, not a 3d normal")
    _want_p2(center, "center")
    if not (radius["type"] == _DIST):
        raise ModelError(f"radius argument is entity {radius['h']}, not a distance")
    return _add(grouph, _CIRCLE, workplane["h"], (center["h"], 0, 0, 0), normal["h"], radius["h"])


def add_workplane(grouph: int, origin: Slvs_Entity, nm: Slvs_Entity) -> Slvs_Entity:
    """A workplane through the 3D point ``origin`` oriented by the normal ``nm``."""
    return _add(grouph, _WP, 0, (origin["h"], 0, 0, 0), nm["h"])


def add_base_2d(grouph: int) -> Slvs_Entity:
    """The xy plane as a workplane in ``grouph`` (normal, origin, then the workplane)."""
    nm = add_normal_3d(grouph, *make_quaternion(1, 0, 0, 0, 1, 0))
    return add_workplane(grouph, add_point_3d(grouph, 0, 0, 0), nm)


# ---------------------------------------------------------------- constraints


def add_constraint(
    grouph: int,
    c_type: int,
    workplane: Slvs_Entity,
    val: float,
    ptA: Slvs_Entity = E_NONE,
    ptB: Slvs_Entity = E_NONE,
    entityA: Slvs_Entity = E_NONE,
    entityB: Slvs_Entity = E_NONE,
    entityC: Slvs_Entity = E_NONE,
    entityD: Slvs_Entity = E_NONE,
    other: int = 0,
    other2: int = 0,
) -> Slvs_Constraint:
    """A constraint of any type with SolveSpace's fields."""
    c_type = int(c_type)
    other = 1 if other else 0
    other2 = 1 if other2 else 0
    h = _m.add_constraint(
        grouph,
        c_type,
        workplane["h"],
        val,
        ptA["h"],
        ptB["h"],
        entityA["h"],
        entityB["h"],
        entityC["h"],
        entityD["h"],
        other,
        other2,
    )
    return {
        "h": h,
        "group": grouph,
        "type": c_type,
        "wrkpl": workplane["h"],
        "valA": float(val),
        "ptA": ptA["h"],
        "ptB": ptB["h"],
        "entityA": entityA["h"],
        "entityB": entityB["h"],
        "entityC": entityC["h"],
        "entityD": entityD["h"],
        "other": other,
        "other2": other2,
    }


C = ConstraintType

_PT_PT_DISTANCE = int(ConstraintType.PT_PT_DISTANCE)
_PERPENDICULAR = int(ConstraintType.PERPENDICULAR)
_POINT_TYPES = (_P3, _P2)


def _quick(
    grouph: int, c_type: int, w: int, val: float, pa: int, pb: int, ea: int, eb: int, other: int
) -> Slvs_Constraint:
    # add_constraint for handles already read, without entityC, entityD and other2: the path
    # of the constraints a script adds by the thousand (a chain's distances and angles).
    h = _m.add_constraint(grouph, c_type, w, val, pa, pb, ea, eb, 0, 0, other, 0)
    return {
        "h": h,
        "group": grouph,
        "type": c_type,
        "wrkpl": w,
        "valA": float(val),
        "ptA": pa,
        "ptB": pb,
        "entityA": ea,
        "entityB": eb,
        "entityC": 0,
        "entityD": 0,
        "other": other,
        "other2": 0,
    }


def coincident(
    grouph: int, entityA: Slvs_Entity, entityB: Slvs_Entity, workplane: Slvs_Entity = E_FREE_IN_3D
) -> Slvs_Constraint:
    """Two points coincide, or a point lies on a workplane, line, circle or arc."""
    if _is_point(entityA) and _is_point(entityB):
        return add_constraint(grouph, C.POINTS_COINCIDENT, workplane, 0.0, entityA, entityB)
    if _is_point(entityA) and _is_wp(entityB):
        return add_constraint(grouph, C.PT_IN_PLANE, E_FREE_IN_3D, 0.0, entityA, E_NONE, entityB)
    if _is_point(entityA) and _is_line(entityB):
        return add_constraint(grouph, C.PT_ON_LINE, workplane, 0.0, entityA, E_NONE, entityB)
    if _is_point(entityA) and _is_round(entityB):
        return add_constraint(grouph, C.PT_ON_CIRCLE, workplane, 0.0, entityA, E_NONE, entityB)
    raise ModelError(f"invalid arguments for coincident: entities {entityA['h']} and {entityB['h']}")


def distance(
    grouph: int,
    entityA: Slvs_Entity,
    entityB: Slvs_Entity,
    value: float,
    workplane: Slvs_Entity,
) -> Slvs_Constraint:
    """The distance between two points, from a point to a workplane (``workplane`` free in
    3D), or to a line."""
    if entityA["type"] in _POINT_TYPES and entityB["type"] in _POINT_TYPES:
        return _quick(grouph, _PT_PT_DISTANCE, workplane["h"], value, entityA["h"], entityB["h"], 0, 0, 0)
    if _is_point(entityA) and _is_wp(entityB) and _free(workplane):
        return add_constraint(grouph, C.PT_PLANE_DISTANCE, entityB, value, entityA, E_NONE, entityB)
    if _is_point(entityA) and _is_line(entityB):
        return add_constraint(grouph, C.PT_LINE_DISTANCE, workplane, value, entityA, E_NONE, entityB)
    raise ModelError(f"invalid arguments for distance: entities {entityA['h']} and {entityB['h']}")


def equal(
    grouph: int, entityA: Slvs_Entity, entityB: Slvs_Entity, workplane: Slvs_Entity = E_FREE_IN_3D
) -> Slvs_Constraint:
    """Two lines of equal length, a line as long as an arc, or two equal radii."""
    if _is_line(entityA) and _is_line(entityB):
        return add_constraint(grouph, C.EQUAL_LENGTH_LINES, workplane, 0.0, E_NONE, E_NONE, entityA, entityB)
    if _is_line(entityA) and _is_round(entityB):
        return add_constraint(grouph, C.EQUAL_LINE_ARC_LEN, workplane, 0.0, E_NONE, E_NONE, entityA, entityB)
    if _is_round(entityA) and _is_round(entityB):
        return add_constraint(grouph, C.EQUAL_RADIUS, workplane, 0.0, E_NONE, E_NONE, entityA, entityB)
    raise ModelError(f"invalid arguments for equal: entities {entityA['h']} and {entityB['h']}")


def _lines(*es: Slvs_Entity) -> bool:
    for e in es:
        if e["type"] != _LINE:
            return False
    return True


def _two_lines(a: Slvs_Entity, b: Slvs_Entity, wp: Slvs_Entity) -> bool:
    # Both lines, in a workplane or free in 3D: the common test of the two-line helpers.
    return a["type"] == _LINE and b["type"] == _LINE and (wp["type"] == _WP or wp["h"] == 0)


def _plane_or_free(wp: Slvs_Entity) -> bool:
    return _is_wp(wp) or _free(wp)


def equal_angle(
    grouph: int,
    entityA: Slvs_Entity,
    entityB: Slvs_Entity,
    entityC: Slvs_Entity,
    entityD: Slvs_Entity,
    workplane: Slvs_Entity = E_FREE_IN_3D,
) -> Slvs_Constraint:
    """The angle between lines entityA and entityB equals the angle between entityC and entityD."""
    if not (_lines(entityA, entityB, entityC, entityD) and _plane_or_free(workplane)):
        raise ModelError("invalid arguments for equal_angle")
    return add_constraint(grouph, C.EQUAL_ANGLE, workplane, 0.0, E_NONE, E_NONE, entityA, entityB, entityC, entityD)


def equal_point_to_line(
    grouph: int,
    entityA: Slvs_Entity,
    entityB: Slvs_Entity,
    entityC: Slvs_Entity,
    entityD: Slvs_Entity,
    workplane: Slvs_Entity = E_FREE_IN_3D,
) -> Slvs_Constraint:
    """The distance from point entityA to line entityB equals that from point entityC to line entityD."""
    ok = _is_point(entityA) and _is_line(entityB) and _is_point(entityC) and _is_line(entityD)
    if not (ok and _plane_or_free(workplane)):
        raise ModelError("invalid arguments for equal_point_to_line")
    return add_constraint(grouph, C.EQ_PT_LN_DISTANCES, workplane, 0.0, entityA, entityB, entityC, entityD)


def ratio(
    grouph: int,
    entityA: Slvs_Entity,
    entityB: Slvs_Entity,
    value: float,
    workplane: Slvs_Entity = E_FREE_IN_3D,
) -> Slvs_Constraint:
    """The length of line entityA over that of line entityB."""
    if not _two_lines(entityA, entityB, workplane):
        raise ModelError("invalid arguments for ratio")
    return add_constraint(grouph, C.LENGTH_RATIO, workplane, value, E_NONE, E_NONE, entityA, entityB)


def symmetric(
    grouph: int,
    entityA: Slvs_Entity,
    entityB: Slvs_Entity,
    entityC: Slvs_Entity = E_NONE,
    workplane: Slvs_Entity = E_FREE_IN_3D,
) -> Slvs_Constraint:
    """Two points symmetric about a workplane (entityC) or, in ``workplane``, about a line (entityC)."""
    if _is_point(entityA) and _is_point(entityB) and _is_wp(entityC) and _free(workplane):
        plane = entityC if entityA["type"] == _P2 else E_FREE_IN_3D
        return add_constraint(grouph, C.SYMMETRIC, plane, 0.0, entityA, entityB, entityC)
    if entityA["type"] == _P2 and entityB["type"] == _P2 and _is_line(entityC):
        if _free(workplane):
            raise ModelError("3d workplane given for a 2d constraint")
        return add_constraint(grouph, C.SYMMETRIC_LINE, workplane, 0.0, entityA, entityB, entityC)
    raise ModelError(f"invalid arguments for symmetric: entities {entityA['h']}, {entityB['h']}, {entityC['h']}")


def symmetric_h(
    grouph: int, ptA: Slvs_Entity, ptB: Slvs_Entity, workplane: Slvs_Entity = E_FREE_IN_3D
) -> Slvs_Constraint:
    """Two points symmetric about the vertical axis of ``workplane`` (mirrored left to right)."""
    if _free(workplane):
        raise ModelError("3d workplane given for a 2d constraint")
    if not (ptA["type"] == _P2 and ptB["type"] == _P2):
        raise ModelError("invalid arguments for symmetric_h")
    return add_constraint(grouph, C.SYMMETRIC_HORIZ, workplane, 0.0, ptA, ptB)


def symmetric_v(
    grouph: int, ptA: Slvs_Entity, ptB: Slvs_Entity, workplane: Slvs_Entity = E_FREE_IN_3D
) -> Slvs_Constraint:
    """Two points symmetric about the horizontal axis of ``workplane`` (mirrored top to bottom)."""
    if _free(workplane):
        raise ModelError("3d workplane given for a 2d constraint")
    if not (ptA["type"] == _P2 and ptB["type"] == _P2):
        raise ModelError("invalid arguments for symmetric_v")
    return add_constraint(grouph, C.SYMMETRIC_VERT, workplane, 0.0, ptA, ptB)


def midpoint(
    grouph: int, ptA: Slvs_Entity, ptB: Slvs_Entity, workplane: Slvs_Entity = E_FREE_IN_3D
) -> Slvs_Constraint:
    """Point ptA is the midpoint of line ptB."""
    if not (_is_point(ptA) and _is_line(ptB) and _plane_or_free(workplane)):
        raise ModelError("invalid arguments for midpoint")
    return add_constraint(grouph, C.AT_MIDPOINT, workplane, 0.0, ptA, E_NONE, ptB)


def horizontal(
    grouph: int, entityA: Slvs_Entity, workplane: Slvs_Entity, entityB: Slvs_Entity = E_NONE
) -> Slvs_Constraint:
    """A line (or the two points entityA, entityB) horizontal in ``workplane``."""
    if _free(workplane):
        raise ModelError("horizontal is not supported in 3d")
    if _is_line(entityA):
        return add_constraint(grouph, C.HORIZONTAL, workplane, 0.0, E_NONE, E_NONE, entityA)
    if not (entityA["type"] == _P2 and entityB["type"] == _P2):
        raise ModelError("invalid arguments for horizontal")
    return add_constraint(grouph, C.HORIZONTAL, workplane, 0.0, entityA, entityB)


def vertical(
    grouph: int, entityA: Slvs_Entity, workplane: Slvs_Entity, entityB: Slvs_Entity = E_NONE
) -> Slvs_Constraint:
    """A line (or the two points entityA, entityB) vertical in ``workplane``."""
    if _free(workplane):
        raise ModelError("vertical is not supported in 3d")
    if _is_line(entityA):
        return add_constraint(grouph, C.VERTICAL, workplane, 0.0, E_NONE, E_NONE, entityA)
    if not (entityA["type"] == _P2 and entityB["type"] == _P2):
        raise ModelError("invalid arguments for vertical")
    return add_constraint(grouph, C.VERTICAL, workplane, 0.0, entityA, entityB)


def diameter(grouph: int, entityA: Slvs_Entity, value: float) -> Slvs_Constraint:
    """The diameter of a circle or arc."""
    if not (_is_round(entityA)):
        raise ModelError(f"invalid arguments for diameter: entity {entityA['h']}")
    return add_constraint(grouph, C.DIAMETER, E_FREE_IN_3D, value, E_NONE, E_NONE, entityA)


def same_orientation(grouph: int, entityA: Slvs_Entity, entityB: Slvs_Entity) -> Slvs_Constraint:
    """Two 3D normals have the same orientation."""
    if not (entityA["type"] == _N3 and entityB["type"] == _N3):
        raise ModelError("invalid arguments for same_orientation")
    return add_constraint(grouph, C.SAME_ORIENTATION, E_FREE_IN_3D, 0.0, E_NONE, E_NONE, entityA, entityB)


def angle(
    grouph: int,
    entityA: Slvs_Entity,
    entityB: Slvs_Entity,
    value: float,
    workplane: Slvs_Entity = E_FREE_IN_3D,
    inverse: bool = False,
) -> Slvs_Constraint:
    """The angle between two lines, in degrees (``inverse``: its supplement)."""
    if not _two_lines(entityA, entityB, workplane):
        raise ModelError("invalid arguments for angle")
    return add_constraint(
        grouph, C.ANGLE, workplane, value, E_NONE, E_NONE, entityA, entityB, E_NONE, E_NONE, int(inverse)
    )


def perpendicular(
    grouph: int,
    entityA: Slvs_Entity,
    entityB: Slvs_Entity,
    workplane: Slvs_Entity = E_FREE_IN_3D,
    inverse: bool = False,
) -> Slvs_Constraint:
    """Two lines are perpendicular."""
    if not _two_lines(entityA, entityB, workplane):
        raise ModelError("invalid arguments for perpendicular")
    return _quick(
        grouph, _PERPENDICULAR, workplane["h"], 0.0, 0, 0, entityA["h"], entityB["h"], 1 if inverse else 0
    )


def parallel(
    grouph: int, entityA: Slvs_Entity, entityB: Slvs_Entity, workplane: Slvs_Entity = E_FREE_IN_3D
) -> Slvs_Constraint:
    """Two lines are parallel."""
    if not _two_lines(entityA, entityB, workplane):
        raise ModelError("invalid arguments for parallel")
    return add_constraint(grouph, C.PARALLEL, workplane, 0.0, E_NONE, E_NONE, entityA, entityB)


def _same(a: int, b: int) -> bool:
    pa, pb = _m.point_values(a), _m.point_values(b)
    return len(pa) == len(pb) and all(abs(x - y) < 1e-6 for x, y in zip(pa, pb))


def _ends(e: Slvs_Entity) -> Tuple[int, int]:
    # Start and finish of an arc or a cubic.
    if e["type"] == _ARC:
        return e["point"][1], e["point"][2]
    return e["point"][0], e["point"][3]


def tangent(
    grouph: int, entityA: Slvs_Entity, entityB: Slvs_Entity, workplane: Slvs_Entity = E_FREE_IN_3D
) -> Slvs_Constraint:
    """An arc or cubic tangent to a line, or two curves tangent, where they share an end
    (which end is found from where the points are now)."""
    curve = (_ARC, _CUBIC)
    if entityA["type"] == _ARC and _is_line(entityB) or entityA["type"] == _CUBIC and _is_line(entityB):
        is_arc = entityA["type"] == _ARC
        if is_arc:
            if _free(workplane):
                raise ModelError("3d workplane given for a 2d constraint")
        s, f = _ends(entityA)
        l0, l1 = entityB["point"][0], entityB["point"][1]
        if _same(l0, s) or _same(l1, s):
            other = 0
        elif _same(l0, f) or _same(l1, f):
            other = 1
        else:
            raise ModelError(
                f"entities {entityA['h']} and {entityB['h']} must share an end before they are made tangent"
            )
        kind = C.ARC_LINE_TANGENT if is_arc else C.CUBIC_LINE_TANGENT
        return add_constraint(grouph, kind, workplane, 0.0, E_NONE, E_NONE, entityA, entityB, E_NONE, E_NONE, other)
    if entityA["type"] in curve and entityB["type"] in curve:
        if _free(workplane):
            raise ModelError("3d workplane given for a 2d constraint")
        (as_, af), (bs, bf) = _ends(entityA), _ends(entityB)
        for o1, o2, p, q in ((0, 0, as_, bs), (0, 1, as_, bf), (1, 0, af, bs), (1, 1, af, bf)):
            if _same(p, q):
                return add_constraint(
                    grouph, C.CURVE_CURVE_TANGENT, workplane, 0.0, E_NONE, E_NONE, entityA, entityB,
                    E_NONE, E_NONE, o1, o2,
                )
        raise ModelError(
            f"entities {entityA['h']} and {entityB['h']} must share an end before they are made tangent"
        )
    raise ModelError(f"invalid arguments for tangent: entities {entityA['h']} and {entityB['h']}")


def distance_proj(grouph: int, ptA: Slvs_Entity, ptB: Slvs_Entity, value: float) -> Slvs_Constraint:
    """The distance between two points projected onto a line (the free 3D form)."""
    if not (_is_point(ptA) and _is_point(ptB)):
        raise ModelError("invalid arguments for distance_proj")
    return add_constraint(grouph, C.PROJ_PT_DISTANCE, E_FREE_IN_3D, value, ptA, ptB)


def length_diff(
    grouph: int,
    entityA: Slvs_Entity,
    entityB: Slvs_Entity,
    value: float,
    workplane: Slvs_Entity = E_FREE_IN_3D,
) -> Slvs_Constraint:
    """The length of one line less the length of another."""
    ok = _lines(entityA, entityB) and _plane_or_free(workplane)
    if not (ok):
        raise ModelError("invalid arguments for length_diff")
    return add_constraint(
        grouph, C.LENGTH_DIFFERENCE, workplane, value, E_NONE, E_NONE, entityA, entityB
    )


def dragged(grouph: int, ptA: Slvs_Entity, workplane: Slvs_Entity = E_FREE_IN_3D) -> Slvs_Constraint:
    """The point stays where it is (a ``WHERE_DRAGGED`` constraint)."""
    if not (_is_point(ptA) and _plane_or_free(workplane)):
        raise ModelError("invalid arguments for dragged")
    return add_constraint(grouph, C.WHERE_DRAGGED, workplane, 0.0, ptA)


def mark_dragged(ptA: Slvs_Entity) -> None:
    """Marks a point as dragged: later solves move its coordinates as little as possible."""
    if not (_is_point(ptA)):
        raise ModelError(f"entity {ptA['h']} is not a point")
    n = 3 if ptA["type"] == _P3 else 2
    _dragged.update(ptA["param"][:n])


# ---------------------------------------------------------------- solving


def clear_sketch() -> None:
    """Empties the sketch: parameters, entities, constraints and dragged marks."""
    global _m
    _m = SlvsModel()
    _dragged.clear()


def solve_sketch(
    grouph: int, calculateFaileds: bool
) -> Union[Slvs_SolveResult, Tuple[Slvs_SolveResult, List[int]]]:
    """Solves group ``grouph``. Returns ``{"result", "dof", "nbad"}``; with
    ``calculateFaileds`` also the list of failed constraint handles, as a pair."""
    result, dof, failed = _m.solve(grouph, sorted(_dragged), bool(calculateFaileds))
    out: Slvs_SolveResult = {"result": result, "dof": dof, "nbad": len(failed)}
    if calculateFaileds:
        return out, list(failed)
    return out


def get_param_value(ph: int) -> float:
    """The value of parameter ``ph``."""
    return _m.value(ph)


def set_param_value(ph: int, value: float) -> None:
    """Sets the value of parameter ``ph``."""
    _m.set_value(ph, value)


def to_system() -> System:
    """The module's sketch as a ``loci.System`` (a copy): to check it, or save it as JSON."""
    return _m.to_system()
