//! `loci.Sketch`: the 2D sketcher — shapes as objects whose coordinates read live from the
//! sketch, user constraints as methods, soft constraints kept by `solve`, and dragging.

use crate::convert::to_json;
use crate::errors;
use crate::result::CheckResult;
use crate::shapes::{Arc, Circle, Cubic, Line, Point};
use crate::sketch_items::{ConstraintArg, DragResult, SketchConstraint, SketchResult};
use crate::system::PySystem;
use loci::format::sketch::{LoadedSketch, SketchFile};
use loci::sketch::{DragStep, PointId, ShapeId, ShapeKind, Sketch, SketchConstraintId, Soft, Spec};
use numpy::{PyArray2, PyArrayMethods, PyReadonlyArray2};
use pyo3::exceptions::{PyKeyError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// A typed sketch handle from its entity handle. The handles are transparent numbers in
/// loci's serde form; whether the shape exists and has the kind is checked by every use.
pub(crate) fn typed<T: serde::de::DeserializeOwned>(h: u32) -> T {
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

    pub(crate) fn kind_of(&self, h: u32) -> PyResult<ShapeKind> {
        self.inner
            .kind(typed::<ShapeId>(h))
            .ok_or_else(|| errors::model(format!("shape {h} is not in this sketch (removed?)")))
    }

    pub(crate) fn point_id(&self, h: u32) -> PyResult<PointId> {
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
pub(crate) fn shape_object(
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

    /// The user constraint that wrote core constraint ``core`` (a handle from ``check()`` or
    /// ``SketchConstraint.core``), or ``None``.
    fn constraint_of(slf: &Bound<'_, Self>, core: u32) -> PyResult<Option<Py<SketchConstraint>>> {
        let id = slf.borrow().inner.owner_of(loci::ConstraintId(core));
        id.map(|id| constraint_object(slf, id.0)).transpose()
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

pub(crate) fn soft(s: Soft) -> (String, u32) {
    let (k, h) = match s {
        Soft::LineLength(l) => ("line_length", l.entity()),
        Soft::ArcRadius(a) => ("arc_radius", a.entity()),
        Soft::ArcStart(a) => ("arc_start", a.entity()),
        Soft::ArcEnd(a) => ("arc_end", a.entity()),
    };
    (k.to_owned(), h.0)
}

/// `(x, y)` for reprs.
pub(crate) fn fmt_xy(p: [f64; 2]) -> String {
    format!("({:.6}, {:.6})", p[0], p[1])
}
