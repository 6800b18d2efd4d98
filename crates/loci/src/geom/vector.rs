//! Small vectors and quaternions over any [`Scalar`].

use super::Scalar;

/// A 3D vector. In a workplane, `z` is zero and `x`, `y` are u, v.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vec3<S> {
    /// x (or u).
    pub x: S,
    /// y (or v).
    pub y: S,
    /// z (zero in a workplane).
    pub z: S,
}

impl<S: Scalar> Vec3<S> {
    /// From components.
    #[inline]
    pub fn new(x: S, y: S, z: S) -> Self {
        Self { x, y, z }
    }

    /// A 2D vector (z = 0).
    #[inline]
    pub fn uv(u: S, v: S) -> Self {
        Self {
            x: u,
            y: v,
            z: S::cst(0.0),
        }
    }

    /// Sum.
    #[inline]
    #[must_use]
    pub fn plus(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }

    /// Difference.
    #[inline]
    #[must_use]
    pub fn minus(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }

    /// Scaled by `k`.
    #[inline]
    #[must_use]
    pub fn scale(self, k: S) -> Self {
        Self::new(self.x * k, self.y * k, self.z * k)
    }

    /// Scaled by a constant.
    #[inline]
    #[must_use]
    pub fn scale_f(self, k: f64) -> Self {
        Self::new(self.x * k, self.y * k, self.z * k)
    }

    /// Dot product.
    #[inline]
    pub fn dot(self, o: Self) -> S {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Cross product.
    #[inline]
    #[must_use]
    pub fn cross(self, o: Self) -> Self {
        Self::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }

    /// Length.
    #[inline]
    pub fn norm(self) -> S {
        self.dot(self).sqrt()
    }

    /// Component `i` (0, 1, 2).
    #[inline]
    pub fn at(self, i: usize) -> S {
        match i {
            0 => self.x,
            1 => self.y,
            _ => self.z,
        }
    }

    /// Values without derivatives.
    #[inline]
    pub fn value(self) -> Vec3<f64> {
        Vec3::new(self.x.val(), self.y.val(), self.z.val())
    }
}

/// A quaternion w + xi + yj + zk describing a rotation (a SolveSpace "normal").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quat<S> {
    /// Real part.
    pub w: S,
    /// i.
    pub x: S,
    /// j.
    pub y: S,
    /// k.
    pub z: S,
}

impl<S: Scalar> Quat<S> {
    /// The rotated x axis: the plane's U direction.
    #[inline]
    pub fn u(self) -> Vec3<S> {
        let Quat { w, x, y, z } = self;
        Vec3::new(
            w * w + x * x - y * y - z * z,
            (w * z + x * y) * 2.0,
            (x * z - w * y) * 2.0,
        )
    }

    /// The rotated y axis: the plane's V direction.
    #[inline]
    pub fn v(self) -> Vec3<S> {
        let Quat { w, x, y, z } = self;
        Vec3::new(
            (x * y - w * z) * 2.0,
            w * w - x * x + y * y - z * z,
            (w * x + y * z) * 2.0,
        )
    }

    /// The rotated z axis: the plane's normal N.
    #[inline]
    pub fn n(self) -> Vec3<S> {
        let Quat { w, x, y, z } = self;
        Vec3::new(
            (w * y + x * z) * 2.0,
            (y * z - w * x) * 2.0,
            w * w - x * x - y * y + z * z,
        )
    }

    /// Squared length (1 for a rotation).
    #[inline]
    pub fn norm2(self) -> S {
        self.w * self.w + self.x * self.x + self.y * self.y + self.z * self.z
    }

    /// Hamilton product `self * o`.
    #[inline]
    #[must_use]
    pub fn times(self, o: Self) -> Self {
        Quat {
            w: self.w * o.w - self.x * o.x - self.y * o.y - self.z * o.z,
            x: self.w * o.x + self.x * o.w + self.y * o.z - self.z * o.y,
            y: self.w * o.y - self.x * o.z + self.y * o.w + self.z * o.x,
            z: self.w * o.z + self.x * o.y - self.y * o.x + self.z * o.w,
        }
    }

    /// Conjugate (the inverse rotation for a unit quaternion).
    #[inline]
    #[must_use]
    pub fn conj(self) -> Self {
        Quat {
            w: self.w,
            x: -self.x,
            y: -self.y,
            z: -self.z,
        }
    }
}

/// The unit quaternion whose U and V axes are `u` and `v` (orthonormal), as libslvs's
/// `Slvs_MakeQuaternion` computes it.
#[must_use]
pub fn quaternion_from_uv(u: [f64; 3], v: [f64; 3]) -> [f64; 4] {
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    // Rotation matrix with columns U, V, N; the standard trace-based extraction, choosing
    // the largest of w, x, y, z to divide by for accuracy.
    let (m00, m01, m02) = (u[0], v[0], n[0]);
    let (m10, m11, m12) = (u[1], v[1], n[1]);
    let (m20, m21, m22) = (u[2], v[2], n[2]);
    let tr = m00 + m11 + m22;
    let q = if tr > 0.0 {
        let s = (tr + 1.0).sqrt() * 2.0;
        [0.25 * s, (m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s]
    } else if m00 > m11 && m00 > m22 {
        let s = (1.0 + m00 - m11 - m22).sqrt() * 2.0;
        [(m21 - m12) / s, 0.25 * s, (m01 + m10) / s, (m02 + m20) / s]
    } else if m11 > m22 {
        let s = (1.0 + m11 - m00 - m22).sqrt() * 2.0;
        [(m02 - m20) / s, (m01 + m10) / s, 0.25 * s, (m12 + m21) / s]
    } else {
        let s = (1.0 + m22 - m00 - m11).sqrt() * 2.0;
        [(m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, 0.25 * s]
    };
    let len = q.iter().map(|a| a * a).sum::<f64>().sqrt();
    q.map(|a| a / len)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quaternion_round_trip() {
        let a = 0.3f64;
        let u = [a.cos(), a.sin(), 0.0];
        let v = [-a.sin() * 0.6, a.cos() * 0.6, 0.8];
        let q = quaternion_from_uv(u, v);
        let q = Quat {
            w: q[0],
            x: q[1],
            y: q[2],
            z: q[3],
        };
        let (uu, vv) = (q.u(), q.v());
        for i in 0..3 {
            assert!((uu.at(i) - u[i]).abs() < 1e-12);
            assert!((vv.at(i) - v[i]).abs() < 1e-12);
        }
        let n = q.n();
        assert!((n.dot(uu)).abs() < 1e-12 && (n.norm() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn identity_axes() {
        let q = Quat {
            w: 1.0,
            x: 0.0,
            y: 0.0,
            z: 0.0,
        };
        assert_eq!(q.u(), Vec3::new(1.0, 0.0, 0.0));
        assert_eq!(q.v(), Vec3::new(0.0, 1.0, 0.0));
        assert_eq!(q.n(), Vec3::new(0.0, 0.0, 1.0));
    }
}
