//! Circles and arcs: radii, diameters, points on circles, arc lengths, tangency to lines.

use super::refs::{Ent, Geo, PointRef};
use super::{Equation, Rows};
use crate::geom::{Scalar, Vec3};

/// The radius of a circle or an arc (distance from centre to start).
fn radius<S: Scalar>(ent: &Ent, g: &Geo<S>) -> S {
    match ent {
        Ent::Circle { radius, .. } => g.p(*radius),
        Ent::Arc {
            center, start, wp, ..
        } => g.at(start, Some(wp)).minus(g.at(center, Some(wp))).norm(),
        _ => unreachable!("validated: a circle or an arc"),
    }
}

/// The angle an arc sweeps counter-clockwise from start to end, in (0, 2 pi].
fn sweep<S: Scalar>(ent: &Ent, g: &Geo<S>) -> S {
    let Ent::Arc {
        center,
        start,
        end,
        wp,
    } = ent
    else {
        unreachable!("validated: an arc")
    };
    let c = g.at(center, Some(wp));
    let (a, b) = (g.at(start, Some(wp)).minus(c), g.at(end, Some(wp)).minus(c));
    let t = a.cross(b).z.atan2(a.dot(b));
    // The branch is a constant shift: derivatives are unchanged.
    if t.val() <= 0.0 {
        t + 2.0 * std::f64::consts::PI
    } else {
        t
    }
}

fn arc_length<S: Scalar>(ent: &Ent, g: &Geo<S>) -> S {
    radius(ent, g) * sweep(ent, g)
}

/// A line's length projected into `w` (or in space).
fn line_length_in<S: Scalar>(ent: &Ent, g: &Geo<S>, w: Option<&super::refs::Frame>) -> S {
    let Ent::Line(l) = ent else {
        unreachable!("validated: a line")
    };
    g.line_dir(l, w).norm()
}

fn line_length<S: Scalar>(ent: &Ent, g: &Geo<S>) -> S {
    let Ent::Line(l) = ent else {
        unreachable!("validated: a line")
    };
    g.pos(&l[1]).minus(g.pos(&l[0])).norm()
}

/// An arc's implicit condition: start and end are equally far from the centre.
pub(super) fn arc_radii<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let Ent::Arc {
        center, end, wp, ..
    } = e.ent(0)
    else {
        unreachable!("an arc")
    };
    let r_end = g.at(end, Some(wp)).minus(g.at(center, Some(wp))).norm();
    out.push(radius(e.ent(0), g) - r_end);
}

/// The diameter of circle or arc `entity_a` is `val`.
pub(super) fn diameter<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    out.push(radius(e.ent(0), g) * 2.0 - e.val);
}

/// `pt_a` lies on the cylinder through circle or arc `entity_a`, normal to its plane.
pub(super) fn pt_on_circle<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let ent = e.ent(0);
    let (center, n): (&PointRef, Vec3<S>) = match ent {
        Ent::Circle { center, q, .. } => (center, g.normal(q).n()),
        Ent::Arc { center, wp, .. } => (center, g.plane_normal(wp)),
        _ => unreachable!("validated: a circle or an arc"),
    };
    let d = g.pos(e.pt(0)).minus(g.pos(center));
    let dn = d.dot(n) / n.norm();
    // SolveSpace writes this as d^2 - r^2, so a circle whose radius parameter went negative
    // still holds its points at |r| (diameter and equal_radius stay signed, as there).
    // d - |r| has the same roots and keeps the residual a length.
    let r = radius(ent, g);
    let r = if r.val() < 0.0 { -r } else { r };
    out.push((d.dot(d) - dn * dn).sqrt() - r);
}

/// Circles or arcs `entity_a` and `entity_b` have equal radius.
pub(super) fn equal_radius<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    out.push(radius(e.ent(0), g) - radius(e.ent(1), g));
}

/// Relations between arc lengths and line lengths.
pub(super) enum ArcRel {
    /// line `entity_a` = arc `entity_b`
    LineEqual,
    /// arc a = val * arc b
    ArcArcRatio,
    /// arc b = val * line a (SolveSpace's order: the line first, measured in the workplane)
    ArcLineRatio,
    /// arc a - arc b = val
    ArcArcDiff,
    /// arc b - line a = val (the line first, measured in the workplane)
    ArcLineDiff,
}

pub(super) fn arc_length_relation<S: Scalar>(
    e: &Equation,
    g: &Geo<S>,
    out: &mut Rows<S>,
    rel: ArcRel,
) {
    let (a, b) = (e.ent(0), e.ent(1));
    out.push(match rel {
        ArcRel::LineEqual => line_length(a, g) - arc_length(b, g),
        ArcRel::ArcArcRatio => arc_length(a, g) - arc_length(b, g) * e.val,
        ArcRel::ArcLineRatio => arc_length(b, g) - line_length_in(a, g, e.wp()) * e.val,
        ArcRel::ArcArcDiff => arc_length(a, g) - arc_length(b, g) - e.val,
        ArcRel::ArcLineDiff => arc_length(b, g) - line_length_in(a, g, e.wp()) - e.val,
    });
}

/// The radius vector of an arc at its start (or end with `at_end`), in the workplane.
pub(super) fn arc_radius_vector<S: Scalar>(ent: &Ent, g: &Geo<S>, at_end: bool) -> Vec3<S> {
    let Ent::Arc {
        center,
        start,
        end,
        wp,
    } = ent
    else {
        unreachable!("validated: an arc")
    };
    let p = if at_end { end } else { start };
    g.at(p, Some(wp)).minus(g.at(center, Some(wp)))
}

pub(super) fn choose_arc_line(_e: &Equation, _g: &Geo<f64>) -> u8 {
    0
}

/// Arc `entity_a` is tangent to line `entity_b` at its start (end with `other`): the line is
/// perpendicular to the radius there.
pub(super) fn arc_line_tangent<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let Ent::Arc { wp, .. } = e.ent(0) else {
        unreachable!("validated: an arc")
    };
    let r = arc_radius_vector(e.ent(0), g, e.other);
    let d = g.line_dir(e.line(1), Some(wp));
    out.push(r.dot(d) / (r.norm() * d.norm()));
}
