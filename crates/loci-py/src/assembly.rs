//! `loci.Assembly`: rigid components placed by poses, related by mates and joints, solved
//! all at once (with each mate's status and each component's remaining motions) or in the
//! stepped mode that reports every pass for animation.

use crate::convert::{ser_to_py, to_json};
use crate::errors;
use loci::assembly::{
    Assembly, AssemblyReport, Component, Mate, MateKind, Pose, Reference, Selection,
};
use pyo3::exceptions::PyKeyError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde_json::{json, Value};

/// A selection: ``"component.reference"``, ``("component", "reference")`` or
/// ``"world.reference"`` for a world reference.
#[derive(FromPyObject)]
pub enum SelectionArg {
    /// ``"component.reference"``.
    Dotted(String),
    /// ``(component, reference)``.
    Pair((String, String)),
}

impl SelectionArg {
    fn selection(self) -> PyResult<Selection> {
        let (c, r) = match self {
            SelectionArg::Pair(p) => p,
            SelectionArg::Dotted(s) => match s.split_once('.') {
                Some((c, r)) => (c.to_owned(), r.to_owned()),
                None => {
                    return Err(errors::model(format!(
                        "selection {s:?}: expected \"component.reference\" or \"world.reference\""
                    )))
                }
            },
        };
        Ok(if c == "world" {
            Selection::world(&r)
        } else {
            Selection::on(&c, &r)
        })
    }
}

fn reference(name: &str, v: &Bound<'_, PyAny>) -> PyResult<Reference> {
    serde_json::from_value(to_json(v)?)
        .map_err(|e| errors::model(format!("reference {name:?}: {e}")))
}

/// An assembly of rigid components. References are dicts in the assembly file's form, e.g.
/// ``{"type": "axis", "point": [0, 0, 0], "direction": [0, 0, 1]}``; mates name them as
/// ``"component.reference"``.
#[pyclass(name = "Assembly", module = "loci")]
#[derive(Clone, Default)]
pub struct PyAssembly {
    pub inner: Assembly,
}

#[pymethods]
impl PyAssembly {
    #[new]
    fn new() -> Self {
        Self::default()
    }

    /// Reads an assembly file's JSON text.
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Self> {
        Ok(Self {
            inner: loci::format::assembly::read(text).map_err(errors::file)?,
        })
    }

    /// The assembly, with its current poses, as an assembly file's JSON text.
    fn to_json(&self) -> String {
        loci::format::assembly::write(&self.inner)
    }

    /// Writes the assembly file to ``path``.
    fn save(&self, path: std::path::PathBuf) -> PyResult<()> {
        std::fs::write(&path, self.to_json())?;
        Ok(())
    }

    fn __repr__(&self) -> String {
        format!(
            "Assembly(components={}, mates={})",
            self.inner.components.len(),
            self.inner.mates.len()
        )
    }

    /// Adds a component at ``position`` turned by the unit quaternion ``rotation``
    /// ``(w, x, y, z)``, with named ``references``. Returns its name.
    #[pyo3(signature = (name, *, position = [0.0, 0.0, 0.0], rotation = [1.0, 0.0, 0.0, 0.0],
        grounded = false, references = None))]
    fn add_component(
        &mut self,
        name: String,
        position: [f64; 3],
        rotation: [f64; 4],
        grounded: bool,
        references: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<String> {
        let mut c = Component::new(name.clone(), Pose::new(position, rotation));
        if grounded {
            c = c.grounded();
        }
        if let Some(refs) = references {
            for (k, v) in refs.iter() {
                let n: String = k.extract()?;
                let r = reference(&n, &v)?;
                c = c.with(n, r);
            }
        }
        self.inner.add_component(c).map_err(errors::model)?;
        Ok(name)
    }

    /// Adds a reference fixed in the world, selected as ``"world.<name>"``.
    fn add_world_reference(&mut self, name: &str, reference_: &Bound<'_, PyAny>) -> PyResult<()> {
        let r = reference(name, reference_)?;
        self.inner.add_world_reference(name, r);
        Ok(())
    }

    /// Adds a mate or joint of ``type`` (``"coincident"``, ``"distance"``, ``"angle"``,
    /// ``"revolute"``, ``"slider"`` ...) between selections ``a`` and ``b``. ``value`` is the
    /// distance of a distance mate or the degrees of an angle mate. Returns the mate's id.
    #[pyo3(signature = (r#type, a, b, *, value = None, flip = false, limits = None, id = None))]
    #[allow(clippy::too_many_arguments)]
    fn add_mate(
        &mut self,
        r#type: &str,
        a: SelectionArg,
        b: SelectionArg,
        value: Option<f64>,
        flip: bool,
        limits: Option<(f64, f64)>,
        id: Option<&str>,
    ) -> PyResult<String> {
        let kind_json = match (r#type, value) {
            ("distance", Some(v)) => json!({"type": "distance", "value": v}),
            ("angle", Some(v)) => json!({"type": "angle", "degrees": v}),
            ("distance" | "angle", None) => {
                return Err(errors::model(format!("a {} mate needs a value", r#type)))
            }
            (t, Some(_)) => return Err(errors::model(format!("a {t} mate takes no value"))),
            (t, None) => json!({ "type": t }),
        };
        let kind: MateKind = serde_json::from_value(kind_json)
            .map_err(|e| errors::model(format!("mate type {:?}: {e}", r#type)))?;
        let mut m = Mate::new(kind, a.selection()?, b.selection()?).flipped(flip);
        if let Some((lo, hi)) = limits {
            m = m.with_limits(lo, hi);
        }
        if let Some(id) = id {
            m = m.with_id(id);
        }
        self.inner.add_mate(m).map_err(errors::model)
    }

    /// The component names, in order.
    #[getter]
    fn components(&self) -> Vec<String> {
        self.inner
            .components
            .iter()
            .map(|c| c.name.clone())
            .collect()
    }

    /// The mates as dicts in the assembly file's form.
    #[getter]
    fn mates(&self, py: Python<'_>) -> PyResult<PyObject> {
        ser_to_py(py, &self.inner.mates)
    }

    /// A component's pose: ``(translation (x, y, z), rotation (w, x, y, z))``.
    fn pose(&self, name: &str) -> PyResult<([f64; 3], [f64; 4])> {
        let c = self
            .inner
            .component(name)
            .ok_or_else(|| PyKeyError::new_err(format!("no component is named {name:?}")))?;
        Ok((c.pose.translation, c.pose.rotation))
    }

    /// Where a point given in a component's frame is in the world.
    fn to_world(&self, name: &str, point: [f64; 3]) -> PyResult<[f64; 3]> {
        let c = self
            .inner
            .component(name)
            .ok_or_else(|| PyKeyError::new_err(format!("no component is named {name:?}")))?;
        Ok(c.pose.point(point))
    }

    /// Solves every mate at once; poses are updated. Releases the GIL.
    fn solve(&mut self, py: Python<'_>) -> PyResult<AssemblyResult> {
        let inner = &mut self.inner;
        let r = py.allow_threads(|| inner.solve()).map_err(errors::model)?;
        Ok(AssemblyResult { r })
    }

    /// The stepped mode: one mate at a time, capped rotations, for animation. Returns
    /// ``(converged, iterations)`` where each iteration is a dict with ``index``, ``poses``
    /// (one per component) and ``errors`` (one per mate). Releases the GIL.
    fn solve_stepped(&mut self, py: Python<'_>) -> PyResult<(bool, PyObject)> {
        let inner = &mut self.inner;
        let run = py
            .allow_threads(|| inner.solve_stepped())
            .map_err(errors::model)?;
        Ok((run.converged, ser_to_py(py, &run.iterations)?))
    }

    /// The angle an angle mate measures now, in degrees (signed about the held axis), or
    /// ``None`` when ``id`` is not an angle mate.
    fn measure_angle(&mut self, id: &str) -> Option<f64> {
        self.inner.measure_angle(id).map(|a| a.signed_deg)
    }

    /// The solver options as a dict (see the assembly file format); assign a dict to change
    /// some of them.
    #[getter]
    fn options(&self, py: Python<'_>) -> PyResult<PyObject> {
        ser_to_py(py, &self.inner.options)
    }

    #[setter]
    fn set_options(&mut self, v: &Bound<'_, PyDict>) -> PyResult<()> {
        let mut cur = serde_json::to_value(&self.inner.options).map_err(errors::model)?;
        if let (Value::Object(m), Value::Object(new)) = (&mut cur, to_json(v.as_any())?) {
            m.extend(new);
        }
        self.inner.options =
            serde_json::from_value(cur).map_err(|e| errors::model(format!("options: {e}")))?;
        Ok(())
    }
}

/// The result of `Assembly.solve`: the outcome, degrees of freedom, each mate's status and
/// each component's pose and remaining motions.
#[pyclass(module = "loci", frozen)]
pub struct AssemblyResult {
    r: AssemblyReport,
}

#[pymethods]
impl AssemblyResult {
    /// How the solve ended.
    #[getter]
    fn outcome(&self) -> &'static str {
        self.r.outcome.name()
    }
    /// Whether every mate holds.
    #[getter]
    fn ok(&self) -> bool {
        self.r.all_hold()
    }
    fn __bool__(&self) -> bool {
        self.r.all_hold()
    }
    /// Degrees of freedom left.
    #[getter]
    fn dof(&self) -> usize {
        self.r.dof
    }
    /// Newton iterations.
    #[getter]
    fn iterations(&self) -> usize {
        self.r.iterations
    }
    /// Largest residual left.
    #[getter]
    fn residual(&self) -> f64 {
        self.r.residual
    }
    /// Each mate's report as a dict: ``id``, ``kind``, ``status``, ``value``, ``error`` ...
    #[getter]
    fn mates(&self, py: Python<'_>) -> PyResult<PyObject> {
        ser_to_py(py, &self.r.mates)
    }
    /// Each component's report as a dict: ``name``, ``grounded``, ``pose``, ``dof`` (``None``
    /// when its motions were not computed: ``"diagnose": False`` in ``options``), ``motions``.
    #[getter]
    fn components(&self, py: Python<'_>) -> PyResult<PyObject> {
        ser_to_py(py, &self.r.components)
    }
    /// Minimal sets of mates that cannot hold together, by id.
    #[getter]
    fn conflicts(&self) -> Vec<Vec<String>> {
        self.r.conflicts.clone()
    }
    /// Sets of mates that hold but are not all needed, by id.
    #[getter]
    fn redundant(&self) -> Vec<Vec<String>> {
        self.r.redundant.clone()
    }
    /// One mate's status (``"satisfied"``, ``"conflicting"`` ...).
    fn status(&self, id: &str) -> PyResult<&'static str> {
        self.r
            .mate(id)
            .map(|m| m.status.name())
            .ok_or_else(|| PyKeyError::new_err(format!("no mate has id {id:?}")))
    }
    /// The whole report as plain dicts and lists.
    fn to_dict(&self, py: Python<'_>) -> PyResult<PyObject> {
        ser_to_py(py, &self.r)
    }
    fn __repr__(&self) -> String {
        let st: Vec<String> = self
            .r
            .mates
            .iter()
            .map(|m| format!("{}: {}", m.id, m.status.name()))
            .collect();
        format!(
            "AssemblyResult(outcome={:?}, dof={}, mates={{{}}})",
            self.r.outcome.name(),
            self.r.dof,
            st.join(", ")
        )
    }
}
