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

use super::records::MAGIC;
use crate::model::{
    Constraint, ConstraintKind, Entity, EntityId, EntityKind, GroupId, ParamId, System,
};
use std::collections::{BTreeMap, BTreeSet, HashMap};
use thiserror::Error;

mod geometry;
mod text;

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
    pub(super) fn group(&self, g: GroupId) -> u32 {
        self.groups[&g].0
    }

    pub(super) fn value(&self, p: ParamId) -> f64 {
        self.sys.value(p).unwrap_or(0.0)
    }

    /// Parameters no written entity holds (a copy's translation, say) become the
    /// coordinates of datum points in 3D of their group, three at a time, so every value
    /// has a place in the file.
    pub(super) fn loose_params(&mut self) -> Result<(), ExportError> {
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
    pub(super) fn references(&mut self) {
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

    pub(super) fn push_ent(
        &mut self,
        h: u32,
        kind: u32,
        wp: u32,
        points: Vec<u32>,
        normal: u32,
        dist: u32,
    ) {
        self.entities.push(Ent {
            h,
            kind,
            workplane: wp,
            points,
            normal,
            distance: dist,
        });
    }

    pub(super) fn request(
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

    pub(super) fn take_request(&mut self) -> Result<u32, ExportError> {
        let r = self.next_request;
        if r > MAX_REQUESTS {
            return Err(ExportError::TooLarge { needed: r as usize });
        }
        self.next_request += 1;
        Ok(r)
    }

    /// The file workplane of loci workplane `w`.
    pub(super) fn workplane_of(&self, w: EntityId) -> Result<u32, ExportError> {
        self.owner.get(&w).copied().ok_or(ExportError::Unsupported {
            entity: w,
            why: "its workplane is not written",
        })
    }

    /// A tie the writer adds: `pt_a` / `entity_a` is already a file handle, the other side
    /// a loci handle.
    pub(super) fn ties(&mut self, c: Constraint) {
        self.constraints.push(Queued::Tie(c));
    }

    pub(super) fn entity(&self, h: EntityId) -> Result<&'a Entity, ExportError> {
        self.sys
            .entity(h)
            .ok_or(ExportError::Model(crate::ModelError::Dangling {
                owner: crate::ObjectId::Entity(h),
                field: "entity",
                target: "entity",
                handle: h.0,
            }))
    }

    /// Queues loci constraint `c`, its handles mapped when the text is written.
    pub(super) fn constraint(&mut self, c: &Constraint) -> Result<(), ExportError> {
        for h in c.fields().into_iter().flatten().chain(c.workplane) {
            self.file_entity(h)?;
        }
        self.constraints.push(Queued::Loci(c.clone()));
        Ok(())
    }

    /// A loci entity's file handle.
    pub(super) fn file_entity(&self, h: EntityId) -> Result<u32, ExportError> {
        self.owner.get(&h).copied().ok_or(ExportError::Unsupported {
            entity: h,
            why: "nothing SolveSpace draws holds it",
        })
    }
}
