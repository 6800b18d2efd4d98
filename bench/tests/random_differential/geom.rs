//! Plain f64 vector geometry for the generator and the checker: 3-vectors and SolveSpace's
//! quaternion convention (w, x, y, z) for a normal's axes. Written here so that the answers
//! are judged without any of loci's own geometry or equation code.

/// A vector or point in 3D (a 2D one has z = 0).
pub type V3 = [f64; 3];

pub fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The full cross product (all three components).
pub fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

pub fn unit(a: V3) -> V3 {
    scale(a, 1.0 / norm(a))
}

/// `a + t (b - a)`.
pub fn lerp(a: V3, b: V3, t: f64) -> V3 {
    add(a, scale(sub(b, a), t))
}

/// The axes U, V, N that a SolveSpace normal with quaternion `q = (w, x, y, z)` stands for:
/// the images of the x, y and z axes under the rotation (exact for a unit quaternion).
pub fn quat_axes(q: [f64; 4]) -> (V3, V3, V3) {
    let [w, x, y, z] = q;
    let u = [
        w * w + x * x - y * y - z * z,
        2.0 * (w * z + x * y),
        2.0 * (x * z - w * y),
    ];
    let v = [
        2.0 * (x * y - w * z),
        w * w - x * x + y * y - z * z,
        2.0 * (w * x + y * z),
    ];
    let n = [
        2.0 * (w * y + x * z),
        2.0 * (y * z - w * x),
        w * w - x * x - y * y + z * z,
    ];
    (u, v, n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quaternion_axes_are_a_right_handed_frame() {
        let q = [0.3f64, -0.5, 0.7, 0.2];
        let m = (q.iter().map(|c| c * c).sum::<f64>()).sqrt();
        let (u, v, n) = quat_axes(q.map(|c| c / m));
        for (a, b) in [(u, v), (v, n), (n, u)] {
            assert!(dot(a, b).abs() < 1e-12);
            assert!((norm(a) - 1.0).abs() < 1e-12);
        }
        let c = cross(u, v);
        assert!(norm(sub(c, n)) < 1e-12);
        // The identity maps the axes to themselves.
        assert_eq!(quat_axes([1.0, 0.0, 0.0, 0.0]).2, [0.0, 0.0, 1.0]);
    }
}
