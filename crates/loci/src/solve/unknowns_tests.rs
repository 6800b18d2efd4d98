//! Steps through `Jᵀ J` (`solve::unknowns`) against steps through `J Jᵀ` alone: on meshes
//! and trusses, solvable, redundant and inconsistent, of a few sizes, the same outcome, DOF,
//! named constraints and (to the slide's tolerance) the same solution.

use super::test_support::{group_values, moved, run, Rng};
use super::{solve, Config, Outcome, Report};
use crate::model::{Constraint, ConstraintKind as K, Entity, Param, System};

const WP: u32 = 200;
const G: u32 = 2;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Variant {
    Solvable,
    /// The first cell's other diagonal, its length as drawn true.
    Redundant,
    /// That diagonal, 1 longer.
    Inconsistent,
}

/// An `n x n` jittered lattice of points drawn up to `off / 2` off along each axis, the first
/// fixed (a point of an earlier group); with `triangles`, each cell split by a random
/// diagonal and a distance on every edge (a mesh: one rotation free), else a distance on every
/// bar and one diagonal bracing the first cell (a truss, a mechanism).
fn lattice(n: usize, seed: u64, off: f64, triangles: bool, variant: Variant) -> System {
    lattice_pinned(n, seed, off, triangles, variant, false)
}

/// [`lattice`], with the first point held where dragged instead of fixed when `dragged`.
fn lattice_pinned(
    n: usize,
    seed: u64,
    off: f64,
    triangles: bool,
    variant: Variant,
    dragged: bool,
) -> System {
    let mut rng = Rng(seed);
    let mut sys = System::new();
    sys.add_xy_workplane(1, 1, [101, 102, WP]).unwrap();
    let at = |i: usize, j: usize| j * n + i;
    let mut true_pts = Vec::new();
    for k in 0..n * n {
        let (i, j) = ((k % n) as f64, (k / n) as f64);
        let p = [10.0 * i + 5.0 * rng.next(), 10.0 * j + 5.0 * rng.next()];
        let (dx, dy) = if k == 0 {
            (0.0, 0.0)
        } else {
            (off * rng.next(), off * rng.next())
        };
        let group = if k == 0 && !dragged { 1 } else { G };
        let (u, v) = (1000 + 2 * k as u32, 1001 + 2 * k as u32);
        sys.add_param(Param::new(u, group, p[0] + dx)).unwrap();
        sys.add_param(Param::new(v, group, p[1] + dy)).unwrap();
        sys.add_entity(Entity::point_2d(300 + k as u32, group, WP, [u, v]))
            .unwrap();
        true_pts.push(p);
    }
    let mut bars = Vec::new();
    let mut first_diagonal = None;
    for j in 0..n {
        for i in 0..n {
            if i + 1 < n {
                bars.push((at(i, j), at(i + 1, j)));
            }
            if j + 1 < n {
                bars.push((at(i, j), at(i, j + 1)));
            }
            if triangles && i + 1 < n && j + 1 < n {
                let d = if rng.next() < 0.0 {
                    (at(i, j), at(i + 1, j + 1))
                } else {
                    (at(i + 1, j), at(i, j + 1))
                };
                first_diagonal.get_or_insert(d);
                bars.push(d);
            }
        }
    }
    if !triangles {
        bars.push((at(0, 0), at(1, 1)));
        first_diagonal = Some((at(0, 0), at(1, 1)));
    }
    let mut lengths: Vec<f64> = bars
        .iter()
        .map(|&(p, q)| {
            let (a, b) = (true_pts[p], true_pts[q]);
            (a[0] - b[0]).hypot(a[1] - b[1])
        })
        .collect();
    if variant != Variant::Solvable {
        let other = match first_diagonal {
            Some((0, _)) => (at(1, 0), at(0, 1)),
            _ => (at(0, 0), at(1, 1)),
        };
        let (a, b) = (true_pts[other.0], true_pts[other.1]);
        let extra = if variant == Variant::Inconsistent {
            1.0
        } else {
            0.0
        };
        bars.push(other);
        lengths.push((a[0] - b[0]).hypot(a[1] - b[1]) + extra);
    }
    for (c, (&(p, q), &len)) in bars.iter().zip(&lengths).enumerate() {
        let con = Constraint::new(c as u32 + 1, G, K::PtPtDistance)
            .in_workplane(Some(WP))
            .with_points(300 + p as u32, 300 + q as u32)
            .with_val(len);
        sys.add_constraint(con).unwrap();
    }
    if dragged {
        let pin = Constraint::new(bars.len() as u32 + 1, G, K::WhereDragged)
            .in_workplane(Some(WP))
            .with_points(300, 0);
        sys.add_constraint(pin).unwrap();
    }
    sys
}

/// The constraints named redundant by `a` (through `Jᵀ J`) and by `b` (through `J Jᵀ` alone)
/// are the same, but for constraints `b` names wrongly: a constraint is on a circuit, and
/// rightly named, exactly when the drawing without it keeps the DOF. On large meshes the rows
/// `J Jᵀ`'s elimination leaves carry rounding amplified by thousands of dependent rows before
/// them, and it named the two distances to a corner point of degree two (which each fix that
/// point, and so are not implied by the others) on a 70x70 mesh.
fn check_named(start: &System, a: &Report, b: &Report, what: &str) {
    let rows_only = Config {
        unknowns_side: false,
        ..Config::default()
    };
    let differ = a
        .failed
        .iter()
        .filter(|c| !b.failed.contains(c))
        .chain(b.failed.iter().filter(|c| !a.failed.contains(c)));
    for &c in differ {
        let mut without = start.clone();
        without.remove_constraint(c).unwrap();
        let (w, _) = run(&without, G, &rows_only);
        assert_eq!(
            w.dof == a.dof,
            a.failed.contains(&c),
            "{what}: {c:?} named {} through Jᵀ J, DOF {} without it",
            a.failed.contains(&c),
            w.dof
        );
    }
}

/// The largest difference between `xa` and `xb`, relative to the size of `xb` (at least 1).
fn relative_difference(xa: &[f64], xb: &[f64]) -> f64 {
    let scale = xb.iter().fold(1.0f64, |s, v| s.max(v.abs()));
    let largest = xa
        .iter()
        .zip(xb)
        .fold(0.0f64, |s, (p, q)| s.max((p - q).abs()));
    largest / scale
}

/// `start` solved as by default (through `Jᵀ J` where it applies), then through `J Jᵀ` alone:
/// each report with the values where it ended.
fn both_ways(start: &System) -> ((Report, Vec<f64>), (Report, Vec<f64>)) {
    let rows_only = Config {
        unknowns_side: false,
        ..Config::default()
    };
    (run(start, G, &Config::default()), run(start, G, &rows_only))
}

/// Solves `start` both ways: the same outcome, DOF and named constraints, and the same
/// solution to `1e-7` of the drawing's size (where the equations cannot hold, residuals
/// within a tenth of each other). Returns the report of the default solve.
fn check_same(start: &System, what: &str) -> Report {
    let ((a, xa), (b, xb)) = both_ways(start);
    assert_eq!(a.outcome, b.outcome, "{what}: {a:?} vs {b:?}");
    assert_eq!(a.dof, b.dof, "{what}");
    assert_eq!(a.failed_entities, b.failed_entities, "{what}");
    if a.outcome.is_ok() {
        check_named(start, &a, &b, what);
    } else {
        assert_eq!(a.failed, b.failed, "{what}");
    }
    if a.outcome.is_ok() {
        assert!(a.residual <= 1e-10, "{what}: {a:?}");
        let largest = relative_difference(&xa, &xb);
        assert!(largest <= 1e-7, "{what}: the solutions differ by {largest}");
        // And no farther from the drawing (the steps through `Jᵀ J` settle at least as close
        // to the nearest solution).
        let (ma, mb) = (moved(start, G, &xa), moved(start, G, &xb));
        assert!(ma <= mb * (1.0 + 1e-9), "{what}: moved {ma} against {mb}");
    } else {
        // Both stop where the equations cannot be brought much closer to holding: the steps
        // through `Jᵀ J` at the least-squares point (they find the merit stationary there), the
        // damped steps through `G` there too or, where they crawl towards it, once the
        // decrease still to come at their rate is under a tenth of the merit (`settles_above`
        // in `newton.rs`). Neither writes its values back.
        assert!(
            (a.residual - b.residual).abs() <= 0.1 * b.residual,
            "{what}: residuals {} and {}",
            a.residual,
            b.residual
        );
    }
    a
}

#[test]
fn meshes_solved_through_the_unknowns_side_end_as_through_the_equations() {
    for (n, seed, off) in [
        (6, 1, 0.6),
        (10, 2, 0.6),
        (20, 3, 0.6),
        (20, 4, 2.0),
        (30, 5, 0.6),
        (30, 4, 0.1),
    ] {
        for variant in [Variant::Solvable, Variant::Redundant] {
            let what = format!("{n}x{n} mesh, seed {seed}, {variant:?}");
            for dragged in [false, true] {
                let start = lattice_pinned(n, seed, off, true, variant, dragged);
                let what = format!("{what}, pin dragged {dragged}");
                let rep = check_same(&start, &what);
                assert_eq!(rep.outcome, Outcome::RedundantOkay, "{what}: {rep:?}");
                assert_eq!(rep.dof, 1, "{what}: only the rotation about the pin");
            }
        }
    }
}

#[test]
fn inconsistent_meshes_are_named_as_through_the_equations() {
    for (n, seed) in [(6, 6), (10, 7)] {
        let what = format!("{n}x{n} inconsistent mesh");
        let rep = check_same(&lattice(n, seed, 0.6, true, Variant::Inconsistent), &what);
        assert_eq!(rep.outcome, Outcome::Inconsistent, "{what}: {rep:?}");
        assert!(!rep.failed.is_empty());
    }
}

#[test]
fn trusses_are_solved_as_through_the_equations() {
    for n in [6, 15] {
        for variant in [Variant::Solvable, Variant::Redundant, Variant::Inconsistent] {
            let what = format!("{n}x{n} truss, {variant:?}");
            let start = lattice(n, 9, 0.6, false, variant);
            let rows_only = Config {
                unknowns_side: false,
                ..Config::default()
            };
            // Fewer equations than unknowns: the same steps, bit for bit.
            let (a, xa) = run(&start, G, &Config::default());
            let (b, xb) = run(&start, G, &rows_only);
            assert_eq!(a, b, "{what}");
            assert_eq!(xa, xb, "{what}");
        }
    }
}

#[test]
fn a_mesh_with_a_dragged_point_ends_as_through_the_equations() {
    // The far corner dragged off where the distances allow: its unknowns weigh less in the
    // nearest solution (columns scaled), in both paths alike.
    let n = 12;
    let mut start = lattice(n, 21, 0.6, true, Variant::Solvable);
    let k = n * n - 1;
    let (u, v) = (1000 + 2 * k as u32, 1001 + 2 * k as u32);
    for p in start.params_mut() {
        if p.h.0 == u || p.h.0 == v {
            p.val += 3.0;
        }
    }
    let dragged = [crate::model::ParamId(u), crate::model::ParamId(v)];
    let solve_with = |cfg: &Config| {
        let mut sys = start.clone();
        let report = solve(&mut sys, G.into(), &dragged, cfg).unwrap();
        (report, group_values(&sys, G))
    };
    let rows_only = Config {
        unknowns_side: false,
        ..Config::default()
    };
    let (a, xa) = solve_with(&Config::default());
    let (b, xb) = solve_with(&rows_only);
    assert_eq!(a.outcome, Outcome::RedundantOkay, "{a:?}");
    assert_eq!((a.outcome, a.dof, &a.failed), (b.outcome, b.dof, &b.failed));
    assert!(a.residual <= 1e-10);
    let largest = xa
        .iter()
        .zip(&xb)
        .fold(0.0f64, |s, (p, q)| s.max((p - q).abs()));
    assert!(largest <= 1e-7 * 120.0, "the solutions differ by {largest}");
}

/// A 70x70 mesh whose corner points have two distances each: through `J Jᵀ` alone, three of
/// those distances were named redundant, which the drawing without any of them disproves
/// (its DOF rises); through `Jᵀ J` they are not named, and the rest is as before.
#[test]
fn distances_that_alone_fix_a_corner_point_are_not_named_redundant() {
    let start = lattice(70, 12, 0.6, true, Variant::Solvable);
    let rep = check_same(&start, "70x70 mesh");
    assert_eq!(rep.dof, 1);
    for c in [1, 2] {
        assert!(!rep.failed.contains(&crate::model::ConstraintId(c)), "{c}");
    }
}

/// `cargo test --release -p loci --lib unknowns_tests::large -- --ignored --nocapture`: the
/// same comparison on larger meshes (a few seconds each).
#[test]
#[ignore]
fn large_meshes_solved_through_the_unknowns_side_end_as_through_the_equations() {
    for (n, seed) in [(50, 11), (100, 13), (100, 14)] {
        let start = lattice(n, seed, 0.6, true, Variant::Solvable);
        let ((a, _), (b, _)) = both_ways(&start);
        let only_a: Vec<_> = a.failed.iter().filter(|c| !b.failed.contains(c)).collect();
        let only_b: Vec<_> = b.failed.iter().filter(|c| !a.failed.contains(c)).collect();
        eprintln!(
            "{n}x{n}: {} and {} named, only through Jᵀ J {only_a:?}, only through J Jᵀ {only_b:?}",
            a.failed.len(),
            b.failed.len()
        );
        check_same(&start, &format!("{n}x{n} mesh"));
    }
}

/// The rotation about the pin (point 0, unknowns 0 and 1 of the group) that takes the solution
/// `x` nearest the drawing `x0`: zero when `x` is the solution nearest it (a pinned rigid mesh's
/// solutions are its rotations about the pin).
fn rotation_to_nearest(x: &[f64], x0: &[f64], pin: [f64; 2]) -> f64 {
    let (mut s, mut c) = (0.0, 0.0);
    for (p, q) in x.chunks_exact(2).zip(x0.chunks_exact(2)) {
        let (px, py) = (p[0] - pin[0], p[1] - pin[1]);
        let (qx, qy) = (q[0] - pin[0], q[1] - pin[1]);
        c += px * qx + py * qy;
        s += px * qy - py * qx;
    }
    s.atan2(c)
}

/// On a pinned 50x50 mesh, the factorisation of `J Jᵀ` at the solution keeps the pivot of one
/// of its 2,304 dependent rows (rounding), and the mesh looked fully constrained: its answer
/// was not slid, and was left 1.9e-7 radians short of the rotation nearest the drawing (points
/// 1e-4 off). Whether to slide is read from the rank checked at the solution: both sides end at
/// the nearest solution.
#[test]
fn a_large_pinned_mesh_ends_at_the_rotation_nearest_the_drawing_either_way() {
    let start = lattice(50, 11, 0.6, true, Variant::Solvable);
    let x0 = group_values(&start, G);
    let at = |h: u32| start.params().iter().find(|p| p.h.0 == h).unwrap().val;
    let pin = [at(1000), at(1001)];
    let rows_only = Config {
        unknowns_side: false,
        ..Config::default()
    };
    let (a, xa) = run(&start, G, &Config::default());
    let (b, xb) = run(&start, G, &rows_only);
    for (what, rep, x) in [("through Jᵀ J", &a, &xa), ("through J Jᵀ", &b, &xb)] {
        assert_eq!(rep.outcome, Outcome::RedundantOkay, "{what}: {rep:?}");
        assert_eq!(rep.dof, 1, "{what}");
        assert!(rep.residual <= 1e-10, "{what}: {rep:?}");
        let turn = rotation_to_nearest(x, &x0, pin);
        assert!(
            turn.abs() <= 1e-12,
            "{what}: {turn:e} radians from the nearest solution"
        );
    }
    assert!(relative_difference(&xa, &xb) <= 1e-12);
}

/// The slide through `Jᵀ J` ends once its steps shrink at a rate whose remaining steps add up
/// to under `PROJECTED`, on the step that shows it, without a step and a Jacobian more to
/// confirm it (a 10x10 mesh: 2e-9 at a rate of 3e-4, then 7e-13 before): four steps from a
/// drawing 0.6 off, and the answer the steps through `J Jᵀ` reach, to 1e-11.
#[test]
fn a_mesh_slide_ends_on_the_step_that_settles_it() {
    for (n, seed) in [(6, 1), (10, 2), (10, 8), (20, 3)] {
        let what = format!("{n}x{n} mesh, seed {seed}");
        let start = lattice(n, seed, 0.6, true, Variant::Solvable);
        let ((a, xa), (b, xb)) = both_ways(&start);
        assert_eq!(a.outcome, Outcome::RedundantOkay, "{what}: {a:?}");
        assert!(a.iterations <= 4, "{what}: {} iterations", a.iterations);
        assert!(a.iterations <= b.iterations, "{what}: {a:?} against {b:?}");
        let d = relative_difference(&xa, &xb);
        assert!(d <= 1e-11, "{what}: the answers differ by {d:e}");
    }
}
