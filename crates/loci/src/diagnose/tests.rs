//! Free motions checked against the equations themselves: each one, applied as a small
//! displacement of the whole system, must keep every residual at zero to first order.

use super::unmerged::Equations;
use super::*;
use crate::model::{Constraint, ConstraintKind as K, Entity, EntityId, Param};

/// The xy workplane (entity 200) in group 1.
fn plane(s: &mut System) {
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
    s.add_entity(Entity::workplane(200, 1, 101, 102)).unwrap();
}

fn pt2(s: &mut System, h: u32, p: u32, x: f64, y: f64) {
    s.add_param(Param::new(p, 2, x)).unwrap();
    s.add_param(Param::new(p + 1, 2, y)).unwrap();
    s.add_entity(Entity::point_2d(h, 2, 200, [p, p + 1]))
        .unwrap();
}

/// An under-constrained sketch with a bit of everything: a line pivoting about a dragged
/// start, a point on that line, a horizontal line free to slide and stretch, a circle with a
/// free radius, a point in 3D tied to a plane, and a free normal in 3D.
fn sketch() -> System {
    let mut s = System::new();
    plane(&mut s);
    pt2(&mut s, 301, 11, 0.0, 0.0);
    pt2(&mut s, 302, 13, 3.0, 4.0);
    s.add_entity(Entity::line(310, 2, Some(200), 301, 302))
        .unwrap();
    s.add_constraint(
        Constraint::new(1, 2, K::WhereDragged)
            .in_workplane(Some(200))
            .with_points(301, 0),
    )
    .unwrap();
    s.add_constraint(
        Constraint::new(2, 2, K::PtPtDistance)
            .in_workplane(Some(200))
            .with_points(301, 302)
            .with_val(5.0),
    )
    .unwrap();
    pt2(&mut s, 303, 15, 1.0, -2.0);
    pt2(&mut s, 304, 17, 6.0, -2.0);
    s.add_entity(Entity::line(311, 2, Some(200), 303, 304))
        .unwrap();
    s.add_constraint(
        Constraint::new(3, 2, K::Horizontal)
            .in_workplane(Some(200))
            .with_entities([311, 0, 0, 0]),
    )
    .unwrap();
    // A point on line 310.
    pt2(&mut s, 309, 23, 1.5, 2.0);
    s.add_constraint(
        Constraint::new(6, 2, K::PtOnLine)
            .in_workplane(Some(200))
            .with_points(309, 0)
            .with_entities([310, 0, 0, 0]),
    )
    .unwrap();
    // A circle: centre dragged, radius free.
    pt2(&mut s, 305, 19, 1.5, 2.0);
    s.add_param(Param::new(21, 2, 1.0)).unwrap();
    s.add_entity(Entity::distance(306, 2, Some(200), 21))
        .unwrap();
    s.add_entity(Entity::normal_2d(307, 2, 200)).unwrap();
    s.add_entity(Entity::circle(308, 2, Some(200), 305, 307, 306))
        .unwrap();
    s.add_constraint(
        Constraint::new(4, 2, K::WhereDragged)
            .in_workplane(Some(200))
            .with_points(305, 0),
    )
    .unwrap();
    // A 3D point at distance 2 from the workplane.
    s.add_param(Param::new(31, 2, 1.0)).unwrap();
    s.add_param(Param::new(32, 2, 1.0)).unwrap();
    s.add_param(Param::new(33, 2, 2.0)).unwrap();
    s.add_entity(Entity::point_3d(320, 2, [31, 32, 33]))
        .unwrap();
    s.add_constraint(
        Constraint::new(5, 2, K::PtPlaneDistance)
            .with_points(320, 0)
            .with_entities([200, 0, 0, 0])
            .with_val(2.0),
    )
    .unwrap();
    // A free orientation (its unit length is its only equation).
    let h = std::f64::consts::FRAC_1_SQRT_2;
    for (p, v) in [(41, h), (42, 0.0), (43, h), (44, 0.0)] {
        s.add_param(Param::new(p, 2, v)).unwrap();
    }
    s.add_entity(Entity::normal_3d(330, 2, [41, 42, 43, 44]))
        .unwrap();
    s
}

fn residuals(sys: &System, values: &[f64]) -> Vec<f64> {
    let start: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
    let eqs = Equations::new(sys, GroupId(2), &start).unwrap();
    let mut r = vec![0.0; eqs.rows];
    eqs.residuals(values, &mut r);
    r
}

#[test]
fn every_reported_motion_keeps_every_residual_zero_to_first_order() {
    let mut sys = sketch();
    assert!(sys.solve_group(2).unwrap().outcome.is_ok());
    let d = sys.diagnose(2).unwrap();
    let base: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
    assert!(residuals(&sys, &base).iter().all(|r| r.abs() < 1e-9));
    let eps = 1e-6;
    let mut checked = 0;
    for f in d.free_entities() {
        for i in 0..f.dof {
            let delta = d.displacement(f.entity, i).expect("a realised motion");
            let mut v = base.clone();
            for (p, x) in &delta {
                v[sys.param_index(*p).unwrap()] += eps * x;
            }
            // The entity itself moves by eps along its basis vector ...
            for (p, b) in f.params.iter().zip(&f.basis[i]) {
                let moved = v[sys.param_index(*p).unwrap()] - base[sys.param_index(*p).unwrap()];
                assert!(
                    (moved - eps * b).abs() < 1e-12,
                    "{f}: {p} moved {moved}, not {}",
                    eps * b
                );
            }
            // ... and nothing breaks beyond second order.
            let worst = residuals(&sys, &v)
                .iter()
                .fold(0.0f64, |a, r| a.max(r.abs()));
            assert!(
                worst < 1e3 * eps * eps,
                "{f}: motion {i} leaves a residual {worst:e}"
            );
            checked += 1;
        }
    }
    assert!(checked >= 8, "only {checked} motions");
}

#[test]
fn motions_are_named() {
    let mut sys = sketch();
    sys.solve_group(2).unwrap();
    let d = sys.diagnose(2).unwrap();
    let said = |h: u32| d.freedom(EntityId(h)).unwrap().to_string();
    // Start dragged, length fixed: the line pivots, its end moves across it.
    assert_eq!(
        said(310),
        "line 310: free to rotate about its start (entity 301)"
    );
    assert_eq!(said(301), "point 301: fixed");
    assert_eq!(said(302), "point 302: free to move along (0.8, -0.6)");
    assert_eq!(said(303), "point 303: free to move in its plane");
    assert_eq!(said(308), "circle 308: radius free");
    assert_eq!(said(309), "point 309: free to move in its plane");
    assert_eq!(said(305), "point 305: fixed");
    assert_eq!(
        said(311),
        "line 311: start free to move in its plane; end free to move in its plane; \
         3 degrees of freedom in all"
    );
    assert_eq!(said(306), "distance 306: value free");
    assert_eq!(
        said(320),
        "point 320: free to move in the plane normal to (0, 0, 1)"
    );
    assert_eq!(said(330), "normal 330: free to turn in any direction");
    // The pivot 1, line 311 3 (horizontal), point 309 1 more (along its line; turning with
    // the line is the pivot's), the radius 1, the 3D point 2, the normal 3.
    assert_eq!(d.dof, 1 + 3 + 1 + 1 + 2 + 3);
    assert_eq!(d.outcome, Outcome::Okay);
}

/// An `n x n` lattice of points in group 2 (the first one in group 1, pinned), each cell
/// split by the same diagonal, a distance on every edge at its drawn length; the first cell's
/// other diagonal is given a length one longer than it is, which cannot hold.
fn impossible_mesh(n: usize) -> System {
    let mut s = System::new();
    plane(&mut s);
    let at = |i: usize, j: usize| 1000 + (j * n + i) as u32;
    let xy = |i: usize, j: usize| {
        // A lattice bent a little, so that no two edges are parallel.
        let (x, y) = (i as f64, j as f64);
        (10.0 * x + 0.3 * (y * y), 10.0 * y + 0.2 * (x * x))
    };
    for j in 0..n {
        for i in 0..n {
            let (x, y) = xy(i, j);
            let p = 2 * at(i, j);
            let g = if (i, j) == (0, 0) { 1 } else { 2 };
            s.add_param(Param::new(p, g, x)).unwrap();
            s.add_param(Param::new(p + 1, g, y)).unwrap();
            s.add_entity(Entity::point_2d(at(i, j), g, 200, [p, p + 1]))
                .unwrap();
        }
    }
    let mut h = 1;
    let mut distance = |s: &mut System, a: (usize, usize), b: (usize, usize), extra: f64| {
        let (pa, pb) = (xy(a.0, a.1), xy(b.0, b.1));
        let d = ((pa.0 - pb.0).powi(2) + (pa.1 - pb.1).powi(2)).sqrt() + extra;
        s.add_constraint(
            Constraint::new(h, 2, K::PtPtDistance)
                .in_workplane(Some(200))
                .with_points(at(a.0, a.1), at(b.0, b.1))
                .with_val(d),
        )
        .unwrap();
        h += 1;
    };
    for j in 0..n {
        for i in 0..n {
            if i + 1 < n {
                distance(&mut s, (i, j), (i + 1, j), 0.0);
            }
            if j + 1 < n {
                distance(&mut s, (i, j), (i, j + 1), 0.0);
            }
            if i + 1 < n && j + 1 < n {
                distance(&mut s, (i, j), (i + 1, j + 1), 0.0);
            }
        }
    }
    distance(&mut s, (1, 0), (0, 1), 1.0);
    s
}

#[test]
fn the_screened_circuits_are_the_conflicting_ones_of_all_circuits() {
    let sys = impossible_mesh(30);
    let cfg = Config::default();
    let (report, values) =
        crate::solve::solve_core(&sys, 2.into(), &[], &cfg.clone().with_find_failed(false))
            .unwrap();
    assert_ne!(report.outcome, Outcome::Okay);
    let start: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
    let eqs = Equations::new(&sys, 2.into(), &start).unwrap();
    let lin = eqs.linearise(&values);
    let mut all = Rank::new(&eqs, &lin, &cfg).unwrap();
    let mut screened = Rank::new(&eqs, &lin, &cfg).unwrap();
    // Enough dependent rows for the screen to run.
    assert!(all.dropped.len() > 2 * 32, "{} dropped", all.dropped.len());
    let every = circuits::circuits(&eqs, &lin, &mut all, &cfg);
    let rows = circuits::may_conflict(&eqs, &lin, &mut screened, &cfg);
    let some = circuits::circuits_of(&eqs, &lin, &mut screened, &cfg, &rows);
    let conflicting = |c: &[Circuit]| -> Vec<Vec<usize>> {
        let mut out: Vec<Vec<usize>> = c
            .iter()
            .filter(|c| c.conflicting)
            .map(|c| c.rows.clone())
            .collect();
        out.sort();
        out
    };
    assert!(!conflicting(&every).is_empty());
    assert_eq!(conflicting(&some), conflicting(&every));
    assert!(
        some.len() < every.len(),
        "{} of {} computed, {} conflicting",
        some.len(),
        every.len(),
        conflicting(&every).len()
    );
}
