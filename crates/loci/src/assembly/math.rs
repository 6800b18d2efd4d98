//! Small vector and quaternion helpers over `f64` for poses and references.
//!
//! Quaternions are `[w, x, y, z]`; a unit quaternion `q` turns `v` into `q v q*`.

/// A 3D vector.
pub type V3 = [f64; 3];
/// A quaternion `[w, x, y, z]`.
pub type Q4 = [f64; 4];

/// The identity rotation.
pub const IDENTITY: Q4 = [1.0, 0.0, 0.0, 0.0];

pub(crate) fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub(crate) fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

pub(crate) fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub(crate) fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// `a` at unit length, or `None` when it has none to speak of.
pub(crate) fn unit(a: V3) -> Option<V3> {
    let n = norm(a);
    (n > 1e-12 && n.is_finite()).then(|| scale(a, 1.0 / n))
}

/// A unit vector perpendicular to the unit vector `a`, chosen from `a` alone.
pub(crate) fn perpendicular(a: V3) -> V3 {
    let helper = if a[2].abs() < 0.9 {
        [0.0, 0.0, 1.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    unit(cross(a, helper)).unwrap_or([1.0, 0.0, 0.0])
}

/// The Hamilton product `a b`.
pub(crate) fn qmul(a: Q4, b: Q4) -> Q4 {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// The conjugate: the inverse of a unit quaternion.
pub(crate) fn qconj(q: Q4) -> Q4 {
    [q[0], -q[1], -q[2], -q[3]]
}

/// `q` at unit length, or `None` for a zero or non-finite quaternion.
pub(crate) fn qunit(q: Q4) -> Option<Q4> {
    let n = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).sqrt();
    (n > 1e-12 && n.is_finite()).then(|| [q[0] / n, q[1] / n, q[2] / n, q[3] / n])
}

/// `v` turned by the unit quaternion `q`.
pub(crate) fn rotate(q: Q4, v: V3) -> V3 {
    let u = [q[1], q[2], q[3]];
    let t = scale(cross(u, v), 2.0);
    add(add(v, scale(t, q[0])), cross(u, t))
}

/// The rotation by `angle` radians about the unit `axis`.
pub(crate) fn axis_angle(axis: V3, angle: f64) -> Q4 {
    let (s, c) = (angle / 2.0).sin_cos();
    [c, axis[0] * s, axis[1] * s, axis[2] * s]
}

/// The shortest rotation taking unit `a` onto unit `b` (half a turn about a perpendicular
/// of `a` when they are opposite).
pub(crate) fn from_to(a: V3, b: V3) -> Q4 {
    let d = dot(a, b);
    if d < -1.0 + 1e-12 {
        let p = perpendicular(a);
        return [0.0, p[0], p[1], p[2]];
    }
    let c = cross(a, b);
    qunit([1.0 + d, c[0], c[1], c[2]]).unwrap_or(IDENTITY)
}

/// The angle in radians between unit vectors, robust near 0 and 180 degrees.
pub(crate) fn angle_between(a: V3, b: V3) -> f64 {
    norm(cross(a, b)).atan2(dot(a, b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotations_compose_and_turn_as_expected() {
        let q = axis_angle([0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2);
        let v = rotate(q, [1.0, 0.0, 0.0]);
        assert!((v[0]).abs() < 1e-15 && (v[1] - 1.0).abs() < 1e-15);
        let qq = qmul(q, q);
        let w = rotate(qq, [1.0, 0.0, 0.0]);
        assert!((w[0] + 1.0).abs() < 1e-15);
        let f = from_to([0.0, 0.0, 1.0], [0.0, 0.0, -1.0]);
        let z = rotate(f, [0.0, 0.0, 1.0]);
        assert!((z[2] + 1.0).abs() < 1e-15);
    }
}
