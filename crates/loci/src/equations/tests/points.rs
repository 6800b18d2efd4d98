//! Points: coincidence, distances to points and planes, symmetry, midpoints, horizontal and
//! vertical, where dragged.

use super::fixture::{
    arr, axis_angle, compile, rank, v3, Break, Built, Case, Expect, Form, Fx, FIXED, MOVING,
};
use crate::model::ConstraintKind as K;
use Form::{Free, Mixed, Plane};

/// Rows of a point-valued residual: two in a workplane, three in space.
fn rows(f: Form, r: [f64; 3]) -> Expect {
    Expect::Rows(if f == Free {
        r.to_vec()
    } else {
        r[..2].to_vec()
    })
}

/// A point at signed distance `h` from the workplane: 3D (free) or a point of `wp2` (plane).
fn off_plane(fx: &mut Fx, f: Form, uv: [f64; 2], h: f64) -> (u32, f64) {
    match f {
        Free => (fx.lift(MOVING, [uv[0], uv[1], h]), h),
        _ => (fx.p2_over(MOVING, uv), fx.wp2_height_over(uv)),
    }
}

fn plane_distance(fx: &mut Fx, f: Form, kind: K) -> Built {
    let (p, h) = off_plane(fx, f, [0.3, -0.4], 2.5);
    assert!(h.abs() > 0.5, "the point is clearly off the plane");
    let c = fx
        .con(kind, f)
        .with_points(p, 0)
        .with_entities([fx.wp, 0, 0, 0]);
    Built::new(c.with_val(h), Break::Val(h + 1.0), Expect::Rows(vec![-1.0]))
}

fn in_plane(fx: &mut Fx, f: Form, kind: K) -> Built {
    // A point of `wp2` on the line where it meets the workplane, or a 3D point on the plane.
    let uv = match f {
        Free => [0.3, -0.4],
        _ => {
            let h0 = fx.wp2_height_over([0.3, 0.0]);
            let slope = fx.wp2_height_over([0.3, 1.0]) - h0;
            [0.3, -h0 / slope]
        }
    };
    let p = match f {
        Free => fx.lift(MOVING, [uv[0], uv[1], 0.0]),
        _ => fx.p2_over(MOVING, uv),
    };
    let c = fx
        .con(kind, f)
        .with_points(p, 0)
        .with_entities([fx.wp, 0, 0, 0]);
    // Moving the point 0.4 along u of the workplane (keeping the 3D point's height) changes
    // its height only for the point of the tilted `wp2`.
    let (brk, want) = match f {
        Free => (fx.shift(Mixed, p, [0.0, 0.0, 0.75]), 0.75),
        _ => (
            fx.shift(Mixed, p, [0.4, 0.0, 0.0]),
            fx.wp2_height_over([uv[0] + 0.4, uv[1]]),
        ),
    };
    Built::new(c, Break::Set(brk), Expect::Rows(vec![want]))
}

/// The point of the workplane's (u, v) at `u` that lies on `wp2`, and the unit direction of
/// `wp2`'s normal projected into the workplane, with that projection's length.
fn on_wp2(fx: &Fx, u: f64) -> ([f64; 2], [f64; 2], f64) {
    let [o, uu, vv, _] = fx.frame(fx.wp);
    let [o2, _, _, n2] = fx.frame(fx.wp2);
    let v = -(o.minus(o2).dot(n2) + u * uu.dot(n2)) / vv.dot(n2);
    let p = [uu.dot(n2), vv.dot(n2)];
    let len = p[0].hypot(p[1]);
    ([u, v], [p[0] / len, p[1] / len], len)
}

fn symmetric(fx: &mut Fx, f: Form) -> Built {
    if f == Free {
        let [o2, _, _, n2] = fx.frame(fx.wp2);
        let pa = v3([1.0, 2.0, 0.5]);
        let pb = pa.minus(n2.scale(2.0 * pa.minus(o2).dot(n2)));
        let a = fx.p3(FIXED, arr(pa));
        let b = fx.p3(MOVING, arr(pb));
        let c = fx
            .con(K::Symmetric, f)
            .with_points(a, b)
            .with_entities([fx.wp2, 0, 0, 0]);
        let brk = fx.place(Free, b, arr(pb.plus(n2.scale(0.4))));
        return Built::new(c, Break::Set(brk), Expect::Rows(vec![0.2, 0.0, 0.0]));
    }
    // Projected: the projections of the points mirror each other in the plane's trace on the
    // workplane; in the mixed form the points sit at different heights over it.
    let (m, d, len) = on_wp2(fx, 0.5);
    let a = fx.pt(FIXED, f, [m[0] - 1.5 * d[0], m[1] - 1.5 * d[1], 0.8]);
    let b = fx.pt(MOVING, f, [m[0] + 1.5 * d[0], m[1] + 1.5 * d[1], -1.3]);
    let c = fx
        .con(K::Symmetric, f)
        .with_points(a, b)
        .with_entities([fx.wp2, 0, 0, 0]);
    let brk = fx.shift(f, b, [0.4 * d[0], 0.4 * d[1], 0.0]);
    Built::new(c, Break::Set(brk), Expect::Rows(vec![0.2 * len, 0.0]))
}

/// The mirror image of `p` in the line through `a` and `b` (2D).
pub(super) fn reflect(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    let d = [b[0] - a[0], b[1] - a[1]];
    let t = ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1]);
    let foot = [a[0] + t * d[0], a[1] + t * d[1]];
    [2.0 * foot[0] - p[0], 2.0 * foot[1] - p[1]]
}

fn horizontal_vertical(fx: &mut Fx, f: Form, kind: K, with_line: bool) -> Built {
    let horizontal = kind == K::Horizontal;
    let (pa, pb) = if horizontal {
        ([0.0, 1.0, 0.5], [3.0, 1.0, -0.5])
    } else {
        ([1.0, 0.0, 0.5], [1.0, 3.0, -0.5])
    };
    let a = fx.pt(FIXED, f, pa);
    let b = fx.pt(MOVING, f, pb);
    let c = fx.con(kind, f);
    let c = if with_line {
        let l = fx.line_of(MOVING, f, a, b);
        c.with_entities([l, 0, 0, 0])
    } else {
        c.with_points(a, b)
    };
    let brk = fx.shift(f, b, [0.5, 0.5, 0.0]);
    Built::new(c, Break::Set(brk), Expect::Rows(vec![-0.5]))
}

const PLANAR: &[Form] = &[Plane, Mixed];
const ALL: &[Form] = &[Plane, Free, Mixed];

pub(super) fn cases() -> Vec<Case> {
    vec![
        Case {
            name: "points_coincident",
            kind: Some(K::PointsCoincident),
            forms: ALL,
            build: |fx, f| {
                let a = fx.pt(FIXED, f, [1.0, 2.0, 0.5]);
                let b = fx.pt(MOVING, f, [1.0, 2.0, if f == Free { 0.5 } else { -0.7 }]);
                let c = fx.con(K::PointsCoincident, f).with_points(a, b);
                let brk = fx.shift(f, b, [0.5, -1.5, 0.25]);
                Built::new(c, Break::Set(brk), rows(f, [-0.5, 1.5, -0.25]))
            },
        },
        Case {
            name: "pt_pt_distance",
            kind: Some(K::PtPtDistance),
            forms: ALL,
            build: |fx, f| {
                let a = fx.pt(FIXED, f, [0.5, -1.0, 2.0]);
                let b = fx.pt(MOVING, f, [3.5, 3.0, 14.0]);
                let d = if f == Free { 13.0 } else { 5.0 };
                let c = fx.con(K::PtPtDistance, f).with_points(a, b).with_val(d);
                Built::new(c, Break::Val(d - 2.0), Expect::Rows(vec![2.0]))
            },
        },
        Case {
            name: "pt_plane_distance",
            kind: Some(K::PtPlaneDistance),
            forms: &[Free, Plane],
            build: |fx, f| plane_distance(fx, f, K::PtPlaneDistance),
        },
        Case {
            name: "pt_face_distance",
            kind: Some(K::PtFaceDistance),
            forms: &[Free, Plane],
            build: |fx, f| plane_distance(fx, f, K::PtFaceDistance),
        },
        Case {
            name: "pt_in_plane",
            kind: Some(K::PtInPlane),
            forms: &[Free, Plane],
            build: |fx, f| in_plane(fx, f, K::PtInPlane),
        },
        Case {
            name: "pt_on_face",
            kind: Some(K::PtOnFace),
            forms: &[Free, Plane],
            build: |fx, f| in_plane(fx, f, K::PtOnFace),
        },
        Case {
            name: "where_dragged",
            kind: Some(K::WhereDragged),
            forms: ALL,
            build: |fx, f| {
                let p = fx.pt(MOVING, f, [1.0, 2.0, 3.0]);
                let q = fx.pt(MOVING, f, [4.0, 6.0, 3.0]);
                // Something else to solve, so that the kept point is tested under load.
                let d = fx.con(K::PtPtDistance, f).with_points(p, q).with_val(5.0);
                fx.sys.add_constraint(d).expect("fresh constraint");
                let c = fx.con(K::WhereDragged, f).with_points(p, 0);
                let brk = fx.shift(f, p, [0.5, -0.25, 0.1]);
                Built::new(c, Break::Set(brk), rows(f, [0.5, -0.25, 0.1]))
            },
        },
        Case {
            name: "proj_pt_distance",
            kind: Some(K::ProjPtDistance),
            forms: ALL,
            build: |fx, f| {
                let (a, b, dir, val) = if f == Free {
                    // 3 along (2, 1, 2) / 3 plus an offset perpendicular to it; the line runs
                    // the other way (a line's direction is start minus end), so -3.
                    let a = fx.p3(FIXED, [0.5, 0.0, 1.0]);
                    let b = fx.p3(MOVING, [3.5, -1.0, 3.0]);
                    let l = fx.line(FIXED, Free, [1.0, 1.0, 1.0], [3.0, 2.0, 3.0]);
                    (a, b, l, -3.0)
                } else {
                    // Along the normal of `wp2` (a 3D normal, or the 2D normal copying it).
                    // In the mixed form B is the 3D point: a point of `wp2` could not move
                    // along `wp2`'s normal.
                    let b = fx.pt(MOVING, f, [2.0, 1.0, 2.5]);
                    let a = fx.pt(FIXED, f, [0.0, 0.0, 0.4]);
                    let dir = match f {
                        Plane => fx.normal_of(fx.wp2),
                        _ => fx.normal2(fx.wp2),
                    };
                    let n2 = fx.frame(fx.wp2)[3];
                    let val = v3(fx.world(b)).minus(v3(fx.world(a))).dot(n2);
                    assert!(val.abs() > 0.5, "{f:?}: {val}");
                    (a, b, dir, val)
                };
                let c = fx.con(K::ProjPtDistance, f).with_points(a, b);
                let c = c.with_entities([dir, 0, 0, 0]).with_val(val);
                Built::new(c, Break::Val(val - 1.0), Expect::Rows(vec![1.0]))
            },
        },
        Case {
            name: "symmetric",
            kind: Some(K::Symmetric),
            forms: ALL,
            build: symmetric,
        },
        Case {
            name: "symmetric_horiz",
            kind: Some(K::SymmetricHoriz),
            forms: PLANAR,
            build: |fx, f| {
                let a = fx.pt(FIXED, f, [-2.0, 1.5, 0.3]);
                let b = fx.pt(MOVING, f, [2.0, 1.5, -0.4]);
                let c = fx.con(K::SymmetricHoriz, f).with_points(a, b);
                let brk = fx.shift(f, b, [0.5, 0.25, 0.0]);
                Built::new(c, Break::Set(brk), Expect::Rows(vec![-0.25, 0.5]))
            },
        },
        Case {
            name: "symmetric_vert",
            kind: Some(K::SymmetricVert),
            forms: PLANAR,
            build: |fx, f| {
                let a = fx.pt(FIXED, f, [1.5, -2.0, 0.3]);
                let b = fx.pt(MOVING, f, [1.5, 2.0, -0.4]);
                let c = fx.con(K::SymmetricVert, f).with_points(a, b);
                let brk = fx.shift(f, b, [0.5, 0.25, 0.0]);
                Built::new(c, Break::Set(brk), Expect::Rows(vec![-0.5, 0.25]))
            },
        },
        Case {
            name: "symmetric_line",
            kind: Some(K::SymmetricLine),
            forms: PLANAR,
            build: |fx, f| {
                let l = fx.line(FIXED, f, [1.0, 1.0, 0.2], [3.0, 2.0, -0.3]);
                let pb = reflect([1.0, 3.0], [1.0, 1.0], [3.0, 2.0]);
                let a = fx.pt(FIXED, f, [1.0, 3.0, 0.6]);
                let b = fx.pt(MOVING, f, [pb[0], pb[1], 1.1]);
                let c = fx.con(K::SymmetricLine, f).with_points(a, b);
                // Half a unit along the line: the midpoint stays on it, the segment tilts.
                let s = 0.5 / 5f64.sqrt();
                let brk = fx.shift(f, b, [2.0 * s, s, 0.0]);
                let c = c.with_entities([l, 0, 0, 0]);
                Built::new(c, Break::Set(brk), Expect::Rows(vec![0.0, 0.5]))
            },
        },
        Case {
            name: "at_midpoint",
            kind: Some(K::AtMidpoint),
            forms: ALL,
            build: |fx, f| {
                let l = fx.line(FIXED, f, [0.0, 0.0, 1.0], [4.0, 2.0, -1.0]);
                let p = fx.pt(MOVING, f, [2.0, 1.0, 0.0]);
                let c = fx
                    .con(K::AtMidpoint, f)
                    .with_points(p, 0)
                    .with_entities([l, 0, 0, 0]);
                let brk = fx.shift(f, p, [0.3, -0.2, 0.1]);
                Built::new(c, Break::Set(brk), rows(f, [0.3, -0.2, 0.1]))
            },
        },
        Case {
            name: "horizontal (line)",
            kind: Some(K::Horizontal),
            forms: PLANAR,
            build: |fx, f| horizontal_vertical(fx, f, K::Horizontal, true),
        },
        Case {
            name: "horizontal (points)",
            kind: Some(K::Horizontal),
            forms: PLANAR,
            build: |fx, f| horizontal_vertical(fx, f, K::Horizontal, false),
        },
        Case {
            name: "vertical (line)",
            kind: Some(K::Vertical),
            forms: PLANAR,
            build: |fx, f| horizontal_vertical(fx, f, K::Vertical, true),
        },
        Case {
            name: "vertical (points)",
            kind: Some(K::Vertical),
            forms: PLANAR,
            build: |fx, f| horizontal_vertical(fx, f, K::Vertical, false),
        },
    ]
}

#[test]
fn point_family_residuals_derivatives_and_solves() {
    super::check_family(&cases());
}

#[test]
fn pt_plane_distance_is_signed_along_the_normal() {
    let mut fx = Fx::new();
    let below = fx.lift(MOVING, [0.3, -0.4, -2.0]);
    for (val, want) in [(-2.0, 0.0), (2.0, -4.0)] {
        let c = fx.con(K::PtPlaneDistance, Free).with_points(below, 0);
        let one = compile(&fx.sys, &c.with_entities([fx.wp, 0, 0, 0]).with_val(val));
        let r = one.residuals(&one.x(&fx.sys));
        assert!((r[0] - want).abs() < 1e-12, "val {val}: {r:?}");
    }
}

#[test]
fn proj_pt_distance_is_signed_from_a_to_b_along_start_minus_end() {
    // b - a = (3, -1, 2); the line from (1, 1, 1) to (3, 2, 3) points along -(2, 1, 2) / 3,
    // as SolveSpace's line vectors do; reversing the line or the points flips the sign.
    let mut fx = Fx::new();
    let a = fx.p3(FIXED, [0.5, 0.0, 1.0]);
    let b = fx.p3(MOVING, [3.5, -1.0, 3.0]);
    let l = fx.line(FIXED, Free, [1.0, 1.0, 1.0], [3.0, 2.0, 3.0]);
    let back = fx.line(FIXED, Free, [3.0, 2.0, 3.0], [1.0, 1.0, 1.0]);
    for (pa, pb, l, val) in [(a, b, l, -3.0), (b, a, l, 3.0), (a, b, back, 3.0)] {
        let c = fx.con(K::ProjPtDistance, Free).with_points(pa, pb);
        let one = compile(&fx.sys, &c.with_entities([l, 0, 0, 0]).with_val(val));
        let r = one.residuals(&one.x(&fx.sys));
        assert!(r[0].abs() < 1e-12, "a->b {val}: {r:?}");
    }
}

#[test]
fn symmetric_in_space_keeps_the_informative_cross_components() {
    // The two rows of (b - a) x n skip n's dominant axis, whichever it is, so that they stay
    // independent at the solution.
    for axis in 0..3 {
        let mut fx = Fx::new();
        let mut normal = [0.05, -0.1, 0.08];
        normal[axis] = 1.0;
        // A plane through the origin with that normal: rotate z onto it.
        let z = [0.0, 0.0, 1.0];
        let n = v3(normal).scale(1.0 / v3(normal).norm());
        let axis_v = v3(z).cross(n);
        let angle = n.z.acos();
        let q = if axis_v.norm() < 1e-12 {
            [1.0, 0.0, 0.0, 0.0]
        } else {
            axis_angle(arr(axis_v), angle)
        };
        let plane = fx.workplane(FIXED, [0.0, 0.0, 0.0], q);
        let n = fx.frame(plane)[3];
        // A point of the plane (through the origin), and 1.5 above it.
        let base = v3([0.3, -0.2, 0.5]);
        let pa = base.minus(n.scale(base.dot(n))).plus(n.scale(1.5));
        let a = fx.p3(FIXED, arr(pa));
        let b = fx.p3(MOVING, arr(pa.minus(n.scale(3.0))));
        let c = fx.con(K::Symmetric, Free).with_points(a, b);
        let one = compile(&fx.sys, &c.with_entities([plane, 0, 0, 0]));
        let x = one.x(&fx.sys);
        let (res, jac) = one.jacobian(&x);
        assert!(res.iter().all(|r| r.abs() < 1e-12), "{res:?}");
        assert_eq!(rank(&jac, x.len(), &one.cols(&fx.sys, b)), 3, "axis {axis}");
    }
}

#[test]
fn constraints_free_in_space_read_points_of_workplanes_in_space() {
    // A point of the workplane and a point of `wp2`, used by constraints free in 3D: the
    // residuals are those of their positions in space.
    let mut fx = Fx::new();
    let a = fx.p2(FIXED, fx.wp, [0.5, -1.0]);
    let b = fx.p2(MOVING, fx.wp2, [2.0, 1.5]);
    let (pa, pb) = (v3(fx.world(a)), v3(fx.world(b)));
    let d = pb.minus(pa);
    let dist = fx
        .con(K::PtPtDistance, Free)
        .with_points(a, b)
        .with_val(1.0);
    let one = compile(&fx.sys, &dist);
    let r = one.residuals(&one.x(&fx.sys));
    assert!((r[0] - (d.norm() - 1.0)).abs() < 1e-12, "{r:?}");
    let same = fx.con(K::PointsCoincident, Free).with_points(a, b);
    let one = compile(&fx.sys, &same);
    let r = one.residuals(&one.x(&fx.sys));
    let want = [-d.x, -d.y, -d.z];
    assert!(
        r.iter().zip(want).all(|(r, w)| (r - w).abs() < 1e-12),
        "{r:?} vs {want:?}"
    );
    // The point of `wp2` can reach a point in space only where that is on `wp2`: put one
    // there and solve the coincidence.
    let [o2, u2, v2, _] = fx.frame(fx.wp2);
    let target = fx.p3(FIXED, arr(o2.plus(u2.scale(1.6)).plus(v2.scale(1.2))));
    let c = fx.con(K::PointsCoincident, Free).with_points(target, b);
    fx.sys.add_constraint(c).expect("fresh constraint");
    let r = crate::solve::solve(
        &mut fx.sys,
        crate::model::GroupId(MOVING),
        &[],
        &crate::solve::Config::default(),
    )
    .expect("solves");
    assert!(r.outcome.is_ok(), "{r:?}");
    let ps = fx.params(b);
    let got = [fx.value(ps[0]), fx.value(ps[1])];
    assert!(
        (got[0] - 1.6).abs() < 1e-9 && (got[1] - 1.2).abs() < 1e-9,
        "{got:?}"
    );
}
