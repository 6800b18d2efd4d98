//! Typed handles: non-zero 32-bit numbers, unique within their kind.

use serde::{Deserialize, Serialize};
use std::fmt;

macro_rules! handle {
    ($(#[$doc:meta])* $name:ident, $label:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
        #[serde(transparent)]
        pub struct $name(pub u32);

        impl $name {
            /// The word used for this kind of object in messages.
            pub const LABEL: &'static str = $label;

            /// Whether this is the reserved zero handle.
            #[must_use]
            pub fn is_zero(self) -> bool {
                self.0 == 0
            }
        }

        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, "{} {}", $label, self.0)
            }
        }

        impl fmt::Debug for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, "{}({})", stringify!($name), self.0)
            }
        }

        impl From<u32> for $name {
            fn from(v: u32) -> Self {
                Self(v)
            }
        }
    };
}

handle!(
    /// Handle of a [`Param`](crate::Param): one real unknown.
    ParamId,
    "param"
);
handle!(
    /// Handle of an [`Entity`](crate::Entity): a point, line, circle, workplane ...
    EntityId,
    "entity"
);
handle!(
    /// Handle of a [`Constraint`](crate::Constraint).
    ConstraintId,
    "constraint"
);
handle!(
    /// A group: the set of parameters, entities and constraints solved together.
    GroupId,
    "group"
);

/// Any object of the model, for error messages and reports.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Debug, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind", content = "h")]
pub enum ObjectId {
    /// A parameter.
    Param(ParamId),
    /// An entity.
    Entity(EntityId),
    /// A constraint.
    Constraint(ConstraintId),
}

impl fmt::Display for ObjectId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ObjectId::Param(h) => h.fmt(f),
            ObjectId::Entity(h) => h.fmt(f),
            ObjectId::Constraint(h) => h.fmt(f),
        }
    }
}
