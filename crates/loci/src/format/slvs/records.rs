//! The `.slvs` text layer: `Key=value` lines gathered into records, each closed by an
//! `Add<Kind>` line, every value checked against the format SolveSpace writes for its key.
//!
//! A SolveSpace file is a magic line, then groups, params, requests, entities, constraints
//! and styles as records, then (for a file other files link to) the solid as `Triangle`,
//! `Surface`, `Curve` ... lines, which loci skips. Zero values are omitted by the writer, so
//! a missing key means 0.

use super::SlvsError;

/// The magic first line SolveSpace writes (three high bytes, then the version tag).
pub(crate) const MAGIC: &[u8] = b"\xb1\xb2\xb3SolveSpaceREVa";

/// The kinds of record, named by the line that closes them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    Group,
    Param,
    Request,
    Entity,
    Constraint,
    Style,
}

impl Kind {
    pub(crate) fn name(self) -> &'static str {
        match self {
            Kind::Group => "Group",
            Kind::Param => "Param",
            Kind::Request => "Request",
            Kind::Entity => "Entity",
            Kind::Constraint => "Constraint",
            Kind::Style => "Style",
        }
    }

    fn from_add_line(line: &str) -> Option<Kind> {
        Some(match line {
            "AddGroup" => Kind::Group,
            "AddParam" => Kind::Param,
            "AddRequest" => Kind::Request,
            "AddEntity" => Kind::Entity,
            "AddConstraint" => Kind::Constraint,
            "AddStyle" => Kind::Style,
            _ => return None,
        })
    }
}

/// How a value is written, as in SolveSpace's save table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Fmt {
    /// `%08x`: a handle.
    Hex,
    /// `%d`.
    Int,
    /// `%.20f`.
    Float,
    /// `0` or `1`.
    Bool,
    /// `%08x`: a packed colour.
    Color,
    /// Free text (names, comments, fonts, paths).
    Text,
    /// `{` then `    <index> <hex handle> <copy number>` lines, then `}`.
    Remap,
}

/// Every key SolveSpace writes, with its record and format.
const KEYS: &[(&str, Kind, Fmt)] = &[
    ("Group.h.v", Kind::Group, Fmt::Hex),
    ("Group.type", Kind::Group, Fmt::Int),
    ("Group.order", Kind::Group, Fmt::Int),
    ("Group.name", Kind::Group, Fmt::Text),
    ("Group.activeWorkplane.v", Kind::Group, Fmt::Hex),
    ("Group.opA.v", Kind::Group, Fmt::Hex),
    ("Group.opB.v", Kind::Group, Fmt::Hex),
    ("Group.valA", Kind::Group, Fmt::Float),
    ("Group.valB", Kind::Group, Fmt::Float),
    ("Group.valC", Kind::Group, Fmt::Float),
    ("Group.color", Kind::Group, Fmt::Color),
    ("Group.subtype", Kind::Group, Fmt::Int),
    ("Group.skipFirst", Kind::Group, Fmt::Bool),
    ("Group.meshCombine", Kind::Group, Fmt::Int),
    ("Group.forceToMesh", Kind::Group, Fmt::Int),
    ("Group.predef.q.w", Kind::Group, Fmt::Float),
    ("Group.predef.q.vx", Kind::Group, Fmt::Float),
    ("Group.predef.q.vy", Kind::Group, Fmt::Float),
    ("Group.predef.q.vz", Kind::Group, Fmt::Float),
    ("Group.predef.origin.v", Kind::Group, Fmt::Hex),
    ("Group.predef.entityB.v", Kind::Group, Fmt::Hex),
    ("Group.predef.entityC.v", Kind::Group, Fmt::Hex),
    ("Group.predef.swapUV", Kind::Group, Fmt::Bool),
    ("Group.predef.negateU", Kind::Group, Fmt::Bool),
    ("Group.predef.negateV", Kind::Group, Fmt::Bool),
    ("Group.visible", Kind::Group, Fmt::Bool),
    ("Group.suppress", Kind::Group, Fmt::Bool),
    ("Group.relaxConstraints", Kind::Group, Fmt::Bool),
    ("Group.allowRedundant", Kind::Group, Fmt::Bool),
    ("Group.allDimsReference", Kind::Group, Fmt::Bool),
    ("Group.scale", Kind::Group, Fmt::Float),
    ("Group.remap", Kind::Group, Fmt::Remap),
    ("Group.impFile", Kind::Group, Fmt::Text),
    ("Group.impFileRel", Kind::Group, Fmt::Text),
    ("Param.h.v.", Kind::Param, Fmt::Hex),
    ("Param.val", Kind::Param, Fmt::Float),
    ("Request.h.v", Kind::Request, Fmt::Hex),
    ("Request.type", Kind::Request, Fmt::Int),
    ("Request.extraPoints", Kind::Request, Fmt::Int),
    ("Request.workplane.v", Kind::Request, Fmt::Hex),
    ("Request.group.v", Kind::Request, Fmt::Hex),
    ("Request.construction", Kind::Request, Fmt::Bool),
    ("Request.style", Kind::Request, Fmt::Hex),
    ("Request.str", Kind::Request, Fmt::Text),
    ("Request.font", Kind::Request, Fmt::Text),
    ("Request.file", Kind::Request, Fmt::Text),
    ("Request.aspectRatio", Kind::Request, Fmt::Float),
    ("Entity.h.v", Kind::Entity, Fmt::Hex),
    ("Entity.type", Kind::Entity, Fmt::Int),
    ("Entity.construction", Kind::Entity, Fmt::Bool),
    ("Entity.style", Kind::Entity, Fmt::Hex),
    ("Entity.str", Kind::Entity, Fmt::Text),
    ("Entity.font", Kind::Entity, Fmt::Text),
    ("Entity.file", Kind::Entity, Fmt::Text),
    ("Entity.point[0].v", Kind::Entity, Fmt::Hex),
    ("Entity.point[1].v", Kind::Entity, Fmt::Hex),
    ("Entity.point[2].v", Kind::Entity, Fmt::Hex),
    ("Entity.point[3].v", Kind::Entity, Fmt::Hex),
    ("Entity.point[4].v", Kind::Entity, Fmt::Hex),
    ("Entity.point[5].v", Kind::Entity, Fmt::Hex),
    ("Entity.point[6].v", Kind::Entity, Fmt::Hex),
    ("Entity.point[7].v", Kind::Entity, Fmt::Hex),
    ("Entity.point[8].v", Kind::Entity, Fmt::Hex),
    ("Entity.point[9].v", Kind::Entity, Fmt::Hex),
    ("Entity.point[10].v", Kind::Entity, Fmt::Hex),
    ("Entity.point[11].v", Kind::Entity, Fmt::Hex),
    ("Entity.extraPoints", Kind::Entity, Fmt::Int),
    ("Entity.normal.v", Kind::Entity, Fmt::Hex),
    ("Entity.distance.v", Kind::Entity, Fmt::Hex),
    ("Entity.workplane.v", Kind::Entity, Fmt::Hex),
    ("Entity.actPoint.x", Kind::Entity, Fmt::Float),
    ("Entity.actPoint.y", Kind::Entity, Fmt::Float),
    ("Entity.actPoint.z", Kind::Entity, Fmt::Float),
    ("Entity.actNormal.w", Kind::Entity, Fmt::Float),
    ("Entity.actNormal.vx", Kind::Entity, Fmt::Float),
    ("Entity.actNormal.vy", Kind::Entity, Fmt::Float),
    ("Entity.actNormal.vz", Kind::Entity, Fmt::Float),
    ("Entity.actDistance", Kind::Entity, Fmt::Float),
    ("Entity.actVisible", Kind::Entity, Fmt::Bool),
    ("Constraint.h.v", Kind::Constraint, Fmt::Hex),
    ("Constraint.type", Kind::Constraint, Fmt::Int),
    ("Constraint.group.v", Kind::Constraint, Fmt::Hex),
    ("Constraint.workplane.v", Kind::Constraint, Fmt::Hex),
    ("Constraint.valA", Kind::Constraint, Fmt::Float),
    ("Constraint.valP.v", Kind::Constraint, Fmt::Hex),
    ("Constraint.ptA.v", Kind::Constraint, Fmt::Hex),
    ("Constraint.ptB.v", Kind::Constraint, Fmt::Hex),
    ("Constraint.entityA.v", Kind::Constraint, Fmt::Hex),
    ("Constraint.entityB.v", Kind::Constraint, Fmt::Hex),
    ("Constraint.entityC.v", Kind::Constraint, Fmt::Hex),
    ("Constraint.entityD.v", Kind::Constraint, Fmt::Hex),
    ("Constraint.other", Kind::Constraint, Fmt::Bool),
    ("Constraint.other2", Kind::Constraint, Fmt::Bool),
    ("Constraint.reference", Kind::Constraint, Fmt::Bool),
    ("Constraint.comment", Kind::Constraint, Fmt::Text),
    ("Constraint.disp.offset.x", Kind::Constraint, Fmt::Float),
    ("Constraint.disp.offset.y", Kind::Constraint, Fmt::Float),
    ("Constraint.disp.offset.z", Kind::Constraint, Fmt::Float),
    ("Constraint.disp.style", Kind::Constraint, Fmt::Hex),
    ("Style.h.v", Kind::Style, Fmt::Hex),
    ("Style.name", Kind::Style, Fmt::Text),
    ("Style.width", Kind::Style, Fmt::Float),
    ("Style.widthAs", Kind::Style, Fmt::Int),
    ("Style.textHeight", Kind::Style, Fmt::Float),
    ("Style.textHeightAs", Kind::Style, Fmt::Int),
    ("Style.textAngle", Kind::Style, Fmt::Float),
    ("Style.textOrigin", Kind::Style, Fmt::Hex),
    ("Style.color", Kind::Style, Fmt::Color),
    ("Style.fillColor", Kind::Style, Fmt::Color),
    ("Style.filled", Kind::Style, Fmt::Bool),
    ("Style.visible", Kind::Style, Fmt::Bool),
    ("Style.exportable", Kind::Style, Fmt::Bool),
    ("Style.stippleType", Kind::Style, Fmt::Int),
    ("Style.stippleScale", Kind::Style, Fmt::Float),
];

/// Lines of a linked file's solid (mesh and shell), which SolveSpace regenerates.
const SOLID_PREFIXES: &[&str] = &[
    "Triangle ",
    "Surface ",
    "SCtrl ",
    "TrimBy ",
    "Curve ",
    "CCtrl ",
    "CurvePt ",
];

/// A parsed value.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Value {
    Hex(u32),
    Int(i64),
    Float(f64),
    Bool(bool),
    Text(String),
    /// `(index, source entity, copy number)` triples.
    Remap(Vec<(u32, u32, u32)>),
}

/// One `Key=value` line.
#[derive(Clone, Debug)]
pub(crate) struct Field {
    pub key: &'static str,
    pub value: Value,
    /// 1-based line number.
    pub line: usize,
}

/// The fields of one object, closed by its `Add<Kind>` line.
#[derive(Clone, Debug)]
pub(crate) struct Record {
    pub kind: Kind,
    /// Line of the first field (or of the `Add` line for an empty record).
    pub line: usize,
    pub fields: Vec<Field>,
}

impl Record {
    fn get(&self, key: &str) -> Option<&Field> {
        self.fields.iter().find(|f| f.key == key)
    }

    /// A handle field; 0 when absent (SolveSpace omits zeros).
    pub fn hex(&self, key: &str) -> u32 {
        match self.get(key).map(|f| &f.value) {
            Some(Value::Hex(v)) => *v,
            _ => 0,
        }
    }

    /// An integer field; 0 when absent.
    pub fn int(&self, key: &str) -> i64 {
        match self.get(key).map(|f| &f.value) {
            Some(Value::Int(v)) => *v,
            _ => 0,
        }
    }

    /// A number field; 0 when absent.
    pub fn float(&self, key: &str) -> f64 {
        match self.get(key).map(|f| &f.value) {
            Some(Value::Float(v)) => *v,
            _ => 0.0,
        }
    }

    /// A flag; false when absent.
    pub fn remap(&self, key: &str) -> &[(u32, u32, u32)] {
        match self.get(key).map(|f| &f.value) {
            Some(Value::Remap(v)) => v,
            _ => &[],
        }
    }

    pub fn flag(&self, key: &str) -> bool {
        matches!(self.get(key).map(|f| &f.value), Some(Value::Bool(true)))
    }

    /// A text field; empty when absent.
    pub fn text(&self, key: &str) -> &str {
        match self.get(key).map(|f| &f.value) {
            Some(Value::Text(v)) => v,
            _ => "",
        }
    }

    /// The line of field `key`, or of the record when it is absent.
    pub fn line_of(&self, key: &str) -> usize {
        self.get(key).map_or(self.line, |f| f.line)
    }
}

/// Where each line of the original bytes starts and ends (without its `\n`).
pub(crate) fn line_spans(bytes: &[u8]) -> Vec<(usize, usize)> {
    let mut spans = Vec::new();
    let mut start = 0;
    for (i, &b) in bytes.iter().enumerate() {
        if b == b'\n' {
            spans.push((start, i));
            start = i + 1;
        }
    }
    if start < bytes.len() {
        spans.push((start, bytes.len()));
    }
    spans
}

/// What the text layer found: the records and how many solid lines it skipped.
pub(crate) struct Parsed {
    pub records: Vec<Record>,
    pub solid_lines: usize,
}

/// Splits a file into records, checking every key and value.
pub(crate) fn parse(bytes: &[u8], spans: &[(usize, usize)]) -> Result<Parsed, SlvsError> {
    let mut records = Vec::new();
    let mut fields: Vec<Field> = Vec::new();
    let mut solid_lines = 0;
    let mut i = 0;
    while i < spans.len() {
        let line_no = i + 1;
        let raw = strip_cr(&bytes[spans[i].0..spans[i].1]);
        i += 1;
        if raw.is_empty() || raw == MAGIC {
            continue;
        }
        let text = std::str::from_utf8(raw).map_err(|_| SlvsError::NotText { line: line_no })?;
        if let Some((key, val)) = text.split_once('=') {
            let Some(&(key, kind, fmt)) = KEYS.iter().find(|(k, _, _)| *k == key) else {
                return Err(SlvsError::UnknownKey {
                    line: line_no,
                    key: key.to_string(),
                    owner: owner_of(&fields),
                });
            };
            if let Some(first) = fields.first() {
                let open = record_kind(first.key);
                if open != kind {
                    return Err(SlvsError::MixedRecord {
                        line: line_no,
                        key: key.to_string(),
                        open: open.name(),
                        owner: owner_of(&fields),
                    });
                }
            }
            let value = if fmt == Fmt::Remap {
                let (v, next) = remap_block(bytes, spans, i, line_no, val)
                    .map_err(|e| with_owner(e, &fields))?;
                i = next;
                Value::Remap(v)
            } else {
                value(fmt, key, val, line_no).map_err(|e| with_owner(e, &fields))?
            };
            fields.push(Field {
                key,
                value,
                line: line_no,
            });
        } else if let Some(kind) = Kind::from_add_line(text) {
            if let Some(first) = fields.first() {
                let open = record_kind(first.key);
                if open != kind {
                    return Err(SlvsError::MixedRecord {
                        line: line_no,
                        key: text.to_string(),
                        open: open.name(),
                        owner: owner_of(&fields),
                    });
                }
            }
            let line = fields.first().map_or(line_no, |f| f.line);
            records.push(Record {
                kind,
                line,
                fields: std::mem::take(&mut fields),
            });
        } else if SOLID_PREFIXES.iter().any(|p| text.starts_with(p))
            || text == "AddSurface"
            || text == "AddCurve"
        {
            solid_lines += 1;
        } else {
            return Err(SlvsError::UnrecognizedLine {
                line: line_no,
                text: text.chars().take(60).collect(),
            });
        }
    }
    if let Some(first) = fields.first() {
        let kind = record_kind(first.key).name();
        let owner = owner_of(&fields);
        let record = if owner.is_empty() {
            format!("the {kind} record")
        } else {
            format!("the {kind} record {owner}")
        };
        return Err(SlvsError::Truncated {
            line: first.line,
            what: format!("{record} starting here has no Add{kind} line"),
        });
    }
    Ok(Parsed {
        records,
        solid_lines,
    })
}

/// The record being read, as the file names it (`Entity.h.v=00040001`), or empty before its
/// handle.
fn owner_of(fields: &[Field]) -> String {
    fields
        .iter()
        .find_map(|f| match (&f.value, f.key.split_once(".h.v")) {
            (Value::Hex(h), Some((record, _))) => Some(super::file_name(record, *h)),
            _ => None,
        })
        .unwrap_or_default()
}

/// `e`, naming the record being read when it is a bad value.
fn with_owner(mut e: SlvsError, fields: &[Field]) -> SlvsError {
    if let SlvsError::BadValue { owner, .. } = &mut e {
        *owner = owner_of(fields);
    }
    e
}

fn strip_cr(raw: &[u8]) -> &[u8] {
    // Mailers sometimes turn line ends into CR LF; SolveSpace ignores the CR too.
    raw.strip_suffix(b"\r").unwrap_or(raw)
}

fn record_kind(key: &str) -> Kind {
    KEYS.iter()
        .find(|(k, _, _)| *k == key)
        .map_or(Kind::Group, |(_, kind, _)| *kind)
}

fn value(fmt: Fmt, key: &str, val: &str, line: usize) -> Result<Value, SlvsError> {
    let bad = |expected: &'static str| SlvsError::BadValue {
        line,
        key: key.to_string(),
        value: val.chars().take(40).collect(),
        expected,
        owner: String::new(),
    };
    Ok(match fmt {
        Fmt::Hex | Fmt::Color => {
            if val.is_empty() || val.len() > 8 || !val.bytes().all(|b| b.is_ascii_hexdigit()) {
                return Err(bad("a hexadecimal number of at most 8 digits"));
            }
            Value::Hex(u32::from_str_radix(val, 16).map_err(|_| bad("a hexadecimal number"))?)
        }
        Fmt::Int => Value::Int(val.trim().parse().map_err(|_| bad("an integer"))?),
        Fmt::Bool => match val.trim() {
            "0" => Value::Bool(false),
            "1" => Value::Bool(true),
            _ => return Err(bad("0 or 1")),
        },
        Fmt::Float => {
            let v: f64 = val.trim().parse().map_err(|_| bad("a number"))?;
            if !v.is_finite() {
                return Err(bad("a finite number"));
            }
            Value::Float(v)
        }
        Fmt::Text => Value::Text(val.to_string()),
        Fmt::Remap => unreachable!("remap blocks are read by remap_block"),
    })
}

/// A remap block's entries: `(index, source entity, copy number)`.
type Remap = Vec<(u32, u32, u32)>;

/// Reads a `{ ... }` remap block whose first line is `line`; returns the entries and the
/// index of the first line after the block.
fn remap_block(
    bytes: &[u8],
    spans: &[(usize, usize)],
    mut i: usize,
    line: usize,
    first: &str,
) -> Result<(Remap, usize), SlvsError> {
    if first.trim() != "{" {
        return Err(SlvsError::BadValue {
            line,
            key: "Group.remap".into(),
            value: first.chars().take(40).collect(),
            expected: "`{` followed by remap lines and `}`",
            owner: String::new(),
        });
    }
    let mut out = Vec::new();
    while i < spans.len() {
        let line_no = i + 1;
        let raw = strip_cr(&bytes[spans[i].0..spans[i].1]);
        i += 1;
        let text = std::str::from_utf8(raw).map_err(|_| SlvsError::NotText { line: line_no })?;
        let t = text.trim();
        if t == "}" {
            return Ok((out, i));
        }
        let parts: Vec<&str> = t.split_whitespace().collect();
        let parsed = match parts.as_slice() {
            [a, b, c] => match (
                a.parse::<u32>(),
                u32::from_str_radix(b, 16),
                c.parse::<u32>(),
            ) {
                (Ok(a), Ok(b), Ok(c)) => Some((a, b, c)),
                _ => None,
            },
            _ => None,
        };
        match parsed {
            Some(e) => out.push(e),
            None => {
                return Err(SlvsError::BadValue {
                    line: line_no,
                    key: "Group.remap".into(),
                    value: t.chars().take(40).collect(),
                    expected: "`<index> <hex entity> <copy number>` or `}`",
                    owner: String::new(),
                })
            }
        }
    }
    Err(SlvsError::Truncated {
        line,
        what: "the remap block starting here has no closing `}`".into(),
    })
}
