//! The structs and numbers of `slvs.h`, laid out exactly as libslvs 3.1 lays them out.
//!
//! Field names follow the C header (hence `non_snake_case`) so that the two read alike.
#![allow(non_snake_case, non_camel_case_types)]

use std::os::raw::c_int;

/// `Slvs_hParam`.
pub type Slvs_hParam = u32;
/// `Slvs_hEntity`.
pub type Slvs_hEntity = u32;
/// `Slvs_hConstraint`.
pub type Slvs_hConstraint = u32;
/// `Slvs_hGroup`.
pub type Slvs_hGroup = u32;

/// `Slvs_Param`: one real number.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slvs_Param {
    /// Handle.
    pub h: Slvs_hParam,
    /// Group.
    pub group: Slvs_hGroup,
    /// Value: initial guess in, solution out.
    pub val: f64,
}

/// `Slvs_Entity`: a point, normal, distance, workplane, line, cubic, circle or arc.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Slvs_Entity {
    /// Handle.
    pub h: Slvs_hEntity,
    /// Group.
    pub group: Slvs_hGroup,
    /// One of the `SLVS_E_*` numbers.
    pub r#type: c_int,
    /// Workplane, or 0 for free in 3D.
    pub wrkpl: Slvs_hEntity,
    /// Points (centre, start, end, control points ...).
    pub point: [Slvs_hEntity; 4],
    /// Normal.
    pub normal: Slvs_hEntity,
    /// Distance (a circle's radius).
    pub distance: Slvs_hEntity,
    /// Parameters (coordinates, quaternion, distance).
    pub param: [Slvs_hParam; 4],
}

/// `Slvs_Constraint`: a geometric condition.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slvs_Constraint {
    /// Handle.
    pub h: Slvs_hConstraint,
    /// Group.
    pub group: Slvs_hGroup,
    /// One of the `SLVS_C_*` numbers.
    pub r#type: c_int,
    /// Workplane, or 0 for free in 3D.
    pub wrkpl: Slvs_hEntity,
    /// The dimension.
    pub valA: f64,
    /// First point.
    pub ptA: Slvs_hEntity,
    /// Second point.
    pub ptB: Slvs_hEntity,
    /// First entity.
    pub entityA: Slvs_hEntity,
    /// Second entity.
    pub entityB: Slvs_hEntity,
    /// Third entity.
    pub entityC: Slvs_hEntity,
    /// Fourth entity.
    pub entityD: Slvs_hEntity,
    /// Flag.
    pub other: c_int,
    /// Second flag.
    pub other2: c_int,
}

/// `Slvs_System`: the whole problem and the solver's answer.
#[repr(C)]
#[derive(Debug)]
pub struct Slvs_System {
    /// Parameters (caller-owned; `val` is written back).
    pub param: *mut Slvs_Param,
    /// Length of `param`.
    pub params: c_int,
    /// Entities (caller-owned, read only).
    pub entity: *mut Slvs_Entity,
    /// Length of `entity`.
    pub entities: c_int,
    /// Constraints (caller-owned, read only).
    pub constraint: *mut Slvs_Constraint,
    /// Length of `constraint`.
    pub constraints: c_int,
    /// Dragged parameters; 0 for unused slots.
    pub dragged: [Slvs_hParam; 4],
    /// Non-zero to name failing constraints.
    pub calculateFaileds: c_int,
    /// Out: failing constraints (caller-owned, `faileds` long on input).
    pub failed: *mut Slvs_hConstraint,
    /// In: capacity of `failed`; out: how many were found.
    pub faileds: c_int,
    /// Out: degrees of freedom.
    pub dof: c_int,
    /// Out: one of the result codes.
    pub result: c_int,
}

/// `SLVS_E_POINT_IN_3D`.
pub const SLVS_E_POINT_IN_3D: c_int = 50000;
/// `SLVS_E_POINT_IN_2D`.
pub const SLVS_E_POINT_IN_2D: c_int = 50001;
/// `SLVS_E_NORMAL_IN_3D`.
pub const SLVS_E_NORMAL_IN_3D: c_int = 60000;
/// `SLVS_E_NORMAL_IN_2D`.
pub const SLVS_E_NORMAL_IN_2D: c_int = 60001;
/// `SLVS_E_DISTANCE`.
pub const SLVS_E_DISTANCE: c_int = 70000;
/// `SLVS_E_WORKPLANE`.
pub const SLVS_E_WORKPLANE: c_int = 80000;
/// `SLVS_E_LINE_SEGMENT`.
pub const SLVS_E_LINE_SEGMENT: c_int = 80001;
/// `SLVS_E_CUBIC`.
pub const SLVS_E_CUBIC: c_int = 80002;
/// `SLVS_E_CIRCLE`.
pub const SLVS_E_CIRCLE: c_int = 80003;
/// `SLVS_E_ARC_OF_CIRCLE`.
pub const SLVS_E_ARC_OF_CIRCLE: c_int = 80004;

/// `SLVS_RESULT_OKAY`: every constraint holds, none redundant.
pub const SLVS_RESULT_OKAY: c_int = 0;
/// `SLVS_RESULT_INCONSISTENT`: conflicting constraints, or (values written) redundant ones.
pub const SLVS_RESULT_INCONSISTENT: c_int = 1;
/// `SLVS_RESULT_DIDNT_CONVERGE`: no solution found.
pub const SLVS_RESULT_DIDNT_CONVERGE: c_int = 2;
/// `SLVS_RESULT_TOO_MANY_UNKNOWNS`: libslvs's size limit; loci never returns it.
pub const SLVS_RESULT_TOO_MANY_UNKNOWNS: c_int = 3;
/// loci extension: the input is not a valid model.
pub const LOCI_SLVS_RESULT_INVALID_INPUT: c_int = 100;
/// loci extension: an internal error (a caught panic).
pub const LOCI_SLVS_RESULT_INTERNAL_ERROR: c_int = 101;

#[cfg(test)]
mod tests {
    use super::*;
    use std::mem::{offset_of, size_of};

    /// The x86-64 / aarch64 layout of libslvs 3.1's structs (LP64: 4-byte int, 8-byte pointer).
    #[test]
    #[cfg(target_pointer_width = "64")]
    fn layout_matches_libslvs_lp64() {
        assert_eq!(size_of::<Slvs_Param>(), 16);
        assert_eq!(offset_of!(Slvs_Param, val), 8);
        assert_eq!(size_of::<Slvs_Entity>(), 56);
        assert_eq!(offset_of!(Slvs_Entity, point), 16);
        assert_eq!(offset_of!(Slvs_Entity, param), 40);
        assert_eq!(size_of::<Slvs_Constraint>(), 56);
        assert_eq!(offset_of!(Slvs_Constraint, valA), 16);
        assert_eq!(offset_of!(Slvs_Constraint, other2), 52);
        assert_eq!(size_of::<Slvs_System>(), 88);
        assert_eq!(offset_of!(Slvs_System, dragged), 44);
        assert_eq!(offset_of!(Slvs_System, calculateFaileds), 60);
        assert_eq!(offset_of!(Slvs_System, failed), 64);
        assert_eq!(offset_of!(Slvs_System, result), 80);
    }
}
