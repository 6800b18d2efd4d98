//! From a mate to primitive relations: resolving its selections and choosing the form its
//! kind takes for the shapes selected.

use super::angle::normalise_degrees;
use super::component::{Component, Pose, Reference, Shape};
use super::error::AssemblyError;
use super::mate::{Mate, MateKind, Persistent, Selection};
use super::math::{self, V3};
use super::prim::{Body, Prim, D, L, P};
use rustc_hash::FxHashMap as HashMap;

/// A selection resolved to its body and reference.
#[derive(Clone, Debug)]
pub(crate) struct Resolved<'a> {
    pub body: Body,
    pub reference: Reference,
    /// What was selected, named in errors only (formatted when one is made).
    pub sel: &'a Selection,
}

impl Resolved<'_> {
    /// The selection as a user wrote it: `component.reference`.
    fn label(&self) -> String {
        self.sel.to_string()
    }
}

/// Finds what `sel` names.
pub(crate) fn resolve<'a>(
    components: &[Component],
    index: &HashMap<&str, usize>,
    world: &[(String, Reference)],
    mate: &str,
    sel: &'a Selection,
) -> Result<Resolved<'a>, AssemblyError> {
    let missing = |c: &str| AssemblyError::UnknownReference {
        mate: mate.into(),
        component: c.into(),
        reference: sel.reference.clone(),
    };
    match &sel.component {
        Some(name) => {
            let i = index.get(name.as_str()).copied().ok_or_else(|| {
                AssemblyError::UnknownComponent {
                    mate: mate.into(),
                    component: name.clone(),
                }
            })?;
            let r = components[i]
                .reference(&sel.reference)
                .ok_or_else(|| missing(name))?;
            Ok(Resolved {
                body: Some(i),
                reference: r.clone(),
                sel,
            })
        }
        None => {
            let r = world
                .iter()
                .find(|(n, _)| *n == sel.reference)
                .map(|(_, r)| r.clone())
                .ok_or_else(|| missing("world"))?;
            Ok(Resolved {
                body: None,
                reference: r,
                sel,
            })
        }
    }
}

struct Ctx<'a> {
    mate: &'a str,
}

impl Ctx<'_> {
    fn unusable(&self, r: &Resolved, needed: &'static str) -> AssemblyError {
        AssemblyError::Unusable {
            mate: self.mate.into(),
            selection: r.label(),
            found: r.reference.kind_name(),
            needed,
        }
    }

    fn point(&self, r: &Resolved) -> P {
        P {
            body: r.body,
            p: r.reference.point(),
        }
    }

    fn dir(&self, r: &Resolved) -> Result<D, AssemblyError> {
        let d = r
            .reference
            .direction()
            .ok_or_else(|| self.unusable(r, "direction"))?;
        Ok(D { body: r.body, d })
    }

    fn line(&self, r: &Resolved) -> Result<L, AssemblyError> {
        if !matches!(r.reference.shape(), Shape::Line) && r.reference != Reference::Frame {
            return Err(self.unusable(r, "line"));
        }
        let d = self.dir(r)?;
        Ok(L {
            body: r.body,
            p: r.reference.point(),
            d: d.d,
        })
    }

    fn plane(&self, r: &Resolved) -> Result<L, AssemblyError> {
        if !matches!(
            r.reference,
            Reference::Face { .. } | Reference::CircularEdge { .. } | Reference::Frame
        ) {
            return Err(self.unusable(r, "plane"));
        }
        let d = self.dir(r)?;
        Ok(L {
            body: r.body,
            p: r.reference.point(),
            d: d.d,
        })
    }

    fn value(&self, v: f64, nonneg: bool) -> Result<f64, AssemblyError> {
        if !(v.is_finite() && v.abs() <= crate::MAX_MAGNITUDE) || (nonneg && v < 0.0) {
            return Err(AssemblyError::BadValue {
                mate: self.mate.into(),
                value: v,
                expected: if nonneg {
                    "a finite distance, zero or more, of size at most 1e100"
                } else {
                    "a finite number of size at most 1e100"
                },
            });
        }
        Ok(v)
    }
}

/// The checks every mate makes on its two selections: two different bodies, not both the
/// world. The angle mate makes the seed's checks in the seed's order instead.
fn check_bodies(mate: &str, a: &Resolved, b: &Resolved) -> Result<(), AssemblyError> {
    match (a.body, b.body) {
        (None, None) => Err(AssemblyError::NotAttached {
            mate: mate.into(),
            selection: b.label(),
        }),
        (Some(x), Some(y)) if x == y => Err(AssemblyError::SameComponent {
            mate: mate.into(),
            component: a.label().split('.').next().unwrap_or_default().into(),
        }),
        _ => Ok(()),
    }
}

/// The primitive relations of `mate`, resolving its selections against `components` at
/// `poses`. Directions a mate fixes on its first solve (the angle's axis, a joint's zero,
/// `fixed`'s relative pose) are captured into `mate.persistent` from the current poses.
///
/// `hints` are pairs of directions other mates hold parallel between two bodies (a hinge's
/// axes), by the pair of bodies (lower first): an angle mate between the same bodies turns about such an axis when it is normal
/// to A's direction.
pub(crate) fn compile(
    components: &[Component],
    index: &HashMap<&str, usize>,
    world: &[(String, Reference)],
    poses: &[Pose],
    mate: &mut Mate,
    hints: &HashMap<(Body, Body), Vec<(D, D)>>,
) -> Result<Vec<Prim>, AssemblyError> {
    // Its parts apart: the selections stay borrowed by what they resolve to while the
    // persistent data is written.
    let Mate {
        id,
        kind,
        a,
        b,
        flip,
        persistent,
        ..
    } = mate;
    let id: &str = id;
    let cx = Ctx { mate: id };
    let ra = resolve(components, index, world, id, a)?;
    let rb = resolve(components, index, world, id, b)?;
    let pose = |b: Body| b.map_or(Pose::IDENTITY, |i| poses[i]);
    if let MateKind::Angle { degrees } = *kind {
        // The seed's order: a direction from each, then both on components, then two of them.
        let (da, db) = (cx.dir(&ra)?, cx.dir(&rb)?);
        for r in [&ra, &rb] {
            if r.body.is_none() {
                return Err(AssemblyError::NotAttached {
                    mate: id.into(),
                    selection: r.label(),
                });
            }
        }
        check_bodies(id, &ra, &rb)?;
        let target = normalise_degrees(cx.value(degrees, false)?).to_radians();
        let axis = match persistent.axis {
            Some(a) => a,
            None => {
                let (wa, wb) = (pose(da.body).direction(da.d), pose(db.body).direction(db.d));
                // A hinge between the two components (a direction both hold parallel, normal
                // to A's) is the axis the angle turns about; `a × b` at the start would carry
                // whatever tilt the start has. It is turned to agree with `a × b`, so that
                // the angle at the start reads positive as in the seed.
                let c = math::cross(wa, wb);
                let pair = |a: Body, b: Body| if a <= b { (a, b) } else { (b, a) };
                let none = Vec::new();
                let near = hints.get(&pair(da.body, db.body)).unwrap_or(&none);
                let hinted = near.iter().find_map(|&(x, y)| {
                    let local = if (x.body, y.body) == (da.body, db.body) {
                        x.d
                    } else if (y.body, x.body) == (da.body, db.body) {
                        y.d
                    } else {
                        return None;
                    };
                    (math::dot(local, da.d).abs() < 1e-9).then_some(local)
                });
                let local = match hinted {
                    Some(h) => {
                        let w = pose(da.body).direction(h);
                        if math::dot(w, c) < 0.0 {
                            math::scale(h, -1.0)
                        } else {
                            h
                        }
                    }
                    None => {
                        let n = math::unit(c)
                            .filter(|_| math::norm(c) > 1e-9)
                            .unwrap_or_else(|| math::perpendicular(wa));
                        pose(da.body).to_local_direction(n)
                    }
                };
                persistent.axis = Some(local);
                local
            }
        };
        return Ok(vec![Prim::SignedAngle {
            a: da,
            b: db,
            axis,
            target,
        }]);
    }
    check_bodies(id, &ra, &rb)?;
    let (sa, sb) = (ra.reference.shape(), rb.reference.shape());
    let flip = *flip;
    use Shape::*;
    let prims = match kind.clone() {
        MateKind::Angle { .. } => unreachable!("handled above"),
        MateKind::Coincident => match (sa, sb) {
            (Point, Point) => vec![Prim::Coincident(cx.point(&ra), cx.point(&rb))],
            (Point, Plane) => vec![Prim::InPlane(cx.point(&ra), cx.plane(&rb)?)],
            (Plane, Point) => vec![Prim::InPlane(cx.point(&rb), cx.plane(&ra)?)],
            (Point, Line) => vec![Prim::OnLine(cx.point(&ra), cx.line(&rb)?)],
            (Line, Point) => vec![Prim::OnLine(cx.point(&rb), cx.line(&ra)?)],
            (Plane, Plane) => planes(&cx, &ra, &rb, flip, None)?,
            (Line, Line) => collinear(&cx, &ra, &rb, flip)?,
            (Line, Plane) => line_in_plane(&cx, &ra, &rb)?,
            (Plane, Line) => line_in_plane(&cx, &rb, &ra)?,
        },
        MateKind::Distance { value } => match (sa, sb) {
            (Point, Point) => {
                let v = cx.value(value, true)?;
                if v == 0.0 {
                    vec![Prim::Coincident(cx.point(&ra), cx.point(&rb))]
                } else {
                    vec![Prim::PtPtDistance(cx.point(&ra), cx.point(&rb), v)]
                }
            }
            (Point, Plane) => vec![Prim::PtPlaneDistance(
                cx.point(&ra),
                cx.plane(&rb)?,
                cx.value(value, false)?,
            )],
            (Plane, Point) => vec![Prim::PtPlaneDistance(
                cx.point(&rb),
                cx.plane(&ra)?,
                cx.value(value, false)?,
            )],
            (Point, Line) | (Line, Point) => {
                let (p, l) = if sa == Point { (&ra, &rb) } else { (&rb, &ra) };
                let v = cx.value(value, true)?;
                if v == 0.0 {
                    vec![Prim::OnLine(cx.point(p), cx.line(l)?)]
                } else {
                    vec![Prim::PtLineDistance(cx.point(p), cx.line(l)?, v)]
                }
            }
            (Plane, Plane) => planes(&cx, &ra, &rb, flip, Some(cx.value(value, false)?))?,
            (Line, Line) => {
                let v = cx.value(value, true)?;
                if v == 0.0 {
                    collinear(&cx, &ra, &rb, flip)?
                } else {
                    let la = cx.line(&ra)?;
                    vec![
                        Prim::Parallel(la.dir(), cx.dir(&rb)?, flip),
                        Prim::PtLineDistance(cx.point(&rb), la, v),
                    ]
                }
            }
            (Line, Plane) => {
                return Err(cx.unusable(&ra, "point or plane for a distance to a plane"))
            }
            (Plane, Line) => {
                return Err(cx.unusable(&rb, "point or plane for a distance to a plane"))
            }
        },
        MateKind::Parallel => vec![Prim::Parallel(cx.dir(&ra)?, cx.dir(&rb)?, flip)],
        MateKind::Perpendicular => vec![Prim::Perpendicular(cx.dir(&ra)?, cx.dir(&rb)?)],
        MateKind::TouchAlign => match (sa, sb) {
            (Plane, Plane) => planes(&cx, &ra, &rb, true, None)?,
            (Line, Line) => collinear(&cx, &ra, &rb, flip)?,
            (Point, Point) => vec![Prim::Coincident(cx.point(&ra), cx.point(&rb))],
            (Point, _) | (Line, _) | (Plane, _) => {
                return Err(cx.unusable(&rb, "face, edge or point matching the other selection"))
            }
        },
        MateKind::Concentric | MateKind::Cylindrical => collinear(&cx, &ra, &rb, flip)?,
        MateKind::Fixed | MateKind::Fastened => {
            let (pa, pb) = (pose(ra.body), pose(rb.body));
            let (t, q) = *persistent.relative.get_or_insert_with(|| {
                (
                    pa.to_local_point(pb.translation),
                    math::qmul(math::qconj(pa.rotation), pb.rotation),
                )
            });
            vec![
                Prim::Coincident(
                    P {
                        body: ra.body,
                        p: t,
                    },
                    P {
                        body: rb.body,
                        p: [0.0; 3],
                    },
                ),
                Prim::SameOrientation(ra.body, rb.body, q),
            ]
        }
        MateKind::Revolute => {
            let (la, lb) = (cx.line(&ra)?, cx.line(&rb)?);
            capture_zero(kind, persistent, &la, &lb, poses);
            vec![
                Prim::Coincident(la.point(), lb.point()),
                Prim::Parallel(la.dir(), lb.dir(), flip),
            ]
        }
        MateKind::Slider => {
            let (la, lb) = (cx.line(&ra)?, cx.line(&rb)?);
            let (ua, ub) = capture_zero(kind, persistent, &la, &lb, poses);
            vec![
                Prim::Parallel(la.dir(), lb.dir(), flip),
                Prim::OnLine(lb.point(), la),
                Prim::Perpendicular(
                    D {
                        body: la.body,
                        d: math::cross(la.d, ua),
                    },
                    D {
                        body: lb.body,
                        d: ub,
                    },
                ),
            ]
        }
        MateKind::Ball => vec![Prim::Coincident(cx.point(&ra), cx.point(&rb))],
        MateKind::Planar => planes(&cx, &ra, &rb, flip, None)?,
        MateKind::PinSlot => {
            let (slot, pin) = (cx.line(&ra)?, cx.line(&rb)?);
            let n = *persistent.axis.get_or_insert_with(|| {
                let pa = pose(slot.body);
                let dp = pa.to_local_direction(pose(pin.body).direction(pin.d));
                let off = math::sub(dp, math::scale(slot.d, math::dot(dp, slot.d)));
                math::unit(off).unwrap_or_else(|| math::perpendicular(slot.d))
            });
            vec![
                Prim::OnLine(pin.point(), slot),
                Prim::Parallel(
                    D {
                        body: slot.body,
                        d: n,
                    },
                    pin.dir(),
                    flip,
                ),
            ]
        }
    };
    Ok(prims)
}

/// Plane–plane: normals parallel (aligned, or opposed with `flip`) and B's point in A's plane,
/// or at signed distance `offset` along A's normal.
fn planes(
    cx: &Ctx,
    ra: &Resolved,
    rb: &Resolved,
    flip: bool,
    offset: Option<f64>,
) -> Result<Vec<Prim>, AssemblyError> {
    let (pa, pb) = (cx.plane(ra)?, cx.plane(rb)?);
    let on = match offset {
        None => Prim::InPlane(pb.point(), pa),
        Some(d) => Prim::PtPlaneDistance(pb.point(), pa, d),
    };
    Ok(vec![Prim::Parallel(pa.dir(), pb.dir(), flip), on])
}

/// Line–line: collinear.
fn collinear(
    cx: &Ctx,
    ra: &Resolved,
    rb: &Resolved,
    flip: bool,
) -> Result<Vec<Prim>, AssemblyError> {
    let (la, lb) = (cx.line(ra)?, cx.line(rb)?);
    Ok(vec![
        Prim::Parallel(la.dir(), lb.dir(), flip),
        Prim::OnLine(lb.point(), la),
    ])
}

/// Line in plane: its point in the plane and its direction normal to the plane's normal.
fn line_in_plane(cx: &Ctx, rl: &Resolved, rp: &Resolved) -> Result<Vec<Prim>, AssemblyError> {
    let (l, p) = (cx.line(rl)?, cx.plane(rp)?);
    Ok(vec![
        Prim::InPlane(l.point(), p),
        Prim::Perpendicular(p.dir(), l.dir()),
    ])
}

/// A joint's zero: a direction normal to A's axis in A's frame, and one normal to B's in B's
/// frame. For a slider, B's is A's world direction when the joint is first solved, so that
/// the slider holds the parts' turn about the axis as it finds it.
fn capture_zero(
    kind: &MateKind,
    persistent: &mut Persistent,
    la: &L,
    lb: &L,
    poses: &[Pose],
) -> (V3, V3) {
    let pose = |b: Body| b.map_or(Pose::IDENTITY, |i| poses[i]);
    if *kind == MateKind::Revolute {
        // A revolute's angle is zero where the two references' frames agree: the same
        // perpendicular of each axis, in each component's own frame.
        let ua = *persistent
            .axis
            .get_or_insert_with(|| math::perpendicular(la.d));
        let ub = *persistent
            .axis_b
            .get_or_insert_with(|| math::perpendicular(lb.d));
        return (ua, ub);
    }
    let ua = *persistent
        .axis
        .get_or_insert_with(|| math::perpendicular(la.d));
    let ub = *persistent
        .axis_b
        .get_or_insert_with(|| pose(lb.body).to_local_direction(pose(la.body).direction(ua)));
    (ua, ub)
}
