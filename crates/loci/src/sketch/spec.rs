//! The user constraints of a sketch, as data: the same enum names shapes by handle in the API
//! (`Spec<ShapeId>`) and by name in sketch files (`Spec<String>`).

use super::{Axis, End};
use serde::{Deserialize, Serialize};

/// A user constraint: what it says and which shapes it says it of. `R` names a shape.
///
/// Distances are in model units, angles in degrees. Signed angles are counter-clockwise
/// positive, from the first line's direction (start to end) to the second's.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Spec<R> {
    /// The point stays where it is.
    Fix {
        /// A point.
        point: R,
    },
    /// Every point of the shape stays where it is (and a circle keeps its radius).
    FixShape {
        /// Any shape.
        shape: R,
    },
    /// The line's length.
    Length {
        /// A line.
        line: R,
        /// The length.
        value: f64,
    },
    /// The line is horizontal.
    Horizontal {
        /// A line.
        line: R,
    },
    /// The line is vertical.
    Vertical {
        /// A line.
        line: R,
    },
    /// The radius of a circle or arc.
    Radius {
        /// A circle or arc.
        shape: R,
        /// The radius.
        value: f64,
    },
    /// The diameter of a circle or arc.
    Diameter {
        /// A circle or arc.
        shape: R,
        /// The diameter.
        value: f64,
    },
    /// The arc's sweep, counter-clockwise from start to end, in degrees (0, 360).
    ArcSweep {
        /// An arc.
        arc: R,
        /// The sweep in degrees.
        degrees: f64,
    },
    /// The shape keeps its size: a line its length, a circle its radius, an arc its radius
    /// and its start and end angles, at the values they have when the lock is made.
    Lock {
        /// A line, circle or arc.
        shape: R,
    },
    /// The distance between two points, whatever shapes they belong to.
    Distance {
        /// A point.
        a: R,
        /// Another point.
        b: R,
        /// The distance.
        value: f64,
    },
    /// Two points coincide.
    Coincident {
        /// A point.
        a: R,
        /// Another point.
        b: R,
    },
    /// Two circles or arcs share their centre.
    Concentric {
        /// A circle or arc.
        a: R,
        /// Another circle or arc.
        b: R,
    },
    /// Two lines are parallel.
    Parallel {
        /// A line.
        a: R,
        /// Another line.
        b: R,
    },
    /// Two lines are perpendicular.
    Perpendicular {
        /// A line.
        a: R,
        /// Another line.
        b: R,
    },
    /// The signed angle from line `a` to line `b`, counter-clockwise positive, in degrees.
    /// It keeps its sign: the mirror image does not satisfy it.
    Angle {
        /// A line.
        a: R,
        /// Another line.
        b: R,
        /// The angle in degrees.
        degrees: f64,
    },
    /// Two lines have the same length.
    EqualLength {
        /// A line.
        a: R,
        /// Another line.
        b: R,
    },
    /// Two circles or arcs have the same radius.
    EqualRadius {
        /// A circle or arc.
        a: R,
        /// Another circle or arc.
        b: R,
    },
    /// Two shapes are tangent: line–arc and arc–arc at the chosen ends (the curves' direction
    /// there, as in SolveSpace; make the ends coincide with [`Spec::Coincident`]),
    /// line–circle and circle–circle (or arc) anywhere, keeping the side they start on.
    Tangent {
        /// A line, circle or arc.
        a: R,
        /// A circle or arc (or a line when `a` is an arc).
        b: R,
        /// Which end of `a` when it is an arc.
        #[serde(default)]
        a_end: End,
        /// Which end of `b` when it is an arc.
        #[serde(default)]
        b_end: End,
    },
    /// The point lies on the line (extended).
    PointOnLine {
        /// A point.
        point: R,
        /// A line.
        line: R,
    },
    /// The point lies on the circle or arc (its whole circle).
    PointOnCircle {
        /// A point.
        point: R,
        /// A circle or arc.
        shape: R,
    },
    /// The point is the line's midpoint.
    Midpoint {
        /// A point.
        point: R,
        /// A line.
        line: R,
    },
    /// Two points are mirror images about a line.
    Symmetric {
        /// A point.
        a: R,
        /// Another point.
        b: R,
        /// The mirror line.
        line: R,
    },
    /// Two points are mirror images about an axis of the sketch.
    SymmetricAxis {
        /// A point.
        a: R,
        /// Another point.
        b: R,
        /// The mirror axis (through the sketch's origin).
        axis: Axis,
    },
    /// The signed distance from the point to the line: positive to the right of the line's
    /// direction (below a line going right).
    PointLineDistance {
        /// A point.
        point: R,
        /// A line.
        line: R,
        /// The distance.
        value: f64,
    },
    /// Line `b` lies on line `a` (extended).
    Collinear {
        /// A line.
        a: R,
        /// Another line.
        b: R,
    },
}

impl<R> Spec<R> {
    /// The name of this kind of constraint, as in files.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Spec::Fix { .. } => "fix",
            Spec::FixShape { .. } => "fix_shape",
            Spec::Length { .. } => "length",
            Spec::Horizontal { .. } => "horizontal",
            Spec::Vertical { .. } => "vertical",
            Spec::Radius { .. } => "radius",
            Spec::Diameter { .. } => "diameter",
            Spec::ArcSweep { .. } => "arc_sweep",
            Spec::Lock { .. } => "lock",
            Spec::Distance { .. } => "distance",
            Spec::Coincident { .. } => "coincident",
            Spec::Concentric { .. } => "concentric",
            Spec::Parallel { .. } => "parallel",
            Spec::Perpendicular { .. } => "perpendicular",
            Spec::Angle { .. } => "angle",
            Spec::EqualLength { .. } => "equal_length",
            Spec::EqualRadius { .. } => "equal_radius",
            Spec::Tangent { .. } => "tangent",
            Spec::PointOnLine { .. } => "point_on_line",
            Spec::PointOnCircle { .. } => "point_on_circle",
            Spec::Midpoint { .. } => "midpoint",
            Spec::Symmetric { .. } => "symmetric",
            Spec::SymmetricAxis { .. } => "symmetric_axis",
            Spec::PointLineDistance { .. } => "point_line_distance",
            Spec::Collinear { .. } => "collinear",
        }
    }

    /// The dimension this constraint sets, if it has one.
    #[must_use]
    pub fn value(&self) -> Option<f64> {
        match self {
            Spec::Length { value, .. }
            | Spec::Radius { value, .. }
            | Spec::Diameter { value, .. }
            | Spec::Distance { value, .. }
            | Spec::PointLineDistance { value, .. } => Some(*value),
            Spec::ArcSweep { degrees, .. } | Spec::Angle { degrees, .. } => Some(*degrees),
            _ => None,
        }
    }

    /// Sets the dimension; false when this constraint has none.
    pub fn set_value(&mut self, v: f64) -> bool {
        match self {
            Spec::Length { value, .. }
            | Spec::Radius { value, .. }
            | Spec::Diameter { value, .. }
            | Spec::Distance { value, .. }
            | Spec::PointLineDistance { value, .. } => *value = v,
            Spec::ArcSweep { degrees, .. } | Spec::Angle { degrees, .. } => *degrees = v,
            _ => return false,
        }
        true
    }

    /// The shapes it refers to, with the name of each argument.
    #[must_use]
    pub fn shapes(&self) -> Vec<(&'static str, &R)> {
        match self {
            Spec::Fix { point } => vec![("point", point)],
            Spec::FixShape { shape }
            | Spec::Lock { shape }
            | Spec::Radius { shape, .. }
            | Spec::Diameter { shape, .. } => vec![("shape", shape)],
            Spec::Length { line, .. } | Spec::Horizontal { line } | Spec::Vertical { line } => {
                vec![("line", line)]
            }
            Spec::ArcSweep { arc, .. } => vec![("arc", arc)],
            Spec::Distance { a, b, .. }
            | Spec::Coincident { a, b }
            | Spec::Concentric { a, b }
            | Spec::Parallel { a, b }
            | Spec::Perpendicular { a, b }
            | Spec::Angle { a, b, .. }
            | Spec::EqualLength { a, b }
            | Spec::EqualRadius { a, b }
            | Spec::Tangent { a, b, .. }
            | Spec::SymmetricAxis { a, b, .. }
            | Spec::Collinear { a, b } => vec![("a", a), ("b", b)],
            Spec::PointOnLine { point, line }
            | Spec::Midpoint { point, line }
            | Spec::PointLineDistance { point, line, .. } => {
                vec![("point", point), ("line", line)]
            }
            Spec::PointOnCircle { point, shape } => vec![("point", point), ("shape", shape)],
            Spec::Symmetric { a, b, line } => vec![("a", a), ("b", b), ("line", line)],
        }
    }

    /// The same constraint naming its shapes another way; the first refusal of `f` stops it.
    ///
    /// # Errors
    /// Whatever `f` returns for a shape it cannot name.
    pub fn try_map<S, E>(
        &self,
        mut f: impl FnMut(&'static str, &R) -> Result<S, E>,
    ) -> Result<Spec<S>, E> {
        Ok(match self {
            Spec::Fix { point } => Spec::Fix {
                point: f("point", point)?,
            },
            Spec::FixShape { shape } => Spec::FixShape {
                shape: f("shape", shape)?,
            },
            Spec::Length { line, value } => Spec::Length {
                line: f("line", line)?,
                value: *value,
            },
            Spec::Horizontal { line } => Spec::Horizontal {
                line: f("line", line)?,
            },
            Spec::Vertical { line } => Spec::Vertical {
                line: f("line", line)?,
            },
            Spec::Radius { shape, value } => Spec::Radius {
                shape: f("shape", shape)?,
                value: *value,
            },
            Spec::Diameter { shape, value } => Spec::Diameter {
                shape: f("shape", shape)?,
                value: *value,
            },
            Spec::ArcSweep { arc, degrees } => Spec::ArcSweep {
                arc: f("arc", arc)?,
                degrees: *degrees,
            },
            Spec::Lock { shape } => Spec::Lock {
                shape: f("shape", shape)?,
            },
            Spec::Distance { a, b, value } => Spec::Distance {
                a: f("a", a)?,
                b: f("b", b)?,
                value: *value,
            },
            Spec::Coincident { a, b } => Spec::Coincident {
                a: f("a", a)?,
                b: f("b", b)?,
            },
            Spec::Concentric { a, b } => Spec::Concentric {
                a: f("a", a)?,
                b: f("b", b)?,
            },
            Spec::Parallel { a, b } => Spec::Parallel {
                a: f("a", a)?,
                b: f("b", b)?,
            },
            Spec::Perpendicular { a, b } => Spec::Perpendicular {
                a: f("a", a)?,
                b: f("b", b)?,
            },
            Spec::Angle { a, b, degrees } => Spec::Angle {
                a: f("a", a)?,
                b: f("b", b)?,
                degrees: *degrees,
            },
            Spec::EqualLength { a, b } => Spec::EqualLength {
                a: f("a", a)?,
                b: f("b", b)?,
            },
            Spec::EqualRadius { a, b } => Spec::EqualRadius {
                a: f("a", a)?,
                b: f("b", b)?,
            },
            Spec::Tangent { a, b, a_end, b_end } => Spec::Tangent {
                a: f("a", a)?,
                b: f("b", b)?,
                a_end: *a_end,
                b_end: *b_end,
            },
            Spec::PointOnLine { point, line } => Spec::PointOnLine {
                point: f("point", point)?,
                line: f("line", line)?,
            },
            Spec::PointOnCircle { point, shape } => Spec::PointOnCircle {
                point: f("point", point)?,
                shape: f("shape", shape)?,
            },
            Spec::Midpoint { point, line } => Spec::Midpoint {
                point: f("point", point)?,
                line: f("line", line)?,
            },
            Spec::Symmetric { a, b, line } => Spec::Symmetric {
                a: f("a", a)?,
                b: f("b", b)?,
                line: f("line", line)?,
            },
            Spec::SymmetricAxis { a, b, axis } => Spec::SymmetricAxis {
                a: f("a", a)?,
                b: f("b", b)?,
                axis: *axis,
            },
            Spec::PointLineDistance { point, line, value } => Spec::PointLineDistance {
                point: f("point", point)?,
                line: f("line", line)?,
                value: *value,
            },
            Spec::Collinear { a, b } => Spec::Collinear {
                a: f("a", a)?,
                b: f("b", b)?,
            },
        })
    }
}
