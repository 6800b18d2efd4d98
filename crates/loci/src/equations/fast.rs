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
