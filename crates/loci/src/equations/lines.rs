//! Lines: distances from points to lines, lengths, angles, parallel and perpendicular.

use super::points::push_across;
use super::refs::{Ent, Frame, Geo, PointRef};
use super::{Equation, Rows};
use crate::geom::{Scalar, Vec3};

/// Distance from `p` to the line through `l`: signed in a workplane, unsigned in space.
///
/// The sign is SolveSpace's: positive to the right of start→end (below a rightward line),
/// as its `PointLineDistance` computes it; files store `val` with that sign (its fixture
/// `constraint/pt_line_distance/normal.slvs` holds the point (-10, 10) above the line
/// (-15, 5)→(-5, 5) at a distance of -5).
fn pt_line<S: Scalar>(g: &Geo<S>, p: &PointRef, l: &[PointRef; 2], w: Option<&Frame>) -> S {
    let a = g.at(&l[0], w);
    let d = g.at(&l[1], w).minus(a);
    let c = d.cross(g.at(p, w).minus(a));
    match w {
        Some(_) => -c.z / d.norm(),
        None => c.norm() / d.norm(),
    }
}

/// Unsigned distance from `p` to line `l`.
fn pt_line_abs<S: Scalar>(g: &Geo<S>, p: &PointRef, l: &[PointRef; 2], w: Option<&Frame>) -> S {
    let a = g.at(&l[0], w);
    let d = g.at(&l[1], w).minus(a);
    d.cross(g.at(p, w).minus(a)).norm() / d.norm()
}

fn length<S: Scalar>(g: &Geo<S>, l: &[PointRef; 2], w: Option<&Frame>) -> S {
    g.line_dir(l, w).norm()
}

/// Distance from `pt_a` to line `entity_a` is `val`.
pub(super) fn pt_line_distance<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    out.push(pt_line(g, e.pt(0), e.line(0), e.wp()) - e.val);
}

/// `pt_a` lies on line `entity_a`: one row in a workplane, two in space.
pub(super) fn pt_on_line<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let w = e.wp();
    let l = e.line(0);
    let a = g.at(&l[0], w);
    let d = g.at(&l[1], w).minus(a);
    let c = d
        .cross(g.at(e.pt(0), w).minus(a))
        .scale(S::cst(1.0) / d.norm());
    match w {
        Some(_) => out.push(c.z),
        None => push_across(c, d, out),
    }
}

/// How the lengths of two lines relate.
pub(super) enum Relation {
    Equal,
    Ratio,
    Difference,
}

/// `|A| = |B|`, `|A| = val |B|` or `|A| - |B| = val`.
pub(super) fn length_relation<S: Scalar>(
    e: &Equation,
    g: &Geo<S>,
    out: &mut Rows<S>,
    rel: Relation,
) {
    let (a, b) = (length(g, e.line(0), e.wp()), length(g, e.line(1), e.wp()));
    out.push(match rel {
        Relation::Equal => a - b,
        Relation::Ratio => a - b * e.val,
        Relation::Difference => a - b - e.val,
    });
}

/// The length of line `entity_a` equals the distance from `pt_a` to line `entity_b`.
pub(super) fn eq_len_pt_line_d<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let w = e.wp();
    out.push(length(g, e.line(0), w) - pt_line_abs(g, e.pt(0), e.line(1), w));
}

/// Distance `pt_a`–line `entity_a` equals distance `pt_b`–line `entity_b`.
pub(super) fn eq_pt_ln_distances<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let w = e.wp();
    out.push(pt_line_abs(g, e.pt(0), e.line(0), w) - pt_line_abs(g, e.pt(1), e.line(1), w));
}

/// The cosine of the angle between `a` and `b`.
fn cosine<S: Scalar>(a: Vec3<S>, b: Vec3<S>) -> S {
    a.dot(b) / (a.norm() * b.norm())
}

/// The direction of entity `i`: a line's start minus end, or a normal's N axis (SolveSpace
/// lets angle, parallel and perpendicular take either, with its `VectorGetExprs`), projected
/// into the workplane. Between two lines the orientation cancels out; between a line and a
/// normal it decides the angle.
fn vector<S: Scalar>(e: &Equation, g: &Geo<S>, i: usize, w: Option<&Frame>) -> Vec3<S> {
    match e.ent(i) {
        Ent::Line(l) => g.at(&l[0], w).minus(g.at(&l[1], w)),
        other => g.project_dir(super::points::direction(other, g), w),
    }
}

fn dirs<S: Scalar>(e: &Equation, g: &Geo<S>, i: usize, j: usize) -> (Vec3<S>, Vec3<S>) {
    (vector(e, g, i, e.wp()), vector(e, g, j, e.wp()))
}

/// The `choice` of a 2D angle written as SolveSpace writes it, `cos(angle) - cos(val)`.
pub(super) const COSINE_FORM: u8 = 2;

/// The largest `|cos(val)|` at which a 2D angle may take the cosine form: closer to 0 or 180
/// degrees its gradient vanishes with the sine.
pub(super) const COSINE_FORM_LIMIT: f64 = 0.99;

/// The target angle in radians.
///
/// SolveSpace's angle (not [`Equation::signed`], and every angle in space) has only a size:
/// `|val|` wrapped to [0, 180] degrees, or its supplement with `other`; in a workplane the
/// branch ([`choose_angle`]) gives it the turning sense drawn at the start. Since a solved
/// angle then turns the way its target does, solving again from the answer keeps it.
///
/// A signed angle in a workplane is `val` wrapped to (-180, 180], counter-clockwise from A to
/// B; with `other` it is measured against B reversed, so the angle from A to B is `val` plus
/// a half turn.
pub(super) fn target(e: &Equation) -> f64 {
    use std::f64::consts::{PI, TAU};
    let wrap = |t: f64| t - TAU * (t / TAU).round();
    let t = wrap(e.val.to_radians());
    match (e.signed && e.wp.is_some(), e.other) {
        (true, false) => t,
        (true, true) => wrap(t + PI),
        (false, false) => t.abs(),
        (false, true) => PI - t.abs(),
    }
}

/// The branch of a 2D angle: 1 when its target turns clockwise, as the lines are drawn at the
/// start (SolveSpace's angle); a signed angle has its sense in its value, and always 0.
pub(super) fn choose_angle(e: &Equation, g: &Geo<f64>) -> u8 {
    if e.wp.is_none() || e.signed {
        return 0;
    }
    let (a, b) = dirs(e, g, 0, 1);
    u8::from(a.cross(b).z < 0.0)
}

/// The angle between lines `entity_a` and `entity_b` is `val` degrees.
///
/// In space this is SolveSpace's `cos(angle) = cos(val)`. In a workplane the angle from A to B
/// is the signed [`target`] (with SolveSpace's angle, the sense it starts with), and the residual is `angle - val` wrapped to (-180, 180]
/// degrees (in radians), computed with `atan2` from the sine and cosine of the difference.
/// Unlike `cos(angle) - cos(val)` it stays well conditioned at 0 and 180 degrees; unlike
/// `sin(angle - val)` it vanishes only at the target, not also at the target plus 180 degrees
/// (the supplement's mirror image, which Newton could otherwise reach from a distant start);
/// and being linear in the angle, Newton reaches the target from anywhere on its side.
///
/// With [`crate::Config::solvespace_angles`] a 2D angle is written as in space (`choice`
/// [`COSINE_FORM`]), so that Newton follows SolveSpace's path.
pub(super) fn angle<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let (a, b) = dirs(e, g, 0, 1);
    match e.wp {
        Some(_) if e.choice != COSINE_FORM => {
            // |a||b| sin(angle) and |a||b| cos(angle): atan2 does not need them normalised.
            let (c, s) = (a.dot(b), a.cross(b).z);
            let (st, ct) = super::fast::angle_sin_cos(e);
            out.push(undefined_or(s * ct - c * st, c * ct + s * st));
        }
        _ => out.push(cosine(a, b) - target(e).cos()),
    }
}

/// `atan2(sin, cos)` of an angle difference given by its sine and cosine scaled by the
/// lengths of the lines; when a line has no length (both zero) the angle is undefined and
/// holds for no target: the residual is then the largest an angle can be, with no
/// derivatives, so the solve moves the line's ends apart instead of accepting it.
pub(super) fn undefined_or<S: Scalar>(sin: S, cos: S) -> S {
    if sin.val() == 0.0 && cos.val() == 0.0 {
        S::cst(UNDEFINED_ANGLE)
    } else {
        sin.atan2(cos)
    }
}

/// The residual of an angle with a line of no length: half a turn, the most any angle can be
/// off by.
pub(crate) const UNDEFINED_ANGLE: f64 = std::f64::consts::PI;

pub(super) fn choose_equal_angle(e: &Equation, g: &Geo<f64>) -> u8 {
    if e.wp.is_none() {
        return 0;
    }
    let mut best = (f64::INFINITY, 0);
    for choice in 0..2u8 {
        let mut r = Rows::new();
        let mut t = e.clone();
        t.choice = choice;
        equal_angle(&t, g, &mut r);
        if r.v[0].abs() < best.0 {
            best = (r.v[0].abs(), choice);
        }
    }
    best.1
}

/// angle(A, B) = angle(C, D), or supplementary with `other`.
///
/// In space: `cos1 = cos2` (or `cos1 = -cos2`), as SolveSpace writes it. In a workplane, with
/// signed angles a1 (A to B) and a2 (C to D), equal unsigned angles mean `a1 = s a2` and
/// supplementary ones `a1 = s a2 + 180` degrees, for a sign s fixed from the start (whichever
/// fits best). The residual is `a1 - s a2` (minus 180 with `other`), wrapped to (-180, 180]
/// and computed with `atan2`: well conditioned at 0 and 180 degrees, and zero only for the
/// requested relation (`sin(a1 - s a2)` would also vanish for the other one).
pub(super) fn equal_angle<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let (a, b) = dirs(e, g, 0, 1);
    let (c, d) = dirs(e, g, 2, 3);
    match e.wp {
        None => {
            let (c1, c2) = (cosine(a, b), cosine(c, d));
            out.push(if e.other { c1 + c2 } else { c1 - c2 });
        }
        Some(_) => {
            // Sines and cosines scaled by the (positive) lengths: atan2 ignores the scale.
            let (c1, s1) = (a.dot(b), a.cross(b).z);
            let (c2, s2) = (c.dot(d), c.cross(d).z);
            let s2 = if e.choice == 1 { -s2 } else { s2 };
            // sin and cos of a1 - s a2, turned by 180 degrees for supplementary angles.
            let (sd, cd) = (s1 * c2 - c1 * s2, c1 * c2 + s1 * s2);
            let (sd, cd) = if e.other { (-sd, -cd) } else { (sd, cd) };
            out.push(undefined_or(sd, cd));
        }
    }
}

/// Lines `entity_a` and `entity_b` are parallel: one row in a workplane, two in space.
pub(super) fn parallel<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let (a, b) = dirs(e, g, 0, 1);
    let c = a.cross(b).scale(S::cst(1.0) / (a.norm() * b.norm()));
    match e.wp {
        Some(_) => out.push(c.z),
        None => push_across(c, a, out),
    }
}

/// Lines `entity_a` and `entity_b` are perpendicular.
pub(super) fn perpendicular<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let (a, b) = dirs(e, g, 0, 1);
    out.push(cosine(a, b));
}
