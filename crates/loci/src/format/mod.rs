//! File formats.

pub mod json;
pub mod sketch;
pub mod slvs;
