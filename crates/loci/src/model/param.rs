//! Parameters: the real numbers the solver may change.

use super::{GroupId, ParamId};
use serde::{Deserialize, Serialize};

/// One real number. Parameters in the group being solved are unknowns; all others are constants.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Param {
    /// Unique non-zero handle.
    pub h: ParamId,
    /// The group this parameter belongs to.
    pub group: GroupId,
    /// Current value: the initial guess before a solve, the answer after.
    pub val: f64,
}

impl Param {
    /// A parameter with handle `h` in `group`, starting at `val`.
    #[must_use]
    pub fn new(h: impl Into<ParamId>, group: impl Into<GroupId>, val: f64) -> Self {
        Self {
            h: h.into(),
            group: group.into(),
            val,
        }
    }
}
