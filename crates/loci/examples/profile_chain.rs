//! Times solving a chain of N line segments: `cargo run --release -p loci --example profile_chain -- 10000`.
use loci::{Config, Constraint, ConstraintKind as K, Entity, GroupId, Param, System};
use std::time::Instant;

fn chain(n: usize, seed: u64) -> System {
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
        s.add_entity(Entity::point_2d(*e, 2, 3, [*p, *p + 1]))
            .unwrap();
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
        s.add_constraint(
            Constraint::new(c, 2, K::PtPtDistance)
                .in_workplane(Some(3))
                .with_points(a, b)
                .with_val(1.0),
        )
        .unwrap();
        c += 1;
        if let Some(pe) = prev_end {
            s.add_constraint(
                Constraint::new(c, 2, K::PointsCoincident)
                    .in_workplane(Some(3))
                    .with_points(pe, a),
            )
            .unwrap();
            c += 1;
        } else {
            s.add_constraint(
                Constraint::new(c, 2, K::WhereDragged)
                    .in_workplane(Some(3))
                    .with_points(a, 0),
            )
            .unwrap();
            c += 1;
        }
        if let Some(&pl) = lines.last() {
            let turn = (theta(i) - theta(i - 1)).abs().to_degrees();
            s.add_constraint(
                Constraint::new(c, 2, K::Angle)
                    .in_workplane(Some(3))
                    .with_entities([pl, l, 0, 0])
                    .with_val(turn),
            )
            .unwrap();
            c += 1;
        }
        lines.push(l);
        prev_end = Some(b);
        (x, y) = (x1, y1);
    }
    s
}

/// `n` independent triangles, each with one point dragged-fixed, a horizontal side and three
/// side lengths, started 0.3 away from a solution.
fn triangles(n: usize) -> System {
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
    s.add_entity(Entity::point_3d(1, 1, [1, 2, 3])).unwrap();
    s.add_entity(Entity::normal_3d(2, 1, [4, 5, 6, 7])).unwrap();
    s.add_entity(Entity::workplane(3, 1, 1, 2)).unwrap();
    let (mut p, mut e, mut c) = (10u32, 10u32, 1u32);
    for i in 0..n {
        let x0 = (i % 100) as f64 * 10.0;
        let y0 = (i / 100) as f64 * 10.0;
        let pts = [(x0, y0), (x0 + 3.2, y0 + 0.25), (x0 + 0.2, y0 + 4.3)];
        let mut ents = [0u32; 3];
        for (k, (x, y)) in pts.iter().enumerate() {
            s.add_param(Param::new(p, 2, *x)).unwrap();
            s.add_param(Param::new(p + 1, 2, *y)).unwrap();
            s.add_entity(Entity::point_2d(e, 2, 3, [p, p + 1])).unwrap();
            ents[k] = e;
            p += 2;
            e += 1;
        }
        let d = |a, b, v, c: &mut u32, s: &mut System| {
            s.add_constraint(
                Constraint::new(*c, 2, K::PtPtDistance)
                    .in_workplane(Some(3))
                    .with_points(a, b)
                    .with_val(v),
            )
            .unwrap();
            *c += 1;
        };
        d(ents[0], ents[1], 3.0, &mut c, &mut s);
        d(ents[1], ents[2], 5.0, &mut c, &mut s);
        d(ents[2], ents[0], 4.0, &mut c, &mut s);
        s.add_constraint(
            Constraint::new(c, 2, K::WhereDragged)
                .in_workplane(Some(3))
                .with_points(ents[0], 0),
        )
        .unwrap();
        c += 1;
        s.add_constraint(
            Constraint::new(c, 2, K::Horizontal)
                .in_workplane(Some(3))
                .with_points(ents[0], ents[1]),
        )
        .unwrap();
        c += 1;
    }
    s
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1000);
    let reps: usize = std::env::args()
        .nth(2)
        .and_then(|a| a.parse().ok())
        .unwrap_or(5);
    let base = if std::env::var_os("TRIANGLES").is_some() {
        triangles(n)
    } else {
        chain(n, 7)
    };
    let mut times = Vec::new();
    for _ in 0..reps {
        let mut s = base.clone();
        let t = Instant::now();
        let r = loci::solve(&mut s, GroupId(2), &[], &Config::default()).unwrap();
        times.push(t.elapsed().as_secs_f64() * 1e3);
        if times.len() == 1 {
            println!(
                "{:?} dof {} iters {} residual {:.2e} unknowns {} eqs {}",
                r.outcome, r.dof, r.iterations, r.residual, r.unknowns, r.equations
            );
        }
    }
    times.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!(
        "chain {n}: median {:.2} ms (min {:.2})",
        times[times.len() / 2],
        times[0]
    );
    // Re-solve after moving the fixed first point slightly, from the solved state.
    let mut solved = base.clone();
    let mut solver = loci::Solver::new(2, &[], Config::default());
    let t = Instant::now();
    solver.solve(&mut solved).unwrap();
    println!(
        "first solve with a Solver: {:.2} ms",
        t.elapsed().as_secs_f64() * 1e3
    );
    let mut again = Vec::new();
    for i in 0..reps {
        let p = loci::ParamId(10);
        let v = solved.value(p).unwrap();
        solved.set_value(p, v + 0.01);
        let t = Instant::now();
        let r = solver.solve(&mut solved).unwrap();
        again.push(t.elapsed().as_secs_f64() * 1e3);
        assert!(r.outcome.is_ok(), "{r:?}");
        if i == 0 {
            println!("re-solve: {} iterations", r.iterations);
        }
    }
    again.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!(
        "re-solve after moving the fixed point by 0.01: median {:.2} ms",
        again[again.len() / 2]
    );
}
