//! Primitive relations between component-frame geometry: what every mate is made of, each
//! written as core constraints ([`super::build`]), measured in world coordinates here, and
//! corrected step by step by [`super::stepped`].

use super::component::Pose;
use super::math::{self, Q4, V3};

/// Which body a piece of geometry is on: a component's index, or `None` for the world.
pub(crate) type Body = Option<usize>;

/// A point in a body's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct P {
    pub body: Body,
    pub p: V3,
}

/// A unit direction in a body's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct D {
    pub body: Body,
    pub d: V3,
}

/// A line (point, unit direction) or a plane (point, unit normal) in a body's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct L {
    pub body: Body,
    pub p: V3,
    pub d: V3,
}

impl L {
    pub fn point(&self) -> P {
        P {
            body: self.body,
            p: self.p,
        }
    }
    pub fn dir(&self) -> D {
        D {
            body: self.body,
            d: self.d,
        }
    }
}

/// One relation; the count in brackets is how many equations it writes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Prim {
    /// The points coincide (3).
    Coincident(P, P),
    /// The point lies in the plane (1).
    InPlane(P, L),
    /// The point lies on the line (2).
    OnLine(P, L),
    /// The directions are parallel, aligned or (`true`) opposed (2).
    Parallel(D, D, bool),
    /// The directions are perpendicular (1).
    Perpendicular(D, D),
    /// The points are `f64` apart (1).
    PtPtDistance(P, P, f64),
    /// The point is at signed distance `f64` from the plane, along its normal (1).
    PtPlaneDistance(P, L, f64),
    /// The point is `f64` from the line (1).
    PtLineDistance(P, L, f64),
    /// Body `b`'s orientation is body `a`'s times `Q4` (3).
    SameOrientation(Body, Body, Q4),
    /// The signed angle from `a` to `b` about the axis (a unit vector in `a`'s body frame,
    /// normal to `a`) is the target in radians (1).
    SignedAngle { a: D, b: D, axis: V3, target: f64 },
}

/// The world poses of the bodies: components by index, the world at the identity.
pub(crate) struct World<'a> {
    pub poses: &'a [Pose],
}

impl World<'_> {
    pub fn pose(&self, b: Body) -> Pose {
        b.map_or(Pose::IDENTITY, |i| self.poses[i])
    }
    pub fn point(&self, p: &P) -> V3 {
        self.pose(p.body).point(p.p)
    }
    pub fn dir(&self, d: &D) -> V3 {
        self.pose(d.body).direction(d.d)
    }
}

/// The signed angle (radians, in `(-pi, pi]`) from `a` to `b` about `axis`, all in world
/// coordinates, `a` normal to `axis`: the angle of `b`'s projection on the plane normal to
/// the axis. Continuous through 0 and 180 degrees: the axis is held, not recomputed from
/// `a × b` (which turns over as the parts pass through those angles).
pub(crate) fn signed_angle(a: V3, b: V3, axis: V3) -> f64 {
    let u = math::cross(axis, a);
    math::dot(u, b).atan2(math::dot(a, b))
}

/// `x` wrapped to `(-pi, pi]`.
pub(crate) fn wrap(x: f64) -> f64 {
    let t = std::f64::consts::TAU;
    let mut y = x.rem_euclid(t);
    if y > std::f64::consts::PI {
        y -= t;
    }
    y
}

impl Prim {
    /// How many conditions it sets (each variant's count above).
    pub fn conditions(&self) -> usize {
        match self {
            Prim::Coincident(..) | Prim::SameOrientation(..) => 3,
            Prim::OnLine(..) | Prim::Parallel(..) => 2,
            Prim::InPlane(..)
            | Prim::Perpendicular(..)
            | Prim::PtPtDistance(..)
            | Prim::PtPlaneDistance(..)
            | Prim::PtLineDistance(..)
            | Prim::SignedAngle { .. } => 1,
        }
    }

    /// The bodies the relation ties.
    pub fn bodies(&self) -> (Body, Body) {
        match *self {
            Prim::Coincident(a, b) | Prim::PtPtDistance(a, b, _) => (a.body, b.body),
            Prim::InPlane(p, l)
            | Prim::OnLine(p, l)
            | Prim::PtPlaneDistance(p, l, _)
            | Prim::PtLineDistance(p, l, _) => (l.body, p.body),
            Prim::Parallel(a, b, _) | Prim::Perpendicular(a, b) => (a.body, b.body),
            Prim::SameOrientation(a, b, _) => (a, b),
            Prim::SignedAngle { a, b, .. } => (a.body, b.body),
        }
    }

    /// Whether the error is an angle (radians) rather than a length.
    pub fn is_angular(&self) -> bool {
        matches!(
            self,
            Prim::Parallel(..)
                | Prim::Perpendicular(..)
                | Prim::SameOrientation(..)
                | Prim::SignedAngle { .. }
        )
    }

    /// How far from holding: a length in model units, or an angle in radians.
    pub fn error(&self, w: &World) -> f64 {
        match self {
            Prim::Coincident(a, b) => math::norm(math::sub(w.point(b), w.point(a))),
            Prim::InPlane(p, l) => plane_offset(w, p, l).abs(),
            Prim::OnLine(p, l) => line_offset(w, p, l),
            Prim::Parallel(a, b, flip) => {
                let (da, db) = (w.dir(a), w.dir(b));
                let db = if *flip { math::scale(db, -1.0) } else { db };
                math::angle_between(da, db)
            }
            Prim::Perpendicular(a, b) => {
                (math::angle_between(w.dir(a), w.dir(b)) - std::f64::consts::FRAC_PI_2).abs()
            }
            Prim::PtPtDistance(a, b, d) => {
                (math::norm(math::sub(w.point(b), w.point(a))) - d).abs()
            }
            Prim::PtPlaneDistance(p, l, d) => (plane_offset(w, p, l) - d).abs(),
            Prim::PtLineDistance(p, l, d) => (line_offset(w, p, l) - d).abs(),
            Prim::SameOrientation(a, b, rel) => {
                let want = math::qmul(w.pose(*a).rotation, *rel);
                let have = w.pose(*b).rotation;
                let d = math::qmul(math::qconj(want), have);
                2.0 * math::norm([d[1], d[2], d[3]]).atan2(d[0].abs())
            }
            Prim::SignedAngle { a, b, axis, target } => {
                let n = w.pose(a.body).direction(*axis);
                wrap(signed_angle(w.dir(a), w.dir(b), n) - target).abs()
            }
        }
    }
}

/// Signed distance of `p` from plane `l`.
pub(crate) fn plane_offset(w: &World, p: &P, l: &L) -> f64 {
    let n = w.dir(&l.dir());
    math::dot(math::sub(w.point(p), w.point(&l.point())), n)
}

/// Distance of `p` from line `l`.
pub(crate) fn line_offset(w: &World, p: &P, l: &L) -> f64 {
    let d = w.dir(&l.dir());
    math::norm(math::cross(math::sub(w.point(p), w.point(&l.point())), d))
}
