//! Removing entities and parameters: refused while something still refers to them, and a
//! structural edit once done.

use loci::{Constraint, ConstraintKind as K, Entity, ModelError, ObjectId, Param, System};

fn two_points_and_a_line() -> System {
    let mut sys = System::new();
    sys.add_xy_workplane(1, 1, [101, 102, 200]).unwrap();
    for (h, v) in [(11, 0.0), (12, 0.0), (13, 3.0), (14, 4.0)] {
        sys.add_param(Param::new(h, 2, v)).unwrap();
    }
    sys.add_entity(Entity::point_2d(301, 2, 200, [11, 12]))
        .unwrap();
    sys.add_entity(Entity::point_2d(302, 2, 200, [13, 14]))
        .unwrap();
    sys.add_entity(Entity::line(400, 2, Some(200), 301, 302))
        .unwrap();
    sys.add_constraint(
        Constraint::new(1, 2, K::PtPtDistance)
            .in_workplane(Some(200))
            .with_points(301, 302)
            .with_val(5.0),
    )
    .unwrap();
    sys
}

#[test]
fn an_entity_in_use_is_not_removed_and_the_error_names_the_user() {
    let mut sys = two_points_and_a_line();
    let rev = sys.revision();
    let err = sys.remove_entity(301.into()).unwrap_err();
    assert_eq!(
        err,
        ModelError::InUse {
            object: ObjectId::Entity(301.into()),
            user: ObjectId::Entity(400.into())
        }
    );
    assert_eq!(sys.revision(), rev);
    assert!(sys.entity(301.into()).is_some());
    // The line goes; the point is still held by the constraint.
    assert!(sys.remove_entity(400.into()).unwrap().is_some());
    let err = sys.remove_entity(301.into()).unwrap_err();
    assert!(matches!(
        err,
        ModelError::InUse {
            user: ObjectId::Constraint(_),
            ..
        }
    ));
}

#[test]
fn removing_an_unused_entity_and_its_params_keeps_the_rest_solvable() {
    let mut sys = two_points_and_a_line();
    sys.remove_constraint(1.into());
    sys.remove_entity(400.into()).unwrap();
    let rev = sys.revision();
    assert!(matches!(
        sys.remove_param(11.into()),
        Err(ModelError::InUse {
            user: ObjectId::Entity(_),
            ..
        })
    ));
    assert!(sys.remove_entity(301.into()).unwrap().is_some());
    assert!(sys.revision() > rev);
    assert!(sys.remove_param(11.into()).unwrap().is_some());
    assert!(sys.remove_param(12.into()).unwrap().is_some());
    assert_eq!(sys.remove_param(12.into()).unwrap(), None);
    assert_eq!(sys.remove_entity(301.into()).unwrap(), None);
    // Lookups by handle still find the objects that moved down the lists.
    assert_eq!(sys.value(13.into()), Some(3.0));
    assert_eq!(sys.entity(302.into()).unwrap().h, 302.into());
    sys.add_constraint(
        Constraint::new(2, 2, K::Horizontal)
            .in_workplane(Some(200))
            .with_points(302, 101),
    )
    .unwrap();
    let r = sys.solve_group(2).unwrap();
    assert!(r.outcome.is_ok());
    assert!(sys.value(14.into()).unwrap().abs() < 1e-9);
}
