//! Bad input is an `Err` naming the object at fault, never a panic.

mod common;

use common::{Sketch, WP};
use loci::format::json::{JsonError, Problem};
use loci::{
    solve, Config, Constraint, ConstraintId, ConstraintKind as K, Entity, EntityId, EntityType,
    ModelError, ObjectId, Param, ParamId, PlaneRule, SolveError, System,
};
use proptest::prelude::*;

fn c_id(h: u32) -> ObjectId {
    ObjectId::Constraint(ConstraintId(h))
}

fn e_id(h: u32) -> ObjectId {
    ObjectId::Entity(EntityId(h))
}

/// Solving `sys` in group 2 must fail with `want`.
fn solve_err(mut sys: System, want: ModelError) {
    assert_eq!(sys.validate(), Err(want.clone()));
    let before: Vec<u64> = sys.params().iter().map(|p| p.val.to_bits()).collect();
    assert_eq!(sys.solve_group(2), Err(SolveError::Model(want)));
    let after: Vec<u64> = sys.params().iter().map(|p| p.val.to_bits()).collect();
    assert_eq!(before, after, "a rejected solve touches nothing");
}

/// Two points 301, 302 and the line 303 between them, in group 2.
fn base() -> Sketch {
    let mut s = Sketch::new();
    s.point(301, 2, [0.0, 0.0]);
    s.point(302, 2, [10.0, 1.0]);
    s.line(303, 2, 301, 302);
    s
}

#[test]
fn zero_handles_are_rejected_on_add() {
    let mut sys = System::new();
    sys.add_param(Param::new(1, 1, 0.0)).unwrap();
    assert_eq!(
        sys.add_param(Param::new(0, 1, 0.0)),
        Err(ModelError::ZeroHandle {
            what: "param",
            index: 1
        })
    );
    assert_eq!(
        sys.add_entity(Entity::distance(0, 1, None, 1)),
        Err(ModelError::ZeroHandle {
            what: "entity",
            index: 0
        })
    );
    assert_eq!(
        sys.add_constraint(Constraint::new(0, 1, K::WhereDragged)),
        Err(ModelError::ZeroHandle {
            what: "constraint",
            index: 0
        })
    );
    assert_eq!(sys.params().len(), 1, "nothing was added");
}

#[test]
fn duplicate_handles_are_rejected_on_add() {
    let mut s = base();
    assert_eq!(
        s.sys.add_param(Param::new(1000, 2, 3.0)),
        Err(ModelError::DuplicateHandle {
            object: ObjectId::Param(ParamId(1000))
        })
    );
    assert_eq!(
        s.sys.add_entity(Entity::line(303, 2, None, 302, 301)),
        Err(ModelError::DuplicateHandle { object: e_id(303) })
    );
    let c = s.on_points(2, K::PtPtDistance, 301, 302, 5.0);
    assert_eq!(
        s.sys
            .add_constraint(Constraint::new(c, 2, K::Vertical).with_entities([303, 0, 0, 0])),
        Err(ModelError::DuplicateHandle { object: c_id(c) })
    );
    assert_eq!(s.sys.constraints().len(), 1);
    assert_eq!(s.sys.constraint(c.into()).unwrap().kind, K::PtPtDistance);
    // The same checks guard whole-list construction.
    let p = Param::new(5, 1, 0.0);
    assert_eq!(
        System::from_parts(vec![p, p], vec![], vec![]).unwrap_err(),
        ModelError::DuplicateHandle {
            object: ObjectId::Param(ParamId(5))
        }
    );
}

#[test]
fn dangling_param_in_an_entity() {
    let mut s = base();
    s.sys
        .add_entity(Entity::point_2d(304, 2, WP, [1000, 4242]))
        .unwrap();
    solve_err(
        s.sys,
        ModelError::Dangling {
            owner: e_id(304),
            field: "params[1]",
            target: "param",
            handle: 4242,
        },
    );
}

#[test]
fn dangling_entity_in_an_entity_and_in_a_constraint() {
    let mut s = base();
    s.sys
        .add_entity(Entity::line(304, 2, None, 301, 999))
        .unwrap();
    solve_err(
        s.sys,
        ModelError::Dangling {
            owner: e_id(304),
            field: "points[1]",
            target: "entity",
            handle: 999,
        },
    );

    let mut s = base();
    let c = s.on_points(2, K::PtPtDistance, 301, 777, 5.0);
    solve_err(
        s.sys,
        ModelError::Dangling {
            owner: c_id(c),
            field: "pt_b",
            target: "entity",
            handle: 777,
        },
    );

    let mut s = base();
    let c = s.constrain(Constraint::new(0, 2, K::Horizontal).with_entities([303, 0, 0, 0]));
    s.sys.constraint_mut(c.into()).unwrap().workplane = Some(EntityId(555));
    solve_err(
        s.sys,
        ModelError::Dangling {
            owner: c_id(c),
            field: "workplane",
            target: "entity",
            handle: 555,
        },
    );
}

#[test]
fn a_circle_where_a_line_is_needed() {
    let mut s = base();
    let r = s.param(2, 4.0);
    s.sys.add_entity(Entity::normal_2d(310, 2, WP)).unwrap();
    s.sys
        .add_entity(Entity::distance(311, 2, Some(WP), r))
        .unwrap();
    s.sys
        .add_entity(Entity::circle(312, 2, Some(WP), 301, 310, 311))
        .unwrap();
    let c = s.on_entities(2, K::EqualLengthLines, 303, 312, 0.0);
    solve_err(
        s.sys,
        ModelError::WrongKind {
            owner: c_id(c),
            field: "entity_b",
            entity: EntityId(312),
            found: EntityType::Circle,
            expected: "a line segment",
        },
    );
}

#[test]
fn a_line_where_a_point_or_workplane_is_needed() {
    let mut s = base();
    s.sys
        .add_entity(Entity::point_2d(304, 2, 303, [1000, 1001]))
        .unwrap();
    solve_err(
        s.sys,
        ModelError::WrongKind {
            owner: e_id(304),
            field: "workplane",
            entity: EntityId(303),
            found: EntityType::LineSegment,
            expected: "a workplane",
        },
    );

    let mut s = base();
    let c = s.on_points(2, K::PtPtDistance, 301, 303, 5.0);
    solve_err(
        s.sys,
        ModelError::WrongKind {
            owner: c_id(c),
            field: "pt_b",
            entity: EntityId(303),
            found: EntityType::LineSegment,
            expected: "a point",
        },
    );

    // A line whose end is a line.
    let mut s = base();
    s.sys
        .add_entity(Entity::line(304, 2, None, 301, 303))
        .unwrap();
    solve_err(
        s.sys,
        ModelError::WrongKind {
            owner: e_id(304),
            field: "points[1]",
            entity: EntityId(303),
            found: EntityType::LineSegment,
            expected: "a point",
        },
    );
}

#[test]
fn a_workplane_built_from_the_wrong_parts() {
    let mut s = base();
    s.sys
        .add_entity(Entity::workplane(320, 2, 301, 102))
        .unwrap();
    solve_err(
        s.sys,
        ModelError::WrongKind {
            owner: e_id(320),
            field: "origin",
            entity: EntityId(301),
            found: EntityType::PointIn2d,
            expected: "a 3D point",
        },
    );
}

#[test]
fn a_line_from_a_point_to_itself() {
    // It has no direction: a point on it divided by its zero length, and read `inconsistent`
    // with a largest residual of 0 (not a number, left out of the largest).
    let mut s = base();
    s.line(320, 2, 302, 302);
    s.constrain(
        Constraint::new(0, 2, K::PtOnLine)
            .with_points(301, 0)
            .with_entities([320, 0, 0, 0]),
    );
    solve_err(
        s.sys,
        ModelError::WrongKind {
            owner: e_id(320),
            field: "points[1]",
            entity: EntityId(302),
            found: EntityType::PointIn2d,
            expected: "a point other than points[0]",
        },
    );
    // Two points at one place are a line of zero length, not a malformed one: it solves.
    let mut s = base();
    s.point(304, 2, [10.0, 1.0]);
    s.line(320, 2, 302, 304);
    s.on_points(2, K::PtPtDistance, 302, 304, 3.0);
    s.constrain(
        Constraint::new(0, 2, K::PtOnLine)
            .with_points(301, 0)
            .with_entities([320, 0, 0, 0]),
    );
    let r = s.sys.solve_group(2).unwrap();
    assert!(r.outcome.is_ok(), "{r:?}");
}
#[test]
fn a_2d_point_without_a_workplane_and_a_point_in_its_own_plane() {
    let mut s = base();
    let mut e = Entity::point_2d(304, 2, WP, [1000, 1001]);
    e.workplane = None;
    s.sys.add_entity(e).unwrap();
    solve_err(
        s.sys,
        ModelError::MissingField {
            owner: e_id(304),
            field: "workplane",
            expected: "a workplane",
        },
    );
    let mut s = base();
    s.sys
        .add_entity(Entity::point_2d(304, 2, 304, [1000, 1001]))
        .unwrap();
    solve_err(
        s.sys,
        ModelError::Cycle {
            entity: EntityId(304),
        },
    );
}

#[test]
fn a_constraint_missing_a_field_it_needs() {
    let mut s = base();
    let c = s.on_points(2, K::PtPtDistance, 301, 0, 5.0);
    solve_err(
        s.sys,
        ModelError::MissingField {
            owner: c_id(c),
            field: "pt_b",
            expected: "a point",
        },
    );
}

#[test]
fn non_finite_values_are_rejected() {
    let mut sys = System::new();
    for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let err = sys.add_param(Param::new(7, 1, v)).unwrap_err();
        assert!(
            matches!(err, ModelError::NonFinite { owner: ObjectId::Param(ParamId(7)), field: "val", value } if value.to_bits() == v.to_bits()),
            "{err:?}"
        );
        let err = sys
            .add_constraint(Constraint::new(3, 1, K::PtPtDistance).with_val(v))
            .unwrap_err();
        assert!(
            matches!(err, ModelError::NonFinite { owner, field: "val", .. } if owner == c_id(3)),
            "{err:?}"
        );
    }
    assert!(sys.params().is_empty() && sys.constraints().is_empty());
}

#[test]
fn non_finite_values_set_after_adding_are_caught_by_the_solve() {
    // A constraint value changed in place.
    let mut s = base();
    let c = s.on_points(2, K::PtPtDistance, 301, 302, 5.0);
    s.sys.constraint_mut(c.into()).unwrap().val = f64::INFINITY;
    solve_err(
        s.sys,
        ModelError::NonFinite {
            owner: c_id(c),
            field: "val",
            value: f64::INFINITY,
        },
    );

    // A parameter value changed in place, in the solved group and as a constant.
    for (h, group) in [(1001u32, 2u32), (4, 1)] {
        let mut s = base();
        s.on_points(2, K::PtPtDistance, 301, 302, 5.0);
        assert!(s.sys.set_value(h.into(), f64::NAN));
        let err = s.sys.solve_group(2).unwrap_err();
        assert!(
            matches!(&err, SolveError::Model(ModelError::NonFinite { owner: ObjectId::Param(p), field: "val", value }) if p.0 == h && value.is_nan()),
            "param {h} (group {group}): {err:?}"
        );
    }
}

#[test]
fn values_too_large_to_solve_with_are_rejected() {
    // A point 1e160 from another: the distance's square overflowed to infinity, and the
    // solve read `inconsistent`, naming the distance.
    let mut sys = System::new();
    for v in [1e160, -1e101, f64::MAX] {
        let err = sys.add_param(Param::new(7, 1, v)).unwrap_err();
        assert_eq!(
            err,
            ModelError::OutOfRange {
                owner: ObjectId::Param(ParamId(7)),
                field: "val",
                value: v
            }
        );
        let err = sys
            .add_constraint(Constraint::new(3, 1, K::PtPtDistance).with_val(v))
            .unwrap_err();
        assert!(
            matches!(err, ModelError::OutOfRange { owner, field: "val", .. } if owner == c_id(3)),
            "{err:?}"
        );
    }
    assert!(sys.params().is_empty() && sys.constraints().is_empty());
    assert!(sys
        .add_param(Param::new(7, 1, -loci::MAX_MAGNITUDE))
        .is_ok());

    // Set in place, caught by the solve; and up to the limit, solved.
    let mut s = base();
    s.on_points(2, K::PtPtDistance, 301, 302, 5.0);
    assert!(s.sys.set_value(1000.into(), 1e160));
    solve_err(
        s.sys,
        ModelError::OutOfRange {
            owner: ObjectId::Param(ParamId(1000)),
            field: "val",
            value: 1e160,
        },
    );
    let mut s = base();
    s.on_points(2, K::PtPtDistance, 301, 302, 5.0);
    assert!(s.sys.set_value(1000.into(), 1e100));
    let r = s.sys.solve_group(2).unwrap();
    assert!(r.outcome.is_ok(), "{r:?}");
    assert!(s.sys.params().iter().all(|p| p.val.is_finite()));
}

#[test]
fn two_d_only_constraints_need_a_workplane() {
    let mut s = base();
    let r = s.param(2, 4.0);
    s.sys.add_entity(Entity::normal_2d(310, 2, WP)).unwrap();
    s.point(311, 2, [0.0, 4.0]);
    s.point(312, 2, [4.0, 0.0]);
    s.sys
        .add_entity(Entity::arc(313, 2, WP, 310, 301, 312, 311))
        .unwrap();
    let _ = r;
    let cases: Vec<Constraint> = vec![
        Constraint::new(1, 2, K::Horizontal).with_entities([303, 0, 0, 0]),
        Constraint::new(1, 2, K::Vertical).with_points(301, 302),
        Constraint::new(1, 2, K::SymmetricHoriz).with_points(301, 302),
        Constraint::new(1, 2, K::SymmetricVert).with_points(301, 302),
        Constraint::new(1, 2, K::SymmetricLine)
            .with_points(311, 312)
            .with_entities([303, 0, 0, 0]),
        Constraint::new(1, 2, K::ArcLineTangent).with_entities([313, 303, 0, 0]),
        Constraint::new(1, 2, K::CurveCurveTangent).with_entities([313, 313, 0, 0]),
    ];
    let required: Vec<K> = K::ALL
        .iter()
        .copied()
        .filter(|k| k.signature().plane == PlaneRule::Required)
        .collect();
    let mut covered: Vec<K> = cases.iter().map(|c| c.kind).collect();
    covered.sort_unstable();
    let mut required = required;
    required.sort_unstable();
    assert_eq!(covered, required, "every 2D-only type is tried");
    for c in cases {
        let kind = c.kind;
        let mut sys = s.sys.clone();
        sys.add_constraint(c).unwrap();
        solve_err(
            sys,
            ModelError::NeedsWorkplane {
                constraint: ConstraintId(1),
                kind,
            },
        );
    }
}

#[test]
fn unknown_dragged_parameter() {
    let mut s = base();
    s.on_points(2, K::PtPtDistance, 301, 302, 5.0);
    assert_eq!(
        solve(
            &mut s.sys,
            2.into(),
            &[ParamId(1000), ParamId(31337)],
            &Config::default()
        ),
        Err(SolveError::UnknownDragged(31337))
    );
}

#[test]
fn bad_options() {
    let mut s = base();
    s.on_points(2, K::PtPtDistance, 301, 302, 5.0);
    let d = Config::default;
    let cases = [
        ("tolerance", d().with_tolerance(0.0), 0.0),
        ("tolerance", d().with_tolerance(-1e-9), -1e-9),
        (
            "tolerance",
            d().with_tolerance(f64::INFINITY),
            f64::INFINITY,
        ),
        ("dragged_scale", d().with_dragged_scale(0.0), 0.0),
        ("dragged_scale", d().with_dragged_scale(1.5), 1.5),
        ("rank_tolerance", d().with_rank_tolerance(0.0), 0.0),
        ("rank_tolerance", d().with_rank_tolerance(1.0), 1.0),
    ];
    for (name, cfg, value) in cases {
        let err = solve(&mut s.sys, 2.into(), &[], &cfg).unwrap_err();
        assert!(
            matches!(err, SolveError::BadOption { name: n, value: v, .. } if n == name && v == value),
            "{name}: {err:?}"
        );
        assert!(err.to_string().contains(name));
    }
    let nan = d().with_tolerance(f64::NAN);
    assert!(matches!(
        solve(&mut s.sys, 2.into(), &[], &nan),
        Err(SolveError::BadOption {
            name: "tolerance",
            ..
        })
    ));
}

#[test]
fn error_messages_name_the_object() {
    let e = ModelError::Dangling {
        owner: c_id(12),
        field: "pt_b",
        target: "entity",
        handle: 777,
    };
    assert_eq!(
        e.to_string(),
        "constraint 12: pt_b refers to entity 777, which does not exist"
    );
    let e = ModelError::NeedsWorkplane {
        constraint: ConstraintId(4),
        kind: K::Horizontal,
    };
    assert!(e.to_string().starts_with("constraint 4 (horizontal)"));
}

const TRIANGLE: &str = include_str!("../../../examples/triangle.json");

fn json_err(text: &str) -> String {
    Problem::from_json(text).unwrap_err().to_string()
}

/// `text` with the `n`th (from 0) occurrence of `old` replaced by `new`.
fn edit(text: &str, old: &str, new: &str, n: usize) -> String {
    let (i, _) = text
        .match_indices(old)
        .nth(n)
        .unwrap_or_else(|| panic!("no {old:?} #{n}"));
    format!("{}{new}{}", &text[..i], &text[i + old.len()..])
}

/// `line L column C` of the first `needle` in `text` (1-based, characters).
fn at(text: &str, needle: &str) -> String {
    let i = text.find(needle).unwrap_or_else(|| panic!("no {needle:?}"));
    let before = &text[..i];
    let line = before.matches('\n').count() + 1;
    let column = before[before.rfind('\n').map_or(0, |j| j + 1)..]
        .chars()
        .count()
        + 1;
    format!("line {line} column {column}")
}

/// The place of the object whose text starts with `{` before `marker` (its first field).
fn object_at(text: &str, marker: &str) -> String {
    let i = text.find(marker).unwrap_or_else(|| panic!("no {marker:?}"));
    let open = text[..i].rfind('{').unwrap();
    at(text, &text[open..])
}

#[test]
fn malformed_json_is_an_error_with_a_position() {
    assert!(Problem::from_json(TRIANGLE).is_ok());
    for cut in [
        1,
        TRIANGLE.len() / 3,
        TRIANGLE.len() / 2,
        TRIANGLE.len() - 3,
    ] {
        let msg = json_err(&TRIANGLE[..cut]);
        assert!(msg.contains("line") && msg.contains("column"), "{msg}");
        assert!(msg.contains("cut short"), "{msg}");
    }
    assert_eq!(
        json_err(""),
        "the file is empty; expected a JSON object with \"params\", \"entities\" and \
         \"constraints\""
    );
    assert_eq!(
        json_err("[]"),
        "line 1 column 1: expected an object with \"params\", \"entities\", \"constraints\" \
         and \"solve\", found an empty array"
    );
    assert_eq!(
        json_err("{\"params\": 3}"),
        "line 1 column 12: field \"params\": expected an array of params, found 3"
    );
    assert_eq!(
        json_err(&format!("{TRIANGLE}xyz")),
        "line 205 column 2: invalid JSON: trailing characters"
    );
}

#[test]
fn a_wrong_field_is_reported_where_it_is_naming_object_and_field() {
    // The constraint with handle 3 is at line 174 of 204; the error used to be reported at
    // the end of the file, naming nothing.
    let text = edit(TRIANGLE, "\"pt_a\": 301", "\"pt_a\": \"abc\"", 1);
    assert_eq!(
        json_err(&text),
        format!(
            "{}: constraint 3 (pt_pt_distance): field \"pt_a\": expected an entity handle (a \
             positive integer), found \"abc\"",
            at(&text, "\"abc\"")
        )
    );
    assert!(json_err(&text).starts_with("line 179 column 12: "));
    let e = Problem::from_json(&text).unwrap_err();
    assert_eq!(
        (e.object.as_str(), e.field.as_str()),
        ("constraint 3 (pt_pt_distance)", "pt_a")
    );

    let cases = [
        (
            edit(TRIANGLE, "\"val\": 30", "\"val\": \"30\"", 0),
            "\"30\"",
            "constraint 3 (pt_pt_distance): field \"val\": expected a number, found \"30\" \
             (numbers are written without quotes)",
        ),
        (
            edit(TRIANGLE, "\"val\": 30", "\"val\": {\"a\": [1, 2]}", 0),
            "{\"a\"",
            "constraint 3 (pt_pt_distance): field \"val\": expected a number, found an object",
        ),
        (
            edit(TRIANGLE, "\"val\": 0.5", "\"val\": 1e999", 0),
            "1e999",
            "param 11: field \"val\": expected a finite number, found 1e999, which is too \
             large for a double",
        ),
        (
            edit(TRIANGLE, "\"val\": 0.5", "\"val\": null", 0),
            "null",
            "param 11: field \"val\": expected a number, found null",
        ),
        (
            edit(TRIANGLE, "\"h\": 301,", "\"h\": -301,", 0),
            "-301",
            "entities[3]: field \"h\": expected an entity handle (a positive integer), found -301",
        ),
        (
            edit(TRIANGLE, "\"h\": 301,", "\"h\": 99999999999,", 0),
            "99999999999",
            "entities[3]: field \"h\": expected an entity handle (a positive integer), found \
             99999999999, larger than the largest handle, 4294967295",
        ),
        (
            edit(TRIANGLE, "\"h\": 301,", "\"h\": 301.5,", 0),
            "301.5",
            "entities[3]: field \"h\": expected an entity handle (a positive integer), found 301.5",
        ),
        (
            edit(TRIANGLE, "\"h\": 302,", "\"h\": 0,", 0),
            "0,\n   \"group\": 2,\n   \"type\": \"point_in_2d\"",
            "entities[4]: field \"h\": expected an entity handle (a positive integer), found 0: \
             handles start at 1",
        ),
        (
            edit(
                TRIANGLE,
                "\"workplane\": 200,\n   \"pt_a\": 301\n",
                "\"workplane\": \"wp\",\n   \"pt_a\": 301\n",
                0,
            ),
            "\"wp\"",
            "constraint 1 (where_dragged): field \"workplane\": expected an entity handle (a \
             positive integer), found \"wp\"",
        ),
        (
            edit(
                TRIANGLE,
                "\"val\": 30",
                "\"val\": 30, \"other\": \"yes\"",
                0,
            ),
            "\"yes\"",
            "constraint 3 (pt_pt_distance): field \"other\": expected true or false, found \"yes\"",
        ),
        (
            edit(TRIANGLE, "[\n    301,\n    302\n   ]", "\"301\"", 0),
            "\"301\"",
            "entity 304 (line_segment): field \"points\": expected an array of 2 entity handles \
             [start, end], found \"301\"",
        ),
        (
            edit(TRIANGLE, "[\n    301,\n    302\n   ]", "[301]", 0),
            "[301]",
            "entity 304 (line_segment): field \"points\": expected an array of 2 entity handles \
             [start, end], found an array of 1 item",
        ),
        (
            edit(TRIANGLE, "    11,\n    12\n", "    11,\n    true\n", 0),
            "true\n",
            "entity 301 (point_in_2d): field \"params[1]\": expected a param handle (a positive \
             integer), found true",
        ),
        (
            edit(TRIANGLE, "  {\n   \"h\": 101,", "  7, {\n   \"h\": 101,", 0),
            "7, {",
            "entities[0]: expected an object, found 7",
        ),
        (
            edit(TRIANGLE, "\"group\": 2\n }", "\"group\": \"two\"\n }", 0),
            "\"two\"",
            "solve: field \"group\": expected a group (an integer from 0 to 4294967295), found \
             \"two\"",
        ),
        (
            edit(
                TRIANGLE,
                "\"group\": 2\n }",
                "\"group\": 2, \"options\": {\"tolerance\": \"small\"}\n }",
                0,
            ),
            "\"small\"",
            "solve: field \"options.tolerance\": expected a number, found \"small\"",
        ),
        (
            edit(
                TRIANGLE,
                "\"group\": 2\n }",
                "\"group\": 2, \"dragged\": [11, -1]\n }",
                0,
            ),
            "-1]",
            "solve: field \"dragged[1]\": expected a param handle (a positive integer), found -1",
        ),
    ];
    for (text, value, want) in cases {
        assert_eq!(json_err(&text), format!("{}: {want}", at(&text, value)));
    }
}

#[test]
fn a_missing_field_is_reported_at_its_object() {
    let text = edit(TRIANGLE, "\"h\": 3,\n   \"group\": 2,", "\"h\": 3,", 0);
    assert_eq!(
        json_err(&text),
        format!(
            "{}: constraint 3 (pt_pt_distance): field \"group\" is missing; it must be a group \
             (an integer from 0 to 4294967295)",
            object_at(&text, "\"val\": 30")
        )
    );
    assert!(
        json_err(&text).starts_with("line 174 column 3: "),
        "{}",
        json_err(&text)
    );
    let text = edit(TRIANGLE, "\"h\": 301,\n", "", 0);
    assert_eq!(
        json_err(&text),
        format!(
            "{}: entities[3]: field \"h\" is missing; it must be an entity handle (a positive \
             integer)",
            object_at(&text, "\"group\": 2,\n   \"type\": \"point_in_2d\"")
        )
    );
    let text = edit(TRIANGLE, "\"points\": [\n    301,\n    302\n   ],", "", 0);
    assert_eq!(
        json_err(&text),
        format!(
            "{}: entity 304 (line_segment): field \"points\" is missing; it must be an array of \
             2 entity handles [start, end]",
            object_at(&text, "\"h\": 304,")
        )
    );
    let text = edit(TRIANGLE, "\"type\": \"pt_pt_distance\",", "", 0);
    let msg = json_err(&text);
    assert!(
        msg.starts_with(&format!(
            "{}: constraint 3: field \"type\" is missing; it must be one of \
             \"points_coincident\", \"pt_pt_distance\", ",
            object_at(&text, "\"val\": 30")
        )),
        "{msg}"
    );
}

#[test]
fn type_names_a_numeric_or_unknown_type_lists_the_accepted_names() {
    let text = edit(TRIANGLE, "\"type\": \"line_segment\"", "\"type\": 3", 0);
    assert_eq!(
        json_err(&text),
        format!(
            "{}: entity 304: field \"type\": expected one of \"point_in_3d\", \"point_in_2d\", \
             \"point_n_trans\", \"point_n_rot_trans\", \"normal_n_rot\", \"normal_in_3d\", \
             \"normal_in_2d\", \"distance\", \"workplane\", \"line_segment\", \"cubic\", \
             \"circle\", \"arc_of_circle\", found 3",
            at(&text, "3,\n   \"points\"")
        )
    );
    let text = edit(TRIANGLE, "\"type\": \"pt_pt_distance\"", "\"type\": 3", 0);
    let msg = json_err(&text);
    let names: Vec<String> = loci::ConstraintKind::ALL
        .iter()
        .map(|k| format!("\"{}\"", k.name()))
        .collect();
    assert_eq!(
        msg,
        format!(
            "{}: constraint 3: field \"type\": expected one of {}, found 3",
            at(&text, "3,\n   \"workplane\": 200,\n   \"pt_a\": 301"),
            names.join(", ")
        )
    );
    let text = edit(TRIANGLE, "\"horizontal\"", "\"Horizontal\"", 0);
    assert!(
        json_err(&text).contains(
            "constraint 2: field \"type\": unknown constraint type \"Horizontal\" (did you mean \
             \"horizontal\"?); expected one of \"points_coincident\""
        ),
        "{}",
        json_err(&text)
    );
}

#[test]
fn unknown_type_names_are_named_in_the_error() {
    let text = TRIANGLE.replace("\"line_segment\"", "\"spline_of_doom\"");
    let msg = json_err(&text);
    assert!(msg.contains("spline_of_doom"), "{msg}");
    let text = TRIANGLE.replacen("\"horizontal\"", "\"kinda_horizontal\"", 1);
    let msg = json_err(&text);
    assert!(msg.contains("kinda_horizontal"), "{msg}");
    assert!(
        msg.contains("points_coincident"),
        "lists the known types: {msg}"
    );
}

#[test]
fn unknown_fields_are_errors_naming_the_object() {
    let cases = [
        (
            edit(TRIANGLE, "\"val\": 0.5", "\"val\": 0.5, \"colour\": 1", 0),
            "\"colour\"",
            "param 11: unknown field \"colour\"; a param has \"h\", \"group\" and \"val\"",
        ),
        (
            edit(
                TRIANGLE,
                "\"h\": 301,",
                "\"h\": 301, \"pramas\": [1, 2],",
                0,
            ),
            "\"pramas\"",
            "entity 301 (point_in_2d): unknown field \"pramas\" (did you mean \"params\"?); a \
             point_in_2d entity has \"h\", \"group\", \"type\", \"workplane\" and \"params\"",
        ),
        (
            edit(
                TRIANGLE,
                "\"h\": 301,",
                "\"h\": 301, \"points\": [1, 2],",
                0,
            ),
            "\"points\"",
            "entity 301 (point_in_2d): field \"points\" is not one a point_in_2d entity has; a \
             point_in_2d entity has \"h\", \"group\", \"type\", \"workplane\" and \"params\"",
        ),
        (
            edit(TRIANGLE, "\"pt_b\": 302", "\"ptb\": 302", 0),
            "\"ptb\"",
            "constraint 3 (pt_pt_distance): unknown field \"ptb\" (did you mean \"pt_b\"?); a \
             constraint has \"h\", \"group\", \"type\", \"workplane\", \"val\", \"pt_a\", \
             \"pt_b\", \"entity_a\", \"entity_b\", \"entity_c\", \"entity_d\", \"other\", \
             \"other2\", \"reference\" and \"signed\"",
        ),
        (
            edit(TRIANGLE, "\"params\": [", "\"parms\": [], \"params\": [", 0),
            "\"parms\"",
            "unknown field \"parms\" (did you mean \"params\"?); a problem has \"params\", \
             \"entities\", \"constraints\" and \"solve\"",
        ),
        (
            edit(
                TRIANGLE,
                "\"group\": 2\n }",
                "\"group\": 2, \"bogus\": 1\n }",
                0,
            ),
            "\"bogus\"",
            "solve: unknown field \"bogus\"; \"solve\" has \"group\", \"dragged\", \
             \"calculate_failed\" and \"options\"",
        ),
        (
            edit(
                TRIANGLE,
                "\"group\": 2\n }",
                "\"group\": 2, \"options\": {\"speed\": 11}\n }",
                0,
            ),
            "\"speed\"",
            "solve: unknown field \"options.speed\"; \"options\" has \"tolerance\", \
             \"max_iterations\", \"dragged_scale\", \"rank_tolerance\", \
             \"verify_conflicts_up_to\", \"nearest\" and \"solvespace_angles\"",
        ),
        (
            edit(TRIANGLE, "\"h\": 11,", "\"h\": 11, \"h\": 12,", 0),
            "12,",
            "params[7]: field \"h\" appears twice",
        ),
    ];
    for (text, value, want) in cases {
        // An unknown field is reported at its value.
        let i = text.find(value).unwrap();
        let key_or_value = if value.starts_with('"') && text[i + value.len()..].starts_with(':') {
            // The unknown field's value follows its name.
            let rest = &text[i + value.len() + 1..];
            let skip = rest.len() - rest.trim_start().len();
            &text[i + value.len() + 1 + skip..]
        } else {
            &text[i..]
        };
        assert_eq!(
            json_err(&text),
            format!("{}: {want}", at(&text, key_or_value))
        );
    }
}

#[test]
fn zero_and_repeated_handles_in_json_are_named() {
    let text = TRIANGLE.replacen("\"h\": 11,", "\"h\": 0,", 1);
    let msg = json_err(&text);
    assert!(msg.contains("params[7]: field \"h\""), "{msg}");
    assert!(msg.contains("found 0: handles start at 1"), "{msg}");
    let text = TRIANGLE.replacen("\"h\": 12,", "\"h\": 11,", 1);
    assert_eq!(
        json_err(&text),
        format!(
            "{}: param 11: handle 11 is already used by the param at {} (each param needs a \
             handle of its own)",
            at(&text, "11,\n   \"group\": 2,\n   \"val\": -0.3"),
            object_at(&text, "\"h\": 11,")
        )
    );
    let e = Problem::from_json(&text).unwrap_err();
    assert_eq!(
        e.model.as_deref(),
        Some(&ModelError::DuplicateHandle {
            object: ObjectId::Param(ParamId(11))
        })
    );
    let text = TRIANGLE.replacen("\"h\": 302,", "\"h\": 301,", 1);
    let msg = json_err(&text);
    assert!(
        msg.contains("entity 301 (point_in_2d): handle 301 is already used by the entity at line 98 column 3"),
        "{msg}"
    );
}

#[test]
fn the_reader_reads_every_example_as_serde_does() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_none_or(|x| x != "json") {
            continue;
        }
        let text = std::fs::read_to_string(&p).unwrap();
        let mine = Problem::from_json(&text).unwrap();
        let serde: Problem = serde_json::from_str(&text).unwrap();
        assert_eq!(mine.to_json(), serde.to_json(), "{}", p.display());
        // And what loci writes reads back the same.
        let again = Problem::from_json(&mine.to_json()).unwrap();
        assert_eq!(again.to_json(), mine.to_json(), "{}", p.display());
    }
}

#[test]
fn a_reference_error_in_json_surfaces_at_solve() {
    let text = TRIANGLE.replacen("\"pt_a\": 301", "\"pt_a\": 399", 1);
    let mut p = Problem::from_json(&text).unwrap();
    let req = p.request();
    let err = solve(&mut p.system, req.group, &req.dragged, &req.config()).unwrap_err();
    assert_eq!(
        err,
        SolveError::Model(ModelError::Dangling {
            owner: c_id(1),
            field: "pt_a",
            target: "entity",
            handle: 399,
        })
    );
    // Placed in the file, with the constraint's type.
    let e = JsonError::from_solve(&text, &p.system, &err);
    assert_eq!(
        e.to_string(),
        format!(
            "{}: constraint 1 (where_dragged): field \"pt_a\": entity 399 does not exist",
            at(&text, "399")
        )
    );
    assert_eq!(e.field, "pt_a");
}

#[test]
fn model_errors_found_at_solve_are_placed_in_the_file() {
    let solve_msg = |text: &str| {
        let mut p = Problem::from_json(text).unwrap();
        let req = p.request();
        let err = solve(&mut p.system, req.group, &req.dragged, &req.config()).unwrap_err();
        JsonError::from_solve(text, &p.system, &err).to_string()
    };
    // A dangling parameter inside an array: placed at the item.
    let text = edit(TRIANGLE, "    13,\n    14\n", "    13,\n    99\n", 0);
    assert_eq!(
        solve_msg(&text),
        format!(
            "{}: entity 302 (point_in_2d): field \"params[1]\": param 99 does not exist",
            at(&text, "99\n")
        )
    );
    // An entity of the wrong type.
    let text = edit(
        TRIANGLE,
        "\"pt_a\": 301,\n   \"pt_b\": 302",
        "\"pt_a\": 304,\n   \"pt_b\": 302",
        0,
    );
    assert_eq!(
        solve_msg(&text),
        format!(
            "{}: constraint 3 (pt_pt_distance): field \"pt_a\": entity 304 is a line_segment, \
             but a point is expected",
            at(&text, "304,\n   \"pt_b\"")
        )
    );
    // A field the type needs is absent: placed at the object.
    let text = edit(TRIANGLE, ",\n   \"entity_a\": 304", "", 0);
    assert_eq!(
        solve_msg(&text),
        format!(
            "{}: constraint 2 (horizontal): field \"entity_a\" is missing; a horizontal \
             constraint needs a line segment in \"entity_a\", or two points in \"pt_a\" and \
             \"pt_b\"",
            object_at(
                &text,
                "\"h\": 2,\n   \"group\": 2,\n   \"type\": \"horizontal\""
            )
        )
    );
    // A 2D-only constraint without a workplane.
    let text = edit(
        TRIANGLE,
        "\"workplane\": 200,\n   \"entity_a\": 304",
        "\"entity_a\": 304",
        0,
    );
    assert_eq!(
        solve_msg(&text),
        format!(
            "{}: constraint 2 (horizontal): field \"workplane\" is missing; a horizontal \
             constraint applies only in a workplane, so it needs one",
            object_at(
                &text,
                "\"h\": 2,\n   \"group\": 2,\n   \"type\": \"horizontal\""
            )
        )
    );
    // A dragged parameter that does not exist, and an option out of range.
    let text = edit(
        TRIANGLE,
        "\"group\": 2\n }",
        "\"group\": 2, \"dragged\": [11, 77]\n }",
        0,
    );
    assert_eq!(
        solve_msg(&text),
        format!(
            "{}: solve: field \"dragged\": param 77 does not exist",
            at(&text, "77]")
        )
    );
    let text = edit(
        TRIANGLE,
        "\"group\": 2\n }",
        "\"group\": 2, \"options\": {\"tolerance\": 0}\n }",
        0,
    );
    assert_eq!(
        solve_msg(&text),
        format!(
            "{}: solve: field \"options.tolerance\": 0 is out of range: expected a positive \
             finite number",
            at(&text, "0}")
        )
    );
}

#[test]
fn json_errors_carry_no_source_to_repeat() {
    let e = Problem::from_json("{\"params\": 3}").unwrap_err();
    assert!(std::error::Error::source(&e).is_none());
}

/// One random object: an entity or constraint with small random handles everywhere.
#[derive(Clone, Debug)]
enum Garbage {
    Param(u32, u32, f64),
    Entity(u32, u32, Option<u32>, u8, [u32; 4]),
    Constraint(u32, u32, usize, Option<u32>, f64, [u32; 6], bool, bool),
}

fn garbage() -> impl Strategy<Value = Garbage> {
    let h = 0u32..12;
    let g = 0u32..4;
    let val = prop_oneof![
        -20.0f64..20.0,
        Just(0.0),
        Just(1.0),
        Just(-1.0),
        Just(1e300),
        Just(f64::NAN),
    ];
    prop_oneof![
        (h.clone(), g.clone(), val.clone()).prop_map(|(h, g, v)| Garbage::Param(h, g, v)),
        (
            h.clone(),
            g.clone(),
            proptest::option::of(h.clone()),
            0u8..10,
            [h.clone(), h.clone(), h.clone(), h.clone()]
        )
            .prop_map(|(h, g, w, k, r)| Garbage::Entity(h, g, w, k, r)),
        (
            h.clone(),
            g,
            0..K::ALL.len(),
            proptest::option::of(h.clone()),
            val,
            [h.clone(), h.clone(), h.clone(), h.clone(), h.clone(), h],
            any::<bool>(),
            any::<bool>()
        )
            .prop_map(|(h, g, k, w, v, f, o, o2)| Garbage::Constraint(h, g, k, w, v, f, o, o2)),
    ]
}

fn entity_of(h: u32, g: u32, w: Option<u32>, kind: u8, r: [u32; 4]) -> Entity {
    let mut e = match kind {
        0 => Entity::point_3d(h, g, [r[0], r[1], r[2]]),
        1 => Entity::point_2d(h, g, r[3], [r[0], r[1]]),
        2 => Entity::normal_3d(h, g, r),
        3 => Entity::normal_2d(h, g, r[0]),
        4 => Entity::distance(h, g, w, r[0]),
        5 => Entity::workplane(h, g, r[0], r[1]),
        6 => Entity::line(h, g, w, r[0], r[1]),
        7 => Entity::cubic(h, g, w, r),
        8 => Entity::circle(h, g, w, r[0], r[1], r[2]),
        _ => Entity::arc(h, g, r[3], r[0], r[1], r[2], r[3]),
    };
    if w.is_some() && kind % 2 == 0 {
        e.workplane = w.map(EntityId);
    }
    e
}

fn build(items: &[Garbage]) -> System {
    let mut sys = System::new();
    for it in items {
        // Adding may fail (zero or repeated handle, NaN): that must be an error, not a panic.
        let _ = match *it {
            Garbage::Param(h, g, v) => sys.add_param(Param::new(h, g, v)).map(|_| ()),
            Garbage::Entity(h, g, w, k, r) => sys.add_entity(entity_of(h, g, w, k, r)).map(|_| ()),
            Garbage::Constraint(h, g, k, w, v, f, o, o2) => {
                let mut c = Constraint::new(h, g, K::ALL[k])
                    .in_workplane(w)
                    .with_points(f[0], f[1])
                    .with_entities([f[2], f[3], f[4], f[5]])
                    .with_flags(o, o2)
                    .with_val(v);
                if o && o2 {
                    c = c.as_reference();
                }
                sys.add_constraint(c).map(|_| ())
            }
        };
    }
    sys
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn random_garbage_never_panics(
        items in proptest::collection::vec(garbage(), 0..40),
        group in 0u32..4,
        dragged in proptest::collection::vec(0u32..14, 0..3),
        iters in 0usize..60,
    ) {
        let mut sys = build(&items);
        let valid = sys.validate();
        let dragged: Vec<ParamId> = dragged.into_iter().map(ParamId).collect();
        let cfg = Config::default().with_max_iterations(iters);
        let before = sys.clone();
        match solve(&mut sys, group.into(), &dragged, &cfg) {
            Ok(rep) => {
                prop_assert!(valid.is_ok(), "solved an invalid model: {:?}", valid);
                prop_assert!(rep.dof <= rep.unknowns);
                if rep.outcome.is_ok() {
                    prop_assert!(rep.residual <= cfg.tolerance, "okay with residual {}", rep.residual);
                } else {
                    prop_assert!(!rep.failed.is_empty() || !rep.failed_entities.is_empty());
                    prop_assert_eq!(sys.params(), before.params());
                }
                for p in sys.params() {
                    prop_assert!(p.val.is_finite(), "{} became {}", p.h, p.val);
                }
            }
            Err(SolveError::Model(e)) => prop_assert_eq!(Err(e), valid.clone()),
            Err(SolveError::UnknownDragged(h)) => {
                prop_assert!(sys.param(ParamId(h)).is_none());
            }
            Err(SolveError::UnknownGroup { group: g, existing }) => {
                prop_assert_eq!(g, group.into());
                prop_assert!(!existing.contains(&g));
                prop_assert_eq!(existing, sys.groups());
            }
            Err(e) => prop_assert!(false, "unexpected error {e}"),
        }
        // The JSON round trip of whatever was built parses back to the same lists.
        let text = serde_json::to_string(&before).unwrap();
        let back: System = serde_json::from_str(&text).unwrap();
        prop_assert_eq!(back.params().len(), before.params().len());
        prop_assert_eq!(back.constraints(), before.constraints());
        // So does loci's own reader, and a model error is placed at its object.
        let problem = Problem { system: before.clone(), solve: None }.to_json();
        let read = Problem::from_json(&problem);
        prop_assert!(read.is_ok(), "{:?}", read.err());
        let read = read.unwrap();
        prop_assert_eq!(read.system.constraints(), before.constraints());
        if let Err(e) = &valid {
            let placed = JsonError::from_model(&problem, &before, e);
            prop_assert!(placed.position.is_some(), "{placed}");
            prop_assert!(!placed.object.is_empty(), "{placed}");
        }
    }
}

/// A fixed pool of geometry in group 2 (every entity type, some degenerate at random
/// values), so random constraints over it mostly pass validation and reach the equations.
fn pool(vals: &[f64]) -> System {
    let mut sys = Sketch::new().sys;
    for (i, &v) in vals.iter().enumerate() {
        sys.add_param(Param::new(11 + i as u32, 2, v)).unwrap();
    }
    let ents = [
        Entity::point_2d(301, 2, WP, [11, 12]),
        Entity::point_2d(302, 2, WP, [13, 14]),
        Entity::point_2d(303, 2, WP, [15, 16]),
        Entity::point_2d(304, 2, WP, [17, 18]),
        Entity::point_3d(305, 2, [19, 20, 21]),
        Entity::point_3d(306, 2, [22, 23, 24]),
        Entity::line(311, 2, Some(WP), 301, 302),
        Entity::line(312, 2, Some(WP), 303, 304),
        Entity::line(313, 2, None, 305, 306),
        Entity::line(314, 2, None, 301, 305),
        Entity::normal_2d(320, 2, WP),
        Entity::normal_3d(321, 2, [25, 26, 27, 28]),
        Entity::distance(322, 2, Some(WP), 29),
        Entity::circle(323, 2, Some(WP), 301, 320, 322),
        Entity::circle(324, 2, None, 305, 321, 322),
        Entity::arc(325, 2, WP, 320, 302, 303, 304),
        Entity::arc(326, 2, WP, 320, 301, 304, 303),
        Entity::cubic(327, 2, Some(WP), [301, 302, 303, 304]),
        Entity::cubic(328, 2, None, [305, 306, 301, 302]),
    ];
    for e in ents {
        sys.add_entity(e).unwrap();
    }
    sys
}

const POOL: [u32; 21] = [
    200, 101, 102, 301, 302, 303, 304, 305, 306, 311, 312, 313, 314, 320, 321, 322, 323, 324, 325,
    326, 327,
];

fn value() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -10.0f64..10.0,
        1 => Just(0.0),
        1 => Just(1.0),
        1 => Just(1e-13),
        1 => Just(1e8),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    /// Random constraints on well-formed (often degenerate) geometry: the solve ends with an
    /// outcome or a typed error, never a panic, and its report is self-consistent.
    #[test]
    fn random_constraints_on_valid_geometry_never_panic(
        vals in proptest::collection::vec(value(), 19),
        cons in proptest::collection::vec(
            (0..K::ALL.len(), proptest::bool::weighted(0.8), value(), proptest::array::uniform6(0usize..256), any::<[bool; 3]>()),
            1..10,
        ),
        dragged in proptest::collection::vec(11u32..30, 0..4),
    ) {
        let mut sys = pool(&vals);
        for (i, (k, in_wp, val, picks, flags)) in cons.into_iter().enumerate() {
            let kind = K::ALL[k];
            let sig = kind.signature();
            // Mostly a reference of the right type, sometimes anything, sometimes nothing.
            let mut f = [0u32; 6];
            for (j, want) in sig.fields.iter().enumerate() {
                let pick = picks[j];
                f[j] = match want {
                    _ if pick >= 252 => 0,
                    _ if pick >= 246 => POOL[pick % POOL.len()],
                    None => 0,
                    Some(w) => {
                        let fits: Vec<u32> = POOL
                            .iter()
                            .copied()
                            .filter(|&h| w.accepts(sys.entity(h.into()).unwrap().entity_type()))
                            .collect();
                        fits[pick % fits.len()]
                    }
                };
            }
            let mut c = Constraint::new(i as u32 + 1, 2, kind)
                .in_workplane(in_wp.then_some(WP))
                .with_points(f[0], f[1])
                .with_entities([f[2], f[3], f[4], f[5]])
                .with_flags(flags[0], flags[1])
                .with_val(val);
            if flags[2] && flags[0] {
                c = c.as_reference();
            }
            sys.add_constraint(c).unwrap();
        }
        let valid = sys.validate();
        let dragged: Vec<ParamId> = dragged.into_iter().map(ParamId).collect();
        let before = sys.clone();
        let cfg = Config::default();
        match solve(&mut sys, 2.into(), &dragged, &cfg) {
            Ok(rep) => {
                prop_assert!(valid.is_ok());
                prop_assert!(rep.dof <= rep.unknowns);
                if rep.outcome.is_ok() {
                    // Held to the tolerance, or on values as large as 1e8 to their rounding.
                    let size = before
                        .params()
                        .iter()
                        .filter(|p| p.group.0 == 2)
                        .fold(0.0f64, |m, p| m.max(p.val.abs()));
                    prop_assert!(rep.residual <= cfg.tolerance_at(size));
                    for p in sys.params() {
                        prop_assert!(p.val.is_finite(), "{} became {}", p.h, p.val);
                    }
                } else {
                    prop_assert!(!rep.failed.is_empty() || !rep.failed_entities.is_empty());
                    prop_assert_eq!(sys.params(), before.params());
                }
                // Whatever the outcome, a second solve from where the first left off must
                // not panic either.
                let _ = solve(&mut sys, 2.into(), &dragged, &cfg);
            }
            Err(SolveError::Model(e)) => prop_assert_eq!(Err(e), valid.clone()),
            Err(e) => prop_assert!(false, "unexpected error {e}"),
        }
    }
}

#[test]
fn a_workplane_whose_handles_are_taken_adds_nothing() {
    let mut sys = System::new();
    sys.add_param(Param::new(3, 1, 5.0)).unwrap();
    let e = sys.add_xy_workplane(1, 1, [101, 102, 200]).unwrap_err();
    assert!(e.to_string().contains('3'), "{e}");
    assert_eq!((sys.params().len(), sys.entities().len()), (1, 0));
    // An entity handle used twice is refused the same way.
    assert!(sys.add_xy_workplane(1, 11, [101, 101, 200]).is_err());
    assert_eq!((sys.params().len(), sys.entities().len()), (1, 0));
    // Free handles: the xy plane, its normal the identity quaternion.
    let wp = sys.add_xy_workplane(1, 11, [101, 102, 200]).unwrap();
    assert_eq!(wp.0, 200);
    let vals: Vec<f64> = (11..=17).map(|h| sys.value(h.into()).unwrap()).collect();
    assert_eq!(vals, [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
}
