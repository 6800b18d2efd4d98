//! Conflicts among objects that are written as several constraints each.
//!
//! The core names a conflict minimal among its constraints: take any one out and the rest can
//! hold. A front end whose objects are written as several constraints (an assembly's mate: a
//! fastened joint is a coincidence and an orientation) reports the objects those constraints
//! belong to, and a set minimal among constraints need not be minimal among objects. One
//! object's constraints can stand in for part of another's: a fastened joint's coincidence with
//! a concentric mate's two constraints, and a distance, can make a minimal set of constraints
//! where the fastened joint alone and the distance already conflict. Shrinking the objects
//! themselves, whole, gives the set the user can act on.

use super::minimal;
use super::unmerged::Equations;
use super::Member;
use crate::error::SolveError;
use crate::model::{ConstraintId, GroupId, System};
use crate::solve::Config;

/// Shrinks `groups` (each the constraints of one object of a front end, all of `group` of
/// `sys`), which together cannot hold, by the deletion filter over whole groups: a group goes
/// when the others still fail on their own, checked from the values in `sys` as the core checks
/// its own conflicts (Newton from there and from a generic point near it, then built up one
/// constraint at a time). Groups are tried from the first, so that the last ones are kept
/// when there is a choice.
///
/// Returns the indices of the groups kept, in order; `None` when the groups together are not
/// shown to fail (nothing to shrink).
///
/// # Errors
/// An invalid model or a bad option, as [`crate::solve`].
pub fn minimal_groups(
    sys: &System,
    group: GroupId,
    groups: &[Vec<ConstraintId>],
    cfg: &Config,
) -> Result<Option<Vec<usize>>, SolveError> {
    cfg.check()?;
    sys.validate()?;
    let start: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
    let eqs = Equations::new(sys, group, &start)?;
    let starts = [&start[..]];
    // The equations of the groups `kept`; a constraint with none here (one written twice, whose
    // copy never reaches the equations) adds nothing.
    let kernels = |kept: &[usize]| -> Vec<usize> {
        kept.iter()
            .flat_map(|&g| groups[g].iter())
            .filter_map(|&c| eqs.kernel_of(Member::Constraint(c)))
            .collect()
    };
    let mut kept: Vec<usize> = (0..groups.len()).collect();
    if minimal::consistent(&eqs, &kernels(&kept), &starts, cfg) {
        return Ok(None);
    }
    for g in 0..groups.len() {
        if kept.len() <= 1 {
            break;
        }
        let rest: Vec<usize> = kept.iter().copied().filter(|&k| k != g).collect();
        if !minimal::consistent(&eqs, &kernels(&rest), &starts, cfg) {
            kept = rest;
        }
    }
    Ok(Some(kept))
}
