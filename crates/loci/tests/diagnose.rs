//! Diagnoses with known answers: which constraints are redundant or in conflict, exactly.

#[path = "common/chain.rs"]
mod chain;

use loci::{
    diagnose, Config, ConflictSet, Constraint, ConstraintId, ConstraintKind as K, Entity, EntityId,
    GroupId, Member, Outcome, Param, System,
};
use proptest::prelude::*;
use proptest::test_runner::{Config as PropConfig, RngSeed};

const WP: u32 = 200;

/// The xy workplane (entity 200) in group 1.
fn plane() -> System {
    let mut s = System::new();
    for (h, v) in [
        (1, 0.0),
        (2, 0.0),
        (3, 0.0),
        (4, 1.0),
        (5, 0.0),
        (6, 0.0),
        (7, 0.0),
    ] {
        s.add_param(Param::new(h, 1, v)).unwrap();
    }
    s.add_entity(Entity::point_3d(101, 1, [1, 2, 3])).unwrap();
    s.add_entity(Entity::normal_3d(102, 1, [4, 5, 6, 7]))
        .unwrap();
    s.add_entity(Entity::workplane(WP, 1, 101, 102)).unwrap();
    s
}

/// Point `h` in group 2 with parameters `10 h` and `10 h + 1`.
fn pt(s: &mut System, h: u32, x: f64, y: f64) {
    s.add_param(Param::new(10 * h, 2, x)).unwrap();
    s.add_param(Param::new(10 * h + 1, 2, y)).unwrap();
    s.add_entity(Entity::point_2d(h, 2, WP, [10 * h, 10 * h + 1]))
        .unwrap();
}

fn line(s: &mut System, h: u32, a: u32, b: u32) {
    s.add_entity(Entity::line(h, 2, Some(WP), a, b)).unwrap();
}

fn add(s: &mut System, c: Constraint) {
    s.add_constraint(c.in_workplane(Some(WP))).unwrap();
}

fn cs(hs: &[u32]) -> Vec<Member> {
    hs.iter()
        .map(|&h| Member::Constraint(ConstraintId(h)))
        .collect()
}

fn run(s: &System) -> loci::Diagnosis {
    diagnose(s, GroupId(2), &Config::default()).unwrap()
}

/// A 3-4-5 right triangle (right angle at point 1), fixed in place, and the distance from
/// point 1 to the hypotenuse (line 23) set to `height`: 2.4 agrees with the sides, anything
/// else does not.
fn triangle(height: f64) -> System {
    let mut s = plane();
    pt(&mut s, 1, 0.0, 0.0);
    pt(&mut s, 2, 3.1, 0.2);
    pt(&mut s, 3, -0.1, 3.8);
    line(&mut s, 12, 1, 2);
    line(&mut s, 23, 2, 3);
    add(
        &mut s,
        Constraint::new(1, 2, K::WhereDragged).with_points(1, 0),
    );
    add(
        &mut s,
        Constraint::new(2, 2, K::PtPtDistance)
            .with_points(1, 2)
            .with_val(3.0),
    );
    add(
        &mut s,
        Constraint::new(3, 2, K::PtPtDistance)
            .with_points(2, 3)
            .with_val(5.0),
    );
    add(
        &mut s,
        Constraint::new(4, 2, K::PtPtDistance)
            .with_points(3, 1)
            .with_val(4.0),
    );
    add(
        &mut s,
        Constraint::new(5, 2, K::Horizontal).with_entities([12, 0, 0, 0]),
    );
    add(
        &mut s,
        Constraint::new(6, 2, K::PtLineDistance)
            .with_points(1, 0)
            .with_entities([23, 0, 0, 0])
            .with_val(height),
    );
    s
}

#[test]
fn triangle_with_a_distance_too_many_that_agrees_is_redundant() {
    let d = run(&triangle(2.4));
    assert_eq!(d.outcome, Outcome::RedundantOkay);
    assert!(d.conflicting.is_empty());
    assert_eq!(d.redundant.len(), 1);
    // The rigid motions (the dragged point, the horizontal) take no part.
    assert_eq!(d.redundant[0].members, cs(&[6, 4, 3, 2]));
    assert_eq!(d.redundant[0].excess, 1);
    assert_eq!(d.dof, 0);
    // Seven equations on six unknowns: over-determined by counting alone.
    assert_eq!(d.structural.len(), 1);
    assert_eq!(d.structural[0].equations - d.structural[0].unknowns, 1);
}

#[test]
fn triangle_with_a_distance_too_many_that_disagrees_conflicts() {
    let mut s = triangle(2.0);
    let d = run(&s);
    assert_eq!(d.outcome, Outcome::Inconsistent);
    assert_eq!(
        d.conflicting,
        vec![ConflictSet {
            members: cs(&[6, 4, 3, 2]),
            verified: true
        }]
    );
    assert!(d.redundant.is_empty());
    // The solver names the same constraints.
    let r = s.solve_group(2).unwrap();
    assert_eq!(r.outcome, Outcome::Inconsistent);
    assert_eq!(r.failed, [2, 3, 4, 6].map(ConstraintId).to_vec());
}

#[test]
fn a_height_beyond_a_side_conflicts_with_a_side_alone() {
    // Point 1 is 3 from point 2 and 4 from point 3, so it cannot be 5 from the line through
    // them. Either side alone makes a minimal conflict; the most recent is kept.
    let d = run(&triangle(5.0));
    assert_eq!(d.outcome, Outcome::Inconsistent);
    assert_eq!(d.conflicting[0].members, cs(&[6, 4]));
    assert!(d.conflicting[0].verified);
}

#[test]
fn a_tangential_height_is_redundant_with_the_side_it_touches() {
    // The distance from point 3 to line 12 is 4 only when the angle at point 1 is right:
    // there, to first order, it says what the side 3-1 says.
    let mut s = triangle(2.4);
    s.remove_constraint(ConstraintId(6));
    add(
        &mut s,
        Constraint::new(7, 2, K::PtLineDistance)
            .with_points(3, 0)
            .with_entities([12, 0, 0, 0])
            .with_val(4.0),
    );
    let d = run(&s);
    assert_eq!(d.outcome, Outcome::RedundantOkay);
    assert_eq!(d.redundant[0].members, cs(&[7, 4]));
}

/// A 10 x 10 square: both horizontals and all four perpendiculars, so two of those six are
/// redundant.
#[test]
fn square_with_both_horizontals_and_a_fourth_perpendicular_is_redundant() {
    let mut s = plane();
    for (h, x, y) in [(1, 0.0, 0.0), (2, 10.2, 0.1), (3, 9.9, 10.1), (4, 0.1, 9.8)] {
        pt(&mut s, h, x, y);
    }
    for (h, a, b) in [(11, 1, 2), (12, 2, 3), (13, 3, 4), (14, 4, 1)] {
        line(&mut s, h, a, b);
    }
    add(
        &mut s,
        Constraint::new(1, 2, K::WhereDragged).with_points(1, 0),
    );
    add(
        &mut s,
        Constraint::new(2, 2, K::Horizontal).with_entities([11, 0, 0, 0]),
    );
    add(
        &mut s,
        Constraint::new(3, 2, K::Horizontal).with_entities([13, 0, 0, 0]),
    );
    add(
        &mut s,
        Constraint::new(4, 2, K::Perpendicular).with_entities([11, 12, 0, 0]),
    );
    add(
        &mut s,
        Constraint::new(5, 2, K::Perpendicular).with_entities([12, 13, 0, 0]),
    );
    add(
        &mut s,
        Constraint::new(6, 2, K::Perpendicular).with_entities([13, 14, 0, 0]),
    );
    add(
        &mut s,
        Constraint::new(7, 2, K::Perpendicular).with_entities([14, 11, 0, 0]),
    );
    add(
        &mut s,
        Constraint::new(8, 2, K::PtPtDistance)
            .with_points(1, 2)
            .with_val(10.0),
    );
    add(
        &mut s,
        Constraint::new(9, 2, K::EqualLengthLines).with_entities([11, 12, 0, 0]),
    );
    let d = run(&s);
    assert_eq!(d.outcome, Outcome::RedundantOkay);
    assert_eq!(d.dof, 0);
    assert_eq!(d.redundant.len(), 1);
    assert_eq!(d.redundant[0].members, cs(&[7, 6, 5, 4, 3, 2]));
    assert_eq!(d.redundant[0].excess, 2);
    assert_eq!(
        d.redundant[0].to_string(),
        "2 of {constraint 7, constraint 6, constraint 5, constraint 4, constraint 3, constraint 2} are redundant"
    );
}

#[test]
fn a_cycle_of_coincident_points_is_redundant_as_a_whole() {
    let mut s = plane();
    pt(&mut s, 1, 0.0, 0.0);
    pt(&mut s, 2, 0.1, 0.0);
    pt(&mut s, 3, 0.0, 0.2);
    add(
        &mut s,
        Constraint::new(1, 2, K::PointsCoincident).with_points(1, 2),
    );
    add(
        &mut s,
        Constraint::new(2, 2, K::PointsCoincident).with_points(2, 3),
    );
    add(
        &mut s,
        Constraint::new(3, 2, K::PointsCoincident).with_points(3, 1),
    );
    add(
        &mut s,
        Constraint::new(4, 2, K::WhereDragged).with_points(1, 0),
    );
    let d = run(&s);
    assert_eq!(d.outcome, Outcome::RedundantOkay);
    assert_eq!(d.redundant.len(), 1);
    // The x and the y rows are separate circuits; they are one set of constraints, of which
    // one can go.
    assert_eq!(d.redundant[0].members, cs(&[3, 2, 1]));
    assert_eq!(d.redundant[0].excess, 1);
    assert_eq!(d.dof, 0);
}

#[test]
fn a_duplicated_constraint_is_redundant_and_a_contradicting_copy_conflicts() {
    for (val, redundant) in [(5.0, true), (6.0, false)] {
        let mut s = plane();
        pt(&mut s, 1, 0.0, 0.0);
        pt(&mut s, 2, 4.0, 3.0);
        add(
            &mut s,
            Constraint::new(1, 2, K::WhereDragged).with_points(1, 0),
        );
        add(
            &mut s,
            Constraint::new(2, 2, K::PtPtDistance)
                .with_points(1, 2)
                .with_val(5.0),
        );
        add(
            &mut s,
            Constraint::new(3, 2, K::PtPtDistance)
                .with_points(1, 2)
                .with_val(val),
        );
        let d = run(&s);
        if redundant {
            assert_eq!(d.outcome, Outcome::RedundantOkay);
            assert_eq!(d.redundant[0].members, cs(&[3, 2]));
            assert_eq!(
                d.redundant[0].to_string(),
                "one of {constraint 3, constraint 2} is redundant"
            );
            assert!(d.conflicting.is_empty());
        } else {
            assert_eq!(d.outcome, Outcome::Inconsistent);
            assert_eq!(
                d.conflicting,
                vec![ConflictSet {
                    members: cs(&[3, 2]),
                    verified: true
                }]
            );
            assert!(d.redundant.is_empty());
        }
        // The point still turns about point 1.
        assert_eq!(d.dof, 1);
    }
}

#[test]
fn two_conflicting_constraints_hidden_in_a_thousand_segment_chain() {
    let (mut s, extra) = chain::chain(1000, true);
    let extra = extra.unwrap();
    let original = chain::distance_of(500);
    let d = run(&s);
    assert_eq!(d.outcome, Outcome::Inconsistent);
    assert_eq!(
        d.conflicting,
        vec![ConflictSet {
            members: vec![Member::Constraint(extra), Member::Constraint(original)],
            verified: true
        }]
    );
    assert!(d.redundant.is_empty());
    assert!(d.structural.is_empty(), "{:?}", d.structural);
    assert_eq!(d.dof, 1);
    let r = s.solve_group(2).unwrap();
    assert_eq!(r.failed, vec![original, extra]);
}

#[test]
fn a_chain_turns_about_its_first_point() {
    let (mut s, _) = chain::chain(50, false);
    assert!(s.solve_group(2).unwrap().outcome.is_ok());
    let d = run(&s);
    assert_eq!(d.outcome, Outcome::Okay);
    assert_eq!(d.dof, 1);
    let (a0, b0, l0) = chain::segment(0);
    assert_eq!(d.freedom(EntityId(a0)).unwrap().dof, 0);
    assert_eq!(d.freedom(EntityId(b0)).unwrap().dof, 1);
    assert_eq!(
        d.freedom(EntityId(l0)).unwrap().to_string(),
        format!("line {l0}: free to rotate about its start (entity {a0})")
    );
    // Every other point and line moves too, with the one rotation.
    assert!(d
        .freedoms
        .iter()
        .filter(|f| f.entity.0 != a0)
        .all(|f| f.dof == 1));
}

#[test]
fn counting_finds_three_equations_on_a_two_coordinate_point() {
    let mut s = plane();
    pt(&mut s, 1, 1.0, 1.0);
    add(
        &mut s,
        Constraint::new(1, 2, K::WhereDragged).with_points(1, 0),
    );
    // A distance to the workplane's origin (a constant of group 1).
    s.add_constraint(
        Constraint::new(2, 2, K::PtPtDistance)
            .with_points(1, 101)
            .with_val(2.0f64.sqrt()),
    )
    .unwrap();
    let d = run(&s);
    assert_eq!(d.structural.len(), 1);
    assert_eq!(d.structural[0].members, cs(&[2, 1]));
    assert_eq!(
        (d.structural[0].equations, d.structural[0].unknowns),
        (3, 2)
    );
    assert_eq!(d.outcome, Outcome::RedundantOkay);
}

#[test]
fn reference_constraints_measure_and_do_not_constrain() {
    let mut s = triangle(2.4);
    s.remove_constraint(ConstraintId(6));
    let r = |c: Constraint| c.in_workplane(Some(WP)).as_reference();
    s.add_constraint(r(Constraint::new(10, 2, K::PtPtDistance)
        .with_points(2, 3)
        .with_val(1.0)))
        .unwrap();
    s.add_constraint(r(
        Constraint::new(11, 2, K::Angle).with_entities([12, 23, 0, 0])
    ))
    .unwrap();
    s.add_constraint(r(Constraint::new(12, 2, K::Angle)
        .with_entities([12, 23, 0, 0])
        .with_flags(true, false)))
        .unwrap();
    s.add_constraint(r(
        Constraint::new(13, 2, K::LengthRatio).with_entities([23, 12, 0, 0])
    ))
    .unwrap();
    let d = run(&s);
    assert_eq!(d.outcome, Outcome::Okay);
    assert_eq!(d.dof, 0);
    let m: Vec<(u32, f64)> = d
        .measurements
        .iter()
        .map(|m| (m.constraint.0, m.value))
        .collect();
    let expect = [
        (10, 5.0),
        (11, 126.869_897_645_844),
        (12, 53.130_102_354_156),
        (13, 5.0 / 3.0),
    ];
    assert_eq!(m.len(), expect.len());
    for ((h, v), (eh, ev)) in m.iter().zip(expect) {
        assert_eq!(*h, eh);
        assert!((v - ev).abs() < 1e-6, "constraint {h}: {v} not {ev}");
    }
}

#[test]
fn a_diagnosis_round_trips_through_json() {
    let d = run(&triangle(2.0));
    let text = serde_json::to_string(&d).unwrap();
    let back: loci::Diagnosis = serde_json::from_str(&text).unwrap();
    assert_eq!(back.conflicting, d.conflicting);
    assert_eq!(back.freedoms.len(), d.freedoms.len());
    assert!(text.contains("\"conflicting\":[{\"members\":[{\"kind\":\"constraint\",\"h\":6}"));
}

/// A random small sketch: up to four points, the lines between consecutive ones, and up to
/// seven constraints, each either agreeing with the drawing or not.
fn random_system(coords: Vec<(i8, i8)>, picks: Vec<(u8, u8, u8, u8, bool)>) -> System {
    let mut s = plane();
    let n = coords.len() as u32;
    for (i, &(x, y)) in coords.iter().enumerate() {
        pt(&mut s, i as u32 + 1, x as f64, y as f64 + 0.5 * i as f64);
    }
    for i in 1..n {
        line(&mut s, 300 + i, i, i + 1);
    }
    let pos = |s: &System, p: u32| {
        (
            s.value((10 * p).into()).unwrap(),
            s.value((10 * p + 1).into()).unwrap(),
        )
    };
    for (c, &(kind, a, b, l, agree)) in picks.iter().enumerate() {
        let h = c as u32 + 1;
        let (a, b) = (a as u32 % n + 1, b as u32 % n + 1);
        let b = if a == b { b % n + 1 } else { b };
        let nl = n - 1;
        let (la, lb) = (300 + (l as u32 % nl) + 1, 300 + ((l as u32 + 1) % nl) + 1);
        let k = match kind % 7 {
            0 => Constraint::new(h, 2, K::WhereDragged).with_points(a, 0),
            1 => {
                let (pa, pb) = (pos(&s, a), pos(&s, b));
                let dist = ((pa.0 - pb.0).powi(2) + (pa.1 - pb.1).powi(2)).sqrt();
                let v = if agree {
                    dist
                } else {
                    dist + 1.0 + l as f64 % 3.0
                };
                Constraint::new(h, 2, K::PtPtDistance)
                    .with_points(a, b)
                    .with_val(v)
            }
            2 => Constraint::new(h, 2, K::Horizontal).with_points(a, b),
            3 => Constraint::new(h, 2, K::Vertical).with_points(a, b),
            4 => Constraint::new(h, 2, K::PointsCoincident).with_points(a, b),
            5 if nl >= 2 => Constraint::new(h, 2, K::Perpendicular).with_entities([la, lb, 0, 0]),
            6 => Constraint::new(h, 2, K::PtOnLine)
                .with_points(a, 0)
                .with_entities([la, 0, 0, 0]),
            _ => Constraint::new(h, 2, K::Vertical).with_entities([la, 0, 0, 0]),
        };
        add(&mut s, k);
    }
    s
}

proptest! {
    #![proptest_config(PropConfig {
        cases: 300,
        rng_seed: RngSeed::Fixed(0x10c1),
        failure_persistence: None,
        ..PropConfig::default()
    })]

    /// A verdict always comes with names, the solver and the diagnosis agree on it and on
    /// the degrees of freedom, and every conflict set is minimal when it says it is checked.
    #[test]
    fn verdicts_come_with_names(
        coords in prop::collection::vec((-5i8..=5, -5i8..=5), 2..=4),
        picks in prop::collection::vec((0u8..7, 0u8..4, 0u8..4, 0u8..3, any::<bool>()), 1..=7),
    ) {
        let mut s = random_system(coords, picks);
        let d = diagnose(&s, GroupId(2), &Config::default()).unwrap();
        let r = s.solve_group(2).unwrap();
        if d.outcome == Outcome::Inconsistent {
            prop_assert!(!d.conflicting.is_empty());
        }
        if d.outcome == Outcome::RedundantOkay {
            prop_assert!(!d.redundant.is_empty());
        }
        if r.outcome == Outcome::Inconsistent {
            prop_assert!(!d.conflicting.is_empty());
            prop_assert!(!r.failed.is_empty() || !r.failed_entities.is_empty());
        }
        if r.outcome == Outcome::RedundantOkay {
            prop_assert!(!d.redundant.is_empty());
        }
        prop_assert!(r.outcome != Outcome::Okay || d.conflicting.is_empty());
        // Only at a solution: at a degenerate stop the solver's rank can be poisoned by a
        // Jacobian that is not finite.
        if r.outcome.is_ok() {
            prop_assert_eq!(d.dof, r.dof);
        }
        for c in &d.conflicting {
            prop_assert!(!c.members.is_empty());
        }
    }
}

/// Points 1 = 2 and 2 = 3 and 1.2 between points 1 and 3, beside a cycle of three equal
/// lengths (one of them redundant), one line ending on point 2. The coincidences merge the
/// three points, so where the solve stops the distance has no direction and stood alone as its
/// own circuit, which holds alone: `did_not_converge`, nothing named (a random 3D sketch
/// against SolveSpace, which names the distance). Off that point its row lies in the span of
/// the coincidences', and the three are named, in 2D and in 3D.
#[test]
fn a_distance_between_points_that_coincidences_join_conflicts_with_them() {
    for three_d in [false, true] {
        let mut s = plane();
        let points = [
            (1, 0.0, 0.0),
            (2, 1.0, 2.0),
            (3, 3.0, 1.0),
            (4, -2.0, 5.0),
            (5, 4.0, 6.0),
            (6, 7.0, -1.0),
            (7, 9.0, 3.0),
            (8, 2.0, 8.0),
        ];
        for (h, x, y) in points {
            if three_d {
                let p = 10 * h;
                for (k, v) in [x, y, 0.5 * x - 0.25 * y].into_iter().enumerate() {
                    s.add_param(Param::new(p + k as u32, 2, v)).unwrap();
                }
                s.add_entity(Entity::point_3d(h, 2, [p, p + 1, p + 2]))
                    .unwrap();
            } else {
                pt(&mut s, h, x, y);
            }
        }
        let wp = (!three_d).then_some(WP);
        for (h, a, b) in [(21, 4, 5), (22, 6, 7), (23, 2, 8)] {
            s.add_entity(Entity::line(h, 2, wp, a, b)).unwrap();
        }
        for c in [
            Constraint::new(1, 2, K::PointsCoincident).with_points(1, 2),
            Constraint::new(2, 2, K::PointsCoincident).with_points(2, 3),
            Constraint::new(3, 2, K::PtPtDistance)
                .with_points(1, 3)
                .with_val(1.2),
            Constraint::new(4, 2, K::PtPtDistance)
                .with_points(4, 5)
                .with_val(7.9),
            Constraint::new(5, 2, K::EqualLengthLines).with_entities([22, 21, 0, 0]),
            Constraint::new(6, 2, K::EqualLengthLines).with_entities([21, 23, 0, 0]),
            Constraint::new(7, 2, K::EqualLengthLines).with_entities([23, 22, 0, 0]),
        ] {
            s.add_constraint(c.in_workplane(wp)).unwrap();
        }
        let d = run(&s);
        assert_eq!(d.outcome, Outcome::Inconsistent, "3D: {three_d}");
        assert!(
            d.conflicting.contains(&ConflictSet {
                members: cs(&[3, 2, 1]),
                verified: true
            }),
            "3D: {three_d}: {:?}",
            d.conflicting
        );
        let r = s.solve_group(2).unwrap();
        assert_eq!(r.outcome, Outcome::Inconsistent, "3D: {three_d}");
        assert_eq!(
            r.failed,
            [1, 2, 3].map(ConstraintId).to_vec(),
            "3D: {three_d}"
        );
    }
}
