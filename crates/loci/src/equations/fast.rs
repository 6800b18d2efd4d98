//! Hand-written derivatives for the equations large sketches are made of: a distance between
//! two points of a workplane, the angle between two lines of it, and the equations of lines
//! joined by tangent arcs (fillets): tangency of an arc and a line, an arc's radius and its
//! equal radii, a point on a line and its distance to it. Every Newton iteration differentiates
//! every equation, and for these the dual numbers cost many times the arithmetic written out
//! here. The generic path stays the definition: tests check that both give the same residuals
//! and derivatives, and each function below falls back to it (returns false) for any
//! configuration it does not cover, degenerate ones included where the generic equation
//! divides by zero.

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
    use ConstraintKind as K;
    match e.kind {
        EqKind::Constraint(K::PtPtDistance) => distance(e, x, active, res, jac),
        EqKind::Constraint(K::Angle) => angle(e, x, active, res, jac),
        EqKind::Constraint(K::ArcLineTangent) => arc_line_tangent(e, x, active, res, jac),
        EqKind::Constraint(K::Diameter) => diameter(e, x, active, res, jac),
        EqKind::ArcRadii => arc_radii(e, x, active, res, jac),
        EqKind::Constraint(K::PtOnLine) => pt_line(e, x, active, res, jac, false),
        EqKind::Constraint(K::PtLineDistance) => pt_line(e, x, active, res, jac, true),
        // In space, on points and normals a pose carries (an assembly's mates).
        EqKind::Constraint(
            K::PointsCoincident | K::Parallel | K::Perpendicular | K::ProjPtDistance,
        )
        | EqKind::UnitQuaternion => super::spatial::jacobian(e, x, active, res, jac),
        // Horizontal and vertical on points of the workplane never reach a kernel of the
        // solve: they are parameter equalities, removed by substitution.
        _ => false,
    }
}

/// `|pt_a - pt_b| - val` in the workplane (`points::pt_pt_distance`).
fn distance(e: &Equation, x: &[f64], active: &[u16], res: &mut [f64], jac: &mut [f64]) -> bool {
    let Some(wp) = e.wp.as_ref() else {
        return false;
    };
    let (Some(a), Some(b)) = (native(e.pts[0].as_ref(), wp), native(e.pts[1].as_ref(), wp)) else {
        return false;
    };
    let (dx, dy) = (
        x[a[0] as usize] - x[b[0] as usize],
        x[a[1] as usize] - x[b[1] as usize],
    );
    let n = len(dx, dy);
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

/// The signed angle between two lines of the workplane minus its target (`lines::angle`).
fn angle(e: &Equation, x: &[f64], active: &[u16], res: &mut [f64], jac: &mut [f64]) -> bool {
    let Some(wp) = e.wp.as_ref() else {
        return false;
    };
    if e.choice == super::lines::COSINE_FORM {
        return false;
    }
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
    let (c, s) = (ax * bx + ay * by + 0.0 * 0.0, ax * by - ay * bx);
    let (st, ct) = angle_sin_cos(e);
    let (num, den) = (s * ct - c * st, c * ct + s * st);
    res[0] = num.atan2(den);
    let r2 = num * num + den * den;
    if r2 == 0.0 {
        // A line of no length: the angle is undefined and does not hold.
        res[0] = super::lines::UNDEFINED_ANGLE;
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

/// The target of a 2D angle with the sign of its branch.
fn signed_target(e: &Equation) -> f64 {
    let t = target(e);
    if e.choice == 1 {
        -t
    } else {
        t
    }
}

/// Computes what the written-out derivatives of `e` can keep between evaluations: for a 2D
/// angle, its signed target with the sine and cosine of it (two of the three transcendental
/// calls of every evaluation), used while the target is that one. Called once the branch is
/// chosen, and again whenever the value changes.
pub(super) fn prepare(e: &mut Equation) {
    if e.kind == EqKind::Constraint(ConstraintKind::Angle) && e.wp.is_some() {
        let t = signed_target(e);
        e.target = [t, t.sin(), t.cos()];
        e.prepared_for = Some((e.val.to_bits(), e.choice, e.other));
    }
}

/// The sine and cosine of a 2D angle's signed target: those [`prepare`] kept while `val`, the
/// branch and `other` are the ones it saw (the same numbers to the bit), computed otherwise.
pub(super) fn angle_sin_cos(e: &Equation) -> (f64, f64) {
    match e.prepared_for {
        Some(seen) if seen == (e.val.to_bits(), e.choice, e.other) => (e.target[1], e.target[2]),
        _ => {
            let t = signed_target(e);
            (t.sin(), t.cos())
        }
    }
}

/// The cosine between an arc's radius at its start (end with `other`) and a line, both in the
/// arc's workplane (`circles::arc_line_tangent`): `f = r.d / (|r| |d|)` with `r` the point
/// minus the centre and `d` the line's end minus its start.
fn arc_line_tangent(
    e: &Equation,
    x: &[f64],
    active: &[u16],
    res: &mut [f64],
    jac: &mut [f64],
) -> bool {
    // The generic equation has a single branch; any other would be a different equation.
    if e.choice != 0 {
        return false;
    }
    let (
        Some(Ent::Arc {
            center,
            start,
            end,
            wp,
        }),
        Some(Ent::Line(l)),
    ) = (e.ents.first(), e.ents.get(1))
    else {
        return false;
    };
    let p = if e.other { end } else { start };
    let (Some(c), Some(p), Some(l0), Some(l1)) = (
        native(Some(center), wp),
        native(Some(p), wp),
        native(Some(&l[0]), wp),
        native(Some(&l[1]), wp),
    ) else {
        return false;
    };
    let v = |s: Slot| x[s as usize];
    let (rx, ry) = (v(p[0]) - v(c[0]), v(p[1]) - v(c[1]));
    let (dx, dy) = (v(l1[0]) - v(l0[0]), v(l1[1]) - v(l0[1]));
    let (nr, nd) = (len(rx, ry), len(dx, dy));
    let den = nr * nd;
    // A zero-length radius or line: the generic quotient is not finite; leave it to it.
    if !usable(den) {
        return false;
    }
    let f = (rx * dx + ry * dy + 0.0) / den;
    res[0] = f;
    // df/dr = d / (|r||d|) - f r / |r|^2, and symmetrically for d.
    let (kr, kd) = (f / (nr * nr), f / (nd * nd));
    let (grx, gry) = (dx / den - kr * rx, dy / den - kr * ry);
    let (gdx, gdy) = (rx / den - kd * dx, ry / den - kd * dy);
    scatter(
        &[
            (p[0], grx),
            (p[1], gry),
            (c[0], -grx),
            (c[1], -gry),
            (l1[0], gdx),
            (l1[1], gdy),
            (l0[0], -gdx),
            (l0[1], -gdy),
        ],
        active,
        jac,
    );
    true
}

/// Twice the radius of a circle (its distance parameter) or of an arc (centre to start, in the
/// arc's workplane) minus `val` (`circles::diameter`).
fn diameter(e: &Equation, x: &[f64], active: &[u16], res: &mut [f64], jac: &mut [f64]) -> bool {
    match e.ents.first() {
        Some(Ent::Circle { radius, .. }) => {
            res[0] = x[*radius as usize] * 2.0 - e.val;
            scatter(&[(*radius, 2.0)], active, jac);
            true
        }
        Some(Ent::Arc {
            center, start, wp, ..
        }) => {
            let (Some(c), Some(s)) = (native(Some(center), wp), native(Some(start), wp)) else {
                return false;
            };
            let (dx, dy) = (
                x[s[0] as usize] - x[c[0] as usize],
                x[s[1] as usize] - x[c[1] as usize],
            );
            let n = len(dx, dy);
            res[0] = n * 2.0 - e.val;
            // At zero radius, no derivative, as with the dual numbers' square root.
            let (gx, gy) = if n > 0.0 {
                (2.0 * (dx / n), 2.0 * (dy / n))
            } else {
                (0.0, 0.0)
            };
            scatter(
                &[(s[0], gx), (s[1], gy), (c[0], -gx), (c[1], -gy)],
                active,
                jac,
            );
            true
        }
        _ => false,
    }
}

/// An arc's implicit equation: `|start - center| - |end - center|` in its workplane
/// (`circles::arc_radii`).
fn arc_radii(e: &Equation, x: &[f64], active: &[u16], res: &mut [f64], jac: &mut [f64]) -> bool {
    let Some(Ent::Arc {
        center,
        start,
        end,
        wp,
    }) = e.ents.first()
    else {
        return false;
    };
    let (Some(c), Some(s), Some(t)) = (
        native(Some(center), wp),
        native(Some(start), wp),
        native(Some(end), wp),
    ) else {
        return false;
    };
    let v = |k: Slot| x[k as usize];
    let (sx, sy) = (v(s[0]) - v(c[0]), v(s[1]) - v(c[1]));
    let (tx, ty) = (v(t[0]) - v(c[0]), v(t[1]) - v(c[1]));
    let (ns, nt) = (len(sx, sy), len(tx, ty));
    res[0] = ns - nt;
    let unit = |dx: f64, dy: f64, n: f64| {
        if n > 0.0 {
            (dx / n, dy / n)
        } else {
            (0.0, 0.0)
        }
    };
    let ((gsx, gsy), (gtx, gty)) = (unit(sx, sy, ns), unit(tx, ty, nt));
    scatter(
        &[
            (s[0], gsx),
            (s[1], gsy),
            (t[0], -gtx),
            (t[1], -gty),
            (c[0], gtx - gsx),
            (c[1], gty - gsy),
        ],
        active,
        jac,
    );
    true
}

/// A point and a line of the workplane, with `d` the line's end minus its start and `q` the
/// point minus the line's start, so that `d x q / |d|` is the point's signed offset from the
/// line: `lines::pt_on_line` (that offset) or, with `distance`, `lines::pt_line_distance`
/// (minus it, minus `val`).
fn pt_line(
    e: &Equation,
    x: &[f64],
    active: &[u16],
    res: &mut [f64],
    jac: &mut [f64],
    distance: bool,
) -> bool {
    // In space the generic equations are others (two rows, or an unsigned distance).
    let Some(wp) = e.wp.as_ref() else {
        return false;
    };
    let Some(Ent::Line(l)) = e.ents.first() else {
        return false;
    };
    let (Some(p), Some(l0), Some(l1)) = (
        native(e.pts[0].as_ref(), wp),
        native(Some(&l[0]), wp),
        native(Some(&l[1]), wp),
    ) else {
        return false;
    };
    let v = |s: Slot| x[s as usize];
    let (dx, dy) = (v(l1[0]) - v(l0[0]), v(l1[1]) - v(l0[1]));
    let (qx, qy) = (v(p[0]) - v(l0[0]), v(p[1]) - v(l0[1]));
    let cz = dx * qy - dy * qx;
    let n = len(dx, dy);
    // A zero-length line: the generic quotient is not finite; leave it to it.
    if !usable(n) {
        return false;
    }
    // The same operations as the generic equations, for the same residual to the last bit.
    let (h, sign) = if distance {
        res[0] = -cz / n - e.val;
        (cz / n, -1.0)
    } else {
        let h = cz * (1.0 / n);
        res[0] = h;
        (h, 1.0)
    };
    // h = cz / |d|: dh/dd = (dcz/dd - h d / |d|) / |d| with dcz/dd = (qy, -qx), and
    // dh/dq = (-dy, dx) / |d|.
    let (gdx, gdy) = (sign * (qy - h * dx / n) / n, sign * (-qx - h * dy / n) / n);
    let (gqx, gqy) = (sign * -dy / n, sign * dx / n);
    scatter(
        &[
            (l1[0], gdx),
            (l1[1], gdy),
            (p[0], gqx),
            (p[1], gqy),
            (l0[0], -gdx - gqx),
            (l0[1], -gdy - gqy),
        ],
        active,
        jac,
    );
    true
}

/// The length of (dx, dy) as the generic code computes the norm of (dx, dy, 0): the `+ 0.0`
/// is its `z * z`, and turns a -0.0 sum into +0.0 as it does.
#[inline]
fn len(dx: f64, dy: f64) -> f64 {
    (dx * dx + dy * dy + 0.0).sqrt()
}

/// A divisor the written-out quotients can use: positive and finite.
#[inline]
fn usable(d: f64) -> bool {
    d > 0.0 && d.is_finite()
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
        // From +0.0, as the dual numbers leave a slot the equation does not read.
        jac[k] = partials
            .iter()
            .filter(|p| p.0 == s)
            .fold(0.0, |sum, p| sum + p.1);
    }
}
