//! Where an error of a problem file is and what it says: a line and column for every object
//! and field, and the words that name them.

use super::fields::*;
use crate::error::{ModelError, SolveError};
use crate::model::{ConstraintKind, ObjectId, System};
use serde_json::value::RawValue;
use std::fmt;

/// A place in a file: line and column, both from 1 (the column counts characters).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Position {
    /// The line.
    pub line: usize,
    /// The column.
    pub column: usize,
}

impl Position {
    /// The place of byte `offset` of `text`.
    pub(super) fn at(text: &str, offset: usize) -> Self {
        let before = &text[..offset.min(text.len())];
        let start = before.rfind('\n').map_or(0, |i| i + 1);
        Position {
            line: before.bytes().filter(|&b| b == b'\n').count() + 1,
            column: before[start..].chars().count() + 1,
        }
    }
}

impl fmt::Display for Position {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {} column {}", self.line, self.column)
    }
}

/// A problem file loci cannot use: where, which object, which field, and what is wrong.
///
/// Displayed as `line 150 column 14: constraint 3 (pt_pt_distance): field "pt_a": expected
/// an entity handle (a positive integer), found "abc"`.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct JsonError {
    /// Where: the value at fault, or the object when a field is missing. `None` when the
    /// error has no place in the text.
    pub position: Option<Position>,
    /// The object at fault as messages name it (`param 11`, `entity 301 (point_in_2d)`,
    /// `constraint 3 (pt_pt_distance)`, `entities[4]` before its handle is known, `solve`),
    /// or empty for the file as a whole.
    pub object: String,
    /// The field at fault (`pt_a`, `params[1]`, `options.tolerance`), or empty.
    pub field: String,
    /// What is wrong, naming the field when there is one.
    pub message: String,
    /// The model error, when the file is valid JSON but the model it describes is not.
    pub model: Option<Box<ModelError>>,
}

impl fmt::Display for JsonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(p) = self.position {
            write!(f, "{p}: ")?;
        }
        if !self.object.is_empty() {
            write!(f, "{}: ", self.object)?;
        }
        f.write_str(&self.message)
    }
}

impl std::error::Error for JsonError {}

impl JsonError {
    pub(super) fn new(
        position: Option<Position>,
        object: &str,
        field: &str,
        message: impl Into<String>,
    ) -> Self {
        JsonError {
            position,
            object: object.to_string(),
            field: field.to_string(),
            message: message.into(),
            model: None,
        }
    }

    /// A model error of the system read from `text`, placed at its object (and field) in
    /// `text`, e.g. `line 150 column 14: constraint 3 (pt_pt_distance): field "pt_a": entity
    /// 399 does not exist`.
    #[must_use]
    pub fn from_model(text: &str, sys: &System, e: &ModelError) -> Self {
        let (owner, mut field, mut message) = model_parts(e);
        // `horizontal` and `vertical` take a line or two points: say so, and name the field
        // missing from the form the constraint has begun.
        if let (ModelError::MissingField { .. }, Owner::Object(ObjectId::Constraint(h))) =
            (e, &owner)
        {
            if let Some(c) = sys.constraint(*h) {
                if matches!(
                    c.kind,
                    ConstraintKind::Horizontal | ConstraintKind::Vertical
                ) {
                    field = match (c.pt_a, c.pt_b) {
                        (None, None) => "entity_a",
                        (None, Some(_)) => "pt_a",
                        (Some(_), _) => "pt_b",
                    }
                    .to_string();
                    message = format!(
                        "field \"{field}\" is missing; a {} constraint needs a line segment in \
                         \"entity_a\", or two points in \"pt_a\" and \"pt_b\"",
                        c.kind
                    );
                }
            }
        }
        let (object, position) = match owner {
            Owner::Object(o) => (name_of(sys, o), locate(text, o, &field)),
            Owner::Index(list, i) => (format!("{list}[{i}]"), locate_index(text, list, i, &field)),
            Owner::File => (String::new(), None),
        };
        JsonError {
            position,
            object,
            field,
            message,
            model: Some(Box::new(e.clone())),
        }
    }

    /// A solve error of the problem read from `text`: a model error (see
    /// [`JsonError::from_model`]), a dragged parameter that does not exist or an option out
    /// of range, placed in the `solve` section.
    #[must_use]
    pub fn from_solve(text: &str, sys: &System, e: &SolveError) -> Self {
        match e {
            SolveError::Model(m) => Self::from_model(text, sys, m),
            SolveError::UnknownDragged(h) => {
                let position = solve_field(text, "dragged").and_then(|(t, raw)| {
                    items(raw)
                        .into_iter()
                        .find(|r| r.get().trim() == h.to_string())
                        .or(Some(raw))
                        .map(|r| pos(t, r))
                });
                JsonError::new(
                    position,
                    "solve",
                    "dragged",
                    format!("field \"dragged\": param {h} does not exist"),
                )
            }
            SolveError::BadOption {
                name,
                value,
                expected,
            } => {
                let position = solve_field(text, "options").and_then(|(t, raw)| {
                    let fields = Fields::of(raw)?;
                    Some(pos(t, fields.find(name).unwrap_or(raw)))
                });
                let field = format!("options.{name}");
                JsonError::new(
                    position,
                    "solve",
                    &field,
                    format!("field \"{field}\": {value} is out of range: expected {expected}"),
                )
            }
            #[allow(unreachable_patterns)]
            other => JsonError::new(None, "", "", other.to_string()),
        }
    }
}

/// Where `object` is in `text`: the value of its `field` (`params[1]` is the second item of
/// `params`) when it is written there, else the object. `None` when the text does not hold
/// the object.
#[must_use]
pub fn locate(text: &str, object: ObjectId, field: &str) -> Option<Position> {
    let (list, h) = match object {
        ObjectId::Param(h) => ("params", h.0),
        ObjectId::Entity(h) => ("entities", h.0),
        ObjectId::Constraint(h) => ("constraints", h.0),
    };
    let top = Fields::of(serde_json::from_str::<&RawValue>(text).ok()?)?;
    let all = items(top.find(list)?);
    let raw = all.into_iter().find(|r| {
        Fields::of(r)
            .and_then(|f| f.find("h"))
            .is_some_and(|v| v.get().trim() == h.to_string())
    })?;
    Some(place_field(text, raw, field))
}

/// The place of `field` of object `raw`, or of the object.
pub(super) fn place_field(text: &str, raw: &RawValue, field: &str) -> Position {
    let (name, index) = split_index(field);
    let at = Fields::of(raw)
        .and_then(|f| f.find(name))
        .map(|v| match index {
            Some(i) => items(v).get(i).copied().unwrap_or(v),
            None => v,
        })
        .unwrap_or(raw);
    pos(text, at)
}

pub(super) fn locate_index(text: &str, list: &str, i: usize, field: &str) -> Option<Position> {
    let top = Fields::of(serde_json::from_str::<&RawValue>(text).ok()?)?;
    let raw = *items(top.find(list)?).get(i)?;
    Some(place_field(text, raw, field))
}

/// The `solve` section's `field`, with the text it is in.
pub(super) fn solve_field<'a>(text: &'a str, field: &str) -> Option<(&'a str, &'a RawValue)> {
    let top = Fields::of(serde_json::from_str::<&RawValue>(text).ok()?)?;
    let solve = Fields::of(top.find("solve")?)?;
    Some((text, solve.find(field)?))
}

/// `params[1]` -> (`params`, 1).
pub(super) fn split_index(field: &str) -> (&str, Option<usize>) {
    match field.strip_suffix(']').and_then(|f| f.split_once('[')) {
        Some((name, i)) => (name, i.parse().ok()),
        None => (field, None),
    }
}

/// Whom a model error is about.
pub(super) enum Owner {
    Object(ObjectId),
    /// An object known only by its place in a list (a zero handle).
    Index(&'static str, usize),
    /// No object in particular.
    File,
}

/// A model error as (owner, field, message about the field).
pub(super) fn model_parts(e: &ModelError) -> (Owner, String, String) {
    let o = Owner::Object;
    match e {
        ModelError::ZeroHandle { what, index } => {
            let list = match *what {
                "param" => "params",
                "entity" => "entities",
                _ => "constraints",
            };
            (
                Owner::Index(list, *index),
                "h".into(),
                "field \"h\": 0 is not a handle; handles start at 1".into(),
            )
        }
        ModelError::DuplicateHandle { object } => {
            (o(*object), String::new(), "is defined twice".into())
        }
        ModelError::Dangling {
            owner,
            field,
            target,
            handle,
        } => (
            o(*owner),
            (*field).into(),
            if *handle == 0 {
                format!("field \"{field}\": 0 refers to no {target}; handles start at 1")
            } else {
                format!("field \"{field}\": {target} {handle} does not exist")
            },
        ),
        ModelError::WrongKind {
            owner,
            field,
            entity,
            found,
            expected,
        } => (
            o(*owner),
            (*field).into(),
            format!(
                "field \"{field}\": {entity} is {} {found}, but {expected} is expected",
                article(found.name())
            ),
        ),
        ModelError::MissingField {
            owner,
            field,
            expected,
        } => (
            o(*owner),
            (*field).into(),
            format!("field \"{field}\" is missing; {expected} is expected"),
        ),
        ModelError::NonFinite {
            owner,
            field,
            value,
        } => (
            o(*owner),
            (*field).into(),
            format!("field \"{field}\": {value} is not a finite number"),
        ),
        ModelError::OutOfRange {
            owner,
            field,
            value,
        } => (
            o(*owner),
            (*field).into(),
            format!(
                "field \"{field}\": {value:e} is beyond 1e100 in size, the largest number loci \
                 solves with"
            ),
        ),
        ModelError::NeedsWorkplane { constraint, kind } => (
            o(ObjectId::Constraint(*constraint)),
            "workplane".into(),
            format!(
                "field \"workplane\" is missing; a {kind} constraint applies only in a \
                 workplane, so it needs one"
            ),
        ),
        ModelError::Cycle { entity } => (
            o(ObjectId::Entity(*entity)),
            String::new(),
            "its references loop back to itself".into(),
        ),
        #[allow(unreachable_patterns)]
        other => (Owner::File, String::new(), other.to_string()),
    }
}

/// An object as messages name it: `constraint 3 (pt_pt_distance)`.
pub(super) fn name_of(sys: &System, o: ObjectId) -> String {
    match o {
        ObjectId::Param(h) => h.to_string(),
        ObjectId::Entity(h) => match sys.entity(h) {
            Some(e) => format!("{h} ({})", e.entity_type()),
            None => h.to_string(),
        },
        ObjectId::Constraint(h) => match sys.constraint(h) {
            Some(c) => format!("{h} ({})", c.kind),
            None => h.to_string(),
        },
    }
}

pub(super) fn article(word: &str) -> &'static str {
    if word.starts_with(['a', 'e', 'i', 'o', 'u']) {
        "an"
    } else {
        "a"
    }
}

/// The byte offset of `part` in `text` (`part` is a slice of it).
pub(super) fn offset(text: &str, part: &str) -> usize {
    (part.as_ptr() as usize).saturating_sub(text.as_ptr() as usize)
}

pub(super) fn pos(text: &str, raw: &RawValue) -> Position {
    Position::at(text, offset(text, raw.get()))
}
