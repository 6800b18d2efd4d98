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

use crate::model::{GroupId, ParamId, System};
use crate::ModelError;
use thiserror::Error;

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
#[derive(Clone, Debug, Error, PartialEq)]
#[non_exhaustive]
pub enum SlvsError {
    /// A line that is not text.
    #[error("line {line}: not UTF-8 text")]
    NotText {
        /// The line.
        line: usize,
    },
    /// A `Key=value` line whose key SolveSpace does not write.
    #[error("line {line}: unknown key `{key}`")]
    UnknownKey {
        /// The line.
        line: usize,
        /// The key.
        key: String,
    },
    /// A line that is neither `Key=value`, an `Add...` line nor part of a saved solid.
    #[error("line {line}: unrecognised line `{text}`")]
    UnrecognizedLine {
        /// The line.
        line: usize,
        /// Its start.
        text: String,
    },
    /// A value that does not parse as its key's format.
    #[error("line {line}: {key}={value}: expected {expected}")]
    BadValue {
        /// The line.
        line: usize,
        /// The key.
        key: String,
        /// The value (its start).
        value: String,
        /// What the format requires.
        expected: &'static str,
    },
    /// A field of one record kind inside a record of another.
    #[error("line {line}: `{key}` inside a {open} record (a missing Add{open} line?)")]
    MixedRecord {
        /// The line.
        line: usize,
        /// The key or Add line.
        key: String,
        /// The kind of the record being read.
        open: &'static str,
    },
    /// The file ends in the middle of something.
    #[error("line {line}: file is truncated: {what}")]
    Truncated {
        /// Where the unfinished part starts.
        line: usize,
        /// What is unfinished.
        what: String,
    },
    /// A record without its handle.
    #[error("line {line}: {record} record has no handle")]
    MissingHandle {
        /// The record's first line.
        line: usize,
        /// Its kind.
        record: &'static str,
    },
    /// Two records of one kind with the same handle.
    #[error("line {line}: {record} {handle:08x} is defined twice")]
    Duplicate {
        /// The second definition.
        line: usize,
        /// Its kind.
        record: &'static str,
        /// The handle.
        handle: u32,
    },
    /// A type number loci does not know.
    #[error("line {line}: unknown {record} type {code}")]
    UnknownType {
        /// The line.
        line: usize,
        /// The record kind.
        record: &'static str,
        /// The number.
        code: i64,
    },
    /// A reference to an object that is not in the file.
    #[error(
        "line {line}: {owner}: {field} refers to {target} {handle:08x}, which is not in the file"
    )]
    Dangling {
        /// The line of the reference.
        line: usize,
        /// The object holding it.
        owner: String,
        /// The field.
        field: &'static str,
        /// What kind of object it names.
        target: &'static str,
        /// The missing handle.
        handle: u32,
    },
    /// A field an object needs is absent.
    #[error("line {line}: {owner} has no {field}")]
    MissingField {
        /// The object's line.
        line: usize,
        /// The object.
        owner: String,
        /// The field.
        field: &'static str,
    },
    /// The model the file describes is invalid (wrong entity types, missing parameters ...).
    #[error("line {line}: {source}")]
    Model {
        /// The line of the object at fault.
        line: usize,
        /// What is wrong.
        source: ModelError,
    },
    /// The file has no groups (an empty or cut-off file).
    #[error("the file has no groups: it is empty or not a SolveSpace file")]
    NoGroups,
}

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
