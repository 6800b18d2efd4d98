//! Result objects of `System.solve` and `System.check`, with properties and reprs.

use crate::convert::ser_to_py;
use loci::{Diagnosis, Member, Outcome, Report};
use pyo3::prelude::*;

/// The result of `System.solve`: how it ended, the degrees of freedom left, the constraints
/// named as failed (redundant, conflicting or unsatisfied) and the work done.
#[pyclass(module = "loci", frozen)]
#[derive(Clone)]
pub struct SolveResult {
    /// The group solved.
    #[pyo3(get)]
    pub group: u32,
    pub outcome: Outcome,
    /// Degrees of freedom left.
    #[pyo3(get)]
    pub dof: usize,
    /// Handles of the constraints named as failed.
    #[pyo3(get)]
    pub failed: Vec<u32>,
    /// Handles of entities whose implicit conditions failed.
    #[pyo3(get)]
    pub failed_entities: Vec<u32>,
    /// Newton iterations.
    #[pyo3(get)]
    pub iterations: usize,
    /// Largest residual left.
    #[pyo3(get)]
    pub residual: f64,
    /// Unknowns solved for.
    #[pyo3(get)]
    pub unknowns: usize,
    /// Equations solved.
    #[pyo3(get)]
    pub equations: usize,
}

impl SolveResult {
    pub fn new(group: u32, r: Report) -> Self {
        Self {
            group,
            outcome: r.outcome,
            dof: r.dof,
            failed: r.failed.iter().map(|c| c.0).collect(),
            failed_entities: r.failed_entities.iter().map(|e| e.0).collect(),
            iterations: r.iterations,
            residual: r.residual,
            unknowns: r.unknowns,
            equations: r.equations,
        }
    }
}

#[pymethods]
impl SolveResult {
    /// ``"okay"``, ``"redundant_okay"``, ``"inconsistent"``, ``"did_not_converge"`` or
    /// ``"too_many_unknowns"``.
    #[getter]
    fn outcome(&self) -> &'static str {
        self.outcome.name()
    }

    /// Whether the constraints hold (possibly with redundant ones).
    #[getter]
    fn ok(&self) -> bool {
        self.outcome.is_ok()
    }

    fn __bool__(&self) -> bool {
        self.outcome.is_ok()
    }

    fn __repr__(&self) -> String {
        format!(
            "SolveResult(group={}, outcome={:?}, dof={}, failed={:?}, iterations={}, residual={:.3e})",
            self.group,
            self.outcome.name(),
            self.dof,
            self.failed,
            self.iterations,
            self.residual
        )
    }
}

/// The result of `System.check`: a diagnosis of a group without changing it.
#[pyclass(module = "loci", frozen)]
pub struct CheckResult {
    d: Diagnosis,
}

impl CheckResult {
    pub fn new(d: Diagnosis) -> Self {
        Self { d }
    }
}

fn constraints_of(members: &[Member]) -> Vec<u32> {
    members
        .iter()
        .filter_map(|m| match m {
            Member::Constraint(c) => Some(c.0),
            Member::Entity(_) => None,
        })
        .collect()
}

#[pymethods]
impl CheckResult {
    /// The group diagnosed.
    #[getter]
    fn group(&self) -> u32 {
        self.d.group.0
    }

    /// How a solve ends (see `SolveResult.outcome`).
    #[getter]
    fn outcome(&self) -> &'static str {
        self.d.outcome.name()
    }

    /// Whether the constraints can hold.
    #[getter]
    fn ok(&self) -> bool {
        self.d.outcome.is_ok()
    }

    /// Degrees of freedom.
    #[getter]
    fn dof(&self) -> usize {
        self.d.dof
    }

    /// Rank of the equations where the solve ended.
    #[getter]
    fn rank(&self) -> usize {
        self.d.rank
    }

    /// Unknowns.
    #[getter]
    fn unknowns(&self) -> usize {
        self.d.unknowns
    }

    /// Equations.
    #[getter]
    fn equations(&self) -> usize {
        self.d.equations
    }

    /// Minimal sets of constraints that cannot hold together (constraint handles), smallest
    /// first.
    #[getter]
    fn conflicting(&self) -> Vec<Vec<u32>> {
        self.d
            .conflicting
            .iter()
            .map(|s| constraints_of(&s.members))
            .collect()
    }

    /// Sets of constraints that hold but are not all needed (constraint handles).
    #[getter]
    fn redundant(&self) -> Vec<Vec<u32>> {
        self.d
            .redundant
            .iter()
            .map(|s| constraints_of(&s.members))
            .collect()
    }

    /// The whole diagnosis as plain dicts and lists (the form ``loci check --json`` prints).
    fn to_dict(&self, py: Python<'_>) -> PyResult<PyObject> {
        ser_to_py(py, &self.d)
    }

    fn __repr__(&self) -> String {
        format!(
            "CheckResult(group={}, outcome={:?}, dof={}, rank={}, conflicting={:?}, redundant={:?})",
            self.d.group.0,
            self.d.outcome.name(),
            self.d.dof,
            self.d.rank,
            self.conflicting(),
            self.redundant()
        )
    }
}
