//! Where things are: entity positions in the model, projected onto the drawing plane, and
//! the map from that plane to SVG pixels (y up in the model, y down in SVG).

use loci::geom::Quat;
use loci::{EntityId, EntityKind, GroupId, System};
use std::collections::BTreeMap;

/// A 2D point or vector: drawing-plane coordinates, or pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct P2 {
    pub x: f64,
    pub y: f64,
}

impl P2 {
    pub(crate) const fn new(x: f64, y: f64) -> Self {
        Self { x, y }
    }
    pub(crate) fn plus(self, o: P2) -> P2 {
        P2::new(self.x + o.x, self.y + o.y)
    }
    pub(crate) fn minus(self, o: P2) -> P2 {
        P2::new(self.x - o.x, self.y - o.y)
    }
    pub(crate) fn scale(self, k: f64) -> P2 {
        P2::new(self.x * k, self.y * k)
    }
    pub(crate) fn dot(self, o: P2) -> f64 {
        self.x * o.x + self.y * o.y
    }
    pub(crate) fn cross(self, o: P2) -> f64 {
        self.x * o.y - self.y * o.x
    }
    pub(crate) fn norm(self) -> f64 {
        self.x.hypot(self.y)
    }
    /// The unit vector along `self`, or `None` for a (near) zero vector.
    pub(crate) fn unit(self) -> Option<P2> {
        let n = self.norm();
        (n > 1e-12 && n.is_finite()).then(|| self.scale(1.0 / n))
    }
    /// Turned a quarter to the left (counter-clockwise with y up).
    pub(crate) fn perp(self) -> P2 {
        P2::new(-self.y, self.x)
    }
    pub(crate) fn mid(self, o: P2) -> P2 {
        self.plus(o).scale(0.5)
    }
    pub(crate) fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }
}

type V3 = [f64; 3];

fn sub3(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot3(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn axpy(p: V3, k: f64, d: V3) -> V3 {
    [p[0] + k * d[0], p[1] + k * d[1], p[2] + k * d[2]]
}

/// An orthonormal frame: an origin and its u, v, n axes.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frame {
    pub origin: V3,
    pub u: V3,
    pub v: V3,
    pub n: V3,
}

/// How the model is projected onto the drawing plane.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Projection {
    /// Onto this workplane, in its own u, v coordinates.
    Workplane(EntityId),
    /// Onto the model's xy plane (every point has the same z).
    Xy,
    /// An isometric view with z up.
    Isometric,
}

/// The drawing plane and how to find entities on it.
pub(crate) struct View<'a> {
    pub sys: &'a System,
    pub projection: Projection,
    frame: Frame,
}

impl<'a> View<'a> {
    /// The view of `group`: its workplane (the one most of its entities and constraints
    /// name) when it has one; otherwise the xy plane when every point lies in one plane
    /// z = const, else an isometric view.
    pub(crate) fn of_group(sys: &'a System, group: GroupId) -> Self {
        let mut count: BTreeMap<EntityId, usize> = BTreeMap::new();
        let named = sys
            .entities()
            .iter()
            .filter(|e| e.group == group)
            .filter_map(|e| e.workplane)
            .chain(
                sys.constraints()
                    .iter()
                    .filter(|c| c.group == group)
                    .filter_map(|c| c.workplane),
            );
        for wp in named {
            *count.entry(wp).or_default() += 1;
        }
        // The most named; on a tie the lowest handle (the map's order), for determinism.
        let best = count
            .iter()
            .filter(|(h, _)| workplane_frame(sys, **h).is_some())
            .max_by(|a, b| a.1.cmp(b.1).then(b.0.cmp(a.0)))
            .map(|(h, _)| *h);
        if let Some(wp) = best {
            if let Some(frame) = workplane_frame(sys, wp) {
                return Self {
                    sys,
                    projection: Projection::Workplane(wp),
                    frame,
                };
            }
        }
        let xy = Frame {
            origin: [0.0; 3],
            u: [1.0, 0.0, 0.0],
            v: [0.0, 1.0, 0.0],
            n: [0.0, 0.0, 1.0],
        };
        let probe = Self {
            sys,
            projection: Projection::Xy,
            frame: xy,
        };
        let zs: Vec<f64> = sys
            .entities()
            .iter()
            .filter(|e| e.entity_type().is_point())
            .filter_map(|e| probe.point3(e.h))
            .map(|p| p[2])
            .collect();
        let flat = zs
            .iter()
            .all(|z| (z - zs.first().copied().unwrap_or(0.0)).abs() < 1e-9);
        if flat {
            return probe;
        }
        let s2 = std::f64::consts::FRAC_1_SQRT_2;
        let s6 = 1.0 / 6f64.sqrt();
        let s3 = 1.0 / 3f64.sqrt();
        Self {
            sys,
            projection: Projection::Isometric,
            frame: Frame {
                origin: [0.0; 3],
                u: [s2, -s2, 0.0],
                v: [-s6, -s6, 2.0 * s6],
                n: [s3, s3, s3],
            },
        }
    }

    /// Projects a model point onto the drawing plane.
    pub(crate) fn project(&self, p: V3) -> P2 {
        let d = sub3(p, self.frame.origin);
        P2::new(dot3(d, self.frame.u), dot3(d, self.frame.v))
    }

    /// The model position of point entity `h`.
    pub(crate) fn point3(&self, h: EntityId) -> Option<V3> {
        let e = self.sys.entity(h)?;
        let val = |p| self.sys.value(p);
        match &e.kind {
            EntityKind::PointIn3d { params }
            | EntityKind::PointNTrans { params, .. }
            | EntityKind::PointNRotTrans { params, .. } => {
                Some([val(params[0])?, val(params[1])?, val(params[2])?])
            }
            EntityKind::PointIn2d { params } => {
                let f = workplane_frame(self.sys, e.workplane?)?;
                let (u, v) = (val(params[0])?, val(params[1])?);
                Some(axpy(axpy(f.origin, u, f.u), v, f.v))
            }
            _ => None,
        }
    }

    /// Point entity `h` on the drawing plane. A point of the view's own workplane is read
    /// directly, without a round trip through 3D.
    pub(crate) fn point(&self, h: EntityId) -> Option<P2> {
        let e = self.sys.entity(h)?;
        if let (EntityKind::PointIn2d { params }, Projection::Workplane(wp)) =
            (&e.kind, self.projection)
        {
            if e.workplane == Some(wp) {
                return Some(P2::new(
                    self.sys.value(params[0])?,
                    self.sys.value(params[1])?,
                ));
            }
        }
        let p = self.project(self.point3(h)?);
        p.is_finite().then_some(p)
    }

    /// The axes of normal entity `h`.
    pub(crate) fn normal_frame(&self, h: EntityId) -> Option<Frame> {
        normal_axes(self.sys, h).map(|(u, v, n)| Frame {
            origin: [0.0; 3],
            u,
            v,
            n,
        })
    }

    /// The value of distance entity `h` (a radius).
    pub(crate) fn distance(&self, h: EntityId) -> Option<f64> {
        match &self.sys.entity(h)?.kind {
            EntityKind::Distance { param } => self.sys.value(*param),
            _ => None,
        }
    }

    /// Whether a plane with normal `n` is parallel to the drawing plane: its circles are
    /// drawn as circles, not sampled ellipses.
    pub(crate) fn faces(&self, n: V3) -> bool {
        (dot3(n, self.frame.n).abs() - 1.0).abs() < 1e-9
    }

    /// Samples the circle about model point `c` with radius `r` in the plane of `axes`
    /// from angle `a0` over `sweep` (radians), projected.
    pub(crate) fn sample(&self, c: V3, r: f64, axes: &Frame, a0: f64, sweep: f64) -> Vec<P2> {
        let n = ((sweep.abs() / (2.0 * std::f64::consts::PI)) * 96.0)
            .ceil()
            .max(8.0) as usize;
        (0..=n)
            .map(|i| {
                let t = a0 + sweep * i as f64 / n as f64;
                self.project(axpy(axpy(c, r * t.cos(), axes.u), r * t.sin(), axes.v))
            })
            .collect()
    }
}

/// The origin and axes of workplane `wp`.
pub(crate) fn workplane_frame(sys: &System, wp: EntityId) -> Option<Frame> {
    let EntityKind::Workplane { origin, normal } = &sys.entity(wp)?.kind else {
        return None;
    };
    let o = match &sys.entity(*origin)?.kind {
        EntityKind::PointIn3d { params }
        | EntityKind::PointNTrans { params, .. }
        | EntityKind::PointNRotTrans { params, .. } => [
            sys.value(params[0])?,
            sys.value(params[1])?,
            sys.value(params[2])?,
        ],
        _ => return None,
    };
    let (u, v, n) = normal_axes(sys, *normal)?;
    Some(Frame { origin: o, u, v, n })
}

/// The u, v, n axes of normal `h` (a 2D normal takes its workplane's).
fn normal_axes(sys: &System, h: EntityId) -> Option<(V3, V3, V3)> {
    let e = sys.entity(h)?;
    match &e.kind {
        EntityKind::NormalIn3d { params } | EntityKind::NormalNRot { params, .. } => {
            let q = params.map(|p| sys.value(p));
            let [w, x, y, z] = [q[0]?, q[1]?, q[2]?, q[3]?];
            let len = (w * w + x * x + y * y + z * z).sqrt();
            if !(len > 1e-12 && len.is_finite()) {
                return None;
            }
            let q = Quat {
                w: w / len,
                x: x / len,
                y: y / len,
                z: z / len,
            };
            let (u, v, n) = (q.u(), q.v(), q.n());
            Some(([u.x, u.y, u.z], [v.x, v.y, v.z], [n.x, n.y, n.z]))
        }
        EntityKind::NormalIn2d => {
            let f = workplane_frame(sys, e.workplane?)?;
            Some((f.u, f.v, f.n))
        }
        _ => None,
    }
}

/// The map from the drawing plane to pixels: uniform scale, y flipped.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ToPixels {
    pub scale: f64,
    pub min_x: f64,
    pub max_y: f64,
}

impl ToPixels {
    /// Fits the box `lo`..`hi` (drawing plane) into `width` × `height` pixels.
    pub(crate) fn fit(lo: P2, hi: P2, width: f64, height: f64) -> Self {
        let (dx, dy) = (hi.x - lo.x, hi.y - lo.y);
        let sx = if dx > 1e-12 {
            width / dx
        } else {
            f64::INFINITY
        };
        let sy = if dy > 1e-12 {
            height / dy
        } else {
            f64::INFINITY
        };
        let mut scale = sx.min(sy);
        if !scale.is_finite() {
            // A single point (or nothing): any scale; centre it.
            scale = 1.0;
        }
        // Centre the drawing in the box along the axis with room to spare.
        let min_x = lo.x - (width / scale - dx).max(0.0) / 2.0;
        let max_y = hi.y + (height / scale - dy).max(0.0) / 2.0;
        Self {
            scale,
            min_x,
            max_y,
        }
    }

    pub(crate) fn px(&self, p: P2) -> P2 {
        P2::new(
            (p.x - self.min_x) * self.scale,
            (self.max_y - p.y) * self.scale,
        )
    }
}
