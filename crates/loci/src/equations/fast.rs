//! Hand-written derivatives for the equations large sketches are made of: a distance between
//! two points of a workplane, and the angle between two lines of it. Every Newton iteration
//! differentiates every equation, and for these two the dual numbers cost some thirty times
//! the arithmetic written out here. The generic path stays the definition: tests check that
//! both give the same residuals and derivatives.

use super::lines::target;
use super::refs::{Ent, Frame, PointRef, Slot};
use super::{EqKind, Equation};
use crate::model::ConstraintKind;

/// Residual and Jacobian (with respect to the slots in `active`, row-major as in
/// [`Equation::jacobian_active`]) when `e` has a written-out derivative; false otherwise.
pub(super) fn jacobian(
    e: &Equation,
    x: &[f64],
    active: &[u16],
    res: &mut [f64],
    jac: &mut [f64],
) -> bool {
    let Some(wp) = e.wp.as_ref() else {
        return false;
    };
    match e.kind {
        EqKind::Constraint(ConstraintKind::PtPtDistance) => {
            let (Some(a), Some(b)) = (native(e.pts[0].as_ref(), wp), native(e.pts[1].as_ref(), wp))
            else {
                return false;
            };
            let (dx, dy) = (
                x[a[0] as usize] - x[b[0] as usize],
                x[a[1] as usize] - x[b[1] as usize],
            );
            let n = (dx * dx + dy * dy + 0.0).sqrt();
            res[0] = n - e.val;
            // At zero length the derivative does not exist; like the dual numbers, report none.
            let (gx, gy) = if n > 0.0 {
                (dx / n, dy / n)
            } else {
                (0.0, 0.0)
            };
            scatter(
                &[(a[0], gx), (a[1], gy), (b[0], -gx), (b[1], -gy)],
                active,
                jac,
            );
            true
        }
        EqKind::Constraint(ConstraintKind::Angle) => {
            let (Some(Ent::Line(l0)), Some(Ent::Line(l1))) = (e.ents.first(), e.ents.get(1)) else {
                return false;
            };
            let (Some(p0), Some(p1), Some(q0), Some(q1)) = (
                native(Some(&l0[0]), wp),
                native(Some(&l0[1]), wp),
                native(Some(&l1[0]), wp),
                native(Some(&l1[1]), wp),
            ) else {
                return false;
            };
            let v = |s: Slot| x[s as usize];
            // Directions start minus end, as the generic equation takes them.
            let (ax, ay) = (v(p0[0]) - v(p1[0]), v(p0[1]) - v(p1[1]));
            let (bx, by) = (v(q0[0]) - v(q1[0]), v(q0[1]) - v(q1[1]));
            let t = target(e);
            let t = if e.choice == 1 { -t } else { t };
            let (c, s) = (ax * bx + ay * by + 0.0 * 0.0, ax * by - ay * bx);
            let (st, ct) = (t.sin(), t.cos());
            let (num, den) = (s * ct - c * st, c * ct + s * st);
            res[0] = num.atan2(den);
            let r2 = num * num + den * den;
            if r2 == 0.0 {
                scatter(&[], active, jac);
                return true;
            }
            // d atan2(num, den) = (den dnum - num dden) / r2, with dnum = ds ct - dc st and
            // dden = dc ct + ds st; then through c = a.b and s = a x b to the coordinates.
            let (kc, ks) = ((-den * st - num * ct) / r2, (den * ct - num * st) / r2);
            let (gax, gay) = (kc * bx + ks * by, kc * by - ks * bx);
            let (gbx, gby) = (kc * ax - ks * ay, kc * ay + ks * ax);
            scatter(
                &[
                    (p0[0], gax),
                    (p0[1], gay),
                    (p1[0], -gax),
                    (p1[1], -gay),
                    (q0[0], gbx),
                    (q0[1], gby),
                    (q1[0], -gbx),
                    (q1[1], -gby),
                ],
                active,
                jac,
            );
            true
        }
        _ => false,
    }
}

/// The (u, v) slots of a point given in workplane `wp` itself.
fn native(p: Option<&PointRef>, wp: &Frame) -> Option<[Slot; 2]> {
    match p? {
        PointRef::P2 { wp: own, uv } if own.id == wp.id => Some(*uv),
        _ => None,
    }
}

/// Writes the one-row Jacobian: the sum of the partials given per slot, for each active slot.
fn scatter(partials: &[(Slot, f64)], active: &[u16], jac: &mut [f64]) {
    for (k, &s) in active.iter().enumerate() {
        jac[k] = partials
            .iter()
            .filter(|p| p.0 == s)
            .map(|p| p.1)
            .sum::<f64>();
    }
}

#[cfg(test)]
mod tests {
    use super::super::compile::resolve_constraint;
    use super::super::refs::Resolver;
    use crate::model::{Constraint, ConstraintKind as K, Entity, GroupId, Param, System};
    use proptest::prelude::*;

    /// The xy workplane (entity 3, group 1) and `pts` points in it (group 2): point `i` is
    /// entity `10 + i` with parameters `100 + 2i`, `101 + 2i`.
    fn plane_with_points(pts: &[[f64; 2]]) -> System {
        let mut s = System::new();
        for (h, v) in [
            (1, 0.0),
            (2, 0.0),
            (3, 0.0),
            (4, 1.0),
            (5, 0.0),
            (6, 0.0),
            (7, 0.0),
        ] {
            s.add_param(Param::new(h, 1, v)).unwrap();
        }
        s.add_entity(Entity::point_3d(1, 1, [1, 2, 3])).unwrap();
        s.add_entity(Entity::normal_3d(2, 1, [4, 5, 6, 7])).unwrap();
        s.add_entity(Entity::workplane(3, 1, 1, 2)).unwrap();
        for (i, p) in pts.iter().enumerate() {
            let (h, e) = (100 + 2 * i as u32, 10 + i as u32);
            s.add_param(Param::new(h, 2, p[0])).unwrap();
            s.add_param(Param::new(h + 1, 2, p[1])).unwrap();
            s.add_entity(Entity::point_2d(e, 2, 3, [h, h + 1])).unwrap();
        }
        s
    }

    /// Residual and Jacobian of `c` over its unknown slots, written out and by dual numbers.
    fn both(s: &System, c: &Constraint) -> ([f64; 2], Vec<f64>, Vec<f64>) {
        s.validate().unwrap();
        let (eq, l) = resolve_constraint(&Resolver::new(s), c).unwrap();
        let x: Vec<f64> = l
            .params
            .iter()
            .map(|&p| s.params()[p as usize].val)
            .collect();
        let active: Vec<u16> = (0..x.len() as u16)
            .filter(|&k| s.params()[l.params[k as usize] as usize].group == GroupId(2))
            .collect();
        let (mut r1, mut r2) = ([0.0], [0.0]);
        let (mut j1, mut j2) = (vec![0.0; active.len()], vec![0.0; active.len()]);
        assert!(
            super::jacobian(&eq, &x, &active, &mut r1, &mut j1),
            "fast path taken"
        );
        eq.jacobian_dual(&x, &active, &mut r2, &mut j2);
        ([r1[0], r2[0]], j1, j2)
    }

    fn assert_same(([r1, r2], j1, j2): ([f64; 2], Vec<f64>, Vec<f64>)) {
        assert!(
            (r1 - r2).abs() <= 1e-12 * (1.0 + r2.abs()),
            "residual {r1} vs {r2}"
        );
        assert_eq!(j1.len(), j2.len());
        for (a, b) in j1.iter().zip(&j2) {
            assert!((a - b).abs() <= 1e-12 * (1.0 + b.abs()), "{j1:?} vs {j2:?}");
        }
    }

    fn coord() -> impl Strategy<Value = [f64; 2]> {
        [-50.0..50.0f64, -50.0..50.0f64]
    }

    proptest! {
        #[test]
        fn distance_matches_dual_numbers(a in coord(), b in coord(), d in 0.0..30.0f64) {
            let s = plane_with_points(&[a, b]);
            let c = Constraint::new(1, 2, K::PtPtDistance)
                .in_workplane(Some(3))
                .with_points(10, 11)
                .with_val(d);
            assert_same(both(&s, &c));
        }

        #[test]
        fn angle_matches_dual_numbers(
            p in proptest::collection::vec(coord(), 4),
            deg in 0.0..180.0f64,
            other: bool,
            shared: bool,
            choice in 0u8..2,
        ) {
            let mut s = plane_with_points(&p);
            // With `shared`, both lines start at the same point entity: slots feed twice.
            let second_start = if shared { 10 } else { 12 };
            s.add_entity(Entity::line(20, 2, Some(3), 10, 11)).unwrap();
            s.add_entity(Entity::line(21, 2, Some(3), second_start, 13)).unwrap();
            let c = Constraint::new(1, 2, K::Angle)
                .in_workplane(Some(3))
                .with_entities([20, 21, 0, 0])
                .with_val(deg)
                .with_flags(other, false);
            s.validate().unwrap();
            let (mut eq, l) = resolve_constraint(&Resolver::new(&s), &c).unwrap();
            eq.choice = choice;
            let x: Vec<f64> = l.params.iter().map(|&q| s.params()[q as usize].val).collect();
            let active: Vec<u16> = (0..x.len() as u16)
                .filter(|&k| s.params()[l.params[k as usize] as usize].group == GroupId(2))
                .collect();
            let (mut r1, mut r2) = ([0.0], [0.0]);
            let (mut j1, mut j2) = (vec![0.0; active.len()], vec![0.0; active.len()]);
            prop_assert!(super::jacobian(&eq, &x, &active, &mut r1, &mut j1));
            eq.jacobian_dual(&x, &active, &mut r2, &mut j2);
            assert_same(([r1[0], r2[0]], j1, j2));
        }
    }

    #[test]
    fn zero_length_distance_has_no_derivative_like_the_dual_numbers() {
        let s = plane_with_points(&[[1.0, 2.0], [1.0, 2.0]]);
        let c = Constraint::new(1, 2, K::PtPtDistance)
            .in_workplane(Some(3))
            .with_points(10, 11)
            .with_val(3.0);
        let (r, j1, j2) = both(&s, &c);
        assert_eq!(r, [-3.0, -3.0]);
        assert_eq!(j1, vec![0.0; 4]);
        assert_eq!(j1, j2);
    }

    #[test]
    fn points_outside_the_workplane_take_the_generic_path() {
        let mut s = plane_with_points(&[[0.0, 0.0]]);
        for (h, v) in [(200, 1.0), (201, 2.0), (202, 3.0)] {
            s.add_param(Param::new(h, 2, v)).unwrap();
        }
        s.add_entity(Entity::point_3d(30, 2, [200, 201, 202]))
            .unwrap();
        let c = Constraint::new(1, 2, K::PtPtDistance)
            .in_workplane(Some(3))
            .with_points(10, 30)
            .with_val(1.0);
        let (eq, l) = resolve_constraint(&Resolver::new(&s), &c).unwrap();
        let x: Vec<f64> = l
            .params
            .iter()
            .map(|&p| s.params()[p as usize].val)
            .collect();
        let (mut r, mut j) = ([0.0], vec![0.0; x.len()]);
        let all: Vec<u16> = (0..x.len() as u16).collect();
        assert!(!super::jacobian(&eq, &x, &all, &mut r, &mut j));
    }
}
