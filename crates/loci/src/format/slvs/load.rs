//! From records to loci's model: SolveSpace's handles, the entities requests and groups
//! generate, and its type numbers mapped onto loci's.
//!
//! Handles follow SolveSpace's scheme. A request `r` generates entities `r << 16 | k` (its
//! main entity at `k = 0`, points from 1, or the point itself at 0 for a datum point; the
//! normal at 32; the distance at 64) and parameters `r << 16 | i` (point `n`'s coordinates
//! at `16 + 3n`, the normal's quaternion at 32..35, the distance at 64). A group `g`
//! generates entities and parameters `0x8000_0000 | g << 16 | i`. Constraints' own
//! parameters (`c | 0x4000_0000 | i`, SolveSpace's helper unknowns for points on lines and
//! parallel lines in 3D) are not needed: loci writes those constraints without them.
//!
//! Bit 30 alone does not tell a constraint's parameter: the parameters of requests
//! `0x4000..=0x7fff` have it too. A parameter with bit 30 is a request's when an entity of
//! the file holds it, as SolveSpace numbers them (see [`own_params`]); otherwise it is a
//! constraint's. Request and group handles above `0x7fff` would run into the group bit, and
//! are errors.

use super::codes::{self, ConstraintCode, EntityCode, GroupKind};
use super::records::{Kind, Record};
use super::{GroupStatus, Note, ParamLine, SlvsError, SlvsFile, SlvsGroup};
use crate::geom::{quaternion_from_uv, Quat};
use crate::model::{Constraint, Entity, EntityId, GroupId, ObjectId, Param, ParamId, System};
use std::collections::{BTreeSet, HashMap, HashSet};

/// The group of geometry loci holds constant: copies a group computes from earlier groups
/// and faces of solids. No solve ever makes it unknown.
pub const FIXED_GROUP: GroupId = GroupId(0);

/// SolveSpace's group of the three reference planes, which it never solves.
const REFERENCES: u32 = 1;

const GROUP_BIT: u32 = 0x8000_0000;
const CONSTRAINT_BIT: u32 = 0x4000_0000;
/// The largest request or group handle: its objects' handles are `h << 16 | i`, which must
/// stay below [`GROUP_BIT`] (a request's) or fit beside it (a group's).
const MAX_OWNER: u32 = 0x7fff;

/// Hands out handles no object of the file uses, for the constants loci adds.
struct Fresh {
    next: u32,
    used: HashSet<u32>,
}

impl Fresh {
    fn new(used: HashSet<u32>) -> Self {
        Self {
            next: 0xF000_0000,
            used,
        }
    }

    fn take(&mut self) -> u32 {
        while self.used.contains(&self.next) {
            self.next += 1;
        }
        self.used.insert(self.next);
        self.next
    }
}

struct Builder<'a> {
    records: &'a [Record],
    sys: System,
    notes: Vec<Note>,
    /// Request handle -> its group.
    requests: HashMap<u32, u32>,
    groups: HashMap<u32, usize>,
    fresh_param: Fresh,
    fresh_entity: Fresh,
    fresh_constraint: Fresh,
    /// Groups that copy by translation (extrude, step and repeat), by handle.
    copiers: HashMap<u32, Copier>,
    /// Linked parts, by group handle: the normal loci made over the group's rotation
    /// quaternion (0 until the parameters are read, or when they are missing).
    linked: HashMap<u32, u32>,
    /// File entities modelled as constants although they move with their own group's
    /// unknowns, with that group: a constraint of that group on them cannot be solved.
    frozen: HashMap<u32, u32>,
    /// Every parameter handle of the file.
    param_handles: HashSet<u32>,
    /// File entities loci did not model, with why.
    skipped: HashMap<u32, &'static str>,
    /// Every entity handle of the file, with its line.
    entity_line: HashMap<u32, usize>,
    constraint_line: HashMap<u32, usize>,
    param_lines: Vec<ParamLine>,
    /// The records of the file's entities and constraints, by handle, to find the line of
    /// a field at fault.
    entity_rec: HashMap<u32, &'a Record>,
    constraint_rec: HashMap<u32, &'a Record>,
    /// Request handle -> the line of its record.
    request_line: HashMap<u32, usize>,
    /// The parameters the file's request entities hold, as SolveSpace numbers them.
    request_params: HashSet<u32>,
}

/// Builds the model of a parsed file.
pub(crate) fn build(
    bytes: Vec<u8>,
    spans: Vec<(usize, usize)>,
    records: &[Record],
    solid_lines: usize,
) -> Result<SlvsFile, SlvsError> {
    let mut param_handles = HashSet::new();
    let mut entity_handles = HashSet::new();
    let mut constraint_handles = HashSet::new();
    let mut request_params = HashSet::new();
    for r in records {
        match r.kind {
            Kind::Param => {
                param_handles.insert(r.hex("Param.h.v."));
            }
            Kind::Entity => {
                let h = r.hex("Entity.h.v");
                entity_handles.insert(h);
                if let Some(kind) = EntityCode::from_code(r.int("Entity.type")) {
                    request_params.extend(own_params(h, kind));
                }
            }
            Kind::Constraint => {
                constraint_handles.insert(r.hex("Constraint.h.v"));
            }
            _ => {}
        }
    }
    let mut b = Builder {
        records,
        sys: System::new(),
        notes: Vec::new(),
        requests: HashMap::new(),
        groups: HashMap::new(),
        fresh_param: Fresh::new(param_handles.clone()),
        fresh_entity: Fresh::new(entity_handles),
        fresh_constraint: Fresh::new(constraint_handles),
        copiers: HashMap::new(),
        linked: HashMap::new(),
        frozen: HashMap::new(),
        param_handles,
        skipped: HashMap::new(),
        entity_line: HashMap::new(),
        constraint_line: HashMap::new(),
        param_lines: Vec::new(),
        entity_rec: HashMap::new(),
        constraint_rec: HashMap::new(),
        request_line: HashMap::new(),
        request_params,
    };
    let mut groups = b.groups()?;
    b.requests()?;
    b.params()?;
    b.linked_rotations(&mut groups);
    b.entities()?;
    b.copier_equations(&mut groups);
    b.constraints(&mut groups)?;
    if solid_lines > 0 {
        b.notes.push(Note {
            line: 0,
            message: format!(
                "skipped {solid_lines} lines of the saved solid (mesh and surfaces), which \
                 SolveSpace regenerates"
            ),
        });
    }
    b.sys.validate().map_err(|e| {
        let line = match e.clone() {
            crate::ModelError::Dangling { owner, field, .. }
            | crate::ModelError::WrongKind { owner, field, .. }
            | crate::ModelError::MissingField { owner, field, .. }
            | crate::ModelError::NonFinite { owner, field, .. } => b.field_line(owner, field),
            crate::ModelError::NeedsWorkplane { constraint, .. } => {
                b.line_of(ObjectId::Constraint(constraint))
            }
            crate::ModelError::Cycle { entity } => b.line_of(ObjectId::Entity(entity)),
            _ => 0,
        };
        SlvsError::Model { line, source: e }
    })?;
    groups.sort_by_key(|g| (g.order, g.h));
    let construction = construction(records, &b.sys);
    Ok(SlvsFile {
        bytes,
        spans,
        system: b.sys,
        groups,
        notes: b.notes,
        param_lines: b.param_lines,
        construction,
    })
}

/// The modelled entities marked construction: by their own record, or by the request that
/// generates them (SolveSpace copies the request's flag onto its entities, but older files
/// may carry it on the request only).
fn construction(records: &[Record], sys: &System) -> BTreeSet<EntityId> {
    let requests: HashSet<u32> = records
        .iter()
        .filter(|r| r.kind == Kind::Request && r.flag("Request.construction"))
        .map(|r| r.hex("Request.h.v"))
        .collect();
    records
        .iter()
        .filter(|r| r.kind == Kind::Entity)
        .filter(|r| {
            let h = r.hex("Entity.h.v");
            r.flag("Entity.construction") || (h & GROUP_BIT == 0 && requests.contains(&(h >> 16)))
        })
        .map(|r| EntityId(r.hex("Entity.h.v")))
        .filter(|h| sys.entity(*h).is_some())
        .collect()
}

impl<'a> Builder<'a> {
    /// The line of `field` of object `o`: its key's when the record has it, else the
    /// record's.
    fn field_line(&self, o: ObjectId, field: &str) -> usize {
        let rec = match o {
            ObjectId::Entity(h) => self.entity_rec.get(&h.0),
            ObjectId::Constraint(h) => self.constraint_rec.get(&h.0),
            ObjectId::Param(_) => None,
        };
        match (rec, super::file_key(o, field)) {
            (Some(r), Some(key)) => r.line_of(key),
            _ => self.line_of(o),
        }
    }

    fn line_of(&self, o: ObjectId) -> usize {
        match o {
            ObjectId::Entity(h) => self.entity_line.get(&h.0).copied().unwrap_or(0),
            ObjectId::Constraint(h) => self.constraint_line.get(&h.0).copied().unwrap_or(0),
            ObjectId::Param(h) => self
                .param_lines
                .iter()
                .find(|p| p.h == h)
                .map_or(0, |p| p.h_line + 1),
        }
    }

    fn handle(r: &Record, key: &'static str) -> Result<u32, SlvsError> {
        match r.hex(key) {
            0 => Err(SlvsError::MissingHandle {
                line: r.line,
                record: r.kind.name(),
            }),
            h => Ok(h),
        }
    }

    fn groups(&mut self) -> Result<Vec<SlvsGroup>, SlvsError> {
        let mut out: Vec<SlvsGroup> = Vec::new();
        for r in self.records.iter().filter(|r| r.kind == Kind::Group) {
            let h = Self::handle(r, "Group.h.v")?;
            if h > MAX_OWNER {
                return Err(SlvsError::HandleTooLarge {
                    line: r.line_of("Group.h.v"),
                    record: "Group",
                    handle: h,
                });
            }
            if let Some(&i) = self.groups.get(&h) {
                return Err(SlvsError::Duplicate {
                    line: r.line,
                    record: "Group",
                    handle: h,
                    first: out[i].line,
                });
            }
            let kind = GroupKind::from_code(r.int("Group.type"));
            let status = if h == REFERENCES {
                GroupStatus::References
            } else if kind.is_sketch() {
                GroupStatus::Solve
            } else if let Some(c) = Copier::of(kind, r) {
                self.copiers.insert(h, c);
                GroupStatus::Solve
            } else if kind == GroupKind::Linked {
                self.linked.insert(h, 0);
                GroupStatus::Solve
            } else {
                GroupStatus::Unsupported(format!("{} groups are not modelled by loci", kind.name()))
            };
            self.groups.insert(h, out.len());
            out.push(SlvsGroup {
                h: GroupId(h),
                name: r.text("Group.name").to_string(),
                kind,
                order: r.int("Group.order"),
                allow_redundant: r.flag("Group.allowRedundant"),
                all_dims_reference: r.flag("Group.allDimsReference"),
                line: r.line,
                status,
            });
        }
        if out.is_empty() {
            return Err(SlvsError::NoGroups);
        }
        Ok(out)
    }

    fn requests(&mut self) -> Result<(), SlvsError> {
        for r in self.records.iter().filter(|r| r.kind == Kind::Request) {
            let h = Self::handle(r, "Request.h.v")?;
            if h > MAX_OWNER {
                return Err(SlvsError::HandleTooLarge {
                    line: r.line_of("Request.h.v"),
                    record: "Request",
                    handle: h,
                });
            }
            if let Some(&first) = self.request_line.get(&h) {
                return Err(SlvsError::Duplicate {
                    line: r.line,
                    record: "Request",
                    handle: h,
                    first,
                });
            }
            let group = r.hex("Request.group.v");
            if !self.groups.contains_key(&group) {
                return Err(SlvsError::Dangling {
                    line: r.line_of("Request.group.v"),
                    owner: super::file_name("Request", h),
                    field: "Request.group.v",
                    target: "group",
                    handle: group,
                });
            }
            self.requests.insert(h, group);
            self.request_line.insert(h, r.line);
        }
        Ok(())
    }

    /// The group that owns a request's or a group's object with handle `h`.
    fn owner_group(&self, h: u32) -> Option<u32> {
        if h & GROUP_BIT != 0 {
            let g = (h >> 16) & 0x7fff;
            self.groups.contains_key(&g).then_some(g)
        } else {
            self.requests.get(&(h >> 16)).copied()
        }
    }

    fn params(&mut self) -> Result<(), SlvsError> {
        let mut orphans = 0;
        for r in self.records.iter().filter(|r| r.kind == Kind::Param) {
            let h = Self::handle(r, "Param.h.v.")?;
            let val_line = r
                .fields
                .iter()
                .find(|f| f.key == "Param.val")
                .map(|f| f.line - 1);
            self.param_lines.push(ParamLine {
                h: ParamId(h),
                h_line: r.line_of("Param.h.v.") - 1,
                val_line,
            });
            if h & GROUP_BIT == 0 && h & CONSTRAINT_BIT != 0 && !self.request_params.contains(&h) {
                // A constraint's helper unknown, which loci does not need.
                continue;
            }
            let Some(group) = self.owner_group(h) else {
                orphans += 1;
                continue;
            };
            self.sys
                .add_param(Param::new(h, group, r.float("Param.val")))
                .map_err(|e| match e {
                    crate::ModelError::DuplicateHandle { .. } => SlvsError::Duplicate {
                        line: r.line,
                        record: "Param",
                        handle: h,
                        first: self.line_of(ObjectId::Param(ParamId(h))),
                    },
                    e => SlvsError::Model {
                        line: r.line,
                        source: e,
                    },
                })?;
        }
        if orphans > 0 {
            self.notes.push(Note {
                line: 0,
                message: format!(
                    "skipped {orphans} parameters whose request or group does not exist"
                ),
            });
        }
        Ok(())
    }

    /// A constant parameter holding `v`.
    fn constant(&mut self, v: f64) -> u32 {
        let h = self.fresh_param.take();
        // Handles from `Fresh` are unused and values come from checked numbers.
        let _ = self.sys.add_param(Param::new(h, FIXED_GROUP, v));
        h
    }

    fn constant_point(&mut self, p: [f64; 3]) -> u32 {
        let params = p.map(|v| self.constant(v));
        let h = self.fresh_entity.take();
        let _ = self
            .sys
            .add_entity(Entity::point_3d(h, FIXED_GROUP.0, params));
        h
    }

    fn constant_normal(&mut self, q: [f64; 4]) -> u32 {
        let params = q.map(|v| self.constant(v));
        let h = self.fresh_entity.take();
        let _ = self
            .sys
            .add_entity(Entity::normal_3d(h, FIXED_GROUP.0, params));
        h
    }

    fn entities(&mut self) -> Result<(), SlvsError> {
        for r in self.records.iter().filter(|r| r.kind == Kind::Entity) {
            let h = Self::handle(r, "Entity.h.v")?;
            if let Some(&first) = self.entity_line.get(&h) {
                return Err(SlvsError::Duplicate {
                    line: r.line,
                    record: "Entity",
                    handle: h,
                    first,
                });
            }
            self.entity_line.insert(h, r.line);
            self.entity_rec.insert(h, r);
            let code = r.int("Entity.type");
            let Some(kind) = EntityCode::from_code(code) else {
                return Err(SlvsError::UnknownType {
                    line: r.line_of("Entity.type"),
                    record: "Entity",
                    handle: h,
                    code,
                });
            };
            if let Some(e) = self.entity(h, kind, r)? {
                let _ = self.sys.add_entity(e);
            }
        }
        Ok(())
    }

    /// The model of file entity `h`, or `None` when loci skips it (with a note).
    fn entity(
        &mut self,
        h: u32,
        kind: EntityCode,
        r: &Record,
    ) -> Result<Option<Entity>, SlvsError> {
        use EntityCode as E;
        let code = r.int("Entity.type");
        let generated = h & GROUP_BIT != 0;
        let group = if generated {
            FIXED_GROUP.0
        } else {
            match self.owner_group(h) {
                Some(g) => g,
                None => {
                    self.skip(h, r, kind, "its request does not exist");
                    return Ok(None);
                }
            }
        };
        let wp = match r.hex("Entity.workplane.v") {
            0 => None,
            w => Some(w),
        };
        let pt = |i: usize| r.hex(POINT_KEYS[i]);
        let act_point = [
            r.float("Entity.actPoint.x"),
            r.float("Entity.actPoint.y"),
            r.float("Entity.actPoint.z"),
        ];
        let act_normal = [
            r.float("Entity.actNormal.w"),
            r.float("Entity.actNormal.vx"),
            r.float("Entity.actNormal.vy"),
            r.float("Entity.actNormal.vz"),
        ];
        let p = own_params(h, kind);
        let e = match kind {
            E::PointIn3d if p.len() == 3 => Entity::point_3d(h, group, [p[0], p[1], p[2]]),
            E::PointIn2d if p.len() == 2 => {
                let Some(wp) = wp else {
                    return Err(SlvsError::MissingField {
                        line: r.line,
                        owner: super::file_name("Entity", h),
                        field: "Entity.workplane.v",
                    });
                };
                Entity::point_2d(h, group, wp, [p[0], p[1]])
            }
            E::NormalIn3d if p.len() == 4 => Entity::normal_3d(h, group, [p[0], p[1], p[2], p[3]]),
            E::Distance if p.len() == 1 => Entity::distance(h, group, wp, p[0]),
            E::NormalIn2d => match wp {
                Some(wp) => Entity::normal_2d(h, group, wp),
                None => {
                    return Err(SlvsError::MissingField {
                        line: r.line,
                        owner: super::file_name("Entity", h),
                        field: "Entity.workplane.v",
                    })
                }
            },
            E::PointCopy if code == POINT_N_ROT_TRANS => match self.moved_point(h, act_point) {
                Some(e) => e,
                None => {
                    let params = act_point.map(|v| self.constant(v));
                    Entity::point_3d(h, FIXED_GROUP.0, params)
                }
            },
            E::NormalCopy if code == NORMAL_N_ROT => match self.rotated_normal(h, act_normal) {
                Some(e) => e,
                None => {
                    let params = act_normal.map(|v| self.constant(v));
                    Entity::normal_3d(h, FIXED_GROUP.0, params)
                }
            },
            E::PointCopy if code == POINT_N_TRANS => match self.translated(h, act_point) {
                Some(e) => e,
                None => {
                    let params = act_point.map(|v| self.constant(v));
                    Entity::point_3d(h, FIXED_GROUP.0, params)
                }
            },
            E::PointCopy => {
                let params = act_point.map(|v| self.constant(v));
                Entity::point_3d(h, FIXED_GROUP.0, params)
            }
            E::NormalCopy => {
                let params = act_normal.map(|v| self.constant(v));
                Entity::normal_3d(h, FIXED_GROUP.0, params)
            }
            E::DistanceCopy => {
                let p = self.constant(r.float("Entity.actDistance"));
                Entity::distance(h, FIXED_GROUP.0, None, p)
            }
            E::Face => {
                // A face is a plane: its point and its (unit) normal vector, which SolveSpace
                // saves as the vector part of `actNormal`. The normal of the faces a
                // translation makes is fixed; their point moves with the translation.
                let n = [act_normal[1], act_normal[2], act_normal[3]];
                let Some(q) = rotation_to(n) else {
                    self.skip(h, r, kind, "its normal is zero");
                    return Ok(None);
                };
                let copier = self.copiers.contains_key(&((h >> 16) & 0x7fff));
                if self.linked_rotation(h).is_some() {
                    // A face of a linked part turns and moves with the part; loci holds it
                    // where it was saved.
                    self.frozen.insert(h, (h >> 16) & 0x7fff);
                }
                let origin = match code {
                    // A face through a point the group copied (an extrusion's top or bottom).
                    FACE_NORMAL_PT if copier && pt(0) >> 16 == h >> 16 => pt(0),
                    // A copied face: the source face's point, translated.
                    FACE_N_TRANS if copier => match self.translated(h, act_point) {
                        Some(e) => {
                            let p = self.fresh_entity.take();
                            let e = Entity {
                                h: EntityId(p),
                                ..e
                            };
                            let _ = self.sys.add_entity(e);
                            p
                        }
                        None => self.constant_point(act_point),
                    },
                    _ => {
                        if copier && code != FACE_NORMAL_PT {
                            // Its normal turns with the translation (a line swept into a
                            // face); loci holds it where it was saved.
                            self.frozen.insert(h, (h >> 16) & 0x7fff);
                        }
                        self.constant_point(act_point)
                    }
                };
                let normal = self.constant_normal(q);
                Entity::workplane(h, FIXED_GROUP.0, origin, normal)
            }
            E::Workplane => Entity::workplane(h, group, pt(0), r.hex("Entity.normal.v")),
            E::LineSegment => Entity::line(h, group, wp, pt(0), pt(1)),
            E::Cubic if r.int("Entity.extraPoints") == 0 => {
                Entity::cubic(h, group, wp, [pt(0), pt(1), pt(2), pt(3)])
            }
            E::Cubic => {
                self.skip(
                    h,
                    r,
                    kind,
                    "a spline through more than four points is not modelled (its points are)",
                );
                return Ok(None);
            }
            E::Circle => Entity::circle(
                h,
                group,
                wp,
                pt(0),
                r.hex("Entity.normal.v"),
                r.hex("Entity.distance.v"),
            ),
            E::ArcOfCircle => match wp {
                Some(wp) => {
                    Entity::arc(h, group, wp, r.hex("Entity.normal.v"), pt(0), pt(1), pt(2))
                }
                None => {
                    self.skip(h, r, kind, "an arc outside a workplane is not modelled");
                    return Ok(None);
                }
            },
            E::CubicPeriodic => {
                self.skip(
                    h,
                    r,
                    kind,
                    "periodic splines are not modelled (their points are)",
                );
                return Ok(None);
            }
            E::TtfText | E::Image => {
                self.skip(
                    h,
                    r,
                    kind,
                    "text and images are not modelled (their points are)",
                );
                return Ok(None);
            }
            E::PointIn3d | E::PointIn2d | E::NormalIn3d | E::Distance => {
                self.skip(h, r, kind, "its handle is not one a request generates");
                return Ok(None);
            }
        };
        Ok(Some(e))
    }

    /// The model of a point group `g` made by translating another (`h` is the file's
    /// entity, at `at` as saved): its own coordinates, tied to its source point plus the
    /// group's translation times the copy's number. `None` when the group does not copy by
    /// translation, or the remap table, the source or the translation is missing; the
    /// caller then holds the point where it was saved, and a constraint of its group on it
    /// makes that group unsupported.
    fn translated(&mut self, h: u32, at: [f64; 3]) -> Option<Entity> {
        let g = (h >> 16) & 0x7fff;
        let base_h = h & 0xffff_0000;
        let copier = self.copiers.get(&g)?;
        let found = copier
            .remap
            .get(&(h & 0xffff))
            .and_then(|&(src, copy)| Some((src, copier.times(copy)?)));
        let translation = [base_h, base_h | 1, base_h | 2];
        let ok = translation.iter().all(|p| self.param_handles.contains(p));
        let source = found.and_then(|(src, times)| {
            // The source of a copied face is a face: its point is the one translated.
            match self.sys.entity(EntityId(src)).map(|e| &e.kind) {
                Some(k) if k.entity_type().is_point() => Some((src, times)),
                Some(crate::EntityKind::Workplane { origin, .. }) if self.is_face(src) => {
                    Some((origin.0, times))
                }
                _ => None,
            }
        });
        let Some((src, times)) = source.filter(|_| ok) else {
            self.frozen.insert(h, g);
            return None;
        };
        // Start where the source and the saved translation put it: SolveSpace saves
        // `actPoint` as of its last regeneration, which need not be current.
        let at = match (self.position(EntityId(src)), self.values(translation)) {
            (Some(b), Some(t)) => [0, 1, 2].map(|i| b[i] + f64::from(times) * t[i]),
            _ => at,
        };
        let params = at.map(|v| {
            let p = self.fresh_param.take();
            let _ = self.sys.add_param(Param::new(p, g, v));
            p
        });
        Some(Entity::point_n_trans(h, g, params, src, translation, times))
    }

    /// The linked parts' rotations: SolveSpace holds a linked group's quaternion (its
    /// parameters 3..6, after the translation's 0..2) at unit length with an equation of the
    /// group; loci makes it a normal of the group, whose implicit condition is the same. A
    /// group without its seven parameters is not modelled.
    fn linked_rotations(&mut self, groups: &mut [SlvsGroup]) {
        let mut hs: Vec<u32> = self.linked.keys().copied().collect();
        hs.sort_unstable();
        for g in hs {
            let base_h = GROUP_BIT | g << 16;
            if !(0..7).all(|i| self.param_handles.contains(&(base_h | i))) {
                self.linked.remove(&g);
                groups[self.groups[&g]].status = GroupStatus::Unsupported(
                    "the file does not hold the linked part's translation and rotation".into(),
                );
                continue;
            }
            let normal = self.fresh_entity.take();
            let q = [3, 4, 5, 6].map(|i| base_h | i);
            let _ = self.sys.add_entity(Entity::normal_3d(normal, g, q));
            self.linked.insert(g, normal);
        }
    }

    /// For an entity of a linked part: its group's translation parameters, the normal holding
    /// its rotation, and their saved values (the rotation scaled to unit length).
    fn linked_rotation(&self, h: u32) -> Option<LinkedMotion> {
        if h & GROUP_BIT == 0 {
            return None;
        }
        let g = (h >> 16) & 0x7fff;
        let normal = *self.linked.get(&g).filter(|&&n| n != 0)?;
        let base_h = h & 0xffff_0000;
        let translation = [base_h, base_h | 1, base_h | 2];
        let t = self.values(translation)?;
        let [w, x, y, z] = self.values([3, 4, 5, 6].map(|i| base_h | i))?;
        let len = (w * w + x * x + y * y + z * z).sqrt();
        // A zero (or NaN) quaternion is no rotation.
        if len.is_nan() || len <= 1e-12 {
            return None;
        }
        let q = Quat {
            w: w / len,
            x: x / len,
            y: y / len,
            z: z / len,
        };
        Some(LinkedMotion {
            translation,
            normal,
            t,
            q,
        })
    }

    /// A point of a linked part, saved at `at`: coordinates of its own tied to the base point
    /// of the linked file, recovered from the saved values as `q* (at - t) q`. `None` outside
    /// a modelled linked part (the caller holds it where it was saved).
    fn moved_point(&mut self, h: u32, at: [f64; 3]) -> Option<Entity> {
        let LinkedMotion {
            translation,
            normal,
            t,
            q,
        } = self.linked_rotation(h)?;
        let d = crate::geom::Vec3::new(at[0] - t[0], at[1] - t[1], at[2] - t[2]);
        // The inverse rotation of d: its components along the rotated axes.
        let base = [d.dot(q.u()), d.dot(q.v()), d.dot(q.n())];
        let g = (h >> 16) & 0x7fff;
        let params = at.map(|v| {
            let p = self.fresh_param.take();
            let _ = self.sys.add_param(Param::new(p, g, v));
            p
        });
        Some(Entity::point_n_rot_trans(
            h,
            g,
            params,
            base,
            translation,
            normal,
        ))
    }

    /// A normal of a linked part, saved as `at`: a quaternion of its own tied to the linked
    /// file's orientation, recovered as `q* at`.
    fn rotated_normal(&mut self, h: u32, at: [f64; 4]) -> Option<Entity> {
        let LinkedMotion { normal, q, .. } = self.linked_rotation(h)?;
        let a = Quat {
            w: at[0],
            x: at[1],
            y: at[2],
            z: at[3],
        };
        let b = q.conj().times(a);
        let g = (h >> 16) & 0x7fff;
        let params = at.map(|v| {
            let p = self.fresh_param.take();
            let _ = self.sys.add_param(Param::new(p, g, v));
            p
        });
        Some(Entity::normal_n_rot(
            h,
            g,
            params,
            [b.w, b.x, b.y, b.z],
            normal,
        ))
    }

    /// The values of parameters `ps`, if all are in the model.
    fn values<const N: usize>(&self, ps: [u32; N]) -> Option<[f64; N]> {
        let mut out = [0.0; N];
        for (o, p) in out.iter_mut().zip(ps) {
            *o = self.sys.value(crate::ParamId(p))?;
        }
        Some(out)
    }

    /// Where point `h` is, from the current parameter values.
    fn position(&self, h: EntityId) -> Option<[f64; 3]> {
        use crate::geom::Quat;
        let e = self.sys.entity(h)?;
        match &e.kind {
            crate::EntityKind::PointIn3d { params }
            | crate::EntityKind::PointNTrans { params, .. }
            | crate::EntityKind::PointNRotTrans { params, .. } => self.values(params.map(|p| p.0)),
            crate::EntityKind::PointIn2d { params } => {
                let [u, v] = self.values(params.map(|p| p.0))?;
                let crate::EntityKind::Workplane { origin, normal } =
                    &self.sys.entity(e.workplane?)?.kind
                else {
                    return None;
                };
                let o = self.position(*origin)?;
                let crate::EntityKind::NormalIn3d { params } = &self.sys.entity(*normal)?.kind
                else {
                    return None;
                };
                let [w, x, y, z] = self.values(params.map(|p| p.0))?;
                let q = Quat { w, x, y, z };
                let (qu, qv) = (q.u(), q.v());
                Some([0, 1, 2].map(|i| o[i] + u * qu.at(i) + v * qv.at(i)))
            }
            _ => None,
        }
    }

    /// Whether file entity `h` is a face (a workplane loci made for it).
    fn is_face(&self, h: u32) -> bool {
        h & GROUP_BIT != 0 && self.entity_line.contains_key(&h)
    }

    /// The conditions a group that copies by translation puts on its translation vector
    /// (SolveSpace writes them as the group's own equations): an extrusion goes along the
    /// normal of its workplane (unless skewed), a step and repeat stays parallel to its
    /// workplane. Written as constraints of the group on the vector as a point from the
    /// origin, with handles the file does not use.
    fn copier_equations(&mut self, groups: &mut [SlvsGroup]) {
        let mut hs: Vec<u32> = self.copiers.keys().copied().collect();
        hs.sort_unstable();
        for g in hs {
            let c = &self.copiers[&g];
            let (kind, wp) = (c.kind, c.workplane);
            let base_h = GROUP_BIT | g << 16;
            let translation = [base_h, base_h | 1, base_h | 2];
            let gi = self.groups[&g];
            if !translation.iter().all(|p| self.param_handles.contains(p)) {
                groups[gi].status = GroupStatus::Unsupported(
                    "the file does not hold the group's translation vector".into(),
                );
                continue;
            }
            let Some(wp) = wp else { continue };
            let plane = match self.sys.entity(EntityId(wp)).map(|e| &e.kind) {
                Some(crate::EntityKind::Workplane { normal, .. }) => *normal,
                _ => {
                    groups[gi].status = GroupStatus::Unsupported(format!(
                        "its workplane Entity.h.v={wp:08x} is not one loci models"
                    ));
                    continue;
                }
            };
            let vector = self.fresh_entity.take();
            let _ = self
                .sys
                .add_entity(Entity::point_3d(vector, g, translation));
            let origin = self.constant_point([0.0; 3]);
            let h = self.fresh_constraint.take();
            let c = match kind {
                // u . t = 0 and v . t = 0: the vector projects onto the workplane's origin.
                GroupKind::Extrude => {
                    Constraint::new(h, g, crate::ConstraintKind::PointsCoincident)
                        .in_workplane(Some(wp))
                        .with_points(vector, origin)
                }
                // n . t = 0: the vector lies in a plane through the origin with the
                // workplane's normal.
                _ => {
                    let through = self.fresh_entity.take();
                    let _ = self.sys.add_entity(Entity::workplane(
                        through,
                        FIXED_GROUP.0,
                        origin,
                        plane.0,
                    ));
                    Constraint::new(h, g, crate::ConstraintKind::PtInPlane)
                        .with_points(vector, 0)
                        .with_entities([through, 0, 0, 0])
                }
            };
            let _ = self.sys.add_constraint(c);
        }
    }

    fn skip(&mut self, h: u32, r: &Record, kind: EntityCode, why: &'static str) {
        self.skipped.insert(h, kind.name());
        self.notes.push(Note {
            line: r.line,
            message: format!("Entity.h.v={h:08x} ({}) skipped: {why}", kind.name()),
        });
    }

    fn constraints(&mut self, groups: &mut [SlvsGroup]) -> Result<(), SlvsError> {
        for r in self.records.iter().filter(|r| r.kind == Kind::Constraint) {
            let h = Self::handle(r, "Constraint.h.v")?;
            if let Some(&first) = self.constraint_line.get(&h) {
                return Err(SlvsError::Duplicate {
                    line: r.line,
                    record: "Constraint",
                    handle: h,
                    first,
                });
            }
            self.constraint_line.insert(h, r.line);
            self.constraint_rec.insert(h, r);
            let code = r.int("Constraint.type");
            let kind = match codes::constraint(code) {
                Some(ConstraintCode::Kind(k)) => k,
                Some(ConstraintCode::Comment) => {
                    self.notes.push(Note {
                        line: r.line,
                        message: format!("Constraint.h.v={h:08x} is a comment: no equations"),
                    });
                    continue;
                }
                None => {
                    return Err(SlvsError::UnknownType {
                        line: r.line_of("Constraint.type"),
                        record: "Constraint",
                        handle: h,
                        code,
                    })
                }
            };
            let g = r.hex("Constraint.group.v");
            let Some(&gi) = self.groups.get(&g) else {
                return Err(SlvsError::Dangling {
                    line: r.line_of("Constraint.group.v"),
                    owner: super::file_name("Constraint", h),
                    field: "Constraint.group.v",
                    target: "group",
                    handle: g,
                });
            };
            // Every entity a constraint names must exist in the file; an entity loci skipped
            // makes the constraint (and so its group) impossible to solve here.
            let mut unmodelled = None;
            for key in ENTITY_KEYS {
                let e = r.hex(key);
                if e == 0 {
                    continue;
                }
                if !self.entity_line.contains_key(&e) {
                    return Err(SlvsError::Dangling {
                        line: r.line_of(key),
                        owner: super::file_name("Constraint", h),
                        field: key,
                        target: "entity",
                        handle: e,
                    });
                }
                if self.frozen.get(&e) == Some(&g) {
                    unmodelled = Some(format!(
                        "Constraint.h.v={h:08x} ({}) refers to Entity.h.v={e:08x}, which moves with \
                         the group's translation in a way loci does not model",
                        kind.name()
                    ));
                }
                if let Some(what) = self.skipped.get(&e) {
                    unmodelled = Some(format!(
                        "Constraint.h.v={h:08x} ({}) refers to Entity.h.v={e:08x} ({what}), which loci \
                         does not model",
                        kind.name()
                    ));
                }
            }
            if let Some(why) = unmodelled {
                if groups[gi].status == GroupStatus::Solve {
                    groups[gi].status = GroupStatus::Unsupported(why);
                }
                continue;
            }
            let nz = |v: u32| (v != 0).then_some(EntityId(v));
            let reference = r.flag("Constraint.reference")
                || (groups[gi].all_dims_reference && kind.has_value());
            let c = Constraint {
                h: crate::ConstraintId(h),
                group: GroupId(g),
                kind,
                workplane: nz(r.hex("Constraint.workplane.v")),
                val: r.float("Constraint.valA"),
                pt_a: nz(r.hex("Constraint.ptA.v")),
                pt_b: nz(r.hex("Constraint.ptB.v")),
                entity_a: nz(r.hex("Constraint.entityA.v")),
                entity_b: nz(r.hex("Constraint.entityB.v")),
                entity_c: nz(r.hex("Constraint.entityC.v")),
                entity_d: nz(r.hex("Constraint.entityD.v")),
                other: r.flag("Constraint.other"),
                other2: r.flag("Constraint.other2"),
                reference,
                // SolveSpace's angle has a size only.
                signed: false,
            };
            self.sys.add_constraint(c).map_err(|e| SlvsError::Model {
                line: r.line_of("Constraint.valA"),
                source: e,
            })?;
        }
        Ok(())
    }
}

/// A linked part's motion: its translation parameters, the normal loci made over its
/// rotation, and their saved values (the rotation scaled to unit length).
struct LinkedMotion {
    translation: [u32; 3],
    normal: u32,
    t: [f64; 3],
    q: Quat<f64>,
}

/// SolveSpace's entity type of a translated point.
const POINT_N_TRANS: i64 = 2010;
/// A point turned and moved (a linked part's points).
const POINT_N_ROT_TRANS: i64 = 2011;
/// A normal turned (a linked part's normals).
const NORMAL_N_ROT: i64 = 3011;
/// A face through a point with a fixed normal.
const FACE_NORMAL_PT: i64 = 5000;
/// A face translated from another.
const FACE_N_TRANS: i64 = 5003;

/// A group that copies the entities of another by translation: which copy number each of
/// its entities is, and the workplane that steers the translation.
struct Copier {
    kind: GroupKind,
    /// Entity index in the group -> (source entity, copy number), from `Group.remap`.
    remap: HashMap<u32, (u32, u32)>,
    /// Copy number -> times the translation is applied.
    times: HashMap<u32, i32>,
    /// `predef.entityB`: the extrusion goes along its normal, a step and repeat stays
    /// parallel to it. `None` for a skewed extrusion or one free in 3D.
    workplane: Option<u32>,
}

impl Copier {
    /// SolveSpace's copy numbers for an extrusion's top and bottom.
    const TOP: u32 = 1001;
    const BOTTOM: u32 = 1002;
    /// The last copy of a step and repeat.
    const LAST: u32 = 1000;

    /// The copier for a group record, or `None` when the group does not copy by
    /// translation (or has a subtype loci does not know).
    fn of(kind: GroupKind, r: &Record) -> Option<Self> {
        const ONE_SIDED: i64 = 7000;
        const TWO_SIDED: i64 = 7001;
        const ONE_SKEWED: i64 = 7004;
        const TWO_SKEWED: i64 = 7005;
        let subtype = r.int("Group.subtype");
        let wp = match r.hex("Group.predef.entityB.v") {
            0 => None,
            w => Some(w),
        };
        let mut times = HashMap::new();
        let workplane = match kind {
            GroupKind::Extrude => {
                let (bottom, top, skewed) = match subtype {
                    ONE_SIDED => (0, 2, false),
                    TWO_SIDED => (-1, 1, false),
                    ONE_SKEWED => (0, 2, true),
                    TWO_SKEWED => (-1, 1, true),
                    _ => return None,
                };
                times.insert(Self::BOTTOM, bottom);
                times.insert(Self::TOP, top);
                if skewed {
                    None
                } else {
                    wp
                }
            }
            GroupKind::Translate => {
                let one_sided = match subtype {
                    ONE_SIDED => true,
                    TWO_SIDED => false,
                    _ => return None,
                };
                times = Self::repeat_times(
                    r.float("Group.valA"),
                    one_sided,
                    r.flag("Group.skipFirst"),
                )?;
                wp
            }
            _ => return None,
        };
        let remap = r
            .remap("Group.remap")
            .iter()
            .map(|&(i, src, copy)| (i, (src, copy)))
            .collect();
        Some(Self {
            kind,
            remap,
            times,
            workplane,
        })
    }

    /// Copy number -> times applied for a step and repeat of `copies` copies. Copy `a` of
    /// `a0..n` sits at `2a` translations (one side) or centred about the original (two
    /// sides); the last copy has its own number. (SolveSpace's translation vector is half
    /// the step.)
    fn repeat_times(copies: f64, one_sided: bool, skip_first: bool) -> Option<HashMap<u32, i32>> {
        if !(1.0..=1e6).contains(&copies) {
            return None;
        }
        let mut n = copies as i64;
        let mut a0 = 0;
        if one_sided && skip_first {
            a0 += 1;
            n += 1;
        }
        let mut times = HashMap::new();
        for a in a0..n {
            let t = a * 2 - if one_sided { 0 } else { n - 1 };
            let copy = if a == n - 1 { Self::LAST } else { a as u32 };
            times.insert(copy, i32::try_from(t).ok()?);
        }
        Some(times)
    }

    fn times(&self, copy: u32) -> Option<i32> {
        self.times.get(&copy).copied()
    }
}

const POINT_KEYS: [&str; 4] = [
    "Entity.point[0].v",
    "Entity.point[1].v",
    "Entity.point[2].v",
    "Entity.point[3].v",
];

const ENTITY_KEYS: [&str; 7] = [
    "Constraint.workplane.v",
    "Constraint.ptA.v",
    "Constraint.ptB.v",
    "Constraint.entityA.v",
    "Constraint.entityB.v",
    "Constraint.entityC.v",
    "Constraint.entityD.v",
];

/// The parameters file entity `h` of type `kind` holds itself, as SolveSpace numbers them
/// from the handle of a request's entity: point `n` (a datum point is entity 0, other points
/// count from 1) at `16 + 3n`, the normal's quaternion at 32..35, a distance at 64. Empty
/// for entities that hold none, and for a group's (copies, which loci models otherwise).
fn own_params(h: u32, kind: EntityCode) -> Vec<u32> {
    if h & GROUP_BIT != 0 {
        return Vec::new();
    }
    let base = h & 0xffff_0000;
    let k = h & 0xffff;
    let (first, count) = match kind {
        EntityCode::PointIn3d if k < 32 => (16 + 3 * k.saturating_sub(1), 3),
        EntityCode::PointIn2d if k < 32 => (16 + 3 * k.saturating_sub(1), 2),
        EntityCode::NormalIn3d if k == 32 => (32, 4),
        EntityCode::Distance if k == 64 => (64, 1),
        _ => return Vec::new(),
    };
    (first..first + count).map(|i| base | i).collect()
}

/// A unit quaternion whose N axis is along `n`, or `None` for a zero vector.
fn rotation_to(n: [f64; 3]) -> Option<[f64; 4]> {
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    // (A NaN length is no direction either.)
    if len.is_nan() || len <= 1e-12 {
        return None;
    }
    let n = n.map(|v| v / len);
    // Any unit u perpendicular to n: cross n with the axis it is least aligned with.
    let a = if n[0].abs() < 0.6 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let u = cross(a, n);
    let ul = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt();
    let u = u.map(|v| v / ul);
    let v = cross(n, u);
    Some(quaternion_from_uv(u, v))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Quat;

    #[test]
    fn step_and_repeat_copies_are_numbered_as_solvespace_does() {
        let sorted = |m: HashMap<u32, i32>| {
            let mut v: Vec<(u32, i32)> = m.into_iter().collect();
            v.sort_unstable();
            v
        };
        // One side, three copies: the original's place, then 2t and 4t (the last).
        let t = Copier::repeat_times(3.0, true, false).unwrap();
        assert_eq!(sorted(t), vec![(0, 0), (1, 2), (Copier::LAST, 4)]);
        // Skipping the first keeps three copies, moved one step on.
        let t = Copier::repeat_times(3.0, true, true).unwrap();
        assert_eq!(sorted(t), vec![(1, 2), (2, 4), (Copier::LAST, 6)]);
        // Two sides: centred on the original.
        let t = Copier::repeat_times(3.0, false, false).unwrap();
        assert_eq!(sorted(t), vec![(0, -2), (1, 0), (Copier::LAST, 2)]);
        assert!(Copier::repeat_times(0.0, true, false).is_none());
        assert!(Copier::repeat_times(f64::NAN, true, false).is_none());
    }

    #[test]
    fn rotation_to_maps_z_onto_the_normal() {
        for n in [[1.0, 0.0, 0.0], [0.0, 0.0, -2.0], [0.3, -0.4, 0.5]] {
            let q = rotation_to(n).unwrap();
            let q = Quat {
                w: q[0],
                x: q[1],
                y: q[2],
                z: q[3],
            };
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            let got = q.n();
            for i in 0..3 {
                assert!((got.at(i) - n[i] / len).abs() < 1e-12, "{n:?}");
            }
        }
        assert!(rotation_to([0.0; 3]).is_none());
    }
}
