//! Solving a file as SolveSpace does: group by group in order, each with the groups before
//! it held fixed.

use super::{GroupKind, GroupStatus, SlvsFile};
use crate::model::GroupId;
use crate::solve::{solve, Config, Report};
use crate::SolveError;
use std::fmt;

/// What happened to one group.
#[derive(Clone, Debug, PartialEq)]
pub struct GroupSolve {
    /// The group.
    pub group: GroupId,
    /// Its name in the file.
    pub name: String,
    /// Its type.
    pub kind: GroupKind,
    /// Whether SolveSpace accepts redundant constraints in it.
    pub allow_redundant: bool,
    /// The result.
    pub result: GroupResult,
}

/// The result of one group.
#[derive(Clone, Debug, PartialEq)]
pub enum GroupResult {
    /// Solved (or not) by loci.
    Solved(Report),
    /// SolveSpace's reference planes: fixed.
    References,
    /// Not solved: loci does not model this group, for the reason given. Its parameters keep
    /// their saved values.
    Unsupported(String),
    /// The solve could not start.
    Error(SolveError),
}

impl GroupSolve {
    /// Whether the group came out as SolveSpace would accept it: okay, or okay with
    /// redundant constraints where the group allows them. Fixed groups count as ok.
    #[must_use]
    pub fn is_ok(&self) -> bool {
        match &self.result {
            GroupResult::Solved(r) => match r.outcome {
                crate::Outcome::Okay => true,
                crate::Outcome::RedundantOkay => self.allow_redundant,
                _ => false,
            },
            GroupResult::References => true,
            GroupResult::Unsupported(_) | GroupResult::Error(_) => false,
        }
    }
}

impl fmt::Display for GroupResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GroupResult::Solved(r) => write!(f, "{} (dof {})", r.outcome, r.dof),
            GroupResult::References => f.write_str("reference planes (fixed)"),
            GroupResult::Unsupported(why) => write!(f, "not solved: {why}"),
            GroupResult::Error(e) => write!(f, "error: {}", super::solve_message(e)),
        }
    }
}

/// Solves every group of `file` in order; each group's solution is written into
/// `file.system` (when it succeeds) before the next group is solved, as in SolveSpace.
#[must_use]
pub fn solve_all(file: &mut SlvsFile, cfg: &Config) -> Vec<GroupSolve> {
    let groups = file.groups.clone();
    groups
        .iter()
        .map(|g| GroupSolve {
            group: g.h,
            name: g.name.clone(),
            kind: g.kind,
            allow_redundant: g.allow_redundant,
            result: match &g.status {
                GroupStatus::References => GroupResult::References,
                GroupStatus::Unsupported(why) => GroupResult::Unsupported(why.clone()),
                // A group the file declares but that owns nothing (a sketch with no entities
                // yet) is solved trivially, as in SolveSpace.
                GroupStatus::Solve if !file.system.groups().contains(&g.h) => {
                    GroupResult::Solved(Report::empty())
                }
                GroupStatus::Solve => match solve(&mut file.system, g.h, &[], cfg) {
                    Ok(r) => GroupResult::Solved(r),
                    Err(e) => GroupResult::Error(e),
                },
            },
        })
        .collect()
}
