//! The JavaScript face of [`SketchBinding`]: every method `RawSketch` has, each a thin call of
//! the Rust side that turns its errors into JavaScript ones.

use super::{ShapeKind, SketchBinding, State};
use crate::error::{js, to_json, Fault};
use loci::sketch::SketchConstraintId;
use wasm_bindgen::prelude::*;

#[wasm_bindgen(js_class = RawSketch)]
impl SketchBinding {
    /// An empty sketch in the xy plane.
    #[wasm_bindgen(constructor)]
    #[must_use]
    pub fn new() -> SketchBinding {
        SketchBinding::default()
    }

    /// Reads a sketch file (JSON with a top-level `sketch`).
    #[wasm_bindgen(js_name = fromJson)]
    pub fn from_json(text: &str) -> Result<SketchBinding, JsValue> {
        js(SketchBinding::read(text))
    }

    /// The sketch file, with the current coordinates and names.
    #[wasm_bindgen(js_name = toJson)]
    #[must_use]
    pub fn to_json(&self) -> String {
        self.write()
    }

    /// The sketch's system as a new `.slvs` file SolveSpace opens.
    #[wasm_bindgen(js_name = toSlvs)]
    pub fn to_slvs(&self) -> Result<Vec<u8>, JsValue> {
        js(loci::format::slvs::export(self.sketch().system())
            .map(|e| e.bytes)
            .map_err(Fault::from))
    }

    /// The sketch's system as a loci JSON problem (solving the shapes' group).
    #[wasm_bindgen(js_name = toProblemJson)]
    #[must_use]
    pub fn to_problem_json(&self) -> String {
        let p = loci::format::json::Problem {
            system: self.sketch().system().clone(),
            solve: None,
        };
        p.to_json()
    }

    /// Adds a point; its handle.
    #[wasm_bindgen(js_name = addPoint)]
    pub fn add_point(&mut self, x: f64, y: f64, name: Option<String>) -> Result<u32, JsValue> {
        js(self.added(ShapeKind::Point, name, |s| {
            s.add_point(x, y).map(Into::into)
        }))
    }

    /// Adds a line between two points.
    #[wasm_bindgen(js_name = addLine)]
    pub fn add_line(&mut self, a: u32, b: u32, name: Option<String>) -> Result<u32, JsValue> {
        js(self.point(a).and_then(|a| {
            let b = self.point(b)?;
            self.added(ShapeKind::Line, name, |s| s.add_line(a, b).map(Into::into))
        }))
    }

    /// Adds a circle about a centre point.
    #[wasm_bindgen(js_name = addCircle)]
    pub fn add_circle(
        &mut self,
        center: u32,
        radius: f64,
        name: Option<String>,
    ) -> Result<u32, JsValue> {
        js(self.point(center).and_then(|c| {
            self.added(ShapeKind::Circle, name, |s| {
                s.add_circle(c, radius).map(Into::into)
            })
        }))
    }

    /// Adds an arc, counter-clockwise from `start` to `end` about `center`.
    #[wasm_bindgen(js_name = addArc)]
    pub fn add_arc(
        &mut self,
        center: u32,
        start: u32,
        end: u32,
        name: Option<String>,
    ) -> Result<u32, JsValue> {
        js((|| {
            let (c, a, b) = (self.point(center)?, self.point(start)?, self.point(end)?);
            self.added(ShapeKind::Arc, name, |s| s.add_arc(c, a, b).map(Into::into))
        })())
    }

    /// Marks a shape as construction geometry (or not).
    #[wasm_bindgen(js_name = setConstruction)]
    pub fn set_construction(&mut self, shape: u32, on: bool) -> Result<(), JsValue> {
        js(self.shape(shape).and_then(|(id, _)| {
            self.sketch_mut()
                .set_construction(id, on)
                .map_err(Fault::from)
        }))
    }

    /// Removes a shape, the shapes built on it and the constraints on them; what was removed
    /// as JSON.
    #[wasm_bindgen(js_name = removeShape)]
    pub fn remove_shape(&mut self, shape: u32) -> Result<String, JsValue> {
        js(self.shape(shape).and_then(|(id, _)| {
            let r = self.sketch_mut().remove_shape(id)?;
            for s in &r.shapes {
                self.unname(s.entity().0);
            }
            for c in &r.constraints {
                self.constraint_names.remove(&c.0);
            }
            Ok(to_json(&serde_json::json!({
                "shapes": r.shapes,
                "constraints": r.constraints,
            })))
        }))
    }

    /// Moves a point (no solve).
    #[wasm_bindgen(js_name = movePoint)]
    pub fn move_point(&mut self, p: u32, x: f64, y: f64) -> Result<(), JsValue> {
        js(self
            .point(p)
            .and_then(|p| self.sketch_mut().move_point(p, [x, y]).map_err(Fault::from)))
    }

    /// Adds a user constraint given as the JSON of a sketch file's constraint, naming shapes
    /// by handle; its handle.
    #[wasm_bindgen(js_name = addConstraint)]
    pub fn add_constraint(
        &mut self,
        spec: &str,
        reference: bool,
        name: Option<String>,
    ) -> Result<u32, JsValue> {
        js(self.add_spec(spec, reference, name))
    }

    /// Removes a user constraint.
    #[wasm_bindgen(js_name = removeConstraint)]
    pub fn remove_constraint(&mut self, id: u32) -> Result<(), JsValue> {
        let r = self
            .sketch_mut()
            .remove_constraint(SketchConstraintId(id))
            .map(|_| ())
            .map_err(Fault::from);
        self.constraint_names.remove(&id);
        js(r)
    }

    /// Changes a dimension's value.
    #[wasm_bindgen(js_name = setValue)]
    pub fn set_value(&mut self, id: u32, value: f64) -> Result<(), JsValue> {
        js(self
            .sketch_mut()
            .set_value(SketchConstraintId(id), value)
            .map_err(Fault::from))
    }

    /// What a constraint measures now and its residual, as JSON.
    pub fn measure(&self, id: u32) -> Result<String, JsValue> {
        js(self
            .sketch()
            .measure(SketchConstraintId(id))
            .map(|m| to_json(&serde_json::json!({"value": m.value, "residual": m.residual})))
            .map_err(Fault::from))
    }

    /// Solves with soft constraints; the report as JSON.
    pub fn solve(&mut self) -> Result<String, JsValue> {
        js(self.solve_sketch())
    }

    /// Degrees of freedom, conflicts and redundancies by constraint, free and fixed shapes,
    /// as JSON.
    pub fn check(&self) -> Result<String, JsValue> {
        js(self.check_sketch())
    }

    /// The shapes, as JSON.
    #[must_use]
    pub fn shapes(&self) -> String {
        self.shape_list()
    }

    /// The user constraints, as JSON.
    #[must_use]
    pub fn constraints(&self) -> String {
        self.constraint_list()
    }

    /// The soft constraints a solve or drag adds now, as JSON.
    #[wasm_bindgen(js_name = softConstraints)]
    #[must_use]
    pub fn soft_constraints(&self) -> String {
        to_json(&self.sketch().soft_constraints())
    }

    /// Every shape's geometry, packed (see the shape list for the order and kinds).
    #[must_use]
    pub fn geometry(&self) -> Vec<f64> {
        self.packed_geometry()
    }

    /// A point's coordinates.
    #[wasm_bindgen(js_name = pointXY)]
    pub fn point_xy(&self, p: u32) -> Result<Vec<f64>, JsValue> {
        js(self.point(p).map(|p| self.sketch().point(p).to_vec()))
    }

    /// A circle's or arc's radius.
    pub fn radius(&self, shape: u32) -> Result<f64, JsValue> {
        js(self
            .circle(shape)
            .map(|c| self.sketch().circle(c).1)
            .or_else(|_| self.arc(shape).map(|a| self.sketch().arc(a).radius)))
    }

    /// A line's length.
    #[wasm_bindgen(js_name = lineLength)]
    pub fn line_length(&self, line: u32) -> Result<f64, JsValue> {
        js(self.line(line).map(|l| {
            let [a, b] = self.sketch().line(l);
            (b[0] - a[0]).hypot(b[1] - a[1])
        }))
    }

    /// Starts dragging a shape: a point, or a whole line, circle or arc.
    #[wasm_bindgen(js_name = beginDrag)]
    pub fn begin_drag(&mut self, shape: u32) -> Result<(), JsValue> {
        js(self.start(shape))
    }

    /// Drags toward a target; what the step did, as JSON.
    #[wasm_bindgen(js_name = dragTo)]
    pub fn drag_to(&mut self, x: f64, y: f64) -> Result<String, JsValue> {
        js(self.step(x, y))
    }

    /// Ends the drag in progress, if any.
    #[wasm_bindgen(js_name = endDrag)]
    pub fn end_drag(&mut self) {
        self.end();
    }

    /// Whether a drag is in progress.
    #[wasm_bindgen(getter)]
    #[must_use]
    pub fn dragging(&self) -> bool {
        matches!(self.state, State::Dragging(_))
    }
}
