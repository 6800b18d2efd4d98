//! Cubic Bezier curves: tangency to lines and between curves (arcs or cubics) at either end.

use super::fixture::{Break, Built, Case, Expect, Form, Fx, FIXED, MOVING};
use crate::model::ConstraintKind as K;
use Form::{Free, Mixed, Plane};

/// A cubic (fixed) and a line (moving) parallel to its tangent at the start, or at the end.
fn cubic_line(fx: &mut Fx, f: Form, at_end: bool) -> Built {
    let (cubic, line, want) = if f == Free {
        let p = [
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [3.0, 1.0, 1.0],
            [3.0, 3.0, 1.0],
        ];
        let cubic = fx.cubic(FIXED, f, p);
        // Tangents (2, 0, 0) at the start and (0, 2, 0) at the end. Broken by switching ends,
        // the rows are the cross product's components off the chosen tangent's dominant axis.
        let (to, want) = if at_end {
            ([1.0, 5.0, 3.0], vec![0.0, 1.0])
        } else {
            ([5.0, 2.0, 3.0], vec![0.0, -1.0])
        };
        (cubic, fx.line(MOVING, f, [1.0, 2.0, 3.0], to), want)
    } else {
        let p = [
            [0.0, 0.0, 0.2],
            [2.0, 1.0, -0.3],
            [4.0, 2.0, 0.5],
            [5.0, 0.0, -0.1],
        ];
        let cubic = fx.cubic(FIXED, f, p);
        // Tangents (2, 1) at the start and (1, -2) at the end: perpendicular, so the
        // normalised cross product at the wrong end is +-1.
        let (to, want) = if at_end {
            ([6.0, 3.0, -0.2], vec![-1.0])
        } else {
            ([9.0, 7.0, -0.2], vec![1.0])
        };
        (cubic, fx.line(MOVING, f, [5.0, 5.0, 0.3], to), want)
    };
    let c = fx
        .con(K::CubicLineTangent, f)
        .with_entities([cubic, line, 0, 0]);
    let c = c.with_flags(at_end, false);
    Built::new(c, Break::Flags(!at_end, false), Expect::Rows(want))
}

/// Arc centred at the origin with radius 2 from 0 to 90 degrees: tangent (0, 2) at its start
/// (2, 0) and (-2, 0) at its end (0, 2).
fn quarter(fx: &mut Fx) -> u32 {
    fx.arc_deg(FIXED, fx.wp, [0.0, 0.0], 2.0, 0.0, 90.0)
}

const CUBIC_A: [[f64; 3]; 4] = [
    [0.0, 0.0, 0.3],
    [1.0, 1.0, -0.2],
    [2.0, 1.0, 0.6],
    [3.0, 0.0, 0.1],
];
const CUBIC_B: [[f64; 3]; 4] = [
    [3.0, 0.0, -0.4],
    [4.0, -1.0, 0.2],
    [5.0, -1.0, 0.7],
    [6.0, 0.0, 0.0],
];

pub(super) fn cases() -> Vec<Case> {
    vec![
        Case {
            name: "cubic_line_tangent",
            kind: Some(K::CubicLineTangent),
            forms: &[Plane, Free, Mixed],
            build: |fx, f| cubic_line(fx, f, false),
        },
        Case {
            name: "cubic_line_tangent (other end)",
            kind: Some(K::CubicLineTangent),
            forms: &[Plane, Free, Mixed],
            build: |fx, f| cubic_line(fx, f, true),
        },
        Case {
            name: "curve_curve_tangent (arc, arc)",
            kind: Some(K::CurveCurveTangent),
            forms: &[Plane],
            build: |fx, f| {
                let a = quarter(fx);
                // Radius 2 about (4, 0) from 180 to 270 degrees: tangent (0, -2) at (2, 0).
                let b = fx.arc_deg(MOVING, fx.wp, [4.0, 0.0], 2.0, 180.0, 270.0);
                let c = fx.con(K::CurveCurveTangent, f).with_entities([a, b, 0, 0]);
                // The end of A against the start of B: (-2, 0) x (0, -2) / 4 = 1.
                Built::new(c, Break::Flags(true, false), Expect::Rows(vec![1.0]))
            },
        },
        Case {
            name: "curve_curve_tangent (arc, cubic)",
            kind: Some(K::CurveCurveTangent),
            forms: &[Plane, Mixed],
            build: |fx, f| {
                let a = quarter(fx);
                let p = [
                    [2.0, 0.0, 0.5],
                    [2.0, -1.0, -0.5],
                    [3.0, -2.0, 0.2],
                    [5.0, -2.0, 0.0],
                ];
                let b = fx.cubic(MOVING, f, p);
                let c = fx.con(K::CurveCurveTangent, f).with_entities([a, b, 0, 0]);
                // The start of A against the end of B: (0, 2) x (2, 0) / 4 = -1.
                Built::new(c, Break::Flags(false, true), Expect::Rows(vec![-1.0]))
            },
        },
        Case {
            name: "curve_curve_tangent (arc of another workplane, cubic)",
            kind: Some(K::CurveCurveTangent),
            forms: &[Mixed],
            build: |fx, f| {
                // An arc of `wp2` from 30 degrees; its tangent there, in space, projected into
                // the workplane the constraint is in, gives the cubic's start direction.
                let a = fx.arc_deg(FIXED, fx.wp2, [0.5, -0.5], 2.0, 30.0, 120.0);
                let [_, u2, v2, _] = fx.frame(fx.wp2);
                let [_, u, v, _] = fx.frame(fx.wp);
                let t = 30f64.to_radians();
                let t3 = u2.scale(-t.sin()).plus(v2.scale(t.cos()));
                let (du, dv) = (t3.dot(u), t3.dot(v));
                let p0 = [1.0, 2.0, 0.4];
                let p1 = [1.0 + 1.5 * du, 2.0 + 1.5 * dv, -0.3];
                let b = fx.cubic(MOVING, f, [p0, p1, [3.0, 0.0, 0.2], [4.0, 1.0, 0.0]]);
                let c = fx.con(K::CurveCurveTangent, f).with_entities([a, b, 0, 0]);
                // The cubic's end tangent (1, 1) against the projected arc tangent.
                let want = (du - dv) / (du.hypot(dv) * 2f64.sqrt());
                Built::new(c, Break::Flags(false, true), Expect::Rows(vec![want]))
            },
        },
        Case {
            name: "curve_curve_tangent (cubic, cubic)",
            kind: Some(K::CurveCurveTangent),
            forms: &[Plane, Mixed],
            build: |fx, f| {
                let a = fx.cubic(FIXED, f, CUBIC_A);
                let b = fx.cubic(MOVING, f, CUBIC_B);
                let c = fx.con(K::CurveCurveTangent, f).with_entities([a, b, 0, 0]);
                let c = c.with_flags(true, false);
                // The end of A (1, -1) against the end of B (1, 1): 2 / 2 = 1.
                Built::new(c, Break::Flags(true, true), Expect::Rows(vec![1.0]))
            },
        },
    ]
}

#[test]
fn curve_family_residuals_derivatives_and_solves() {
    super::check_family(&cases());
}
