//! Reading a problem object by object, so that every error names the object and the field at
//! fault and the line and column where it is written.
//!
//! The text is first checked as JSON as a whole (a syntax error has its place from the
//! parser). Then each parameter, entity and constraint is taken as raw text, whose place in
//! the file is known, and its fields are read one by one: a missing field is reported at its
//! object, a wrong value at the value. A derived `Deserialize` cannot do this for the model
//! (entities are told apart by a `type` tag beside their other fields, and serde buffers such
//! objects, losing their place).

use super::{Options, Problem, SolveRequest};
use crate::error::{ModelError, SolveError};
use crate::model::{
    Constraint, ConstraintKind, Entity, EntityId, EntityKind, EntityType, GroupId, ObjectId, Param,
    ParamId, System,
};
use serde::de::{Deserialize, Deserializer, MapAccess, Visitor};
use serde_json::value::RawValue;
use std::borrow::Cow;
use std::collections::HashMap;
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
    fn at(text: &str, offset: usize) -> Self {
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
    fn new(
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
fn place_field(text: &str, raw: &RawValue, field: &str) -> Position {
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

fn locate_index(text: &str, list: &str, i: usize, field: &str) -> Option<Position> {
    let top = Fields::of(serde_json::from_str::<&RawValue>(text).ok()?)?;
    let raw = *items(top.find(list)?).get(i)?;
    Some(place_field(text, raw, field))
}

/// The `solve` section's `field`, with the text it is in.
fn solve_field<'a>(text: &'a str, field: &str) -> Option<(&'a str, &'a RawValue)> {
    let top = Fields::of(serde_json::from_str::<&RawValue>(text).ok()?)?;
    let solve = Fields::of(top.find("solve")?)?;
    Some((text, solve.find(field)?))
}

/// `params[1]` -> (`params`, 1).
fn split_index(field: &str) -> (&str, Option<usize>) {
    match field.strip_suffix(']').and_then(|f| f.split_once('[')) {
        Some((name, i)) => (name, i.parse().ok()),
        None => (field, None),
    }
}

/// Whom a model error is about.
enum Owner {
    Object(ObjectId),
    /// An object known only by its place in a list (a zero handle).
    Index(&'static str, usize),
    /// No object in particular.
    File,
}

/// A model error as (owner, field, message about the field).
fn model_parts(e: &ModelError) -> (Owner, String, String) {
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
fn name_of(sys: &System, o: ObjectId) -> String {
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

fn article(word: &str) -> &'static str {
    if word.starts_with(['a', 'e', 'i', 'o', 'u']) {
        "an"
    } else {
        "a"
    }
}

/// The byte offset of `part` in `text` (`part` is a slice of it).
fn offset(text: &str, part: &str) -> usize {
    (part.as_ptr() as usize).saturating_sub(text.as_ptr() as usize)
}

fn pos(text: &str, raw: &RawValue) -> Position {
    Position::at(text, offset(text, raw.get()))
}

/// A field name, borrowed when it has no escapes.
struct Key<'a>(Cow<'a, str>);

impl<'de> Deserialize<'de> for Key<'de> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Key<'de>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a field name")
            }
            fn visit_borrowed_str<E>(self, v: &'de str) -> Result<Key<'de>, E> {
                Ok(Key(Cow::Borrowed(v)))
            }
            fn visit_str<E>(self, v: &str) -> Result<Key<'de>, E> {
                Ok(Key(Cow::Owned(v.to_string())))
            }
        }
        d.deserialize_str(V)
    }
}

/// The fields of one JSON object, in the order written (repeats kept).
struct Fields<'a>(Vec<(Cow<'a, str>, &'a RawValue)>);

impl<'de> Deserialize<'de> for Fields<'de> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Fields<'de>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an object")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut m: A) -> Result<Fields<'de>, A::Error> {
                let mut v = Vec::new();
                while let Some((k, raw)) = m.next_entry::<Key<'de>, &'de RawValue>()? {
                    v.push((k.0, raw));
                }
                Ok(Fields(v))
            }
        }
        d.deserialize_map(V)
    }
}

impl<'a> Fields<'a> {
    /// The fields of `raw`, or `None` when it is not an object.
    fn of(raw: &'a RawValue) -> Option<Self> {
        if !raw.get().starts_with('{') {
            return None;
        }
        serde_json::from_str(raw.get()).ok()
    }

    fn find(&self, key: &str) -> Option<&'a RawValue> {
        self.0.iter().find(|(k, _)| k == key).map(|(_, v)| *v)
    }
}

/// The items of array `raw` (none when it is not an array).
fn items(raw: &RawValue) -> Vec<&RawValue> {
    if !raw.get().starts_with('[') {
        return Vec::new();
    }
    serde_json::from_str(raw.get()).unwrap_or_default()
}

/// A value as a message shows it: scalars as written (cut short), containers by kind.
fn found(raw: &str) -> String {
    match raw.as_bytes().first() {
        Some(b'{') => "an object".into(),
        Some(b'[') => match serde_json::from_str::<Vec<&RawValue>>(raw) {
            Ok(v) if v.is_empty() => "an empty array".into(),
            Ok(v) if v.len() == 1 => "an array of 1 item".into(),
            Ok(v) => format!("an array of {} items", v.len()),
            Err(_) => "an array".into(),
        },
        _ if raw.chars().count() > 40 => {
            let cut: String = raw.chars().take(37).collect();
            format!("{cut}...")
        }
        _ => raw.to_string(),
    }
}

/// A hint for a number written as a string.
fn quoted_number_hint(raw: &str) -> &'static str {
    let inner = raw.strip_prefix('"').and_then(|r| r.strip_suffix('"'));
    match inner {
        Some(s) if s.trim().parse::<f64>().is_ok() => " (numbers are written without quotes)",
        _ => "",
    }
}

/// What a value must be, for messages and checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Expect {
    /// A handle of a param, an entity or a constraint (the word).
    Handle(&'static str),
    Group,
    Number,
    Bool,
    I32,
    Count,
}

impl Expect {
    fn describe(self) -> String {
        match self {
            Expect::Handle(what) => format!("{} {what} handle (a positive integer)", article(what)),
            Expect::Group => "a group (an integer from 0 to 4294967295)".into(),
            Expect::Number => "a number".into(),
            Expect::Bool => "true or false".into(),
            Expect::I32 => "an integer".into(),
            Expect::Count => "a whole number (0 or more)".into(),
        }
    }

    fn plural(self) -> String {
        match self {
            Expect::Handle(what) => format!("{what} handles"),
            Expect::Number => "numbers".into(),
            other => other.describe(),
        }
    }
}

/// A parsed scalar.
#[derive(Clone, Copy, Debug)]
enum Scalar {
    U(u64),
    I(i64),
    F(f64),
    B(bool),
}

/// Reads scalar `raw` as `want`; the error is the message about its value.
fn scalar(raw: &str, want: Expect) -> Result<Scalar, String> {
    let wrong = || {
        format!(
            "expected {}, found {}{}",
            want.describe(),
            found(raw),
            quoted_number_hint(raw)
        )
    };
    let is_number = raw
        .as_bytes()
        .first()
        .is_some_and(|b| *b == b'-' || b.is_ascii_digit());
    match want {
        Expect::Bool => match raw {
            "true" => Ok(Scalar::B(true)),
            "false" => Ok(Scalar::B(false)),
            _ => Err(wrong()),
        },
        Expect::Number => {
            if !is_number {
                return Err(wrong());
            }
            match raw.parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(Scalar::F(v)),
                _ => Err(format!(
                    "expected a finite number, found {}, which is too large for a double",
                    found(raw)
                )),
            }
        }
        Expect::Handle(_) | Expect::Group | Expect::Count => {
            if !is_number {
                return Err(wrong());
            }
            match raw.parse::<u64>() {
                Ok(v) => Ok(Scalar::U(v)),
                Err(_) if raw.bytes().all(|b| b == b'-' || b.is_ascii_digit()) => {
                    if raw.starts_with('-') {
                        Err(wrong())
                    } else {
                        Ok(Scalar::U(u64::MAX))
                    }
                }
                Err(_) => Err(wrong()),
            }
        }
        Expect::I32 => {
            if !is_number {
                return Err(wrong());
            }
            match raw.parse::<i64>() {
                Ok(v) => Ok(Scalar::I(v)),
                Err(_) => Err(wrong()),
            }
        }
    }
}

/// An object's own handle: 1 or more.
fn handle_value(raw: &str, what: &'static str) -> Result<u32, String> {
    let v = reference_value(raw, what)?;
    if v == 0 {
        return Err(format!(
            "expected {}, found 0: handles start at 1",
            Expect::Handle(what).describe()
        ));
    }
    Ok(v)
}

/// A reference to another object. 0 reads (as it always has), and a solve reports that no
/// object has it when the field is one the type uses.
fn reference_value(raw: &str, what: &'static str) -> Result<u32, String> {
    let Scalar::U(v) = scalar(raw, Expect::Handle(what))? else {
        unreachable!("handles are read as unsigned")
    };
    u32::try_from(v).map_err(|_| {
        format!(
            "expected {}, found {}, larger than the largest handle, 4294967295",
            Expect::Handle(what).describe(),
            found(raw)
        )
    })
}

fn group_value(raw: &str) -> Result<u32, String> {
    let Scalar::U(v) = scalar(raw, Expect::Group)? else {
        unreachable!("groups are read as unsigned")
    };
    u32::try_from(v).map_err(|_| {
        format!(
            "expected {}, found {}",
            Expect::Group.describe(),
            found(raw)
        )
    })
}

fn number_value(raw: &str) -> Result<f64, String> {
    match scalar(raw, Expect::Number)? {
        Scalar::F(v) => Ok(v),
        _ => unreachable!("numbers are read as floats"),
    }
}

fn bool_value(raw: &str) -> Result<bool, String> {
    match scalar(raw, Expect::Bool)? {
        Scalar::B(v) => Ok(v),
        _ => unreachable!("flags are read as booleans"),
    }
}

fn i32_value(raw: &str) -> Result<i32, String> {
    let Scalar::I(v) = scalar(raw, Expect::I32)? else {
        unreachable!("integers are read as signed")
    };
    i32::try_from(v).map_err(|_| {
        format!(
            "expected an integer from -2147483648 to 2147483647, found {}",
            found(raw)
        )
    })
}

fn count_value(raw: &str) -> Result<usize, String> {
    let Scalar::U(v) = scalar(raw, Expect::Count)? else {
        unreachable!("counts are read as unsigned")
    };
    Ok(usize::try_from(v).unwrap_or(usize::MAX))
}

/// The closest of `names` to `word`, when it is close enough to be a slip.
fn suggest<'n>(word: &str, names: impl IntoIterator<Item = &'n str>) -> Option<&'n str> {
    let w = word.to_ascii_lowercase().replace(['-', ' '], "_");
    names
        .into_iter()
        .map(|n| (edit_distance(&w, n), n))
        .filter(|(d, n)| *d <= 2.max(n.len() / 4))
        .min_by_key(|(d, _)| *d)
        .map(|(_, n)| n)
}

fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for j in 0..b.len() {
            let cur = row[j + 1];
            row[j + 1] = if ca == b[j] {
                prev
            } else {
                1 + prev.min(row[j]).min(row[j + 1])
            };
            prev = cur;
        }
    }
    row[b.len()]
}

/// `"a", "b" and "c"`.
fn quoted_list(names: &[&str]) -> String {
    let q: Vec<String> = names.iter().map(|n| format!("\"{n}\"")).collect();
    match q.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => q.join(""),
    }
}

/// `expected one of "a", "b", "c"`.
fn one_of(names: &[&str]) -> String {
    let q: Vec<String> = names.iter().map(|n| format!("\"{n}\"")).collect();
    format!("expected one of {}", q.join(", "))
}

/// One JSON object being read: its fields, which have been used, and how to name it.
struct Obj<'a> {
    text: &'a str,
    raw: &'a RawValue,
    name: String,
    /// Put before field names in messages: `options.` for the solve options.
    prefix: &'static str,
    fields: Vec<(Cow<'a, str>, &'a RawValue)>,
    used: Vec<bool>,
}

impl<'a> Obj<'a> {
    /// `raw` as an object named `name`; an error when it is not one or repeats a field.
    fn new(text: &'a str, raw: &'a RawValue, name: String) -> Result<Self, JsonError> {
        let Some(Fields(fields)) = Fields::of(raw) else {
            return Err(JsonError::new(
                Some(pos(text, raw)),
                &name,
                "",
                format!("expected an object, found {}", found(raw.get())),
            ));
        };
        for (i, (k, v)) in fields.iter().enumerate() {
            if fields[..i].iter().any(|(k2, _)| k2 == k) {
                // (An object repeating a field: the later value would silently win.)
                return Err(JsonError::new(
                    Some(pos(text, v)),
                    &name,
                    k,
                    format!("field \"{k}\" appears twice"),
                ));
            }
        }
        let used = vec![false; fields.len()];
        Ok(Obj {
            text,
            raw,
            name,
            prefix: "",
            fields,
            used,
        })
    }

    fn position(&self) -> Position {
        pos(self.text, self.raw)
    }

    fn at(&self, raw: &RawValue) -> Position {
        pos(self.text, raw)
    }

    /// An error about `field` at `raw` (the object when `None`); `message` writes the field
    /// as `{f}`, replaced by its label (`"options.tolerance"`).
    fn err(&self, raw: Option<&RawValue>, field: &str, message: String) -> JsonError {
        let position = raw.map_or_else(|| self.position(), |r| self.at(r));
        let label = format!("{}{field}", self.prefix);
        let message = message.replacen("{f}", &label, 1);
        JsonError::new(Some(position), &self.name, &label, message)
    }

    fn get(&mut self, key: &str) -> Option<&'a RawValue> {
        let i = self.fields.iter().position(|(k, _)| k == key)?;
        self.used[i] = true;
        Some(self.fields[i].1)
    }

    /// Field `key`, which must be there: `needs` says what it holds.
    fn need(
        &mut self,
        key: &str,
        needs: impl FnOnce() -> String,
    ) -> Result<&'a RawValue, JsonError> {
        match self.get(key) {
            Some(raw) => Ok(raw),
            None => Err(self.err(
                None,
                key,
                format!("field \"{{f}}\" is missing; it must be {}", needs()),
            )),
        }
    }

    fn value<T>(
        &mut self,
        key: &str,
        read: impl Fn(&str) -> Result<T, String>,
    ) -> Result<Option<T>, JsonError> {
        let Some(raw) = self.get(key) else {
            return Ok(None);
        };
        read(raw.get())
            .map(Some)
            .map_err(|m| self.err(Some(raw), key, format!("field \"{{f}}\": {m}")))
    }

    /// An optional reference to another object.
    fn handle(&mut self, key: &str, what: &'static str) -> Result<Option<u32>, JsonError> {
        self.value(key, |r| reference_value(r, what))
    }

    /// A reference the object needs.
    fn need_ref(&mut self, key: &str, what: &'static str) -> Result<u32, JsonError> {
        self.need(key, || Expect::Handle(what).describe())?;
        Ok(self.handle(key, what)?.unwrap_or_default())
    }

    /// The object's own handle, `h`.
    fn own_handle(&mut self, what: &'static str) -> Result<u32, JsonError> {
        self.need("h", || Expect::Handle(what).describe())?;
        Ok(self
            .value("h", |r| handle_value(r, what))?
            .unwrap_or_default())
    }

    fn need_group(&mut self) -> Result<u32, JsonError> {
        self.need("group", || Expect::Group.describe())?;
        Ok(self.value("group", group_value)?.unwrap_or_default())
    }

    /// An array of `N` values read by `read`, each `want`; `items` names them in order.
    fn array<T: Copy + Default, const N: usize>(
        &mut self,
        key: &str,
        want: Expect,
        names: &str,
        read: impl Fn(&str) -> Result<T, String>,
    ) -> Result<[T; N], JsonError> {
        let what = || format!("an array of {N} {} {names}", want.plural());
        let raw = self.need(key, what)?;
        let list = items(raw);
        if !raw.get().starts_with('[') || list.len() != N {
            return Err(self.err(
                Some(raw),
                key,
                format!(
                    "field \"{{f}}\": expected {}, found {}",
                    what(),
                    found(raw.get())
                ),
            ));
        }
        let mut out = [T::default(); N];
        for (i, item) in list.iter().enumerate() {
            out[i] = read(item.get())
                .map_err(|m| self.err(Some(item), key, format!("field \"{{f}}[{i}]\": {m}")))?;
        }
        Ok(out)
    }

    fn handles<const N: usize>(
        &mut self,
        key: &str,
        what: &'static str,
        names: &str,
    ) -> Result<[u32; N], JsonError> {
        self.array(key, Expect::Handle(what), names, |r| {
            reference_value(r, what)
        })
    }

    /// Fails on the first field not in `allowed`. For the message, `describe` gives the
    /// object's kind (`a param`, `a point_in_2d entity`) and the fields other kinds of it
    /// have.
    fn finish(
        &self,
        allowed: &[&[&str]],
        describe: impl FnOnce() -> (String, Vec<&'static str>),
    ) -> Result<(), JsonError> {
        for (i, (k, v)) in self.fields.iter().enumerate() {
            if self.used[i] || allowed.iter().any(|a| a.contains(&k.as_ref())) {
                continue;
            }
            let (kind, elsewhere) = describe();
            let allowed = allowed.concat();
            let has = format!("{kind} has {}", quoted_list(&allowed));
            let message = if elsewhere.contains(&k.as_ref()) {
                format!("field \"{{f}}\" is not one {kind} has; {has}")
            } else {
                match suggest(k, allowed.iter().copied()) {
                    Some(s) => format!("unknown field \"{{f}}\" (did you mean \"{s}\"?); {has}"),
                    None => format!("unknown field \"{{f}}\"; {has}"),
                }
            };
            return Err(self.err(Some(v), k, message));
        }
        Ok(())
    }
}

/// Every entity type, in the order of [`EntityType`].
const ENTITY_TYPES: [EntityType; 13] = [
    EntityType::PointIn3d,
    EntityType::PointIn2d,
    EntityType::PointNTrans,
    EntityType::PointNRotTrans,
    EntityType::NormalNRot,
    EntityType::NormalIn3d,
    EntityType::NormalIn2d,
    EntityType::Distance,
    EntityType::Workplane,
    EntityType::LineSegment,
    EntityType::Cubic,
    EntityType::Circle,
    EntityType::ArcOfCircle,
];

/// The fields every entity has.
const ENTITY_COMMON: [&str; 4] = ["h", "group", "type", "workplane"];

/// The fields of an entity type besides [`ENTITY_COMMON`].
pub(crate) fn entity_fields(t: EntityType) -> &'static [&'static str] {
    match t {
        EntityType::PointIn3d | EntityType::PointIn2d | EntityType::NormalIn3d => &["params"],
        EntityType::PointNTrans => &["params", "base", "translation", "times"],
        EntityType::PointNRotTrans => &["params", "base", "translation", "rotation"],
        EntityType::NormalNRot => &["params", "base", "rotation"],
        EntityType::NormalIn2d => &[],
        EntityType::Distance => &["param"],
        EntityType::Workplane => &["origin", "normal"],
        EntityType::LineSegment | EntityType::Cubic => &["points"],
        EntityType::Circle => &["center", "normal", "radius"],
        EntityType::ArcOfCircle => &["normal", "center", "start", "end"],
    }
}

/// The fields of a constraint.
pub(crate) const CONSTRAINT_FIELDS: [&str; 15] = [
    "h",
    "group",
    "type",
    "workplane",
    "val",
    "pt_a",
    "pt_b",
    "entity_a",
    "entity_b",
    "entity_c",
    "entity_d",
    "other",
    "other2",
    "reference",
    "signed",
];

const PARAM_FIELDS: [&str; 3] = ["h", "group", "val"];
const TOP_FIELDS: [&str; 4] = ["params", "entities", "constraints", "solve"];
const SOLVE_FIELDS: [&str; 4] = ["group", "dragged", "calculate_failed", "options"];
const OPTION_FIELDS: [&str; 7] = [
    "tolerance",
    "max_iterations",
    "dragged_scale",
    "rank_tolerance",
    "verify_conflicts_up_to",
    "nearest",
    "solvespace_angles",
];

/// Reads `type`: a name `of` knows, or an error naming all of `names`.
fn type_name<T: Copy>(
    o: &mut Obj<'_>,
    kind: &str,
    names: impl Fn() -> Vec<&'static str>,
    of: impl Fn(&str) -> Option<T>,
) -> Result<T, JsonError> {
    let raw = o.need("type", || one_of(&names()).replacen("expected ", "", 1))?;
    let text = raw.get();
    // A name without escapes, as written (the common case), or any JSON string.
    let plain = text
        .strip_prefix('"')
        .and_then(|t| t.strip_suffix('"'))
        .filter(|t| !t.contains('\\'));
    let name = match plain {
        Some(p) => Ok(Cow::Borrowed(p)),
        None => serde_json::from_str::<Cow<'_, str>>(text),
    };
    if let Ok(name) = name {
        if let Some(t) = of(&name) {
            return Ok(t);
        }
        let names = names();
        if text.starts_with('"') {
            let hint = match suggest(&name, names.iter().copied()) {
                Some(s) => format!(" (did you mean \"{s}\"?)"),
                None => String::new(),
            };
            return Err(o.err(
                Some(raw),
                "type",
                format!(
                    "field \"type\": unknown {kind} type {text}{hint}; {}",
                    one_of(&names)
                ),
            ));
        }
    }
    Err(o.err(
        Some(raw),
        "type",
        format!(
            "field \"type\": {}, found {}",
            one_of(&names()),
            found(text)
        ),
    ))
}

/// Handles already seen in one list, with where (a byte offset: lines are counted only for
/// a message).
struct Seen {
    what: &'static str,
    at: HashMap<u32, usize>,
}

impl Seen {
    fn new(what: &'static str) -> Self {
        Seen {
            what,
            at: HashMap::new(),
        }
    }

    /// Records handle `h` of object `o`; an error when it was seen before.
    fn add(&mut self, o: &Obj<'_>, h: u32) -> Result<(), JsonError> {
        let Some(first) = self.at.insert(h, offset(o.text, o.raw.get())) else {
            return Ok(());
        };
        let first = Position::at(o.text, first);
        let what = self.what;
        let object = match what {
            "param" => ObjectId::Param(ParamId(h)),
            "entity" => ObjectId::Entity(EntityId(h)),
            _ => ObjectId::Constraint(crate::ConstraintId(h)),
        };
        let at = o.fields.iter().find(|(k, _)| k == "h").map(|(_, v)| *v);
        let mut e = o.err(
            at,
            "h",
            format!(
                "handle {h} is already used by the {what} at {first} (each {what} needs a \
                 handle of its own)"
            ),
        );
        e.model = Some(Box::new(ModelError::DuplicateHandle { object }));
        Err(e)
    }
}

/// Reads a problem, checking every field of every object.
pub(super) fn problem(text: &str) -> Result<Problem, JsonError> {
    let top: &RawValue = serde_json::from_str(text).map_err(|e| syntax(text, &e))?;
    let mut o = Obj::new(text, top, String::new()).map_err(|mut e| {
        e.message = format!(
            "expected an object with \"params\", \"entities\", \"constraints\" and \"solve\", \
             found {}",
            found(top.get())
        );
        e
    })?;
    let params = list(&mut o, "params", Seen::new("param"), param)?;
    let entities = list(&mut o, "entities", Seen::new("entity"), entity)?;
    let constraints = list(&mut o, "constraints", Seen::new("constraint"), constraint)?;
    let solve = match o.get("solve") {
        Some(raw) if raw.get() == "null" => None,
        Some(raw) => Some(solve_request(text, raw)?),
        None => None,
    };
    o.finish(&[&TOP_FIELDS], || ("a problem".into(), Vec::new()))?;
    // Handles are checked above, so this does not fail; if it did, say where.
    let system = System::from_parts(params, entities, constraints)
        .map_err(|e| JsonError::from_model(text, &System::new(), &e))?;
    Ok(Problem { system, solve })
}

/// The objects of list `key`, each read by `read`, their handles checked for repeats.
fn list<'a, T>(
    top: &mut Obj<'a>,
    key: &str,
    mut seen: Seen,
    read: impl Fn(&mut Obj<'a>) -> Result<(T, u32), JsonError>,
) -> Result<Vec<T>, JsonError> {
    let Some(raw) = top.get(key) else {
        return Ok(Vec::new());
    };
    if !raw.get().starts_with('[') {
        return Err(top.err(
            Some(raw),
            key,
            format!(
                "field \"{key}\": expected an array of {key}, found {}",
                found(raw.get())
            ),
        ));
    }
    let all = items(raw);
    let mut out = Vec::with_capacity(all.len());
    for (i, item) in all.into_iter().enumerate() {
        let mut o = Obj::new(top.text, item, format!("{key}[{i}]"))?;
        let (v, h) = read(&mut o)?;
        seen.add(&o, h)?;
        out.push(v);
    }
    Ok(out)
}

fn param(o: &mut Obj<'_>) -> Result<(Param, u32), JsonError> {
    let h = o.own_handle("param")?;
    o.name = ParamId(h).to_string();
    let group = o.need_group()?;
    o.need("val", || "a number".into())?;
    let val = o.value("val", number_value)?.unwrap_or_default();
    o.finish(&[&PARAM_FIELDS], || ("a param".into(), Vec::new()))?;
    Ok((Param::new(h, group, val), h))
}

fn entity(o: &mut Obj<'_>) -> Result<(Entity, u32), JsonError> {
    let h = o.own_handle("entity")?;
    o.name = EntityId(h).to_string();
    let names = || ENTITY_TYPES.iter().map(|t| t.name()).collect();
    let t = type_name(o, "entity", names, |n| {
        ENTITY_TYPES.iter().copied().find(|t| t.name() == n)
    })?;
    o.name = format!("{} ({t})", EntityId(h));
    let group = o.need_group()?;
    let workplane = o.handle("workplane", "entity")?.map(EntityId);
    let p = ParamId;
    let e = EntityId;
    let kind = match t {
        EntityType::PointIn3d => EntityKind::PointIn3d {
            params: o.handles("params", "param", "[x, y, z]")?.map(p),
        },
        EntityType::PointIn2d => EntityKind::PointIn2d {
            params: o.handles("params", "param", "[u, v]")?.map(p),
        },
        EntityType::PointNTrans => EntityKind::PointNTrans {
            params: o.handles("params", "param", "[x, y, z]")?.map(p),
            base: e(o.need_ref("base", "entity")?),
            translation: o.handles("translation", "param", "[x, y, z]")?.map(p),
            times: {
                o.need("times", || "an integer".into())?;
                o.value("times", i32_value)?.unwrap_or_default()
            },
        },
        EntityType::PointNRotTrans => EntityKind::PointNRotTrans {
            params: o.handles("params", "param", "[x, y, z]")?.map(p),
            base: o.array("base", Expect::Number, "[x, y, z]", number_value)?,
            translation: o.handles("translation", "param", "[x, y, z]")?.map(p),
            rotation: e(o.need_ref("rotation", "entity")?),
        },
        EntityType::NormalNRot => EntityKind::NormalNRot {
            params: o.handles("params", "param", "[w, x, y, z]")?.map(p),
            base: o.array("base", Expect::Number, "[w, x, y, z]", number_value)?,
            rotation: e(o.need_ref("rotation", "entity")?),
        },
        EntityType::NormalIn3d => EntityKind::NormalIn3d {
            params: o.handles("params", "param", "[w, x, y, z]")?.map(p),
        },
        EntityType::NormalIn2d => EntityKind::NormalIn2d,
        EntityType::Distance => EntityKind::Distance {
            param: p(o.need_ref("param", "param")?),
        },
        EntityType::Workplane => EntityKind::Workplane {
            origin: e(o.need_ref("origin", "entity")?),
            normal: e(o.need_ref("normal", "entity")?),
        },
        EntityType::LineSegment => EntityKind::LineSegment {
            points: o.handles("points", "entity", "[start, end]")?.map(e),
        },
        EntityType::Cubic => EntityKind::Cubic {
            points: o.handles("points", "entity", "[p0, p1, p2, p3]")?.map(e),
        },
        EntityType::Circle => EntityKind::Circle {
            center: e(o.need_ref("center", "entity")?),
            normal: e(o.need_ref("normal", "entity")?),
            radius: e(o.need_ref("radius", "entity")?),
        },
        EntityType::ArcOfCircle => EntityKind::ArcOfCircle {
            normal: e(o.need_ref("normal", "entity")?),
            center: e(o.need_ref("center", "entity")?),
            start: e(o.need_ref("start", "entity")?),
            end: e(o.need_ref("end", "entity")?),
        },
    };
    o.finish(&[&ENTITY_COMMON, entity_fields(t)], || {
        let kind = format!("{} {t} entity", article(t.name()));
        let elsewhere = ENTITY_TYPES
            .iter()
            .flat_map(|t| entity_fields(*t).iter().copied())
            .collect();
        (kind, elsewhere)
    })?;

    Ok((
        Entity {
            h: EntityId(h),
            group: GroupId(group),
            workplane,
            kind,
        },
        h,
    ))
}

fn constraint(o: &mut Obj<'_>) -> Result<(Constraint, u32), JsonError> {
    let h = o.own_handle("constraint")?;
    o.name = crate::ConstraintId(h).to_string();
    let names = || ConstraintKind::ALL.iter().map(|k| k.name()).collect();
    let kind = type_name(o, "constraint", names, ConstraintKind::from_name)?;
    o.name = format!("{} ({kind})", crate::ConstraintId(h));
    let group = o.need_group()?;
    let mut c = Constraint::new(h, group, kind);
    c.workplane = o.handle("workplane", "entity")?.map(EntityId);
    c.val = o.value("val", number_value)?.unwrap_or_default();
    c.pt_a = o.handle("pt_a", "entity")?.map(EntityId);
    c.pt_b = o.handle("pt_b", "entity")?.map(EntityId);
    c.entity_a = o.handle("entity_a", "entity")?.map(EntityId);
    c.entity_b = o.handle("entity_b", "entity")?.map(EntityId);
    c.entity_c = o.handle("entity_c", "entity")?.map(EntityId);
    c.entity_d = o.handle("entity_d", "entity")?.map(EntityId);
    c.other = o.value("other", bool_value)?.unwrap_or_default();
    c.other2 = o.value("other2", bool_value)?.unwrap_or_default();
    c.reference = o.value("reference", bool_value)?.unwrap_or_default();
    c.signed = o.value("signed", bool_value)?.unwrap_or_default();
    o.finish(&[&CONSTRAINT_FIELDS], || {
        ("a constraint".into(), Vec::new())
    })?;
    Ok((c, h))
}

fn solve_request(text: &str, raw: &RawValue) -> Result<SolveRequest, JsonError> {
    let mut o = Obj::new(text, raw, "solve".into())?;
    let group = GroupId(o.need_group()?);
    let dragged = match o.get("dragged") {
        None => Vec::new(),
        Some(r) if !r.get().starts_with('[') => {
            return Err(o.err(
                Some(r),
                "dragged",
                format!(
                    "field \"dragged\": expected an array of param handles, found {}",
                    found(r.get())
                ),
            ))
        }
        Some(r) => {
            let mut v = Vec::new();
            for (i, item) in items(r).into_iter().enumerate() {
                let h = handle_value(item.get(), "param").map_err(|m| {
                    o.err(Some(item), "dragged", format!("field \"{{f}}[{i}]\": {m}"))
                })?;
                v.push(ParamId(h));
            }
            v
        }
    };
    let calculate_failed = o.value("calculate_failed", bool_value)?.unwrap_or(true);
    let options = match o.get("options") {
        None => Options::default(),
        Some(r) => {
            let mut p = Obj::new(text, r, "solve".into()).map_err(|mut e| {
                e.field = "options".into();
                e.message = format!("field \"options\": {}", e.message);
                e
            })?;
            p.prefix = "options.";
            let options = Options {
                tolerance: p.value("tolerance", number_value)?,
                max_iterations: p.value("max_iterations", count_value)?,
                dragged_scale: p.value("dragged_scale", number_value)?,
                rank_tolerance: p.value("rank_tolerance", number_value)?,
                verify_conflicts_up_to: p.value("verify_conflicts_up_to", count_value)?,
                nearest: p.value("nearest", bool_value)?,
                solvespace_angles: p.value("solvespace_angles", bool_value)?,
            };
            p.finish(&[&OPTION_FIELDS], || ("\"options\"".into(), Vec::new()))?;
            options
        }
    };
    o.finish(&[&SOLVE_FIELDS], || ("\"solve\"".into(), Vec::new()))?;
    Ok(SolveRequest {
        group,
        dragged,
        calculate_failed,
        options,
    })
}

/// A JSON syntax error, with its place and without serde's position suffix.
fn syntax(text: &str, e: &serde_json::Error) -> JsonError {
    let full = e.to_string();
    let what = match full.rfind(" at line ") {
        Some(i) => &full[..i],
        None => &full,
    };
    if text.trim().is_empty() {
        return JsonError::new(
            None,
            "",
            "",
            "the file is empty; expected a JSON object with \"params\", \"entities\" and \
             \"constraints\"",
        );
    }
    let message = if e.is_eof() {
        match what.strip_prefix("EOF while parsing ") {
            Some("a value") => {
                "the file ends where a value should be (is it cut short?)".to_string()
            }
            Some(thing) => format!("the file ends inside {thing} (is it cut short?)"),
            None => format!("{what} (is the file cut short?)"),
        }
    } else {
        format!("invalid JSON: {what}")
    };
    JsonError::new(
        Some(Position {
            line: e.line().max(1),
            column: e.column().max(1),
        }),
        "",
        "",
        message,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value;

    const SCHEMA: &str = include_str!("../../../../../docs/loci.schema.json");

    fn keys(v: &Value) -> Vec<String> {
        let mut k: Vec<String> = v.as_object().unwrap().keys().cloned().collect();
        k.sort();
        k
    }

    fn sorted(v: &[&str]) -> Vec<String> {
        let mut k: Vec<String> = v.iter().map(|s| (*s).to_string()).collect();
        k.sort();
        k
    }

    #[test]
    fn the_field_tables_are_the_schema_s() {
        let schema: Value = serde_json::from_str(SCHEMA).unwrap();
        let defs = &schema["$defs"];
        let variants = defs["entity"]["oneOf"].as_array().unwrap();
        assert_eq!(variants.len(), ENTITY_TYPES.len());
        for t in ENTITY_TYPES {
            let v = variants
                .iter()
                .find(|v| v["title"] == t.name())
                .unwrap_or_else(|| panic!("{t} is not in the schema"));
            let mut mine: Vec<&str> = ENTITY_COMMON.to_vec();
            mine.extend(entity_fields(t));
            assert_eq!(keys(&v["properties"]), sorted(&mine), "{t}");
        }
        assert_eq!(
            keys(&defs["constraint"]["properties"]),
            sorted(&CONSTRAINT_FIELDS)
        );
        assert_eq!(keys(&defs["param"]["properties"]), sorted(&PARAM_FIELDS));
        assert_eq!(keys(&schema["properties"]), sorted(&TOP_FIELDS));
        assert_eq!(keys(&defs["solve"]["properties"]), sorted(&SOLVE_FIELDS));
        assert_eq!(
            keys(&defs["solve"]["properties"]["options"]["properties"]),
            sorted(&OPTION_FIELDS)
        );
    }

    #[test]
    fn the_field_tables_are_what_the_model_writes() {
        // A constraint with every field set writes every field the reader accepts.
        let mut c = Constraint::new(1, 2, ConstraintKind::Angle)
            .in_workplane(Some(3))
            .with_val(4.0)
            .with_points(5, 6)
            .with_entities([7, 8, 9, 10]);
        c.other = true;
        c.other2 = true;
        c.reference = true;
        c.signed = true;
        let v = serde_json::to_value(&c).unwrap();
        assert_eq!(keys(&v), sorted(&CONSTRAINT_FIELDS));
        let v = serde_json::to_value(Param::new(1, 2, 3.0)).unwrap();
        assert_eq!(keys(&v), sorted(&PARAM_FIELDS));
        let samples = [
            Entity::point_3d(1, 1, [1, 2, 3]),
            Entity::point_2d(1, 1, 9, [1, 2]),
            Entity::point_n_trans(1, 1, [1, 2, 3], 4, [5, 6, 7], 2),
            Entity::point_n_rot_trans(1, 1, [1, 2, 3], [0.0; 3], [5, 6, 7], 8),
            Entity::normal_n_rot(1, 1, [1, 2, 3, 4], [1.0, 0.0, 0.0, 0.0], 8),
            Entity::normal_3d(1, 1, [1, 2, 3, 4]),
            Entity::normal_2d(1, 1, 9),
            Entity::distance(1, 1, Some(9), 1),
            Entity::workplane(1, 1, 2, 3),
            Entity::line(1, 1, Some(9), 2, 3),
            Entity::cubic(1, 1, Some(9), [2, 3, 4, 5]),
            Entity::circle(1, 1, Some(9), 2, 3, 4),
            Entity::arc(1, 1, 9, 2, 3, 4, 5),
        ];
        for (t, e) in ENTITY_TYPES.iter().zip(samples) {
            assert_eq!(e.entity_type(), *t);
            let mut e = e;
            e.workplane = Some(EntityId(9));
            let v = serde_json::to_value(&e).unwrap();
            let mut mine: Vec<&str> = ENTITY_COMMON.to_vec();
            mine.extend(entity_fields(*t));
            assert_eq!(keys(&v), sorted(&mine), "{t}");
        }
    }

    #[test]
    fn positions_count_lines_and_characters() {
        let text = "{\n  \"é\": [1,\n   2]}";
        let at = |needle: &str| Position::at(text, text.find(needle).unwrap());
        assert_eq!(at("{"), Position { line: 1, column: 1 });
        assert_eq!(at("[1"), Position { line: 2, column: 8 });
        assert_eq!(at("2]"), Position { line: 3, column: 4 });
    }

    #[test]
    fn suggestions_catch_slips_only() {
        let names = ["pt_a", "pt_b", "entity_a", "horizontal", "vertical"];
        assert_eq!(suggest("ptb", names), Some("pt_b"));
        assert_eq!(suggest("Horizontal", names), Some("horizontal"));
        assert_eq!(suggest("entitya", names), Some("entity_a"));
        assert_eq!(suggest("colour", names), None);
    }
}
