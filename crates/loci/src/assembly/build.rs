//! From primitive relations to a core [`System`]: each free component's pose is seven
//! parameters (a translation and a `normal_in_3d` quaternion) in the solved group; its
//! references become `point_n_rot_trans` / `normal_n_rot` entities carried by that pose, so
//! every mate is a set of ordinary core constraints. The core reads those entities as
//! expressions of the pose, so a free component is seven unknowns however many references it
//! carries. Grounded components and the world are constants (plain points and normals in an
//! earlier group) and can never move.

use super::component::Pose;
use super::math::{self, V3};
use super::prim::{Body, Prim, D, L, P};
use crate::{
    Constraint, ConstraintKind as K, Entity, EntityId, ModelError, Param, ParamId, System,
};
use rustc_hash::FxHashMap as HashMap;

/// Whether directions other than a body's z axis are written as lines from its origin
/// instead of turned normals. Off: fewer unknowns, but Newton took five times the iterations
/// on a revolute chain (21 against 4 at 1,000 links), and the solve was slower overall.
const LINE_DIRECTIONS: bool = false;

/// The group of constants.
pub(crate) const FIXED: u32 = 1;
/// The solved group.
pub(crate) const FREE: u32 = 2;

/// A free component's pose in the system.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PoseParams {
    pub translation: [ParamId; 3],
    pub rotation: [ParamId; 4],
    /// The `normal_in_3d` of the rotation.
    pub normal: EntityId,
    /// A point carried at the component's origin.
    pub origin: EntityId,
}

/// The system and how to read it back.
pub(crate) struct Built {
    pub sys: System,
    /// Per component: its pose parameters when it is free.
    pub poses: Vec<Option<PoseParams>>,
    /// The mate (index) each constraint was written for, by constraint handle (handles are
    /// 1, 2, 3 ... in the order written: index 0 is unused).
    pub owner: Vec<usize>,
}

struct Builder<'a> {
    /// Whether signed angles are written exactly (see [`build`]).
    exact_angles: bool,
    sys: System,
    poses: &'a [Pose],
    free: Vec<Option<PoseParams>>,
    next_param: u32,
    next_entity: u32,
    next_constraint: u32,
    cache: HashMap<(Body, u8, [u64; 3]), EntityId>,
    owner: Vec<usize>,
}

/// Builds the system for `prims` (each with the index of its mate) at `poses`; `grounded`
/// says which components are constants. Parallel and orientation prims whose index `sensed`
/// holds are written by their sense (see [`Builder::prim`]), the others as a cross product,
/// which also holds with one direction reversed (an orientation, a quarter or half turn
/// off). With `exact_angles`, signed angles are written so that they hold at their target
/// only (B's direction seen in the plane normal to the axis), at some cost; without, as one
/// perpendicularity, which also holds at the target plus 180 degrees and where B's direction
/// lies along the axis.
pub(crate) fn build(
    poses: &[Pose],
    grounded: &[bool],
    prims: &[(usize, Prim)],
    exact_angles: bool,
    sensed: &[bool],
) -> Result<Built, ModelError> {
    let mut b = Builder {
        exact_angles,
        sys: System::new(),
        poses,
        free: vec![None; poses.len()],
        next_param: 1,
        next_entity: 1,
        next_constraint: 1,
        cache: HashMap::default(),
        owner: vec![usize::MAX],
    };
    for (i, pose) in poses.iter().enumerate() {
        if grounded[i] {
            continue;
        }
        let t = b.params(FREE, pose.translation)?;
        let q = b.params(FREE, pose.rotation)?;
        let normal = b.entity(Entity::normal_3d(0, FREE, q.map(|p| p.0)))?;
        b.free[i] = Some(PoseParams {
            translation: t,
            rotation: q,
            normal,
            origin: normal,
        });
        let origin = b.point(&P {
            body: Some(i),
            p: [0.0; 3],
        })?;
        if let Some(pp) = b.free[i].as_mut() {
            pp.origin = origin;
        }
    }
    for (k, &(mate, ref prim)) in prims.iter().enumerate() {
        b.prim(mate, prim, sensed.get(k).copied().unwrap_or(false))?;
    }
    Ok(Built {
        sys: b.sys,
        poses: b.free,
        owner: b.owner,
    })
}

impl Builder<'_> {
    fn param(&mut self, group: u32, v: f64) -> Result<ParamId, ModelError> {
        let h = self.next_param;
        self.next_param += 1;
        self.sys.add_param(Param::new(h, group, v))
    }

    fn params<const N: usize>(
        &mut self,
        group: u32,
        v: [f64; N],
    ) -> Result<[ParamId; N], ModelError> {
        let mut out = [ParamId(0); N];
        for (o, x) in out.iter_mut().zip(v) {
            *o = self.param(group, x)?;
        }
        Ok(out)
    }

    fn entity(&mut self, mut e: Entity) -> Result<EntityId, ModelError> {
        e.h = EntityId(self.next_entity);
        self.next_entity += 1;
        self.sys.add_entity(e)
    }

    fn pose(&self, b: Body) -> Pose {
        b.map_or(Pose::IDENTITY, |i| self.poses[i])
    }

    fn free(&self, b: Body) -> Option<PoseParams> {
        b.and_then(|i| self.free[i])
    }

    fn key(b: Body, kind: u8, v: V3) -> (Body, u8, [u64; 3]) {
        (b, kind, v.map(f64::to_bits))
    }

    fn point(&mut self, p: &P) -> Result<EntityId, ModelError> {
        let key = Self::key(p.body, 0, p.p);
        if let Some(&e) = self.cache.get(&key) {
            return Ok(e);
        }
        let w = self.pose(p.body).point(p.p);
        let e = match self.free(p.body) {
            Some(pp) => {
                let own = self.params(FREE, w)?.map(|p| p.0);
                self.entity(Entity::point_n_rot_trans(
                    0,
                    FREE,
                    own,
                    p.p,
                    pp.translation.map(|x| x.0),
                    pp.normal.0,
                ))?
            }
            None => {
                let own = self.params(FIXED, w)?.map(|p| p.0);
                self.entity(Entity::point_3d(0, FIXED, own))?
            }
        };
        self.cache.insert(key, e);
        Ok(e)
    }

    /// An entity whose direction is `d`, for parallel, perpendicular and angle relations: a
    /// normal turned onto it (for the body's z axis, a copy of the body's rotation that
    /// merges into the pose's parameters and costs nothing). See [`LINE_DIRECTIONS`].
    fn direction(&mut self, d: &D) -> Result<EntityId, ModelError> {
        if d.d == [0.0, 0.0, 1.0] || !LINE_DIRECTIONS {
            return self.normal(d);
        }
        let key = Self::key(d.body, 2, d.d);
        if let Some(&e) = self.cache.get(&key) {
            return Ok(e);
        }
        let e = self.line(&L {
            body: d.body,
            p: [0.0; 3],
            d: d.d,
        })?;
        self.cache.insert(key, e);
        Ok(e)
    }

    /// A normal whose axis is the direction `d` (a quaternion taking z onto it).
    fn normal(&mut self, d: &D) -> Result<EntityId, ModelError> {
        let key = Self::key(d.body, 1, d.d);
        if let Some(&e) = self.cache.get(&key) {
            return Ok(e);
        }
        let base = math::from_to([0.0, 0.0, 1.0], d.d);
        let e = self.normal_from(d.body, base)?;
        self.cache.insert(key, e);
        Ok(e)
    }

    fn normal_from(&mut self, body: Body, base: [f64; 4]) -> Result<EntityId, ModelError> {
        let w = math::qmul(self.pose(body).rotation, base);
        match self.free(body) {
            Some(pp) => {
                let own = self.params(FREE, w)?.map(|p| p.0);
                self.entity(Entity::normal_n_rot(0, FREE, own, base, pp.normal.0))
            }
            None => {
                let own = self.params(FIXED, w)?.map(|p| p.0);
                self.entity(Entity::normal_3d(0, FIXED, own))
            }
        }
    }

    fn group_of(&self, b: Body) -> u32 {
        if self.free(b).is_some() {
            FREE
        } else {
            FIXED
        }
    }

    /// A plane as its point and normal: the core's workplanes take only plain normals, so
    /// plane relations are written as signed distances along the normal
    /// (`proj_pt_distance`), which a plane carried by a pose can use.
    fn plane(&mut self, l: &L) -> Result<(EntityId, EntityId), ModelError> {
        Ok((self.point(&l.point())?, self.normal(&l.dir())?))
    }

    /// A workplane through `body`'s origin, normal to `axis` (in the body's frame), carried
    /// by the body.
    fn plane_of(&mut self, body: Body, axis: V3) -> Result<EntityId, ModelError> {
        let key = Self::key(body, 3, axis);
        if let Some(&e) = self.cache.get(&key) {
            return Ok(e);
        }
        // Only the plane's orientation enters a 2D angle between directions: its origin is
        // the fixed world origin, which ties nothing to the pose.
        let origin = self.point(&P {
            body: None,
            p: [0.0; 3],
        })?;
        let normal = self.normal(&D { body, d: axis })?;
        let g = self.group_of(body);
        let e = self.entity(Entity::workplane(0, g, origin.0, normal.0))?;
        self.cache.insert(key, e);
        Ok(e)
    }

    fn line(&mut self, l: &L) -> Result<EntityId, ModelError> {
        let a = self.point(&l.point())?;
        let b = self.point(&P {
            body: l.body,
            p: math::add(l.p, l.d),
        })?;
        let g = self.group_of(l.body);
        self.entity(Entity::line(0, g, None, a.0, b.0))
    }

    fn constraint(&mut self, mate: usize, c: Constraint) -> Result<(), ModelError> {
        let h = self.next_constraint;
        self.next_constraint += 1;
        self.sys.add_constraint(Constraint { h: h.into(), ..c })?;
        debug_assert_eq!(self.owner.len(), h as usize);
        self.owner.push(mate);
        Ok(())
    }

    fn prim(&mut self, mate: usize, prim: &Prim, sensed: bool) -> Result<(), ModelError> {
        let new = |k| Constraint::new(1, FREE, k);
        match *prim {
            Prim::Coincident(a, b) => {
                let (a, b) = (self.point(&a)?, self.point(&b)?);
                self.constraint(mate, new(K::PointsCoincident).with_points(a.0, b.0))
            }
            Prim::InPlane(p, l) => {
                let (p, (o, n)) = (self.point(&p)?, self.plane(&l)?);
                self.constraint(
                    mate,
                    new(K::ProjPtDistance)
                        .with_points(o.0, p.0)
                        .with_entities([n.0, 0, 0, 0]),
                )
            }
            Prim::OnLine(p, l) => {
                let (p, l) = (self.point(&p)?, self.line(&l)?);
                self.constraint(
                    mate,
                    new(K::PtOnLine)
                        .with_points(p.0, 0)
                        .with_entities([l.0, 0, 0, 0]),
                )
            }
            Prim::Parallel(a, b, flip) if sensed => {
                // B's direction along A's (against it with `flip`), as two 2D angles of zero
                // in workplanes A carries, normal to A's direction and to each other. The
                // cross product of the quick form also holds with B's direction the other
                // way; these hold only where B's direction has the sense its mate asks.
                let want = if flip { math::scale(a.d, -1.0) } else { a.d };
                let u = math::perpendicular(a.d);
                let v = math::cross(a.d, u);
                let nt = self.normal(&D {
                    body: a.body,
                    d: want,
                })?;
                let nb = self.normal(&b)?;
                for axis in [u, v] {
                    let wp = self.plane_of(a.body, axis)?;
                    let mut angle = new(K::Angle).with_entities([nt.0, nb.0, 0, 0]);
                    angle.workplane = Some(wp);
                    self.constraint(mate, angle)?;
                }
                Ok(())
            }
            Prim::Parallel(a, b, _) => {
                let (a, b) = (self.direction(&a)?, self.direction(&b)?);
                self.constraint(mate, new(K::Parallel).with_entities([a.0, b.0, 0, 0]))
            }
            Prim::Perpendicular(a, b) => {
                let (a, b) = (self.direction(&a)?, self.direction(&b)?);
                self.constraint(mate, new(K::Perpendicular).with_entities([a.0, b.0, 0, 0]))
            }
            Prim::PtPtDistance(a, b, d) => {
                let (a, b) = (self.point(&a)?, self.point(&b)?);
                self.constraint(mate, new(K::PtPtDistance).with_points(a.0, b.0).with_val(d))
            }
            Prim::PtPlaneDistance(p, l, d) => {
                let (p, (o, n)) = (self.point(&p)?, self.plane(&l)?);
                self.constraint(
                    mate,
                    new(K::ProjPtDistance)
                        .with_points(o.0, p.0)
                        .with_entities([n.0, 0, 0, 0])
                        .with_val(d),
                )
            }
            Prim::PtLineDistance(p, l, d) => {
                let (p, l) = (self.point(&p)?, self.line(&l)?);
                self.constraint(
                    mate,
                    new(K::PtLineDistance)
                        .with_points(p.0, 0)
                        .with_entities([l.0, 0, 0, 0])
                        .with_val(d),
                )
            }
            Prim::SameOrientation(a, b, rel) if sensed => {
                // B's frame turned exactly as A's times `rel`: its X axis along that frame's
                // (two 2D angles of zero in planes A carries, normal to the frame's Z and Y)
                // and its Y axis along the frame's, seen in the plane normal to its X. The
                // core's same orientation (N axes parallel either way, U normal to V or U)
                // also holds a quarter or half turn off, and Newton can end there: a fastened
                // joint, started far off, ended with its equations at 5e-15 and the part
                // turned half a turn.
                let [ex, ey, ez] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
                    .map(|v| math::rotate(rel, v));
                let ax = self.normal(&D { body: a, d: ex })?;
                let ay = self.normal(&D { body: a, d: ey })?;
                let bx = self.normal(&D {
                    body: b,
                    d: [1.0, 0.0, 0.0],
                })?;
                let by = self.normal(&D {
                    body: b,
                    d: [0.0, 1.0, 0.0],
                })?;
                for (axis, na, nb) in [(ez, ax, bx), (ey, ax, bx), (ex, ay, by)] {
                    let wp = self.plane_of(a, axis)?;
                    let mut angle = new(K::Angle).with_entities([na.0, nb.0, 0, 0]);
                    angle.workplane = Some(wp);
                    self.constraint(mate, angle)?;
                }
                Ok(())
            }
            Prim::SameOrientation(a, b, rel) => {
                let na = self.normal_from(a, rel)?;
                let nb = self.normal_from(b, math::IDENTITY)?;
                self.constraint(
                    mate,
                    new(K::SameOrientation).with_entities([na.0, nb.0, 0, 0]),
                )
            }
            Prim::SignedAngle { a, b, axis, target } if !self.exact_angles => {
                // B's direction normal to the direction a quarter turn past the target: one
                // cheap row, right wherever B's direction is held normal to the axis and
                // near the target (a hinge, after prealignment); checked after the solve.
                let (s, c) = target.sin_cos();
                let u = math::cross(axis, a.d);
                let dir = math::add(math::scale(a.d, -s), math::scale(u, c));
                let na = self.direction(&D {
                    body: a.body,
                    d: math::unit(dir).unwrap_or(u),
                })?;
                let nb = self.direction(&b)?;
                self.constraint(
                    mate,
                    new(K::Perpendicular).with_entities([na.0, nb.0, 0, 0]),
                )
            }
            Prim::SignedAngle { a, b, axis, target } => {
                // The direction at the target angle from A's about the axis, both held by A;
                // B's direction seen in the plane normal to the axis must point along it: a
                // 2D angle of zero in a workplane A carries. Unlike `b ⟂ (axis × t)` it
                // holds neither at the target plus 180 degrees nor where B's direction lies
                // along the axis (no angle about the axis there: the residual is half a turn).
                // The plane reads A's carried origin and axis by their own parameters, tied
                // to A's pose by their implicit equations, which a conflict set is checked
                // with: two angles that fight are named with or without a hinge.
                let (s, c) = target.sin_cos();
                let u = math::cross(axis, a.d);
                let t = math::add(math::scale(a.d, c), math::scale(u, s));
                let nt = self.normal(&D {
                    body: a.body,
                    d: math::unit(t).unwrap_or(a.d),
                })?;
                let nb = self.normal(&b)?;
                let wp = self.plane_of(a.body, axis)?;
                let mut angle = new(K::Angle).with_entities([nt.0, nb.0, 0, 0]);
                angle.workplane = Some(wp);
                self.constraint(mate, angle)
            }
        }
    }
}

/// The poses read back from solved values.
pub(crate) fn read_poses(sys: &System, built: &[Option<PoseParams>], poses: &mut [Pose]) {
    for (pose, pp) in poses.iter_mut().zip(built) {
        let Some(pp) = pp else { continue };
        let v = |p: ParamId| sys.value(p).unwrap_or(0.0);
        *pose = Pose::new(pp.translation.map(v), pp.rotation.map(v));
    }
}

/// Writes `poses` into the solved values, for another solve to go on from them.
pub(crate) fn write_poses(sys: &mut System, built: &[Option<PoseParams>], poses: &[Pose]) {
    for (pose, pp) in poses.iter().zip(built) {
        let Some(pp) = pp else { continue };
        for (&h, &v) in pp.translation.iter().zip(&pose.translation) {
            sys.set_value(h, v);
        }
        for (&h, &v) in pp.rotation.iter().zip(&pose.rotation) {
            sys.set_value(h, v);
        }
    }
}
