//! # loci-wasm
//!
//! WebAssembly bindings of loci with wasm-bindgen, over its three layers:
//!
//! - [`system::System`] (`RawSystem` in JavaScript): the SolveSpace model read from loci JSON
//!   or `.slvs`, or built call by call; solved group by group, diagnosed, saved.
//! - [`sketch::SketchBinding`] (`RawSketch`): the 2D sketcher with named shapes, user and
//!   soft constraints, and drags that span mouse events.
//! - [`assembly::AssemblyBinding`] (`RawAssembly`): components, mates, solves at once or
//!   stepped.
//!
//! The raw classes pass structured values as JSON text and bulk values as `Float64Array`;
//! the package's JavaScript module (`js/loci.js`, typed by `js/loci.d.ts`) wraps them with
//! typed handles and reports and throws errors as `Error` subclasses naming the object at
//! fault ([`error::Fault`]). Nothing panics across the boundary: every fallible call returns
//! a typed error.
//!
//! The crate also builds natively (an `rlib`), so that the workspace's tests check the
//! bindings' Rust side.

pub mod assembly;
pub mod error;
pub mod sketch;
pub mod system;

use wasm_bindgen::prelude::*;

/// The version of loci these bindings were built from.
#[wasm_bindgen]
#[must_use]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
