//! loci-bench: loci side by side with SolveSpace, PlaneGCS and ezpz on the same generated
//! problems.
//!
//! A run generates each family at each size once ([`generate`]), as a neutral
//! [`problem::Problem`], translates it to each solver ([`slvs`], [`peers`]), runs every
//! solver in a worker process with a time limit ([`run`]), checks every answer's residuals
//! itself ([`check`]), and writes a markdown table and an SVG plot ([`report`]).

pub mod assembly;
pub mod assembly_brep;
pub mod assembly_cadquery;
pub mod check;
pub mod compare;
pub mod drag;
pub mod drag_peers;
pub mod generate;
pub mod peers;
pub mod problem;
pub mod python;
pub mod report;
pub mod run;
pub mod setup;
pub mod slvs;
pub mod wasm;
