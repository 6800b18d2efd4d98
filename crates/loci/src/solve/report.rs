//! What a solve reports.

use crate::model::{ConstraintId, EntityId};
use serde::{Deserialize, Serialize};
use std::fmt;

/// How a solve ended, with SolveSpace's meanings.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Outcome {
    /// Every constraint holds and none is redundant.
    Okay,
    /// Every constraint holds, but some are redundant (listed in `failed`).
    RedundantOkay,
    /// Some constraints cannot hold together (listed in `failed`).
    Inconsistent,
    /// No solution was found, and no conflict was proven (unsatisfied constraints in `failed`).
    /// A placement reached only by sending points more than ten thousand times the drawing's
    /// size away (where parallel lines that must meet appear to) counts as none: those
    /// constraints are named.
    DidNotConverge,
}

impl Outcome {
    /// Whether every constraint holds.
    #[must_use]
    pub fn is_ok(self) -> bool {
        matches!(self, Outcome::Okay | Outcome::RedundantOkay)
    }

    /// The `snake_case` name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Outcome::Okay => "okay",
            Outcome::RedundantOkay => "redundant_okay",
            Outcome::Inconsistent => "inconsistent",
            Outcome::DidNotConverge => "did_not_converge",
        }
    }
}

impl fmt::Display for Outcome {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The result of solving one group.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Report {
    /// How it ended.
    pub outcome: Outcome,
    /// Degrees of freedom left: unknowns minus the rank of the equations.
    pub dof: usize,
    /// For `redundant_okay`: constraints any of which could be removed; for `inconsistent`: the
    /// constraints involved in a conflict; for `did_not_converge`: those left unsatisfied.
    /// Ascending handles.
    pub failed: Vec<ConstraintId>,
    /// Entities whose implicit condition (unit quaternion, equal arc radii) is involved.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub failed_entities: Vec<EntityId>,
    /// Newton iterations (the most any component needed).
    pub iterations: usize,
    /// Largest residual left.
    pub residual: f64,
    /// Number of unknowns after merging equal parameters.
    pub unknowns: usize,
    /// Number of equations after substitution.
    pub equations: usize,
    /// Number of independent components solved.
    pub components: usize,
}

impl Report {
    /// The report of a group with nothing in it: okay, no unknowns, no equations.
    #[must_use]
    pub fn empty() -> Self {
        Self {
            outcome: Outcome::Okay,
            dof: 0,
            failed: Vec::new(),
            failed_entities: Vec::new(),
            iterations: 0,
            residual: 0.0,
            unknowns: 0,
            equations: 0,
            components: 0,
        }
    }
}
