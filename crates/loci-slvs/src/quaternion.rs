//! `Slvs_QuaternionU/V/N` and `Slvs_MakeQuaternion`.

use loci::geom::{Quat, Vec3};

/// Writes the three components of `v` through the out-pointers, skipping null ones.
///
/// # Safety
/// Each pointer is null or valid for one `f64` write.
unsafe fn put3(v: Vec3<f64>, x: *mut f64, y: *mut f64, z: *mut f64) {
    for (p, val) in [(x, v.x), (y, v.y), (z, v.z)] {
        // SAFETY: the caller promises each pointer is null or writable; `as_mut` sorts out null.
        if let Some(r) = unsafe { p.as_mut() } {
            *r = val;
        }
    }
}

/// The unit quaternion of the rotation matrix with columns `u`, `v`, `u x v`.
///
/// The textbook extraction divides by the largest of `4w²`, `4x²`, `4y²`, `4z²`; which branch
/// runs decides the overall sign of the result (`q` and `-q` are the same rotation). libslvs
/// takes the `w` branch whenever `1 + trace > 1e-4`, and so does this, so that callers who
/// store or compare quaternions get libslvs's numbers, not just the same rotation.
fn quaternion_from_basis(u: [f64; 3], v: [f64; 3]) -> [f64; 4] {
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let q = if 1.0 + u[0] + v[1] + n[2] > 1e-4 {
        let s = 2.0 * (1.0 + u[0] + v[1] + n[2]).sqrt();
        [
            s / 4.0,
            (v[2] - n[1]) / s,
            (n[0] - u[2]) / s,
            (u[1] - v[0]) / s,
        ]
    } else if u[0] > v[1] && u[0] > n[2] {
        let s = 2.0 * (1.0 + u[0] - v[1] - n[2]).sqrt();
        [
            (v[2] - n[1]) / s,
            s / 4.0,
            (u[1] + v[0]) / s,
            (n[0] + u[2]) / s,
        ]
    } else if v[1] > n[2] {
        let s = 2.0 * (1.0 - u[0] + v[1] - n[2]).sqrt();
        [
            (n[0] - u[2]) / s,
            (u[1] + v[0]) / s,
            s / 4.0,
            (v[2] + n[1]) / s,
        ]
    } else {
        let s = 2.0 * (1.0 - u[0] - v[1] + n[2]).sqrt();
        [
            (u[1] - v[0]) / s,
            (n[0] + u[2]) / s,
            (v[2] + n[1]) / s,
            s / 4.0,
        ]
    };
    let len = q.iter().map(|a| a * a).sum::<f64>().sqrt();
    q.map(|a| a / len)
}

fn quat(w: f64, x: f64, y: f64, z: f64) -> Quat<f64> {
    Quat { w, x, y, z }
}

/// The U basis vector (the rotated x axis) of quaternion `(qw, qx, qy, qz)`.
///
/// # Safety
/// `x`, `y` and `z` are each null or valid for writing one `double`.
#[no_mangle]
pub unsafe extern "C" fn Slvs_QuaternionU(
    qw: f64,
    qx: f64,
    qy: f64,
    qz: f64,
    x: *mut f64,
    y: *mut f64,
    z: *mut f64,
) {
    // SAFETY: forwarded from this function's own contract.
    unsafe { put3(quat(qw, qx, qy, qz).u(), x, y, z) }
}

/// The V basis vector (the rotated y axis) of quaternion `(qw, qx, qy, qz)`.
///
/// # Safety
/// `x`, `y` and `z` are each null or valid for writing one `double`.
#[no_mangle]
pub unsafe extern "C" fn Slvs_QuaternionV(
    qw: f64,
    qx: f64,
    qy: f64,
    qz: f64,
    x: *mut f64,
    y: *mut f64,
    z: *mut f64,
) {
    // SAFETY: forwarded from this function's own contract.
    unsafe { put3(quat(qw, qx, qy, qz).v(), x, y, z) }
}

/// The N basis vector (the normal, the rotated z axis) of quaternion `(qw, qx, qy, qz)`.
///
/// # Safety
/// `x`, `y` and `z` are each null or valid for writing one `double`.
#[no_mangle]
pub unsafe extern "C" fn Slvs_QuaternionN(
    qw: f64,
    qx: f64,
    qy: f64,
    qz: f64,
    x: *mut f64,
    y: *mut f64,
    z: *mut f64,
) {
    // SAFETY: forwarded from this function's own contract.
    unsafe { put3(quat(qw, qx, qy, qz).n(), x, y, z) }
}

/// The unit quaternion that rotates the x and y axes onto the orthonormal vectors `u`, `v`.
///
/// # Safety
/// `qw`, `qx`, `qy` and `qz` are each null or valid for writing one `double`.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn Slvs_MakeQuaternion(
    ux: f64,
    uy: f64,
    uz: f64,
    vx: f64,
    vy: f64,
    vz: f64,
    qw: *mut f64,
    qx: *mut f64,
    qy: *mut f64,
    qz: *mut f64,
) {
    let q = quaternion_from_basis([ux, uy, uz], [vx, vy, vz]);
    for (p, val) in [(qw, q[0]), (qx, q[1]), (qy, q[2]), (qz, q[3])] {
        // SAFETY: the caller promises each pointer is null or writable; `as_mut` sorts out null.
        if let Some(r) = unsafe { p.as_mut() } {
            *r = val;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_through_the_c_functions() {
        let a = 0.7f64;
        let (u, v) = ([a.cos(), a.sin(), 0.0], [-a.sin(), a.cos(), 0.0]);
        let mut q = [0.0; 4];
        let [w, x, y, z] = &mut q;
        // SAFETY: four distinct live locals.
        unsafe { Slvs_MakeQuaternion(u[0], u[1], u[2], v[0], v[1], v[2], w, x, y, z) };
        // A rotation by `a` about z is (cos a/2, 0, 0, sin a/2).
        assert!((q[0] - (a / 2.0).cos()).abs() < 1e-12 && (q[3] - (a / 2.0).sin()).abs() < 1e-12);
        let mut n = [9.0; 3];
        let [nx, ny, nz] = &mut n;
        // SAFETY: three distinct live locals.
        unsafe { Slvs_QuaternionN(q[0], q[1], q[2], q[3], nx, ny, nz) };
        assert!((n[0]).abs() < 1e-12 && n[1].abs() < 1e-12 && (n[2] - 1.0).abs() < 1e-12);
        // Null out-pointers are skipped, not written.
        let mut ux = 9.0;
        // SAFETY: null is allowed for every out-pointer; `ux` is a live local.
        unsafe {
            Slvs_QuaternionU(
                1.0,
                0.0,
                0.0,
                0.0,
                &mut ux,
                std::ptr::null_mut(),
                std::ptr::null_mut(),
            )
        };
        n[0] = ux;
        assert_eq!(n[0], 1.0);
    }
}
