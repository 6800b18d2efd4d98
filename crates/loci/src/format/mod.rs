//! File formats.

pub mod json;
pub mod slvs;
