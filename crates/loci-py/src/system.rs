//! `loci.System`: the SolveSpace model — parameters, entities and constraints in groups,
//! addressed by integer handles — with solves that release the GIL and NumPy bulk access to
//! parameter values.

use crate::convert::{ser_to_py, to_json};
use crate::errors;
use crate::result::{CheckResult, SolveResult};
use loci::format::json::Problem;
use loci::{Config, Constraint, ConstraintKind, Entity, Param, ParamId, System};
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::{PyKeyError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde_json::Value;

/// Solver settings given as keyword arguments; `None` keeps loci's default.
#[derive(Default, Clone, Copy)]
pub struct SolveOptions {
    pub tolerance: Option<f64>,
    pub max_iterations: Option<usize>,
    pub find_failed: Option<bool>,
    pub nearest: Option<bool>,
    pub solvespace_angles: Option<bool>,
}

impl SolveOptions {
    pub fn config(self) -> Config {
        let mut c = Config::default();
        if let Some(t) = self.tolerance {
            c = c.with_tolerance(t);
        }
        if let Some(m) = self.max_iterations {
            c = c.with_max_iterations(m);
        }
        if let Some(f) = self.find_failed {
            c = c.with_find_failed(f);
        }
        if let Some(n) = self.nearest {
            c = c.with_nearest(n);
        }
        if let Some(a) = self.solvespace_angles {
            c = c.with_solvespace_angles(a);
        }
        c
    }
}

/// The SolveSpace model: parameters (numbers), entities (points, normals, workplanes, lines,
/// circles, arcs, cubics, distances) and constraints, each in a group and addressed by an
/// integer handle. Solving a group makes its parameters the unknowns; every other group's
/// parameters are constants.
///
/// Handles are given by the caller (``handle=``) or chosen as one more than the largest in use.
#[pyclass(name = "System", module = "loci")]
#[derive(Clone, Default)]
pub struct PySystem {
    pub sys: System,
    next: [u32; 3],
}

impl PySystem {
    /// Wraps a system read from a file.
    pub fn from_system(sys: System) -> Self {
        let max = |it: &mut dyn Iterator<Item = u32>| it.max().unwrap_or(0) + 1;
        let next = [
            max(&mut sys.params().iter().map(|p| p.h.0)),
            max(&mut sys.entities().iter().map(|e| e.h.0)),
            max(&mut sys.constraints().iter().map(|c| c.h.0)),
        ];
        Self { sys, next }
    }

    fn handle(&mut self, kind: usize, given: Option<u32>) -> u32 {
        let next = &mut self.next[kind];
        let h = given.unwrap_or((*next).max(1));
        *next = (*next).max(h.saturating_add(1));
        h
    }

    /// Adds a parameter with a fresh handle.
    pub fn push_param(&mut self, value: f64, group: u32) -> PyResult<u32> {
        let h = self.handle(0, None);
        self.sys
            .add_param(Param::new(h, group, value))
            .map_err(errors::model)?;
        Ok(h)
    }

    /// Adds an entity, giving it a fresh handle when its own is 0.
    pub fn push_entity(&mut self, mut e: Entity) -> PyResult<u32> {
        let h = self.handle(1, (e.h.0 != 0).then_some(e.h.0));
        e.h = h.into();
        self.sys.add_entity(e).map_err(errors::model)?;
        Ok(h)
    }

    /// Adds a constraint, giving it a fresh handle when its own is 0.
    pub fn push_constraint(&mut self, mut c: Constraint) -> PyResult<u32> {
        let h = self.handle(2, (c.h.0 != 0).then_some(c.h.0));
        c.h = h.into();
        self.sys.add_constraint(c).map_err(errors::model)?;
        Ok(h)
    }

    /// Solves with the GIL released.
    pub fn solve_in(
        &mut self,
        py: Python<'_>,
        group: u32,
        dragged: &[u32],
        opts: SolveOptions,
    ) -> PyResult<SolveResult> {
        let dragged: Vec<ParamId> = dragged.iter().map(|&h| ParamId(h)).collect();
        let cfg = opts.config();
        let sys = &mut self.sys;
        let report = py
            .allow_threads(|| loci::solve(sys, group.into(), &dragged, &cfg))
            .map_err(errors::solve)?;
        Ok(SolveResult::new(group, report))
    }
}

/// The kind of a constraint given by name (`"pt_pt_distance"`) or SolveSpace code (100001).
fn constraint_kind(kind: &Bound<'_, PyAny>) -> PyResult<ConstraintKind> {
    if let Ok(code) = kind.extract::<u32>() {
        return ConstraintKind::from_slvs_code(code).ok_or_else(|| {
            errors::model(format!(
                "{code} is not a constraint type code (100000..=100037)"
            ))
        });
    }
    let name: String = kind.extract()?;
    ConstraintKind::from_name(&name.to_ascii_lowercase()).ok_or_else(|| {
        errors::model(format!(
            "{name:?} is not a constraint type; expected a name such as \"pt_pt_distance\""
        ))
    })
}

#[pymethods]
impl PySystem {
    #[new]
    fn new() -> Self {
        Self::default()
    }

    /// Reads a system from loci's JSON text (the ``solve`` part, if any, is ignored).
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Self> {
        let p = Problem::from_json(text).map_err(errors::file)?;
        Ok(Self::from_system(p.system))
    }

    /// The system as loci's JSON text.
    fn to_json(&self) -> String {
        Problem {
            system: self.sys.clone(),
            solve: None,
        }
        .to_json()
    }

    /// Writes the system to ``path`` as loci's JSON.
    fn save(&self, path: std::path::PathBuf) -> PyResult<()> {
        std::fs::write(&path, self.to_json())?;
        Ok(())
    }

    fn __repr__(&self) -> String {
        let groups: Vec<String> = self.sys.groups().iter().map(|g| g.0.to_string()).collect();
        format!(
            "System(params={}, entities={}, constraints={}, groups=[{}])",
            self.sys.params().len(),
            self.sys.entities().len(),
            self.sys.constraints().len(),
            groups.join(", ")
        )
    }

    fn __copy__(&self) -> Self {
        self.clone()
    }

    fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
        self.clone()
    }

    /// A parameter: a number, an unknown when its group is solved. Returns its handle.
    #[pyo3(signature = (value, *, group = 1, handle = None))]
    fn add_param(&mut self, value: f64, group: u32, handle: Option<u32>) -> PyResult<u32> {
        let h = self.handle(0, handle);
        self.sys
            .add_param(Param::new(h, group, value))
            .map_err(errors::model)?;
        Ok(h)
    }

    /// An entity of any type, with the fields of loci's JSON format (``params=[...]``,
    /// ``points=[...]``, ``origin=``, ``normal=``, ``center=``, ``radius=``, ``start=``,
    /// ``end=``, ``param=`` ...). Returns its handle.
    #[pyo3(signature = (r#type, *, group = 1, workplane = None, handle = None, **fields))]
    fn add_entity(
        &mut self,
        r#type: &str,
        group: u32,
        workplane: Option<u32>,
        handle: Option<u32>,
        fields: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<u32> {
        let mut m = match fields {
            Some(f) => match to_json(f.as_any())? {
                Value::Object(m) => m,
                _ => serde_json::Map::new(),
            },
            None => serde_json::Map::new(),
        };
        m.insert("type".into(), r#type.into());
        m.insert("h".into(), handle.unwrap_or(0).into());
        m.insert("group".into(), group.into());
        if let Some(w) = workplane {
            m.insert("workplane".into(), w.into());
        }
        let e: Entity = serde_json::from_value(Value::Object(m))
            .map_err(|e| errors::model(format!("entity of type {type:?}: {e}", type = r#type)))?;
        self.push_entity(e)
    }

    /// A point in a workplane at (u, v), with two new parameters. Returns its handle.
    #[pyo3(signature = (u, v, *, workplane, group = 1, handle = None))]
    fn add_point_2d(
        &mut self,
        u: f64,
        v: f64,
        workplane: u32,
        group: u32,
        handle: Option<u32>,
    ) -> PyResult<u32> {
        let a = self.push_param(u, group)?;
        let b = self.push_param(v, group)?;
        self.push_entity(Entity::point_2d(
            handle.unwrap_or(0),
            group,
            workplane,
            [a, b],
        ))
    }

    /// A point in 3D at (x, y, z), with three new parameters. Returns its handle.
    #[pyo3(signature = (x, y, z, *, group = 1, handle = None))]
    fn add_point_3d(
        &mut self,
        x: f64,
        y: f64,
        z: f64,
        group: u32,
        handle: Option<u32>,
    ) -> PyResult<u32> {
        let p = [
            self.push_param(x, group)?,
            self.push_param(y, group)?,
            self.push_param(z, group)?,
        ];
        self.push_entity(Entity::point_3d(handle.unwrap_or(0), group, p))
    }

    /// An orientation in 3D as the unit quaternion (w, x, y, z). Returns its handle.
    #[pyo3(signature = (w, x, y, z, *, group = 1, handle = None))]
    fn add_normal_3d(
        &mut self,
        w: f64,
        x: f64,
        y: f64,
        z: f64,
        group: u32,
        handle: Option<u32>,
    ) -> PyResult<u32> {
        let mut p = [0; 4];
        for (slot, v) in p.iter_mut().zip([w, x, y, z]) {
            *slot = self.push_param(v, group)?;
        }
        self.push_entity(Entity::normal_3d(handle.unwrap_or(0), group, p))
    }

    /// The normal of a workplane. Returns its handle.
    #[pyo3(signature = (*, workplane, group = 1, handle = None))]
    fn add_normal_2d(&mut self, workplane: u32, group: u32, handle: Option<u32>) -> PyResult<u32> {
        self.push_entity(Entity::normal_2d(handle.unwrap_or(0), group, workplane))
    }

    /// A workplane from a 3D point and a 3D normal. Returns its handle.
    #[pyo3(signature = (origin, normal, *, group = 1, handle = None))]
    fn add_workplane(
        &mut self,
        origin: u32,
        normal: u32,
        group: u32,
        handle: Option<u32>,
    ) -> PyResult<u32> {
        self.push_entity(Entity::workplane(
            handle.unwrap_or(0),
            group,
            origin,
            normal,
        ))
    }

    /// The xy plane: its origin at (0, 0, 0), its normal the identity quaternion, all in
    /// ``group`` (usually a group that is not solved). Returns the workplane's handle.
    #[pyo3(signature = (*, group = 1))]
    fn add_xy_workplane(&mut self, group: u32) -> PyResult<u32> {
        let o = self.add_point_3d(0.0, 0.0, 0.0, group, None)?;
        let n = self.add_normal_3d(1.0, 0.0, 0.0, 0.0, group, None)?;
        self.add_workplane(o, n, group, None)
    }

    /// A distance entity (a circle's radius), with a new parameter. Returns its handle.
    #[pyo3(signature = (value, *, workplane = None, group = 1, handle = None))]
    fn add_distance(
        &mut self,
        value: f64,
        workplane: Option<u32>,
        group: u32,
        handle: Option<u32>,
    ) -> PyResult<u32> {
        let p = self.push_param(value, group)?;
        self.push_entity(Entity::distance(handle.unwrap_or(0), group, workplane, p))
    }

    /// A line segment between two points. Returns its handle.
    #[pyo3(signature = (a, b, *, workplane = None, group = 1, handle = None))]
    fn add_line(
        &mut self,
        a: u32,
        b: u32,
        workplane: Option<u32>,
        group: u32,
        handle: Option<u32>,
    ) -> PyResult<u32> {
        self.push_entity(Entity::line(handle.unwrap_or(0), group, workplane, a, b))
    }

    /// A circle: centre point, normal and a distance entity for its radius. Returns its handle.
    #[pyo3(signature = (center, normal, radius, *, workplane = None, group = 1, handle = None))]
    fn add_circle(
        &mut self,
        center: u32,
        normal: u32,
        radius: u32,
        workplane: Option<u32>,
        group: u32,
        handle: Option<u32>,
    ) -> PyResult<u32> {
        self.push_entity(Entity::circle(
            handle.unwrap_or(0),
            group,
            workplane,
            center,
            normal,
            radius,
        ))
    }

    /// An arc, counter-clockwise from ``start`` to ``end`` about ``center``. Returns its handle.
    #[pyo3(signature = (normal, center, start, end, *, workplane, group = 1, handle = None))]
    #[allow(clippy::too_many_arguments)]
    fn add_arc(
        &mut self,
        normal: u32,
        center: u32,
        start: u32,
        end: u32,
        workplane: u32,
        group: u32,
        handle: Option<u32>,
    ) -> PyResult<u32> {
        self.push_entity(Entity::arc(
            handle.unwrap_or(0),
            group,
            workplane,
            normal,
            center,
            start,
            end,
        ))
    }

    /// A cubic Bezier segment through four control points. Returns its handle.
    #[pyo3(signature = (p0, p1, p2, p3, *, workplane = None, group = 1, handle = None))]
    #[allow(clippy::too_many_arguments)]
    fn add_cubic(
        &mut self,
        p0: u32,
        p1: u32,
        p2: u32,
        p3: u32,
        workplane: Option<u32>,
        group: u32,
        handle: Option<u32>,
    ) -> PyResult<u32> {
        self.push_entity(Entity::cubic(
            handle.unwrap_or(0),
            group,
            workplane,
            [p0, p1, p2, p3],
        ))
    }

    /// A constraint of any type, by name (``"pt_pt_distance"``) or SolveSpace code (100001),
    /// with SolveSpace's fields. Returns its handle.
    #[pyo3(signature = (r#type, *, group = 1, workplane = None, value = 0.0, pt_a = None,
        pt_b = None, entity_a = None, entity_b = None, entity_c = None, entity_d = None,
        other = false, other2 = false, reference = false, signed = false, handle = None))]
    #[allow(clippy::too_many_arguments)]
    fn add_constraint(
        &mut self,
        r#type: &Bound<'_, PyAny>,
        group: u32,
        workplane: Option<u32>,
        value: f64,
        pt_a: Option<u32>,
        pt_b: Option<u32>,
        entity_a: Option<u32>,
        entity_b: Option<u32>,
        entity_c: Option<u32>,
        entity_d: Option<u32>,
        other: bool,
        other2: bool,
        reference: bool,
        signed: bool,
        handle: Option<u32>,
    ) -> PyResult<u32> {
        let kind = constraint_kind(r#type)?;
        let nz = |h: Option<u32>| h.filter(|&h| h != 0).map(Into::into);
        let mut c = Constraint::new(handle.unwrap_or(0), group, kind)
            .in_workplane(workplane.filter(|&w| w != 0))
            .with_val(value)
            .with_flags(other, other2);
        c.pt_a = nz(pt_a);
        c.pt_b = nz(pt_b);
        c.entity_a = nz(entity_a);
        c.entity_b = nz(entity_b);
        c.entity_c = nz(entity_c);
        c.entity_d = nz(entity_d);
        if reference {
            c = c.as_reference();
        }
        c.signed = signed;
        self.push_constraint(c)
    }

    /// Removes a constraint; returns whether it was there.
    fn remove_constraint(&mut self, handle: u32) -> bool {
        self.sys.remove_constraint(handle.into()).is_some()
    }

    /// Removes an entity that nothing refers to; returns whether it was there.
    fn remove_entity(&mut self, handle: u32) -> PyResult<bool> {
        Ok(self
            .sys
            .remove_entity(handle.into())
            .map_err(errors::model)?
            .is_some())
    }

    /// Removes a parameter that no entity uses; returns whether it was there.
    fn remove_param(&mut self, handle: u32) -> PyResult<bool> {
        Ok(self
            .sys
            .remove_param(handle.into())
            .map_err(errors::model)?
            .is_some())
    }

    /// The value of a parameter.
    fn value(&self, handle: u32) -> PyResult<f64> {
        self.sys
            .value(handle.into())
            .ok_or_else(|| PyKeyError::new_err(format!("param {handle} does not exist")))
    }

    /// Sets the value of a parameter.
    fn set_value(&mut self, handle: u32, value: f64) -> PyResult<()> {
        if self.sys.set_value(handle.into(), value) {
            Ok(())
        } else {
            Err(PyKeyError::new_err(format!(
                "param {handle} does not exist"
            )))
        }
    }

    /// Every parameter's value, in the order of ``param_handles``, as a NumPy array (a copy).
    /// Assigning an array of the same length sets them all.
    #[getter(values)]
    fn values_array<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_iter(py, self.sys.params().iter().map(|p| p.val))
    }

    #[setter(values)]
    fn set_all_values(&mut self, values: PyReadonlyArray1<'_, f64>) -> PyResult<()> {
        let v = values.as_array();
        let n = self.sys.params().len();
        if v.len() != n {
            return Err(PyValueError::new_err(format!(
                "{} values given for {n} parameters",
                v.len()
            )));
        }
        for (slot, x) in self.sys.values_mut().zip(v.iter()) {
            *slot = *x;
        }
        Ok(())
    }

    /// Every parameter's handle, as a NumPy array of uint32.
    #[getter]
    fn param_handles<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<u32>> {
        PyArray1::from_iter(py, self.sys.params().iter().map(|p| p.h.0))
    }

    /// The values of the parameters ``handles`` (any sequence or array of ints), as an array.
    fn get_values<'py>(
        &self,
        py: Python<'py>,
        handles: Vec<u32>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let params = self.sys.params();
        let mut out = Vec::with_capacity(handles.len());
        for h in handles {
            let i = self
                .sys
                .param_index(h.into())
                .ok_or_else(|| PyKeyError::new_err(format!("param {h} does not exist")))?;
            out.push(params[i].val);
        }
        Ok(PyArray1::from_vec(py, out))
    }

    /// Sets the parameters ``handles`` to ``values`` (two sequences or arrays of one length).
    fn set_values(&mut self, handles: Vec<u32>, values: PyReadonlyArray1<'_, f64>) -> PyResult<()> {
        let v = values.as_array();
        if v.len() != handles.len() {
            return Err(PyValueError::new_err(format!(
                "{} values given for {} handles",
                v.len(),
                handles.len()
            )));
        }
        if let Some(h) = handles
            .iter()
            .find(|&&h| self.sys.param_index(h.into()).is_none())
        {
            return Err(PyKeyError::new_err(format!("param {h} does not exist")));
        }
        for (h, x) in handles.iter().zip(v.iter()) {
            self.sys.set_value((*h).into(), *x);
        }
        Ok(())
    }

    /// The groups that have parameters, entities or constraints, in increasing order.
    #[getter]
    fn groups(&self) -> Vec<u32> {
        self.sys.groups().iter().map(|g| g.0).collect()
    }

    /// The parameters as dicts ``{"h", "group", "val"}``.
    #[getter]
    fn params(&self, py: Python<'_>) -> PyResult<PyObject> {
        ser_to_py(py, &self.sys.params())
    }

    /// The entities as dicts, in loci's JSON form.
    #[getter]
    fn entities(&self, py: Python<'_>) -> PyResult<PyObject> {
        ser_to_py(py, &self.sys.entities())
    }

    /// The constraints as dicts, in loci's JSON form.
    #[getter]
    fn constraints(&self, py: Python<'_>) -> PyResult<PyObject> {
        ser_to_py(py, &self.sys.constraints())
    }

    /// One entity as a dict.
    fn entity(&self, py: Python<'_>, handle: u32) -> PyResult<PyObject> {
        let e = self
            .sys
            .entity(handle.into())
            .ok_or_else(|| PyKeyError::new_err(format!("entity {handle} does not exist")))?;
        ser_to_py(py, e)
    }

    /// One constraint as a dict.
    fn constraint(&self, py: Python<'_>, handle: u32) -> PyResult<PyObject> {
        let c = self
            .sys
            .constraint(handle.into())
            .ok_or_else(|| PyKeyError::new_err(format!("constraint {handle} does not exist")))?;
        ser_to_py(py, c)
    }

    /// Solves ``group``: its parameters are the unknowns, ``dragged`` parameters move as little
    /// as possible. Values are written back when the result is ok; an inconsistent system is a
    /// result naming the failed constraints. ``nearest=False`` ends where Newton's steps do, as
    /// SolveSpace does; ``solvespace_angles=True`` writes 2D angles as SolveSpace does, so that
    /// with it an under-constrained sketch ends where SolveSpace's would. The GIL is released
    /// while it runs.
    ///
    /// Raises ``ModelError`` for an invalid model, ``SolveError`` when it cannot start.
    #[pyo3(signature = (group, dragged = Vec::new(), *, find_failed = true, tolerance = None,
        max_iterations = None, nearest = None, solvespace_angles = None))]
    #[allow(clippy::too_many_arguments)] // Python's keyword arguments
    fn solve(
        &mut self,
        py: Python<'_>,
        group: u32,
        dragged: Vec<u32>,
        find_failed: bool,
        tolerance: Option<f64>,
        max_iterations: Option<usize>,
        nearest: Option<bool>,
        solvespace_angles: Option<bool>,
    ) -> PyResult<SolveResult> {
        let opts = SolveOptions {
            tolerance,
            max_iterations,
            find_failed: Some(find_failed),
            nearest,
            solvespace_angles,
        };
        self.solve_in(py, group, &dragged, opts)
    }

    /// Diagnoses ``group`` without changing it: degrees of freedom, rank, minimal conflicting
    /// sets, redundant sets and the blocks over-constrained by counting. Releases the GIL.
    fn check(&self, py: Python<'_>, group: u32) -> PyResult<CheckResult> {
        let sys = &self.sys;
        let d = py
            .allow_threads(|| loci::diagnose(sys, group.into(), &Config::default()))
            .map_err(errors::solve)?;
        Ok(CheckResult::new(d))
    }
}
