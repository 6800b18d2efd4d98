//! Normals: equal orientation, the unit length of a 3D normal's quaternion, and the rigid motions
//! of linked parts (moved points and rotated normals).

use super::fixture::{
    arr, axis_angle, compile, rank, v3, Break, Built, Case, Expect, Form, Fx, Target, FIXED, MOVING,
};
use std::f64::consts::FRAC_PI_2;

use crate::geom::Quat;
use crate::model::ConstraintKind as K;
use Form::{Free, Plane};

fn quat(q: [f64; 4]) -> Quat<f64> {
    Quat {
        w: q[0],
        x: q[1],
        y: q[2],
        z: q[3],
    }
}

/// Normal A (fixed: a 3D normal, or the 2D normal of the workplane) and normal B (moving, a
/// copy of A's quaternion).
fn same_pair(fx: &mut Fx, f: Form) -> (u32, u32, [f64; 4]) {
    let (a, q) = if f == Free {
        let q = axis_angle([1.0, 2.0, -1.0], 0.9);
        (fx.normal3(FIXED, q), q)
    } else {
        let ps = fx.params(fx.normal_of(fx.wp));
        let q = [0, 1, 2, 3].map(|i| fx.value(ps[i]));
        (fx.normal2(fx.wp), q)
    };
    (a, fx.normal3(MOVING, q), q)
}

pub(super) fn cases() -> Vec<Case> {
    vec![
        Case {
            name: "same_orientation",
            kind: Some(K::SameOrientation),
            forms: &[Free, Plane],
            build: |fx, f| {
                let (a, b, q) = same_pair(fx, f);
                // B turned by 0.4 rad about its own U: N_a x N_b = sin(0.4) U_a, less its
                // component along N_a's dominant axis, and U_a stays perpendicular to V_b.
                let turned = quat(q).times(quat(axis_angle([1.0, 0.0, 0.0], 0.4)));
                let ps = fx.params(b);
                let brk = vec![
                    (ps[0], turned.w),
                    (ps[1], turned.x),
                    (ps[2], turned.y),
                    (ps[3], turned.z),
                ];
                let (u, n) = (quat(q).u().scale(0.4f64.sin()), quat(q).n());
                let a_n = [n.x.abs(), n.y.abs(), n.z.abs()];
                let skip = (0..3).fold(0, |m, i| if a_n[i] > a_n[m] { i } else { m });
                let mut want: Vec<f64> = (0..3).filter(|&i| i != skip).map(|i| u.at(i)).collect();
                want.push(0.0);
                let c = fx.con(K::SameOrientation, f).with_entities([a, b, 0, 0]);
                Built::new(c, Break::Set(brk), Expect::Rows(want))
            },
        },
        Case {
            name: "unit_quaternion",
            kind: None,
            forms: &[Free],
            build: |fx, _| {
                let q = axis_angle([0.2, -1.0, 0.4], 1.3);
                let h = fx.normal3(MOVING, q);
                let w = fx.params(h)[0];
                Built {
                    target: Target::Entity(h),
                    brk: Break::Set(vec![(w, q[0] + 0.1)]),
                    expect: Expect::Rows(vec![0.2 * q[0] + 0.01]),
                }
            },
        },
        Case {
            // A linked part's point: at t + q p0 q*. Moving t along x by 0.5 leaves the point
            // 0.5 behind in x.
            name: "point_n_rot_trans",
            kind: None,
            forms: &[Free],
            build: |fx, _| {
                let q = axis_angle([0.4, 1.0, -0.3], 0.9);
                let t = [1.5, -0.5, 2.0];
                let (th, rot) = fx.motion(MOVING, t, q);
                let base = [0.7, -1.2, 0.4];
                let r = quat(q);
                let at = v3(t)
                    .plus(r.u().scale(base[0]))
                    .plus(r.v().scale(base[1]))
                    .plus(r.n().scale(base[2]));
                let h = fx.moved_point(MOVING, arr(at), base, th, rot);
                Built {
                    target: Target::Entity(h),
                    brk: Break::Set(vec![(th[0], t[0] + 0.5)]),
                    expect: Expect::Rows(vec![-0.5, 0.0, 0.0]),
                }
            },
        },
        Case {
            // A linked part's normal: q q0. Raising its own w by 0.1 leaves it 0.1 off in w.
            name: "normal_n_rot",
            kind: None,
            forms: &[Free],
            build: |fx, _| {
                let q = axis_angle([0.4, 1.0, -0.3], 0.9);
                let (_, rot) = fx.motion(MOVING, [0.0; 3], q);
                let base = axis_angle([1.0, -0.5, 0.2], 2.1);
                let at = quat(q).times(quat(base));
                let at = [at.w, at.x, at.y, at.z];
                let h = fx.rotated_normal(MOVING, at, base, rot);
                let w = fx.params(h)[0];
                Built {
                    target: Target::Entity(h),
                    brk: Break::Set(vec![(w, at[0] + 0.1)]),
                    expect: Expect::Rows(vec![0.1, 0.0, 0.0, 0.0]),
                }
            },
        },
    ]
}

#[test]
fn orientation_family_residuals_derivatives_and_solves() {
    super::check_family(&cases());
}

#[test]
fn same_orientation_accepts_the_negated_quaternion_and_quarter_turns_and_removes_three_freedoms() {
    // SolveSpace's meaning: N axes parallel, and U of A perpendicular to V or to U of B.
    let mut fx = Fx::new();
    let (a, b, q) = same_pair(&mut fx, Free);
    let ps = fx.params(b);
    let negated: Vec<(u32, f64)> = ps.iter().zip(q).map(|(&p, v)| (p, -v)).collect();
    let quarter = quat(q).times(quat(axis_angle([0.0, 0.0, 1.0], FRAC_PI_2)));
    let quarter = [quarter.w, quarter.x, quarter.y, quarter.z];
    let quarter: Vec<(u32, f64)> = ps.iter().zip(quarter).map(|(&p, v)| (p, v)).collect();
    let c = fx.con(K::SameOrientation, Free).with_entities([a, b, 0, 0]);
    for values in [vec![], negated, quarter] {
        fx.set(&values);
        let one = compile(&fx.sys, &c);
        let x = one.x(&fx.sys);
        let (res, jac) = one.jacobian(&x);
        assert!(res.iter().all(|r| r.abs() < 1e-12), "{res:?}");
        assert_eq!(rank(&jac, x.len(), &one.cols(&fx.sys, b)), 3);
    }
}
