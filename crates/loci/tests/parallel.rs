//! Large groups are compiled and their components solved on several threads; the answer must
//! not depend on how many: every value bit for bit, and the same report.
#![allow(missing_docs)]

mod common;

use loci::{Config, Constraint, ConstraintKind as K, Entity, Param, System};

/// `n` independent triangles in the xy workplane, each started off its solution: three lengths,
/// a horizontal base and a pinned corner. Thousands of components and constraints, so both the
/// compile and the solve are split across threads.
fn triangles(n: u32) -> System {
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
        s.add_param(Param::new(h, 1, v)).expect("fresh");
    }
    s.add_entity(Entity::point_3d(1, 1, [1, 2, 3]))
        .expect("fresh");
    s.add_entity(Entity::normal_3d(2, 1, [4, 5, 6, 7]))
        .expect("fresh");
    s.add_entity(Entity::workplane(3, 1, 1, 2)).expect("fresh");
    let wp = Some(3);
    for i in 0..n {
        let (p, e, c) = (100 + 6 * i, 100 + 4 * i, 100 + 5 * i);
        let x0 = 40.0 * f64::from(i);
        // A 3-4-5 triangle, each coordinate moved by a different small amount.
        let start = [(x0, 0.0), (x0 + 3.3, 0.2), (x0 - 0.1, 3.8)];
        for (k, (x, y)) in start.into_iter().enumerate() {
            let k = k as u32;
            let wobble = f64::from((i * 7 + k * 3) % 11) * 0.01;
            s.add_param(Param::new(p + 2 * k, 2, x + wobble))
                .expect("fresh");
            s.add_param(Param::new(p + 2 * k + 1, 2, y - wobble))
                .expect("fresh");
            s.add_entity(Entity::point_2d(e + k, 2, 3, [p + 2 * k, p + 2 * k + 1]))
                .expect("fresh");
        }
        s.add_entity(Entity::line(e + 3, 2, wp, e, e + 1))
            .expect("fresh");
        let dist = |h, a, b, d| {
            Constraint::new(h, 2, K::PtPtDistance)
                .in_workplane(wp)
                .with_points(a, b)
                .with_val(d)
        };
        for con in [
            dist(c, e, e + 1, 3.0),
            dist(c + 1, e, e + 2, 4.0),
            dist(c + 2, e + 1, e + 2, 5.0),
            Constraint::new(c + 3, 2, K::Horizontal)
                .in_workplane(wp)
                .with_entities([e + 3, 0, 0, 0]),
            Constraint::new(c + 4, 2, K::WhereDragged)
                .in_workplane(wp)
                .with_points(e, 0),
        ] {
            s.add_constraint(con).expect("fresh");
        }
    }
    s
}

/// Solves a copy of `sys` on a pool of `threads` threads: the report and every value's bits.
fn solve_on(sys: &System, threads: usize) -> (String, Vec<u64>) {
    solve_group_on(sys, 2, threads)
}

fn solve_group_on(sys: &System, group: u32, threads: usize) -> (String, Vec<u64>) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    let mut sys = sys.clone();
    let report = pool
        .install(|| loci::solve(&mut sys, group.into(), &[], &Config::default()))
        .expect("valid");
    let bits = sys.params().iter().map(|p| p.val.to_bits()).collect();
    (format!("{report:?}"), bits)
}

#[test]
fn thread_count_does_not_change_the_answer() {
    let sys = triangles(1500);
    let (report, one) = solve_on(&sys, 1);
    assert!(report.contains("Okay"), "{report}");
    assert!(report.contains("components: 1500"), "{report}");
    for threads in [2, 3] {
        let (r, bits) = solve_on(&sys, threads);
        assert_eq!(r, report, "report with {threads} threads");
        assert!(bits == one, "values differ with {threads} threads");
    }
    // And the triangles did move onto their lengths: corner 3 of the first is 4 from corner 1.
    let mut solved = sys.clone();
    loci::solve(&mut solved, 2.into(), &[], &Config::default()).expect("valid");
    let v = |h: u32| solved.value(loci::ParamId(h)).expect("param");
    let d = ((v(104) - v(100)).powi(2) + (v(105) - v(101)).powi(2)).sqrt();
    assert!((d - 4.0).abs() < 1e-9, "{d}");
}

#[test]
fn one_large_component_evaluated_on_several_threads_gives_the_same_answer() {
    // 3,000 segments: about 6,000 rows in one component, whose equations are evaluated on all
    // cores.
    let ch = common::perturbed_chain::chain(3000, 4, 0.3);
    let (report, one) = solve_group_on(&ch.system, ch.group.0, 1);
    assert!(report.contains("Okay"), "{report}");
    assert!(report.contains("components: 1"), "{report}");
    for threads in [2, 3] {
        let (r, bits) = solve_group_on(&ch.system, ch.group.0, threads);
        assert_eq!(r, report, "report with {threads} threads");
        assert!(bits == one, "values differ with {threads} threads");
    }
}
