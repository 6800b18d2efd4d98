//! Equations that never read their workplane: a distance between two points of the workplane,
//! the angle between two of its lines. Written in the workplane's own coordinates, they depend
//! on the points' `(u, v)` alone (the workplane is rigid), so its origin and orientation, seven
//! parameters, need not be among their locals: every evaluation gathers four or eight values
//! instead of eleven or fifteen, and the structure of the solve is smaller.

use super::refs::{Ent, Frame, Locals, PointRef, Slot};
use super::{EqKind, Equation};
use crate::model::ConstraintKind;

/// A slot no value is gathered for: the workplane of a planar equation, which it never reads.
const UNREAD: Slot = Slot::MAX;

/// Whether `eq` reads nothing but the `(u, v)` of points of its own workplane.
fn planar(eq: &Equation) -> bool {
    let Some(wp) = eq.wp.as_ref() else {
        return false;
    };
    let own = |p: &PointRef| matches!(p, PointRef::P2 { wp: w, .. } if w.id == wp.id);
    match eq.kind {
        EqKind::Constraint(ConstraintKind::PtPtDistance) => {
            eq.ents.is_empty() && eq.pts.iter().all(|p| p.as_ref().is_some_and(own))
        }
        EqKind::Constraint(ConstraintKind::Angle) => {
            eq.pts.iter().all(Option::is_none)
                && eq.ents.len() == 2
                && eq
                    .ents
                    .iter()
                    .all(|e| matches!(e, Ent::Line(l) if l.iter().all(own)))
        }
        _ => false,
    }
}

/// For a planar equation, its locals without the workplane's parameters (the equation's
/// slots renumbered to match); `None` for any other equation, which keeps `locals`.
pub(super) fn compact(eq: &mut Equation, locals: &Locals) -> Option<Locals> {
    if !planar(eq) {
        return None;
    }
    let wp = eq.wp.as_ref()?;
    let gone = Frame {
        id: wp.id,
        origin: [UNREAD; 3],
        q: [UNREAD; 4],
    };
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
        if let Ent::Line(l) = e {
            l.iter_mut().for_each(&mut renumber);
        }
    }
    eq.wp = Some(gone);
    Some(out)
}
