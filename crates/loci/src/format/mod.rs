//! File formats.

pub mod assembly;
pub mod json;
pub mod sketch;
pub mod slvs;
