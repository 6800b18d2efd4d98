//! Normals: unit quaternions and equal orientation.

use super::points::push_across;
use super::refs::{Ent, Geo};
use super::{Equation, Rows};
use crate::geom::{Quat, Scalar};

/// A 3D normal's implicit condition `w^2 + x^2 + y^2 + z^2 = 1`.
pub(super) fn unit_quaternion<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let Ent::Normal(q) = e.ent(0) else {
        unreachable!("a normal")
    };
    out.push(g.normal(q).norm2() - 1.0);
}

/// A rotated normal (`ents[0]`) is the rotation (`ents[1]`) times its base (w in `val`,
/// x, y, z in `target`): four rows, w, x, y, z.
pub(super) fn rotated<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let (Ent::Normal(own), Ent::Normal(q)) = (e.ent(0), e.ent(1)) else {
        unreachable!("resolved: two normals")
    };
    let base = Quat {
        w: S::cst(e.val),
        x: S::cst(e.target[0]),
        y: S::cst(e.target[1]),
        z: S::cst(e.target[2]),
    };
    let want = g.normal(q).times(base);
    let own = g.normal(own);
    out.push(own.w - want.w);
    out.push(own.x - want.x);
    out.push(own.y - want.y);
    out.push(own.z - want.z);
}

/// The branch of `same_orientation`: 1 when U of `a` is held perpendicular to V of `b`
/// (else to U of `b`), whichever is nearer to holding at the start.
pub(super) fn choose_same_orientation(e: &Equation, g: &Geo<f64>) -> u8 {
    let (a, b) = normals(e, g);
    u8::from(a.u().dot(b.v()).abs() < a.u().dot(b.u()).abs())
}

fn normals<S: Scalar>(e: &Equation, g: &Geo<S>) -> (Quat<S>, Quat<S>) {
    let (Ent::Normal(a), Ent::Normal(b)) = (e.ent(0), e.ent(1)) else {
        unreachable!("validated: normals")
    };
    (g.normal(a), g.normal(b))
}

/// Normals `entity_a` and `entity_b` have the same orientation, as SolveSpace means it:
/// their N axes are parallel (either direction), and U of `a` is perpendicular to V of `b`
/// or to U of `b`, whichever is nearer when the equations are built, so the frames agree up
/// to a quarter or half turn in the plane. Three rows.
pub(super) fn same_orientation<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let (a, b) = normals(e, g);
    push_across(a.n().cross(b.n()), a.n(), out);
    out.push(if e.choice == 1 {
        a.u().dot(b.v())
    } else {
        a.u().dot(b.u())
    });
}
