"""``loci.Assembly``: components, mates, solves and stepped solves."""

import math
from pathlib import Path

import pytest

import loci

AXIS = {"type": "axis", "point": [0, 0, 0], "direction": [0, 0, 1]}


def door(angle: float = 30.0) -> loci.Assembly:
    a = loci.Assembly()
    a.add_component(
        "frame",
        grounded=True,
        references={"hinge": AXIS, "jamb": {"type": "face", "point": [0, 0, 0], "normal": [1, 0, 0]}},
    )
    a.add_component(
        "door",
        position=(0.1, 0.0, 0.2),
        references={"hinge": AXIS, "face": {"type": "face", "point": [0, 0, 0], "normal": [1, 0, 0]}},
    )
    a.add_mate("revolute", "frame.hinge", ("door", "hinge"), id="hinge")
    a.add_mate("angle", "frame.jamb", "door.face", value=angle, id="open")
    return a


def test_door_opens_to_the_angle() -> None:
    a = door(30.0)
    r = a.solve()
    assert r.ok and r.outcome == "okay" and r.dof == 0
    assert {m["id"]: m["status"] for m in r.mates} == {"hinge": "adjusted", "open": "adjusted"}
    t, q = a.pose("door")
    assert t == pytest.approx([0, 0, 0.2], abs=1e-9) or t[:2] == pytest.approx([0, 0], abs=1e-9)
    # The door's face normal turned 30 degrees about z from the jamb's.
    nx, ny, _ = (x - o for x, o in zip(a.to_world("door", [1, 0, 0]), a.to_world("door", [0, 0, 0])))
    assert abs(math.degrees(math.atan2(ny, nx))) == pytest.approx(30.0, abs=1e-6)
    assert a.measure_angle("open") == pytest.approx(30.0, abs=1e-6)
    assert "AssemblyResult(outcome=\"okay\", dof=0" in repr(r)
    assert r.status("open") == "adjusted"


def test_free_hinge_has_one_rotation() -> None:
    a = door()
    a2 = loci.Assembly()
    a2.add_component("frame", grounded=True, references={"hinge": AXIS})
    a2.add_component("door", position=(0.1, 0, 0), references={"hinge": AXIS})
    a2.add_mate("revolute", "frame.hinge", "door.hinge")
    r = a2.solve()
    assert r.ok and r.dof == 1
    door_report = [c for c in r.components if c["name"] == "door"][0]
    assert door_report["motions"] == ["rotates about axis (0, 0, 1) through (0, 0, 0)"]
    assert a.components == ["frame", "door"]


def test_stepped_solve_converges() -> None:
    a = door(45.0)
    converged, iterations = a.solve_stepped()
    assert converged and len(iterations) >= 1
    last = iterations[-1]
    assert len(last["poses"]) == 2 and max(last["errors"]) <= 1e-6


def test_conflicting_mates_are_named() -> None:
    a = door(30.0)
    a.add_mate("angle", "frame.jamb", "door.face", value=60.0, id="other")
    r = a.solve()
    assert not r.ok
    assert any("other" in c for c in r.conflicts)


def test_errors() -> None:
    a = loci.Assembly()
    a.add_component("frame", grounded=True)
    with pytest.raises(loci.ModelError):
        a.add_component("frame")
    with pytest.raises(loci.ModelError, match="needs a value"):
        a.add_mate("distance", "frame.frame", "frame.frame")
    with pytest.raises(loci.ModelError, match="selection"):
        a.add_mate("coincident", "frame", "frame.frame")
    with pytest.raises(loci.ModelError, match="reference \"bad\""):
        a.add_component("x", references={"bad": {"type": "nope"}})
    with pytest.raises(KeyError):
        a.pose("nobody")


def test_example_files_round_trip(examples: Path, tmp_path: Path) -> None:
    for f in sorted((examples / "assembly").glob("*.json")):
        a = loci.load(f)
        assert isinstance(a, loci.Assembly), f
        r = a.solve()
        assert r.ok, (f, r)
        out = tmp_path / f.name
        a.save(out)
        b = loci.load(out)
        assert isinstance(b, loci.Assembly)
        assert b.components == a.components
        for name in a.components:
            assert b.pose(name)[0] == pytest.approx(a.pose(name)[0], abs=1e-12)
