//! A [`Solver`] reused across edits: structural edits rebuild what it compiled, value edits
//! keep it, and either way the answer is the one a fresh solve gives.

mod common;

use common::{uv, Sketch, WP};
use loci::{
    solve, Config, Constraint, ConstraintId, ConstraintKind as K, Outcome, SolveError, Solver,
    System,
};
use proptest::prelude::*;

/// A line 301-302 from (0, 0) to (10, 1), its start fixed, length 10.
fn line_sketch() -> (Sketch, u32) {
    let mut s = Sketch::new();
    let a = s.point(301, 2, [0.0, 0.0]);
    let b = s.point(302, 2, [10.0, 1.0]);
    s.line(310, 2, a, b);
    s.on_points(2, K::WhereDragged, a, 0, 0.0);
    s.on_points(2, K::PtPtDistance, a, b, 10.0);
    let h = s.on_entities(2, K::Horizontal, 310, 0, 0.0);
    (s, h)
}

#[test]
fn swapping_horizontal_for_vertical_is_seen() {
    let (mut s, horizontal) = line_sketch();
    let mut solver = Solver::new(2, &[], Config::default());
    let r = solver.solve(&mut s.sys).unwrap();
    assert_eq!(r.outcome, Outcome::Okay);
    assert!(uv(&s.sys, 302)[1].abs() < 1e-9);
    // Same counts of everything, different structure.
    s.sys.remove_constraint(ConstraintId(horizontal));
    s.on_entities(2, K::Vertical, 310, 0, 0.0);
    let r = solver.solve(&mut s.sys).unwrap();
    assert_eq!(r.outcome, Outcome::Okay);
    let b = uv(&s.sys, 302);
    assert!(
        b[0].abs() < 1e-9 && (b[1].abs() - 10.0).abs() < 1e-9,
        "{b:?}"
    );
}

#[test]
fn a_kind_changed_in_place_is_seen_and_a_value_edit_keeps_the_structure() {
    let (mut s, horizontal) = line_sketch();
    let mut solver = Solver::new(2, &[], Config::default());
    solver.solve(&mut s.sys).unwrap();
    let rev = s.sys.revision();
    // A value edit: the revision stays.
    s.sys.constraint_mut(ConstraintId(2)).unwrap().val = 12.0;
    assert_eq!(s.sys.revision(), rev);
    solver.solve(&mut s.sys).unwrap();
    assert!((uv(&s.sys, 302)[0] - 12.0).abs() < 1e-9);
    // A kind changed through the same call: structural.
    s.sys.constraint_mut(ConstraintId(horizontal)).unwrap().kind = K::Vertical;
    assert!(s.sys.revision() > rev);
    let r = solver.solve(&mut s.sys).unwrap();
    assert_eq!(r.outcome, Outcome::Okay);
    let b = uv(&s.sys, 302);
    assert!(
        b[0].abs() < 1e-9 && (b[1].abs() - 12.0).abs() < 1e-9,
        "{b:?}"
    );
    // The handle cannot be changed in place.
    s.sys.constraint_mut(ConstraintId(2)).unwrap().h = ConstraintId(99);
    assert!(s.sys.constraint(ConstraintId(2)).is_some());
    assert!(s.sys.constraint(ConstraintId(99)).is_none());
}

#[test]
fn a_solver_does_not_take_a_clone_for_the_system_it_compiled() {
    let (mut s, horizontal) = line_sketch();
    let mut solver = Solver::new(2, &[], Config::default());
    solver.solve(&mut s.sys).unwrap();
    let mut other = s.sys.clone();
    other.constraint_mut(ConstraintId(horizontal)).unwrap().kind = K::Vertical;
    // Same revision count as the original could reach; still a different system.
    let r = solver.solve(&mut other).unwrap();
    assert_eq!(r.outcome, Outcome::Okay);
    assert!(uv(&other, 302)[0].abs() < 1e-9);
}

#[test]
fn solving_a_group_that_does_not_exist_is_an_error_naming_the_groups() {
    let (mut s, _) = line_sketch();
    let err = solve(&mut s.sys, 7.into(), &[], &Config::default()).unwrap_err();
    assert!(matches!(err, SolveError::UnknownGroup { .. }), "{err:?}");
    assert_eq!(
        err.to_string(),
        "group 7 does not exist; the groups of this system are 1, 2"
    );
    let mut solver = Solver::new(7, &[], Config::default());
    assert!(solver.solve(&mut s.sys).is_err());
    let mut empty = System::new();
    let err = empty.solve_group(1).unwrap_err();
    assert_eq!(
        err.to_string(),
        "group 1 does not exist; the groups of this system are none (it is empty)"
    );
}

#[test]
fn a_value_set_to_nan_between_solves_is_an_error() {
    let (mut s, _) = line_sketch();
    let mut solver = Solver::new(2, &[], Config::default());
    solver.solve(&mut s.sys).unwrap();
    s.sys.constraint_mut(ConstraintId(2)).unwrap().val = f64::NAN;
    assert!(solver.solve(&mut s.sys).is_err());
}

/// One edit of the sketch below.
#[derive(Clone, Debug)]
enum Edit {
    /// Move point `i`'s parameters by (du, dv).
    Nudge(usize, f64, f64),
    /// Set constraint value of constraint slot `i`.
    Value(usize, f64),
    /// Remove constraint slot `i` if present, else add it back.
    Toggle(usize),
    /// Change constraint slot `i` to the `k`-th of a few kinds that fit its references.
    Kind(usize, usize),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (0..4usize, -2.0..2.0f64, -2.0..2.0f64).prop_map(|(i, u, v)| Edit::Nudge(i, u, v)),
        (0..6usize, 3.0..12.0f64).prop_map(|(i, v)| Edit::Value(i, v)),
        (0..6usize).prop_map(Edit::Toggle),
        (0..6usize, 0..3usize).prop_map(|(i, k)| Edit::Kind(i, k)),
    ]
}

/// A quadrilateral 301-302-303-304 with lines 311..314, point 301 dragged in place, and six
/// constraints on the lines whose kinds and presence the edits change.
fn quad() -> (Sketch, Vec<Constraint>) {
    let mut s = Sketch::new();
    let pts = [[0.0, 0.0], [8.0, 1.0], [9.0, 7.0], [-1.0, 6.0]];
    for (i, p) in pts.iter().enumerate() {
        s.point(301 + i as u32, 2, *p);
    }
    for i in 0..4u32 {
        s.line(311 + i, 2, 301 + i, 301 + (i + 1) % 4);
    }
    s.on_points(2, K::WhereDragged, 301, 0, 0.0);
    let slots = vec![
        Constraint::new(100, 2, K::Horizontal).with_entities([311, 0, 0, 0]),
        Constraint::new(101, 2, K::PtPtDistance)
            .with_points(301, 302)
            .with_val(8.0),
        Constraint::new(102, 2, K::Vertical).with_entities([312, 0, 0, 0]),
        Constraint::new(103, 2, K::PtPtDistance)
            .with_points(302, 303)
            .with_val(6.0),
        Constraint::new(104, 2, K::Parallel).with_entities([311, 313, 0, 0]),
        Constraint::new(105, 2, K::EqualLengthLines).with_entities([312, 314, 0, 0]),
    ];
    let slots: Vec<Constraint> = slots
        .into_iter()
        .map(|c| c.in_workplane(Some(WP)))
        .collect();
    for c in &slots {
        s.sys.add_constraint(c.clone()).unwrap();
    }
    (s, slots)
}

fn apply(sys: &mut System, slots: &[Constraint], e: &Edit) {
    match *e {
        Edit::Nudge(i, du, dv) => {
            let params = sys
                .entity((301 + i as u32).into())
                .unwrap()
                .kind
                .params()
                .to_vec();
            for (p, d) in params.iter().zip([du, dv]) {
                let v = sys.value(*p).unwrap();
                sys.set_value(*p, v + d);
            }
        }
        Edit::Value(i, v) => {
            if let Some(mut c) = sys.constraint_mut(slots[i].h) {
                if c.kind == K::PtPtDistance {
                    c.val = v;
                }
            }
        }
        Edit::Toggle(i) => {
            if sys.remove_constraint(slots[i].h).is_none() {
                sys.add_constraint(slots[i].clone()).unwrap();
            }
        }
        Edit::Kind(i, k) => {
            if let Some(mut c) = sys.constraint_mut(slots[i].h) {
                // Kinds that take the same references.
                let kinds: &[K] = if c.pt_a.is_some() {
                    &[K::PtPtDistance, K::Horizontal, K::Vertical]
                } else if c.entity_b.is_some() {
                    &[K::Parallel, K::Perpendicular, K::EqualLengthLines]
                } else {
                    &[K::Horizontal, K::Vertical, K::Horizontal]
                };
                c.kind = kinds[k];
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// After any sequence of edits, a solve with the reused solver gives the outcome, DOF,
    /// failed list and values (to the bit) of a fresh solve of the same system.
    #[test]
    fn reused_solver_answers_as_a_fresh_one(edits in prop::collection::vec(edit(), 1..10)) {
        let (mut s, slots) = quad();
        let cfg = Config::default();
        let mut solver = Solver::new(2, &[], cfg.clone());
        solver.solve(&mut s.sys).unwrap();
        for e in &edits {
            apply(&mut s.sys, &slots, e);
            let mut fresh = s.sys.clone();
            let want = solve(&mut fresh, 2.into(), &[], &cfg).unwrap();
            let got = solver.solve(&mut s.sys).unwrap();
            prop_assert_eq!(got.outcome, want.outcome, "after {:?}", e);
            prop_assert_eq!(got.dof, want.dof);
            prop_assert_eq!(&got.failed, &want.failed);
            let bits = |s: &System| s.params().iter().map(|p| p.val.to_bits()).collect::<Vec<_>>();
            prop_assert_eq!(bits(&s.sys), bits(&fresh), "values after {:?}", e);
        }
    }
}
