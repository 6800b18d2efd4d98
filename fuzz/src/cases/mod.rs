//! The checks behind the fuzz targets, in plain Rust (loci and the standard library only),
//! so that `crates/loci/tests/fuzz_regressions.rs` runs the very same code on the saved
//! inputs without libFuzzer.

pub mod bytes;
pub mod files;
pub mod geometry;
pub mod json;
pub mod resolve;
pub mod slvs;
