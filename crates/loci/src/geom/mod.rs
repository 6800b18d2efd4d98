//! Geometry over generic scalars: vectors, quaternions, dual numbers.

mod scalar;
mod splitmix;
mod vector;

pub use scalar::{Dual, Scalar};
pub(crate) use splitmix::SplitMix;
pub use vector::{quaternion_from_uv, Quat, Vec3};
