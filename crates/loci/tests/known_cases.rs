//! Cases where loci once answered wrongly, found by testing against SolveSpace 3.3 and by
//! fuzzing (`tests/data/bugs`, with `expected.tsv` saying what is right). Each must give the
//! right outcome; a `solved` one must hold every equation, and no case may claim a solution
//! that breaks a constraint.

mod common;

use common::{Sketch, WP};
use loci::{solve, Config, Member, Outcome, System};
use std::path::PathBuf;

fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/bugs")
        .join(name)
}

fn load(name: &str) -> System {
    let text = std::fs::read_to_string(data(name)).expect("test data is there");
    serde_json::from_str(&text).expect("a valid problem")
}

/// Cases whose right outcome loci does not reach yet, with what it says instead. Each still
/// runs: it must never claim a solution, and a satisfiable one never a conflict.
const NOT_YET: &[(&str, &str)] = &[];

#[test]
fn every_known_case_gives_the_right_outcome() {
    let table = std::fs::read_to_string(data("expected.tsv")).unwrap();
    let mut checked = 0;
    for line in table.lines() {
        if line.starts_with('#') || line.trim().is_empty() {
            continue;
        }
        let (file, want) = line.split_once('\t').unwrap();
        let mut sys = load(file);
        let before = sys.clone();
        let r = solve(&mut sys, 2.into(), &[], &Config::default()).unwrap();
        // Never a false solution, whatever else.
        if r.outcome.is_ok() {
            assert!(
                r.residual <= 1e-9,
                "{file}: okay with residual {}",
                r.residual
            );
            let again = solve(&mut sys.clone(), 2.into(), &[], &Config::default()).unwrap();
            assert!(
                again.outcome.is_ok() && again.iterations == 0,
                "{file}: {again:?}"
            );
        } else {
            assert_eq!(
                sys.params(),
                before.params(),
                "{file}: values written on failure"
            );
        }
        if let Some((_, why)) = NOT_YET.iter().find(|(f, _)| *f == file) {
            assert!(!r.outcome.is_ok(), "{file}: claims a solution ({why})");
            assert!(
                want != "solved" || r.outcome != Outcome::Inconsistent,
                "{file}: satisfiable, but named a conflict: {r:?}"
            );
            eprintln!("not yet right: {file}: {} ({why})", r.outcome);
            continue;
        }
        // The diagnosis (`loci check`) reaches the same verdict as the solve: it once said
        // `did_not_converge` on a sketch the solve solved (seed 202986).
        let d = before.diagnose(2).unwrap();
        match want {
            "inconsistent" => {
                assert_eq!(r.outcome, Outcome::Inconsistent, "{file}");
                assert!(!r.failed.is_empty(), "{file}: a conflict without names");
                assert_eq!(d.outcome, Outcome::Inconsistent, "{file}: diagnosis");
            }
            "solved" => {
                assert!(r.outcome.is_ok(), "{file}: {r:?}");
                assert!(d.outcome.is_ok(), "{file}: diagnosis {}", d.outcome);
            }
            other => panic!("{file}: unknown expectation {other}"),
        }
        checked += 1;
    }
    assert!(checked >= 7, "only {checked} cases checked");
}

#[test]
fn check_is_deterministic_and_does_not_panic_on_degenerate_repeats() {
    // Repeated constraints and a curve tangent to itself: `loci check` panicked on a sort
    // that was not a total order, in most runs, and named its sets in a different order.
    let sys = load("json_check_panic_sort_min.json");
    let first = format!("{:?}", sys.diagnose(2).unwrap());
    for _ in 0..20 {
        assert_eq!(format!("{:?}", sys.diagnose(2).unwrap()), first);
    }
}

#[test]
fn three_d_parallel_and_point_on_line_conflicts_are_named() {
    for file in ["parallel3d_handmade.json", "pt_on_line3d_handmade.json"] {
        let sys = load(file);
        let d = sys.diagnose(2).unwrap();
        assert_eq!(d.outcome, Outcome::Inconsistent, "{file}");
        assert!(d.conflicting.iter().all(|c| c.verified), "{file}: {d:?}");
    }
}

/// Total movement of the linkage's nine points from the drawing.
fn movement(start: &System, end: &System) -> f64 {
    let mut sq = 0.0;
    for p in start.params().iter().filter(|p| p.group.0 == 1) {
        let d = end.value(p.h).unwrap() - p.val;
        sq += d * d;
    }
    sq.sqrt()
}

#[test]
fn the_jansen_linkage_lands_nearest_the_drawing() {
    // SolveSpace's own Python test asserts p8 = (18.93036, 13.63778), 20.208 from the drawing
    // in all (SolveSpace 3.3, PyPI slvs, gives that whole configuration); the end of loci's
    // Newton path is 20.427 away, at p8 = (19.35966, 14.03307). Both are valid (DOF 10 as the
    // file writes the workplane). By default loci moves on to the solution of least movement.
    let start = load("jansen_linkage.json");
    let mut near = start.clone();
    let r = solve(&mut near, 1.into(), &[], &Config::default()).unwrap();
    assert!(r.outcome.is_ok() && r.residual <= 1e-9, "{r:?}");
    let near_moved = movement(&start, &near);
    assert!(
        near_moved < 20.2080,
        "{near_moved}: not nearer than SolveSpace's 20.208"
    );
    assert!((near_moved - 18.8778).abs() < 1e-3, "{near_moved}");
    // SolveSpace's behaviour: the end of Newton's path.
    let mut plain = start.clone();
    let cfg = Config::default().with_nearest(false);
    let r = solve(&mut plain, 1.into(), &[], &cfg).unwrap();
    assert!(r.outcome.is_ok() && r.residual <= 1e-9, "{r:?}");
    let plain_moved = movement(&start, &plain);
    assert!((plain_moved - 20.4266).abs() < 1e-3, "{plain_moved}");
}

#[test]
fn the_jansen_linkage_ends_where_solvespace_does_with_its_angle_form() {
    // SolveSpace writes a 2D angle as cos(angle) - cos(val); Newton's steps follow that form,
    // and with it (and no slide to the nearest solution) loci ends at the configuration
    // SolveSpace's own test asserts: p8 (params 24, 25) at (18.93036, 13.63778).
    let mut sys = load("jansen_linkage.json");
    let start = sys.clone();
    let cfg = Config::default()
        .with_nearest(false)
        .with_solvespace_angles(true);
    let r = solve(&mut sys, 1.into(), &[], &cfg).unwrap();
    assert!(r.outcome.is_ok() && r.residual <= 1e-9, "{r:?}");
    let p8 = (sys.value(24.into()).unwrap(), sys.value(25.into()).unwrap());
    assert!((p8.0 - 18.93036).abs() < 1e-5, "{p8:?}");
    assert!((p8.1 - 13.63778).abs() < 1e-5, "{p8:?}");
    assert!((movement(&start, &sys) - 20.2081).abs() < 1e-3);
    // The answer is judged with loci's own signed form: the angle holds on its branch.
    let again = solve(&mut sys.clone(), 1.into(), &[], &Config::default()).unwrap();
    assert_eq!(again.iterations, 0, "{again:?}");
}

/// `n` distances between one pair of points of a workplane (values alternating 10 and 11
/// when `mixed`), as `gen_pair.py` writes them.
fn pair(n: u32, mixed: bool) -> System {
    use loci::{Constraint, ConstraintKind as K, Entity, Param};
    let mut sys = Sketch::new().sys;
    for (h, v) in [(11, 0.0), (12, 0.0), (13, 9.0), (14, 1.0)] {
        sys.add_param(Param::new(h, 2, v)).unwrap();
    }
    sys.add_entity(Entity::point_2d(11, 2, WP, [11, 12]))
        .unwrap();
    sys.add_entity(Entity::point_2d(12, 2, WP, [13, 14]))
        .unwrap();
    for i in 0..n {
        let val = if mixed { 10.0 + f64::from(i % 2) } else { 10.0 };
        let c = Constraint::new(i + 1, 2, K::PtPtDistance)
            .in_workplane(Some(WP))
            .with_points(
                if i % 3 == 0 { 12 } else { 11 },
                if i % 3 == 0 { 11 } else { 12 },
            )
            .with_val(val);
        sys.add_constraint(c).unwrap();
    }
    sys
}

#[test]
fn many_copies_of_one_constraint_cost_linear_time_and_memory() {
    // 200,000 copies asked for a 160 GB matrix and aborted; now they never reach the solver.
    let mut sys = pair(200_000, false);
    let r = sys.solve_group(2).unwrap();
    assert_eq!(r.outcome, Outcome::RedundantOkay);
    assert_eq!((r.equations, r.dof), (1, 3));
    assert_eq!(r.failed.len(), 200_000);
    // Alternating values: two different equations, a conflict of two.
    let mut sys = pair(10_000, true);
    let r = sys.solve_group(2).unwrap();
    assert_eq!(r.outcome, Outcome::Inconsistent);
    assert_eq!(r.failed, vec![1.into(), 2.into()]);
    let d = sys.diagnose(2).unwrap();
    assert_eq!(d.conflicting.len(), 1);
    assert_eq!(d.conflicting[0].members.len(), 2);
}

/// `n` points of a workplane, each at distance 10 from one centre point.
fn star(n: u32) -> System {
    use loci::{Constraint, ConstraintKind as K, Entity, Param};
    let mut sys = Sketch::new().sys;
    let mut next = 10_000;
    let mut point = |sys: &mut System, h: u32, uv: [f64; 2]| {
        let (a, b) = (next, next + 1);
        next += 2;
        sys.add_param(Param::new(a, 2, uv[0])).unwrap();
        sys.add_param(Param::new(b, 2, uv[1])).unwrap();
        sys.add_entity(Entity::point_2d(h, 2, WP, [a, b])).unwrap();
    };
    point(&mut sys, 1_000, [0.0, 0.0]);
    for i in 0..n {
        let t = f64::from(i) * 0.001;
        point(&mut sys, 1_001 + i, [9.0 * t.cos(), 9.0 * t.sin()]);
        let c = Constraint::new(i + 1, 2, K::PtPtDistance)
            .in_workplane(Some(WP))
            .with_points(1_000, 1_001 + i)
            .with_val(10.0);
        sys.add_constraint(c).unwrap();
    }
    sys
}

#[test]
fn a_point_shared_by_too_many_constraints_is_a_typed_error_not_an_abort() {
    // Every distance shares the centre's two unknowns: J Jᵀ is dense, n² / 2 entries.
    let mut small = star(2_000);
    assert!(small.solve_group(2).unwrap().outcome.is_ok());
    let mut huge = star(12_000);
    let err = huge.solve_group(2).unwrap_err();
    assert!(
        matches!(
            err,
            loci::SolveError::TooLarge {
                equations: 12_000,
                ..
            }
        ),
        "{err}"
    );
    assert!(err.to_string().contains("12000 equations"), "{err}");
}

/// A staircase of `n` segments of length 3, each perpendicular to the next, the first
/// horizontal from a dragged point, drawn far from any answer: its points along the x axis,
/// 3 apart, with a little height each.
fn staircase_drawn_flat(n: u32) -> System {
    use loci::ConstraintKind as K;
    let mut s = Sketch::new();
    for i in 0..=n {
        let y = 0.1 * f64::from((7 * i) % 5);
        s.point(1_000 + i, 2, [3.0 * f64::from(i), y]);
    }
    for i in 0..n {
        s.line(5_000 + i, 2, 1_000 + i, 1_001 + i);
    }
    s.on_points(2, K::WhereDragged, 1_000, 0, 0.0);
    s.on_entities(2, K::Horizontal, 5_000, 0, 0.0);
    for i in 0..n {
        s.on_points(2, K::PtPtDistance, 1_000 + i, 1_001 + i, 3.0);
    }
    for i in 1..n {
        s.on_entities(2, K::Perpendicular, 4_999 + i, 5_000 + i, 0.0);
    }
    s.sys
}

#[test]
fn a_staircase_drawn_flat_is_never_called_inconsistent() {
    // Every segment's length and the turn between segments can hold together (a staircase of
    // right-angle turns), so no set of these constraints conflicts: a solve that cannot reach
    // a solution from a drawing this far off did not converge. Sets of 42 and 69 of them were
    // once named as conflicts because Newton on them alone ran off (residuals of 10²³), which
    // says nothing about whether they can hold.
    for n in [100, 200] {
        for cfg in [
            Config::default(),
            Config::default()
                .with_nearest(false)
                .with_solvespace_angles(true),
        ] {
            let mut sys = staircase_drawn_flat(n);
            let r = solve(&mut sys, 2.into(), &[], &cfg).unwrap();
            assert_ne!(r.outcome, Outcome::Inconsistent, "{n} segments: {r:?}");
            if r.outcome.is_ok() {
                assert_eq!(r.dof, 0);
            }
        }
        let d = staircase_drawn_flat(n).diagnose(2).unwrap();
        assert!(
            d.conflicting.is_empty(),
            "{n} segments: {:?}",
            d.conflicting
        );
        assert_ne!(d.outcome, Outcome::Inconsistent);
    }
}

/// Random sketches against SolveSpace 3.3, cut down to what shows each failure, where loci
/// did not converge and named nothing and SolveSpace names the planted constraint. Seed 844:
/// an angle of 137.87 degrees between a horizontal and a vertical line, whose derivatives
/// were rounding (6e-17) and, normalised, read its miss as 3e16. Seed 53: a distance between
/// two points that two coincidences join, whose row is empty where the solve stops. Seed
/// 2830: a distance, a midpoint and the distance to it that cannot agree, beside an angle
/// that made Newton wander; damped steps stopped short of the least-squares point, where the
/// rank was still full. Each now names the planted conflict and nothing else.
#[test]
fn conflicts_through_merged_points_and_lines_are_named() {
    for (file, named) in [
        ("diff_seed844_conflicting.json", vec![2, 13, 20]),
        ("diff_seed53_conflicting.json", vec![2, 5, 6]),
        ("diff_seed2830_conflicting.json", vec![2, 5, 6]),
    ] {
        let mut sys = load(file);
        let r = solve(&mut sys, 2.into(), &[], &Config::default()).unwrap();
        assert_eq!(r.outcome, Outcome::Inconsistent, "{file}");
        let failed: Vec<u32> = r.failed.iter().map(|c| c.0).collect();
        assert_eq!(failed, named, "{file}");
        let d = loci::diagnose(&sys, 2.into(), &Config::default()).unwrap();
        assert_eq!(d.outcome, Outcome::Inconsistent, "{file}");
        let mut sets: Vec<Vec<u32>> = d
            .conflicting
            .iter()
            .map(|s| {
                let mut m: Vec<u32> = s
                    .members
                    .iter()
                    .map(|m| match m {
                        loci::Member::Constraint(c) => c.0,
                        loci::Member::Entity(e) => e.0,
                    })
                    .collect();
                m.sort_unstable();
                m
            })
            .collect();
        sets.sort();
        assert_eq!(sets, vec![named.clone()], "{file}");
        assert!(d.conflicting.iter().all(|s| s.verified), "{file}");
    }
}

/// Seeds 7929 and 25105 of the random differential (`bench/tests/random_differential`):
/// satisfiable 3D sketches with a root where rows of the Jacobian become dependent only at the
/// solution, which Newton reaches linearly, its smallest pivot shrinking with the residual. The
/// rank test dropped such a row while its equation still missed by 4.9e-10 (9.5e-10), plain
/// steps leave a dropped row alone, and both ended `did_not_converge` where SolveSpace solves
/// them. The steps now go on at a tighter rank tolerance that keeps the row; the rank of the
/// answer is read at the usual one, so the row counts as dependent there (one more degree of
/// freedom than SolveSpace reports, whose tolerance keeps it).
#[test]
fn roots_where_rows_become_dependent_are_reached() {
    for (file, dof) in [
        ("diff_seed7929_redundant.json", 71),
        ("diff_seed25105_base.json", 67),
    ] {
        let mut sys = load(file);
        let r = solve(&mut sys, 2.into(), &[], &Config::default()).unwrap();
        assert_eq!(r.outcome, Outcome::RedundantOkay, "{file}: {r:?}");
        assert!(r.residual <= 1e-10, "{file}: residual {}", r.residual);
        assert_eq!(r.dof, dof, "{file}");
        // Solved again from its answer: nothing to do, and the same reading.
        let again = solve(&mut sys.clone(), 2.into(), &[], &Config::default()).unwrap();
        assert_eq!(again.iterations, 0, "{file}");
        assert_eq!((again.outcome, again.dof), (r.outcome, r.dof), "{file}");
    }
}

/// Seed 59100 of the random differential: a satisfiable 2D sketch of 23 constraints that
/// SolveSpace solves. Newton from the drawing failed, no dependence showed a conflict, and
/// shrinking the whole group found 18 constraints whose solves failed while each 17 of them
/// solved: the sketch was called inconsistent with those named, where building it up one
/// constraint at a time solves it (as `loci check` did). A set found that way no longer
/// proves a conflict before the build-up has been tried.
#[test]
fn a_set_found_only_by_failing_solves_does_not_stop_the_build_up() {
    let file = "diff_seed59100_base.json";
    let mut sys = load(file);
    let r = solve(&mut sys, 2.into(), &[], &Config::default()).unwrap();
    assert_eq!(r.outcome, Outcome::Okay, "{r:?}");
    assert!(r.residual <= 1e-10, "residual {}", r.residual);
    assert_eq!(r.dof, 26);
    let d = load(file).diagnose(2).unwrap();
    assert_eq!((d.outcome, d.dof), (Outcome::Okay, 26));
    assert!(d.conflicting.is_empty());
}

/// `sys` with only the constraints `keep` (and every entity and parameter).
fn only(sys: &System, keep: &[loci::ConstraintId]) -> System {
    let mut part = sys.clone();
    let all: Vec<loci::ConstraintId> = part.constraints().iter().map(|c| c.h).collect();
    for h in all.into_iter().filter(|h| !keep.contains(h)) {
        part.remove_constraint(h);
    }
    part
}

/// Sketches whose diagnosis once named a set of constraints that, kept alone, solve: variants
/// of fuzzed sketches with one constraint taken out. In the first, 23 constraints, Newton
/// failed and the diagnosis found 17 whose solves failed from where the solve stopped and from
/// the drawing; too large to shrink, the set was only checked that quickly, and named. In the
/// second, 8 constraints (points dragged, points on planes, two 3D lines parallel), a set of 6
/// was shrunk and checked every way the diagnosis had: Newton, built up one constraint at a
/// time, solved alone as drawn. Both solve when kept alone and built up with SolveSpace's
/// steps, as `solve` looks for a solution of a group it cannot solve from the drawing. Neither
/// sketch is shown to be impossible now: both did not converge.
#[test]
fn a_set_that_holds_alone_is_never_named() {
    for (file, set) in [
        (
            "json_large_set_holds_alone.json",
            &[
                6, 7, 9, 13, 16, 19, 20, 22, 23, 27, 28, 30, 31, 32, 33, 35, 38,
            ][..],
        ),
        (
            "json_set_holds_when_built_alone.json",
            &[1, 2, 4, 5, 6, 9][..],
        ),
    ] {
        let sys = load(file);
        let set: Vec<loci::ConstraintId> = set.iter().map(|&h| loci::ConstraintId(h)).collect();
        let mut alone = only(&sys, &set);
        let held = solve(&mut alone, 2.into(), &[], &Config::default()).unwrap();
        assert!(held.outcome.is_ok(), "{file}: {held:?}");
        assert!(held.residual <= 1e-10, "{file}: residual {}", held.residual);

        let mut whole = sys.clone();
        let r = solve(&mut whole, 2.into(), &[], &Config::default()).unwrap();
        let d = sys.diagnose(2).unwrap();
        match r.outcome {
            // A solution found some day is welcome, as long as it is one.
            Outcome::Okay | Outcome::RedundantOkay => assert!(r.residual <= 1e-9, "{r:?}"),
            Outcome::DidNotConverge => {
                assert_eq!(whole.params(), sys.params(), "{file}");
                assert!(d.conflicting.is_empty(), "{file}: {:?}", d.conflicting);
            }
            // Whatever is named must not solve when kept alone.
            _ => {
                assert!(!r.failed.is_empty(), "{file}: {r:?}");
                let mut named = only(&sys, &r.failed);
                let again = solve(&mut named, 2.into(), &[], &Config::default()).unwrap();
                assert!(
                    !again.outcome.is_ok(),
                    "{file}: named {:?}, which holds alone",
                    r.failed
                );
            }
        }
    }
}

/// A line 0.9 long made horizontal, and an angle of 51 degrees from it to a line 9.6 long
/// drawn at 129 degrees (constraints 3 and 4 of seed 430,180 of the random systems against
/// SolveSpace, kept alone). They can hold: turn the long line. But the least movement towards
/// the angle moves their shared point across the short line's other end, and every start near
/// the drawing ends with the short line about to vanish, where the angle's row and the
/// horizontal's are dependent: the pair was named a conflict by the solve and by the
/// diagnosis. A set about to be named is now also solved alone from starts drawn further off,
/// where the pair holds: neither names it, and the whole solves from there (SolveSpace reads
/// `did_not_converge`). The whole system of seed 430,180, a horizontal and a vertical line with
/// that angle between them, still names all three.
///
/// Of the same kind, seed 451,288: an angle of 140 degrees from a horizontal line to a
/// vertical one (constraints 1, 8 and 4). The deletion filter, solving near the drawing, finds
/// the angle and the horizontal failing without the vertical (the pair folds) and shrinks the
/// conflict to the pair, which the check above then drops. The search runs again with the
/// pair's solution from the random start among its starts; there the pair holds, and the
/// three are named (before: the pair, then nothing).
#[test]
fn sets_that_fold_the_sketch_near_the_drawing_are_not_named() {
    let sys = load("diff_seed430180_folded_pair.json");
    let mut solved = sys.clone();
    let r = solve(&mut solved, 2.into(), &[], &Config::default()).unwrap();
    assert_eq!(r.outcome, Outcome::Okay, "{r:?}");
    assert!(r.failed.is_empty() && r.residual < 1e-10, "{r:?}");
    // Judged apart from the solve: the line is horizontal and the angle is 51.2 degrees.
    let at = |h: u32| solved.params().iter().find(|p| p.h.0 == h).unwrap().val;
    let again = solve(&mut solved.clone(), 2.into(), &[], &Config::default()).unwrap();
    assert!(again.outcome.is_ok() && again.iterations == 0, "{again:?}");
    assert!(
        (at(9) - at(11)).abs() < 1e-9,
        "the short line is not horizontal"
    );
    let (d6, d8) = (
        [at(10) - at(8), at(11) - at(9)],
        [at(12) - at(10), at(13) - at(11)],
    );
    let cos = (d6[0] * d8[0] + d6[1] * d8[1]) / (d6[0].hypot(d6[1]) * d8[0].hypot(d8[1]));
    assert!(
        (cos.abs() - 51.20708754352129f64.to_radians().cos()).abs() < 1e-9,
        "the lines meet at {} degrees",
        cos.acos().to_degrees()
    );
    let d = sys.diagnose(2).unwrap();
    assert!(d.conflicting.is_empty(), "{:?}", d.conflicting);
    assert!(d.outcome.is_ok(), "{}", d.outcome);
    // The pair holds: the short line made horizontal and the long one turned to 51 degrees
    // from it (directions start minus end, as the angle measures them) solve as they are.
    let mut held = sys.clone();
    let value = |s: &System, h: u32| s.params().iter().find(|p| p.h.0 == h).unwrap().val;
    let (x5, y4) = (value(&sys, 10), value(&sys, 9));
    let turn = (180.0f64 + 51.20708754352129).to_radians();
    let (x7, y7) = (x5 - 9.58 * turn.cos(), y4 - 9.58 * turn.sin());
    for p in held.params_mut() {
        match p.h.0 {
            11 => p.val = y4,
            12 => p.val = x7,
            13 => p.val = y7,
            _ => {}
        }
    }
    let r = solve(&mut held, 2.into(), &[], &Config::default()).unwrap();
    assert!(r.outcome.is_ok() && r.iterations == 0, "{r:?}");

    // Seed 451,288: the three named, by the solve and by the diagnosis.
    let sys = load("diff_seed451288_conflicting.json");
    let r = solve(&mut sys.clone(), 2.into(), &[], &Config::default()).unwrap();
    let three: Vec<loci::ConstraintId> = [1u32, 4, 8].map(Into::into).to_vec();
    assert_eq!(r.outcome, Outcome::Inconsistent, "{r:?}");
    assert_eq!(r.failed, three);
    let d = sys.diagnose(2).unwrap();
    assert_eq!(d.outcome, Outcome::Inconsistent);
    assert_eq!(d.conflicting.len(), 1, "{:?}", d.conflicting);
    let mut named: Vec<loci::ConstraintId> = d.conflicting[0]
        .members
        .iter()
        .map(|m| match *m {
            Member::Constraint(c) => c,
            Member::Entity(e) => panic!("entity {e:?} named"),
        })
        .collect();
    named.sort_unstable();
    assert_eq!(named, three);
}
