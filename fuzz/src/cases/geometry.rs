//! An independent reading of a solved model: positions, directions and the residual of each
//! common constraint, computed here from parameter values and the meaning of each constraint
//! type (see `docs/` and SolveSpace), without loci's equation code. The `resolve` target
//! uses it to check that a system loci calls solved really is.

use loci::{Constraint, ConstraintKind as K, EntityId, EntityKind, PlaneRule, System};

/// A 3D vector.
pub type V = [f64; 3];

fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale(a: V, s: f64) -> V {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The full cross product (all three components).
fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn norm(a: V) -> f64 {
    dot(a, a).sqrt()
}

/// The rotated x, y and z axes of quaternion `w, x, y, z` (SolveSpace's U, V and N).
pub fn axes(q: [f64; 4]) -> (V, V, V) {
    let [w, x, y, z] = q;
    let u = [
        w * w + x * x - y * y - z * z,
        2.0 * (w * z + x * y),
        2.0 * (x * z - w * y),
    ];
    let v = [
        2.0 * (x * y - w * z),
        w * w - x * x + y * y - z * z,
        2.0 * (w * x + y * z),
    ];
    let n = [
        2.0 * (w * y + x * z),
        2.0 * (y * z - w * x),
        w * w - x * x - y * y + z * z,
    ];
    (u, v, n)
}

/// A workplane: origin and axes.
#[derive(Clone, Copy)]
pub struct Frame {
    o: V,
    u: V,
    v: V,
    n: V,
}

/// What a residual measures, for its tolerance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Unit {
    /// A length, compared relative to the size of the model.
    Length,
    /// A cosine, sine or other pure number.
    Pure,
}

/// The model's values, read independently.
pub struct Geo<'a> {
    /// The system.
    pub sys: &'a System,
}

impl<'a> Geo<'a> {
    /// Whether this reading models every entity of the system (points, normals, distances,
    /// workplanes, lines, cubics, circles and arcs, not moved copies) and every workplane is
    /// a rotation (a unit quaternion), so that 2D coordinates are lengths.
    pub fn models(sys: &System) -> bool {
        sys.entities().iter().all(|e| match &e.kind {
            EntityKind::PointNTrans { .. }
            | EntityKind::PointNRotTrans { .. }
            | EntityKind::NormalNRot { .. } => false,
            EntityKind::Workplane { normal, .. } => match sys.entity(*normal).map(|n| &n.kind) {
                Some(EntityKind::NormalIn3d { params }) => {
                    let n2: f64 = params
                        .iter()
                        .map(|&p| sys.value(p).unwrap_or(0.0).powi(2))
                        .sum();
                    (n2 - 1.0).abs() <= 1e-12
                }
                _ => false,
            },
            _ => true,
        })
    }

    fn val(&self, h: loci::ParamId) -> f64 {
        self.sys.value(h).expect("a parameter of a valid model")
    }

    fn kind(&self, h: EntityId) -> &'a EntityKind {
        &self.sys.entity(h).expect("an entity of a valid model").kind
    }

    /// The quaternion of a normal (a 2D normal: its workplane's).
    pub fn quat(&self, h: EntityId) -> [f64; 4] {
        let e = self.sys.entity(h).expect("an entity of a valid model");
        match &e.kind {
            EntityKind::NormalIn3d { params } => params.map(|p| self.val(p)),
            EntityKind::NormalIn2d => {
                let wp = e.workplane.expect("a 2D normal has a workplane");
                match self.kind(wp) {
                    EntityKind::Workplane { normal, .. } => self.quat(*normal),
                    _ => unreachable!("validated: a workplane"),
                }
            }
            other => panic!("not a normal this check models: {other:?}"),
        }
    }

    /// The N axis of a normal.
    pub fn normal_n(&self, h: EntityId) -> V {
        axes(self.quat(h)).2
    }

    /// Workplane `h`.
    pub fn frame(&self, h: EntityId) -> Frame {
        match self.kind(h) {
            EntityKind::Workplane { origin, normal } => {
                let (u, v, n) = axes(self.quat(*normal));
                Frame {
                    o: self.pos(*origin),
                    u,
                    v,
                    n,
                }
            }
            _ => unreachable!("validated: a workplane"),
        }
    }

    /// A point in space.
    pub fn pos(&self, h: EntityId) -> V {
        let e = self.sys.entity(h).expect("an entity of a valid model");
        match &e.kind {
            EntityKind::PointIn3d { params } => params.map(|p| self.val(p)),
            EntityKind::PointIn2d { params } => {
                let f = self.frame(e.workplane.expect("a 2D point has a workplane"));
                let (a, b) = (self.val(params[0]), self.val(params[1]));
                add(f.o, add(scale(f.u, a), scale(f.v, b)))
            }
            other => panic!("not a point this check models: {other:?}"),
        }
    }

    /// A point projected into `f` as (u, v, 0), or in space.
    pub fn at(&self, h: EntityId, f: Option<&Frame>) -> V {
        let p = self.pos(h);
        match f {
            None => p,
            Some(f) => {
                let d = sub(p, f.o);
                [dot(d, f.u), dot(d, f.v), 0.0]
            }
        }
    }

    fn dir_in(&self, d: V, f: Option<&Frame>) -> V {
        match f {
            None => d,
            Some(f) => [dot(d, f.u), dot(d, f.v), 0.0],
        }
    }

    fn line(&self, h: EntityId) -> [EntityId; 2] {
        match self.kind(h) {
            EntityKind::LineSegment { points } => *points,
            other => panic!("not a line: {other:?}"),
        }
    }

    /// A line's direction (start minus end) or a normal's N axis, projected into `f`.
    pub fn direction(&self, h: EntityId, f: Option<&Frame>) -> V {
        match self.kind(h) {
            EntityKind::LineSegment { points } => sub(self.at(points[0], f), self.at(points[1], f)),
            _ => self.dir_in(self.normal_n(h), f),
        }
    }

    /// A line's length in `f` (or in space).
    pub fn length(&self, h: EntityId, f: Option<&Frame>) -> f64 {
        let [a, b] = self.line(h);
        norm(sub(self.at(b, f), self.at(a, f)))
    }

    /// Distance from `p` to the line `l` in `f`: signed in a workplane (positive to the
    /// right of start to end), unsigned in space. `None` for a line of no length.
    pub fn pt_line(&self, p: EntityId, l: EntityId, f: Option<&Frame>) -> Option<f64> {
        let [a, b] = self.line(l);
        let a = self.at(a, f);
        let d = sub(self.at(b, f), a);
        let len = norm(d);
        if len < 1e-9 {
            return None;
        }
        let c = cross(d, sub(self.at(p, f), a));
        Some(match f {
            Some(_) => -c[2] / len,
            None => norm(c) / len,
        })
    }

    /// The radius of a circle (its distance, signed) or an arc (centre to start).
    pub fn radius(&self, h: EntityId) -> f64 {
        match self.kind(h) {
            EntityKind::Circle { radius, .. } => match self.kind(*radius) {
                EntityKind::Distance { param } => self.val(*param),
                _ => unreachable!("validated: a distance"),
            },
            EntityKind::ArcOfCircle { center, start, .. } => {
                norm(sub(self.pos(*start), self.pos(*center)))
            }
            other => panic!("not a circle: {other:?}"),
        }
    }

    fn circle_center_normal(&self, h: EntityId) -> (V, V) {
        let e = self.sys.entity(h).expect("an entity");
        match &e.kind {
            EntityKind::Circle { center, normal, .. } => {
                (self.pos(*center), self.normal_n(*normal))
            }
            EntityKind::ArcOfCircle { center, .. } => (
                self.pos(*center),
                self.frame(e.workplane.expect("an arc has a workplane")).n,
            ),
            other => panic!("not a circle: {other:?}"),
        }
    }

    /// The largest coordinate or radius in the model, at least 1: the scale of lengths.
    pub fn size(&self) -> f64 {
        self.sys
            .params()
            .iter()
            .map(|p| p.val.abs())
            .fold(1.0, f64::max)
    }

    fn plane_of(&self, c: &Constraint) -> Option<Frame> {
        match (c.kind.signature().plane, c.workplane) {
            (PlaneRule::Ignored, _) | (_, None) => None,
            (_, Some(w)) => Some(self.frame(w)),
        }
    }

    /// The current value of the dimension of a constraint that has one, as `val` would
    /// have to be for it to hold now; `None` for kinds this reading does not measure or
    /// degenerate geometry.
    pub fn measure(&self, c: &Constraint) -> Option<f64> {
        let f = self.plane_of(c);
        let f = f.as_ref();
        match c.kind {
            K::PtPtDistance => Some(norm(sub(self.at(c.pt_a?, f), self.at(c.pt_b?, f)))),
            K::PtLineDistance => self.pt_line(c.pt_a?, c.entity_a?, f),
            K::PtPlaneDistance | K::PtFaceDistance => {
                let w = self.frame(c.entity_a?);
                Some(dot(sub(self.pos(c.pt_a?), w.o), w.n) / norm(w.n))
            }
            K::ProjPtDistance => {
                let d = self.direction(c.entity_a?, None);
                let n = norm(d);
                let (a, b) = (self.pos(c.pt_a?), self.pos(c.pt_b?));
                (n > 1e-9).then(|| dot(sub(b, a), d) / n)
            }
            _ => self.measure_entities(c, f),
        }
    }

    fn measure_entities(&self, c: &Constraint, f: Option<&Frame>) -> Option<f64> {
        match c.kind {
            K::Diameter => Some(2.0 * self.radius(c.entity_a?)),
            K::Angle => {
                let (a, b) = (
                    self.direction(c.entity_a?, f),
                    self.direction(c.entity_b?, f),
                );
                let (na, nb) = (norm(a), norm(b));
                if na < 1e-9 || nb < 1e-9 {
                    return None;
                }
                let deg = (dot(a, b) / (na * nb)).clamp(-1.0, 1.0).acos().to_degrees();
                Some(if c.other { 180.0 - deg } else { deg })
            }
            K::LengthRatio => {
                let b = self.length(c.entity_b?, f);
                let a = self.length(c.entity_a?, f);
                (b > 1e-9).then(|| a / b)
            }
            K::LengthDifference => Some(self.length(c.entity_a?, f) - self.length(c.entity_b?, f)),
            _ => None,
        }
    }

    /// The residuals of constraint `c` (zero when it holds), each with its unit; `None` for
    /// kinds this reading does not model, reference constraints, and degenerate geometry
    /// (lines of no length, points on a circle's centre ...). `start` is the model before the
    /// solve, for `where_dragged`.
    pub fn residuals(&self, c: &Constraint, start: &Geo<'_>) -> Option<Vec<(f64, Unit)>> {
        use Unit::{Length as L, Pure as P};
        if c.reference {
            return None;
        }
        let f = self.plane_of(c);
        let f = f.as_ref();
        let tiny = 1e-9 * self.size();
        let unit = |a: V, b: V| -> Option<(V, V)> {
            let (na, nb) = (norm(a), norm(b));
            (na > tiny && nb > tiny).then(|| (scale(a, 1.0 / na), scale(b, 1.0 / nb)))
        };
        let v = c.val;
        Some(match c.kind {
            K::PointsCoincident => {
                let d = sub(self.at(c.pt_a?, f), self.at(c.pt_b?, f));
                d.iter().map(|&x| (x, L)).collect()
            }
            K::PtPtDistance => vec![(norm(sub(self.at(c.pt_a?, f), self.at(c.pt_b?, f))) - v, L)],
            K::PtPlaneDistance | K::PtFaceDistance | K::PtInPlane | K::PtOnFace => {
                let w = self.frame(c.entity_a?);
                let target = if matches!(c.kind, K::PtInPlane | K::PtOnFace) {
                    0.0
                } else {
                    v
                };
                vec![(
                    dot(sub(self.pos(c.pt_a?), w.o), w.n) / norm(w.n) - target,
                    L,
                )]
            }
            K::PtLineDistance => vec![(self.pt_line(c.pt_a?, c.entity_a?, f)? - v, L)],
            K::PtOnLine => vec![(self.pt_line(c.pt_a?, c.entity_a?, f)?, L)],
            K::EqualLengthLines => {
                vec![(self.length(c.entity_a?, f) - self.length(c.entity_b?, f), L)]
            }
            K::LengthRatio => vec![(
                self.length(c.entity_a?, f) - v * self.length(c.entity_b?, f),
                L,
            )],
            K::LengthDifference => vec![(
                self.length(c.entity_a?, f) - self.length(c.entity_b?, f) - v,
                L,
            )],
            K::EqLenPtLineD => vec![(
                self.length(c.entity_a?, f) - self.pt_line(c.pt_a?, c.entity_b?, f)?.abs(),
                L,
            )],
            K::EqPtLnDistances => vec![(
                self.pt_line(c.pt_a?, c.entity_a?, f)?.abs()
                    - self.pt_line(c.pt_b?, c.entity_b?, f)?.abs(),
                L,
            )],
            K::SymmetricHoriz | K::SymmetricVert => {
                let (a, b) = (self.at(c.pt_a?, f), self.at(c.pt_b?, f));
                if c.kind == K::SymmetricHoriz {
                    vec![(a[1] - b[1], L), (a[0] + b[0], L)]
                } else {
                    vec![(a[0] - b[0], L), (a[1] + b[1], L)]
                }
            }
            K::SymmetricLine => {
                let [l0, l1] = self.line(c.entity_a?);
                let (l0, l1) = (self.at(l0, f), self.at(l1, f));
                let (a, b) = (self.at(c.pt_a?, f), self.at(c.pt_b?, f));
                let d = sub(l1, l0);
                let len = norm(d);
                if len < tiny {
                    return None;
                }
                let mid = scale(add(a, b), 0.5);
                vec![
                    (cross(d, sub(mid, l0))[2] / len, L),
                    (dot(d, sub(b, a)) / len, L),
                ]
            }
            K::Symmetric if f.is_none() => {
                let w = self.frame(c.entity_a?);
                let (a, b) = (self.pos(c.pt_a?), self.pos(c.pt_b?));
                let n = scale(w.n, 1.0 / norm(w.n));
                let mid = scale(add(a, b), 0.5);
                let mut r = vec![(dot(sub(mid, w.o), n), L)];
                r.extend(cross(sub(b, a), n).iter().map(|&x| (x, L)));
                r
            }
            K::AtMidpoint => {
                let [l0, l1] = self.line(c.entity_a?);
                let mid = scale(add(self.at(l0, f), self.at(l1, f)), 0.5);
                let d = sub(self.at(c.pt_a?, f), mid);
                d.iter().map(|&x| (x, L)).collect()
            }
            K::Horizontal | K::Vertical => {
                let (a, b) = match c.entity_a {
                    Some(l) => {
                        let [a, b] = self.line(l);
                        (a, b)
                    }
                    None => (c.pt_a?, c.pt_b?),
                };
                let (a, b) = (self.at(a, f), self.at(b, f));
                let i = usize::from(c.kind == K::Horizontal);
                vec![(a[i] - b[i], L)]
            }
            K::Diameter => vec![(2.0 * self.radius(c.entity_a?) - v, L)],
            K::EqualRadius => vec![(self.radius(c.entity_a?) - self.radius(c.entity_b?), L)],
            K::PtOnCircle => {
                let (center, n) = self.circle_center_normal(c.entity_a?);
                let nn = norm(n);
                if nn < 1e-9 {
                    return None;
                }
                let d = sub(self.pos(c.pt_a?), center);
                let dn = dot(d, n) / nn;
                let in_plane = (dot(d, d) - dn * dn).max(0.0).sqrt();
                vec![(in_plane - self.radius(c.entity_a?).abs(), L)]
            }
            K::Angle => {
                let (a, b) = unit(
                    self.direction(c.entity_a?, f),
                    self.direction(c.entity_b?, f),
                )?;
                let t = if c.other { 180.0 - v } else { v }.to_radians();
                vec![(dot(a, b) - t.cos(), P)]
            }
            K::Parallel => {
                let (a, b) = unit(
                    self.direction(c.entity_a?, f),
                    self.direction(c.entity_b?, f),
                )?;
                cross(a, b).iter().map(|&x| (x, P)).collect()
            }
            K::Perpendicular => {
                let (a, b) = unit(
                    self.direction(c.entity_a?, f),
                    self.direction(c.entity_b?, f),
                )?;
                vec![(dot(a, b), P)]
            }
            K::ProjPtDistance => {
                let d = self.direction(c.entity_a?, None);
                let n = norm(d);
                if n < tiny {
                    return None;
                }
                vec![(dot(sub(self.pos(c.pt_b?), self.pos(c.pt_a?)), d) / n - v, L)]
            }
            K::WhereDragged => {
                // Where the point was in the workplane as it was (the workplane may move too).
                let f0 = start.plane_of(c);
                let d = sub(self.at(c.pt_a?, f), start.at(c.pt_a?, f0.as_ref()));
                d.iter().map(|&x| (x, L)).collect()
            }
            K::CubicLineTangent => {
                let EntityKind::Cubic { points } = self.kind(c.entity_a?) else {
                    return None;
                };
                let t = if c.other {
                    sub(self.at(points[3], f), self.at(points[2], f))
                } else {
                    sub(self.at(points[1], f), self.at(points[0], f))
                };
                let (a, b) = unit(t, self.direction(c.entity_b?, f))?;
                cross(a, b).iter().map(|&x| (x, P)).collect()
            }
            K::ArcLineTangent => {
                let e = self.sys.entity(c.entity_a?)?;
                let EntityKind::ArcOfCircle {
                    center, start, end, ..
                } = e.kind
                else {
                    return None;
                };
                let w = self.frame(e.workplane?);
                let p = if c.other { end } else { start };
                let r = sub(self.at(p, Some(&w)), self.at(center, Some(&w)));
                let (a, b) = unit(r, self.direction(c.entity_b?, Some(&w)))?;
                vec![(dot(a, b), P)]
            }
            K::SameOrientation => {
                let (ua, _, na) = axes(self.quat(c.entity_a?));
                let (ub, vb, nb) = axes(self.quat(c.entity_b?));
                let (na, nb) = unit(na, nb)?;
                let mut r: Vec<(f64, Unit)> = cross(na, nb).iter().map(|&x| (x, P)).collect();
                // U of a is perpendicular to V of b or to U of b (a quarter or half turn).
                let (ua, ub) = unit(ua, ub)?;
                let vb = scale(vb, 1.0 / norm(vb));
                r.push((dot(ua, ub).abs().min(dot(ua, vb).abs()), P));
                r
            }
            _ => return None,
        })
    }

    fn has_param_in(&self, h: EntityId, group: u32) -> bool {
        let e = self.sys.entity(h).expect("an entity");
        e.kind
            .params()
            .iter()
            .any(|&p| self.sys.param(p).is_some_and(|p| p.group.0 == group))
    }

    /// The residuals of the implicit conditions of entities in `group`: unit quaternions and
    /// equal arc radii. An entity none of whose parameters is in the group is left out: loci
    /// documents that its condition is no equation of the group (it belongs to a copy).
    pub fn implicit_residuals(&self, group: u32) -> Vec<(EntityId, f64, Unit)> {
        let mut out = Vec::new();
        for e in self.sys.entities() {
            if e.group.0 != group {
                continue;
            }
            let own = match &e.kind {
                EntityKind::ArcOfCircle {
                    center, start, end, ..
                } => [*center, *start, *end]
                    .iter()
                    .any(|&p| self.has_param_in(p, group)),
                _ => self.has_param_in(e.h, group),
            };
            if !own {
                continue;
            }
            match &e.kind {
                EntityKind::NormalIn3d { params } => {
                    let q = params.map(|p| self.val(p));
                    let n2: f64 = q.iter().map(|x| x * x).sum();
                    out.push((e.h, n2.sqrt() - 1.0, Unit::Pure));
                }
                EntityKind::ArcOfCircle {
                    center, start, end, ..
                } => {
                    let c = self.pos(*center);
                    let r0 = norm(sub(self.pos(*start), c));
                    let r1 = norm(sub(self.pos(*end), c));
                    out.push((e.h, r0 - r1, Unit::Length));
                }
                _ => {}
            }
        }
        out
    }
}
