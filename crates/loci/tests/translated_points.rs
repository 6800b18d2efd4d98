//! Translated points (`point_n_trans`): a copy held at its base plus a multiple of a
//! translation vector that is the copying group's unknown.

use loci::{
    solve, Config, Constraint, ConstraintKind, Entity, EntityType, GroupId, ModelError, ObjectId,
    Outcome, Param, ParamId, System,
};

/// A base point at (1, 2, 3) in group 1; in group 2 a translation vector (t) and the copies
/// at base + 0 t and base + 2 t, as an extrusion's bottom and top.
fn extrusion() -> System {
    let mut sys = System::new();
    for (h, v) in [(1, 1.0), (2, 2.0), (3, 3.0)] {
        sys.add_param(Param::new(h, 1, v)).unwrap();
    }
    sys.add_entity(Entity::point_3d(100, 1, [1, 2, 3])).unwrap();
    // The translation starts away from any solution; the copies start at the base.
    for (h, v) in [(10, 0.5), (11, -0.5), (12, 0.2)] {
        sys.add_param(Param::new(h, 2, v)).unwrap();
    }
    for h in 20..26 {
        sys.add_param(Param::new(h, 2, 0.0)).unwrap();
    }
    sys.add_entity(Entity::point_n_trans(
        101,
        2,
        [20, 21, 22],
        100,
        [10, 11, 12],
        0,
    ))
    .unwrap();
    sys.add_entity(Entity::point_n_trans(
        102,
        2,
        [23, 24, 25],
        100,
        [10, 11, 12],
        2,
    ))
    .unwrap();
    sys
}

fn values(sys: &System, ps: [u32; 3]) -> [f64; 3] {
    ps.map(|p| sys.value(ParamId(p)).unwrap())
}

#[test]
fn copies_follow_the_translation() {
    let mut sys = extrusion();
    // The vector as a point from the origin: hold it at (0, 0, -5).
    for (h, v) in [(30, 0.0), (31, 0.0), (32, -5.0)] {
        sys.add_param(Param::new(h, 0, v)).unwrap();
    }
    sys.add_entity(Entity::point_3d(103, 2, [10, 11, 12]))
        .unwrap();
    sys.add_entity(Entity::point_3d(104, 0, [30, 31, 32]))
        .unwrap();
    sys.add_constraint(
        Constraint::new(1, 2, ConstraintKind::PointsCoincident).with_points(103, 104),
    )
    .unwrap();
    let r = solve(&mut sys, GroupId(2), &[], &Config::default()).unwrap();
    assert_eq!(r.outcome, Outcome::Okay);
    assert_eq!(r.dof, 0);
    let close = |a: [f64; 3], b: [f64; 3]| (0..3).all(|i| (a[i] - b[i]).abs() < 1e-9);
    assert!(close(values(&sys, [10, 11, 12]), [0.0, 0.0, -5.0]));
    assert!(close(values(&sys, [20, 21, 22]), [1.0, 2.0, 3.0]));
    assert!(close(values(&sys, [23, 24, 25]), [1.0, 2.0, -7.0]));
}

#[test]
fn a_distance_between_copies_sets_the_translation_length() {
    let mut sys = extrusion();
    // Top to bottom is 2 |t|, so |t| = 4 (its direction stays free).
    sys.add_constraint(
        Constraint::new(1, 2, ConstraintKind::PtPtDistance)
            .with_points(101, 102)
            .with_val(8.0),
    )
    .unwrap();
    let r = solve(&mut sys, GroupId(2), &[], &Config::default()).unwrap();
    assert_eq!(r.outcome, Outcome::Okay);
    // Unknowns: t (3) and two copies (6); equations: 6 ties and the distance.
    assert_eq!(r.dof, 2);
    let t = values(&sys, [10, 11, 12]);
    let len = (t[0] * t[0] + t[1] * t[1] + t[2] * t[2]).sqrt();
    assert!((len - 4.0).abs() < 1e-9, "{t:?}");
    let top = values(&sys, [23, 24, 25]);
    for i in 0..3 {
        assert!((top[i] - ([1.0, 2.0, 3.0][i] + 2.0 * t[i])).abs() < 1e-9);
    }
}

#[test]
fn bad_translated_points_are_named() {
    // The base must be a point.
    let mut sys = extrusion();
    sys.add_param(Param::new(40, 1, 1.0)).unwrap();
    sys.add_entity(Entity::distance(105, 1, None, 40)).unwrap();
    sys.add_entity(Entity::point_n_trans(
        106,
        2,
        [20, 21, 22],
        105,
        [10, 11, 12],
        1,
    ))
    .unwrap();
    match sys.validate() {
        Err(ModelError::WrongKind {
            owner,
            field,
            found,
            ..
        }) => {
            assert_eq!(owner, ObjectId::Entity(loci::EntityId(106)));
            assert_eq!(field, "base");
            assert_eq!(found, EntityType::Distance);
        }
        other => panic!("expected WrongKind, got {other:?}"),
    }
    // The translation's parameters must exist.
    let mut sys = extrusion();
    sys.add_entity(Entity::point_n_trans(
        106,
        2,
        [20, 21, 22],
        100,
        [10, 11, 99],
        1,
    ))
    .unwrap();
    match sys.validate() {
        Err(ModelError::Dangling { field, handle, .. }) => {
            assert_eq!(field, "translation[2]");
            assert_eq!(handle, 99);
        }
        other => panic!("expected Dangling, got {other:?}"),
    }
}

#[test]
fn json_names_the_kind_point_n_trans() {
    let sys = extrusion();
    let text = serde_json::to_string(&sys).unwrap();
    assert!(text.contains("\"point_n_trans\""), "{text}");
    let back: System = serde_json::from_str(&text).unwrap();
    assert_eq!(
        back.entity(loci::EntityId(102)),
        sys.entity(loci::EntityId(102))
    );
    assert_eq!(
        back.entity(loci::EntityId(102)).unwrap().entity_type(),
        EntityType::PointNTrans
    );
}
