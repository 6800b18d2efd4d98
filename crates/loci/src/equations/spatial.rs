//! Hand-written derivatives for the equations an assembly is made of: coincidence of two
//! points in space, parallel and perpendicular directions, a point's distance along a
//! direction, and a quaternion's unit length, on points and normals carried by a pose
//! (`t + q base q*`, `q * base`, see [`super::carried`]) as well as plain ones.
//!
//! Through a carried reference every entry of the Jacobian is a product of quaternion
//! components, and the dual numbers carried a dozen directions through each of them: most of
//! the time of a small assembly's Newton step. Here each point or direction is formed once
//! with its partial derivatives by local slot (the rotated axes are linear in each quaternion
//! component), then combined by the chain rule. The residuals are the generic `f64`
//! evaluation itself, to the last bit; the derivatives are the dual numbers' to rounding, as
//! tests check. Anything not covered (a workplane, a 2D point, a degenerate direction, an
//! equation on plain points and normals only) takes the generic path (returns false).

use super::points::dominant_axis;
use super::refs::{Ent, NormalRef, PointRef, Slot};
use super::{EqKind, Equation, Rows};
use crate::geom::Vec3;
use crate::model::ConstraintKind;

#[cfg(test)]
thread_local! {
    /// Whether this thread's solves leave every equation here to the dual numbers.
    static DUAL_ONLY: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Whether this thread's solves leave every equation here to the dual numbers.
#[cfg(test)]
pub(crate) fn dual_only_now() -> bool {
    DUAL_ONLY.with(std::cell::Cell::get)
}

/// Runs `f` with the equations of this file differentiated by dual numbers, as every solve did
/// before they were written out: tests compare the two.
#[cfg(test)]
pub(crate) fn dual_only<R>(f: impl FnOnce() -> R) -> R {
    struct Restore(bool);
    impl Drop for Restore {
        fn drop(&mut self) {
            DUAL_ONLY.with(|d| d.set(self.0));
        }
    }
    let _restore = Restore(DUAL_ONLY.with(|d| d.replace(true)));
    f()
}

/// Most slots one point or direction reads: a line between two moved points (seven each).
const MAX_SLOTS: usize = 14;

/// Most local slots an equation may read to be written out here (an assembly's read at most
/// 28: two lines between moved points); more take the generic path.
const MAX_LOCALS: usize = 64;

/// No column: the slot is a constant of this evaluation.
const NONE: u8 = u8::MAX;

/// A vector in space and its partial derivative with respect to each local slot it reads
/// (a slot may appear twice, for a line whose two points share a pose: the partials add).
struct Lin {
    v: [f64; 3],
    d: [(Slot, [f64; 3]); MAX_SLOTS],
    n: usize,
}

impl Lin {
    fn new(v: [f64; 3]) -> Self {
        Self {
            v,
            d: [(0, [0.0; 3]); MAX_SLOTS],
            n: 0,
        }
    }

    fn push(&mut self, s: Slot, d: [f64; 3]) {
        self.d[self.n] = (s, d);
        self.n += 1;
    }

    fn partials(&self) -> &[(Slot, [f64; 3])] {
        &self.d[..self.n]
    }
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The partials of the rotated axes U, V and N of a quaternion `(w, x, y, z)` with respect to
/// w, x, y and z, for a point of coordinates `(a, b, c)` on them: `a dU + b dV + c dN`.
fn axes_partials(q: [f64; 4], [a, b, c]: [f64; 3]) -> [[f64; 3]; 4] {
    let [w, x, y, z] = q.map(|v| 2.0 * v);
    // U = (w²+x²-y²-z², 2(wz+xy), 2(xz-wy)), V = (2(xy-wz), w²-x²+y²-z², 2(wx+yz)),
    // N = (2(wy+xz), 2(yz-wx), w²-x²-y²+z²), each differentiated (with the factor 2 taken
    // into the components above).
    let du = [[w, z, -y], [x, y, z], [-y, x, -w], [-z, w, x]];
    let dv = [[-z, w, x], [y, -x, w], [x, y, z], [-w, -z, y]];
    let dn = [[y, -x, w], [z, -w, -x], [w, z, -y], [x, y, z]];
    let mut out = [[0.0; 3]; 4];
    for i in 0..4 {
        for k in 0..3 {
            out[i][k] = a * du[i][k] + b * dv[i][k] + c * dn[i][k];
        }
    }
    out
}

/// The N axis of a quaternion.
fn n_axis([w, x, y, z]: [f64; 4]) -> [f64; 3] {
    [
        (w * y + x * z) * 2.0,
        (y * z - w * x) * 2.0,
        w * w - x * x - y * y + z * z,
    ]
}

fn quat(x: &[f64], q: [Slot; 4]) -> [f64; 4] {
    q.map(|s| x[s as usize])
}

/// `q * b` (Hamilton product), and its partials with respect to q's components.
fn turned(q: [f64; 4], b: [f64; 4]) -> ([f64; 4], [[f64; 4]; 4]) {
    let [qw, qx, qy, qz] = q;
    let [bw, bx, by, bz] = b;
    let v = [
        qw * bw - qx * bx - qy * by - qz * bz,
        qw * bx + qx * bw + qy * bz - qz * by,
        qw * by - qx * bz + qy * bw + qz * bx,
        qw * bz + qx * by - qy * bx + qz * bw,
    ];
    let d = [
        [bw, bx, by, bz],
        [-bx, bw, -bz, by],
        [-by, bz, bw, -bx],
        [-bz, -by, bx, bw],
    ];
    (v, d)
}

/// A normal's quaternion and its partials: by slot, the derivative of each component.
fn normal(n: &NormalRef, x: &[f64], k: &[[f64; 4]]) -> ([f64; 4], [(Slot, [f64; 4]); 4]) {
    match n {
        NormalRef::Q(q) => {
            let mut d = [(0, [0.0; 4]); 4];
            for (i, (o, &s)) in d.iter_mut().zip(q).enumerate() {
                let mut e = [0.0; 4];
                e[i] = 1.0;
                *o = (s, e);
            }
            (quat(x, *q), d)
        }
        NormalRef::Turned { q, base } => {
            let (v, dq) = turned(quat(x, *q), k[*base as usize]);
            let mut d = [(0, [0.0; 4]); 4];
            for (o, (&s, di)) in d.iter_mut().zip(q.iter().zip(dq)) {
                *o = (s, di);
            }
            (v, d)
        }
    }
}

/// A point in space with its partials; `sign` -1 negates both (for a difference).
fn point(p: &PointRef, x: &[f64], k: &[[f64; 4]], sign: f64, out: &mut Lin) -> Option<()> {
    let e = |i: usize| {
        let mut v = [0.0; 3];
        v[i] = sign;
        v
    };
    match p {
        PointRef::P3(s) => {
            for (i, &si) in s.iter().enumerate() {
                out.v[i] += sign * x[si as usize];
                out.push(si, e(i));
            }
        }
        PointRef::Moved { t, q, base } => {
            let qv = quat(x, *q);
            let b = k[*base as usize];
            let bp = [b[0], b[1], b[2]];
            // The value is only used for the derivatives of the quotients: the residual is the
            // generic evaluation's.
            let [w, qx, qy, qz] = qv;
            let u = [
                w * w + qx * qx - qy * qy - qz * qz,
                (w * qz + qx * qy) * 2.0,
                (qx * qz - w * qy) * 2.0,
            ];
            let v = [
                (qx * qy - w * qz) * 2.0,
                w * w - qx * qx + qy * qy - qz * qz,
                (w * qx + qy * qz) * 2.0,
            ];
            let n = n_axis(qv);
            for (i, &si) in t.iter().enumerate() {
                out.v[i] += sign * (x[si as usize] + bp[0] * u[i] + bp[1] * v[i] + bp[2] * n[i]);
                out.push(si, e(i));
            }
            for (&si, d) in q.iter().zip(axes_partials(qv, bp)) {
                out.push(si, d.map(|c| sign * c));
            }
        }
        PointRef::Shifted { base, t, times } => {
            let m = f64::from(*times);
            for i in 0..3 {
                out.v[i] += sign * (x[base[i] as usize] + m * x[t[i] as usize]);
                out.push(base[i], e(i));
                out.push(t[i], e(i).map(|c| c * m));
            }
        }
        PointRef::P2 { .. } => return None,
    }
    Some(())
}

/// The direction of a line (start minus end) or the N axis of a normal or workplane, in
/// space, with its partials (`points::direction`).
fn direction(ent: &Ent, x: &[f64], k: &[[f64; 4]]) -> Option<Lin> {
    let mut out = Lin::new([0.0; 3]);
    match ent {
        Ent::Line(l) => {
            point(&l[0], x, k, 1.0, &mut out)?;
            point(&l[1], x, k, -1.0, &mut out)?;
        }
        Ent::Normal(n) => {
            let (q, dq) = normal(n, x, k);
            out.v = n_axis(q);
            let dn = axes_partials(q, [0.0, 0.0, 1.0]);
            for (s, dqi) in dq {
                // dN/dq_i = sum_j dN/dQ_j dQ_j/dq_i.
                let mut d = [0.0; 3];
                for (j, dnj) in dn.iter().enumerate() {
                    for c in 0..3 {
                        d[c] += dnj[c] * dqi[j];
                    }
                }
                out.push(s, d);
            }
        }
        Ent::Workplane(f) => {
            let q = quat(x, f.q);
            out.v = n_axis(q);
            for (&s, d) in f.q.iter().zip(axes_partials(q, [0.0, 0.0, 1.0])) {
                out.push(s, d);
            }
        }
        _ => return None,
    }
    Some(out)
}

/// Whether `e` reads a point or normal carried by a pose (or a translation).
fn reads_carried(e: &Equation) -> bool {
    let point = |p: &PointRef| matches!(p, PointRef::Moved { .. } | PointRef::Shifted { .. });
    e.pts.iter().flatten().any(point)
        || e.ents.iter().any(|ent| match ent {
            Ent::Point(p) => point(p),
            Ent::Normal(n) => matches!(n, NormalRef::Turned { .. }),
            Ent::Line(l) => l.iter().any(point),
            _ => false,
        })
}

/// A positive finite length, by which the quotients can divide.
fn usable(d: f64) -> bool {
    d > 0.0 && d.is_finite()
}

/// Residuals and Jacobian (row-major over `active`, as in [`Equation::jacobian_active`]) of
/// the equations this file writes out; false for any other, or when `active` is empty (the
/// residuals alone are the generic evaluation).
pub(super) fn jacobian(
    e: &Equation,
    x: &[f64],
    active: &[u16],
    res: &mut [f64],
    jac: &mut [f64],
) -> bool {
    use ConstraintKind as K;
    if active.is_empty() || e.wp.is_some() {
        return false;
    }
    #[cfg(test)]
    if DUAL_ONLY.with(std::cell::Cell::get) {
        return false;
    }
    // Plain points and normals keep the dual numbers: the solve of an impossible assembly
    // is done again on them (see `solve::solve_values_checked`), and the conflict it names
    // is read at a least-squares point that the last bits of the derivatives can move. A
    // quaternion's unit length is the exception: its derivative, `2 q`, is the same to the
    // bit either way.
    if e.kind != EqKind::UnitQuaternion && !reads_carried(e) {
        return false;
    }
    let k = &e.consts[..];
    // Each slot's column among `active` (or none), and the rows the equation will have:
    // partials are added straight into the Jacobian, in the order they come, from +0.0 (as the
    // dual numbers leave a slot the equation does not read).
    if x.len() > MAX_LOCALS {
        return false;
    }
    let mut col = [NONE; MAX_LOCALS];
    for (c, &s) in active.iter().enumerate() {
        col[s as usize] = c as u8;
    }
    let rows = match e.kind {
        EqKind::Constraint(K::PointsCoincident) => 3,
        EqKind::Constraint(K::Parallel) => 2,
        EqKind::Constraint(K::Perpendicular | K::ProjPtDistance) | EqKind::UnitQuaternion => 1,
        _ => return false,
    };
    let na = active.len();
    if jac.len() < rows * na || res.len() < rows {
        return false;
    }
    jac[..rows * na].fill(0.0);
    let mut put = |r: usize, s: Slot, v: f64| {
        let c = col[s as usize];
        if c != NONE {
            jac[r * na + c as usize] += v;
        }
    };
    match e.kind {
        EqKind::Constraint(K::PointsCoincident) => {
            let mut d = Lin::new([0.0; 3]);
            let (Some(a), Some(b)) = (e.pts[0].as_ref(), e.pts[1].as_ref()) else {
                return false;
            };
            if point(a, x, k, 1.0, &mut d).is_none() || point(b, x, k, -1.0, &mut d).is_none() {
                return false;
            }
            for r in 0..3 {
                for &(s, v) in d.partials() {
                    put(r, s, v[r]);
                }
            }
        }
        EqKind::Constraint(K::Parallel | K::Perpendicular) => {
            let (Some(a), Some(b)) = (direction(e.ent(0), x, k), direction(e.ent(1), x, k)) else {
                return false;
            };
            let (na2, nb2) = (dot(a.v, a.v), dot(b.v, b.v));
            let (na, nb) = (na2.sqrt(), nb2.sqrt());
            if !usable(na * nb) {
                return false;
            }
            let f = 1.0 / (na * nb);
            if e.kind == EqKind::Constraint(K::Perpendicular) {
                // cos = a.b f: d cos = (da.b + a.db) f - cos (a.da / |a|² + b.db / |b|²).
                let cos = dot(a.v, b.v) * f;
                for &(s, da) in a.partials() {
                    put(0, s, dot(da, b.v) * f - cos * dot(a.v, da) / na2);
                }
                for &(s, db) in b.partials() {
                    put(0, s, dot(a.v, db) * f - cos * dot(b.v, db) / nb2);
                }
            } else {
                // c = (a x b) f, two of its components (`points::push_across`):
                // dc = (da x b + a x db) f - c (a.da / |a|² + b.db / |b|²).
                let p = cross(a.v, b.v);
                let c = p.map(|v| v * f);
                let skip = dominant_axis(Vec3::new(a.v[0], a.v[1], a.v[2])) as usize;
                let keep = match skip {
                    0 => [1, 2],
                    1 => [0, 2],
                    _ => [0, 1],
                };
                let mut add = |s: Slot, dp: [f64; 3], dn: f64| {
                    for (r, &i) in keep.iter().enumerate() {
                        put(r, s, dp[i] * f - c[i] * dn);
                    }
                };
                for &(s, da) in a.partials() {
                    add(s, cross(da, b.v), dot(a.v, da) / na2);
                }
                for &(s, db) in b.partials() {
                    add(s, cross(a.v, db), dot(b.v, db) / nb2);
                }
            }
        }
        EqKind::Constraint(K::ProjPtDistance) => {
            // (p1 - p0).dir / |dir| - val.
            let (Some(p0), Some(p1)) = (e.pts[0].as_ref(), e.pts[1].as_ref()) else {
                return false;
            };
            let mut d = Lin::new([0.0; 3]);
            if point(p1, x, k, 1.0, &mut d).is_none() || point(p0, x, k, -1.0, &mut d).is_none() {
                return false;
            }
            let Some(dir) = direction(e.ent(0), x, k) else {
                return false;
            };
            let n2 = dot(dir.v, dir.v);
            let n = n2.sqrt();
            if !usable(n) {
                return false;
            }
            let h = dot(d.v, dir.v) / n;
            for &(s, dd) in d.partials() {
                put(0, s, dot(dd, dir.v) / n);
            }
            // d (d.dir / |dir|) / d dir = d / |dir| - h dir / |dir|².
            for &(s, dv) in dir.partials() {
                put(0, s, dot(d.v, dv) / n - h * dot(dir.v, dv) / n2);
            }
        }
        EqKind::UnitQuaternion => {
            let Ent::Normal(q) = e.ent(0) else {
                return false;
            };
            let (v, dq) = normal(q, x, k);
            for (s, d) in dq {
                put(
                    0,
                    s,
                    2.0 * (v[0] * d[0] + v[1] * d[1] + v[2] * d[2] + v[3] * d[3]),
                );
            }
        }
        _ => return false,
    }
    let mut out = Rows::new();
    e.eval(x, &mut out);
    if out.n != rows {
        return false;
    }
    res[..rows].copy_from_slice(&out.v[..rows]);
    true
}
