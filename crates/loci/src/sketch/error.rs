//! What can go wrong when editing or solving a sketch.

use super::{ShapeId, ShapeKind, SketchConstraintId};
use crate::error::{ModelError, SolveError};
use thiserror::Error;

/// A sketch edit or solve that cannot be done; each names the object at fault.
#[derive(Clone, Debug, Error, PartialEq)]
#[non_exhaustive]
pub enum SketchError {
    /// No shape with this handle (never made, or removed).
    #[error("{0} does not exist")]
    NoShape(ShapeId),
    /// No constraint with this handle.
    #[error("{0} does not exist")]
    NoConstraint(SketchConstraintId),
    /// A constraint was given a shape of the wrong kind.
    #[error("{constraint}: {field} is {shape}, a {found}, but {expected} is expected")]
    WrongShape {
        /// The kind of constraint being made.
        constraint: &'static str,
        /// The argument.
        field: &'static str,
        /// The shape given.
        shape: ShapeId,
        /// What it is.
        found: ShapeKind,
        /// What the constraint needs.
        expected: &'static str,
    },
    /// A number that is not finite, or out of its range.
    #[error("{what} is {value}: {expected} is expected")]
    BadValue {
        /// Which number.
        what: &'static str,
        /// The value given.
        value: f64,
        /// Its range.
        expected: &'static str,
    },
    /// A constraint that measures nothing cannot be a reference dimension.
    #[error("{0} has no value to measure, so it cannot be a reference dimension")]
    NotADimension(&'static str),
    /// The same shape twice where two different ones are needed.
    #[error("{constraint}: {shape} is given twice; two different shapes are needed")]
    SameShape {
        /// The kind of constraint being made.
        constraint: &'static str,
        /// The repeated shape.
        shape: ShapeId,
    },
    /// A drag of a shape that cannot be dragged.
    #[error("{0} cannot be dragged: it is held by a fixed constraint")]
    Fixed(ShapeId),
    /// The underlying model refused an edit.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// The solver could not start.
    #[error(transparent)]
    Solve(#[from] SolveError),
}
