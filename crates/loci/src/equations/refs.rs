//! Entities resolved for evaluation: every parameter an equation reads becomes a local slot.

use super::carried::Carried;
use crate::error::ModelError;
use crate::geom::{Quat, Scalar, Vec3};
use crate::model::{EntityId, EntityKind, ObjectId, System};
use smallvec::SmallVec;

/// Index into an equation's local parameter list.
pub(crate) type Slot = u16;

/// A workplane: origin and orientation.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frame {
    pub id: EntityId,
    pub origin: [Slot; 3],
    pub q: [Slot; 4],
}

/// A point: three coordinates in space, or two in a workplane, or an expression of what
/// carries it (see [`super::carried`]).
#[derive(Clone, Copy, Debug)]
pub(crate) enum PointRef {
    P3([Slot; 3]),
    P2 {
        wp: Frame,
        uv: [Slot; 2],
    },
    /// A constant point carried by a rigid motion: `t + q base q*`, its base (x, y, z) the
    /// equation's constant `base` (kept apart so that every reference stays as small as a
    /// point of a workplane: sketches hold many).
    Moved {
        t: [Slot; 3],
        q: [Slot; 4],
        base: Konst,
    },
    /// A point moved by a multiple of a translation: `base + times t`.
    Shifted {
        base: [Slot; 3],
        t: [Slot; 3],
        times: i32,
    },
}

/// An orientation: a quaternion of its own, or a constant one turned by a rotation.
#[derive(Clone, Copy, Debug)]
pub(crate) enum NormalRef {
    Q([Slot; 4]),
    /// `q * base` (see [`super::carried`]), its base (w, x, y, z) the equation's constant
    /// `base`.
    Turned {
        q: [Slot; 4],
        base: Konst,
    },
}

/// Index into an equation's constants (the bases of carried entities).
pub(crate) type Konst = u16;

/// Any entity, resolved.
#[derive(Clone, Debug)]
pub(crate) enum Ent {
    Point(PointRef),
    Normal(NormalRef),
    Distance(Slot),
    Workplane(Frame),
    Line([PointRef; 2]),
    Cubic([PointRef; 4]),
    Circle {
        center: PointRef,
        q: NormalRef,
        radius: Slot,
    },
    Arc {
        center: PointRef,
        start: PointRef,
        end: PointRef,
        wp: Frame,
    },
}

/// The parameters one equation reads, as positions in [`System::params`].
#[derive(Clone, Debug)]
pub(crate) struct Locals {
    pub params: SmallVec<[u32; 16]>,
    /// The constants the equation reads (see [`Konst`]), moved into it once built.
    pub consts: Vec<[f64; 4]>,
    /// The workplane resolved last, already in these locals: the points of one constraint
    /// nearly always share it, and it is seven parameters to look up.
    last_frame: Option<Frame>,
}

impl Default for Locals {
    /// Room inline for a constraint on two lines in a workplane: most equations gather their
    /// parameters with no allocation (those that become parameter equalities need none).
    fn default() -> Self {
        Self {
            params: SmallVec::new(),
            consts: Vec::new(),
            last_frame: None,
        }
    }
}

impl Locals {
    pub fn slot(&mut self, param: usize) -> Slot {
        let p = param as u32;
        if let Some(i) = self.params.iter().position(|&q| q == p) {
            return i as Slot;
        }
        self.params.push(p);
        (self.params.len() - 1) as Slot
    }

    /// The index of constant `v` among the equation's constants.
    pub fn konst(&mut self, v: [f64; 4]) -> Konst {
        self.consts.push(v);
        (self.consts.len() - 1) as Konst
    }
}

/// Resolves entity handles into slot-based references.
pub(crate) struct Resolver<'a> {
    pub sys: &'a System,
    /// Every workplane, resolved once, by entity position: its origin and quaternion parameters
    /// (positions in [`System::params`]), or `None`. Every 2D point refers to its workplane, so
    /// this is hot. Filled before any constraint is resolved, so that one resolver serves many
    /// threads.
    frames: Vec<Option<[u32; 7]>>,
    /// The entities read as expressions of what carries them, if any.
    carried: Option<&'a Carried>,
}

impl<'a> Resolver<'a> {
    /// A resolver that reads every entity by its own parameters.
    pub fn new(sys: &'a System) -> Self {
        Self::with(sys, None)
    }

    /// A resolver that reads the entities of `carried` as expressions.
    pub fn carrying(sys: &'a System, carried: &'a Carried) -> Self {
        Self::with(sys, (!carried.is_empty()).then_some(carried))
    }

    fn with(sys: &'a System, carried: Option<&'a Carried>) -> Self {
        let mut r = Self {
            sys,
            frames: Vec::new(),
            carried,
        };
        let mut frames = vec![None; sys.entities().len()];
        let mut any = false;
        for (i, e) in sys.entities().iter().enumerate() {
            if !matches!(e.kind, EntityKind::Workplane { .. }) {
                continue;
            }
            let mut l = Locals::default();
            // A workplane that does not resolve is reported by the constraint that uses it.
            if let Ok(Ent::Workplane(f)) = r.entity(ObjectId::Entity(e.h), e.h, &mut l) {
                let mut g = [0u32; 7];
                for (o, &s) in g.iter_mut().zip(f.origin.iter().chain(&f.q)) {
                    *o = l.params[s as usize];
                }
                frames[i] = Some(g);
                any = true;
            }
        }
        if any {
            r.frames = frames;
        }
        r
    }

    /// Whether the entity at position `index` is read as an expression of what carries it.
    pub fn carries(&self, index: usize) -> bool {
        self.carried.is_some_and(|c| c.entity(index))
    }

    fn cached_frame(&self, h: EntityId, index: usize, l: &mut Locals) -> Option<Frame> {
        let g = (*self.frames.get(index)?)?;
        let mut s = [0; 7];
        for (o, p) in s.iter_mut().zip(g) {
            *o = l.slot(p as usize);
        }
        Some(Frame {
            id: h,
            origin: [s[0], s[1], s[2]],
            q: [s[3], s[4], s[5], s[6]],
        })
    }

    fn param(
        &self,
        owner: EntityId,
        h: crate::model::ParamId,
        l: &mut Locals,
    ) -> Result<Slot, ModelError> {
        let i = self.sys.param_index(h).ok_or(ModelError::Dangling {
            owner: ObjectId::Entity(owner),
            field: "params",
            target: "param",
            handle: h.0,
        })?;
        Ok(l.slot(i))
    }

    /// Resolves parameters `ps` read by entity `owner`.
    pub(crate) fn params<const N: usize>(
        &self,
        owner: EntityId,
        ps: &[crate::model::ParamId],
        l: &mut Locals,
    ) -> Result<[Slot; N], ModelError> {
        let mut out = [0; N];
        for (o, p) in out.iter_mut().zip(ps) {
            *o = self.param(owner, *p, l)?;
        }
        Ok(out)
    }

    fn dangling(owner: ObjectId, h: EntityId) -> ModelError {
        ModelError::Dangling {
            owner,
            field: "entity",
            target: "entity",
            handle: h.0,
        }
    }

    /// A carried point or normal (`h`, read elsewhere as an expression of what carries it)
    /// by its own parameters; `None` for any other entity.
    fn own(&self, h: EntityId, l: &mut Locals) -> Result<Option<Ent>, ModelError> {
        let Some(index) = self.sys.entity_index(h) else {
            return Ok(None);
        };
        if !self.carries(index) {
            return Ok(None);
        }
        Ok(match &self.sys.entities()[index].kind {
            EntityKind::PointNTrans { params, .. } | EntityKind::PointNRotTrans { params, .. } => {
                Some(Ent::Point(PointRef::P3(self.params(h, params, l)?)))
            }
            EntityKind::NormalNRot { params, .. } => {
                Some(Ent::Normal(NormalRef::Q(self.params(h, params, l)?)))
            }
            _ => None,
        })
    }

    /// Resolves entity `h`; `owner` is named in errors.
    pub fn entity(&self, owner: ObjectId, h: EntityId, l: &mut Locals) -> Result<Ent, ModelError> {
        self.entity_depth(owner, h, l, 0)
    }

    fn entity_depth(
        &self,
        owner: ObjectId,
        h: EntityId,
        l: &mut Locals,
        depth: u32,
    ) -> Result<Ent, ModelError> {
        if depth > 4 {
            return Err(ModelError::Cycle { entity: h });
        }
        if let Some(f) = l.last_frame.filter(|f| f.id == h) {
            return Ok(Ent::Workplane(f));
        }
        let index = self
            .sys
            .entity_index(h)
            .ok_or_else(|| Self::dangling(owner, h))?;
        if let Some(f) = self.cached_frame(h, index, l) {
            l.last_frame = Some(f);
            return Ok(Ent::Workplane(f));
        }
        let e = &self.sys.entities()[index];
        let me = ObjectId::Entity(h);
        let sub = |l: &mut Locals, r: EntityId| self.entity_depth(me, r, l, depth + 1);
        let point = |l: &mut Locals, r: EntityId| -> Result<PointRef, ModelError> {
            match sub(l, r)? {
                Ent::Point(p) => Ok(p),
                _ => Err(self.wrong(me, r, "a point")),
            }
        };
        let frame_of = |l: &mut Locals| -> Result<Frame, ModelError> {
            let wp = e.workplane.ok_or(ModelError::MissingField {
                owner: me,
                field: "workplane",
                expected: "a workplane",
            })?;
            match sub(l, wp)? {
                Ent::Workplane(f) => Ok(f),
                _ => Err(self.wrong(me, wp, "a workplane")),
            }
        };
        if self.carried.is_some_and(|c| c.entity(index)) {
            return self.carried_entity(h, &e.kind, l, depth);
        }
        Ok(match &e.kind {
            EntityKind::PointIn3d { params } => {
                Ent::Point(PointRef::P3(self.params(h, params, l)?))
            }
            // A translated (or moved) point has coordinates of its own; its tie to the base
            // is an implicit equation of its group, so everywhere else it is a point in 3D.
            EntityKind::PointNTrans { params, .. } | EntityKind::PointNRotTrans { params, .. } => {
                Ent::Point(PointRef::P3(self.params(h, params, l)?))
            }
            EntityKind::PointIn2d { params } => {
                let wp = frame_of(l)?;
                Ent::Point(PointRef::P2 {
                    wp,
                    uv: self.params(h, params, l)?,
                })
            }
            // Likewise a rotated normal has a quaternion of its own.
            EntityKind::NormalIn3d { params } | EntityKind::NormalNRot { params, .. } => {
                Ent::Normal(NormalRef::Q(self.params(h, params, l)?))
            }
            EntityKind::NormalIn2d => Ent::Normal(NormalRef::Q(frame_of(l)?.q)),
            EntityKind::Distance { param } => Ent::Distance(self.param(h, *param, l)?),
            EntityKind::Workplane { origin, normal } => {
                // A frame is read through its parameters: a carried origin or normal (a
                // workplane a rigid part carries) by its own, which its implicit equations
                // then tie to the pose (see `compile_group`).
                let o = match self.own(*origin, l)? {
                    Some(Ent::Point(PointRef::P3(s))) => s,
                    None => match sub(l, *origin)? {
                        Ent::Point(PointRef::P3(s)) => s,
                        _ => return Err(self.wrong(me, *origin, "a 3D point")),
                    },
                    _ => return Err(self.wrong(me, *origin, "a 3D point")),
                };
                let q = match self.own(*normal, l)? {
                    Some(Ent::Normal(NormalRef::Q(q))) => q,
                    None => match sub(l, *normal)? {
                        Ent::Normal(NormalRef::Q(q)) => q,
                        _ => return Err(self.wrong(me, *normal, "a normal")),
                    },
                    _ => return Err(self.wrong(me, *normal, "a normal")),
                };
                let f = Frame {
                    id: h,
                    origin: o,
                    q,
                };
                l.last_frame = Some(f);
                Ent::Workplane(f)
            }
            EntityKind::LineSegment { points } => {
                Ent::Line([point(l, points[0])?, point(l, points[1])?])
            }
            EntityKind::Cubic { points } => Ent::Cubic([
                point(l, points[0])?,
                point(l, points[1])?,
                point(l, points[2])?,
                point(l, points[3])?,
            ]),
            EntityKind::Circle {
                center,
                normal,
                radius,
            } => {
                let center = point(l, *center)?;
                let q = match sub(l, *normal)? {
                    Ent::Normal(q) => q,
                    _ => return Err(self.wrong(me, *normal, "a normal")),
                };
                let radius = match sub(l, *radius)? {
                    Ent::Distance(s) => s,
                    _ => return Err(self.wrong(me, *radius, "a distance")),
                };
                Ent::Circle { center, q, radius }
            }
            EntityKind::ArcOfCircle {
                center, start, end, ..
            } => {
                let wp = frame_of(l)?;
                Ent::Arc {
                    center: point(l, *center)?,
                    start: point(l, *start)?,
                    end: point(l, *end)?,
                    wp,
                }
            }
        })
    }

    /// An entity of [`Carried`] as the expression of what carries it: the parameters read
    /// are the carrier's, never its own.
    fn carried_entity(
        &self,
        h: EntityId,
        kind: &EntityKind,
        l: &mut Locals,
        depth: u32,
    ) -> Result<Ent, ModelError> {
        let me = ObjectId::Entity(h);
        let rotation = |l: &mut Locals, r: EntityId| match self.entity_depth(me, r, l, depth + 1)? {
            Ent::Normal(NormalRef::Q(q)) => Ok(q),
            _ => Err(self.wrong(me, r, "a 3D normal")),
        };
        Ok(match kind {
            EntityKind::PointNRotTrans {
                base,
                translation,
                rotation: rot,
                ..
            } => {
                let t = self.params(h, translation, l)?;
                // A point at the part's origin is its translation: it reads no rotation, so
                // its equations leave the rotation's columns of the Jacobian alone (a
                // revolute chain's pivots).
                if *base == [0.0; 3] {
                    return Ok(Ent::Point(PointRef::P3(t)));
                }
                let q = rotation(l, *rot)?;
                let [x, y, z] = *base;
                Ent::Point(PointRef::Moved {
                    t,
                    q,
                    base: l.konst([x, y, z, 0.0]),
                })
            }
            EntityKind::NormalNRot {
                base,
                rotation: rot,
                ..
            } => {
                let q = rotation(l, *rot)?;
                // Turned by nothing, it is the rotation itself.
                Ent::Normal(if *base == [1.0, 0.0, 0.0, 0.0] {
                    NormalRef::Q(q)
                } else {
                    NormalRef::Turned {
                        q,
                        base: l.konst(*base),
                    }
                })
            }
            EntityKind::PointNTrans {
                base,
                translation,
                times,
                ..
            } => {
                let b = match self.entity_depth(me, *base, l, depth + 1)? {
                    Ent::Point(PointRef::P3(s)) => s,
                    _ => return Err(self.wrong(me, *base, "a 3D point")),
                };
                Ent::Point(PointRef::Shifted {
                    base: b,
                    t: self.params(h, translation, l)?,
                    times: *times,
                })
            }
            _ => unreachable!("carried entities are moved points and normals"),
        })
    }

    fn wrong(&self, owner: ObjectId, h: EntityId, expected: &'static str) -> ModelError {
        match self.sys.entity(h) {
            Some(e) => ModelError::WrongKind {
                owner,
                field: "entity",
                entity: h,
                found: e.entity_type(),
                expected,
            },
            None => Self::dangling(owner, h),
        }
    }
}

/// Geometry read from local slot values and the equation's constants.
pub(crate) struct Geo<'a, S> {
    pub x: &'a [S],
    pub k: &'a [[f64; 4]],
}

impl<S: Scalar> Geo<'_, S> {
    #[inline]
    pub fn p(&self, s: Slot) -> S {
        self.x[s as usize]
    }

    #[inline]
    pub fn quat(&self, q: [Slot; 4]) -> Quat<S> {
        Quat {
            w: self.p(q[0]),
            x: self.p(q[1]),
            y: self.p(q[2]),
            z: self.p(q[3]),
        }
    }

    #[inline]
    pub fn v3(&self, s: [Slot; 3]) -> Vec3<S> {
        Vec3::new(self.p(s[0]), self.p(s[1]), self.p(s[2]))
    }

    /// An orientation's quaternion.
    #[inline]
    pub fn normal(&self, n: &NormalRef) -> Quat<S> {
        match n {
            NormalRef::Q(q) => self.quat(*q),
            NormalRef::Turned { q, base } => {
                let b = self.k[*base as usize];
                self.quat(*q).times(Quat {
                    w: S::cst(b[0]),
                    x: S::cst(b[1]),
                    y: S::cst(b[2]),
                    z: S::cst(b[3]),
                })
            }
        }
    }

    /// The point in space.
    pub fn pos(&self, p: &PointRef) -> Vec3<S> {
        match p {
            PointRef::P3(s) => self.v3(*s),
            // As a moved point's implicit equation has it: `q p q*` written with the
            // quaternion's rotated axes, `p.x U + p.y V + p.z N`.
            PointRef::Moved { t, q, base } => {
                let q = self.quat(*q);
                let b = self.k[*base as usize];
                let [bx, by, bz] = [b[0], b[1], b[2]].map(S::cst);
                self.v3(*t)
                    .plus(q.u().scale(bx))
                    .plus(q.v().scale(by))
                    .plus(q.n().scale(bz))
            }
            PointRef::Shifted { base, t, times } => self
                .v3(*base)
                .plus(self.v3(*t).scale(S::cst(f64::from(*times)))),
            PointRef::P2 { wp, uv } => {
                let q = self.quat(wp.q);
                let (u, v) = (self.p(uv[0]), self.p(uv[1]));
                self.v3(wp.origin).plus(q.u().scale(u)).plus(q.v().scale(v))
            }
        }
    }

    /// The point in workplane `wp` as (u, v, 0), or in space when `wp` is `None`.
    pub fn at(&self, p: &PointRef, wp: Option<&Frame>) -> Vec3<S> {
        match (p, wp) {
            (_, None) => self.pos(p),
            (PointRef::P2 { wp: own, uv }, Some(f)) if own.id == f.id => {
                Vec3::uv(self.p(uv[0]), self.p(uv[1]))
            }
            (_, Some(f)) => {
                let d = self.pos(p).minus(self.v3(f.origin));
                let q = self.quat(f.q);
                Vec3::uv(d.dot(q.u()), d.dot(q.v()))
            }
        }
    }

    /// A direction in space projected into `wp` (or left in space).
    pub fn project_dir(&self, d: Vec3<S>, wp: Option<&Frame>) -> Vec3<S> {
        match wp {
            None => d,
            Some(f) => {
                let q = self.quat(f.q);
                Vec3::uv(d.dot(q.u()), d.dot(q.v()))
            }
        }
    }

    /// End minus start of a line, in `wp` or in space.
    pub fn line_dir(&self, l: &[PointRef; 2], wp: Option<&Frame>) -> Vec3<S> {
        self.at(&l[1], wp).minus(self.at(&l[0], wp))
    }

    /// The normal vector of a workplane.
    pub fn plane_normal(&self, f: &Frame) -> Vec3<S> {
        self.quat(f.q).n()
    }
}
