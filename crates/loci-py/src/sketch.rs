//! `loci.Sketch`: the 2D sketcher — shapes as objects whose coordinates read live from the
//! sketch, user constraints as methods, soft constraints kept by `solve`, and dragging.

use crate::convert::{ser_to_py, to_json};
use crate::errors;
use crate::result::CheckResult;
use crate::system::PySystem;
use loci::format::sketch::{LoadedSketch, SketchFile};
use loci::sketch::{
    ArcId, CircleId, CubicId, DragStep, LineId, PointId, ShapeId, ShapeKind, Sketch,
    SketchConstraintId, SketchReport, Soft, Spec,
};
use numpy::{PyArray2, PyArrayMethods, PyReadonlyArray2};
use pyo3::exceptions::{PyKeyError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// A typed sketch handle from its entity handle. The handles are transparent numbers in
/// loci's serde form; whether the shape exists and has the kind is checked by every use.
fn typed<T: serde::de::DeserializeOwned>(h: u32) -> T {
    serde_json::from_value(Value::from(h)).expect("a handle deserialises from its number")
}

/// A 2D sketch: shapes (points, lines, circles, arcs, cubics) and user constraints, solved
/// with soft constraints that keep lengths and radii the user did not fix.
///
/// Shapes are returned as ``Point``, ``Line``, ``Circle``, ``Arc`` and ``Cubic`` objects
/// whose coordinates are read from the sketch when asked; constraints as
/// ``SketchConstraint`` objects. Iterating a sketch yields its shapes.
#[pyclass(name = "Sketch", module = "loci")]
pub struct PySketch {
    pub inner: Sketch,
    /// Names of shapes and constraints read from a sketch file.
    names: BTreeMap<String, ShapeId>,
    constraint_names: BTreeMap<String, SketchConstraintId>,
}

impl PySketch {
    pub fn from_loaded(l: LoadedSketch) -> Self {
        Self {
            inner: l.sketch,
            names: l.shapes,
            constraint_names: l.constraints,
        }
    }

    pub fn from_json_text(text: &str) -> PyResult<Self> {
        let f = SketchFile::from_json(text).map_err(errors::file)?;
        Ok(Self::from_loaded(f.load().map_err(errors::file)?))
    }

    fn kind_of(&self, h: u32) -> PyResult<ShapeKind> {
        self.inner
            .kind(typed::<ShapeId>(h))
            .ok_or_else(|| errors::model(format!("shape {h} is not in this sketch (removed?)")))
    }

    fn point_id(&self, h: u32) -> PyResult<PointId> {
        self.inner
            .as_point(typed(h))
            .ok_or_else(|| errors::model(format!("shape {h} is not a point of this sketch")))
    }

    fn spec(&mut self, v: Value, reference: bool) -> PyResult<u32> {
        let name = v["type"].as_str().unwrap_or("?").to_owned();
        let spec: Spec<ShapeId> = serde_json::from_value(v)
            .map_err(|e| errors::model(format!("{name} constraint: {e}")))?;
        let id = if reference {
            self.inner.add_reference(spec)
        } else {
            self.inner.add(spec)
        }
        .map_err(errors::model)?;
        Ok(id.0)
    }
}

/// Any shape argument: a shape object of this package or a bare entity handle.
pub struct ShapeArg(u32);

impl ShapeArg {
    fn h(&self) -> u32 {
        self.0
    }
}

impl<'py> FromPyObject<'py> for ShapeArg {
    fn extract_bound(ob: &Bound<'py, PyAny>) -> PyResult<Self> {
        if let Ok(s) = ob.downcast::<Point>() {
            return Ok(Self(s.get().h));
        }
        if let Ok(s) = ob.downcast::<Line>() {
            return Ok(Self(s.get().h));
        }
        if let Ok(s) = ob.downcast::<Circle>() {
            return Ok(Self(s.get().h));
        }
        if let Ok(s) = ob.downcast::<Arc>() {
            return Ok(Self(s.get().h));
        }
        if let Ok(s) = ob.downcast::<Cubic>() {
            return Ok(Self(s.get().h));
        }
        if ob.is_instance_of::<pyo3::types::PyInt>() {
            return Ok(Self(ob.extract()?));
        }
        Err(PyTypeError::new_err(format!(
            "expected a shape (Point, Line, Circle, Arc or Cubic) or its handle, not {}",
            ob.get_type().name()?
        )))
    }
}

/// A point argument: a ``Point`` (or handle), or ``(x, y)`` for a new point.
#[derive(FromPyObject)]
pub enum PointArg {
    /// An existing point.
    Shape(ShapeArg),
    /// Coordinates of a new point.
    At((f64, f64)),
}

/// Wraps a shape handle as the Python object of its kind.
fn shape_object(
    py: Python<'_>,
    sketch: &Py<PySketch>,
    kind: ShapeKind,
    h: u32,
) -> PyResult<PyObject> {
    let sketch = sketch.clone_ref(py);
    Ok(match kind {
        ShapeKind::Point => Py::new(py, Point { sketch, h })?.into_any(),
        ShapeKind::Line => Py::new(py, Line { sketch, h })?.into_any(),
        ShapeKind::Circle => Py::new(py, Circle { sketch, h })?.into_any(),
        ShapeKind::Arc => Py::new(py, Arc { sketch, h })?.into_any(),
        ShapeKind::Cubic => Py::new(py, Cubic { sketch, h })?.into_any(),
    })
}

fn resolve_point(slf: &Bound<'_, PySketch>, p: PointArg) -> PyResult<u32> {
    match p {
        PointArg::Shape(s) => {
            let h = s.h();
            slf.borrow().point_id(h)?;
            Ok(h)
        }
        PointArg::At((x, y)) => Ok(slf
            .borrow_mut()
            .inner
            .add_point(x, y)
            .map_err(errors::model)?
            .entity()
            .0),
    }
}

fn constraint_object(slf: &Bound<'_, PySketch>, id: u32) -> PyResult<Py<SketchConstraint>> {
    Py::new(
        slf.py(),
        SketchConstraint {
            sketch: slf.clone().unbind(),
            id,
        },
    )
}

macro_rules! constraint_methods {
    ($($(#[$doc:meta])* fn $name:ident($($arg:ident: $ty:ty),*) $(value $v:ident)? => $json:tt;)*) => {
        #[pymethods]
        impl PySketch {
            $(
                $(#[$doc])*
                #[pyo3(signature = ($($arg,)* $($v,)? *, reference = false))]
                fn $name(
                    slf: &Bound<'_, Self>,
                    $($arg: $ty,)*
                    $($v: f64,)?
                    reference: bool,
                ) -> PyResult<Py<SketchConstraint>> {
                    let id = slf.borrow_mut().spec(json!($json), reference)?;
                    constraint_object(slf, id)
                }
            )*
        }
    };
}

constraint_methods! {
    /// The point stays where it is.
    fn fix(point: ShapeArg) => {"type": "fix", "point": point.h()};
    /// Every point of the shape stays where it is (a circle keeps its radius too).
    fn fix_shape(shape: ShapeArg) => {"type": "fix_shape", "shape": shape.h()};
    /// The line's length.
    fn length(line: ShapeArg) value value => {"type": "length", "line": line.h(), "value": value};
    /// The line is horizontal.
    fn horizontal(line: ShapeArg) => {"type": "horizontal", "line": line.h()};
    /// The line is vertical.
    fn vertical(line: ShapeArg) => {"type": "vertical", "line": line.h()};
    /// The radius of a circle or arc.
    fn radius(shape: ShapeArg) value value => {"type": "radius", "shape": shape.h(), "value": value};
    /// The diameter of a circle or arc.
    fn diameter(shape: ShapeArg) value value => {"type": "diameter", "shape": shape.h(), "value": value};
    /// The arc's counter-clockwise sweep in degrees, in (0, 360).
    fn arc_sweep(arc: ShapeArg) value degrees => {"type": "arc_sweep", "arc": arc.h(), "degrees": degrees};
    /// The distance between two points.
    fn distance(a: ShapeArg, b: ShapeArg) value value => {"type": "distance", "a": a.h(), "b": b.h(), "value": value};
    /// Two points coincide.
    fn coincident(a: ShapeArg, b: ShapeArg) => {"type": "coincident", "a": a.h(), "b": b.h()};
    /// Two circles or arcs share their centre.
    fn concentric(a: ShapeArg, b: ShapeArg) => {"type": "concentric", "a": a.h(), "b": b.h()};
    /// Two lines are parallel.
    fn parallel(a: ShapeArg, b: ShapeArg) => {"type": "parallel", "a": a.h(), "b": b.h()};
    /// Two lines are perpendicular.
    fn perpendicular(a: ShapeArg, b: ShapeArg) => {"type": "perpendicular", "a": a.h(), "b": b.h()};
    /// The signed angle from line ``a`` to line ``b`` in degrees, counter-clockwise positive.
    fn angle(a: ShapeArg, b: ShapeArg) value degrees => {"type": "angle", "a": a.h(), "b": b.h(), "degrees": degrees};
    /// Two lines have the same length.
    fn equal_length(a: ShapeArg, b: ShapeArg) => {"type": "equal_length", "a": a.h(), "b": b.h()};
    /// Two circles or arcs have the same radius.
    fn equal_radius(a: ShapeArg, b: ShapeArg) => {"type": "equal_radius", "a": a.h(), "b": b.h()};
    /// The point lies on the line (extended).
    fn point_on_line(point: ShapeArg, line: ShapeArg) => {"type": "point_on_line", "point": point.h(), "line": line.h()};
    /// The point lies on the circle or arc.
    fn point_on_circle(point: ShapeArg, shape: ShapeArg) => {"type": "point_on_circle", "point": point.h(), "shape": shape.h()};
    /// The point is the line's midpoint.
    fn midpoint(point: ShapeArg, line: ShapeArg) => {"type": "midpoint", "point": point.h(), "line": line.h()};
    /// Two points are mirror images about a line.
    fn symmetric(a: ShapeArg, b: ShapeArg, line: ShapeArg) => {"type": "symmetric", "a": a.h(), "b": b.h(), "line": line.h()};
    /// The signed distance from the point to the line (positive to the right of its direction).
    fn point_line_distance(point: ShapeArg, line: ShapeArg) value value => {"type": "point_line_distance", "point": point.h(), "line": line.h(), "value": value};
    /// Line ``b`` lies on line ``a`` (extended).
    fn collinear(a: ShapeArg, b: ShapeArg) => {"type": "collinear", "a": a.h(), "b": b.h()};
}

#[pymethods]
impl PySketch {
    #[new]
    fn new() -> Self {
        Self {
            inner: Sketch::new(),
            names: BTreeMap::new(),
            constraint_names: BTreeMap::new(),
        }
    }

    /// Reads a sketch file's JSON text.
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Self> {
        Self::from_json_text(text)
    }

    /// The sketch as a sketch file's JSON text, with its current coordinates.
    fn to_json(&self) -> String {
        let names: BTreeMap<ShapeId, &String> = self.names.iter().map(|(n, s)| (*s, n)).collect();
        SketchFile::from_sketch(&self.inner, |s| names.get(&s).map(|n| (*n).clone())).to_json()
    }

    /// Writes the sketch file to ``path``.
    fn save(&self, path: std::path::PathBuf) -> PyResult<()> {
        std::fs::write(&path, self.to_json())?;
        Ok(())
    }

    fn __repr__(&self) -> String {
        format!(
            "Sketch(shapes={}, constraints={})",
            self.inner.shapes().count(),
            self.inner.constraints().count()
        )
    }

    fn __len__(&self) -> usize {
        self.inner.shapes().count()
    }

    /// The shapes, in the order added.
    fn __iter__(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        let list = Self::shapes(slf)?;
        Ok(list.bind(slf.py()).try_iter()?.into_any().unbind())
    }

    /// A shape by the name a sketch file gave it.
    fn __getitem__(slf: &Bound<'_, Self>, name: &str) -> PyResult<PyObject> {
        let s = slf.borrow();
        let id = *s
            .names
            .get(name)
            .ok_or_else(|| PyKeyError::new_err(format!("no shape is named {name:?}")))?;
        let kind = s.kind_of(id.entity().0)?;
        drop(s);
        shape_object(slf.py(), &slf.clone().unbind(), kind, id.entity().0)
    }

    /// Adds a point at (x, y).
    #[pyo3(signature = (x, y, *, construction = false))]
    fn add_point(slf: &Bound<'_, Self>, x: f64, y: f64, construction: bool) -> PyResult<Point> {
        let mut s = slf.borrow_mut();
        let p = s.inner.add_point(x, y).map_err(errors::model)?;
        if construction {
            s.inner.set_construction(p, true).map_err(errors::model)?;
        }
        Ok(Point {
            sketch: slf.clone().unbind(),
            h: p.entity().0,
        })
    }

    /// Adds a line between two points (``Point`` objects, or ``(x, y)`` for new ones).
    #[pyo3(signature = (a, b, *, construction = false))]
    fn add_line(
        slf: &Bound<'_, Self>,
        a: PointArg,
        b: PointArg,
        construction: bool,
    ) -> PyResult<Line> {
        let a = resolve_point(slf, a)?;
        let b = resolve_point(slf, b)?;
        let mut s = slf.borrow_mut();
        let l = s
            .inner
            .add_line(typed(a), typed(b))
            .map_err(errors::model)?;
        if construction {
            s.inner.set_construction(l, true).map_err(errors::model)?;
        }
        Ok(Line {
            sketch: slf.clone().unbind(),
            h: l.entity().0,
        })
    }

    /// Adds a circle about a centre point (or ``(x, y)``) with a radius.
    #[pyo3(signature = (center, radius, *, construction = false))]
    fn add_circle(
        slf: &Bound<'_, Self>,
        center: PointArg,
        radius: f64,
        construction: bool,
    ) -> PyResult<Circle> {
        let c = resolve_point(slf, center)?;
        let mut s = slf.borrow_mut();
        let id = s
            .inner
            .add_circle(typed(c), radius)
            .map_err(errors::model)?;
        if construction {
            s.inner.set_construction(id, true).map_err(errors::model)?;
        }
        Ok(Circle {
            sketch: slf.clone().unbind(),
            h: id.entity().0,
        })
    }

    /// Adds an arc about ``center``, counter-clockwise from ``start`` to ``end``.
    #[pyo3(signature = (center, start, end, *, construction = false))]
    fn add_arc(
        slf: &Bound<'_, Self>,
        center: PointArg,
        start: PointArg,
        end: PointArg,
        construction: bool,
    ) -> PyResult<Arc> {
        let c = resolve_point(slf, center)?;
        let a = resolve_point(slf, start)?;
        let b = resolve_point(slf, end)?;
        let mut s = slf.borrow_mut();
        let id = s
            .inner
            .add_arc(typed(c), typed(a), typed(b))
            .map_err(errors::model)?;
        if construction {
            s.inner.set_construction(id, true).map_err(errors::model)?;
        }
        Ok(Arc {
            sketch: slf.clone().unbind(),
            h: id.entity().0,
        })
    }

    /// Adds a cubic Bezier with four control points.
    #[pyo3(signature = (p0, p1, p2, p3, *, construction = false))]
    fn add_cubic(
        slf: &Bound<'_, Self>,
        p0: PointArg,
        p1: PointArg,
        p2: PointArg,
        p3: PointArg,
        construction: bool,
    ) -> PyResult<Cubic> {
        let mut hs = [0u32; 4];
        for (slot, p) in hs.iter_mut().zip([p0, p1, p2, p3]) {
            *slot = resolve_point(slf, p)?;
        }
        let mut s = slf.borrow_mut();
        let id = s
            .inner
            .add_cubic(hs.map(typed::<PointId>))
            .map_err(errors::model)?;
        if construction {
            s.inner.set_construction(id, true).map_err(errors::model)?;
        }
        Ok(Cubic {
            sketch: slf.clone().unbind(),
            h: id.entity().0,
        })
    }

    /// Removes a shape, the shapes built on it and the constraints on them. Returns the
    /// handles removed: ``(shapes, constraints)``.
    fn remove(&mut self, shape: ShapeArg) -> PyResult<(Vec<u32>, Vec<u32>)> {
        let r = self
            .inner
            .remove_shape(typed::<ShapeId>(shape.h()))
            .map_err(errors::model)?;
        Ok((
            r.shapes.iter().map(|s| s.entity().0).collect(),
            r.constraints.iter().map(|c| c.0).collect(),
        ))
    }

    /// Every shape, in the order added.
    #[getter]
    fn shapes(slf: &Bound<'_, Self>) -> PyResult<Py<pyo3::types::PyList>> {
        let py = slf.py();
        let list: Vec<(ShapeKind, u32)> = slf
            .borrow()
            .inner
            .shapes()
            .map(|(s, k)| (k, s.entity().0))
            .collect();
        let me = slf.clone().unbind();
        let out = pyo3::types::PyList::empty(py);
        for (k, h) in list {
            out.append(shape_object(py, &me, k, h)?)?;
        }
        Ok(out.unbind())
    }

    /// Every point, in the order added.
    #[getter]
    fn points(slf: &Bound<'_, Self>) -> Vec<Point> {
        let me = slf.clone().unbind();
        slf.borrow()
            .inner
            .shapes()
            .filter(|(_, k)| *k == ShapeKind::Point)
            .map(|(s, _)| Point {
                sketch: me.clone_ref(slf.py()),
                h: s.entity().0,
            })
            .collect()
    }

    /// The user constraints, in the order added.
    #[getter]
    fn constraints(slf: &Bound<'_, Self>) -> PyResult<Vec<Py<SketchConstraint>>> {
        let ids: Vec<u32> = slf
            .borrow()
            .inner
            .constraints()
            .map(|(id, _)| id.0)
            .collect();
        ids.into_iter()
            .map(|id| constraint_object(slf, id))
            .collect()
    }

    /// A constraint by the name a sketch file gave it (or ``#i`` for the i-th, from 1).
    fn constraint(slf: &Bound<'_, Self>, name: &str) -> PyResult<Py<SketchConstraint>> {
        let id = *slf
            .borrow()
            .constraint_names
            .get(name)
            .ok_or_else(|| PyKeyError::new_err(format!("no constraint is named {name:?}")))?;
        constraint_object(slf, id.0)
    }

    /// A constraint of any type with the fields of the sketch file format, shapes given as
    /// shape objects or handles: ``add_constraint("tangent", a=arc, b=line, a_end="end")``.
    #[pyo3(signature = (r#type, *, reference = false, **fields))]
    fn add_constraint(
        slf: &Bound<'_, Self>,
        r#type: &str,
        reference: bool,
        fields: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Py<SketchConstraint>> {
        let mut m = serde_json::Map::new();
        if let Some(f) = fields {
            for (k, v) in f.iter() {
                let key: String = k.extract()?;
                let shape =
                    !v.is_instance_of::<pyo3::types::PyInt>() && v.extract::<ShapeArg>().is_ok();
                let val = if shape {
                    Value::from(v.extract::<ShapeArg>()?.h())
                } else {
                    to_json(&v)?
                };
                m.insert(key, val);
            }
        }
        m.insert("type".into(), r#type.into());
        let id = slf.borrow_mut().spec(Value::Object(m), reference)?;
        constraint_object(slf, id)
    }

    /// Two points mirror about an axis of the sketch: ``axis`` is ``"vertical"`` (the y axis)
    /// or ``"horizontal"`` (the x axis).
    #[pyo3(signature = (a, b, axis = "vertical"))]
    fn symmetric_axis(
        slf: &Bound<'_, Self>,
        a: ShapeArg,
        b: ShapeArg,
        axis: &str,
    ) -> PyResult<Py<SketchConstraint>> {
        let v = json!({"type": "symmetric_axis", "a": a.h(), "b": b.h(), "axis": axis});
        let id = slf.borrow_mut().spec(v, false)?;
        constraint_object(slf, id)
    }

    /// Two shapes are tangent. ``a_end``/``b_end`` (``"start"`` or ``"end"``) choose the end
    /// of an arc that touches.
    #[pyo3(signature = (a, b, *, a_end = "start", b_end = "start"))]
    fn tangent(
        slf: &Bound<'_, Self>,
        a: ShapeArg,
        b: ShapeArg,
        a_end: &str,
        b_end: &str,
    ) -> PyResult<Py<SketchConstraint>> {
        let v = json!({"type": "tangent", "a": a.h(), "b": b.h(), "a_end": a_end, "b_end": b_end});
        let id = slf.borrow_mut().spec(v, false)?;
        constraint_object(slf, id)
    }

    /// Locks a line's length or a circle's or arc's size at its current value; locking a
    /// locked shape unlocks it (returning ``None``).
    fn lock(slf: &Bound<'_, Self>, shape: ShapeArg) -> PyResult<Option<Py<SketchConstraint>>> {
        let id = slf
            .borrow_mut()
            .inner
            .lock(typed::<ShapeId>(shape.h()))
            .map_err(errors::model)?;
        id.map(|id| constraint_object(slf, id.0)).transpose()
    }

    /// Removes a user constraint.
    fn remove_constraint(&mut self, constraint: ConstraintArg) -> PyResult<()> {
        self.inner
            .remove_constraint(SketchConstraintId(constraint.id()))
            .map_err(errors::model)?;
        Ok(())
    }

    /// Solves the sketch, keeping lengths and radii no constraint decides (soft constraints)
    /// unless they stand in the way. Releases the GIL.
    fn solve(&mut self, py: Python<'_>) -> PyResult<SketchResult> {
        let inner = &mut self.inner;
        let r = py.allow_threads(|| inner.solve()).map_err(errors::model)?;
        Ok(SketchResult::from(r))
    }

    /// Drags a shape's grip (a point, a line's midpoint, a circle's centre ...) toward
    /// ``to = (x, y)``, as a sketcher does with the mouse. Releases the GIL.
    fn drag(&mut self, py: Python<'_>, shape: ShapeArg, to: (f64, f64)) -> PyResult<DragResult> {
        let inner = &mut self.inner;
        let s = typed::<ShapeId>(shape.h());
        let step = py
            .allow_threads(|| inner.drag(s, [to.0, to.1]))
            .map_err(errors::model)?;
        Ok(DragResult::from(step))
    }

    /// Drags a shape through a path of targets (an N x 2 array or a list of pairs), one
    /// drag step each, reusing the compiled solver; returns each step's result.
    fn drag_path(
        &mut self,
        py: Python<'_>,
        shape: ShapeArg,
        path: Vec<(f64, f64)>,
    ) -> PyResult<Vec<DragResult>> {
        let inner = &mut self.inner;
        let s = typed::<ShapeId>(shape.h());
        let steps = py
            .allow_threads(|| -> Result<Vec<DragStep>, loci::sketch::SketchError> {
                let mut d = inner.begin_drag(s)?;
                path.iter().map(|t| d.step([t.0, t.1])).collect()
            })
            .map_err(errors::model)?;
        Ok(steps.into_iter().map(DragResult::from).collect())
    }

    /// The soft constraints a solve would add now, as ``(keeps, shape handle)`` pairs.
    #[getter]
    fn soft_constraints(&self) -> Vec<(String, u32)> {
        self.inner
            .soft_constraints()
            .into_iter()
            .map(soft)
            .collect()
    }

    /// Every point's coordinates as an (N, 2) NumPy array, in the order of ``points``.
    /// Assigning an array of the same shape moves them all (a value edit, no solve).
    #[getter]
    fn xy<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let pts: Vec<[f64; 2]> = self
            .inner
            .shapes()
            .filter_map(|(s, _)| self.inner.as_point(s))
            .map(|p| self.inner.point(p))
            .collect();
        let flat: Vec<f64> = pts.iter().flatten().copied().collect();
        numpy::PyArray1::from_vec(py, flat)
            .reshape([pts.len(), 2])
            .expect("n x 2 values")
    }

    #[setter]
    fn set_xy(&mut self, xy: PyReadonlyArray2<'_, f64>) -> PyResult<()> {
        let a = xy.as_array();
        let pts: Vec<PointId> = self
            .inner
            .shapes()
            .filter_map(|(s, _)| self.inner.as_point(s))
            .collect();
        if a.shape() != [pts.len(), 2] {
            return Err(PyValueError::new_err(format!(
                "an array of shape ({}, 2) is expected, not {:?}",
                pts.len(),
                a.shape()
            )));
        }
        for (i, p) in pts.into_iter().enumerate() {
            self.inner
                .move_point(p, [a[[i, 0]], a[[i, 1]]])
                .map_err(errors::model)?;
        }
        Ok(())
    }

    /// The core system the sketch writes (a copy): workplane in group 1, shapes in group 2.
    #[getter]
    fn system(&self) -> PySystem {
        PySystem::from_system(self.inner.system().clone())
    }

    /// Diagnoses the sketch's core system (its shapes' group): degrees of freedom, conflicts
    /// and redundancies, named by core constraint handle (see ``SketchConstraint.core``).
    fn check(&self, py: Python<'_>) -> PyResult<CheckResult> {
        let sys = self.inner.system();
        let d = py
            .allow_threads(|| loci::diagnose(sys, Sketch::SHAPE_GROUP, self.inner.config()))
            .map_err(errors::solve)?;
        Ok(CheckResult::new(d))
    }
}

fn soft(s: Soft) -> (String, u32) {
    let (k, h) = match s {
        Soft::LineLength(l) => ("line_length", l.entity()),
        Soft::ArcRadius(a) => ("arc_radius", a.entity()),
        Soft::ArcStart(a) => ("arc_start", a.entity()),
        Soft::ArcEnd(a) => ("arc_end", a.entity()),
    };
    (k.to_owned(), h.0)
}

macro_rules! shape_class {
    ($(#[$doc:meta])* $name:ident, $kind:literal) => {
        $(#[$doc])*
        #[pyclass(module = "loci", frozen)]
        pub struct $name {
            sketch: Py<PySketch>,
            /// The shape's entity handle.
            h: u32,
        }

        #[pymethods]
        impl $name {
            /// The shape's entity handle in the sketch's core system.
            #[getter]
            fn handle(&self) -> u32 {
                self.h
            }

            /// ``"point"``, ``"line"``, ``"circle"``, ``"arc"`` or ``"cubic"``.
            #[getter]
            fn kind(&self) -> &'static str {
                $kind
            }

            /// The sketch it belongs to.
            #[getter]
            fn sketch(&self, py: Python<'_>) -> Py<PySketch> {
                self.sketch.clone_ref(py)
            }

            /// Whether it is construction geometry.
            #[getter]
            fn construction(&self, py: Python<'_>) -> bool {
                self.sketch.borrow(py).inner.is_construction(loci::EntityId(self.h))
            }

            #[setter]
            fn set_construction(&self, py: Python<'_>, v: bool) -> PyResult<()> {
                self.sketch
                    .borrow_mut(py)
                    .inner
                    .set_construction(typed::<ShapeId>(self.h), v)
                    .map_err(errors::model)
            }

            /// The user constraints on this shape.
            #[getter]
            fn constraints(&self, py: Python<'_>) -> PyResult<Vec<Py<SketchConstraint>>> {
                let ids = self
                    .sketch
                    .borrow(py)
                    .inner
                    .constraints_on(typed::<ShapeId>(self.h));
                ids.into_iter()
                    .map(|id| {
                        Py::new(
                            py,
                            SketchConstraint {
                                sketch: self.sketch.clone_ref(py),
                                id: id.0,
                            },
                        )
                    })
                    .collect()
            }

            fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
                other
                    .downcast::<$name>()
                    .is_ok_and(|o| o.get().h == self.h && o.get().sketch.is(&self.sketch))
            }

            fn __hash__(&self) -> u64 {
                u64::from(self.h)
            }

            fn __repr__(&self, py: Python<'_>) -> String {
                match self.describe(py) {
                    Ok(s) => s,
                    Err(_) => format!("{}(#{}, removed)", stringify!($name), self.h),
                }
            }
        }
    };
}

shape_class!(
    /// A point of a sketch: ``x``, ``y`` and ``xy`` read its current coordinates.
    Point,
    "point"
);
shape_class!(
    /// A line of a sketch between two points ``a`` and ``b``.
    Line,
    "line"
);
shape_class!(
    /// A circle of a sketch: ``center`` and ``radius``.
    Circle,
    "circle"
);
shape_class!(
    /// An arc of a sketch, counter-clockwise from ``start`` to ``end`` about ``center``.
    Arc,
    "arc"
);
shape_class!(
    /// A cubic Bezier of a sketch with four control ``points``.
    Cubic,
    "cubic"
);

fn fmt_xy(p: [f64; 2]) -> String {
    format!("({:.6}, {:.6})", p[0], p[1])
}

impl Point {
    fn id(&self, py: Python<'_>) -> PyResult<PointId> {
        self.sketch.borrow(py).point_id(self.h)
    }
    fn describe(&self, py: Python<'_>) -> PyResult<String> {
        let [x, y] = self.get_xy(py)?;
        Ok(format!("Point(#{}, x={x:.6}, y={y:.6})", self.h))
    }
    fn get_xy(&self, py: Python<'_>) -> PyResult<[f64; 2]> {
        let id = self.id(py)?;
        Ok(self.sketch.borrow(py).inner.point(id))
    }
}

#[pymethods]
impl Point {
    /// The x coordinate.
    #[getter]
    fn x(&self, py: Python<'_>) -> PyResult<f64> {
        Ok(self.get_xy(py)?[0])
    }

    /// The y coordinate.
    #[getter]
    fn y(&self, py: Python<'_>) -> PyResult<f64> {
        Ok(self.get_xy(py)?[1])
    }

    /// ``(x, y)``; assigning moves the point (no solve).
    #[getter]
    fn xy(&self, py: Python<'_>) -> PyResult<(f64, f64)> {
        let [x, y] = self.get_xy(py)?;
        Ok((x, y))
    }

    #[setter(xy)]
    fn move_to(&self, py: Python<'_>, to: (f64, f64)) -> PyResult<()> {
        let id = self.id(py)?;
        self.sketch
            .borrow_mut(py)
            .inner
            .move_point(id, [to.0, to.1])
            .map_err(errors::model)
    }
}

impl Line {
    fn id(&self, py: Python<'_>) -> PyResult<LineId> {
        self.sketch
            .borrow(py)
            .inner
            .as_line(typed(self.h))
            .ok_or_else(|| errors::model(format!("shape {} is not a line of this sketch", self.h)))
    }
    fn ends(&self, py: Python<'_>) -> PyResult<[[f64; 2]; 2]> {
        let id = self.id(py)?;
        Ok(self.sketch.borrow(py).inner.line(id))
    }
    fn describe(&self, py: Python<'_>) -> PyResult<String> {
        let [a, b] = self.ends(py)?;
        Ok(format!("Line(#{}, {} -> {})", self.h, fmt_xy(a), fmt_xy(b)))
    }
}

#[pymethods]
impl Line {
    /// The start point.
    #[getter]
    fn a(&self, py: Python<'_>) -> PyResult<Point> {
        let id = self.id(py)?;
        let [a, _] = self.sketch.borrow(py).inner.line_points(id);
        Ok(Point {
            sketch: self.sketch.clone_ref(py),
            h: a.entity().0,
        })
    }

    /// The end point.
    #[getter]
    fn b(&self, py: Python<'_>) -> PyResult<Point> {
        let id = self.id(py)?;
        let [_, b] = self.sketch.borrow(py).inner.line_points(id);
        Ok(Point {
            sketch: self.sketch.clone_ref(py),
            h: b.entity().0,
        })
    }

    /// ``((x1, y1), (x2, y2))``.
    #[getter]
    fn coords(&self, py: Python<'_>) -> PyResult<((f64, f64), (f64, f64))> {
        let [a, b] = self.ends(py)?;
        Ok(((a[0], a[1]), (b[0], b[1])))
    }

    /// The current length.
    #[getter]
    fn length(&self, py: Python<'_>) -> PyResult<f64> {
        let [a, b] = self.ends(py)?;
        Ok((b[0] - a[0]).hypot(b[1] - a[1]))
    }
}

impl Circle {
    fn id(&self, py: Python<'_>) -> PyResult<CircleId> {
        self.sketch
            .borrow(py)
            .inner
            .as_circle(typed(self.h))
            .ok_or_else(|| {
                errors::model(format!("shape {} is not a circle of this sketch", self.h))
            })
    }
    fn describe(&self, py: Python<'_>) -> PyResult<String> {
        let id = self.id(py)?;
        let (c, r) = self.sketch.borrow(py).inner.circle(id);
        Ok(format!(
            "Circle(#{}, center={}, radius={r:.6})",
            self.h,
            fmt_xy(c)
        ))
    }
}

#[pymethods]
impl Circle {
    /// The centre point.
    #[getter]
    fn center(&self, py: Python<'_>) -> PyResult<Point> {
        let id = self.id(py)?;
        let c = self.sketch.borrow(py).inner.circle_center(id);
        Ok(Point {
            sketch: self.sketch.clone_ref(py),
            h: c.entity().0,
        })
    }

    /// The current radius.
    #[getter]
    fn radius(&self, py: Python<'_>) -> PyResult<f64> {
        let id = self.id(py)?;
        Ok(self.sketch.borrow(py).inner.circle(id).1)
    }
}

impl Arc {
    fn id(&self, py: Python<'_>) -> PyResult<ArcId> {
        self.sketch
            .borrow(py)
            .inner
            .as_arc(typed(self.h))
            .ok_or_else(|| errors::model(format!("shape {} is not an arc of this sketch", self.h)))
    }
    fn point(&self, py: Python<'_>, i: usize) -> PyResult<Point> {
        let id = self.id(py)?;
        let p = self.sketch.borrow(py).inner.arc_points(id)[i];
        Ok(Point {
            sketch: self.sketch.clone_ref(py),
            h: p.entity().0,
        })
    }
    fn geometry(&self, py: Python<'_>) -> PyResult<loci::sketch::ArcGeometry> {
        let id = self.id(py)?;
        Ok(self.sketch.borrow(py).inner.arc(id))
    }
    fn describe(&self, py: Python<'_>) -> PyResult<String> {
        let g = self.geometry(py)?;
        Ok(format!(
            "Arc(#{}, center={}, radius={:.6}, start_angle={:.6}, sweep={:.6})",
            self.h,
            fmt_xy(g.center),
            g.radius,
            g.start_angle,
            g.sweep
        ))
    }
}

#[pymethods]
impl Arc {
    /// The centre point.
    #[getter]
    fn center(&self, py: Python<'_>) -> PyResult<Point> {
        self.point(py, 0)
    }
    /// The start point.
    #[getter]
    fn start(&self, py: Python<'_>) -> PyResult<Point> {
        self.point(py, 1)
    }
    /// The end point.
    #[getter]
    fn end(&self, py: Python<'_>) -> PyResult<Point> {
        self.point(py, 2)
    }
    /// The distance from the centre to the start.
    #[getter]
    fn radius(&self, py: Python<'_>) -> PyResult<f64> {
        Ok(self.geometry(py)?.radius)
    }
    /// Direction of the start from the centre, degrees in (-180, 180].
    #[getter]
    fn start_angle(&self, py: Python<'_>) -> PyResult<f64> {
        Ok(self.geometry(py)?.start_angle)
    }
    /// Direction of the end from the centre, degrees in (-180, 180].
    #[getter]
    fn end_angle(&self, py: Python<'_>) -> PyResult<f64> {
        Ok(self.geometry(py)?.end_angle)
    }
    /// Counter-clockwise sweep from start to end, degrees in [0, 360).
    #[getter]
    fn sweep(&self, py: Python<'_>) -> PyResult<f64> {
        Ok(self.geometry(py)?.sweep)
    }
}

impl Cubic {
    fn id(&self, py: Python<'_>) -> PyResult<CubicId> {
        self.sketch
            .borrow(py)
            .inner
            .as_cubic(typed(self.h))
            .ok_or_else(|| errors::model(format!("shape {} is not a cubic of this sketch", self.h)))
    }
    fn describe(&self, py: Python<'_>) -> PyResult<String> {
        let id = self.id(py)?;
        let p = self.sketch.borrow(py).inner.cubic(id);
        let pts: Vec<String> = p.iter().map(|q| fmt_xy(*q)).collect();
        Ok(format!("Cubic(#{}, {})", self.h, pts.join(", ")))
    }
}

#[pymethods]
impl Cubic {
    /// The four control points.
    #[getter]
    fn points(&self, py: Python<'_>) -> PyResult<Vec<Point>> {
        let id = self.id(py)?;
        let s = self.sketch.borrow(py);
        Ok(s.inner
            .defining_points(id)
            .into_iter()
            .map(|p| Point {
                sketch: self.sketch.clone_ref(py),
                h: p.entity().0,
            })
            .collect())
    }

    /// The control points' coordinates, as four ``(x, y)`` pairs.
    #[getter]
    fn coords(&self, py: Python<'_>) -> PyResult<Vec<(f64, f64)>> {
        let id = self.id(py)?;
        Ok(self
            .sketch
            .borrow(py)
            .inner
            .cubic(id)
            .iter()
            .map(|p| (p[0], p[1]))
            .collect())
    }
}

/// A constraint argument: a ``SketchConstraint`` or its id.
pub struct ConstraintArg(u32);

impl ConstraintArg {
    fn id(&self) -> u32 {
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
    sketch: Py<PySketch>,
    id: u32,
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
    /// Pieces undone because they would have flipped a triangle, an arc or a tangent side.
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
