//! The written-out derivatives of `equations/fast.rs` against the dual numbers, which define
//! them: same residual, same derivatives, on the fixture's tilted workplane.

use super::super::compile::resolve_constraint;
use super::super::fast;
use super::super::refs::Resolver;
use super::fixture::{Form, Fx, MOVING};
use crate::model::{Constraint, ConstraintKind as K, GroupId};
use proptest::prelude::*;

/// A residual and its row of the Jacobian.
type Row = (f64, Vec<f64>);

/// Residual and Jacobian over the unknown slots of `c` (with its branch set to `choice`), by
/// the written-out path (`None` when it does not apply) and by dual numbers.
fn both(fx: &Fx, c: &Constraint, choice: u8) -> (Option<Row>, Row) {
    fx.sys.validate().expect("the fixture builds a valid model");
    let (mut eq, l) = resolve_constraint(&Resolver::new(&fx.sys), c).expect("resolves");
    eq.choice = choice;
    let params = fx.sys.params();
    let x: Vec<f64> = l.params.iter().map(|&p| params[p as usize].val).collect();
    let active: Vec<u16> = (0..x.len() as u16)
        .filter(|&k| params[l.params[k as usize] as usize].group == GroupId(MOVING))
        .collect();
    let (mut r1, mut j1) = ([0.0], vec![0.0; active.len()]);
    let written = fast::jacobian(&eq, &x, &active, &mut r1, &mut j1).then_some((r1[0], j1));
    let (mut r2, mut j2) = ([0.0], vec![0.0; active.len()]);
    eq.jacobian_dual(&x, &active, &mut r2, &mut j2);
    (written, (r2[0], j2))
}

fn assert_same(fx: &Fx, c: &Constraint, choice: u8) {
    let (written, (r2, j2)) = both(fx, c, choice);
    let (r1, j1) = written.expect("the written-out path applies");
    assert!(
        (r1 - r2).abs() <= 1e-12 * (1.0 + r2.abs()),
        "residual {r1} vs {r2}"
    );
    assert_eq!(j1.len(), j2.len());
    for (a, b) in j1.iter().zip(&j2) {
        assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "{j1:?} vs {j2:?}");
    }
}

fn coord() -> impl Strategy<Value = [f64; 2]> {
    [-50.0..50.0f64, -50.0..50.0f64]
}

proptest! {
    #[test]
    fn distance_matches_dual_numbers(a in coord(), b in coord(), d in 0.0..30.0f64) {
        let mut fx = Fx::new();
        let (pa, pb) = (fx.p2(MOVING, fx.wp, a), fx.p2(MOVING, fx.wp, b));
        let c = fx.con(K::PtPtDistance, Form::Plane).with_points(pa, pb).with_val(d);
        assert_same(&fx, &c, 0);
    }

    #[test]
    fn angle_matches_dual_numbers(
        p in proptest::collection::vec(coord(), 4),
        deg in 0.0..180.0f64,
        other: bool,
        shared: bool,
        choice in 0u8..2,
    ) {
        let mut fx = Fx::new();
        let pts: Vec<u32> = p.iter().map(|&uv| fx.p2(MOVING, fx.wp, uv)).collect();
        // With `shared`, both lines start at the same point entity: its slots feed twice.
        let second_start = if shared { pts[0] } else { pts[2] };
        let l0 = fx.line_of(MOVING, Form::Plane, pts[0], pts[1]);
        let l1 = fx.line_of(MOVING, Form::Plane, second_start, pts[3]);
        let c = fx
            .con(K::Angle, Form::Plane)
            .with_entities([l0, l1, 0, 0])
            .with_val(deg)
            .with_flags(other, false);
        assert_same(&fx, &c, choice);
    }
}

#[test]
fn zero_length_distance_has_no_derivative_like_the_dual_numbers() {
    let mut fx = Fx::new();
    let (pa, pb) = (
        fx.p2(MOVING, fx.wp, [1.0, 2.0]),
        fx.p2(MOVING, fx.wp, [1.0, 2.0]),
    );
    let c = fx
        .con(K::PtPtDistance, Form::Plane)
        .with_points(pa, pb)
        .with_val(3.0);
    let (written, (r2, j2)) = both(&fx, &c, 0);
    assert_eq!(written, Some((-3.0, vec![0.0; 4])));
    assert_eq!((r2, j2), (-3.0, vec![0.0; 4]));
}

#[test]
fn points_outside_the_workplane_take_the_generic_path() {
    let mut fx = Fx::new();
    let pa = fx.p2(MOVING, fx.wp, [0.0, 0.0]);
    let pb = fx.p3(MOVING, [1.0, 2.0, 3.0]);
    let c = fx
        .con(K::PtPtDistance, Form::Plane)
        .with_points(pa, pb)
        .with_val(1.0);
    assert!(both(&fx, &c, 0).0.is_none());
    // A line given in space is no line of the workplane either.
    let (q0, q1) = (
        fx.p3(MOVING, [0.0, 0.0, 1.0]),
        fx.p3(MOVING, [1.0, 0.0, 1.0]),
    );
    let l0 = fx.line_of(MOVING, Form::Free, q0, q1);
    let l1 = fx.line_of(MOVING, Form::Plane, pa, pa);
    let c = fx
        .con(K::Angle, Form::Plane)
        .with_entities([l0, l1, 0, 0])
        .with_val(30.0);
    assert!(both(&fx, &c, 0).0.is_none());
}
