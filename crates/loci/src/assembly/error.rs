//! Typed errors of the assembly layer: each names the component, reference or mate at fault.

use thiserror::Error;

/// Something in an assembly that cannot be used as given.
#[derive(Clone, Debug, Error, PartialEq)]
#[non_exhaustive]
pub enum AssemblyError {
    /// Two components share a name.
    #[error("component `{0}` is defined twice")]
    DuplicateComponent(String),
    /// A component's pose has a non-finite number or a rotation that is not a unit quaternion.
    #[error("component `{0}`: the pose must be finite with a unit rotation quaternion")]
    BadPose(String),
    /// A reference holds a non-finite number.
    #[error("component `{component}`: reference `{reference}` has a number that is not finite")]
    BadReference {
        /// The component.
        component: String,
        /// The reference.
        reference: String,
    },
    /// A selection names a component that does not exist.
    #[error("mate {mate}: component `{component}` does not exist")]
    UnknownComponent {
        /// The mate's id.
        mate: String,
        /// The missing component.
        component: String,
    },
    /// A selection names a reference its component does not have.
    #[error("mate {mate}: `{component}` has no reference `{reference}`")]
    UnknownReference {
        /// The mate's id.
        mate: String,
        /// The component (or `world`).
        component: String,
        /// The missing reference.
        reference: String,
    },
    /// A selection cannot give what the mate needs (a direction from a vertex, a line from a
    /// face ...).
    #[error("mate {mate}: {selection} is a {found}, which gives no {needed}")]
    Unusable {
        /// The mate's id.
        mate: String,
        /// The selection, `component.reference`.
        selection: String,
        /// What the reference is.
        found: &'static str,
        /// What the mate needs from it.
        needed: &'static str,
    },
    /// Both selections are on one component: a mate relates two components.
    #[error("mate {mate}: both selections are on `{component}`; select references on two different components")]
    SameComponent {
        /// The mate's id.
        mate: String,
        /// The component.
        component: String,
    },
    /// A selection is not attached to any component (a world reference) where the mate
    /// needs components.
    #[error("mate {mate}: {selection} is not attached to a component; both selections must belong to components")]
    NotAttached {
        /// The mate's id.
        mate: String,
        /// The selection.
        selection: String,
    },
    /// A mate's value is not a finite number, or a distance is negative where it cannot be.
    #[error("mate {mate}: the value {value} is not usable: {expected}")]
    BadValue {
        /// The mate's id.
        mate: String,
        /// The value.
        value: f64,
        /// What is expected.
        expected: &'static str,
    },
    /// Two mates share an id.
    #[error("mate id `{0}` is used twice")]
    DuplicateMate(String),
    /// The core refused the system built from the assembly (a bug in this layer if it happens).
    #[error("the constraint system built from the assembly is invalid: {0}")]
    Solve(#[from] crate::SolveError),
    /// The core refused an object built from the assembly.
    #[error("the constraint system built from the assembly is invalid: {0}")]
    Model(#[from] crate::ModelError),
    /// A bad option.
    #[error("option `{name}` is {value}, but {expected} is expected")]
    BadOption {
        /// The option.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What is expected.
        expected: &'static str,
    },
}
