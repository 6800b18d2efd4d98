//! The commonest constraints of a sketch read straight from the model: a horizontal or vertical
//! line, two coincident points, a dragged point, all of them in the constraint's workplane,
//! are equalities between parameters (or a parameter and its value) and become substitution
//! links without resolving the workplane or building an equation. A distance between two of
//! its points and the angle between two of its lines become their (planar) equations the same
//! way. Anything else, including every case that could be an error, takes the general path.

use super::compile::{kernel, Compiled, Link};
use super::refs::{Ent, Locals, PointRef};
use super::{EqKind, Equation, Owner};
use crate::model::{Constraint, ConstraintKind, EntityId, EntityKind, PlaneRule, System};

/// The `(u, v)` parameter positions of point `h` when it is a point of workplane `wp`.
fn uv(sys: &System, h: Option<EntityId>, wp: EntityId) -> Option<[usize; 2]> {
    let e = sys.entity(h?)?;
    match &e.kind {
        EntityKind::PointIn2d { params } if e.workplane == Some(wp) => {
            Some([sys.param_index(params[0])?, sys.param_index(params[1])?])
        }
        _ => None,
    }
}

/// Adds the links (or the planar kernel) of `c` to `out` when it is one of the constraints
/// above; false (and nothing added) otherwise.
pub(super) fn links(
    sys: &System,
    c: &Constraint,
    values: &[f64],
    x: &mut Vec<f64>,
    out: &mut Compiled,
) -> bool {
    use ConstraintKind as K;
    let Some(wp) = c.workplane else {
        return false;
    };
    if !matches!(
        sys.entity(wp).map(|e| &e.kind),
        Some(EntityKind::Workplane { .. })
    ) {
        return false;
    }
    let owner = Owner::Constraint(c.h);
    match c.kind {
        K::Horizontal | K::Vertical => {
            let (a, b) = match c.entity_a {
                Some(l) => match sys.entity(l).map(|e| &e.kind) {
                    Some(EntityKind::LineSegment { points }) => {
                        (uv(sys, Some(points[0]), wp), uv(sys, Some(points[1]), wp))
                    }
                    _ => return false,
                },
                None => (uv(sys, c.pt_a, wp), uv(sys, c.pt_b, wp)),
            };
            let (Some(a), Some(b)) = (a, b) else {
                return false;
            };
            let i = usize::from(c.kind == K::Horizontal);
            out.links.push(Link::Equal {
                owner,
                a: a[i],
                b: b[i],
            });
            true
        }
        K::PointsCoincident => {
            let (Some(a), Some(b)) = (uv(sys, c.pt_a, wp), uv(sys, c.pt_b, wp)) else {
                return false;
            };
            for i in 0..2 {
                out.links.push(Link::Equal {
                    owner,
                    a: a[i],
                    b: b[i],
                });
            }
            true
        }
        K::WhereDragged => {
            let Some(a) = uv(sys, c.pt_a, wp) else {
                return false;
            };
            for p in a {
                out.links.push(Link::Fix {
                    owner,
                    p,
                    value: values[p],
                });
            }
            true
        }
        K::PtPtDistance | K::Angle | K::ArcLineTangent | K::Diameter => {
            planar_kernel(sys, c, wp, values, x, out)
        }
        _ => false,
    }
}

/// A distance between two points of workplane `wp`, the angle between two of its lines, the
/// tangency of one of its arcs and one of its lines, or an arc's diameter: the equation
/// [`super::planar::compact`] makes of the resolved constraint, built from the `(u, v)` of the
/// points, in the order the resolver meets them.
fn planar_kernel(
    sys: &System,
    c: &Constraint,
    wp: EntityId,
    values: &[f64],
    x: &mut Vec<f64>,
    out: &mut Compiled,
) -> bool {
    use ConstraintKind as K;
    let mut l = Locals::default();
    // Points and entities in the order the resolver meets them, so that the slots agree.
    let parts = (|| {
        Some(match c.kind {
            K::PtPtDistance => (
                [
                    Some(point(sys, wp, &mut l, c.pt_a)?),
                    Some(point(sys, wp, &mut l, c.pt_b)?),
                ],
                Vec::new(),
            ),
            K::Angle => (
                [None, None],
                vec![
                    line(sys, wp, &mut l, c.entity_a)?,
                    line(sys, wp, &mut l, c.entity_b)?,
                ],
            ),
            K::ArcLineTangent => (
                [None, None],
                vec![
                    arc(sys, wp, &mut l, c.entity_a)?,
                    line(sys, wp, &mut l, c.entity_b)?,
                ],
            ),
            K::Diameter => ([None, None], vec![arc(sys, wp, &mut l, c.entity_a)?]),
            _ => return None,
        })
    })();
    let Some((pts, ents)) = parts else {
        return false;
    };
    // As the resolver has it: no workplane for a kind that ignores it (a diameter).
    let frame =
        (c.kind.signature().plane != PlaneRule::Ignored).then(|| super::planar::unread_frame(wp));
    let eq = Equation::of_constraint(c, frame, pts, ents);
    out.kernels
        .push(kernel(Owner::Constraint(c.h), l, eq, values, x));
    true
}

/// Point `h` of workplane `wp`, its `(u, v)` given slots in `l`.
fn point(sys: &System, wp: EntityId, l: &mut Locals, h: Option<EntityId>) -> Option<PointRef> {
    let [u, v] = uv(sys, h, wp)?;
    Some(PointRef::P2 {
        wp: super::planar::unread_frame(wp),
        uv: [l.slot(u), l.slot(v)],
    })
}

/// Line segment `h` with both ends points of workplane `wp`.
fn line(sys: &System, wp: EntityId, l: &mut Locals, h: Option<EntityId>) -> Option<Ent> {
    match &sys.entity(h?)?.kind {
        EntityKind::LineSegment { points } => Some(Ent::Line([
            point(sys, wp, l, Some(points[0]))?,
            point(sys, wp, l, Some(points[1]))?,
        ])),
        _ => None,
    }
}

/// Arc `h` of workplane `wp`, with its centre and ends points of it.
fn arc(sys: &System, wp: EntityId, l: &mut Locals, h: Option<EntityId>) -> Option<Ent> {
    let e = sys.entity(h?)?;
    match &e.kind {
        EntityKind::ArcOfCircle {
            center, start, end, ..
        } if e.workplane == Some(wp) => Some(Ent::Arc {
            center: point(sys, wp, l, Some(*center))?,
            start: point(sys, wp, l, Some(*start))?,
            end: point(sys, wp, l, Some(*end))?,
            wp: super::planar::unread_frame(wp),
        }),
        _ => None,
    }
}

/// The implicit equation of arc `e` (its ends equally far from its centre) when it lies in a
/// workplane with its three points: the compacted equation and its locals, as
/// [`super::compile`] makes them by resolving the arc.
pub(super) fn arc_radii(sys: &System, e: &crate::model::Entity) -> Option<(Equation, Locals)> {
    let wp = e.workplane?;
    if !matches!(
        sys.entity(wp).map(|w| &w.kind),
        Some(EntityKind::Workplane { .. })
    ) {
        return None;
    }
    let mut l = Locals::default();
    let a = arc(sys, wp, &mut l, Some(e.h))?;
    Some((
        Equation::of_entity(EqKind::ArcRadii, vec![a], 0.0, [0.0; 3]),
        l,
    ))
}

#[cfg(test)]
mod tests {
    use super::super::compile::{compile_resolved, Compiled};
    use super::super::refs::Resolver;
    use super::links;
    use crate::model::{Constraint, ConstraintKind as K, Entity, Param, System};

    /// A workplane with three points and a line in it, a point of another workplane, and a
    /// point in space.
    fn sketch() -> System {
        let mut s = System::new();
        let mut h = 0u32;
        let mut param = |s: &mut System, v: f64| {
            h += 1;
            s.add_param(Param::new(h, 1, v)).expect("fresh param");
            h
        };
        let o = [param(&mut s, 0.0), param(&mut s, 0.0), param(&mut s, 0.0)];
        let q = [
            param(&mut s, 1.0),
            param(&mut s, 0.0),
            param(&mut s, 0.0),
            param(&mut s, 0.0),
        ];
        let mut pts = Vec::new();
        for v in [[1.0, 2.0], [3.0, 4.5], [-1.0, 0.5], [7.0, 8.0]] {
            pts.push([param(&mut s, v[0]), param(&mut s, v[1])]);
        }
        let p3 = [param(&mut s, 1.0), param(&mut s, 1.0), param(&mut s, 1.0)];
        let ents = [
            Entity::point_3d(100, 1, o),
            Entity::normal_3d(101, 1, q),
            Entity::workplane(102, 1, 100, 101),
            Entity::workplane(103, 1, 100, 101),
            Entity::point_2d(110, 1, 102, pts[0]),
            Entity::point_2d(111, 1, 102, pts[1]),
            Entity::point_2d(112, 1, 102, pts[2]),
            Entity::point_2d(113, 1, 103, pts[3]),
            Entity::point_3d(114, 1, p3),
            Entity::line(120, 1, Some(102), 110, 111),
            Entity::line(121, 1, Some(102), 110, 113),
            Entity::line(122, 1, Some(102), 112, 111),
            Entity::arc(130, 1, 102, 101, 110, 111, 112),
            Entity::arc(131, 1, 103, 101, 113, 110, 111),
        ];
        for e in ents {
            s.add_entity(e).expect("fresh entity");
        }
        s
    }

    #[test]
    fn direct_links_are_those_of_the_resolved_constraint() {
        let s = sketch();
        let values: Vec<f64> = s.params().iter().map(|p| p.val).collect();
        let r = Resolver::new(&s);
        let on = |h, kind, wp: u32| Constraint::new(h, 1, kind).in_workplane(Some(wp));
        let cases = [
            (
                on(1, K::Horizontal, 102).with_entities([120, 0, 0, 0]),
                true,
            ),
            (on(2, K::Vertical, 102).with_entities([120, 0, 0, 0]), true),
            (on(3, K::Horizontal, 102).with_points(111, 112), true),
            (on(4, K::PointsCoincident, 102).with_points(110, 112), true),
            (on(5, K::WhereDragged, 102).with_points(111, 0), true),
            // A point of another workplane, a point in space, a line leaving the workplane,
            // or the other workplane: the general path decides.
            (on(6, K::PointsCoincident, 102).with_points(110, 113), false),
            (on(7, K::PointsCoincident, 102).with_points(110, 114), false),
            (on(8, K::Vertical, 102).with_entities([121, 0, 0, 0]), false),
            (on(9, K::WhereDragged, 103).with_points(111, 0), false),
            (on(10, K::PtPtDistance, 102).with_points(110, 112), true),
            (on(11, K::PtPtDistance, 102).with_points(111, 111), true),
            (on(12, K::PtPtDistance, 102).with_points(110, 113), false),
            (on(13, K::PtPtDistance, 103).with_points(110, 111), false),
            (on(14, K::Angle, 102).with_entities([120, 122, 0, 0]), true),
            (on(15, K::Angle, 102).with_entities([120, 120, 0, 0]), true),
            (on(16, K::Angle, 102).with_entities([120, 121, 0, 0]), false),
            (
                on(17, K::ArcLineTangent, 102).with_entities([130, 122, 0, 0]),
                true,
            ),
            (
                on(18, K::ArcLineTangent, 102).with_entities([130, 121, 0, 0]),
                false,
            ),
            (
                on(19, K::ArcLineTangent, 102).with_entities([131, 120, 0, 0]),
                false,
            ),
            (on(20, K::Diameter, 102).with_entities([130, 0, 0, 0]), true),
            (
                on(21, K::Diameter, 103).with_entities([130, 0, 0, 0]),
                false,
            ),
        ];
        for (c, direct) in cases {
            let c = c.with_val(12.5);
            let (mut a, mut b) = (Compiled::default(), Compiled::default());
            let x = &mut Vec::new();
            assert_eq!(links(&s, &c, &values, x, &mut a), direct, "{:?}", c.kind);
            compile_resolved(&r, &c, &values, x, &mut b).expect("compiles");
            if direct {
                assert_eq!(format!("{:?}", a.links), format!("{:?}", b.links));
                assert_eq!(format!("{:?}", a.kernels), format!("{:?}", b.kernels));
                assert_eq!(
                    a.links.len() + a.kernels.len(),
                    b.links.len() + b.kernels.len()
                );
            } else {
                assert!(a.links.is_empty() && a.kernels.is_empty());
            }
        }
    }

    #[test]
    fn an_arc_of_a_workplane_is_the_compacted_resolved_arc() {
        use super::super::planar::compact;
        use super::super::refs::Locals;
        use super::super::{EqKind, Equation};
        use crate::model::ObjectId;
        let s = sketch();
        let r = Resolver::new(&s);
        let arc = s.entity(130.into()).expect("arc");
        let mut l = Locals::default();
        let ent = r
            .entity(ObjectId::Entity(arc.h), arc.h, &mut l)
            .expect("resolves");
        let mut eq = Equation::of_entity(EqKind::ArcRadii, vec![ent], 0.0, [0.0; 3]);
        let kept = compact(&mut eq, &l).expect("planar");
        let (direct, dl) = super::arc_radii(&s, arc).expect("direct");
        assert_eq!(format!("{direct:?}"), format!("{eq:?}"));
        assert_eq!(dl.params, kept.params);
        // An arc whose points leave its workplane is resolved instead.
        assert!(super::arc_radii(&s, s.entity(131.into()).expect("arc")).is_none());
    }
}
