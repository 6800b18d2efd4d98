//! Typed handles of a sketch: each shape kind has its own, so that a call asking for a line
//! cannot be given a circle.

use crate::model::EntityId;
use serde::{Deserialize, Serialize};
use std::fmt;

macro_rules! shape_id {
    ($(#[$doc:meta])* $name:ident, $label:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Debug, Serialize, Deserialize)]
        #[serde(transparent)]
        pub struct $name(pub(crate) EntityId);

        impl $name {
            /// The entity of the sketch's [`System`](crate::System) this shape is.
            #[must_use]
            pub fn entity(self) -> EntityId {
                self.0
            }
        }

        impl From<$name> for ShapeId {
            fn from(v: $name) -> ShapeId {
                ShapeId(v.0)
            }
        }

        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, "{} {}", $label, self.0 .0)
            }
        }
    };
}

/// Any shape of a sketch: a point, line, circle, arc or cubic.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Debug, Serialize, Deserialize)]
#[serde(transparent)]
pub struct ShapeId(pub(crate) EntityId);

impl ShapeId {
    /// The entity of the sketch's [`System`](crate::System) this shape is.
    #[must_use]
    pub fn entity(self) -> EntityId {
        self.0
    }
}

impl fmt::Display for ShapeId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "shape {}", self.0 .0)
    }
}

shape_id!(
    /// A point of a sketch.
    PointId,
    "point"
);
shape_id!(
    /// A line segment of a sketch.
    LineId,
    "line"
);
shape_id!(
    /// A full circle of a sketch.
    CircleId,
    "circle"
);
shape_id!(
    /// An arc of circle of a sketch, counter-clockwise from its start to its end.
    ArcId,
    "arc"
);
shape_id!(
    /// A cubic Bézier segment of a sketch.
    CubicId,
    "cubic"
);

/// A user constraint of a sketch; one may write several core constraints.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Debug, Serialize, Deserialize)]
#[serde(transparent)]
pub struct SketchConstraintId(pub u32);

impl fmt::Display for SketchConstraintId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "sketch constraint {}", self.0)
    }
}

/// The kind of a shape.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ShapeKind {
    /// A point.
    Point,
    /// A line segment.
    Line,
    /// A circle.
    Circle,
    /// An arc of circle.
    Arc,
    /// A cubic Bézier.
    Cubic,
}

impl ShapeKind {
    /// The word for messages.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            ShapeKind::Point => "point",
            ShapeKind::Line => "line",
            ShapeKind::Circle => "circle",
            ShapeKind::Arc => "arc",
            ShapeKind::Cubic => "cubic",
        }
    }
}

impl fmt::Display for ShapeKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Which end of a line, arc or cubic.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum End {
    /// The start (first point).
    #[default]
    Start,
    /// The end (last point).
    End,
}

/// An axis of the sketch's plane.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Axis {
    /// The horizontal (x) axis.
    Horizontal,
    /// The vertical (y) axis.
    Vertical,
}
