//! Normals: unit quaternions and equal orientation.

use super::refs::{Ent, Geo};
use super::{Equation, Rows};
use crate::geom::Scalar;

/// A 3D normal's implicit condition `w^2 + x^2 + y^2 + z^2 = 1`.
pub(super) fn unit_quaternion<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let Ent::Normal(q) = e.ent(0) else {
        unreachable!("a normal")
    };
    out.push(g.quat(*q).norm2() - 1.0);
}

pub(super) fn choose_same_orientation(_e: &Equation, _g: &Geo<f64>) -> u8 {
    0
}

/// Normals `entity_a` and `entity_b` are the same rotation: the vector part of
/// `q_a * conj(q_b)` is zero (three rows; `q` and `-q` are the same rotation).
pub(super) fn same_orientation<S: Scalar>(e: &Equation, g: &Geo<S>, out: &mut Rows<S>) {
    let (Ent::Normal(a), Ent::Normal(b)) = (e.ent(0), e.ent(1)) else {
        unreachable!("validated: normals")
    };
    let r = g.quat(*a).times(g.quat(*b).conj());
    out.push(r.x);
    out.push(r.y);
    out.push(r.z);
}
