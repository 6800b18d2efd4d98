//! Linked parts: points (`point_n_rot_trans`) and normals (`normal_n_rot`) carried by a rigid
//! motion (a translation and a unit rotation quaternion) that is their group's unknown.

use loci::{
    solve, Config, Constraint, ConstraintKind, Entity, EntityId, EntityType, GroupId, ModelError,
    ObjectId, Outcome, Param, ParamId, System,
};

/// Group 1 holds a target point at (5, 0, 0), one at (5, 1, 0) and a normal turned a quarter
/// turn about z. Group 2 is a part with points based at the origin and at (1, 0, 0) and a
/// normal based at the identity, placed by translation (params 10..12) and the rotation
/// normal 200 (params 13..16), starting at the identity.
fn part() -> System {
    let mut sys = System::new();
    let s = std::f64::consts::FRAC_1_SQRT_2;
    for (h, v) in [
        (1, 5.0),
        (2, 0.0),
        (3, 0.0),
        (4, 5.0),
        (5, 1.0),
        (6, 0.0),
        (7, s),
        (8, 0.0),
        (9, 0.0),
        (30, s),
    ] {
        sys.add_param(Param::new(h, 1, v)).unwrap();
    }
    sys.add_entity(Entity::point_3d(100, 1, [1, 2, 3])).unwrap();
    sys.add_entity(Entity::point_3d(101, 1, [4, 5, 6])).unwrap();
    sys.add_entity(Entity::normal_3d(102, 1, [7, 8, 9, 30]))
        .unwrap();
    for (h, v) in [
        (10, 0.3),
        (11, -0.2),
        (12, 0.1),
        (13, 1.0),
        (14, 0.0),
        (15, 0.0),
        (16, 0.0),
    ] {
        sys.add_param(Param::new(h, 2, v)).unwrap();
    }
    sys.add_entity(Entity::normal_3d(200, 2, [13, 14, 15, 16]))
        .unwrap();
    // Own coordinates where the starting motion puts them.
    for (h, v) in [
        (20, 0.3),
        (21, -0.2),
        (22, 0.1),
        (23, 1.3),
        (24, -0.2),
        (25, 0.1),
    ] {
        sys.add_param(Param::new(h, 2, v)).unwrap();
    }
    for (h, v) in [(26, 1.0), (27, 0.0), (28, 0.0), (29, 0.0)] {
        sys.add_param(Param::new(h, 2, v)).unwrap();
    }
    sys.add_entity(Entity::point_n_rot_trans(
        201,
        2,
        [20, 21, 22],
        [0.0; 3],
        [10, 11, 12],
        200,
    ))
    .unwrap();
    sys.add_entity(Entity::point_n_rot_trans(
        202,
        2,
        [23, 24, 25],
        [1.0, 0.0, 0.0],
        [10, 11, 12],
        200,
    ))
    .unwrap();
    sys.add_entity(Entity::normal_n_rot(
        203,
        2,
        [26, 27, 28, 29],
        [1.0, 0.0, 0.0, 0.0],
        200,
    ))
    .unwrap();
    sys
}

fn value(sys: &System, p: u32) -> f64 {
    sys.value(ParamId(p)).unwrap()
}

#[test]
fn an_unconstrained_part_moves_six_ways() {
    let mut sys = part();
    let r = solve(&mut sys, GroupId(2), &[], &Config::default()).unwrap();
    assert_eq!(r.outcome, Outcome::Okay);
    // 7 motion parameters less the unit length; every copy is tied to them.
    assert_eq!(r.dof, 6);
}

#[test]
fn constraints_on_the_copies_place_the_part() {
    let mut sys = part();
    sys.add_constraint(
        Constraint::new(1, 2, ConstraintKind::PointsCoincident).with_points(201, 100),
    )
    .unwrap();
    sys.add_constraint(
        Constraint::new(2, 2, ConstraintKind::PointsCoincident).with_points(202, 101),
    )
    .unwrap();
    let r = solve(&mut sys, GroupId(2), &[], &Config::default()).unwrap();
    // The part is rigid, so the second point adds two conditions, not three: one equation is
    // redundant, and the part can still turn about the line through both points.
    assert_eq!(r.outcome, Outcome::RedundantOkay, "{r:?}");
    assert_eq!(r.dof, 1);
    // The translation takes the base origin to (5, 0, 0); the rotation turns x onto y.
    for (p, want) in [(10, 5.0), (11, 0.0), (12, 0.0)] {
        assert!((value(&sys, p) - want).abs() < 1e-9, "param {p}");
    }
    let q = [13, 14, 15, 16].map(|p| value(&sys, p));
    let (w, x, y, z) = (q[0], q[1], q[2], q[3]);
    let u = [
        w * w + x * x - y * y - z * z,
        2.0 * (w * z + x * y),
        2.0 * (x * z - w * y),
    ];
    for (got, want) in u.iter().zip([0.0, 1.0, 0.0]) {
        assert!((got - want).abs() < 1e-9, "rotation {q:?} takes x to {u:?}");
    }
    assert!((w * w + x * x + y * y + z * z - 1.0).abs() < 1e-9);
    // The copies follow: B at (5, 1, 0), the normal at q times the identity.
    for (p, want) in [(23, 5.0), (24, 1.0), (25, 0.0)] {
        assert!((value(&sys, p) - want).abs() < 1e-9, "param {p}");
    }
    for (i, p) in [26, 27, 28, 29].into_iter().enumerate() {
        assert!((value(&sys, p) - q[i]).abs() < 1e-9, "param {p}");
    }
}

#[test]
fn same_orientation_on_a_copied_normal_fixes_the_rotation() {
    let mut sys = part();
    // Start near the answer: SolveSpace's same_orientation picks its branch (which axes it
    // holds perpendicular) from the starting configuration.
    let s = std::f64::consts::FRAC_1_SQRT_2;
    for (p, v) in [(13, 0.8), (16, 0.55), (26, 0.8), (29, 0.55)] {
        assert!(sys.set_value(ParamId(p), v));
    }
    sys.add_constraint(
        Constraint::new(1, 2, ConstraintKind::PointsCoincident).with_points(201, 100),
    )
    .unwrap();
    sys.add_constraint(
        Constraint::new(3, 2, ConstraintKind::SameOrientation).with_entities([203, 102, 0, 0]),
    )
    .unwrap();
    let r = solve(&mut sys, GroupId(2), &[], &Config::default()).unwrap();
    assert_eq!(r.outcome, Outcome::Okay, "{r:?}");
    assert_eq!(r.dof, 0);
    let q = [13, 14, 15, 16].map(|p| value(&sys, p));
    let sign = q[0].signum();
    for (got, want) in q.iter().zip([s, 0.0, 0.0, s]) {
        assert!((got * sign - want).abs() < 1e-9, "{q:?}");
    }
    // B, based at (1, 0, 0), lands at (5, 1, 0).
    for (p, want) in [(23, 5.0), (24, 1.0), (25, 0.0)] {
        assert!((value(&sys, p) - want).abs() < 1e-9, "param {p}");
    }
}

#[test]
fn bad_moved_copies_are_named() {
    // The rotation must be a 3D normal.
    let mut sys = part();
    sys.add_entity(Entity::point_n_rot_trans(
        204,
        2,
        [20, 21, 22],
        [0.0; 3],
        [10, 11, 12],
        100,
    ))
    .unwrap();
    match sys.validate() {
        Err(ModelError::WrongKind {
            owner,
            field,
            found,
            ..
        }) => {
            assert_eq!(owner, ObjectId::Entity(EntityId(204)));
            assert_eq!(field, "rotation");
            assert_eq!(found, EntityType::PointIn3d);
        }
        other => panic!("expected WrongKind, got {other:?}"),
    }
    // The base must be finite.
    let mut sys = part();
    sys.add_entity(Entity::normal_n_rot(
        204,
        2,
        [26, 27, 28, 29],
        [1.0, f64::NAN, 0.0, 0.0],
        200,
    ))
    .unwrap();
    match sys.validate() {
        Err(ModelError::NonFinite { owner, field, .. }) => {
            assert_eq!(owner, ObjectId::Entity(EntityId(204)));
            assert_eq!(field, "base");
        }
        other => panic!("expected NonFinite, got {other:?}"),
    }
    // The rotation must exist.
    let mut sys = part();
    sys.add_entity(Entity::normal_n_rot(
        204,
        2,
        [26, 27, 28, 29],
        [1.0, 0.0, 0.0, 0.0],
        999,
    ))
    .unwrap();
    match sys.validate() {
        Err(ModelError::Dangling { field, handle, .. }) => {
            assert_eq!(field, "rotation");
            assert_eq!(handle, 999);
        }
        other => panic!("expected Dangling, got {other:?}"),
    }
}

#[test]
fn json_names_the_kinds() {
    let sys = part();
    let text = serde_json::to_string(&sys).unwrap();
    assert!(text.contains("\"point_n_rot_trans\""), "{text}");
    assert!(text.contains("\"normal_n_rot\""), "{text}");
    let back: System = serde_json::from_str(&text).unwrap();
    for h in [201, 202, 203] {
        assert_eq!(back.entity(EntityId(h)), sys.entity(EntityId(h)));
    }
    assert_eq!(
        back.entity(EntityId(203)).unwrap().entity_type(),
        EntityType::NormalNRot
    );
}
