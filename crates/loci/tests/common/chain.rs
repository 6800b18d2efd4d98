//! A chain of unit segments in a workplane, for tests and benchmarks: consecutive segments
//! joined by `points_coincident`, a `pt_pt_distance` per segment, an `angle` between
//! neighbours, the first point `where_dragged`. The drawing starts a little off its solution.
#![allow(dead_code)]

use loci::{Constraint, ConstraintId, ConstraintKind as K, Entity, Param, System};

/// The workplane entity.
pub const WP: u32 = 3;

/// Handles of segment `i`: its start point, end point and line.
pub fn segment(i: usize) -> (u32, u32, u32) {
    let e = 10 + 3 * i as u32;
    (e, e + 1, e + 2)
}

/// The handle of the distance constraint of segment `i`.
pub fn distance_of(i: usize) -> ConstraintId {
    // where_dragged, then per segment: distance, and (after the first) coincident and angle.
    ConstraintId(if i == 0 { 2 } else { 3 + 3 * (i as u32 - 1) })
}

/// A chain of `n` segments. With `conflict`, segment `n / 2` gets a second distance (1.5, the
/// last constraint added) that contradicts its own: the returned handle.
pub fn chain(n: usize, conflict: bool) -> (System, Option<ConstraintId>) {
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
    s.add_entity(Entity::workplane(WP, 1, 1, 2)).unwrap();
    let wp = Some(WP);
    let mut c = 1u32;
    let add = |s: &mut System, k: Constraint| {
        s.add_constraint(k).unwrap();
    };
    // A zigzag: segments alternate between +30 and -30 degrees, 60 degrees apart.
    let (mut x, mut y) = (0.0f64, 0.0f64);
    let wobble = |k: u32| 0.02 * ((k as f64 * 0.7548776662).fract() - 0.5);
    for i in 0..n {
        let t = if i % 2 == 0 { 30f64 } else { -30f64 }.to_radians();
        let (x1, y1) = (x + t.cos(), y + t.sin());
        let (a, b, l) = segment(i);
        let p = 100 + 4 * i as u32;
        for (h, v) in [(p, x), (p + 1, y), (p + 2, x1), (p + 3, y1)] {
            s.add_param(Param::new(h, 2, v + wobble(h))).unwrap();
        }
        s.add_entity(Entity::point_2d(a, 2, WP, [p, p + 1]))
            .unwrap();
        s.add_entity(Entity::point_2d(b, 2, WP, [p + 2, p + 3]))
            .unwrap();
        s.add_entity(Entity::line(l, 2, wp, a, b)).unwrap();
        if i == 0 {
            add(
                &mut s,
                Constraint::new(c, 2, K::WhereDragged)
                    .in_workplane(wp)
                    .with_points(a, 0),
            );
            c += 1;
        }
        add(
            &mut s,
            Constraint::new(c, 2, K::PtPtDistance)
                .in_workplane(wp)
                .with_points(a, b)
                .with_val(1.0),
        );
        c += 1;
        if i > 0 {
            let (_, prev_b, prev_l) = segment(i - 1);
            add(
                &mut s,
                Constraint::new(c, 2, K::PointsCoincident)
                    .in_workplane(wp)
                    .with_points(prev_b, a),
            );
            c += 1;
            add(
                &mut s,
                Constraint::new(c, 2, K::Angle)
                    .in_workplane(wp)
                    .with_entities([prev_l, l, 0, 0])
                    .with_val(60.0),
            );
            c += 1;
        }
        (x, y) = (x1, y1);
    }
    let extra = conflict.then(|| {
        let (a, b, _) = segment(n / 2);
        add(
            &mut s,
            Constraint::new(c, 2, K::PtPtDistance)
                .in_workplane(wp)
                .with_points(a, b)
                .with_val(1.5),
        );
        ConstraintId(c)
    });
    (s, extra)
}
