//! Circles and arcs: diameters, points on circles, equal radii, arc lengths, tangency of arcs
//! and lines, and the arc's implicit equal radii.

use std::f64::consts::PI;

use super::fixture::{
    arr, axis_angle, compile, v3, Break, Built, Case, Expect, Form, Fx, Target, FIXED, MOVING,
};
use crate::geom::Quat;
use crate::model::ConstraintKind as K;
use Form::{Free, Mixed, Plane};

/// The orientation of the 3D circles.
fn circle_q() -> [f64; 4] {
    axis_angle([0.3, -1.0, 0.5], 0.8)
}

/// Values that move point `p` of an arc centred at `c` (in the arc's own workplane `wp`)
/// radially outwards by `dr`.
fn push_out(fx: &Fx, wp: u32, c: [f64; 2], p: u32, dr: f64) -> Vec<(u32, f64)> {
    let ps = fx.params(p);
    let (u, v) = (fx.value(ps[0]), fx.value(ps[1]));
    let (du, dv) = (u - c[0], v - c[1]);
    let k = 1.0 + dr / du.hypot(dv);
    assert!(fx.entity(p).workplane.map(|w| w.0) == Some(wp));
    vec![(ps[0], c[0] + k * du), (ps[1], c[1] + k * dv)]
}

/// A line of length `len` in the workplane (plane) or in space along (2, 1, 2) / 3 (free),
/// with the values that lengthen it by `more`.
fn line_of_length(fx: &mut Fx, g: u32, f: Form, len: f64, more: f64) -> (u32, Vec<(u32, f64)>) {
    let (o, d) = if f == Free {
        ([1.0, 1.0, 1.0], [2.0 / 3.0, 1.0 / 3.0, 2.0 / 3.0])
    } else {
        ([0.0, -3.0, 0.0], [1.0, 0.0, 0.0])
    };
    let at = |k: f64| [o[0] + k * d[0], o[1] + k * d[1], o[2] + k * d[2]];
    let l = fx.line(g, f, at(0.0), at(len));
    let brk = fx.place(f, fx.point_of(l, 1), at(len + more));
    (l, brk)
}

/// Arc-length relations: arc A (moving) of radius `ra` over `sa` degrees, and arc B (in `wp2`
/// for the mixed form) of radius `rb` over `sb` degrees, or a line of length `lb`.
fn arc_relation(fx: &mut Fx, f: Form, kind: K) -> Built {
    let wp = fx.wp;
    let a = fx.arc_deg(MOVING, wp, [0.0, 0.0], 3.0, 20.0, 110.0); // 1.5 pi
    let with_arc = matches!(kind, K::ArcArcLenRatio | K::ArcArcDifference);
    let b = if with_arc {
        let wp_b = if f == Mixed { fx.wp2 } else { fx.wp };
        fx.arc_deg(FIXED, wp_b, [5.0, 0.0], 1.0, 300.0, 210.0) // 270 degrees: 1.5 pi
    } else {
        line_of_length(fx, FIXED, f, 0.75 * PI, 0.0).0
    };
    // SolveSpace's order for the arc-line relations: the line first.
    let c = if with_arc {
        fx.con(kind, f).with_entities([a, b, 0, 0])
    } else {
        fx.con(kind, f).with_entities([b, a, 0, 0])
    };
    match kind {
        K::ArcArcLenRatio => Built::new(
            c.with_val(1.0),
            Break::Val(2.0),
            Expect::Rows(vec![-1.5 * PI]),
        ),
        K::ArcLineLenRatio => Built::new(
            c.with_val(2.0),
            Break::Val(3.0),
            Expect::Rows(vec![-0.75 * PI]),
        ),
        _ => {
            let val = if with_arc { 0.0 } else { 0.75 * PI };
            Built::new(
                c.with_val(val),
                Break::Val(val - 1.0),
                Expect::Rows(vec![1.0]),
            )
        }
    }
}

/// Arc centred at the origin of the workplane with radius 2 from 0 to 90 degrees, and a line
/// (moving) tangent to it at its start (vertical through (2, 0)) or end (horizontal through
/// (0, 2)).
fn arc_line_tangent(fx: &mut Fx, f: Form, at_end: bool) -> Built {
    let arc = fx.arc_deg(FIXED, fx.wp, [0.0, 0.0], 2.0, 0.0, 90.0);
    let line = if at_end {
        fx.line(MOVING, f, [-1.0, 2.0, 0.4], [3.0, 2.0, -0.3])
    } else {
        fx.line(MOVING, f, [2.0, -1.0, 0.4], [2.0, 3.0, -0.3])
    };
    let c = fx
        .con(K::ArcLineTangent, f)
        .with_entities([arc, line, 0, 0]);
    // At the other end the line runs along the radius: cos = 1.
    let c = c.with_flags(at_end, false);
    Built::new(c, Break::Flags(!at_end, false), Expect::Rows(vec![1.0]))
}

pub(super) fn cases() -> Vec<Case> {
    vec![
        Case {
            name: "diameter",
            kind: Some(K::Diameter),
            forms: &[Free, Plane],
            build: |fx, f| {
                let (e, d) = if f == Free {
                    (
                        fx.circle(MOVING, Free, [1.0, 2.0, 3.0], circle_q(), 2.5),
                        5.0,
                    )
                } else {
                    (fx.arc_deg(MOVING, fx.wp, [0.0, 0.0], 3.0, 30.0, 120.0), 6.0)
                };
                let c = fx
                    .con(K::Diameter, f)
                    .with_entities([e, 0, 0, 0])
                    .with_val(d);
                Built::new(c, Break::Val(d - 1.0), Expect::Rows(vec![1.0]))
            },
        },
        Case {
            name: "pt_on_circle",
            kind: Some(K::PtOnCircle),
            forms: &[Free, Plane, Mixed],
            build: |fx, f| {
                let t = 40f64.to_radians();
                if f == Free {
                    // On the cylinder: 1.3 above the circle's plane.
                    let circle = fx.circle(FIXED, Free, [1.0, 2.0, 3.0], circle_q(), 2.0);
                    let q = circle_q();
                    let q = Quat {
                        w: q[0],
                        x: q[1],
                        y: q[2],
                        z: q[3],
                    };
                    let p = v3([1.0, 2.0, 3.0])
                        .plus(q.u().scale(2.0 * t.cos()))
                        .plus(q.v().scale(2.0 * t.sin()))
                        .plus(q.n().scale(1.3));
                    let p = fx.p3(MOVING, arr(p));
                    let c = fx.con(K::PtOnCircle, f).with_points(p, 0);
                    let brk = vec![(fx.radius_param(circle), 2.5)];
                    let c = c.with_entities([circle, 0, 0, 0]);
                    return Built::new(c, Break::Set(brk), Expect::Rows(vec![-0.5]));
                }
                let arc = fx.arc_deg(FIXED, fx.wp, [1.0, 1.0], 3.0, 0.0, 120.0);
                let at = [1.0 + 3.0 * t.cos(), 1.0 + 3.0 * t.sin(), 2.0];
                let p = if f == Plane {
                    fx.pt(MOVING, f, at)
                } else {
                    fx.lift(MOVING, at)
                };
                let brk = fx.shift(Mixed, p, [0.5 * t.cos(), 0.5 * t.sin(), 0.0]);
                let c = fx
                    .con(K::PtOnCircle, f)
                    .with_points(p, 0)
                    .with_entities([arc, 0, 0, 0]);
                Built::new(c, Break::Set(brk), Expect::Rows(vec![0.5]))
            },
        },
        Case {
            // SolveSpace keeps a circle whose radius parameter is negative and holds its
            // points at |r|: a point 2 from the centre is on the circle of radius -2, and
            // moving the radius to -2.5 leaves it 0.5 inside.
            name: "pt_on_circle with a negative radius",
            kind: Some(K::PtOnCircle),
            forms: &[Free],
            build: |fx, f| {
                let circle = fx.circle(FIXED, Free, [1.0, 2.0, 3.0], circle_q(), -2.0);
                let q = circle_q();
                let q = Quat {
                    w: q[0],
                    x: q[1],
                    y: q[2],
                    z: q[3],
                };
                let t = 200f64.to_radians();
                let p = v3([1.0, 2.0, 3.0])
                    .plus(q.u().scale(2.0 * t.cos()))
                    .plus(q.v().scale(2.0 * t.sin()))
                    .plus(q.n().scale(-0.7));
                let p = fx.p3(MOVING, arr(p));
                let brk = vec![(fx.radius_param(circle), -2.5)];
                let c = fx
                    .con(K::PtOnCircle, f)
                    .with_points(p, 0)
                    .with_entities([circle, 0, 0, 0]);
                Built::new(c, Break::Set(brk), Expect::Rows(vec![-0.5]))
            },
        },
        Case {
            name: "equal_radius",
            kind: Some(K::EqualRadius),
            forms: &[Free, Plane, Mixed],
            build: |fx, f| {
                let c = fx.con(K::EqualRadius, f);
                match f {
                    Free => {
                        let a = fx.circle(FIXED, Free, [1.0, 2.0, 3.0], circle_q(), 2.0);
                        let q = axis_angle([1.0, 1.0, 0.0], -0.4);
                        let b = fx.circle(MOVING, Free, [-1.0, 0.0, 2.0], q, 2.0);
                        let brk = vec![(fx.radius_param(b), 2.75)];
                        let c = c.with_entities([a, b, 0, 0]);
                        Built::new(c, Break::Set(brk), Expect::Rows(vec![-0.75]))
                    }
                    Plane => {
                        let a = fx.arc_deg(FIXED, fx.wp, [0.0, 0.0], 2.0, 0.0, 90.0);
                        let b = fx.arc_deg(MOVING, fx.wp, [5.0, 0.0], 2.0, 30.0, 200.0);
                        let brk = push_out(fx, fx.wp, [5.0, 0.0], fx.point_of(b, 1), 0.75);
                        let c = c.with_entities([a, b, 0, 0]);
                        Built::new(c, Break::Set(brk), Expect::Rows(vec![-0.75]))
                    }
                    Mixed => {
                        // A circle in space and an arc of the other workplane.
                        let a = fx.circle(FIXED, Free, [1.0, 2.0, 3.0], circle_q(), 2.0);
                        let b = fx.arc_deg(MOVING, fx.wp2, [0.0, 0.0], 2.0, 30.0, 200.0);
                        let brk = vec![(fx.radius_param(a), 2.75)];
                        let c = c.with_entities([a, b, 0, 0]);
                        Built::new(c, Break::Set(brk), Expect::Rows(vec![0.75]))
                    }
                }
            },
        },
        Case {
            name: "equal_line_arc_len",
            kind: Some(K::EqualLineArcLen),
            // The line's length is its length in space, whatever the workplane.
            forms: &[Plane, Free],
            build: |fx, f| {
                // Radius 2 over 270 degrees: 3 pi.
                let arc = fx.arc_deg(FIXED, fx.wp, [0.0, 0.0], 2.0, 60.0, 330.0);
                let (line, brk) = line_of_length(fx, MOVING, f, 3.0 * PI, 0.5);
                let c = fx
                    .con(K::EqualLineArcLen, f)
                    .with_entities([line, arc, 0, 0]);
                Built::new(c, Break::Set(brk), Expect::Rows(vec![0.5]))
            },
        },
        Case {
            name: "arc_arc_len_ratio",
            kind: Some(K::ArcArcLenRatio),
            forms: &[Plane, Mixed],
            build: |fx, f| arc_relation(fx, f, K::ArcArcLenRatio),
        },
        Case {
            name: "arc_line_len_ratio",
            kind: Some(K::ArcLineLenRatio),
            forms: &[Plane, Free],
            build: |fx, f| arc_relation(fx, f, K::ArcLineLenRatio),
        },
        Case {
            name: "arc_arc_difference",
            kind: Some(K::ArcArcDifference),
            forms: &[Plane, Mixed],
            build: |fx, f| arc_relation(fx, f, K::ArcArcDifference),
        },
        Case {
            name: "arc_line_difference",
            kind: Some(K::ArcLineDifference),
            forms: &[Plane, Free],
            build: |fx, f| arc_relation(fx, f, K::ArcLineDifference),
        },
        Case {
            name: "arc_line_tangent",
            kind: Some(K::ArcLineTangent),
            forms: &[Plane, Mixed],
            build: |fx, f| arc_line_tangent(fx, f, false),
        },
        Case {
            name: "arc_line_tangent (other end)",
            kind: Some(K::ArcLineTangent),
            forms: &[Plane, Mixed],
            build: |fx, f| arc_line_tangent(fx, f, true),
        },
        Case {
            name: "arc_radii",
            kind: None,
            forms: &[Plane],
            build: |fx, _| {
                let arc = fx.arc_deg(MOVING, fx.wp, [0.5, -0.5], 2.0, 10.0, 100.0);
                let brk = push_out(fx, fx.wp, [0.5, -0.5], fx.point_of(arc, 2), 0.5);
                Built {
                    target: Target::Entity(arc),
                    brk: Break::Set(brk),
                    expect: Expect::Rows(vec![-0.5]),
                }
            },
        },
    ]
}

#[test]
fn circle_family_residuals_derivatives_and_solves() {
    super::check_family(&cases());
}

#[test]
fn arc_length_counts_the_counter_clockwise_sweep() {
    // The same three points swept the other way: 90 and 270 degrees; and a closed arc is a
    // full circle.
    for (from, to, sweep) in [(0.0, 90.0, 90.0), (90.0, 0.0, 270.0), (30.0, 30.0, 360.0)] {
        let mut fx = Fx::new();
        let arc = fx.arc_deg(MOVING, fx.wp, [0.0, 0.0], 2.0, from, to);
        let len: f64 = 2.0 * f64::to_radians(sweep);
        let c = fx.con(K::ArcLineDifference, Plane);
        let line = fx.line(FIXED, Plane, [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        let one = compile(
            &fx.sys,
            &c.with_entities([line, arc, 0, 0]).with_val(len - 1.0),
        );
        let r = one.residuals(&one.x(&fx.sys));
        assert!(r[0].abs() < 1e-12, "{from} -> {to}: {r:?}");
    }
}
