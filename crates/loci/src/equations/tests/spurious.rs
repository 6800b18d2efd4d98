//! Constraints in space written as two components of a cross product: no spurious roots.
//!
//! `parallel`, `pt_on_line`, `cubic_line_tangent`, `symmetric` and the axes of
//! `same_orientation` say `v × w = 0` with two rows. Two components of a cross product taken
//! over an axis fixed at the start vanish also when `v` and `w` both turn perpendicular to that
//! axis, whatever the angle between them. Here each equation is compiled where its reference
//! vector runs along one axis, then evaluated where both vectors are perpendicular to that
//! axis and far from parallel (the old spurious root), and at seeded random configurations:
//! the two rows must measure the sine of the angle (or the distance) to within a factor √3.

use super::fixture::{compile, v3, Fx, Rng, FIXED, MOVING};
use super::Form::Free;
use crate::geom::Vec3;
use crate::model::{Constraint, ConstraintKind as K};

/// The norm of the residual rows of `c` at the system's current values, compiled at `start`
/// (parameter, value) pairs applied first and then undone by `now`.
fn rows_norm(fx: &mut Fx, c: &Constraint, start: &[(u32, f64)], now: &[(u32, f64)]) -> f64 {
    fx.set(start);
    let one = compile(&fx.sys, c);
    fx.set(now);
    let r = one.residuals(&one.x(&fx.sys));
    assert_eq!(r.len(), 2, "{}: two rows in space", c.kind);
    r.iter().map(|v| v * v).sum::<f64>().sqrt()
}

/// Sets the two points of line `l` to `a` and `a + d`.
fn place_line(fx: &Fx, l: u32, a: [f64; 3], d: [f64; 3]) -> Vec<(u32, f64)> {
    let mut out = Vec::new();
    for (i, p) in [a, [a[0] + d[0], a[1] + d[1], a[2] + d[2]]]
        .iter()
        .enumerate()
    {
        let pt = fx.point_of(l, i);
        out.extend(fx.params(pt).into_iter().zip(p.iter().copied()));
    }
    out
}

fn sine(a: [f64; 3], b: [f64; 3]) -> f64 {
    let (a, b) = (v3(a), v3(b));
    a.cross(b).norm() / (a.norm() * b.norm())
}

fn random_dir(rng: &mut Rng) -> [f64; 3] {
    [
        rng.signed(0.0, 2.0),
        rng.signed(0.0, 2.0),
        rng.signed(0.0, 2.0),
    ]
}

/// Directions perpendicular to axis `k`, 90 degrees apart: the old spurious root.
fn across(k: usize) -> ([f64; 3], [f64; 3]) {
    let (i, j) = ((k + 1) % 3, (k + 2) % 3);
    let (mut a, mut b) = ([0.0; 3], [0.0; 3]);
    (a[i], b[j]) = (1.5, 2.0);
    (a, b)
}

fn unit(k: usize) -> [f64; 3] {
    let mut v = [0.0; 3];
    v[k] = 1.0;
    v
}

#[test]
fn parallel_in_space_has_no_spurious_root() {
    let mut fx = Fx::new();
    let a = fx.line(MOVING, Free, [0.0; 3], [1.0, 0.0, 0.0]);
    let b = fx.line(MOVING, Free, [1.0, 1.0, 1.0], [2.0, 1.0, 1.0]);
    let c = fx.con(K::Parallel, Free).with_entities([a, b, 0, 0]);
    let mut rng = Rng::new(7);
    for k in 0..3 {
        let start = [
            place_line(&fx, a, [0.0; 3], unit(k)),
            place_line(&fx, b, [1.0; 3], unit(k)),
        ]
        .concat();
        let (da, db) = across(k);
        let now = [
            place_line(&fx, a, [0.0; 3], da),
            place_line(&fx, b, [1.0; 3], db),
        ]
        .concat();
        let n = rows_norm(&mut fx, &c, &start, &now);
        assert!(
            n >= 1.0 / 3f64.sqrt() - 1e-12,
            "axis {k}: lines 90 degrees apart give {n}"
        );
        for _ in 0..200 {
            let (da, db) = (random_dir(&mut rng), random_dir(&mut rng));
            let now = [
                place_line(&fx, a, [0.0; 3], da),
                place_line(&fx, b, [1.0; 3], db),
            ]
            .concat();
            let n = rows_norm(&mut fx, &c, &start, &now);
            let s = sine(da, db);
            assert!(
                n >= s / 3f64.sqrt() - 1e-12 && n <= s + 1e-12,
                "{da:?} {db:?}: {n} for sine {s}"
            );
        }
    }
}

#[test]
fn pt_on_line_in_space_has_no_spurious_root() {
    let mut fx = Fx::new();
    let l = fx.line(MOVING, Free, [0.0; 3], [1.0, 0.0, 0.0]);
    let p = fx.pt(MOVING, Free, [0.5, 0.0, 0.0]);
    let c = fx
        .con(K::PtOnLine, Free)
        .with_points(p, 0)
        .with_entities([l, 0, 0, 0]);
    let pp = fx.params(p);
    let at = |q: [f64; 3]| pp.iter().copied().zip(q).collect::<Vec<_>>();
    let mut rng = Rng::new(11);
    for k in 0..3 {
        let start = [place_line(&fx, l, [0.0; 3], unit(k)), at(unit(k))].concat();
        // The line turned perpendicular to axis k, the point 5 off it, also off axis k.
        let (d, off) = across(k);
        let q = [off[0] * 2.5, off[1] * 2.5, off[2] * 2.5];
        let now = [place_line(&fx, l, [0.0; 3], d), at(q)].concat();
        let n = rows_norm(&mut fx, &c, &start, &now);
        assert!(
            n >= 5.0 / 3f64.sqrt() - 1e-9,
            "axis {k}: a point 5 off gives {n}"
        );
        for _ in 0..200 {
            let (o, d, q) = (
                random_dir(&mut rng),
                random_dir(&mut rng),
                random_dir(&mut rng),
            );
            let now = [place_line(&fx, l, o, d), at(q)].concat();
            let n = rows_norm(&mut fx, &c, &start, &now);
            let rel = v3(q).minus(v3(o));
            let dist = v3(d).cross(rel).norm() / v3(d).norm();
            assert!(
                n >= dist / 3f64.sqrt() - 1e-12 && n <= dist + 1e-12,
                "{n} for {dist}"
            );
        }
    }
}

#[test]
fn cubic_line_tangent_in_space_has_no_spurious_root() {
    let mut fx = Fx::new();
    let cu = fx.cubic(
        MOVING,
        Free,
        [[0.0; 3], [1.0, 0.0, 0.0], [2.0, 1.0, 0.0], [3.0, 1.0, 0.0]],
    );
    let l = fx.line(MOVING, Free, [0.0; 3], [1.0, 0.0, 0.0]);
    let c = fx
        .con(K::CubicLineTangent, Free)
        .with_entities([cu, l, 0, 0]);
    let p1 = fx.params(fx.point_of(cu, 1));
    let ctrl = |q: [f64; 3]| p1.iter().copied().zip(q).collect::<Vec<_>>();
    for k in 0..3 {
        let start = [ctrl(unit(k)), place_line(&fx, l, [0.0; 3], unit(k))].concat();
        let (t, d) = across(k);
        let now = [ctrl(t), place_line(&fx, l, [0.0; 3], d)].concat();
        let n = rows_norm(&mut fx, &c, &start, &now);
        assert!(n >= 1.0 / 3f64.sqrt() - 1e-12, "axis {k}: {n}");
    }
}

#[test]
fn symmetric_in_space_has_no_spurious_root() {
    // Points mirrored about a plane: the segment between them must follow the normal. Move the
    // second point sideways, perpendicular to the normal: the rows must see it.
    let mut fx = Fx::new();
    for k in 0..3 {
        let mut q = [1.0, 0.0, 0.0, 0.0];
        // Normal along x, y or z: a quarter turn about y takes z to x, about x takes z to -y.
        match k {
            0 => q = [0.5f64.sqrt(), 0.0, 0.5f64.sqrt(), 0.0],
            1 => q = [0.5f64.sqrt(), 0.5f64.sqrt(), 0.0, 0.0],
            _ => {}
        }
        let plane = fx.workplane(FIXED, [0.0; 3], q);
        let n = fx.frame(plane)[3];
        let a = fx.p3(MOVING, [n.x, n.y, n.z]);
        let b = fx.p3(MOVING, [-n.x, -n.y, -n.z]);
        let c = fx
            .con(K::Symmetric, Free)
            .with_points(a, b)
            .with_entities([plane, 0, 0, 0]);
        let (side, _) = across(k);
        let pb = fx.params(b);
        let moved: Vec<(u32, f64)> = pb
            .iter()
            .copied()
            .zip([side[0] - n.x, side[1] - n.y, side[2] - n.z])
            .collect();
        let one = compile(&fx.sys, &c);
        fx.set(&moved);
        let r = one.residuals(&one.x(&fx.sys));
        let norm = r[1..].iter().map(|v| v * v).sum::<f64>().sqrt();
        assert!(
            norm > 0.5,
            "normal along axis {k}: a sideways offset of 1.5 gives {r:?}"
        );
    }
}

#[test]
fn same_orientation_axes_have_no_spurious_root() {
    // Two normals whose N axes are 90 degrees apart, both perpendicular to the axis that was
    // dominant at the start.
    let mut fx = Fx::new();
    let a = fx.normal3(MOVING, [1.0, 0.0, 0.0, 0.0]);
    let b = fx.normal3(MOVING, [1.0, 0.0, 0.0, 0.0]);
    let c = fx.con(K::SameOrientation, Free).with_entities([a, b, 0, 0]);
    let h = 0.5f64.sqrt();
    // N of a quaternion turned a quarter about x is -y; about y it is x.
    let set = |fx: &mut Fx, e: u32, q: [f64; 4]| {
        let v: Vec<(u32, f64)> = fx.params(e).into_iter().zip(q).collect();
        fx.set(&v);
    };
    let one = compile(&fx.sys, &c);
    set(&mut fx, a, [h, h, 0.0, 0.0]);
    set(&mut fx, b, [h, 0.0, h, 0.0]);
    let r = one.residuals(&one.x(&fx.sys));
    let na: Vec3<f64> = v3([0.0, -1.0, 0.0]);
    let nb: Vec3<f64> = v3([1.0, 0.0, 0.0]);
    assert!(na.cross(nb).norm() > 0.99);
    let axes = r[..2].iter().map(|v| v * v).sum::<f64>().sqrt();
    assert!(
        axes >= 1.0 / 3f64.sqrt() - 1e-12,
        "N axes 90 degrees apart: {r:?}"
    );
}
