//! Writing a loci [`System`] as a new `.slvs` file that SolveSpace 3.x opens.
//!
//! SolveSpace derives geometry from requests: a request owns its points, its normal and its
//! distance, and their handles follow from the request's (see [`super::load`]). loci
//! entities are free to share points, so the writer gives every line, cubic, circle, arc and
//! workplane its own request, lets the first of them that uses a point (or normal, or
//! distance) own it, and ties every later use to the owner with a constraint, as a
//! SolveSpace user would draw it: `points_coincident` for points (in the workplane when
//! both are points of it, else in 3D), `same_orientation` for normals and `equal_radius`
//! for a radius two circles share. A point that nothing uses is a datum point; a 3D normal
//! that nothing uses becomes the normal of a workplane request of its own.
//!
//! Groups: group 1 holds SolveSpace's three reference planes; each loci group becomes a
//! sketch in 3D (groups 2, 3, ... in ascending order of loci's handles), solved in that
//! order, each with the groups before it fixed.
//!
//! What is lost: handles (the writer returns the parameter map); the tie of translated and
//! moved copies (`point_n_trans`, `point_n_rot_trans`, `normal_n_rot`) to their base, which
//! are written as free points and normals with their current values; parameters no
//! written entity holds (such a copy's translation, a distance no circle uses) are written as
//! the coordinates of datum points of their group, so their values survive but nothing ties
//! them; faces (SolveSpace makes them only for solids), so `pt_on_face` and
//! `pt_face_distance` are written as `pt_in_plane` and `pt_plane_distance`, whose equations
//! are the same; the choice of branch `same_orientation` makes, which allows quarter
//! turns; and the sign of a `signed` angle: SolveSpace's angle has a size only, and keeps
//! the turn the lines have in the file (the one a solved signed angle has).

use super::codes::GroupKind;
use super::records::MAGIC;
use crate::geom::Quat;
use crate::model::{
    Constraint, ConstraintKind, Entity, EntityId, EntityKind, GroupId, ParamId, System,
};
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fmt::Write;
use thiserror::Error;

/// A system the writer cannot express as a `.slvs` file.
#[derive(Clone, Debug, Error, PartialEq)]
#[non_exhaustive]
pub enum ExportError {
    /// The model is invalid (a dangling reference, a wrong entity type ...). The message
    /// holds the model error's text, so it is not also given as the source.
    #[error("invalid model: {0}")]
    Model(crate::ModelError),
    /// More requests than SolveSpace's handles can number (a request's handle is its upper
    /// 16 bits, below the bits that mark generated and constraint parameters).
    #[error("the system needs {needed} requests; a .slvs file holds at most {MAX_REQUESTS}")]
    TooLarge {
        /// How many the system needs at least.
        needed: usize,
    },
    /// An entity SolveSpace has no way to hold in this place.
    #[error("entity {entity}: {why}")]
    Unsupported {
        /// The entity.
        entity: EntityId,
        /// Why.
        why: &'static str,
    },
}

impl From<crate::ModelError> for ExportError {
    fn from(e: crate::ModelError) -> Self {
        ExportError::Model(e)
    }
}

/// A written file and where each of loci's parameters went.
#[derive(Clone, Debug)]
pub struct Export {
    /// The file's bytes.
    pub bytes: Vec<u8>,
    /// loci's parameter handle -> the file's parameter holding it.
    pub params: BTreeMap<ParamId, ParamId>,
    /// loci's group handle -> the file's group.
    pub groups: BTreeMap<GroupId, GroupId>,
}

/// The most requests a file can hold: handles from 1 up to where SolveSpace's constraint
/// parameters (`0x4000_0000 | ...`) begin.
const MAX_REQUESTS: u32 = 0x3fff;

/// SolveSpace's request types.
const REQ_WORKPLANE: u32 = 100;
const REQ_DATUM_POINT: u32 = 101;
const REQ_LINE: u32 = 200;
const REQ_CUBIC: u32 = 300;
const REQ_CIRCLE: u32 = 400;
const REQ_ARC: u32 = 500;

/// SolveSpace's entity types.
const E_POINT_3D: u32 = 2000;
const E_POINT_2D: u32 = 2001;
const E_NORMAL_3D: u32 = 3000;
const E_NORMAL_2D: u32 = 3001;
const E_DISTANCE: u32 = 4000;
const E_WORKPLANE: u32 = 10000;
const E_LINE: u32 = 11000;
const E_CUBIC: u32 = 12000;
const E_CIRCLE: u32 = 13000;
const E_ARC: u32 = 14000;

/// The file's constraint type number of `kind`.
fn constraint_code(kind: ConstraintKind) -> i64 {
    (0..=1000)
        .find(|&c| super::codes::constraint(c) == Some(super::codes::ConstraintCode::Kind(kind)))
        .unwrap_or(0)
}

/// The kind written for `kind`. A SolveSpace face comes only from a solid, which the writer
/// never makes: loci's faces are workplanes, so constraints on faces are written as the same
/// constraints on planes (their equations are the same).
fn written_kind(kind: ConstraintKind) -> ConstraintKind {
    match kind {
        ConstraintKind::PtOnFace => ConstraintKind::PtInPlane,
        ConstraintKind::PtFaceDistance => ConstraintKind::PtPlaneDistance,
        k => k,
    }
}

/// A constraint to write, and which of its handles are already the file's.
enum Queued {
    /// One of loci's: every handle is loci's.
    Loci(Constraint),
    /// A tie the writer adds: `pt_a` / `entity_a` is a file handle, the other side loci's.
    Tie(Constraint),
    /// A tie between two file entities, `entity_a` and `entity_b`.
    File(Constraint),
}

/// One entity record to write.
struct Ent {
    h: u32,
    kind: u32,
    workplane: u32,
    points: Vec<u32>,
    normal: u32,
    distance: u32,
}

struct Req {
    h: u32,
    kind: u32,
    group: u32,
    workplane: u32,
}

struct Writer<'a> {
    sys: &'a System,
    groups: BTreeMap<GroupId, GroupId>,
    next_request: u32,
    requests: Vec<Req>,
    entities: Vec<Ent>,
    params: Vec<(u32, f64)>,
    constraints: Vec<Queued>,
    /// loci entity -> the file entity that owns it (points, normals, distances,
    /// workplanes, and every request's main entity).
    owner: HashMap<EntityId, u32>,
    map: BTreeMap<ParamId, ParamId>,
    /// Circles by the radius entity they own, for `equal_radius` ties.
    radius_circle: HashMap<EntityId, u32>,
}

/// Writes `sys` as a `.slvs` file.
///
/// # Errors
/// An invalid model, an entity SolveSpace cannot hold (an arc outside a workplane, a circle
/// whose radius is not a distance), or more requests than a file can number.
pub fn export(sys: &System) -> Result<Export, ExportError> {
    sys.validate()?;
    let mut loci_groups: BTreeSet<GroupId> = sys.params().iter().map(|p| p.group).collect();
    loci_groups.extend(sys.entities().iter().map(|e| e.group));
    loci_groups.extend(sys.constraints().iter().map(|c| c.group));
    let groups = loci_groups
        .iter()
        .enumerate()
        .map(|(i, &g)| (g, GroupId(i as u32 + 2)))
        .collect();
    let mut w = Writer {
        sys,
        groups,
        next_request: 4,
        requests: Vec::new(),
        entities: Vec::new(),
        params: Vec::new(),
        constraints: Vec::new(),
        owner: HashMap::new(),
        map: BTreeMap::new(),
        radius_circle: HashMap::new(),
    };
    w.references();
    // Workplanes first (2D points need theirs), then the entities that own points, then
    // whatever is left on its own.
    for e in sys.entities() {
        if let EntityKind::Workplane { origin, normal } = e.kind {
            w.workplane(e, Some(origin), Some(normal))?;
        }
    }
    for e in sys.entities() {
        match e.kind {
            EntityKind::LineSegment { points } => w.curve(e, REQ_LINE, E_LINE, &points)?,
            EntityKind::Cubic { points } => w.curve(e, REQ_CUBIC, E_CUBIC, &points)?,
            EntityKind::Circle { .. } => w.circle(e)?,
            EntityKind::ArcOfCircle { .. } => w.arc(e)?,
            _ => {}
        }
    }
    for e in sys.entities() {
        if w.owner.contains_key(&e.h) {
            continue;
        }
        if e.entity_type().is_point() {
            let r = w.request(REQ_DATUM_POINT, e.group, e.workplane)?;
            // A datum point is its request's entity 0.
            w.point_at(e.h, (r, e.group), 0, e.workplane)?;
        } else if e.entity_type().is_normal_3d() {
            w.workplane(e, None, Some(e.h))?;
        }
    }
    w.loose_params()?;
    for c in sys.constraints() {
        w.constraint(c)?;
    }
    let mut bytes = MAGIC.to_vec();
    bytes.extend_from_slice(w.text().as_bytes());
    Ok(Export {
        bytes,
        params: w.map,
        groups: w.groups,
    })
}

impl<'a> Writer<'a> {
    fn group(&self, g: GroupId) -> u32 {
        self.groups[&g].0
    }

    fn value(&self, p: ParamId) -> f64 {
        self.sys.value(p).unwrap_or(0.0)
    }

    /// Parameters no written entity holds (a copy's translation, say) become the
    /// coordinates of datum points in 3D of their group, three at a time, so every value
    /// has a place in the file.
    fn loose_params(&mut self) -> Result<(), ExportError> {
        let mut loose: BTreeMap<GroupId, Vec<ParamId>> = BTreeMap::new();
        for p in self.sys.params() {
            if !self.map.contains_key(&p.h) {
                loose.entry(p.group).or_default().push(p.h);
            }
        }
        for (g, ps) in loose {
            for chunk in ps.chunks(3) {
                let r = self.take_request()?;
                self.requests.push(Req {
                    h: r,
                    kind: REQ_DATUM_POINT,
                    group: self.group(g),
                    workplane: 0,
                });
                for i in 0..3 {
                    let h = r << 16 | (16 + i as u32);
                    let v = chunk.get(i).map_or(0.0, |&p| self.value(p));
                    self.params.push((h, v));
                    if let Some(&p) = chunk.get(i) {
                        self.map.insert(p, ParamId(h));
                    }
                }
                self.push_ent(r << 16, E_POINT_3D, 0, vec![], 0, 0);
            }
        }
        Ok(())
    }

    /// SolveSpace's three reference planes in group 1: requests 1..3 with their origin at
    /// zero and normals along z, x and y.
    fn references(&mut self) {
        let quats = [
            [1.0, 0.0, 0.0, 0.0],
            [0.5, 0.5, 0.5, 0.5],
            [0.5, -0.5, -0.5, -0.5],
        ];
        for (i, q) in quats.into_iter().enumerate() {
            let r = i as u32 + 1;
            self.requests.push(Req {
                h: r,
                kind: REQ_WORKPLANE,
                group: 1,
                workplane: 0,
            });
            let b = r << 16;
            for k in 0..3 {
                self.params.push((b | (16 + k), 0.0));
            }
            for (k, v) in q.into_iter().enumerate() {
                self.params.push((b | (32 + k as u32), v));
            }
            self.push_ent(b, E_WORKPLANE, 0, vec![b | 1], b | 32, 0);
            self.push_ent(b | 1, E_POINT_3D, 0, vec![], 0, 0);
            self.push_ent(b | 32, E_NORMAL_3D, 0, vec![b | 1], 0, 0);
        }
    }

    fn push_ent(&mut self, h: u32, kind: u32, wp: u32, points: Vec<u32>, normal: u32, dist: u32) {
        self.entities.push(Ent {
            h,
            kind,
            workplane: wp,
            points,
            normal,
            distance: dist,
        });
    }

    fn request(
        &mut self,
        kind: u32,
        group: GroupId,
        wp: Option<EntityId>,
    ) -> Result<u32, ExportError> {
        let workplane = match wp {
            Some(w) => self.workplane_of(w)?,
            None => 0,
        };
        let r = self.take_request()?;
        self.requests.push(Req {
            h: r,
            kind,
            group: self.group(group),
            workplane,
        });
        Ok(r)
    }

    fn take_request(&mut self) -> Result<u32, ExportError> {
        let r = self.next_request;
        if r > MAX_REQUESTS {
            return Err(ExportError::TooLarge { needed: r as usize });
        }
        self.next_request += 1;
        Ok(r)
    }

    /// The file workplane of loci workplane `w`.
    fn workplane_of(&self, w: EntityId) -> Result<u32, ExportError> {
        self.owner.get(&w).copied().ok_or(ExportError::Unsupported {
            entity: w,
            why: "its workplane is not written",
        })
    }

    /// The file point `k` of request `r` (entity 0 for a datum point), owning loci point `p`
    /// when it fits (a point of the request's workplane, or a 3D point for a request in 3D)
    /// and nothing owns it yet; else a point of its own at `p`'s position, tied to `p`'s
    /// owner (written later) by a coincident constraint.
    fn point_at(
        &mut self,
        p: EntityId,
        (r, group): (u32, GroupId),
        k: u32,
        wp: Option<EntityId>,
    ) -> Result<u32, ExportError> {
        let e = self.entity(p)?;
        let h = r << 16 | k;
        let n = k.saturating_sub(1);
        let base = r << 16 | (16 + 3 * n);
        let file_wp = match wp {
            Some(w) => self.workplane_of(w)?,
            None => 0,
        };
        let fits = match (&e.kind, wp) {
            (EntityKind::PointIn2d { .. }, Some(w)) => e.workplane == Some(w),
            (EntityKind::PointIn2d { .. }, None) => false,
            (_, None) => true,
            (_, Some(_)) => false,
        };
        // A request's points are unknowns of its group: it owns only points of that group.
        let own = fits && e.group == group && !self.owner.contains_key(&p);
        let values: Vec<f64> = if own {
            e.kind.params().iter().map(|&q| self.value(q)).collect()
        } else {
            let pos = self.position(p)?;
            match wp {
                Some(w) => self.project(w, pos)?.to_vec(),
                None => pos.to_vec(),
            }
        };
        for (i, v) in values.iter().enumerate() {
            self.params.push((base + i as u32, *v));
        }
        if own {
            for (i, &q) in e.kind.params().iter().enumerate() {
                self.map.insert(q, ParamId(base + i as u32));
            }
            self.owner.insert(p, h);
        } else {
            // Tie the copy to the loci point (mapped when constraints are written).
            let both_in = match (wp, e.workplane, &e.kind) {
                (Some(w), Some(pw), EntityKind::PointIn2d { .. }) if w == pw => Some(w),
                _ => None,
            };
            // The tie belongs to the later of the two groups, which solves it.
            let c = Constraint::new(0, e.group.max(group).0, ConstraintKind::PointsCoincident)
                .in_workplane(both_in.map(|w| w.0))
                .with_points(h, p.0);
            self.ties(c);
        }
        let kind = if wp.is_some() { E_POINT_2D } else { E_POINT_3D };
        self.push_ent(h, kind, file_wp, vec![], 0, 0);
        Ok(h)
    }

    /// A tie the writer adds: `pt_a` / `entity_a` is already a file handle, the other side
    /// a loci handle.
    fn ties(&mut self, c: Constraint) {
        self.constraints.push(Queued::Tie(c));
    }

    fn entity(&self, h: EntityId) -> Result<&'a Entity, ExportError> {
        self.sys
            .entity(h)
            .ok_or(ExportError::Model(crate::ModelError::Dangling {
                owner: crate::ObjectId::Entity(h),
                field: "entity",
                target: "entity",
                handle: h.0,
            }))
    }

    /// Where loci point `p` is in space.
    fn position(&self, p: EntityId) -> Result<[f64; 3], ExportError> {
        let e = self.entity(p)?;
        match &e.kind {
            EntityKind::PointIn2d { params } => {
                let w = e.workplane.ok_or(ExportError::Unsupported {
                    entity: p,
                    why: "a 2D point without a workplane",
                })?;
                let (o, q) = self.frame(w)?;
                let (u, v) = (self.value(params[0]), self.value(params[1]));
                let (qu, qv) = (q.u(), q.v());
                Ok([0, 1, 2].map(|i| o[i] + u * qu.at(i) + v * qv.at(i)))
            }
            k => {
                let ps = k.params();
                Ok([0, 1, 2].map(|i| ps.get(i).map_or(0.0, |&q| self.value(q))))
            }
        }
    }

    fn quat(&self, n: EntityId) -> Result<Quat<f64>, ExportError> {
        let e = self.entity(n)?;
        match &e.kind {
            EntityKind::NormalIn3d { params } | EntityKind::NormalNRot { params, .. } => {
                let [w, x, y, z] = params.map(|p| self.value(p));
                Ok(Quat { w, x, y, z })
            }
            EntityKind::NormalIn2d => {
                let w = e.workplane.ok_or(ExportError::Unsupported {
                    entity: n,
                    why: "a 2D normal without a workplane",
                })?;
                Ok(self.frame(w)?.1)
            }
            _ => Err(ExportError::Unsupported {
                entity: n,
                why: "not a normal",
            }),
        }
    }

    fn frame(&self, w: EntityId) -> Result<([f64; 3], Quat<f64>), ExportError> {
        match self.entity(w)?.kind {
            EntityKind::Workplane { origin, normal } => {
                Ok((self.position(origin)?, self.quat(normal)?))
            }
            _ => Err(ExportError::Unsupported {
                entity: w,
                why: "not a workplane",
            }),
        }
    }

    fn project(&self, w: EntityId, p: [f64; 3]) -> Result<[f64; 2], ExportError> {
        let (o, q) = self.frame(w)?;
        let d = crate::geom::Vec3::new(p[0] - o[0], p[1] - o[1], p[2] - o[2]);
        Ok([d.dot(q.u()), d.dot(q.v())])
    }

    /// The 3D normal at entity 32 of request `r`, owning loci normal `n` when nothing owns it
    /// yet, else a copy tied by `same_orientation`.
    fn normal_3d_at(
        &mut self,
        n: EntityId,
        (r, group): (u32, GroupId),
        point: u32,
    ) -> Result<u32, ExportError> {
        let h = r << 16 | 32;
        let q = self.quat(n)?;
        let e = self.entity(n)?;
        let same_group = e.group == group;
        let tie_group = e.group.max(group);
        let own_params: Option<Vec<ParamId>> = match &e.kind {
            EntityKind::NormalIn3d { params } | EntityKind::NormalNRot { params, .. } => {
                Some(params.to_vec())
            }
            _ => None,
        };
        for (i, v) in [q.w, q.x, q.y, q.z].into_iter().enumerate() {
            self.params.push((r << 16 | (32 + i as u32), v));
        }
        match own_params.filter(|_| same_group && !self.owner.contains_key(&n)) {
            Some(ps) => {
                for (i, p) in ps.into_iter().enumerate() {
                    self.map.insert(p, ParamId(r << 16 | (32 + i as u32)));
                }
                self.owner.insert(n, h);
            }
            None => {
                let c = Constraint::new(0, tie_group.0, ConstraintKind::SameOrientation)
                    .with_entities([h, n.0, 0, 0]);
                self.ties(c);
            }
        }
        self.push_ent(h, E_NORMAL_3D, 0, vec![point], 0, 0);
        Ok(h)
    }

    /// A workplane request for loci workplane `e` (or, with no origin, a request that only
    /// holds the 3D normal `normal`).
    fn workplane(
        &mut self,
        e: &'a Entity,
        origin: Option<EntityId>,
        normal: Option<EntityId>,
    ) -> Result<(), ExportError> {
        let r = self.request(REQ_WORKPLANE, e.group, None)?;
        let b = r << 16;
        let pt = match origin {
            Some(o) => self.point_at(o, (r, e.group), 1, None)?,
            None => {
                let pos = [0.0; 3];
                for (i, v) in pos.into_iter().enumerate() {
                    self.params.push((b | (16 + i as u32), v));
                }
                self.push_ent(b | 1, E_POINT_3D, 0, vec![], 0, 0);
                b | 1
            }
        };
        if let Some(n) = normal {
            self.normal_3d_at(n, (r, e.group), pt)?;
        }
        // Only a loci workplane is this file workplane; a normal's carrier is not.
        if origin.is_some() {
            self.owner.insert(e.h, b);
        }
        self.push_ent(b, E_WORKPLANE, 0, vec![pt], b | 32, 0);
        Ok(())
    }

    fn curve(
        &mut self,
        e: &Entity,
        req: u32,
        kind: u32,
        points: &[EntityId],
    ) -> Result<(), ExportError> {
        let r = self.request(req, e.group, e.workplane)?;
        let mut hs = Vec::new();
        for (i, &p) in points.iter().enumerate() {
            hs.push(self.point_at(p, (r, e.group), i as u32 + 1, e.workplane)?);
        }
        let wp = match e.workplane {
            Some(w) => self.workplane_of(w)?,
            None => 0,
        };
        self.push_ent(r << 16, kind, wp, hs, 0, 0);
        self.owner.insert(e.h, r << 16);
        Ok(())
    }

    /// The normal of a request drawn in workplane `wp`: a 2D normal (SolveSpace's normal in
    /// 2D copies its workplane's).
    fn normal_2d_at(&mut self, n: EntityId, r: u32, wp: u32, point: u32) -> u32 {
        let h = r << 16 | 32;
        self.owner.entry(n).or_insert(h);
        self.push_ent(h, E_NORMAL_2D, wp, vec![point], 0, 0);
        h
    }

    fn circle(&mut self, e: &Entity) -> Result<(), ExportError> {
        let EntityKind::Circle {
            center,
            normal,
            radius,
        } = e.kind
        else {
            return Ok(());
        };
        // In a workplane when its normal is that workplane's; else free in 3D.
        let planar = e.workplane.filter(|&w| {
            self.sys
                .entity(normal)
                .is_some_and(|n| n.kind == EntityKind::NormalIn2d && n.workplane == Some(w))
        });
        let r = self.request(REQ_CIRCLE, e.group, planar)?;
        let b = r << 16;
        let c = self.point_at(center, (r, e.group), 1, planar)?;
        let n = match planar {
            Some(w) => {
                let fw = self.workplane_of(w)?;
                self.normal_2d_at(normal, r, fw, c)
            }
            None => self.normal_3d_at(normal, (r, e.group), c)?,
        };
        let d = b | 64;
        let rp = match self.entity(radius)?.kind {
            EntityKind::Distance { param } => param,
            _ => {
                return Err(ExportError::Unsupported {
                    entity: radius,
                    why: "a circle's radius must be a distance",
                })
            }
        };
        self.params.push((d, self.value(rp)));
        let fw = match planar {
            Some(w) => self.workplane_of(w)?,
            None => 0,
        };
        let radius_group = self.entity(radius)?.group;
        match self.radius_circle.get(&radius) {
            // A radius of an earlier group is written as a value of the circle's own.
            None if radius_group != e.group => {}
            None => {
                self.map.insert(rp, ParamId(d));
                self.owner.insert(radius, d);
                self.radius_circle.insert(radius, b);
            }
            Some(&first) => {
                let c = Constraint::new(0, e.group.0, ConstraintKind::EqualRadius)
                    .with_entities([b, first, 0, 0]);
                self.constraints.push(Queued::File(c));
            }
        }
        self.push_ent(d, E_DISTANCE, fw, vec![], 0, 0);
        self.push_ent(b, E_CIRCLE, fw, vec![c], n, d);
        self.owner.insert(e.h, b);
        Ok(())
    }

    fn arc(&mut self, e: &Entity) -> Result<(), ExportError> {
        let EntityKind::ArcOfCircle {
            normal,
            center,
            start,
            end,
        } = e.kind
        else {
            return Ok(());
        };
        let Some(w) = e.workplane else {
            return Err(ExportError::Unsupported {
                entity: e.h,
                why: "an arc needs a workplane",
            });
        };
        let r = self.request(REQ_ARC, e.group, Some(w))?;
        let b = r << 16;
        let fw = self.workplane_of(w)?;
        let c = self.point_at(center, (r, e.group), 1, Some(w))?;
        let s = self.point_at(start, (r, e.group), 2, Some(w))?;
        let f = self.point_at(end, (r, e.group), 3, Some(w))?;
        let n = self.normal_2d_at(normal, r, fw, c);
        self.push_ent(b, E_ARC, fw, vec![c, s, f], n, 0);
        self.owner.insert(e.h, b);
        Ok(())
    }

    /// Queues loci constraint `c`, its handles mapped when the text is written.
    fn constraint(&mut self, c: &Constraint) -> Result<(), ExportError> {
        for h in c.fields().into_iter().flatten().chain(c.workplane) {
            self.file_entity(h)?;
        }
        self.constraints.push(Queued::Loci(c.clone()));
        Ok(())
    }

    /// A loci entity's file handle.
    fn file_entity(&self, h: EntityId) -> Result<u32, ExportError> {
        self.owner.get(&h).copied().ok_or(ExportError::Unsupported {
            entity: h,
            why: "nothing SolveSpace draws holds it",
        })
    }

    fn text(&mut self) -> String {
        let mut s = String::from("\n\n\n");
        let _ = write!(
            s,
            "Group.h.v=00000001\nGroup.type={}\nGroup.order=0\nGroup.name=#references\n\
             Group.remap={{\n}}\nAddGroup\n\n",
            GroupKind::Drawing3d.code()
        );
        for (i, (loci, g)) in self.groups.iter().enumerate() {
            let _ = write!(
                s,
                "Group.h.v={:08x}\nGroup.type={}\nGroup.order={}\nGroup.name=g{}\n\
                 Group.activeWorkplane.v=00010000\nGroup.remap={{\n}}\nAddGroup\n\n",
                g.0,
                GroupKind::Drawing3d.code(),
                i + 1,
                loci.0
            );
        }
        let mut params = std::mem::take(&mut self.params);
        params.sort_by_key(|p| p.0);
        for (h, v) in params {
            let _ = writeln!(s, "Param.h.v.={h:08x}");
            if v != 0.0 {
                let _ = writeln!(s, "Param.val={v:.20}");
            }
            s.push_str("AddParam\n\n");
        }
        for r in &self.requests {
            let _ = writeln!(s, "Request.h.v={:08x}\nRequest.type={}", r.h, r.kind);
            if r.workplane != 0 {
                let _ = writeln!(s, "Request.workplane.v={:08x}", r.workplane);
            }
            let _ = write!(
                s,
                "Request.group.v={:08x}\nRequest.construction=0\nAddRequest\n\n",
                r.group
            );
        }
        self.entities.sort_by_key(|e| e.h);
        for e in &self.entities {
            let _ = writeln!(
                s,
                "Entity.h.v={:08x}\nEntity.type={}\nEntity.construction=0",
                e.h, e.kind
            );
            for (i, p) in e.points.iter().enumerate() {
                let _ = writeln!(s, "Entity.point[{i}].v={p:08x}");
            }
            if e.normal != 0 {
                let _ = writeln!(s, "Entity.normal.v={:08x}", e.normal);
            }
            if e.distance != 0 {
                let _ = writeln!(s, "Entity.distance.v={:08x}", e.distance);
            }
            if e.workplane != 0 {
                let _ = writeln!(s, "Entity.workplane.v={:08x}", e.workplane);
            }
            s.push_str("Entity.actVisible=1\nAddEntity\n\n");
        }
        let constraints = std::mem::take(&mut self.constraints);
        let mut n = 0;
        for c in &constraints {
            let Some(text) = self.constraint_text(c) else {
                continue;
            };
            n += 1;
            let _ = write!(s, "Constraint.h.v={n:08x}\n{text}AddConstraint\n\n");
        }
        s
    }

    /// A constraint's fields, its loci handles mapped to the file's.
    fn constraint_text(&self, q: &Queued) -> Option<String> {
        let (c, tie, both_file) = match q {
            Queued::Loci(c) => (c, false, false),
            Queued::Tie(c) => (c, true, false),
            Queued::File(c) => (c, true, true),
        };
        let map = |h: Option<EntityId>, file: bool| -> Option<u32> {
            match h {
                None => Some(0),
                Some(h) if file => Some(h.0),
                Some(h) => self.file_entity(h).ok(),
            }
        };
        let mut s = String::new();
        let _ = writeln!(
            s,
            "Constraint.type={}\nConstraint.group.v={:08x}",
            constraint_code(written_kind(c.kind)),
            self.groups.get(&c.group)?.0
        );
        let wp = map(c.workplane, false)?;
        if wp != 0 {
            let _ = writeln!(s, "Constraint.workplane.v={wp:08x}");
        }
        if c.val != 0.0 {
            let _ = writeln!(s, "Constraint.valA={:.20}", c.val);
        }
        let fields = [
            ("ptA", c.pt_a, tie),
            ("ptB", c.pt_b, both_file),
            ("entityA", c.entity_a, tie),
            ("entityB", c.entity_b, both_file),
            ("entityC", c.entity_c, false),
            ("entityD", c.entity_d, false),
        ];
        for (name, h, file) in fields {
            let v = map(h, file)?;
            if v != 0 {
                let _ = writeln!(s, "Constraint.{name}.v={v:08x}");
            }
        }
        let (other, other2) = if tie {
            (false, false)
        } else {
            (c.other, c.other2)
        };
        let _ = writeln!(
            s,
            "Constraint.other={}\nConstraint.other2={}\nConstraint.reference={}",
            u8::from(other),
            u8::from(other2),
            u8::from(c.reference)
        );
        Some(s)
    }
}
