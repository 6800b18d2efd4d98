//! # loci-slvs
//!
//! A C library with the interface of SolveSpace 3.1's `libslvs`, backed by loci: the same
//! `slvs.h` names, struct layouts and constants (`include/slvs.h` in this crate), and the same
//! behaviour, so a program written for libslvs compiles and links against `libloci_slvs`
//! unchanged.
//!
//! Exported functions: `Slvs_Solve`, `Slvs_QuaternionU`, `Slvs_QuaternionV`,
//! `Slvs_QuaternionN`, `Slvs_MakeQuaternion`, and the extension `Loci_Slvs_LastError`.
//!
//! ## Behaviour, as libslvs 3.1 (checked against it by `tests/differential.rs`)
//! - The caller owns every array; only `param[].val`, `failed[]`, `faileds`, `dof` and
//!   `result` are written.
//! - Parameters of the solved group are unknowns; everything else is constant.
//! - `SLVS_RESULT_OKAY`: values written. `SLVS_RESULT_INCONSISTENT`: conflicting constraints
//!   (values not written), or every constraint holds but some are redundant (values written);
//!   `failed[]` names them. `SLVS_RESULT_DIDNT_CONVERGE`: values not written.
//! - `dof` is reported in every case (unknowns minus the rank of the equations).
//! - `dragged[]`: those parameters move as little as possible (their steps weigh 20 times
//!   more); unused slots are 0 and unknown handles are ignored.
//! - There is no size limit, so `SLVS_RESULT_TOO_MANY_UNKNOWNS` never happens.
//!
//! ## Where loci is stricter
//! libslvs trusts its input; loci checks it. A null array with a non-zero count, a negative
//! count, an unknown type, a zero, repeated or dangling handle, a NaN or infinite value, or a
//! wrong entity type for a field gives `LOCI_SLVS_RESULT_INVALID_INPUT` (100) with the
//! offending constraint in `failed[]` when there is one; a panic inside loci gives
//! `LOCI_SLVS_RESULT_INTERNAL_ERROR` (101). Neither writes any parameter.
//! `Loci_Slvs_LastError` returns the message.

pub mod abi;
pub mod convert;
mod last_error;
mod quaternion;
mod solve;
mod start;

pub use last_error::Loci_Slvs_LastError;
pub use quaternion::{Slvs_MakeQuaternion, Slvs_QuaternionN, Slvs_QuaternionU, Slvs_QuaternionV};
pub use solve::{result_code, solve_arrays, Answer, Slvs_Solve};

/// The directory holding this crate's `slvs.h`, for build scripts and tests.
pub const INCLUDE_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/include");
