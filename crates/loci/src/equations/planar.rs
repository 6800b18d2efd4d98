//! Equations that never read their workplane: a distance between two points of the workplane,
//! the angle between two of its lines, an arc's diameter, its equal radii, its tangency to a
//! line of its plane. Written in the workplane's own coordinates, they depend on the points'
//! `(u, v)` alone (the workplane is rigid), so its origin and orientation, seven parameters,
//! need not be among their locals: every evaluation gathers four to ten values instead of
//! eleven to seventeen, and the structure of the solve is smaller.

use super::refs::{Ent, Frame, Locals, PointRef, Slot};
use super::{EqKind, Equation};
use crate::model::{ConstraintKind, EntityId};

/// A slot no value is gathered for: the workplane of a planar equation, which it never reads.
const UNREAD: Slot = Slot::MAX;

/// The workplane `eq` is written in, when it reads nothing but the `(u, v)` of points of it.
fn planar(eq: &Equation) -> Option<EntityId> {
    let in_wp = |p: &PointRef, id: EntityId| matches!(p, PointRef::P2 { wp, .. } if wp.id == id);
    let no_pts = eq.pts.iter().all(Option::is_none);
    // An arc's own workplane, when the constraint names none or the same one.
    let arc = |i: usize| -> Option<EntityId> {
        match eq.ents.get(i)? {
            Ent::Arc {
                center,
                start,
                end,
                wp,
            } if [center, start, end].iter().all(|p| in_wp(p, wp.id))
                && eq.wp.as_ref().is_none_or(|w| w.id == wp.id) =>
            {
                Some(wp.id)
            }
            _ => None,
        }
    };
    let line_in = |i: usize, id: EntityId| matches!(eq.ents.get(i), Some(Ent::Line(l)) if l.iter().all(|p| in_wp(p, id)));
    use ConstraintKind as K;
    match eq.kind {
        EqKind::Constraint(K::PtPtDistance) => {
            let id = eq.wp.as_ref()?.id;
            (eq.ents.is_empty()
                && eq
                    .pts
                    .iter()
                    .all(|p| p.as_ref().is_some_and(|p| in_wp(p, id))))
            .then_some(id)
        }
        EqKind::Constraint(K::Angle) => {
            let id = eq.wp.as_ref()?.id;
            (no_pts && eq.ents.len() == 2 && line_in(0, id) && line_in(1, id)).then_some(id)
        }
        EqKind::Constraint(K::ArcLineTangent) => {
            let id = arc(0)?;
            (no_pts && eq.ents.len() == 2 && line_in(1, id)).then_some(id)
        }
        EqKind::Constraint(K::Diameter) | EqKind::ArcRadii => {
            let id = arc(0)?;
            (no_pts && eq.ents.len() == 1).then_some(id)
        }
        _ => None,
    }
}

/// The workplane `id` of a planar equation: none of its parameters is read.
pub(super) fn unread_frame(id: EntityId) -> Frame {
    Frame {
        id,
        origin: [UNREAD; 3],
        q: [UNREAD; 4],
    }
}

/// For a planar equation, its locals without the workplane's parameters (the equation's
/// slots renumbered to match); `None` for any other equation, which keeps `locals`.
pub(super) fn compact(eq: &mut Equation, locals: &Locals) -> Option<Locals> {
    let id = planar(eq)?;
    let gone = unread_frame(id);
    let mut out = Locals::default();
    let mut renumber = |p: &mut PointRef| {
        if let PointRef::P2 { wp, uv } = p {
            *wp = gone;
            for s in uv {
                *s = out.slot(locals.params[*s as usize] as usize);
            }
        }
    };
    for p in eq.pts.iter_mut().flatten() {
        renumber(p);
    }
    for e in &mut eq.ents {
        match e {
            Ent::Line(l) => l.iter_mut().for_each(&mut renumber),
            Ent::Arc {
                center,
                start,
                end,
                wp,
            } => {
                for p in [center, start, end] {
                    renumber(p);
                }
                *wp = gone;
            }
            _ => {}
        }
    }
    if eq.wp.is_some() {
        eq.wp = Some(gone);
    }
    Some(out)
}
