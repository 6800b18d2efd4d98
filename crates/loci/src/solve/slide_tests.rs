//! The slide to the solution nearest the drawing, folded into Newton's steps, against the
//! same slide run after Newton has reached a solution: both must end at the same solution.
//! Likewise steps solved with an earlier factorisation, refined, against fresh ones.

use super::test_support::{moved, run, Rng};
use super::{Config, Outcome};
use crate::model::{Constraint, ConstraintKind as K, Entity, Param, System};

/// The workplane of the 2D sketches.
const WP: u32 = 200;
const G: u32 = 2;

/// An `n x n` truss: jittered lattice points, a distance on every bar (lengths of another
/// jitter, so the drawing does not hold), one diagonal bracing the first cell, the first
/// point where dragged. A mechanism with about `2n` degrees of freedom.
fn truss(n: usize) -> System {
    let mut rng = Rng(0x7255);
    let mut sys = System::new();
    sys.add_xy_workplane(1, 1, [101, 102, WP]).unwrap();
    let at = |i: usize, j: usize| j * n + i;
    let mut true_pts = Vec::new();
    for k in 0..n * n {
        let (i, j) = ((k % n) as f64, (k / n) as f64);
        let p = [10.0 * i + 3.0 * rng.next(), 10.0 * j + 3.0 * rng.next()];
        let drawn = [p[0] + 2.0 * rng.next(), p[1] + 2.0 * rng.next()];
        let (u, v) = (1000 + 2 * k as u32, 1001 + 2 * k as u32);
        sys.add_param(Param::new(u, G, drawn[0])).unwrap();
        sys.add_param(Param::new(v, G, drawn[1])).unwrap();
        sys.add_entity(Entity::point_2d(300 + k as u32, G, WP, [u, v]))
            .unwrap();
        true_pts.push(p);
    }
    let mut bars = Vec::new();
    for j in 0..n {
        for i in 0..n {
            if i + 1 < n {
                bars.push((at(i, j), at(i + 1, j)));
            }
            if j + 1 < n {
                bars.push((at(i, j), at(i, j + 1)));
            }
        }
    }
    bars.push((at(0, 0), at(1, 1)));
    for (c, &(p, q)) in bars.iter().enumerate() {
        let (a, b) = (true_pts[p], true_pts[q]);
        let len = (a[0] - b[0]).hypot(a[1] - b[1]);
        let con = Constraint::new(c as u32 + 1, G, K::PtPtDistance)
            .in_workplane(Some(WP))
            .with_points(300 + p as u32, 300 + q as u32)
            .with_val(len);
        sys.add_constraint(con).unwrap();
    }
    let pin = Constraint::new(bars.len() as u32 + 1, G, K::WhereDragged)
        .in_workplane(Some(WP))
        .with_points(300, 0);
    sys.add_constraint(pin).unwrap();
    sys
}

/// A chain of `n` segments in space: a distance between consecutive points (lengths of a
/// true chain, the drawing off it) and the first point where dragged. `2n` degrees of freedom.
fn chain_3d(n: usize) -> System {
    let mut rng = Rng(0x3d);
    let mut sys = System::new();
    let mut true_pts = Vec::new();
    let mut p = [0.0f64; 3];
    for k in 0..=n {
        if k > 0 {
            p = [
                p[0] + 8.0 + 4.0 * rng.next(),
                p[1] + 6.0 * rng.next(),
                p[2] + 6.0 * rng.next(),
            ];
        }
        let drawn = [
            p[0] + 0.3 * rng.next(),
            p[1] + 0.3 * rng.next(),
            p[2] + 0.3 * rng.next(),
        ];
        let h = [
            1000 + 3 * k as u32,
            1001 + 3 * k as u32,
            1002 + 3 * k as u32,
        ];
        for (t, &ph) in h.iter().enumerate() {
            sys.add_param(Param::new(ph, G, drawn[t])).unwrap();
        }
        sys.add_entity(Entity::point_3d(300 + k as u32, G, h))
            .unwrap();
        true_pts.push(p);
    }
    for k in 0..n {
        let (a, b) = (true_pts[k], true_pts[k + 1]);
        let len = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
        let con = Constraint::new(k as u32 + 1, G, K::PtPtDistance)
            .with_points(300 + k as u32, 301 + k as u32)
            .with_val(len);
        sys.add_constraint(con).unwrap();
    }
    let pin = Constraint::new(n as u32 + 1, G, K::WhereDragged).with_points(300, 0);
    sys.add_constraint(pin).unwrap();
    sys
}

/// The folded slide, the separate slide and Newton alone on `start`: the two slides land on
/// the same solution, nearer the drawing than Newton's, with the same DOF; the folded one in
/// no more iterations.
fn check_same_nearest(start: &System) {
    let folded_cfg = Config::default();
    let separate_cfg = Config {
        fold_slide: false,
        ..Config::default()
    };
    let (folded, xf) = run(start, G, &folded_cfg);
    let (separate, xs) = run(start, G, &separate_cfg);
    let (newton, xn) = run(start, G, &Config::default().with_nearest(false));
    for r in [&folded, &separate, &newton] {
        assert_eq!(r.outcome, Outcome::Okay, "{r:?}");
        assert!(r.residual <= 1e-10, "{r:?}");
    }
    assert_eq!(folded.dof, separate.dof);
    assert_eq!(folded.dof, newton.dof);
    assert!(folded.dof > 0, "{folded:?}");
    let scale = xs.iter().fold(1.0f64, |a, v| a.max(v.abs()));
    let largest = xf
        .iter()
        .zip(&xs)
        .fold(0.0f64, |a, (p, q)| a.max((p - q).abs()));
    assert!(largest <= 1e-7 * scale, "the slides differ by {largest}");
    let (mf, ms, mn) = (
        moved(start, G, &xf),
        moved(start, G, &xs),
        moved(start, G, &xn),
    );
    assert!((mf - ms).abs() <= 1e-9 * ms, "{mf} vs {ms}");
    assert!(mf < mn, "{mf} is not nearer than Newton's {mn}");
    assert!(
        folded.iterations <= separate.iterations,
        "{} vs {}",
        folded.iterations,
        separate.iterations
    );
}

#[test]
fn folded_and_separate_slides_reach_the_same_truss_solution() {
    check_same_nearest(&truss(12));
}

#[test]
fn folded_and_separate_slides_reach_the_same_chain_solution_in_space() {
    check_same_nearest(&chain_3d(60));
}

#[test]
fn a_fully_constrained_solve_takes_the_same_steps_with_or_without_the_slide() {
    // One braced cell with its first side horizontal is rigid: there is nothing to slide, so
    // the steps (and their rounding) are Newton's.
    let mut sys = truss(2);
    let level = Constraint::new(1000, G, K::Horizontal)
        .in_workplane(Some(WP))
        .with_points(300, 301);
    sys.add_constraint(level).unwrap();
    let (a, xa) = run(&sys, G, &Config::default());
    let (b, xb) = run(&sys, G, &Config::default().with_nearest(false));
    assert_eq!(a.dof, 0, "{a:?}");
    assert!(a.outcome.is_ok() && a.residual <= 1e-10, "{a:?}");
    assert!(a.iterations > 0, "{a:?}");
    assert_eq!(a.iterations, b.iterations);
    assert_eq!(xa, xb);
}

/// Solves `start` with steps after small ones solved with the factorisation before (the
/// default) and with a fresh factorisation every step: the same solution, DOF and iterations.
fn check_reuse_same(start: &System) {
    let fresh_cfg = Config {
        reuse_factor: false,
        ..Config::default()
    };
    let (reused, xr) = run(start, G, &Config::default());
    let (fresh, xf) = run(start, G, &fresh_cfg);
    for r in [&reused, &fresh] {
        assert!(r.outcome.is_ok() && r.residual <= 1e-10, "{r:?}");
    }
    assert_eq!(reused.dof, fresh.dof);
    assert_eq!(reused.iterations, fresh.iterations);
    let scale = xf.iter().fold(1.0f64, |a, v| a.max(v.abs()));
    let largest = xr
        .iter()
        .zip(&xf)
        .fold(0.0f64, |a, (p, q)| a.max((p - q).abs()));
    assert!(
        largest <= 1e-9 * scale,
        "reused and fresh differ by {largest}"
    );
}

#[test]
fn reused_and_fresh_factorisations_reach_the_same_truss_solution() {
    check_reuse_same(&truss(12));
    check_reuse_same(&truss(30));
}

#[test]
fn reused_and_fresh_factorisations_reach_the_same_chain_solution_in_space() {
    check_reuse_same(&chain_3d(60));
}
