//! A sketch's user constraints as Python objects, and the results of its solves and drags.

use crate::convert::ser_to_py;
use crate::errors;
use crate::sketch::{fmt_xy, shape_object, soft, PySketch};
use loci::sketch::{DragStep, ShapeId, SketchConstraintId, SketchReport, Spec};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;

/// A constraint argument: a ``SketchConstraint`` or its id.
pub struct ConstraintArg(pub(crate) u32);

impl ConstraintArg {
    pub(crate) fn id(&self) -> u32 {
        self.0
    }
}

impl<'py> FromPyObject<'py> for ConstraintArg {
    fn extract_bound(ob: &Bound<'py, PyAny>) -> PyResult<Self> {
        if let Ok(c) = ob.downcast::<SketchConstraint>() {
            return Ok(Self(c.get().id));
        }
        Ok(Self(ob.extract().map_err(|_| {
            PyTypeError::new_err("expected a SketchConstraint or its id")
        })?))
    }
}

/// A user constraint of a sketch: its ``type``, the ``shapes`` it names, its ``value``
/// (assignable, for dimensions) and what it measures now (``measure()``).
#[pyclass(module = "loci", frozen)]
pub struct SketchConstraint {
    pub(crate) sketch: Py<PySketch>,
    pub(crate) id: u32,
}

impl SketchConstraint {
    fn spec(&self, py: Python<'_>) -> PyResult<(Spec<ShapeId>, bool)> {
        self.sketch
            .borrow(py)
            .inner
            .constraint(SketchConstraintId(self.id))
            .map(|(s, r)| (s.clone(), r))
            .ok_or_else(|| errors::model(format!("sketch constraint {} was removed", self.id)))
    }
}

#[pymethods]
impl SketchConstraint {
    /// Its id in the sketch.
    #[getter]
    fn id(&self) -> u32 {
        self.id
    }

    /// Its type, as in sketch files: ``"length"``, ``"coincident"`` ...
    #[getter]
    fn r#type(&self, py: Python<'_>) -> PyResult<&'static str> {
        Ok(self.spec(py)?.0.name())
    }

    /// Whether it is a reference (driven) dimension, which only measures.
    #[getter]
    fn reference(&self, py: Python<'_>) -> PyResult<bool> {
        Ok(self.spec(py)?.1)
    }

    /// Its dimension (a distance, or an angle in degrees), or ``None``; assignable.
    #[getter]
    fn value(&self, py: Python<'_>) -> PyResult<Option<f64>> {
        Ok(self.spec(py)?.0.value())
    }

    #[setter]
    fn set_value(&self, py: Python<'_>, v: f64) -> PyResult<()> {
        self.sketch
            .borrow_mut(py)
            .inner
            .set_value(SketchConstraintId(self.id), v)
            .map_err(errors::model)
    }

    /// The shapes it names, as ``(field, shape)`` pairs.
    #[getter]
    fn shapes(&self, py: Python<'_>) -> PyResult<Vec<(String, PyObject)>> {
        let (spec, _) = self.spec(py)?;
        let mut out = Vec::new();
        for (field, s) in spec.shapes() {
            let kind = self.sketch.borrow(py).kind_of(s.entity().0)?;
            out.push((
                field.to_owned(),
                shape_object(py, &self.sketch, kind, s.entity().0)?,
            ));
        }
        Ok(out)
    }

    /// The handles of the core constraints it wrote into the sketch's system.
    #[getter]
    fn core(&self, py: Python<'_>) -> Vec<u32> {
        self.sketch
            .borrow(py)
            .inner
            .core_constraints(SketchConstraintId(self.id))
            .iter()
            .map(|c| c.0)
            .collect()
    }

    /// What it measures now: ``(value, residual)``; the residual is 0 when it holds.
    fn measure(&self, py: Python<'_>) -> PyResult<(Option<f64>, f64)> {
        let m = self
            .sketch
            .borrow(py)
            .inner
            .measure(SketchConstraintId(self.id))
            .map_err(errors::model)?;
        Ok((m.value, m.residual))
    }

    /// The constraint as a dict in the sketch file's form (shapes by handle).
    fn to_dict(&self, py: Python<'_>) -> PyResult<PyObject> {
        let (spec, _) = self.spec(py)?;
        ser_to_py(py, &spec)
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .downcast::<SketchConstraint>()
            .is_ok_and(|o| o.get().id == self.id && o.get().sketch.is(&self.sketch))
    }

    fn __hash__(&self) -> u64 {
        u64::from(self.id)
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        match self.spec(py) {
            Ok((spec, reference)) => {
                let shapes: Vec<String> = spec
                    .shapes()
                    .iter()
                    .map(|(f, s)| format!("{f}=#{}", s.entity().0))
                    .collect();
                let value = spec
                    .value()
                    .map(|v| format!(", value={v}"))
                    .unwrap_or_default();
                let r = if reference { ", reference=True" } else { "" };
                format!(
                    "SketchConstraint(#{}, {}, {}{value}{r})",
                    self.id,
                    spec.name(),
                    shapes.join(", ")
                )
            }
            Err(_) => format!("SketchConstraint(#{}, removed)", self.id),
        }
    }
}

/// The result of `Sketch.solve`.
#[pyclass(module = "loci", frozen)]
pub struct SketchResult {
    r: SketchReport,
}

impl From<SketchReport> for SketchResult {
    fn from(r: SketchReport) -> Self {
        Self { r }
    }
}

#[pymethods]
impl SketchResult {
    /// How it ended: ``"okay"``, ``"redundant_okay"``, ``"inconsistent"`` or
    /// ``"did_not_converge"``.
    #[getter]
    fn outcome(&self) -> &'static str {
        self.r.outcome.name()
    }
    /// Whether the user constraints hold.
    #[getter]
    fn ok(&self) -> bool {
        self.r.outcome.is_ok()
    }
    fn __bool__(&self) -> bool {
        self.r.outcome.is_ok()
    }
    /// Ids of the user constraints named as redundant, conflicting or unsatisfied.
    #[getter]
    fn failed(&self) -> Vec<u32> {
        self.r.failed.iter().map(|c| c.0).collect()
    }
    /// Soft constraints that held, as ``(keeps, shape handle)``.
    #[getter]
    fn kept(&self) -> Vec<(String, u32)> {
        self.r.kept.iter().copied().map(soft).collect()
    }
    /// Soft constraints dropped because they stood in the way.
    #[getter]
    fn dropped(&self) -> Vec<(String, u32)> {
        self.r.dropped.iter().copied().map(soft).collect()
    }
    /// Newton iterations of the last solve.
    #[getter]
    fn iterations(&self) -> usize {
        self.r.iterations
    }
    /// Largest residual left.
    #[getter]
    fn residual(&self) -> f64 {
        self.r.residual
    }
    fn __repr__(&self) -> String {
        format!(
            "SketchResult(outcome={:?}, failed={:?}, kept={}, dropped={}, iterations={}, residual={:.3e})",
            self.r.outcome.name(),
            self.failed(),
            self.r.kept.len(),
            self.r.dropped.len(),
            self.r.iterations,
            self.r.residual
        )
    }
}

/// The result of one drag step.
#[pyclass(module = "loci", frozen)]
pub struct DragResult {
    s: DragStep,
}

impl From<DragStep> for DragResult {
    fn from(s: DragStep) -> Self {
        Self { s }
    }
}

#[pymethods]
impl DragResult {
    /// The outcome of the last solve.
    #[getter]
    fn outcome(&self) -> &'static str {
        self.s.outcome.name()
    }
    /// Whether the whole step was taken.
    #[getter]
    fn reached(&self) -> bool {
        self.s.reached
    }
    /// Where the grip ended, ``(x, y)``.
    #[getter]
    fn at(&self) -> (f64, f64) {
        (self.s.at[0], self.s.at[1])
    }
    /// How far that is from the target.
    #[getter]
    fn miss(&self) -> f64 {
        self.s.miss
    }
    /// Pieces solved and kept.
    #[getter]
    fn pieces(&self) -> usize {
        self.s.pieces
    }
    /// Pieces undone because they failed or would have flipped something.
    #[getter]
    fn refused(&self) -> usize {
        self.s.refused
    }
    /// Pieces undone because they would have flipped a triangle, a hinge's bend, an arc or a
    /// tangent side.
    #[getter]
    fn flips_prevented(&self) -> usize {
        self.s.flips_prevented
    }
    fn __repr__(&self) -> String {
        format!(
            "DragResult(outcome={:?}, reached={}, at={}, miss={:.3e})",
            self.s.outcome.name(),
            if self.s.reached { "True" } else { "False" },
            fmt_xy(self.s.at),
            self.s.miss
        )
    }
}
