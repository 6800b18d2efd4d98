//! `Slvs_Solve`: read the caller's arrays, solve with loci, write the answer back.

use crate::abi::*;
use crate::convert::{self, InputError};
use crate::last_error;
use crate::start;
use loci::{Config, Outcome, ParamId};
use std::os::raw::c_int;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// What a solve produced, before it is written into the caller's `Slvs_System`.
#[derive(Debug, PartialEq)]
pub struct Answer {
    /// `result`.
    pub result: c_int,
    /// `dof`.
    pub dof: c_int,
    /// The constraints for `failed[]`.
    pub failed: Vec<Slvs_hConstraint>,
    /// New values of `param[i].val` by index, when they are to be written.
    pub values: Option<Vec<(usize, f64)>>,
}

/// The libslvs result code for a loci outcome.
///
/// libslvs 3.1 has no code for "solved, but some constraints are redundant": it reports
/// `SLVS_RESULT_INCONSISTENT` with the redundant constraints in `failed[]`, yet writes the
/// solved values back. loci does the same, so callers written for libslvs see no change.
#[must_use]
pub fn result_code(o: Outcome) -> c_int {
    match o {
        Outcome::Okay => SLVS_RESULT_OKAY,
        Outcome::RedundantOkay | Outcome::Inconsistent => SLVS_RESULT_INCONSISTENT,
        Outcome::DidNotConverge => SLVS_RESULT_DIDNT_CONVERGE,
    }
}

/// Solves group `hg` of the model in the given arrays.
///
/// Dragged handles that name no parameter are ignored, as libslvs ignores them.
///
/// # Errors
/// Input that is not a valid model.
pub fn solve_arrays(
    params: &[Slvs_Param],
    entities: &[Slvs_Entity],
    constraints: &[Slvs_Constraint],
    dragged: [Slvs_hParam; 4],
    calculate_faileds: bool,
    hg: Slvs_hGroup,
) -> Result<Answer, InputError> {
    let mut sys = convert::system(params, entities, constraints)?;
    let dragged: Vec<ParamId> = dragged
        .iter()
        .filter(|&&h| h != 0)
        .map(|&h| ParamId(h))
        .filter(|&h| sys.param(h).is_some())
        .collect();
    let dragged_handles: Vec<Slvs_hParam> = dragged.iter().map(|h| h.0).collect();
    for (i, v) in start::merged_start_values(params, entities, constraints, &dragged_handles, hg) {
        sys.set_value(ParamId(params[i].h), v);
    }
    // Always look for the failing constraints: libslvs names conflicting ones even when
    // calculateFaileds is 0, and only leaves out the redundant ones then. A program written
    // for libslvs expects its answer for an under-constrained sketch, the end of Newton's
    // path, not the solution nearest the drawing that the Rust API gives by default; and
    // that path depends on how the equations are written, so 2D angles are written as
    // libslvs writes them.
    let cfg = Config::default()
        .with_nearest(false)
        .with_solvespace_angles(true);
    let report = match loci::solve(&mut sys, hg.into(), &dragged, &cfg) {
        // libslvs answers okay, DOF 0, for a group with nothing in it, and programs written
        // for it rely on that; loci does the same, and says why in Loci_Slvs_LastError.
        Err(e @ loci::SolveError::UnknownGroup { .. }) => {
            last_error::set(format!("warning: {e}"));
            return Ok(Answer {
                result: SLVS_RESULT_OKAY,
                dof: 0,
                failed: Vec::new(),
                values: Some(Vec::new()),
            });
        }
        other => other,
    };
    let report = report.map_err(|e| match e {
        loci::SolveError::Model(m) => InputError::Model(m),
        // The model was validated and unknown dragged handles dropped above, and the default
        // options are in range, so this is not expected; keep loci's message if it happens.
        other => InputError::Solve(other.to_string()),
    })?;
    let failed = if report.outcome == Outcome::RedundantOkay && !calculate_faileds {
        Vec::new()
    } else {
        report.failed.iter().map(|c| c.0).collect()
    };
    let values = report.outcome.is_ok().then(|| {
        sys.params()
            .iter()
            .enumerate()
            .filter(|(_, p)| p.group.0 == hg)
            .map(|(i, p)| (i, p.val))
            .collect()
    });
    Ok(Answer {
        result: result_code(report.outcome),
        dof: c_int::try_from(report.dof).unwrap_or(c_int::MAX),
        failed,
        values,
    })
}

/// A slice over a caller's array, or why it cannot be one.
///
/// # Safety
/// When `ptr` is non-null and `count` positive, `ptr` points to `count` initialised elements
/// that stay valid and unmodified by anyone else for `'a`.
unsafe fn c_slice<'a, T>(
    ptr: *const T,
    count: c_int,
    array: &'static str,
    count_field: &'static str,
) -> Result<&'a [T], InputError> {
    let n = usize::try_from(count).map_err(|_| InputError::NegativeCount { count_field, count })?;
    if n == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(InputError::NullArray { array, count });
    }
    if !ptr.is_aligned() {
        return Err(InputError::Misaligned { array });
    }
    // SAFETY: non-null and aligned (checked above); length and lifetime from the caller.
    Ok(unsafe { std::slice::from_raw_parts(ptr, n) })
}

/// The part of [`Slvs_Solve`] that may fail; `sys` is non-null.
///
/// # Safety
/// As [`Slvs_Solve`].
unsafe fn solve_c(sys: *mut Slvs_System, hg: Slvs_hGroup) {
    // SAFETY: `sys` is non-null (checked by the caller) and valid by the contract; copying the
    // input fields out means no reference into the caller's struct is held while we write.
    let (param, params, entity, entities, constraint, constraints, dragged, calc) = unsafe {
        let s = &*sys;
        (
            s.param,
            s.params,
            s.entity,
            s.entities,
            s.constraint,
            s.constraints,
            s.dragged,
            s.calculateFaileds,
        )
    };
    let answer = (|| {
        // SAFETY: the arrays are the caller's, `params`/`entities`/`constraints` long, and not
        // touched by anyone else during the call (the contract of Slvs_Solve).
        let (p, e, c) = unsafe {
            (
                c_slice(param, params, "param", "params")?,
                c_slice(entity, entities, "entity", "entities")?,
                c_slice(constraint, constraints, "constraint", "constraints")?,
            )
        };
        solve_arrays(p, e, c, dragged, calc != 0, hg)
    })();
    let (result, dof, failed) = match answer {
        Ok(a) => {
            if let Some(values) = &a.values {
                for &(i, v) in values {
                    // SAFETY: `i < params` (it came from the slice over this array), and the
                    // shared slice above is no longer used.
                    unsafe { (*param.add(i)).val = v };
                }
            }
            (a.result, a.dof, a.failed)
        }
        Err(e) => {
            let culprit = e.culprit();
            last_error::set(e.to_string());
            (
                LOCI_SLVS_RESULT_INVALID_INPUT,
                -1,
                culprit.into_iter().collect(),
            )
        }
    };
    // SAFETY: `sys` is valid for writes (contract); `failed`, when non-null, holds at least the
    // `faileds` entries the caller put in on input, and we write no more than that.
    unsafe {
        let s = &mut *sys;
        s.result = result;
        s.dof = dof;
        if !s.failed.is_null() {
            let room = usize::try_from(s.faileds).unwrap_or(0);
            for (i, &h) in failed.iter().take(room).enumerate() {
                *s.failed.add(i) = h;
            }
            s.faileds = c_int::try_from(failed.len()).unwrap_or(c_int::MAX);
        }
    }
}

/// Solves group `hg` of `sys`, as libslvs's `Slvs_Solve` does.
///
/// Never unwinds into C: a panic inside loci becomes `LOCI_SLVS_RESULT_INTERNAL_ERROR`, and
/// invalid input becomes `LOCI_SLVS_RESULT_INVALID_INPUT` (see `slvs.h`). A null `sys` is
/// ignored (there is nowhere to write a result) but recorded for `Loci_Slvs_LastError`.
///
/// # Safety
/// `sys` is null or points to a valid `Slvs_System` whose arrays are as long as their counts
/// say (`failed` at least `faileds` long, or null), and nothing else accesses them during the
/// call.
#[no_mangle]
pub unsafe extern "C" fn Slvs_Solve(sys: *mut Slvs_System, hg: Slvs_hGroup) {
    last_error::clear();
    if sys.is_null() {
        last_error::set(InputError::NullSystem.to_string());
        return;
    }
    // SAFETY: non-null, and the rest is this function's contract.
    let caught = catch_unwind(AssertUnwindSafe(|| unsafe { solve_c(sys, hg) }));
    if let Err(panic) = caught {
        let what = panic
            .downcast_ref::<&str>()
            .map(|s| (*s).to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".to_string());
        last_error::set(format!("internal error in loci: {what}"));
        // SAFETY: as in `solve_c`: `sys` is non-null and valid for writes.
        unsafe {
            let s = &mut *sys;
            s.result = LOCI_SLVS_RESULT_INTERNAL_ERROR;
            s.dof = -1;
            if !s.failed.is_null() {
                s.faileds = 0;
            }
        }
    }
}
