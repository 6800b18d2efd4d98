//! Lines: distances from points to lines, lengths, angles, parallel and perpendicular.

use super::fixture::{compile, rank, Break, Built, Case, Expect, Form, Fx, FIXED, MOVING};
use crate::model::{ConstraintKind as K, GroupId};
use crate::solve::{solve, Config};
use Form::{Free, Mixed, Plane};

const ALL: &[Form] = &[Plane, Free, Mixed];

/// A reference line (start, end), a point on it and a unit vector perpendicular to it: in the
/// workplane it runs rightwards and the vector points up (left of start->end).
fn off_line(f: Form) -> ([f64; 3], [f64; 3], [f64; 3], [f64; 3]) {
    if f == Free {
        let s = 1.0 / 5f64.sqrt();
        // Along (2, 1, 1.5): no two components tie, so the rows kept in space (those off
        // the dominant axis) stay the same at every point the derivative test samples.
        (
            [1.0, 1.0, 1.0],
            [3.0, 2.0, 2.5],
            [2.0, 1.5, 1.75],
            [s, -2.0 * s, 0.0],
        )
    } else {
        (
            [-1.0, 0.5, 0.3],
            [3.0, 0.5, -0.2],
            [1.0, 0.5, 0.6],
            [0.0, 1.0, 0.0],
        )
    }
}

fn along(p: [f64; 3], d: [f64; 3], k: f64) -> [f64; 3] {
    [p[0] + k * d[0], p[1] + k * d[1], p[2] + k * d[2]]
}

/// Lines A (fixed, length `la`) and B (its end moving, length `lb_over_la * la`), and B's end
/// point with B's unit direction.
fn two_lines(fx: &mut Fx, f: Form, lb_over_la: f64) -> (u32, u32, u32, f64, [f64; 3]) {
    let (a0, a1, b0, dir, la) = if f == Free {
        let d = [6.0 / 7.0, 2.0 / 7.0, 3.0 / 7.0];
        ([0.0, 0.0, 0.0], [2.0, 3.0, 6.0], [1.0, -1.0, 2.0], d, 7.0)
    } else {
        (
            [0.0, 0.0, 0.2],
            [3.0, 4.0, -0.5],
            [1.0, -1.0, 0.3],
            [1.0, 0.0, 0.0],
            5.0,
        )
    };
    let a = fx.line(FIXED, f, a0, a1);
    let (p0, p1) = (
        fx.pt(FIXED, f, b0),
        fx.pt(MOVING, f, along(b0, dir, lb_over_la * la)),
    );
    let b = fx.line_of(MOVING, f, p0, p1);
    (a, b, p1, la, dir)
}

fn length_relation(fx: &mut Fx, f: Form, kind: K) -> Built {
    let lb_over_la = match kind {
        K::EqualLengthLines => 1.0,
        K::LengthRatio => 0.5,
        _ => (if f == Free { 5.0 } else { 3.0 }) / (if f == Free { 7.0 } else { 5.0 }),
    };
    let (a, b, end, la, dir) = two_lines(fx, f, lb_over_la);
    let c = fx.con(kind, f).with_entities([a, b, 0, 0]);
    match kind {
        K::EqualLengthLines => {
            let brk = fx.shift(f, end, dir);
            Built::new(c, Break::Set(brk), Expect::Rows(vec![-1.0]))
        }
        K::LengthRatio => Built::new(
            c.with_val(2.0),
            Break::Val(3.0),
            Expect::Rows(vec![-la / 2.0]),
        ),
        _ => Built::new(c.with_val(2.0), Break::Val(1.0), Expect::Rows(vec![1.0])),
    }
}

/// A line from `o` at `deg` degrees in the workplane, two units long.
fn ray(fx: &mut Fx, g: u32, f: Form, o: [f64; 2], deg: f64) -> u32 {
    let t = deg.to_radians();
    fx.line(
        g,
        f,
        [o[0], o[1], 0.3],
        [o[0] + 2.0 * t.cos(), o[1] + 2.0 * t.sin(), -0.4],
    )
}

/// Values that turn ray `l` (from `o`) to `deg` degrees.
fn turn(fx: &Fx, f: Form, l: u32, o: [f64; 2], deg: f64) -> Vec<(u32, f64)> {
    let t = deg.to_radians();
    let end = [o[0] + 2.0 * t.cos(), o[1] + 2.0 * t.sin(), -0.4];
    fx.place(f, fx.point_of(l, 1), end)
}

/// A 3D direction at `deg` degrees from x, in the plane of x and `(0, 0.6, 0.8)`.
fn dir3(deg: f64) -> [f64; 3] {
    let t = deg.to_radians();
    [2.0 * t.cos(), 1.2 * t.sin(), 1.6 * t.sin()]
}

/// A 3D direction at `deg` degrees from y, in the plane of y and z.
fn dir3_y(deg: f64) -> [f64; 3] {
    let t = deg.to_radians();
    [0.0, 2.0 * t.cos(), 2.0 * t.sin()]
}

fn ray3(fx: &mut Fx, g: u32, o: [f64; 3], d: [f64; 3]) -> u32 {
    fx.line(g, Free, o, along(o, d, 1.0))
}

fn cos_deg(d: f64) -> f64 {
    d.to_radians().cos()
}

/// Equal angles: in the workplane from signed angles `deg` of lines A..D (D moves, and is
/// broken by turning it to `d_to`, giving `want` radians); in space angle(A, B) = 40 degrees
/// and angle(C, D) = `free_deg` degrees, D broken to `free_to`.
fn equal_angle(fx: &mut Fx, f: Form, deg: [f64; 4], other: bool, to: (f64, f64)) -> Built {
    let c = fx.con(K::EqualAngle, f).with_flags(other, false);
    if f == Free {
        let free_deg = if other { 140.0 } else { 40.0 };
        let a = ray3(fx, FIXED, [0.0, 0.0, 0.0], dir3(0.0));
        let b = ray3(fx, FIXED, [1.0, 0.0, 0.5], dir3(40.0));
        let cl = ray3(fx, FIXED, [0.0, 2.0, 0.0], dir3_y(0.0));
        let d = ray3(fx, MOVING, [1.0, 2.0, 0.5], dir3_y(free_deg));
        let free_to = free_deg + 10.0;
        let brk = fx.place(
            f,
            fx.point_of(d, 1),
            along([1.0, 2.0, 0.5], dir3_y(free_to), 1.0),
        );
        let want = cos_deg(40.0)
            + if other {
                cos_deg(free_to)
            } else {
                -cos_deg(free_to)
            };
        let c = c.with_entities([a, b, cl, d]);
        return Built::new(c, Break::Set(brk), Expect::Rows(vec![want]));
    }
    let o = [[0.0, 0.0], [0.5, 3.0], [4.0, 0.0], [4.5, 3.0]];
    let a = ray(fx, FIXED, f, o[0], deg[0]);
    let b = ray(fx, FIXED, f, o[1], deg[1]);
    let cl = ray(fx, FIXED, f, o[2], deg[2]);
    let d = ray(fx, MOVING, f, o[3], deg[3]);
    let brk = turn(fx, f, d, o[3], to.0);
    let c = c.with_entities([a, b, cl, d]);
    Built::new(c, Break::Set(brk), Expect::Rows(vec![to.1.to_radians()]))
}

fn angle(fx: &mut Fx, f: Form, other: bool) -> Built {
    // 30 degrees, or 150 degrees as the supplement of 30.
    let between = if other { 150.0 } else { 30.0 };
    let c = fx.con(K::Angle, f).with_val(30.0).with_flags(other, false);
    let (a, b) = if f == Free {
        let a = ray3(fx, FIXED, [0.0, 0.0, 0.0], dir3(0.0));
        (a, ray3(fx, MOVING, [1.0, 1.0, 1.0], dir3(between)))
    } else {
        let a = ray(fx, FIXED, f, [0.0, 0.0], 10.0);
        (a, ray(fx, MOVING, f, [1.0, 2.0], 10.0 + between))
    };
    let c = c.with_entities([a, b, 0, 0]);
    match (f, other) {
        // In space the residual is the difference of cosines; in a workplane, of angles.
        (Free, false) => Built::new(
            c,
            Break::Val(40.0),
            Expect::Rows(vec![cos_deg(30.0) - cos_deg(40.0)]),
        ),
        (Free, true) => Built::new(
            c,
            Break::Flags(false, false),
            Expect::Rows(vec![cos_deg(150.0) - cos_deg(30.0)]),
        ),
        (_, false) => Built::new(
            c,
            Break::Val(40.0),
            Expect::Rows(vec![(-10f64).to_radians()]),
        ),
        (_, true) => Built::new(
            c,
            Break::Flags(false, false),
            Expect::Rows(vec![120f64.to_radians()]),
        ),
    }
}

/// A signed angle of -30 degrees (clockwise from A to B), or with `other` of 30 measured
/// against B reversed (-150 from A to B); a value of 40 breaks either.
fn signed_angle(fx: &mut Fx, f: Form, other: bool) -> Built {
    let (val, between) = if other {
        (30.0, -150.0)
    } else {
        (-30.0, -30.0)
    };
    let c = fx
        .con(K::Angle, f)
        .with_val(val)
        .with_flags(other, false)
        .as_signed();
    let a = ray(fx, FIXED, f, [0.0, 0.0], 10.0);
    let b = ray(fx, MOVING, f, [1.0, 2.0], 10.0 + between);
    let c = c.with_entities([a, b, 0, 0]);
    // Targets 40 and 220 (-140) degrees: off by -70 and -10.
    let off: f64 = if other { -10.0 } else { -70.0 };
    Built::new(c, Break::Val(40.0), Expect::Rows(vec![off.to_radians()]))
}

pub(super) fn cases() -> Vec<Case> {
    vec![
        Case {
            name: "pt_line_distance",
            kind: Some(K::PtLineDistance),
            forms: ALL,
            build: |fx, f| {
                let (l0, l1, base, up) = off_line(f);
                let l = fx.line(FIXED, f, l0, l1);
                // In the workplane the distance is signed, positive below a rightward line.
                let (k, val) = if f == Free { (2.5, 2.5) } else { (-2.0, 2.0) };
                let p = fx.pt(MOVING, f, along(base, up, k));
                let c = fx.con(K::PtLineDistance, f).with_points(p, 0);
                let c = c.with_entities([l, 0, 0, 0]).with_val(val);
                Built::new(c, Break::Val(val - 1.0), Expect::Rows(vec![1.0]))
            },
        },
        Case {
            name: "pt_on_line",
            kind: Some(K::PtOnLine),
            forms: ALL,
            build: |fx, f| {
                let (l, p) = if f == Free {
                    // Along (2, 1, 1.5): no tie between components, so the same two rows
                    // are kept at every point the derivative test samples.
                    let l = fx.line(FIXED, f, [1.0, 1.0, 1.0], [3.0, 2.0, 2.5]);
                    (l, fx.pt(MOVING, f, [2.0, 1.5, 1.75]))
                } else {
                    let l = fx.line(FIXED, f, [0.0, 0.0, 0.4], [4.0, 2.0, -0.3]);
                    (l, fx.pt(MOVING, f, [2.0, 1.0, 1.1]))
                };
                let c = fx
                    .con(K::PtOnLine, f)
                    .with_points(p, 0)
                    .with_entities([l, 0, 0, 0]);
                // Off the line by (0, 0, 0.6) in space: (d x w) / |d| = (0.6, -1.2, 0) / |d|,
                // whose x (the line's dominant axis) is dropped; by (0, 1) in the plane:
                // 4 / sqrt(20).
                let (brk, want) = if f == Free {
                    (
                        fx.shift(f, p, [0.0, 0.0, 0.6]),
                        vec![-1.2 / 7.25f64.sqrt(), 0.0],
                    )
                } else {
                    (fx.shift(f, p, [0.0, 1.0, 0.0]), vec![4.0 / 20f64.sqrt()])
                };
                Built::new(c, Break::Set(brk), Expect::Rows(want))
            },
        },
        Case {
            name: "equal_length_lines",
            kind: Some(K::EqualLengthLines),
            forms: ALL,
            build: |fx, f| length_relation(fx, f, K::EqualLengthLines),
        },
        Case {
            name: "length_ratio",
            kind: Some(K::LengthRatio),
            forms: ALL,
            build: |fx, f| length_relation(fx, f, K::LengthRatio),
        },
        Case {
            name: "length_difference",
            kind: Some(K::LengthDifference),
            forms: ALL,
            build: |fx, f| length_relation(fx, f, K::LengthDifference),
        },
        Case {
            name: "eq_len_pt_line_d",
            kind: Some(K::EqLenPtLineD),
            forms: ALL,
            build: |fx, f| {
                let a = if f == Free {
                    fx.line(FIXED, f, [0.0, 0.0, 3.0], [2.0, 0.0, 3.0])
                } else {
                    fx.line(FIXED, f, [0.0, 3.0, 0.1], [2.0, 3.0, -0.1])
                };
                let (l0, l1, base, up) = off_line(f);
                let b = fx.line(FIXED, f, l0, l1);
                let p = fx.pt(MOVING, f, along(base, up, 2.0));
                let c = fx.con(K::EqLenPtLineD, f).with_points(p, 0);
                let brk = fx.shift(f, p, along([0.0; 3], up, 0.5));
                let c = c.with_entities([a, b, 0, 0]);
                Built::new(c, Break::Set(brk), Expect::Rows(vec![-0.5]))
            },
        },
        Case {
            name: "eq_pt_ln_distances",
            kind: Some(K::EqPtLnDistances),
            forms: ALL,
            build: |fx, f| {
                let (l0, l1, base, up) = off_line(f);
                let s = [0.5, -4.0, if f == Free { 1.0 } else { 0.2 }];
                let shifted = |p: [f64; 3]| along(p, s, 1.0);
                let la = fx.line(FIXED, f, l0, l1);
                let lb = fx.line(FIXED, f, shifted(l0), shifted(l1));
                // Equal distances on opposite sides: the distances are unsigned.
                let pa = fx.pt(FIXED, f, along(base, up, 1.5));
                let pb = fx.pt(MOVING, f, along(shifted(base), up, -1.5));
                let c = fx.con(K::EqPtLnDistances, f).with_points(pa, pb);
                let brk = fx.shift(f, pb, along([0.0; 3], up, -0.5));
                let c = c.with_entities([la, lb, 0, 0]);
                Built::new(c, Break::Set(brk), Expect::Rows(vec![-0.5]))
            },
        },
        Case {
            name: "equal_angle",
            kind: Some(K::EqualAngle),
            forms: ALL,
            build: |fx, f| equal_angle(fx, f, [10.0, 50.0, 100.0, 140.0], false, (150.0, -10.0)),
        },
        Case {
            name: "equal_angle (opposite sign)",
            kind: Some(K::EqualAngle),
            forms: &[Plane, Mixed],
            build: |fx, f| equal_angle(fx, f, [10.0, 50.0, 140.0, 100.0], false, (90.0, -10.0)),
        },
        Case {
            name: "equal_angle (supplementary)",
            kind: Some(K::EqualAngle),
            forms: ALL,
            build: |fx, f| equal_angle(fx, f, [10.0, 50.0, 100.0, 240.0], true, (250.0, 10.0)),
        },
        Case {
            name: "angle",
            kind: Some(K::Angle),
            forms: ALL,
            build: |fx, f| angle(fx, f, false),
        },
        Case {
            name: "angle (supplementary)",
            kind: Some(K::Angle),
            forms: ALL,
            build: |fx, f| angle(fx, f, true),
        },
        Case {
            name: "angle (signed)",
            kind: Some(K::Angle),
            forms: &[Plane, Mixed],
            build: |fx, f| signed_angle(fx, f, false),
        },
        Case {
            name: "angle (signed, supplementary)",
            kind: Some(K::Angle),
            forms: &[Plane, Mixed],
            build: |fx, f| signed_angle(fx, f, true),
        },
        Case {
            name: "parallel",
            kind: Some(K::Parallel),
            forms: ALL,
            build: |fx, f| {
                let (a, b, end) = if f == Free {
                    // Along (2, 1, 1.5), so that no two components tie (see pt_on_line).
                    let a = fx.line(FIXED, f, [0.0, 0.0, 0.0], [2.0, 1.0, 1.5]);
                    let b = fx.line(MOVING, f, [1.0, 0.0, 1.0], [5.0, 2.0, 4.0]);
                    (a, b, [0.0, 0.0, 1.0])
                } else {
                    let a = fx.line(FIXED, f, [0.0, 0.0, 0.3], [2.0, 1.0, -0.2]);
                    let b = fx.line(MOVING, f, [1.0, -1.0, 0.5], [5.0, 1.0, 0.1]);
                    (a, b, [0.0, 1.0, 0.0])
                };
                let brk = fx.shift(f, fx.point_of(b, 1), end);
                // (2,1,1.5) x (4,2,4) = (1,-2,0), over 6 sqrt(7.25), x dropped;
                // (2,1) x (4,3) = 2.
                let want = if f == Free {
                    vec![-2.0 / (6.0 * 7.25f64.sqrt()), 0.0]
                } else {
                    vec![2.0 / (5.0 * 5f64.sqrt())]
                };
                let c = fx.con(K::Parallel, f).with_entities([a, b, 0, 0]);
                Built::new(c, Break::Set(brk), Expect::Rows(want))
            },
        },
        Case {
            name: "perpendicular",
            kind: Some(K::Perpendicular),
            forms: ALL,
            build: |fx, f| {
                let (a, b, end, want) = if f == Free {
                    let a = fx.line(FIXED, f, [0.0, 0.0, 0.0], [2.0, 1.0, 2.0]);
                    let b = fx.line(MOVING, f, [1.0, 0.0, 1.0], [2.0, -2.0, 1.0]);
                    (a, b, [0.0, 0.0, 1.0], 2.0 / (3.0 * 6f64.sqrt()))
                } else {
                    let a = fx.line(FIXED, f, [0.0, 0.0, 0.3], [2.0, 1.0, -0.2]);
                    let b = fx.line(MOVING, f, [1.0, -1.0, 0.5], [0.0, 1.0, 0.1]);
                    (a, b, [1.0, 0.0, 0.0], 1.0 / 5f64.sqrt())
                };
                let brk = fx.shift(f, fx.point_of(b, 1), end);
                let c = fx.con(K::Perpendicular, f).with_entities([a, b, 0, 0]);
                Built::new(c, Break::Set(brk), Expect::Rows(vec![want]))
            },
        },
    ]
}

#[test]
fn line_family_residuals_derivatives_and_solves() {
    super::check_family(&cases());
}

/// Solves group 2 and asserts success.
fn solve_ok(fx: &mut Fx) {
    let r = solve(&mut fx.sys, GroupId(MOVING), &[], &Config::default()).expect("solves");
    assert!(r.outcome.is_ok(), "{r:?}");
}

/// The signed angle in degrees of line `l` in the workplane.
fn heading(fx: &Fx, l: u32) -> f64 {
    let (a, b) = (
        fx.coords(Plane, fx.point_of(l, 0)),
        fx.coords(Plane, fx.point_of(l, 1)),
    );
    (b[1] - a[1]).atan2(b[0] - a[0]).to_degrees()
}

#[test]
fn pt_line_distance_in_a_workplane_is_positive_right_of_the_line() {
    // SolveSpace's own fixture (test/constraint/pt_line_distance/normal.slvs): a rightward line
    // from (-15, 5) to (-5, 5) and the point (-10, 10) above it, at distance -5.
    let mut fx = Fx::new();
    let l = fx.line(FIXED, Plane, [-15.0, 5.0, 0.0], [-5.0, 5.0, 0.0]);
    let p = fx.pt(MOVING, Plane, [-10.0, 10.0, 0.0]);
    for (val, want) in [(-5.0, 0.0), (5.0, -10.0)] {
        let c = fx.con(K::PtLineDistance, Plane).with_points(p, 0);
        let one = compile(&fx.sys, &c.with_entities([l, 0, 0, 0]).with_val(val));
        let r = one.residuals(&one.x(&fx.sys));
        assert!((r[0] - want).abs() < 1e-12, "val {val}: {r:?}");
    }
    // From a start near it, the point stays above the line.
    let c = fx.con(K::PtLineDistance, Plane).with_points(p, 0);
    let c = c.with_entities([l, 0, 0, 0]).with_val(-5.0);
    fx.sys.add_constraint(c).expect("fresh constraint");
    let moved = fx.shift(Plane, p, [0.3, -0.6, 0.0]);
    fx.set(&moved);
    solve_ok(&mut fx);
    let at = fx.coords(Plane, p);
    assert!((at[1] - 10.0).abs() < 1e-9, "{at:?}");
}

#[test]
fn angle_in_a_workplane_keeps_its_sign() {
    // Start at +-35 or +-145 degrees from A, for 30 degrees or its supplement.
    for (start, other, end) in [
        (35.0, false, 30.0),
        (-35.0, false, -30.0),
        (145.0, true, 150.0),
        (-145.0, true, -150.0),
        // Far from the target, but on the same side: still the signed target, not its mirror.
        (170.0, false, 30.0),
        (-100.0, false, -30.0),
    ] {
        let mut fx = Fx::new();
        let a = ray(&mut fx, FIXED, Plane, [0.0, 0.0], 0.0);
        let b = ray(&mut fx, MOVING, Plane, [1.0, 1.0], start);
        let c = fx
            .con(K::Angle, Plane)
            .with_val(30.0)
            .with_flags(other, false);
        fx.sys
            .add_constraint(c.with_entities([a, b, 0, 0]))
            .expect("fresh");
        solve_ok(&mut fx);
        let got = heading(&fx, b);
        assert!((got - end).abs() < 1e-7, "from {start}: {got}, want {end}");
    }
}

#[test]
fn equal_angle_in_a_workplane_picks_equal_or_opposite_from_the_start() {
    // angle(A, B) = 40 degrees; D starts near +45 or -45 degrees from C (or near the
    // supplement 135 with `other`), and ends at exactly +40, -40 (or 140).
    for (start, other, end) in [
        (45.0, false, 40.0),
        (-45.0, false, -40.0),
        (135.0, true, 140.0),
        (-135.0, true, -140.0),
    ] {
        let mut fx = Fx::new();
        let a = ray(&mut fx, FIXED, Plane, [0.0, 0.0], 10.0);
        let b = ray(&mut fx, FIXED, Plane, [0.5, 3.0], 50.0);
        let cl = ray(&mut fx, FIXED, Plane, [4.0, 0.0], 100.0);
        let d = ray(&mut fx, MOVING, Plane, [4.5, 3.0], 100.0 + start);
        let c = fx.con(K::EqualAngle, Plane).with_flags(other, false);
        fx.sys
            .add_constraint(c.with_entities([a, b, cl, d]))
            .expect("fresh");
        solve_ok(&mut fx);
        let got = (heading(&fx, d) - 100.0 + 540.0) % 360.0 - 180.0;
        assert!((got - end).abs() < 1e-7, "from {start}: {got}, want {end}");
    }
}

#[test]
fn equal_angle_tells_equal_from_supplementary() {
    // angle(A, B) = 30 degrees and angle(C, D) = 150 degrees: supplementary, not equal.
    for f in [Plane, Free] {
        let mut fx = Fx::new();
        let (a, b, cl, d) = if f == Free {
            (
                ray3(&mut fx, FIXED, [0.0, 0.0, 0.0], dir3(0.0)),
                ray3(&mut fx, FIXED, [1.0, 0.0, 0.5], dir3(30.0)),
                ray3(&mut fx, FIXED, [0.0, 2.0, 0.0], dir3_y(0.0)),
                ray3(&mut fx, MOVING, [1.0, 2.0, 0.5], dir3_y(150.0)),
            )
        } else {
            (
                ray(&mut fx, FIXED, f, [0.0, 0.0], 0.0),
                ray(&mut fx, FIXED, f, [0.5, 3.0], 30.0),
                ray(&mut fx, FIXED, f, [4.0, 0.0], 0.0),
                ray(&mut fx, MOVING, f, [4.5, 3.0], 150.0),
            )
        };
        for other in [false, true] {
            let c = fx.con(K::EqualAngle, f).with_flags(other, false);
            let one = compile(&fx.sys, &c.with_entities([a, b, cl, d]));
            let r = one.residuals(&one.x(&fx.sys))[0];
            if other {
                assert!(r.abs() < 1e-12, "{f:?} supplementary: {r}");
            } else {
                assert!(
                    r.abs() > 0.5,
                    "{f:?}: 30 and 150 degrees taken as equal ({r})"
                );
            }
        }
    }
}

#[test]
fn parallel_and_pt_on_line_in_space_keep_the_informative_cross_components() {
    // The two rows are the components of a cross product off the line's dominant axis, so
    // they stay independent at the solution whichever axis the line follows.
    for axis in 0..3 {
        let mut d = [0.3, -0.2, 0.25];
        d[axis] = 2.0;
        let mut fx = Fx::new();
        let a = ray3(&mut fx, FIXED, [0.0, 0.0, 0.0], d);
        let b = ray3(&mut fx, MOVING, [1.0, 1.0, 1.0], along([0.0; 3], d, 1.5));
        let p = fx.pt(MOVING, Free, along([0.0; 3], d, 0.4));
        let par = fx.con(K::Parallel, Free).with_entities([a, b, 0, 0]);
        let on = fx.con(K::PtOnLine, Free).with_points(p, 0);
        let on = on.with_entities([a, 0, 0, 0]);
        for (c, moving) in [(par, fx.point_of(b, 1)), (on, p)] {
            let one = compile(&fx.sys, &c);
            let x = one.x(&fx.sys);
            let (res, jac) = one.jacobian(&x);
            assert!(res.iter().all(|r| r.abs() < 1e-12), "{}: {res:?}", c.kind);
            let cols = one.cols(&fx.sys, moving);
            assert_eq!(rank(&jac, x.len(), &cols), 2, "{} along {d:?}", c.kind);
        }
    }
}
