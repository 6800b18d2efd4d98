//! The shapes of a `loci.Sketch` as Python objects: each holds its sketch and its entity
//! handle, and reads its coordinates from the sketch when asked, so it is never stale.

use crate::errors;
use crate::sketch::{fmt_xy, typed, PySketch};
use crate::sketch_items::SketchConstraint;
use loci::sketch::{ArcId, CircleId, CubicId, LineId, PointId, ShapeId};
use pyo3::prelude::*;

macro_rules! shape_class {
    ($(#[$doc:meta])* $name:ident, $kind:literal) => {
        $(#[$doc])*
        #[pyclass(module = "loci", frozen)]
        pub struct $name {
            pub(crate) sketch: Py<PySketch>,
            /// The shape's entity handle.
            pub(crate) h: u32,
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
