//! What an assembly solve reports: per mate its status, value and error; the assembly's
//! degrees of freedom; each component's remaining motions in words; conflicts as minimal
//! sets of mates.

use super::component::Pose;
use crate::Outcome;
use serde::{Deserialize, Serialize};
use std::fmt;

/// How a mate ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MateStatus {
    /// It held before the solve: nothing had to move for it.
    Satisfied,
    /// It holds after the solve moved components.
    Adjusted,
    /// It does not hold and cannot: both of its components are grounded (or the world).
    Blocked,
    /// A selection cannot give what the mate needs (unknown name, a vertex for a line ...).
    InvalidSelection,
    /// The angle mate's seed rejection: a selection gives no direction.
    NoDirection,
    /// The angle mate's seed rejection: both selections are on one component.
    SameComponent,
    /// The angle mate's seed rejection: a selection is attached to no component.
    NotAttached,
    /// It holds, but adds nothing the others do not already ask.
    Redundant,
    /// It is in a minimal set of mates that cannot all hold.
    Conflicting,
    /// It does not hold and no conflict was proven (the solve did not converge, or the
    /// parts came to rest with a direction the other way round).
    Unsatisfied,
}

impl MateStatus {
    /// The `snake_case` name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            MateStatus::Satisfied => "satisfied",
            MateStatus::Adjusted => "adjusted",
            MateStatus::Blocked => "blocked",
            MateStatus::InvalidSelection => "invalid_selection",
            MateStatus::NoDirection => "no_direction",
            MateStatus::SameComponent => "same_component",
            MateStatus::NotAttached => "not_attached",
            MateStatus::Redundant => "redundant",
            MateStatus::Conflicting => "conflicting",
            MateStatus::Unsatisfied => "unsatisfied",
        }
    }

    /// Whether the mate holds.
    #[must_use]
    pub fn holds(self) -> bool {
        matches!(
            self,
            MateStatus::Satisfied | MateStatus::Adjusted | MateStatus::Redundant
        )
    }
}

/// One mate's line in the report.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MateReport {
    /// The mate's id.
    pub id: String,
    /// Its kind's name.
    pub kind: String,
    /// How it ended.
    pub status: MateStatus,
    /// What it measures now, where it has a dimension: a distance, an angle in degrees (the
    /// signed angle for `angle`, the joint angle for `revolute`), a slider's travel.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<f64>,
    /// How far from holding: the largest error of its relations (a length, or radians).
    pub error: f64,
    /// Why it is invalid, or which limit is violated.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub message: String,
    /// Whether a joint limit is violated.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub limit_violated: bool,
}

impl MateReport {
    /// The line of mate `id` of kind `kind` before it is measured and judged: unsatisfied,
    /// no value, no error, no message.
    pub(crate) fn unmeasured(id: String, kind: String) -> Self {
        Self {
            id,
            kind,
            status: MateStatus::Unsatisfied,
            value: None,
            error: 0.0,
            message: String::new(),
            limit_violated: false,
        }
    }
}

/// One component's line in the report.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ComponentReport {
    /// Its name.
    pub name: String,
    /// Whether it is grounded.
    pub grounded: bool,
    /// Where it is after the solve.
    pub pose: Pose,
    /// Its independent motions left (0: held), or `None` when they were not computed: the
    /// motions come from the diagnosis, which `options.diagnose: false` turns off. The
    /// assembly's own `dof` is counted either way.
    pub dof: Option<usize>,
    /// Those motions in words, e.g. "rotates about axis (0, 0, 1) through (10, 0, 0)" (empty
    /// when `dof` is `None`).
    pub motions: Vec<String>,
}

/// Everything an assembly solve found.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AssemblyReport {
    /// The core solve's outcome (`okay` when nothing had to be solved).
    pub outcome: Outcome,
    /// Degrees of freedom of the whole assembly.
    pub dof: usize,
    /// Newton iterations.
    pub iterations: usize,
    /// Largest residual left.
    pub residual: f64,
    /// Per mate, in the assembly's order.
    pub mates: Vec<MateReport>,
    /// Per component, in the assembly's order.
    pub components: Vec<ComponentReport>,
    /// Minimal sets of mates that cannot all hold, by id.
    pub conflicts: Vec<Vec<String>>,
    /// Sets of mates that ask something twice, by id: some of them are not needed (status
    /// `redundant`), or, where no one of them can go whole, only parts of them (a ball joint
    /// and collinear edges on one part: seven conditions on six freedoms).
    pub redundant: Vec<Vec<String>>,
}

impl AssemblyReport {
    /// Whether every mate holds.
    #[must_use]
    pub fn all_hold(&self) -> bool {
        self.mates.iter().all(|m| m.status.holds())
    }

    /// The report of mate `id`.
    #[must_use]
    pub fn mate(&self, id: &str) -> Option<&MateReport> {
        self.mates.iter().find(|m| m.id == id)
    }

    /// The report of component `name`.
    #[must_use]
    pub fn component(&self, name: &str) -> Option<&ComponentReport> {
        self.components.iter().find(|c| c.name == name)
    }
}

impl fmt::Display for AssemblyReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "outcome: {} ({} iterations, residual {:.1e}); assembly dof: {}",
            self.outcome, self.iterations, self.residual, self.dof
        )?;
        writeln!(f, "mates:")?;
        for m in &self.mates {
            write!(f, "  {:<8} {:<14} {:<18}", m.id, m.kind, m.status.name())?;
            if let Some(v) = m.value {
                write!(f, " value {}", round(v))?;
            }
            write!(f, " error {:.1e}", m.error)?;
            if !m.message.is_empty() {
                write!(f, "  ({})", m.message)?;
            }
            writeln!(f)?;
        }
        writeln!(f, "components:")?;
        for c in &self.components {
            let t = c.pose.translation.map(round);
            write!(f, "  {} at ({}, {}, {})", c.name, t[0], t[1], t[2])?;
            match c.dof {
                _ if c.grounded => writeln!(f, ": grounded")?,
                None => writeln!(f, ": motions not computed (diagnose is off)")?,
                Some(0) => writeln!(f, ": fully placed")?,
                Some(n) => writeln!(f, ": {n} dof; {}", c.motions.join("; "))?,
            }
        }
        for c in &self.conflicts {
            writeln!(f, "conflict: {{{}}} cannot all hold", c.join(", "))?;
        }
        for r in &self.redundant {
            writeln!(f, "redundant: {{{}}}", r.join(", "))?;
        }
        Ok(())
    }
}

/// A number for people: four decimals, no negative zero.
pub(crate) fn round(x: f64) -> f64 {
    let r = (x * 1e4).round() / 1e4;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}
