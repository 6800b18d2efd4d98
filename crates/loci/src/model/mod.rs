//! The SolveSpace model: parameters, entities, constraints, groups and their handles.

mod constraint;
mod entity;
mod handle;
mod index;
mod param;
mod part;
mod system;
mod validate;

pub use constraint::{Constraint, ConstraintKind, PlaneRule, Signature, Want, FIELD_NAMES};
pub use entity::{Entity, EntityKind, EntityType};
pub use handle::{ConstraintId, EntityId, GroupId, ObjectId, ParamId};
pub use param::Param;
pub use system::{ConstraintMut, System};
pub use validate::MAX_MAGNITUDE;
