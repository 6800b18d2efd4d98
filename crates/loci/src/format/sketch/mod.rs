//! Sketch files: a [`Sketch`](crate::sketch::Sketch) as JSON, naming shapes and constraints the way its API does.
//!
//! ```json
//! { "sketch": {
//!     "points": [ { "name": "a", "x": 0, "y": 0 }, { "name": "b", "x": 9, "y": 1 } ],
//!     "lines": [ { "name": "base", "a": "a", "b": "b" } ],
//!     "constraints": [
//!       { "type": "fix", "point": "a" },
//!       { "type": "horizontal", "line": "base" },
//!       { "type": "length", "line": "base", "value": 10 } ] } }
//! ```
//!
//! Shapes of every kind share one name space. A constraint is a [`Spec`] naming shapes by
//! name, with an optional `name` of its own and `"reference": true` for a driven dimension.
//! The format is described in `docs/sketch-format.md`, with a JSON Schema beside it.

mod read;
mod write;

pub use read::{LoadedSketch, SketchFileError};

use crate::sketch::Spec;
use serde::{Deserialize, Serialize};

/// The top level of a sketch file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SketchFile {
    /// The sketch.
    pub sketch: SketchData,
}

/// Shapes and constraints, by name.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SketchData {
    /// Points.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub points: Vec<PointData>,
    /// Line segments.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub lines: Vec<LineData>,
    /// Circles.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub circles: Vec<CircleData>,
    /// Arcs, counter-clockwise from start to end.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub arcs: Vec<ArcData>,
    /// Cubic Béziers.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub cubics: Vec<CubicData>,
    /// User constraints.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub constraints: Vec<ConstraintData>,
}

fn is_false(b: &bool) -> bool {
    !*b
}

/// A point.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointData {
    /// Its name.
    pub name: String,
    /// x.
    pub x: f64,
    /// y.
    pub y: f64,
    /// Construction geometry.
    #[serde(default, skip_serializing_if = "is_false")]
    pub construction: bool,
}

/// A line segment from point `a` to point `b`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineData {
    /// Its name.
    pub name: String,
    /// The start point's name.
    pub a: String,
    /// The end point's name.
    pub b: String,
    /// Construction geometry.
    #[serde(default, skip_serializing_if = "is_false")]
    pub construction: bool,
}

/// A circle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CircleData {
    /// Its name.
    pub name: String,
    /// The centre point's name.
    pub center: String,
    /// The radius (the starting value when a constraint sets it).
    pub radius: f64,
    /// Construction geometry.
    #[serde(default, skip_serializing_if = "is_false")]
    pub construction: bool,
}

/// An arc.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArcData {
    /// Its name.
    pub name: String,
    /// The centre point's name.
    pub center: String,
    /// The start point's name.
    pub start: String,
    /// The end point's name.
    pub end: String,
    /// Construction geometry.
    #[serde(default, skip_serializing_if = "is_false")]
    pub construction: bool,
}

/// A cubic Bézier.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CubicData {
    /// Its name.
    pub name: String,
    /// The four control points' names.
    pub points: [String; 4],
    /// Construction geometry.
    #[serde(default, skip_serializing_if = "is_false")]
    pub construction: bool,
}

/// A user constraint naming shapes by name.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ConstraintData {
    /// An optional name, to refer to it in reports.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// What it says.
    #[serde(flatten)]
    pub spec: Spec<String>,
    /// A reference (driven) dimension.
    #[serde(default, skip_serializing_if = "is_false")]
    pub reference: bool,
}

/// Whether JSON text is a sketch file (an object with a top-level `"sketch"` key) rather than
/// a core problem.
#[must_use]
pub fn is_sketch_json(text: &str) -> bool {
    #[derive(Deserialize)]
    struct Probe {
        sketch: Option<serde::de::IgnoredAny>,
    }
    serde_json::from_str::<Probe>(text).is_ok_and(|p| p.sketch.is_some())
}
