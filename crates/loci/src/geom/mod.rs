//! Geometry over generic scalars: vectors, quaternions, dual numbers.

mod scalar;
mod vector;

pub use scalar::{Dual, Scalar};
pub use vector::{quaternion_from_uv, Quat, Vec3};
