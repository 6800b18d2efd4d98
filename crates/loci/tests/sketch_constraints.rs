//! Every user constraint of a sketch: it holds after a solve, it is found again from a
//! perturbed start, and its value reads back; plus lock, removal and listing by shape.

use loci::sketch::{Axis, End, Measured, PointId, ShapeId, Sketch, SketchConstraintId, Spec};

const TOL: f64 = 1e-8;

fn m(s: &Sketch, id: SketchConstraintId) -> Measured {
    s.measure(id).unwrap()
}

/// Moves every point that is not fixed by a small, deterministic amount.
fn perturb(s: &mut Sketch, by: f64) {
    let pts: Vec<PointId> = s
        .shapes()
        .filter(|(_, k)| *k == loci::sketch::ShapeKind::Point)
        .map(|(h, _)| s.defining_points(h)[0])
        .collect();
    for (i, p) in pts.into_iter().enumerate() {
        let [x, y] = s.point(p);
        let t = i as f64 * 1.7;
        s.move_point(p, [x + by * t.sin(), y + by * t.cos()])
            .unwrap();
    }
}

/// Solves, checks every user constraint holds, perturbs, and checks again.
fn holds_from_start_and_perturbed(s: &mut Sketch, id: SketchConstraintId, want: Option<f64>) {
    for round in 0..2 {
        if round == 1 {
            perturb(s, 0.15);
            let worst = s
                .constraints()
                .map(|(c, _)| m(s, c).residual)
                .fold(0.0, f64::max);
            assert!(worst > 1e-6 || want.is_none(), "perturbed");
        }
        let r = s.solve().unwrap();
        assert!(r.outcome.is_ok(), "round {round}: {r:?}");
        let ids: Vec<_> = s.constraints().map(|(i, _)| i).collect();
        for c in ids {
            let got = m(s, c);
            assert!(
                got.residual < TOL,
                "round {round}: {:?} residual {}",
                s.constraint(c),
                got.residual
            );
        }
        if let Some(v) = want {
            let got = m(s, id).value.unwrap();
            assert!(
                (got - v).abs() < 1e-7,
                "round {round}: value {got}, want {v}"
            );
        }
        // Nothing of the solve stays in the system.
        let cores: usize = s
            .constraints()
            .map(|(i, _)| s.core_constraints(i).len())
            .sum();
        assert_eq!(s.system().constraints().len(), cores);
    }
}

fn line(s: &mut Sketch, a: [f64; 2], b: [f64; 2]) -> loci::sketch::LineId {
    let p = s.add_point(a[0], a[1]).unwrap();
    let q = s.add_point(b[0], b[1]).unwrap();
    s.add_line(p, q).unwrap()
}

#[test]
fn fix_holds_a_point_where_it_was_fixed() {
    let mut s = Sketch::new();
    let p = s.add_point(1.0, 2.0).unwrap();
    let l = line(&mut s, [3.0, 0.0], [4.0, 1.0]);
    let [a, _] = s.line_points(l);
    s.coincident(p, a).unwrap();
    let id = s.fix(p).unwrap();
    holds_from_start_and_perturbed(&mut s, id, None);
    let q = s.point(p);
    assert!((q[0] - 1.0).abs() < TOL && (q[1] - 2.0).abs() < TOL);
}

#[test]
fn fix_shape_holds_a_circle_and_its_radius() {
    let mut s = Sketch::new();
    let c0 = s.add_point(0.0, 0.0).unwrap();
    let c = s.add_circle(c0, 2.0).unwrap();
    let p = s.add_point(3.0, 0.5).unwrap();
    let id = s.fix_shape(c).unwrap();
    s.point_on_circle(p, c).unwrap();
    holds_from_start_and_perturbed(&mut s, id, None);
    let (ctr, r) = s.circle(c);
    assert!(ctr[0].abs() < TOL && ctr[1].abs() < TOL && (r - 2.0).abs() < TOL);
}

#[test]
fn length_horizontal_and_vertical() {
    let mut s = Sketch::new();
    let l = line(&mut s, [0.0, 0.0], [3.0, 1.0]);
    let v = line(&mut s, [5.0, 0.0], [5.5, 4.0]);
    let id = s.length(l, 5.0).unwrap();
    s.horizontal(l).unwrap();
    let vid = s.vertical(v).unwrap();
    holds_from_start_and_perturbed(&mut s, id, Some(5.0));
    let [p, q] = s.line(l);
    assert!((p[1] - q[1]).abs() < TOL);
    let [p, q] = s.line(v);
    assert!((p[0] - q[0]).abs() < TOL);
    assert_eq!(m(&s, vid).value, None);
}

#[test]
fn radius_diameter_and_arc_sweep() {
    let mut s = Sketch::new();
    let c0 = s.add_point(0.0, 0.0).unwrap();
    let c = s.add_circle(c0, 2.0).unwrap();
    let rid = s.radius(c, 2.5).unwrap();
    let [ac, a0, a1] =
        [[10.0, 0.0], [12.0, 0.0], [10.0, 2.0]].map(|p| s.add_point(p[0], p[1]).unwrap());
    let arc = s.add_arc(ac, a0, a1).unwrap();
    let did = s.diameter(arc, 6.0).unwrap();
    let sid = s.arc_sweep(arc, 120.0).unwrap();
    holds_from_start_and_perturbed(&mut s, rid, Some(2.5));
    assert!((m(&s, did).value.unwrap() - 6.0).abs() < 1e-7);
    assert!((m(&s, sid).value.unwrap() - 120.0).abs() < 1e-7);
    assert!((s.arc(arc).sweep - 120.0).abs() < 1e-7);
}

#[test]
fn a_sweep_past_half_a_turn_is_kept() {
    let mut s = Sketch::new();
    let [ac, a0, a1] =
        [[0.0, 0.0], [2.0, 0.0], [0.0, -2.0]].map(|p| s.add_point(p[0], p[1]).unwrap());
    let arc = s.add_arc(ac, a0, a1).unwrap();
    let id = s.arc_sweep(arc, 250.0).unwrap();
    holds_from_start_and_perturbed(&mut s, id, Some(250.0));
}

#[test]
fn distance_coincident_and_concentric() {
    let mut s = Sketch::new();
    let l1 = line(&mut s, [0.0, 0.0], [2.0, 0.0]);
    let l2 = line(&mut s, [2.2, 0.3], [4.0, 1.0]);
    let [_, b1] = s.line_points(l1);
    let [a2, b2] = s.line_points(l2);
    let cid = s.coincident(b1, a2).unwrap();
    let [p, _] = s.line_points(l1);
    let did = s.distance(p, b2, 3.5).unwrap();
    holds_from_start_and_perturbed(&mut s, did, Some(3.5));
    assert!(m(&s, cid).residual < TOL);

    let mut s = Sketch::new();
    let c0 = s.add_point(0.0, 0.0).unwrap();
    let c = s.add_circle(c0, 1.0).unwrap();
    let [ac, a0, a1] =
        [[0.4, 0.2], [2.4, 0.2], [0.4, 2.2]].map(|p| s.add_point(p[0], p[1]).unwrap());
    let arc = s.add_arc(ac, a0, a1).unwrap();
    let id = s.concentric(c, arc).unwrap();
    holds_from_start_and_perturbed(&mut s, id, None);
}

#[test]
fn parallel_perpendicular_and_equal_length() {
    let mut s = Sketch::new();
    let a = line(&mut s, [0.0, 0.0], [4.0, 1.0]);
    let b = line(&mut s, [0.0, 2.0], [4.0, 3.5]);
    let c = line(&mut s, [6.0, 0.0], [6.5, 3.0]);
    let pid = s.parallel(a, b).unwrap();
    let qid = s.perpendicular(a, c).unwrap();
    let eid = s.equal_length(b, c).unwrap();
    holds_from_start_and_perturbed(&mut s, pid, None);
    assert!(m(&s, qid).value.unwrap().abs() - 90.0 < 1e-7);
    assert!(m(&s, eid).value.unwrap().abs() < TOL);
}

#[test]
fn signed_angle_keeps_its_sign() {
    for want in [30.0f64, -30.0, 135.0, -150.0] {
        let mut s = Sketch::new();
        let a = line(&mut s, [0.0, 0.0], [4.0, 0.0]);
        // Drawn on the other side from where the angle asks for.
        let b = line(&mut s, [0.0, 1.0], [3.0, 1.0 - want.signum() * 1.0]);
        let id = s.angle(a, b, want).unwrap();
        holds_from_start_and_perturbed(&mut s, id, Some(want));
    }
}

#[test]
fn equal_radius_and_tangents() {
    // Line–arc at the arc's end, arc–arc, line–circle, circle–circle.
    let mut s = Sketch::new();
    let [ac, a0, a1] =
        [[0.0, 0.0], [2.0, 0.0], [0.1, 2.0]].map(|p| s.add_point(p[0], p[1]).unwrap());
    let arc = s.add_arc(ac, a0, a1).unwrap();
    let q = s.add_point(-3.0, 2.3).unwrap();
    let l = s.add_line(a1, q).unwrap();
    let t1 = s.tangent(l, End::Start, arc, End::End).unwrap();
    let [bc, b0, b1] =
        [[2.0, 4.2], [1.0, 5.0], [3.0, 4.0]].map(|p| s.add_point(p[0], p[1]).unwrap());
    let arc2 = s.add_arc(bc, b0, b1).unwrap();
    let t2 = s.tangent(arc, End::Start, arc2, End::End).unwrap();
    let c0 = s.add_point(8.0, 1.3).unwrap();
    let circle = s.add_circle(c0, 1.0).unwrap();
    let floor = line(&mut s, [5.0, 0.0], [11.0, 0.0]);
    let t3 = s.tangent(floor, End::Start, circle, End::Start).unwrap();
    let c1 = s.add_point(10.4, 1.0).unwrap();
    let circle2 = s.add_circle(c1, 1.2).unwrap();
    let t4 = s.tangent(circle, End::Start, circle2, End::Start).unwrap();
    let eq = s.equal_radius(circle, circle2).unwrap();
    s.fix_shape(floor).unwrap();
    holds_from_start_and_perturbed(&mut s, t1, None);
    for t in [t2, t3, t4, eq] {
        assert!(m(&s, t).residual < TOL);
    }
    // The circle stays above the floor, outside its neighbour.
    assert!(s.circle(circle).0[1] > 0.0);
    let ((p, r), (q2, r2)) = (s.circle(circle), s.circle(circle2));
    assert!(((p[0] - q2[0]).hypot(p[1] - q2[1]) - (r + r2)).abs() < 1e-7);
}

#[test]
fn points_on_lines_and_circles_midpoint_and_collinear() {
    let mut s = Sketch::new();
    let l = line(&mut s, [0.0, 0.0], [4.0, 2.0]);
    let p = s.add_point(1.0, 1.5).unwrap();
    let id = s.point_on_line(p, l).unwrap();
    let mid = s.add_point(2.5, 0.5).unwrap();
    let mid_id = s.midpoint(mid, l).unwrap();
    let c0 = s.add_point(0.0, 5.0).unwrap();
    let c = s.add_circle(c0, 1.5).unwrap();
    let on = s.add_point(1.0, 5.0).unwrap();
    let on_id = s.point_on_circle(on, c).unwrap();
    let l2 = line(&mut s, [5.0, 2.0], [7.0, 3.7]);
    let col = s.collinear(l, l2).unwrap();
    holds_from_start_and_perturbed(&mut s, id, None);
    for c in [mid_id, on_id, col] {
        assert!(m(&s, c).residual < TOL);
    }
}

#[test]
fn symmetric_about_a_line_and_an_axis_and_point_line_distance() {
    let mut s = Sketch::new();
    let axis = line(&mut s, [0.0, 0.0], [1.0, 1.0]);
    let a = s.add_point(2.0, 0.0).unwrap();
    let b = s.add_point(0.2, 1.7).unwrap();
    let id = s.symmetric(a, b, axis).unwrap();
    let c = s.add_point(-3.0, 1.0).unwrap();
    let d = s.add_point(2.5, 1.2).unwrap();
    let ax = s.symmetric_axis(c, d, Axis::Vertical).unwrap();
    let e = s.add_point(-1.0, -3.0).unwrap();
    let f = s.add_point(1.0, -3.3).unwrap();
    let ax2 = s.symmetric_axis(e, f, Axis::Horizontal).unwrap();
    let far = s.add_point(3.0, 1.0).unwrap();
    let pl = s.point_line_distance(far, axis, 2.0).unwrap();
    holds_from_start_and_perturbed(&mut s, pl, Some(2.0));
    for c in [id, ax, ax2] {
        assert!(m(&s, c).residual < TOL);
    }
    let (pc, pd) = (s.point(c), s.point(d));
    assert!((pc[0] + pd[0]).abs() < TOL && (pc[1] - pd[1]).abs() < TOL);
    let (pe, pf) = (s.point(e), s.point(f));
    assert!((pe[1] + pf[1]).abs() < TOL && (pe[0] - pf[0]).abs() < TOL);
    // Positive to the right of the axis's direction (below-right of y = x).
    let p = s.point(far);
    assert!(p[0] > p[1]);
}

#[test]
fn lock_toggles_and_keeps_a_line_and_an_arc() {
    let mut s = Sketch::new();
    let l = line(&mut s, [0.0, 0.0], [3.0, 4.0]);
    let lock = s.lock(l).unwrap().expect("locked");
    assert!(s.is_locked(l));
    s.horizontal(l).unwrap();
    let r = s.solve().unwrap();
    assert!(r.outcome.is_ok());
    let [p, q] = s.line(l);
    assert!(((q[0] - p[0]).abs() - 5.0).abs() < TOL && (q[1] - p[1]).abs() < TOL);
    assert!(m(&s, lock).residual < TOL);
    assert_eq!(s.lock(l).unwrap(), None, "the second call unlocks");
    assert!(!s.is_locked(l));
    assert!(s.constraint(lock).is_none());

    let mut s = Sketch::new();
    let [ac, a0, a1] =
        [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]].map(|p| s.add_point(p[0], p[1]).unwrap());
    let arc = s.add_arc(ac, a0, a1).unwrap();
    let lock = s.lock(arc).unwrap().unwrap();
    // Moving the centre carries the whole arc along: radius and angles are kept.
    s.move_point(ac, [1.0, 1.0]).unwrap();
    let r = s.solve().unwrap();
    assert!(r.outcome.is_ok());
    assert!(m(&s, lock).residual < TOL);
    let g = s.arc(arc);
    assert!((g.radius - 2.0).abs() < TOL && (g.sweep - 90.0).abs() < 1e-7);
    // A point cannot be locked.
    assert!(s.lock(ac).is_err());
}

#[test]
fn reference_dimensions_measure_and_never_drive() {
    let mut s = Sketch::new();
    let l = line(&mut s, [0.0, 0.0], [3.0, 4.0]);
    let id = s
        .add_reference(Spec::Length {
            line: l.into(),
            value: 1.0,
        })
        .unwrap();
    let r = s.solve().unwrap();
    assert!(r.outcome.is_ok());
    let got = m(&s, id);
    assert!((got.value.unwrap() - 5.0).abs() < TOL);
    assert_eq!(got.residual, 0.0);
    let [p, _] = s.line_points(l);
    assert!(s.add_reference(Spec::Fix { point: p.into() }).is_err());
}

#[test]
fn removing_a_point_removes_its_shapes_and_constraints_and_says_which() {
    let mut s = Sketch::new();
    let l = line(&mut s, [0.0, 0.0], [3.0, 0.0]);
    let l2 = line(&mut s, [3.0, 0.5], [3.0, 4.0]);
    let [a, b] = s.line_points(l);
    let [c, _] = s.line_points(l2);
    let h = s.horizontal(l).unwrap();
    let co = s.coincident(b, c).unwrap();
    let len = s.length(l2, 4.0).unwrap();
    assert_eq!(s.constraints_on(l), vec![h, co]);
    assert_eq!(s.constraints_on(b), vec![co]);
    let removed = s.remove_shape(b).unwrap();
    assert_eq!(removed.shapes, vec![ShapeId::from(b), l.into()]);
    assert_eq!(removed.constraints, vec![h, co]);
    assert!(s.kind(l).is_none() && s.kind(a).is_some());
    // What is left still solves and reads by index.
    let r = s.solve().unwrap();
    assert!(r.outcome.is_ok());
    assert!((m(&s, len).value.unwrap() - 4.0).abs() < TOL);
    assert!(s.remove_constraint(len).is_ok());
    assert!(s.remove_constraint(len).is_err());
}

#[test]
fn wrong_shapes_and_values_are_refused_by_name() {
    let mut s = Sketch::new();
    let l = line(&mut s, [0.0, 0.0], [1.0, 0.0]);
    let [p, _] = s.line_points(l);
    let err = s
        .add(Spec::Radius {
            shape: l.into(),
            value: 1.0,
        })
        .unwrap_err();
    assert!(err.to_string().contains("a circle or an arc"), "{err}");
    let err = s.add(Spec::Horizontal { line: p.into() }).unwrap_err();
    assert!(err.to_string().contains("a line"), "{err}");
    assert!(s.length(l, f64::NAN).is_err());
    assert!(s.length(l, -1.0).is_err());
    assert!(s.add_point(f64::INFINITY, 0.0).is_err());
    assert!(s.tangent(l, End::Start, l, End::End).is_err());
    assert_eq!(
        s.system().constraints().len(),
        0,
        "a refused constraint writes nothing"
    );
}

#[test]
fn set_value_is_a_value_edit() {
    let mut s = Sketch::new();
    let l = line(&mut s, [0.0, 0.0], [3.0, 0.0]);
    let id = s.length(l, 3.0).unwrap();
    let rev = s.system().revision();
    s.set_value(id, 7.0).unwrap();
    assert_eq!(s.system().revision(), rev);
    assert!(s.solve().unwrap().outcome.is_ok());
    assert!((m(&s, id).value.unwrap() - 7.0).abs() < TOL);
}

#[test]
fn a_cubic_tangent_to_a_line_at_its_start() {
    let mut s = Sketch::new();
    let p =
        [[0.0, 0.0], [1.0, 1.2], [3.0, 1.0], [4.0, 0.0]].map(|q| s.add_point(q[0], q[1]).unwrap());
    let cubic = s.add_cubic(p).unwrap();
    let q = s.add_point(-3.0, 0.4).unwrap();
    let l = s.add_line(q, p[0]).unwrap();
    s.horizontal(l).unwrap();
    let t = s.tangent(cubic, End::Start, l, End::End).unwrap();
    holds_from_start_and_perturbed(&mut s, t, None);
    // The first control leg lies along the line.
    let c = s.cubic(cubic);
    assert!((c[1][1] - c[0][1]).abs() < 1e-7);
    let round = s.add_circle(q, 1.0).unwrap();
    let err = s.add(Spec::Tangent {
        a: cubic.into(),
        b: round.into(),
        a_end: End::Start,
        b_end: End::Start,
    });
    assert!(err.is_err());
}
