//! SolveSpace's `.slvs` files: load, solve group by group, and save.
//!
//! ```no_run
//! use loci::format::slvs::{solve_all, SlvsFile};
//! use loci::Config;
//!
//! let bytes = std::fs::read("part.slvs")?;
//! let mut file = SlvsFile::parse(&bytes)?;
//! for g in solve_all(&mut file, &Config::default()) {
//!     println!("{} ({}): {}", g.group, g.name, g.result);
//! }
//! std::fs::write("part-solved.slvs", file.to_bytes())?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! What loci models: sketch groups (in 3D and in a workplane) with every request SolveSpace
//! draws (workplanes, datum points, lines, cubics, circles, arcs) and every constraint type;
//! extrusions and step-and-repeat by translation, whose copied points are
//! [`point_n_trans`](crate::EntityKind::PointNTrans) entities tied to their source by the
//! group's translation vector (its unknown, held along the workplane's normal for an
//! extrusion and in the workplane for a step and repeat, as SolveSpace does), with their
//! top and bottom faces (and copied faces) as planes through those points. A face swept
//! from a line, whose normal turns with the translation, is held as saved; a constraint of
//! its own group on it makes that group unsupported. Linked parts: the imported points and
//! normals are [`point_n_rot_trans`](crate::EntityKind::PointNRotTrans) and
//! [`normal_n_rot`](crate::EntityKind::NormalNRot) entities carried by the group's
//! translation (parameters 0..2) and rotation quaternion (3..6, held at unit length as
//! SolveSpace does); their constant bases are recovered from the saved positions and the
//! saved motion, so the linked file itself is not read.
//! What it does not: the other groups that build solids (lathe, revolve, helix, step and
//! repeat by rotation) are reported as unsupported by name and left as
//! saved; the geometry they generate is read from the file as constants, so later
//! sketches that use it still solve. Text, images, splines through more than four points and periodic splines
//! are skipped (their points are modelled); the saved solid (meshes, surfaces) is skipped.
//! Each skip is recorded as a [`Note`].
//!
//! Saving keeps the original text and rewrites only parameter values, so everything loci
//! does not interpret (styles, colours, labels, the solid) survives unchanged.

mod codes;
pub mod conformance;
mod export;
mod load;
mod records;
mod solve;
mod write;

pub use codes::GroupKind;
pub use export::{export, Export, ExportError};
pub use load::FIXED_GROUP;
pub use solve::{solve_all, GroupResult, GroupSolve};

use crate::model::{EntityId, GroupId, ObjectId, ParamId, System};
use crate::{ModelError, SolveError};
use std::collections::BTreeSet;
use std::fmt;

/// A loaded `.slvs` file: loci's model of it, its groups in solve order, and the original
/// text for saving.
#[derive(Clone, Debug)]
pub struct SlvsFile {
    bytes: Vec<u8>,
    spans: Vec<(usize, usize)>,
    /// The model: parameters (SolveSpace's handles), entities and constraints. Constants
    /// loci adds (copied geometry, faces) are in [`FIXED_GROUP`] with handles the file
    /// does not use.
    pub system: System,
    /// The groups, in SolveSpace's solve order.
    pub groups: Vec<SlvsGroup>,
    /// What loci skipped, and why.
    pub notes: Vec<Note>,
    param_lines: Vec<ParamLine>,
    /// The modelled entities the file marks as construction geometry (SolveSpace's
    /// `construction` flag): they constrain like any other, and are drawn dashed.
    pub construction: BTreeSet<EntityId>,
}

/// Where a parameter is written in the original text (0-based line indices).
#[derive(Clone, Debug)]
struct ParamLine {
    h: ParamId,
    h_line: usize,
    val_line: Option<usize>,
}

/// A group of the file.
#[derive(Clone, Debug, PartialEq)]
pub struct SlvsGroup {
    /// Its handle.
    pub h: GroupId,
    /// Its name.
    pub name: String,
    /// Its type.
    pub kind: GroupKind,
    /// Its place in the solve order.
    pub order: i64,
    /// Whether SolveSpace accepts redundant constraints in it (`allowRedundant`).
    pub allow_redundant: bool,
    /// Whether every dimension in it is a reference (`allDimsReference`).
    pub all_dims_reference: bool,
    /// The line of its record.
    pub line: usize,
    /// Whether loci solves it.
    pub status: GroupStatus,
}

/// Whether and why loci solves a group.
#[derive(Clone, Debug, PartialEq)]
pub enum GroupStatus {
    /// A sketch loci solves.
    Solve,
    /// SolveSpace's reference planes: fixed, never solved.
    References,
    /// A group loci cannot solve, with the reason.
    Unsupported(String),
}

/// Something loci skipped while loading.
#[derive(Clone, Debug, PartialEq)]
pub struct Note {
    /// The line it concerns (0 when it concerns the whole file).
    pub line: usize,
    /// What was skipped and why.
    pub message: String,
}

/// A file loci cannot read, with the line (1-based) where the problem is.
///
/// Messages name objects as the file writes them: `Entity.h.v=00040001`, with the key of the
/// field at fault (`Constraint.ptB.v=00090000`). The message is complete in itself: a
/// [`ModelError`] inside [`SlvsError::Model`] is part of the text, not a separate source.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SlvsError {
    /// A line that is not text.
    NotText {
        /// The line.
        line: usize,
    },
    /// A `Key=value` line whose key SolveSpace does not write.
    UnknownKey {
        /// The line.
        line: usize,
        /// The key.
        key: String,
        /// The record it is in, as the file names it, or empty before the record's handle.
        owner: String,
    },
    /// A line that is neither `Key=value`, an `Add...` line nor part of a saved solid.
    UnrecognizedLine {
        /// The line.
        line: usize,
        /// Its start.
        text: String,
    },
    /// A value that does not parse as its key's format.
    BadValue {
        /// The line.
        line: usize,
        /// The key.
        key: String,
        /// The value (its start).
        value: String,
        /// What the format requires.
        expected: &'static str,
        /// The record it is in, as the file names it (`Entity.h.v=00040001`), or empty when
        /// the record's handle is not known yet.
        owner: String,
    },
    /// A field of one record kind inside a record of another.
    MixedRecord {
        /// The line.
        line: usize,
        /// The key or Add line.
        key: String,
        /// The kind of the record being read.
        open: &'static str,
        /// The record being read, as the file names it, or empty before its handle.
        owner: String,
    },
    /// The file ends in the middle of something.
    Truncated {
        /// Where the unfinished part starts.
        line: usize,
        /// What is unfinished.
        what: String,
    },
    /// A record without its handle.
    MissingHandle {
        /// The record's first line.
        line: usize,
        /// Its kind.
        record: &'static str,
    },
    /// A handle too large for SolveSpace's numbering: the handles of a request's (or a
    /// group's) entities and parameters are its own shifted left by 16 bits, below the bit
    /// that marks a group's.
    HandleTooLarge {
        /// The line of the handle.
        line: usize,
        /// The record kind.
        record: &'static str,
        /// The handle.
        handle: u32,
    },
    /// Two records of one kind with the same handle.
    Duplicate {
        /// The second definition.
        line: usize,
        /// Its kind.
        record: &'static str,
        /// The handle.
        handle: u32,
        /// The line of the first definition.
        first: usize,
    },
    /// A type number loci does not know.
    UnknownType {
        /// The line.
        line: usize,
        /// The record kind.
        record: &'static str,
        /// The record's handle.
        handle: u32,
        /// The number.
        code: i64,
    },
    /// A reference to an object that is not in the file.
    Dangling {
        /// The line of the reference.
        line: usize,
        /// The object holding it, as the file names it (`Constraint.h.v=00000003`).
        owner: String,
        /// The field's key (`Constraint.ptB.v`).
        field: &'static str,
        /// What kind of object it names.
        target: &'static str,
        /// The missing handle.
        handle: u32,
    },
    /// A field an object needs is absent.
    MissingField {
        /// The object's line.
        line: usize,
        /// The object, as the file names it (`Entity.h.v=00040001`).
        owner: String,
        /// The field's key.
        field: &'static str,
    },
    /// The model the file describes is invalid (wrong entity types, missing parameters ...).
    Model {
        /// The line of the object (or of its field) at fault.
        line: usize,
        /// What is wrong. Its handles are the file's; the message writes them as the file
        /// does.
        source: ModelError,
    },
    /// The file has no groups (an empty or cut-off file).
    NoGroups,
}

/// The key of a record kind's handle, e.g. `Entity.h.v` (a parameter's is `Param.h.v.`).
fn handle_key(record: &str) -> &'static str {
    match record {
        "Group" => "Group.h.v",
        "Param" => "Param.h.v.",
        "Request" => "Request.h.v",
        "Entity" => "Entity.h.v",
        "Constraint" => "Constraint.h.v",
        _ => "Style.h.v",
    }
}

/// An object as the file names it: `Request.h.v=00040000`.
pub(crate) fn file_name(record: &str, h: u32) -> String {
    format!("{}={h:08x}", handle_key(record))
}

/// A model object as the file names it.
fn object_name(o: ObjectId) -> String {
    match o {
        ObjectId::Param(h) => file_name("Param", h.0),
        ObjectId::Entity(h) => file_name("Entity", h.0),
        ObjectId::Constraint(h) => file_name("Constraint", h.0),
    }
}

/// The file's key for a field loci names `field` (`pt_a` is `Constraint.ptA.v`), or `None`
/// for fields loci derives (an entity's parameters, a copy's base and motion).
pub(crate) fn file_key(owner: ObjectId, field: &str) -> Option<&'static str> {
    Some(match owner {
        ObjectId::Param(_) => match field {
            "val" => "Param.val",
            _ => return None,
        },
        ObjectId::Entity(_) => match field {
            "workplane" => "Entity.workplane.v",
            "points[0]" | "origin" | "center" => "Entity.point[0].v",
            "points[1]" | "start" => "Entity.point[1].v",
            "points[2]" | "end" => "Entity.point[2].v",
            "points[3]" => "Entity.point[3].v",
            "normal" => "Entity.normal.v",
            "radius" => "Entity.distance.v",
            _ => return None,
        },
        ObjectId::Constraint(_) => match field {
            "workplane" => "Constraint.workplane.v",
            "pt_a" => "Constraint.ptA.v",
            "pt_b" => "Constraint.ptB.v",
            "entity_a" => "Constraint.entityA.v",
            "entity_b" => "Constraint.entityB.v",
            "entity_c" => "Constraint.entityC.v",
            "entity_d" => "Constraint.entityD.v",
            "val" => "Constraint.valA",
            _ => return None,
        },
    })
}

fn article(target: &str) -> &'static str {
    if target.starts_with(['a', 'e', 'i', 'o', 'u']) {
        "an"
    } else {
        "a"
    }
}

/// A model error in the file's terms: objects and fields as the file writes them, handles
/// in hex.
#[must_use]
pub fn model_message(e: &ModelError) -> String {
    // A field as the file writes it with its value, or loci's name for a derived one.
    let field_is = |owner: ObjectId, field: &str, target: &str, h: u32| match file_key(owner, field)
    {
        Some(key) => format!("{key}={h:08x}"),
        None if target == "param" => format!("its parameter {field}, Param.h.v.={h:08x},"),
        None => format!("its {field}, Entity.h.v={h:08x},"),
    };
    match e {
        ModelError::ZeroHandle { what, index } => {
            format!("{what} #{index} has handle 00000000; handles start at 00000001")
        }
        ModelError::DuplicateHandle { object } => {
            format!("{} is defined twice", object_name(*object))
        }
        ModelError::Dangling {
            owner,
            field,
            target,
            handle,
        } => match file_key(*owner, field) {
            Some(key) => format!(
                "{}: {key}={handle:08x} refers to {} {target} that is not in the file",
                object_name(*owner),
                article(target)
            ),
            None => format!(
                "{}: {} is not in the file",
                object_name(*owner),
                field_is(*owner, field, target, *handle)
            ),
        },
        ModelError::WrongKind {
            owner,
            field,
            entity,
            found,
            expected,
        } => format!(
            "{}: {} is {} {found}, but {expected} is expected",
            object_name(*owner),
            field_is(*owner, field, "entity", entity.0),
            article(found.name())
        ),
        ModelError::MissingField {
            owner,
            field,
            expected,
        } => format!(
            "{} has no {}; {expected} is expected",
            object_name(*owner),
            file_key(*owner, field).unwrap_or(field)
        ),
        ModelError::NonFinite {
            owner,
            field,
            value,
        } => format!(
            "{}: {} is {value}, not a finite number",
            object_name(*owner),
            file_key(*owner, field).unwrap_or(field)
        ),
        ModelError::OutOfRange {
            owner,
            field,
            value,
        } => format!(
            "{}: {} is {value:e}, beyond 1e100 in size, the largest number loci solves with",
            object_name(*owner),
            file_key(*owner, field).unwrap_or(field)
        ),
        ModelError::NeedsWorkplane { constraint, kind } => format!(
            "{} ({kind}) has no Constraint.workplane.v; it applies only in a workplane",
            object_name(ObjectId::Constraint(*constraint))
        ),
        ModelError::Cycle { entity } => format!(
            "{}: its references loop back to itself",
            object_name(ObjectId::Entity(*entity))
        ),
        #[allow(unreachable_patterns)]
        other => other.to_string(),
    }
}

/// A solve error in the file's terms (see [`model_message`]).
#[must_use]
pub fn solve_message(e: &SolveError) -> String {
    match e {
        SolveError::Model(m) => model_message(m),
        other => other.to_string(),
    }
}

impl fmt::Display for SlvsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SlvsError::NotText { line } => write!(f, "line {line}: not UTF-8 text"),
            SlvsError::UnknownKey { line, key, owner } if owner.is_empty() => {
                write!(f, "line {line}: unknown key `{key}`")
            }
            SlvsError::UnknownKey { line, key, owner } => {
                write!(f, "line {line}: {owner}: unknown key `{key}`")
            }
            SlvsError::UnrecognizedLine { line, text } => {
                write!(f, "line {line}: unrecognised line `{text}`")
            }
            SlvsError::BadValue {
                line,
                key,
                value,
                expected,
                owner,
            } => {
                write!(f, "line {line}: ")?;
                if !owner.is_empty() {
                    write!(f, "{owner}: ")?;
                }
                write!(f, "{key}={value}: expected {expected}")
            }
            SlvsError::MixedRecord {
                line,
                key,
                open,
                owner,
            } => {
                let record = if owner.is_empty() {
                    format!("a {open} record")
                } else {
                    format!("the {open} record {owner}")
                };
                write!(
                    f,
                    "line {line}: `{key}` inside {record} (a missing Add{open} line?)"
                )
            }
            SlvsError::Truncated { line, what } => {
                write!(f, "line {line}: file is truncated: {what}")
            }
            SlvsError::MissingHandle { line, record } => write!(
                f,
                "line {line}: {record} record has no handle ({})",
                handle_key(record)
            ),
            SlvsError::HandleTooLarge {
                line,
                record,
                handle,
            } => write!(
                f,
                "line {line}: {} is too large: the handles of a {}'s entities and parameters \
                 are its own shifted left by 16 bits, so it must be at most 00007fff",
                file_name(record, *handle),
                record.to_lowercase()
            ),
            SlvsError::Duplicate {
                line,
                record,
                handle,
                first,
            } => write!(
                f,
                "line {line}: {} is defined twice (first at line {first})",
                file_name(record, *handle)
            ),
            SlvsError::UnknownType {
                line,
                record,
                handle,
                code,
            } => write!(
                f,
                "line {line}: {}: unknown type {record}.type={code}",
                file_name(record, *handle)
            ),
            SlvsError::Dangling {
                line,
                owner,
                field,
                target,
                handle,
            } => write!(
                f,
                "line {line}: {owner}: {field}={handle:08x} refers to {} {target} that is not \
                 in the file",
                article(target)
            ),
            SlvsError::MissingField { line, owner, field } => {
                write!(f, "line {line}: {owner} has no {field}")
            }
            SlvsError::Model { line, source } => {
                write!(f, "line {line}: {}", model_message(source))
            }
            SlvsError::NoGroups => {
                f.write_str("the file has no groups: it is empty or not a SolveSpace file")
            }
        }
    }
}

// No `source`: every message already holds the text of what caused it, and a chain printer
// (`{:#}` in anyhow) would repeat it.
impl std::error::Error for SlvsError {}

impl SlvsError {
    /// The line the error concerns (1-based), or 0 for the whole file.
    #[must_use]
    pub fn line(&self) -> usize {
        match self {
            SlvsError::NotText { line }
            | SlvsError::UnknownKey { line, .. }
            | SlvsError::UnrecognizedLine { line, .. }
            | SlvsError::BadValue { line, .. }
            | SlvsError::MixedRecord { line, .. }
            | SlvsError::Truncated { line, .. }
            | SlvsError::MissingHandle { line, .. }
            | SlvsError::HandleTooLarge { line, .. }
            | SlvsError::Duplicate { line, .. }
            | SlvsError::UnknownType { line, .. }
            | SlvsError::Dangling { line, .. }
            | SlvsError::MissingField { line, .. }
            | SlvsError::Model { line, .. } => *line,
            SlvsError::NoGroups => 0,
        }
    }
}

impl SlvsFile {
    /// Reads a file's bytes.
    ///
    /// # Errors
    /// A malformed file: unknown keys or lines, bad numbers or handles, a truncated record,
    /// references to objects that are not in the file; each error names its line.
    pub fn parse(bytes: &[u8]) -> Result<Self, SlvsError> {
        let spans = records::line_spans(bytes);
        let parsed = records::parse(bytes, &spans)?;
        load::build(bytes.to_vec(), spans, &parsed.records, parsed.solid_lines)
    }

    /// The group with handle `h`.
    #[must_use]
    pub fn group(&self, h: GroupId) -> Option<&SlvsGroup> {
        self.groups.iter().find(|g| g.h == h)
    }

    /// The file's own parameter handles (those a `Param` record defines), in file order.
    pub fn file_params(&self) -> impl Iterator<Item = ParamId> + '_ {
        self.param_lines.iter().map(|p| p.h)
    }
}

#[cfg(test)]
mod tests;
