//! Cubic Bezier curves: tangency to lines and to other curves.

use super::circles::arc_radius_vector;
use super::points::push_across;
use super::refs::{Ent, Frame, Geo};
use super::{Equation, Rows};
use crate::geom::{Scalar, Vec3};

/// The tangent direction of a curve at its start (or end with `at_end`), in `w` or in space.
fn tangent<S: Scalar>(ent: &Ent, g: &Geo<S>, at_end: bool, w: Option<&Frame>) -> Vec3<S> {
    match ent {
        Ent::Cubic(p) => {
            if at_end {
                g.at(&p[3], w).minus(g.at(&p[2], w))
            } else {
                g.at(&p[1], w).minus(g.at(&p[0], w))
            }
        }
        Ent::Arc { wp: own, .. } => {
            // Perpendicular to the radius, in the arc's plane. Only the direction's line matters.
            let r = arc_radius_vector(ent, g, at_end);
            let t = Vec3::uv(-r.y, r.x);
            match w {
                Some(f) if f.id == own.id => t,
                // An arc of another workplane: its tangent in space, projected like the rest.
                _ => {
                    let q = g.quat(own.q);
                    g.project_dir(q.u().scale(t.x).plus(q.v().scale(t.y)), w)
                }
            }
        }
        _ => unreachable!("validated: an arc or a cubic"),
    }
}

/// Cubic `entity_a` is tangent to line `entity_b` at its start (end with `other`).
pub(super) fn cubic_line_tangent<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let w = e.wp();
    let t = tangent(e.ent(0), g, e.other, w);
    let d = g.line_dir(e.line(1), w);
    let c = t.cross(d).scale(S::cst(1.0) / (t.norm() * d.norm()));
    match w {
        Some(_) => out.push(c.z),
        None => push_across(c, t, out),
    }
}

pub(super) fn choose_curve_curve(_e: &Equation, _g: &Geo<f64>) -> u8 {
    0
}

/// Curves `entity_a` and `entity_b` (arcs or cubics) are tangent at the chosen ends.
pub(super) fn curve_curve_tangent<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let w = e.wp();
    let ta = tangent(e.ent(0), g, e.other, w);
    let tb = tangent(e.ent(1), g, e.other2, w);
    out.push(ta.cross(tb).z / (ta.norm() * tb.norm()));
}
