//! Points: coincidence, distances to points and planes, symmetry, midpoints, horizontal and
//! vertical.

use super::refs::{Ent, Geo};
use super::{Equation, Rows};
use crate::geom::{Scalar, Vec3};

/// `pt_a = pt_b`: two rows in a workplane, three in space.
pub(super) fn coincident<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let d = g.at(e.pt(0), e.wp()).minus(g.at(e.pt(1), e.wp()));
    out.push(d.x);
    out.push(d.y);
    if e.wp.is_none() {
        out.push(d.z);
    }
}

/// `|pt_a - pt_b| = val`.
pub(super) fn pt_pt_distance<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let d = g.at(e.pt(0), e.wp()).minus(g.at(e.pt(1), e.wp()));
    out.push(d.norm() - e.val);
}

/// Signed distance from `pt_a` to the plane `entity_a` (along its normal) is `val`.
pub(super) fn pt_plane_distance<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let f = e.frame(0);
    let d = g.pos(e.pt(0)).minus(g.v3(f.origin));
    out.push(d.dot(g.plane_normal(f)) - e.val);
}

/// `pt_a` lies in plane `entity_a`.
pub(super) fn pt_in_plane<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let f = e.frame(0);
    let d = g.pos(e.pt(0)).minus(g.v3(f.origin));
    out.push(d.dot(g.plane_normal(f)));
}

/// A translated point (`ents[0]`) is at its base (`ents[1]`) plus `val` times the
/// translation vector (`ents[2]`, read as a point in 3D): three rows, x, y, z.
pub(super) fn translated<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let (Ent::Point(p), Ent::Point(base), Ent::Point(t)) = (e.ent(0), e.ent(1), e.ent(2)) else {
        unreachable!("resolved: three points")
    };
    let d = g
        .pos(p)
        .minus(g.pos(base))
        .minus(g.pos(t).scale(S::cst(e.val)));
    out.push(d.x);
    out.push(d.y);
    out.push(d.z);
}

/// A moved point (`ents[0]`) is at the translation (`ents[1]`, read as a point in 3D) plus
/// its base (`target`) turned by the rotation quaternion (`ents[2]`): three rows, x, y, z.
/// `q p q*` is written with the quaternion's rotated axes, `p.x U + p.y V + p.z N`.
pub(super) fn rot_translated<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let (Ent::Point(p), Ent::Point(t), Ent::Normal(q)) = (e.ent(0), e.ent(1), e.ent(2)) else {
        unreachable!("resolved: two points and a normal")
    };
    let q = g.normal(q);
    let [bx, by, bz] = e.target.map(S::cst);
    let moved = g
        .pos(t)
        .plus(q.u().scale(bx))
        .plus(q.v().scale(by))
        .plus(q.n().scale(bz));
    let d = g.pos(p).minus(moved);
    out.push(d.x);
    out.push(d.y);
    out.push(d.z);
}

/// `pt_a` stays at the position it had when the equations were built.
pub(super) fn where_dragged<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let p = g.at(e.pt(0), e.wp());
    out.push(p.x - e.target[0]);
    out.push(p.y - e.target[1]);
    if e.wp.is_none() {
        out.push(p.z - e.target[2]);
    }
}

/// `(pt_b - pt_a) . dir / |dir| = val`, with `dir` a line's or a normal's direction
/// (see [`direction`]).
pub(super) fn proj_pt_distance<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let dir = direction(e.ent(0), g);
    let d = g.pos(e.pt(1)).minus(g.pos(e.pt(0)));
    out.push(d.dot(dir) / dir.norm() - e.val);
}

/// The direction of a line or of a normal (its N axis), in space. A line's direction is
/// start minus end, as SolveSpace's `VectorGetExprs` has it: signed dimensions along a line
/// (`proj_pt_distance`) and angles between a line and a normal depend on it.
pub(super) fn direction<S: Scalar>(ent: &Ent, g: &Geo<S>) -> Vec3<S> {
    match ent {
        Ent::Line(l) => g.pos(&l[0]).minus(g.pos(&l[1])),
        Ent::Normal(q) => g.normal(q).n(),
        Ent::Workplane(f) => g.plane_normal(f),
        _ => unreachable!("validated: a line or a normal"),
    }
}

/// Index of the largest component of `v` in magnitude.
pub(super) fn dominant_axis(v: Vec3<f64>) -> u8 {
    let a = [v.x.abs(), v.y.abs(), v.z.abs()];
    if a[0] >= a[1] && a[0] >= a[2] {
        0
    } else if a[1] >= a[2] {
        1
    } else {
        2
    }
}

/// Two rows that vanish exactly when `c = v × w` does, for any `w`: the components of `c`
/// other than the dominant axis of `v`, taken at the current point.
///
/// `c · v = 0` always, so if the two kept components are zero, `c_k v_k = 0` for the dropped
/// axis `k`; `v_k` is the largest component of `v` in magnitude, non-zero for any `v ≠ 0`,
/// hence `c = 0` too. Three rows would say the same with a Jacobian of rank two at every
/// root (a dependency the rank test would report); two rows over an axis fixed once, at the
/// start, have spurious roots wherever `v` and `w` both turn perpendicular to that axis (two
/// lines 90 degrees apart in the plane of the other two axes). Choosing the axis from the
/// values being evaluated keeps both rows informative and every root a true one. The choice
/// changes only where two components of `v` tie in magnitude; the dual numbers and the
/// values take it from the same real parts, so derivatives match the residuals.
pub(super) fn push_across<S: Scalar>(c: Vec3<S>, v: Vec3<S>, out: &mut Rows<S>) {
    let skip = dominant_axis(Vec3 {
        x: v.x.val(),
        y: v.y.val(),
        z: v.z.val(),
    });
    for i in 0..3u8 {
        if i != skip {
            out.push(c.at(i as usize));
        }
    }
}

/// `pt_a` and `pt_b` mirror each other in plane `entity_a`: the midpoint is on the plane and
/// the segment between them is along the normal.
///
/// In a workplane the constraint applies to the points' projections into it, as SolveSpace
/// does: the midpoint of the projections (placed back in space, on the workplane) is on the
/// plane, and the projected segment is along the normal projected into the workplane. Points
/// of the workplane are their own projections; other points (in space, or of another
/// workplane) may sit at any height over it.
pub(super) fn symmetric<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let f = e.frame(0);
    let n = g.plane_normal(f);
    match e.wp() {
        None => {
            let (a, b) = (g.pos(e.pt(0)), g.pos(e.pt(1)));
            let mid = a.plus(b).scale_f(0.5);
            out.push(mid.minus(g.v3(f.origin)).dot(n));
            push_across(b.minus(a).cross(n).scale(S::cst(1.0) / n.norm()), n, out);
        }
        Some(w) => {
            let (a, b) = (g.at(e.pt(0), Some(w)), g.at(e.pt(1), Some(w)));
            let m = a.plus(b).scale_f(0.5);
            let q = g.quat(w.q);
            let mid = g.v3(w.origin).plus(q.u().scale(m.x)).plus(q.v().scale(m.y));
            out.push(mid.minus(g.v3(f.origin)).dot(n));
            let n2 = g.project_dir(n, Some(w));
            out.push(b.minus(a).cross(n2).z / n2.norm());
        }
    }
}

/// Symmetric about an axis of the workplane: `horizontal` mirrors across the vertical axis
/// (same v, opposite u); otherwise across the horizontal axis (same u, opposite v).
pub(super) fn symmetric_axis<S: Scalar>(
    e: &Equation,
    g: &Geo<S>,
    out: &mut Rows<S>,
    horizontal: bool,
) {
    let (a, b) = (g.at(e.pt(0), e.wp()), g.at(e.pt(1), e.wp()));
    if horizontal {
        out.push(a.y - b.y);
        out.push(a.x + b.x);
    } else {
        out.push(a.x - b.x);
        out.push(a.y + b.y);
    }
}

/// `pt_a` and `pt_b` mirror each other across line `entity_a` in the workplane.
pub(super) fn symmetric_line<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let w = e.wp();
    let l = e.line(0);
    let (l0, l1) = (g.at(&l[0], w), g.at(&l[1], w));
    let (a, b) = (g.at(e.pt(0), w), g.at(e.pt(1), w));
    let d = l1.minus(l0);
    let len = d.norm();
    let mid = a.plus(b).scale_f(0.5);
    out.push(d.cross(mid.minus(l0)).z / len);
    out.push(d.dot(b.minus(a)) / len);
}

/// `pt_a` is at the midpoint of line `entity_a`; or, with no `pt_a`, the midpoint of line
/// `entity_a` lies in plane `entity_b` (SolveSpace's second form of this constraint).
pub(super) fn at_midpoint<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let w = e.wp();
    let l = e.line(0);
    let mid = g.at(&l[0], w).plus(g.at(&l[1], w)).scale_f(0.5);
    let Some(p) = &e.pts[0] else {
        // In a workplane the midpoint is taken there and lifted back into space, as
        // SolveSpace does.
        let m = match w {
            None => mid,
            Some(f) => {
                let q = g.quat(f.q);
                g.v3(f.origin)
                    .plus(q.u().scale(mid.x))
                    .plus(q.v().scale(mid.y))
            }
        };
        let plane = e.frame(1);
        out.push(m.minus(g.v3(plane.origin)).dot(g.plane_normal(plane)));
        return;
    };
    let d = g.at(p, w).minus(mid);
    out.push(d.x);
    out.push(d.y);
    if w.is_none() {
        out.push(d.z);
    }
}

/// A line (or `pt_a`–`pt_b`) is horizontal (equal v) or vertical (equal u) in the workplane.
pub(super) fn horizontal_vertical<S: Scalar>(
    e: &Equation,
    g: &Geo<S>,
    out: &mut Rows<S>,
    horizontal: bool,
) {
    let w = e.wp();
    let (a, b) = match e.ents.first() {
        Some(Ent::Line(l)) => (g.at(&l[0], w), g.at(&l[1], w)),
        _ => (g.at(e.pt(0), w), g.at(e.pt(1), w)),
    };
    out.push(if horizontal { a.y - b.y } else { a.x - b.x });
}
