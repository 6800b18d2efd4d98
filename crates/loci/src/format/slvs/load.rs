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
use crate::model::{Constraint, Entity, EntityId, GroupId, ObjectId, Param, ParamId, System};
use std::collections::{BTreeSet, HashMap, HashSet};

mod copies;
mod entities;

use copies::Copier;

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
            | crate::ModelError::NonFinite { owner, field, .. }
            | crate::ModelError::OutOfRange { owner, field, .. } => b.field_line(owner, field),
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
