//! loci's JSON format: a problem (the model plus what to solve) and a result.
//!
//! The model part mirrors [`System`] one-to-one; see `docs/format.md` and
//! `docs/loci.schema.json`.

use crate::model::{GroupId, ParamId, System};
use crate::solve::{Config, Outcome, Report};
use crate::{ConstraintId, EntityId};
use serde::{Deserialize, Serialize};

mod error;
mod fields;
mod read;

pub use error::{locate, JsonError, Position};

/// A problem file: the model and a solve request.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Problem {
    /// Parameters, entities and constraints.
    #[serde(flatten)]
    pub system: System,
    /// What to solve; when absent, the group of the last constraint (or 1) with defaults.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub solve: Option<SolveRequest>,
}

/// Which group to solve and how.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SolveRequest {
    /// The group whose parameters are unknowns.
    pub group: GroupId,
    /// Parameters that should move as little as possible.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub dragged: Vec<ParamId>,
    /// Whether to name failed constraints (default true).
    #[serde(default = "yes")]
    pub calculate_failed: bool,
    /// Solver settings.
    #[serde(default)]
    pub options: Options,
}

fn yes() -> bool {
    true
}

/// Solver settings in a file; absent fields take [`Config`]'s defaults.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Options {
    /// See [`Config::tolerance`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tolerance: Option<f64>,
    /// See [`Config::max_iterations`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_iterations: Option<usize>,
    /// See [`Config::dragged_scale`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dragged_scale: Option<f64>,
    /// See [`Config::rank_tolerance`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rank_tolerance: Option<f64>,
    /// See [`Config::verify_conflicts_up_to`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub verify_conflicts_up_to: Option<usize>,
    /// See [`Config::nearest`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub nearest: Option<bool>,
    /// See [`Config::solvespace_angles`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub solvespace_angles: Option<bool>,
}

impl SolveRequest {
    /// The solver configuration this request asks for.
    #[must_use]
    pub fn config(&self) -> Config {
        let d = Config::default();
        let o = &self.options;
        Config::default()
            .with_tolerance(o.tolerance.unwrap_or(d.tolerance))
            .with_max_iterations(o.max_iterations.unwrap_or(d.max_iterations))
            .with_dragged_scale(o.dragged_scale.unwrap_or(d.dragged_scale))
            .with_rank_tolerance(o.rank_tolerance.unwrap_or(d.rank_tolerance))
            .with_verify_conflicts_up_to(
                o.verify_conflicts_up_to.unwrap_or(d.verify_conflicts_up_to),
            )
            .with_nearest(o.nearest.unwrap_or(d.nearest))
            .with_solvespace_angles(o.solvespace_angles.unwrap_or(d.solvespace_angles))
            .with_find_failed(self.calculate_failed)
    }
}

impl Problem {
    /// Parses a problem.
    ///
    /// References between objects are not checked here but by every solve (see
    /// [`System::validate`]); [`JsonError::from_solve`] places such an error in `text`.
    ///
    /// # Errors
    /// Malformed JSON; a field missing, of the wrong type or unknown; an unknown type name;
    /// a handle that is zero or repeated; a number too large for a double. The error names
    /// the object and field and gives the line and column of the value (or of the object,
    /// for a missing field).
    pub fn from_json(text: &str) -> Result<Self, JsonError> {
        read::problem(text)
    }

    /// The solve request, or the default one (the highest group that has constraints).
    #[must_use]
    pub fn request(&self) -> SolveRequest {
        self.solve.clone().unwrap_or_else(|| SolveRequest {
            group: self
                .system
                .constraints()
                .iter()
                .map(|c| c.group)
                .max()
                .unwrap_or(GroupId(1)),
            dragged: Vec::new(),
            calculate_failed: true,
            options: Options::default(),
        })
    }

    /// Pretty JSON.
    #[must_use]
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }
}

/// A parameter value in a result.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ParamValue {
    /// Handle.
    pub h: ParamId,
    /// Value after the solve.
    pub val: f64,
}

/// The result file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SolveResult {
    /// The group solved.
    pub group: GroupId,
    /// How it ended.
    pub outcome: Outcome,
    /// Degrees of freedom left.
    pub dof: usize,
    /// Failed constraints (see [`Report::failed`]).
    pub failed: Vec<ConstraintId>,
    /// Entities whose implicit conditions are involved.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub failed_entities: Vec<EntityId>,
    /// Newton iterations.
    pub iterations: usize,
    /// Largest residual left.
    pub residual: f64,
    /// Values of the group's parameters.
    pub params: Vec<ParamValue>,
}

impl SolveResult {
    /// The result of solving `group` of `sys` as `report` says.
    #[must_use]
    pub fn new(sys: &System, group: GroupId, report: &Report) -> Self {
        Self {
            group,
            outcome: report.outcome,
            dof: report.dof,
            failed: report.failed.clone(),
            failed_entities: report.failed_entities.clone(),
            iterations: report.iterations,
            residual: report.residual,
            params: sys
                .params()
                .iter()
                .filter(|p| p.group == group)
                .map(|p| ParamValue { h: p.h, val: p.val })
                .collect(),
        }
    }

    /// Pretty JSON.
    #[must_use]
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }
}
