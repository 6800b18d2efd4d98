//! Scale: a chain of 10,000 line segments solves from a perturbed start, checked against its
//! constraints independently of the solver and against the exact drawing.

mod common;

use common::perturbed_chain::{chain, Chain};
use common::{dist, uv};
use loci::{Outcome, System};

/// The largest violation of any chain constraint, computed from the parameter values alone.
fn worst_residual(ch: &Chain, sys: &System) -> f64 {
    let mut worst = 0.0f64;
    let p = |h: u32| uv(sys, h);
    let [a0, b0, _] = ch.segments[0];
    worst = worst.max(dist(p(a0), ch.joints[0])); // where_dragged at the origin
    worst = worst.max((p(b0)[1] - p(a0)[1]).abs()); // horizontal
    for (i, &[a, b, _]) in ch.segments.iter().enumerate() {
        worst = worst.max((dist(p(a), p(b)) - ch.lengths[i]).abs());
        if let Some(&[a1, b1, _]) = ch.segments.get(i + 1) {
            worst = worst.max(dist(p(b), p(a1)));
            let (u, w) = (sub(p(b), p(a)), sub(p(b1), p(a1)));
            let turn = (u[0] * w[1] - u[1] * w[0]).atan2(u[0] * w[0] + u[1] * w[1]);
            // Angle rows are sines of the angle error; compare like with like.
            let err = (turn.abs() - ch.angles[i].to_radians()).sin().abs();
            worst = worst.max(err);
        }
    }
    worst
}

fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

fn solve_and_check(n: usize, seed: u64) {
    let mut ch = chain(n, seed, 0.3);
    let mut sys = std::mem::take(&mut ch.system);
    let start = worst_residual(&ch, &sys);
    assert!(start > 1e-3, "the start is perturbed: {start}");
    let rep = sys.solve_group(ch.group).unwrap();
    assert_eq!(rep.outcome, Outcome::Okay, "{rep:?}");
    // 4n unknowns and 4n independent equations: see the construction's notes.
    assert_eq!(rep.dof, 0);
    assert!(rep.failed.is_empty());
    assert_eq!(
        rep.unknowns,
        4 * n - 2 * (n - 1) - 3,
        "coincidences, pin and horizontal merge"
    );
    let worst = worst_residual(&ch, &sys);
    assert!(worst < 1e-9, "largest residual {worst:e}");
    // Fully constrained and started near the exact drawing: the solve lands on it. The
    // tolerance allows for per-joint rounding carried along 10,000 segments.
    let mut far = 0.0f64;
    for (i, &[a, _, _]) in ch.segments.iter().enumerate() {
        far = far.max(dist(uv(&sys, a), ch.joints[i]));
    }
    let last = ch.segments[n - 1][1];
    far = far.max(dist(uv(&sys, last), ch.joints[n]));
    assert!(far < 1e-8, "joints off the exact drawing by {far:e}");
}

#[test]
fn chain_of_ten_thousand_segments_solves_exactly() {
    solve_and_check(10_000, 1);
}

#[test]
fn short_chains_solve_for_several_seeds() {
    for seed in 2..8 {
        solve_and_check(50, seed);
    }
    solve_and_check(1, 9);
}

#[test]
fn a_solver_keeps_up_with_changed_angles() {
    let mut ch = chain(50, 3, 0.3);
    let mut sys = std::mem::take(&mut ch.system);
    let mut solver = loci::Solver::new(ch.group, &[], loci::Config::default());
    assert_eq!(solver.solve(&mut sys).unwrap().outcome, Outcome::Okay);
    assert!(worst_residual(&ch, &sys) < 1e-9);
    // The angles are the constraints of that kind, in segment order. Re-solving with the
    // structure kept must read each new value, not the one the first solve compiled.
    let angles: Vec<loci::ConstraintId> = sys
        .constraints()
        .iter()
        .filter(|c| c.kind == loci::ConstraintKind::Angle)
        .map(|c| c.h)
        .collect();
    assert_eq!(angles.len(), ch.angles.len());
    for (i, &h) in angles.iter().enumerate().step_by(7) {
        ch.angles[i] += 4.0;
        sys.constraint_mut(h).unwrap().val = ch.angles[i];
    }
    assert!(
        worst_residual(&ch, &sys) > 1e-3,
        "the new angles do not hold yet"
    );
    let rep = solver.solve(&mut sys).unwrap();
    assert_eq!(rep.outcome, Outcome::Okay, "{rep:?}");
    let worst = worst_residual(&ch, &sys);
    assert!(worst < 1e-9, "largest residual {worst:e}");
}

#[test]
fn a_free_chain_ends_on_the_step_that_converged_quadratically() {
    // Without its horizontal, the chain turns freely about its first joint and its steps slide
    // towards the solution nearest the drawing. From this start they shrink from 3e-2 to 3e-4
    // to 6e-8: the solve ends on the third, as the next would be about 1e-11, rather than
    // take a fourth Jacobian and factorisation to see it (`QUADRATIC` in `solve/newton.rs`).
    let mut ch = chain(10, 2, 0.3);
    let mut sys = std::mem::take(&mut ch.system);
    let horizontal: Vec<_> = sys
        .constraints()
        .iter()
        .filter(|c| c.kind == loci::ConstraintKind::Horizontal)
        .map(|c| c.h)
        .collect();
    assert_eq!(horizontal.len(), 1);
    sys.remove_constraint(horizontal[0]);
    let rep = sys.solve_group(ch.group).unwrap();
    assert_eq!(rep.outcome, Outcome::Okay);
    assert_eq!(rep.dof, 1);
    assert_eq!(rep.iterations, 3, "{rep:?}");
    let p = |h: u32| uv(&sys, h);
    assert!(dist(p(ch.segments[0][0]), ch.joints[0]) < 1e-12);
    for (i, &[a, b, _]) in ch.segments.iter().enumerate() {
        assert!(
            (dist(p(a), p(b)) - ch.lengths[i]).abs() < 1e-10,
            "length {i}"
        );
        if let Some(&[a1, _, _]) = ch.segments.get(i + 1) {
            assert!(dist(p(b), p(a1)) < 1e-12, "joint {i}");
        }
    }
    // Where the last end was with the fourth step taken (measured when solves still took
    // it): the step that ends the solve is no more than rounding away from it.
    let [_, b, _] = ch.segments[9];
    assert!(dist(p(b), [90.952_583_051_370_31, -26.922_391_432_971_29]) < 1e-9);
}
