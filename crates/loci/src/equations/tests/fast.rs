//! The written-out derivatives of `equations/fast.rs` against the dual numbers, which define
//! them: same residual, same derivatives, on the fixture's tilted workplane.

use super::super::compile::resolve_constraint;
use super::super::fast;
use super::super::refs::Resolver;
use super::super::{Equation, Rows};
use super::fixture::{compile, compile_implicit, Form, Fx, One, FIXED, MOVING};
use crate::model::{Constraint, ConstraintKind as K, Entity, GroupId};
use proptest::prelude::*;

/// A residual and its row of the Jacobian.
type Row = (f64, Vec<f64>);

/// Which local slots a check differentiates with respect to: those of [`MOVING`] parameters
/// (some slots then stay constants, as in a solve), or every one (the workplane's too, whose
/// derivatives are zero for points of the workplane).
#[derive(Clone, Copy, Debug)]
enum Unknowns {
    Moving,
    All,
}

/// Residual and Jacobian of `eq` over `unknowns`, by the written-out path (`None` when it does
/// not apply) and by dual numbers; and the residual the solver evaluates (in `f64`).
fn rows(fx: &Fx, eq: &Equation, locals: &[u32], unknowns: Unknowns) -> (Option<Row>, Row, f64) {
    let params = fx.sys.params();
    let x: Vec<f64> = locals.iter().map(|&p| params[p as usize].val).collect();
    let active: Vec<u16> = (0..x.len() as u16)
        .filter(|&k| match unknowns {
            Unknowns::Moving => params[locals[k as usize] as usize].group == GroupId(MOVING),
            Unknowns::All => true,
        })
        .collect();
    let (mut r1, mut j1) = ([0.0], vec![0.0; active.len()]);
    let written = fast::jacobian(eq, &x, &active, &mut r1, &mut j1).then_some((r1[0], j1));
    // The residual alone, as the line search evaluates it: the same, to the last bit.
    let mut r3 = [f64::NAN];
    assert_eq!(eq.residuals_fast(&x, &mut r3), written.is_some());
    if let Some((r, _)) = &written {
        assert_eq!(r3[0].to_bits(), r.to_bits());
    }
    // The generic equation may have more rows (in space): the first is compared.
    let mut out = Rows::new();
    eq.eval(&x, &mut out);
    let (mut r2, mut j2) = (vec![0.0; out.n], vec![0.0; out.n * active.len()]);
    eq.jacobian_dual(&x, &active, &mut r2, &mut j2);
    j2.truncate(active.len());
    (written, (r2[0], j2), out.v[0])
}

/// Residual and Jacobian over the unknown slots of `c` (with its branch set to `choice`), by
/// the written-out path (`None` when it does not apply) and by dual numbers.
fn both(fx: &Fx, c: &Constraint, choice: u8) -> (Option<Row>, Row) {
    let (eq, locals) = resolved(fx, c, choice);
    let (written, dual, _) = rows(fx, &eq, &locals, Unknowns::Moving);
    (written, dual)
}

/// Constraint `c` resolved as the solver does, with its branch set to `choice`.
fn resolved(fx: &Fx, c: &Constraint, choice: u8) -> (Equation, Vec<u32>) {
    fx.sys.validate().expect("the fixture builds a valid model");
    let (mut eq, l) = resolve_constraint(&Resolver::new(&fx.sys), c).expect("resolves");
    eq.choice = choice;
    (eq, l.params.to_vec())
}

/// The written-out path applies to `eq`, and gives the residual of the generic `f64`
/// evaluation to the last bit and the dual numbers' derivatives, over the moving slots and
/// over all of them.
fn assert_matches(fx: &Fx, eq: &Equation, locals: &[u32]) {
    for unknowns in [Unknowns::Moving, Unknowns::All] {
        let (written, (r2, j2), r0) = rows(fx, eq, locals, unknowns);
        let (r1, j1) = written.expect("the written-out path applies");
        assert_eq!(r1.to_bits(), r0.to_bits(), "residual {r1} vs generic {r0}");
        assert!(
            (r1 - r2).abs() <= 1e-12 * (1.0 + r2.abs()),
            "residual {r1} vs {r2}"
        );
        assert_eq!(j1.len(), j2.len());
        for (a, b) in j1.iter().zip(&j2) {
            assert!(
                (a - b).abs() <= 1e-12 * (1.0 + b.abs()),
                "{unknowns:?}: {j1:?} vs {j2:?}"
            );
        }
    }
}

fn assert_same(fx: &Fx, c: &Constraint, choice: u8) {
    let (eq, locals) = resolved(fx, c, choice);
    assert_matches(fx, &eq, &locals);
}

/// Two moving lines of the workplane on points `pts[0..4]`; with `shared`, both start at the
/// same point entity, whose slots then feed twice.
fn two_lines(fx: &mut Fx, pts: &[u32], shared: bool) -> (u32, u32) {
    let second_start = if shared { pts[0] } else { pts[2] };
    let l0 = fx.line_of(MOVING, Form::Plane, pts[0], pts[1]);
    let l1 = fx.line_of(MOVING, Form::Plane, second_start, pts[3]);
    (l0, l1)
}

fn coord() -> impl Strategy<Value = [f64; 2]> {
    [-50.0..50.0f64, -50.0..50.0f64]
}

/// An arc of the workplane on existing points (any group), so that its centre can move and
/// its points can be shared. Its handle is far above the fixture's own.
fn arc_of(fx: &mut Fx, center: u32, start: u32, end: u32) -> u32 {
    let n = fx.normal2(fx.wp);
    let h = 1_000_000 + fx.sys.entities().len() as u32;
    fx.sys
        .add_entity(Entity::arc(h, MOVING, fx.wp, n, center, start, end))
        .expect("fresh entity");
    h
}

/// Three moving points of the workplane and an arc on them; `start_is_end` makes start and
/// end one point.
fn moving_arc(fx: &mut Fx, p: &[[f64; 2]], start_is_end: bool) -> (u32, [u32; 3]) {
    let c = fx.p2(MOVING, fx.wp, p[0]);
    let s = fx.p2(MOVING, fx.wp, p[1]);
    let e = if start_is_end {
        s
    } else {
        fx.p2(MOVING, fx.wp, p[2])
    };
    (arc_of(fx, c, s, e), [c, s, e])
}

/// The written-out residual and Jacobian of a compiled equation over all its slots, with
/// slot `k` in column `k`.
fn written_all(fx: &Fx, one: &One) -> Option<Row> {
    let x = one.x(&fx.sys);
    let active: Vec<u16> = (0..x.len() as u16).collect();
    let (mut r, mut j) = ([0.0], vec![0.0; x.len()]);
    fast::jacobian(&one.eq, &x, &active, &mut r, &mut j).then_some((r[0], j))
}

/// The derivatives of `jac` with respect to the parameters of point `h`.
fn d_point(fx: &Fx, one: &One, jac: &[f64], h: u32) -> Vec<f64> {
    one.cols(&fx.sys, h).iter().map(|&k| jac[k]).collect()
}

fn assert_near(got: &[f64], want: &[f64]) {
    assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!(
            (g - w).abs() <= 1e-12 * (1.0 + w.abs()),
            "{got:?} vs {want:?}"
        );
    }
}

proptest! {
    #[test]
    fn distance_matches_dual_numbers(a in coord(), b in coord(), d in 0.0..30.0f64) {
        let mut fx = Fx::new();
        let (pa, pb) = (fx.p2(MOVING, fx.wp, a), fx.p2(MOVING, fx.wp, b));
        let c = fx.con(K::PtPtDistance, Form::Plane).with_points(pa, pb).with_val(d);
        assert_same(&fx, &c, 0);
    }

    #[test]
    fn angle_matches_dual_numbers(
        p in proptest::collection::vec(coord(), 4),
        deg in -400.0..400.0f64,
        other: bool,
        signed: bool,
        shared: bool,
        choice in 0u8..2,
    ) {
        let mut fx = Fx::new();
        let pts: Vec<u32> = p.iter().map(|&uv| fx.p2(MOVING, fx.wp, uv)).collect();
        let (l0, l1) = two_lines(&mut fx, &pts, shared);
        let mut c = fx
            .con(K::Angle, Form::Plane)
            .with_entities([l0, l1, 0, 0])
            .with_val(deg)
            .with_flags(other, false);
        c.signed = signed;
        assert_same(&fx, &c, choice);
    }

    #[test]
    fn arc_line_tangent_matches_dual_numbers(
        p in proptest::collection::vec(coord(), 5),
        other: bool,
        shared in 0u8..4,
    ) {
        let mut fx = Fx::new();
        let (arc, [center, start, end]) = moving_arc(&mut fx, &p, false);
        let (at, far) = if other { (end, start) } else { (start, end) };
        // 1: the line leaves the arc where it is tangent, as in a fillet; 2: it runs from the
        // arc's other end to that point; 3: it starts at the centre.
        let (a, b) = match shared {
            0 => (fx.p2(MOVING, fx.wp, p[3]), fx.p2(MOVING, fx.wp, p[4])),
            1 => (at, fx.p2(MOVING, fx.wp, p[4])),
            2 => (far, at),
            _ => (center, fx.p2(MOVING, fx.wp, p[4])),
        };
        let line = fx.line_of(MOVING, Form::Plane, a, b);
        let c = fx
            .con(K::ArcLineTangent, Form::Plane)
            .with_entities([arc, line, 0, 0])
            .with_flags(other, false);
        assert_same(&fx, &c, 0);
    }

    #[test]
    fn arc_diameter_matches_dual_numbers(
        p in proptest::collection::vec(coord(), 3),
        d in 0.0..60.0f64,
    ) {
        let mut fx = Fx::new();
        let (arc, _) = moving_arc(&mut fx, &p, false);
        let c = fx.con(K::Diameter, Form::Plane).with_entities([arc, 0, 0, 0]).with_val(d);
        assert_same(&fx, &c, 0);
    }

    #[test]
    fn circle_diameter_matches_dual_numbers(
        r in -20.0..20.0f64,
        d in 0.0..60.0f64,
        in_plane: bool,
    ) {
        let mut fx = Fx::new();
        // A circle of the workplane, or one in space with a normal of its own: the diameter
        // reads the radius parameter only.
        let form = if in_plane { Form::Plane } else { Form::Free };
        let q = [0.9, 0.1, -0.3, 0.2];
        let circle = fx.circle(MOVING, form, [1.0, 2.0, 3.0], q, r);
        let c = fx.con(K::Diameter, form).with_entities([circle, 0, 0, 0]).with_val(d);
        assert_same(&fx, &c, 0);
    }

    #[test]
    fn arc_radii_match_dual_numbers(
        p in proptest::collection::vec(coord(), 3),
        start_is_end: bool,
    ) {
        let mut fx = Fx::new();
        let (arc, _) = moving_arc(&mut fx, &p, start_is_end);
        let one = compile_implicit(&fx.sys, arc);
        assert_matches(&fx, &one.eq, &one.locals);
    }

    #[test]
    fn pt_on_line_and_distance_match_dual_numbers(
        p in proptest::collection::vec(coord(), 3),
        shared in 0u8..3,
        distance: bool,
        d in -30.0..30.0f64,
        choice in 0u8..3,
    ) {
        let mut fx = Fx::new();
        let (l0, l1) = (fx.p2(MOVING, fx.wp, p[0]), fx.p2(MOVING, fx.wp, p[1]));
        // The point may be one of the line's own: its slots then feed twice.
        let pt = match shared {
            0 => fx.p2(MOVING, fx.wp, p[2]),
            1 => l0,
            _ => l1,
        };
        let line = fx.line_of(MOVING, Form::Plane, l0, l1);
        let kind = if distance { K::PtLineDistance } else { K::PtOnLine };
        let c = fx
            .con(kind, Form::Plane)
            .with_points(pt, 0)
            .with_entities([line, 0, 0, 0])
            .with_val(d);
        // A point on a line chooses a branch from its direction in space; in the workplane
        // the equation has one row whatever it is.
        assert_same(&fx, &c, choice);
    }
}

#[test]
fn zero_length_distance_has_no_derivative_like_the_dual_numbers() {
    let mut fx = Fx::new();
    let (pa, pb) = (
        fx.p2(MOVING, fx.wp, [1.0, 2.0]),
        fx.p2(MOVING, fx.wp, [1.0, 2.0]),
    );
    let c = fx
        .con(K::PtPtDistance, Form::Plane)
        .with_points(pa, pb)
        .with_val(3.0);
    let (written, (r2, j2)) = both(&fx, &c, 0);
    assert_eq!(written, Some((-3.0, vec![0.0; 4])));
    assert_eq!((r2, j2), (-3.0, vec![0.0; 4]));
}

#[test]
fn zero_radius_arc_has_no_radius_derivative_like_the_dual_numbers() {
    let mut fx = Fx::new();
    let (arc, _) = moving_arc(&mut fx, &[[1.0, 2.0], [1.0, 2.0], [4.0, 6.0]], false);
    let c = fx
        .con(K::Diameter, Form::Plane)
        .with_entities([arc, 0, 0, 0])
        .with_val(3.0);
    let (written, (r2, j2)) = both(&fx, &c, 0);
    // Centre and start: no derivative; the end is not read.
    assert_eq!(written, Some((-3.0, vec![0.0; 6])));
    assert_eq!((r2, j2), (-3.0, vec![0.0; 6]));
    // The arc's own equation: the start's radius is 0, the end's 5.
    let one = compile_implicit(&fx.sys, arc);
    let (res, jac) = written_all(&fx, &one).expect("the written-out path applies");
    assert_eq!(res, -5.0);
    let [center, start, end] = [0, 1, 2].map(|i| fx.point_of(arc, i));
    assert_eq!(d_point(&fx, &one, &jac, start), vec![0.0, 0.0]);
    assert_near(&d_point(&fx, &one, &jac, end), &[-0.6, -0.8]);
    assert_near(&d_point(&fx, &one, &jac, center), &[0.6, 0.8]);
    assert_matches(&fx, &one.eq, &one.locals);
}

#[test]
fn zero_length_radius_or_line_takes_the_generic_path() {
    // The generic quotients divide by zero there; the written-out path leaves them to it.
    let mut fx = Fx::new();
    let (arc, [_, start, _]) = moving_arc(&mut fx, &[[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]], false);
    let q = fx.p2(MOVING, fx.wp, [2.0, 0.0]);
    let dot = fx.line_of(MOVING, Form::Plane, start, q);
    let c = fx
        .con(K::ArcLineTangent, Form::Plane)
        .with_entities([arc, dot, 0, 0]);
    assert!(both(&fx, &c, 0).0.is_none());
    let p = fx.p2(MOVING, fx.wp, [5.0, 1.0]);
    for kind in [K::PtOnLine, K::PtLineDistance] {
        let c = fx
            .con(kind, Form::Plane)
            .with_points(p, 0)
            .with_entities([dot, 0, 0, 0]);
        assert!(both(&fx, &c, 0).0.is_none());
    }
    let (arc, _) = moving_arc(&mut fx, &[[0.0, 0.0], [0.0, 0.0], [0.0, 2.0]], false);
    let line = fx.line(MOVING, Form::Plane, [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
    let c = fx
        .con(K::ArcLineTangent, Form::Plane)
        .with_entities([arc, line, 0, 0]);
    assert!(both(&fx, &c, 0).0.is_none());
}

/// A fillet's corner: the arc of radius 2 about the origin from 0 to 90 degrees, and a line
/// from its start (2, 0) up to (2, 3), tangent to it there.
#[test]
fn tangent_line_at_an_arc_has_the_written_out_values() {
    let mut fx = Fx::new();
    let (arc, [center, start, _]) =
        moving_arc(&mut fx, &[[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]], false);
    let top = fx.p2(MOVING, fx.wp, [2.0, 3.0]);
    let line = fx.line_of(MOVING, Form::Plane, start, top);
    let c = fx
        .con(K::ArcLineTangent, Form::Plane)
        .with_entities([arc, line, 0, 0]);
    let one = compile(&fx.sys, &c);
    let (res, jac) = written_all(&fx, &one).expect("the written-out path applies");
    assert_eq!(res, 0.0);
    // r = (2, 0), d = (0, 3): df/dr = d / 6 = (0, 0.5), df/dd = r / 6 = (1/3, 0). The start is
    // both the radius's end and the line's start: (0, 0.5) - (1/3, 0).
    assert_near(&d_point(&fx, &one, &jac, start), &[-1.0 / 3.0, 0.5]);
    assert_near(&d_point(&fx, &one, &jac, center), &[0.0, -0.5]);
    assert_near(&d_point(&fx, &one, &jac, top), &[1.0 / 3.0, 0.0]);
    // At the other end (0, 2) the radius runs along the line: cos = 1, and no first-order
    // change turns it.
    let c = c.with_flags(true, false);
    let one = compile(&fx.sys, &c);
    let (res, jac) = written_all(&fx, &one).expect("the written-out path applies");
    assert_eq!(res, 1.0);
    assert!(jac.iter().all(|&v| v.abs() < 1e-15), "{jac:?}");
    assert_same(&fx, &c, 0);
    // Another branch than the generic equation's one is not written out.
    assert!(both(&fx, &c, 1).0.is_none());
}

#[test]
fn diameters_have_the_written_out_values() {
    let mut fx = Fx::new();
    let (arc, [center, start, end]) =
        moving_arc(&mut fx, &[[1.0, 1.0], [4.0, 5.0], [-4.0, 1.0]], false);
    let c = fx
        .con(K::Diameter, Form::Plane)
        .with_entities([arc, 0, 0, 0])
        .with_val(8.0);
    let one = compile(&fx.sys, &c);
    let (res, jac) = written_all(&fx, &one).expect("the written-out path applies");
    // Radius 5 from the centre to the start: 10 - 8; d/dstart = 2 (0.6, 0.8).
    assert_eq!(res, 2.0);
    assert_near(&d_point(&fx, &one, &jac, start), &[1.2, 1.6]);
    assert_near(&d_point(&fx, &one, &jac, center), &[-1.2, -1.6]);
    // The end is read with the arc, but its radius is the implicit equation's business.
    assert_eq!(d_point(&fx, &one, &jac, end), vec![0.0, 0.0]);
    let circle = fx.circle(
        MOVING,
        Form::Plane,
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0, 0.0],
        2.5,
    );
    let c = fx
        .con(K::Diameter, Form::Plane)
        .with_entities([circle, 0, 0, 0])
        .with_val(4.0);
    let one = compile(&fx.sys, &c);
    let (res, jac) = written_all(&fx, &one).expect("the written-out path applies");
    assert_eq!(res, 1.0);
    // The circle's centre and normal are read but do not count: 2 for the radius only.
    let radius = fx.radius_param(circle);
    let k = one
        .locals
        .iter()
        .position(|&l| fx.sys.params()[l as usize].h.0 == radius)
        .expect("the radius is a local");
    let want: Vec<f64> = (0..jac.len())
        .map(|i| if i == k { 2.0 } else { 0.0 })
        .collect();
    assert_eq!(jac, want);
    assert_matches(&fx, &one.eq, &one.locals);
}

#[test]
fn point_and_line_have_the_written_out_values() {
    // The line (0, 0) -> (4, 0) and the point (1, 2): 2 to its left.
    let mut fx = Fx::new();
    let line = fx.line(MOVING, Form::Plane, [0.0, 0.0, 0.0], [4.0, 0.0, 0.0]);
    let (l0, l1) = (fx.point_of(line, 0), fx.point_of(line, 1));
    let p = fx.p2(MOVING, fx.wp, [1.0, 2.0]);
    let on = fx
        .con(K::PtOnLine, Form::Plane)
        .with_points(p, 0)
        .with_entities([line, 0, 0, 0]);
    let one = compile(&fx.sys, &on);
    let (res, jac) = written_all(&fx, &one).expect("the written-out path applies");
    assert_eq!(res, 2.0);
    assert_near(&d_point(&fx, &one, &jac, p), &[0.0, 1.0]);
    // Moving the end up turns the line towards the point; the start, the other way.
    assert_near(&d_point(&fx, &one, &jac, l1), &[0.0, -0.25]);
    assert_near(&d_point(&fx, &one, &jac, l0), &[0.0, -0.75]);
    // SolveSpace's sign: a point to the left of start -> end is at a negative distance.
    let dist = fx
        .con(K::PtLineDistance, Form::Plane)
        .with_points(p, 0)
        .with_entities([line, 0, 0, 0])
        .with_val(-1.5);
    let one = compile(&fx.sys, &dist);
    let (res, jac) = written_all(&fx, &one).expect("the written-out path applies");
    assert_eq!(res, -0.5);
    assert_near(&d_point(&fx, &one, &jac, p), &[0.0, -1.0]);
    assert_near(&d_point(&fx, &one, &jac, l1), &[0.0, 0.25]);
    assert_near(&d_point(&fx, &one, &jac, l0), &[0.0, 0.75]);
}

#[test]
fn points_outside_the_workplane_take_the_generic_path() {
    let mut fx = Fx::new();
    let pa = fx.p2(MOVING, fx.wp, [0.0, 0.0]);
    let pb = fx.p3(MOVING, [1.0, 2.0, 3.0]);
    let c = fx
        .con(K::PtPtDistance, Form::Plane)
        .with_points(pa, pb)
        .with_val(1.0);
    assert!(both(&fx, &c, 0).0.is_none());
    // A line given in space is no line of the workplane either.
    let (q0, q1) = (
        fx.p3(MOVING, [0.0, 0.0, 1.0]),
        fx.p3(MOVING, [1.0, 0.0, 1.0]),
    );
    let l0 = fx.line_of(MOVING, Form::Free, q0, q1);
    let pc = fx.p2(MOVING, fx.wp, [2.0, 1.0]);
    let l1 = fx.line_of(MOVING, Form::Plane, pa, pc);
    let c = fx
        .con(K::Angle, Form::Plane)
        .with_entities([l0, l1, 0, 0])
        .with_val(30.0);
    assert!(both(&fx, &c, 0).0.is_none());
    // Nor are a point in space and a line of the workplane, or either free in space.
    let line = fx.line(MOVING, Form::Plane, [0.0, 0.0, 0.0], [4.0, 1.0, 0.0]);
    for kind in [K::PtOnLine, K::PtLineDistance] {
        for (p, l, form) in [
            (pb, line, Form::Plane),
            (pa, l0, Form::Plane),
            (pb, l0, Form::Free),
        ] {
            let c = fx
                .con(kind, form)
                .with_points(p, 0)
                .with_entities([l, 0, 0, 0]);
            assert!(both(&fx, &c, 0).0.is_none(), "{kind:?} {form:?}");
        }
    }
    // A line of the second workplane, and an arc of the first: the tangency is measured in
    // the arc's.
    let arc = fx.arc_deg(FIXED, fx.wp, [0.0, 0.0], 2.0, 0.0, 90.0);
    let other = fx.line(MOVING, Form::Mixed, [2.0, 0.0, 0.0], [2.0, 3.0, 0.0]);
    let other2 = fx.line(MOVING, Form::Mixed, [2.0, 0.0, 0.0], [2.0, 3.0, 0.0]);
    for l in [other, other2] {
        let c = fx
            .con(K::ArcLineTangent, Form::Plane)
            .with_entities([arc, l, 0, 0]);
        assert!(both(&fx, &c, 0).0.is_none());
    }
}

/// A planar equation without its workplane's parameters gives the same residual and the same
/// derivatives (to the last bit) over the `n` locals it keeps.
fn assert_compacts(fx: &Fx, c: &Constraint, choice: u8, n: usize) {
    let (mut eq, l) = resolve_constraint(&Resolver::new(&fx.sys), c).expect("resolves");
    eq.choice = choice;
    let mut small = eq.clone();
    let kept = super::super::planar::compact(&mut small, &l).expect("planar");
    assert_eq!(kept.params.len(), n);
    let params = fx.sys.params();
    let values = |ls: &[u32]| -> Vec<f64> { ls.iter().map(|&p| params[p as usize].val).collect() };
    let (x, xk) = (values(&l.params), values(&kept.params));
    let (mut r, mut rk) = (Rows::new(), Rows::new());
    eq.eval(&x, &mut r);
    small.eval(&xk, &mut rk);
    assert!(r.v[0].to_bits() == rk.v[0].to_bits() || (r.v[0].is_nan() && rk.v[0].is_nan()));
    let all: Vec<u16> = (0..x.len() as u16).collect();
    let allk: Vec<u16> = (0..xk.len() as u16).collect();
    let (mut j, mut jk) = (vec![0.0; x.len()], vec![0.0; xk.len()]);
    let (mut r1, mut r2) = ([0.0], [0.0]);
    eq.jacobian_active(&x, &all, &mut r1, &mut j);
    small.jacobian_active(&xk, &allk, &mut r2, &mut jk);
    assert!(r1[0].to_bits() == r2[0].to_bits() || (r1[0].is_nan() && r2[0].is_nan()));
    for (s, &p) in l.params.iter().enumerate() {
        match kept.params.iter().position(|&q| q == p) {
            Some(k) => assert!(
                j[s].to_bits() == jk[k].to_bits() || (j[s].is_nan() && jk[k].is_nan()),
                "slot {s}: {} vs {}",
                j[s],
                jk[k]
            ),
            // The workplane's own parameters: the equation does not depend on them.
            // (At a degenerate configuration, a zero radius, every derivative is NaN.)
            None => assert!(
                j[s] == 0.0 || j.iter().all(|v| v.is_nan()),
                "slot {s}: {j:?}"
            ),
        }
    }
}

proptest! {
    #[test]
    fn planar_distance_and_angle_drop_the_workplane(
        p in proptest::collection::vec(coord(), 4),
        d in 0.0..30.0f64,
        deg in 0.0..180.0f64,
        shared: bool,
        choice in 0u8..2,
    ) {
        let mut fx = Fx::new();
        let pts: Vec<u32> = p.iter().map(|&uv| fx.p2(MOVING, fx.wp, uv)).collect();
        let c = fx.con(K::PtPtDistance, Form::Plane).with_points(pts[0], pts[1]).with_val(d);
        assert_compacts(&fx, &c, 0, 4);
        let (l0, l1) = two_lines(&mut fx, &pts, shared);
        let c = fx
            .con(K::Angle, Form::Plane)
            .with_entities([l0, l1, 0, 0])
            .with_val(deg);
        assert_compacts(&fx, &c, choice, if shared { 6 } else { 8 });
    }
}

proptest! {
    #[test]
    fn arc_equations_drop_the_workplane(
        p in proptest::collection::vec(coord(), 5),
        other: bool,
        d in 0.5..30.0f64,
    ) {
        let mut fx = Fx::new();
        let (arc, [_, start, _]) = moving_arc(&mut fx, &p, false);
        let far = fx.p2(MOVING, fx.wp, p[4]);
        let line = fx.line_of(MOVING, Form::Plane, start, far);
        let c = fx
            .con(K::ArcLineTangent, Form::Plane)
            .with_entities([arc, line, 0, 0])
            .with_flags(other, false);
        // Centre, start, end, and the line's far end: the start is shared.
        assert_compacts(&fx, &c, 0, 8);
        let c = fx
            .con(K::Diameter, Form::Plane)
            .with_entities([arc, 0, 0, 0])
            .with_val(d);
        // The arc resolves with its three points.
        assert_compacts(&fx, &c, 0, 6);
    }
}

#[test]
fn equations_that_read_the_workplane_keep_it() {
    // A distance between a point of the workplane and one in space reads the workplane.
    let mut fx = Fx::new();
    let a = fx.p2(MOVING, fx.wp, [1.0, 2.0]);
    let b = fx.p3(MOVING, [3.0, -1.0, 2.0]);
    let c = fx
        .con(K::PtPtDistance, Form::Plane)
        .with_points(a, b)
        .with_val(4.0);
    let (mut eq, l) = resolve_constraint(&Resolver::new(&fx.sys), &c).expect("resolves");
    assert!(super::super::planar::compact(&mut eq, &l).is_none());
}
