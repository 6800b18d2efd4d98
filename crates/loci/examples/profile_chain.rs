//! Times solving a chain of N line segments: `cargo run --release -p loci --example profile_chain -- 10000`.
use loci::{Config, Constraint, ConstraintKind as K, Entity, GroupId, Param, System};
use std::time::Instant;

fn chain(n: usize, seed: u64) -> System {
    let mut s = System::new();
    for (h, v) in [(1, 0.0), (2, 0.0), (3, 0.0), (4, 1.0), (5, 0.0), (6, 0.0), (7, 0.0)] {
        s.add_param(Param::new(h, 1, v)).unwrap();
    }
    s.add_entity(Entity::point_3d(1, 1, [1, 2, 3])).unwrap();
    s.add_entity(Entity::normal_3d(2, 1, [4, 5, 6, 7])).unwrap();
    s.add_entity(Entity::workplane(3, 1, 1, 2)).unwrap();
    let mut rng = seed;
    let mut rnd = || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng % 10000) as f64 / 10000.0 - 0.5
    };
    let (mut p, mut e, mut c) = (10u32, 10u32, 1u32);
    let pt = |s: &mut System, p: &mut u32, e: &mut u32, x: f64, y: f64| {
        s.add_param(Param::new(*p, 2, x)).unwrap();
        s.add_param(Param::new(*p + 1, 2, y)).unwrap();
        s.add_entity(Entity::point_2d(*e, 2, 3, [*p, *p + 1])).unwrap();
        *p += 2;
        *e += 1;
        *e - 1
    };
    let mut lines = Vec::new();
    let mut prev_end = None;
    // The solution: a wavy chain of unit segments; the start is it perturbed by up to 0.15.
    let theta = |i: usize| (i as f64 * 0.3).sin() * 0.5;
    let (mut x, mut y) = (0.0f64, 0.0f64);
    for i in 0..n {
        let (x1, y1) = (x + theta(i).cos(), y + theta(i).sin());
        let a = pt(&mut s, &mut p, &mut e, x + 0.3 * rnd(), y + 0.3 * rnd());
        let b = pt(&mut s, &mut p, &mut e, x1 + 0.3 * rnd(), y1 + 0.3 * rnd());
        let l = e;
        s.add_entity(Entity::line(l, 2, Some(3), a, b)).unwrap();
        e += 1;
        s.add_constraint(Constraint::new(c, 2, K::PtPtDistance).in_workplane(Some(3)).with_points(a, b).with_val(1.0)).unwrap();
        c += 1;
        if let Some(pe) = prev_end {
            s.add_constraint(Constraint::new(c, 2, K::PointsCoincident).in_workplane(Some(3)).with_points(pe, a)).unwrap();
            c += 1;
        } else {
            s.add_constraint(Constraint::new(c, 2, K::WhereDragged).in_workplane(Some(3)).with_points(a, 0)).unwrap();
            c += 1;
        }
        if let Some(&pl) = lines.last() {
            let turn = (theta(i) - theta(i - 1)).abs().to_degrees();
            s.add_constraint(Constraint::new(c, 2, K::Angle).in_workplane(Some(3)).with_entities([pl, l, 0, 0]).with_val(turn)).unwrap();
            c += 1;
        }
        lines.push(l);
        prev_end = Some(b);
        (x, y) = (x1, y1);
    }
    s
}

fn main() {
    let n: usize = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(1000);
    let reps: usize = std::env::args().nth(2).and_then(|a| a.parse().ok()).unwrap_or(5);
    let base = chain(n, 7);
    let mut times = Vec::new();
    for _ in 0..reps {
        let mut s = base.clone();
        let t = Instant::now();
        let r = loci::solve(&mut s, GroupId(2), &[], &Config::default()).unwrap();
        times.push(t.elapsed().as_secs_f64() * 1e3);
        if times.len() == 1 {
            println!("{:?} dof {} iters {} residual {:.2e} unknowns {} eqs {}", r.outcome, r.dof, r.iterations, r.residual, r.unknowns, r.equations);
        }
    }
    times.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!("chain {n}: median {:.2} ms (min {:.2})", times[times.len() / 2], times[0]);
}
