//! Typed errors: each names the object that is wrong and what was expected.

use crate::model::{ConstraintId, ConstraintKind, EntityId, EntityType, GroupId, ObjectId};
use thiserror::Error;

/// Something in a [`System`](crate::System) that cannot be solved as given.
#[derive(Clone, Debug, Error, PartialEq)]
#[non_exhaustive]
pub enum ModelError {
    /// A handle is 0, which is reserved.
    #[error("{what} #{index} has handle 0; handles start at 1")]
    ZeroHandle {
        /// "param", "entity" or "constraint".
        what: &'static str,
        /// Its position in the list (0-based).
        index: usize,
    },
    /// Two objects of one kind share a handle.
    #[error("{object} is defined twice")]
    DuplicateHandle {
        /// The repeated handle.
        object: ObjectId,
    },
    /// A reference to an object that does not exist.
    #[error("{owner}: {field} refers to {target} {handle}, which does not exist")]
    Dangling {
        /// The object holding the reference.
        owner: ObjectId,
        /// The field.
        field: &'static str,
        /// "param" or "entity".
        target: &'static str,
        /// The missing handle.
        handle: u32,
    },
    /// A reference to an entity of the wrong type.
    #[error("{owner}: {field} is {entity}, a {found}, but {expected} is expected")]
    WrongKind {
        /// The object holding the reference.
        owner: ObjectId,
        /// The field.
        field: &'static str,
        /// The entity referred to.
        entity: EntityId,
        /// What it is.
        found: EntityType,
        /// What it should be.
        expected: &'static str,
    },
    /// A required field is empty.
    #[error("{owner}: {field} is missing; {expected} is expected")]
    MissingField {
        /// The object.
        owner: ObjectId,
        /// The field.
        field: &'static str,
        /// What it should hold.
        expected: &'static str,
    },
    /// An object cannot be removed while another still refers to it.
    #[error("{object} cannot be removed: {user} still refers to it")]
    InUse {
        /// The object asked to be removed.
        object: ObjectId,
        /// The first object found that refers to it.
        user: ObjectId,
    },
    /// A NaN or infinite number.
    #[error("{owner}: {field} is {value}, not a finite number")]
    NonFinite {
        /// The object.
        owner: ObjectId,
        /// The field.
        field: &'static str,
        /// The value.
        value: f64,
    },
    /// A finite number too large to solve with: beyond [`crate::MAX_MAGNITUDE`], the squares
    /// and products the equations take of it overflow.
    #[error(
        "{owner}: {field} is {value:e}, beyond 1e100 in size, the largest number loci solves with"
    )]
    OutOfRange {
        /// The object.
        owner: ObjectId,
        /// The field.
        field: &'static str,
        /// The value.
        value: f64,
    },
    /// A constraint that only applies in a workplane has none.
    #[error("{constraint} ({kind}) must be given a workplane; it cannot be free in 3D")]
    NeedsWorkplane {
        /// The constraint.
        constraint: ConstraintId,
        /// Its type.
        kind: ConstraintKind,
    },
    /// An entity refers to itself through its references.
    #[error("{entity}: its references loop back to itself")]
    Cycle {
        /// The entity.
        entity: EntityId,
    },
}

/// Why a solve could not start.
#[derive(Clone, Debug, Error, PartialEq)]
#[non_exhaustive]
pub enum SolveError {
    /// The model is not valid.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// No parameter, entity or constraint belongs to the group asked for.
    #[error("{group} does not exist; the groups of this system are {}", list_groups(.existing))]
    UnknownGroup {
        /// The group asked for.
        group: GroupId,
        /// The groups that have objects, in increasing order.
        existing: Vec<GroupId>,
    },
    /// One block of equations shares unknowns so widely (a point that tens of thousands of
    /// constraints refer to) that its normal equations would take gigabytes: refused rather
    /// than allocated.
    #[error(
        "{equations} equations on {unknowns} unknowns share unknowns so widely that solving them \
         would build {products} products (at most {} are built); split the constraints on \
         the most shared points over several points",
        crate::solve::MAX_PRODUCTS
    )]
    TooLarge {
        /// Equations of the block.
        equations: usize,
        /// Unknowns of the block.
        unknowns: usize,
        /// Products of Jacobian entries its normal equations need.
        products: usize,
    },
    /// A dragged parameter does not exist.
    #[error("dragged parameter {0} does not exist")]
    UnknownDragged(u32),
    /// A solver option is out of range.
    #[error("option {name} = {value} is out of range: {expected}")]
    BadOption {
        /// The option.
        name: &'static str,
        /// Its value.
        value: f64,
        /// The allowed range.
        expected: &'static str,
    },
}

fn list_groups(groups: &[GroupId]) -> String {
    if groups.is_empty() {
        return "none (it is empty)".to_string();
    }
    let names: Vec<String> = groups.iter().map(|g| g.0.to_string()).collect();
    names.join(", ")
}
