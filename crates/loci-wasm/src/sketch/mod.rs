//! The sketcher: a [`loci::sketch::Sketch`] with names for its shapes and constraints, typed
//! shape handles checked at the boundary, soft constraints and dragging across calls.

use crate::error::{parse, to_json, Fault, Res};
use loci::format::sketch::SketchFile;
use loci::sketch::{
    ArcId, CircleId, Drag, LineId, PointId, ShapeId, ShapeKind, Sketch, SketchConstraintId, Spec,
};
use loci::Member;
use serde::Serialize;
use std::collections::{BTreeMap, HashSet};
use wasm_bindgen::prelude::*;

mod js;

/// The sketch, or the drag that holds it between mouse events.
// One per sketch object of JavaScript, moved only when a drag starts or ends: its size is no cost.
#[allow(clippy::large_enum_variant)]
enum State {
    Idle(Sketch),
    Dragging(Drag<'static>),
    /// Only while a drag hands the sketch back.
    Moving,
}

/// A sketch with the names of its shapes and constraints.
#[wasm_bindgen(js_name = RawSketch)]
pub struct SketchBinding {
    state: State,
    /// Each named shape's name, by entity handle.
    shape_names: BTreeMap<u32, String>,
    /// Every shape name in use, to refuse a repeated one and pick fresh ones in constant time.
    taken: HashSet<String>,
    /// The next number tried for an unnamed shape of each kind (`P1`, `L1`, ...).
    next_auto: [u32; 5],
    /// Each named constraint's name.
    constraint_names: BTreeMap<u32, String>,
}

/// A shape as listed to JavaScript.
#[derive(Serialize)]
struct ShapeLine {
    id: u32,
    kind: &'static str,
    name: String,
    construction: bool,
    points: Vec<u32>,
}

/// A user constraint as listed to JavaScript.
#[derive(Serialize)]
struct ConstraintLine<'a> {
    id: u32,
    name: String,
    reference: bool,
    spec: &'a Spec<ShapeId>,
}

/// A solve's report with names.
#[derive(Serialize)]
struct SolveLine {
    outcome: loci::Outcome,
    failed: Vec<u32>,
    failed_names: Vec<String>,
    kept: Vec<loci::sketch::Soft>,
    dropped: Vec<loci::sketch::Soft>,
    iterations: usize,
    residual: f64,
}

/// A diagnosis with sketch handles and names.
#[derive(Serialize)]
struct CheckLine {
    outcome: loci::Outcome,
    dof: usize,
    /// Minimal sets of user constraints that cannot hold together.
    conflicting: Vec<Vec<u32>>,
    /// Sets of user constraints of which some are redundant.
    redundant: Vec<Vec<u32>>,
    /// Every constraint named in a conflict or redundancy, with its name.
    names: BTreeMap<u32, String>,
    /// Shapes that can still move, with their degrees of freedom.
    free: Vec<(u32, usize)>,
    /// Shapes that cannot move at all.
    fixed: Vec<u32>,
}

/// What one drag step did.
#[derive(Serialize)]
struct StepLine {
    outcome: loci::Outcome,
    reached: bool,
    pieces: usize,
    refused: usize,
    flips_prevented: usize,
    at: [f64; 2],
    miss: f64,
}

impl Default for SketchBinding {
    fn default() -> Self {
        Self::from_sketch(Sketch::new())
    }
}

/// The handle of a shape, by its entity handle.
fn shape_id(h: u32) -> Res<ShapeId> {
    serde_json::from_value(h.into())
        .map_err(|e| Fault::input(Some(format!("shape {h}")), e.to_string()))
}

impl SketchBinding {
    fn from_sketch(s: Sketch) -> Self {
        SketchBinding {
            state: State::Idle(s),
            shape_names: BTreeMap::new(),
            taken: HashSet::new(),
            next_auto: [1; 5],
            constraint_names: BTreeMap::new(),
        }
    }

    /// Reads a sketch file.
    ///
    /// # Errors
    /// A file that is not a sketch, or a shape or constraint the sketch refuses, named.
    pub fn read(text: &str) -> Res<Self> {
        let l = SketchFile::from_json(text)?.load()?;
        let mut b = Self::from_sketch(l.sketch);
        b.taken = l.shapes.keys().cloned().collect();
        b.shape_names = l
            .shapes
            .iter()
            .map(|(n, s)| (s.entity().0, n.clone()))
            .collect();
        b.constraint_names = l
            .constraints
            .iter()
            .filter(|(n, _)| !n.starts_with('#'))
            .map(|(n, c)| (c.0, n.clone()))
            .collect();
        Ok(b)
    }

    /// The sketch, whether or not a drag holds it.
    #[must_use]
    pub fn sketch(&self) -> &Sketch {
        match &self.state {
            State::Idle(s) => s,
            State::Dragging(d) => d.sketch(),
            State::Moving => unreachable!("the sketch is back before any call returns"),
        }
    }

    /// The sketch to edit: a drag in progress ends first.
    pub fn sketch_mut(&mut self) -> &mut Sketch {
        self.end();
        match &mut self.state {
            State::Idle(s) => s,
            _ => unreachable!("the drag ended above"),
        }
    }

    /// Ends a drag in progress (its soft constraints are taken out).
    pub fn end(&mut self) {
        if let State::Dragging(_) = self.state {
            if let State::Dragging(d) = std::mem::replace(&mut self.state, State::Moving) {
                let s = d.into_sketch().expect("the drag owns the sketch");
                self.state = State::Idle(s);
            }
        }
    }

    /// The sketch file of the sketch as it is now, with its names.
    #[must_use]
    pub fn write(&self) -> String {
        let s = self.sketch();
        let mut f = SketchFile::from_sketch(s, |id| self.shape_names.get(&id.entity().0).cloned());
        for ((id, _), c) in s.constraints().zip(f.sketch.constraints.iter_mut()) {
            c.name = self.constraint_names.get(&id.0).cloned();
        }
        f.to_json()
    }

    fn shape(&self, h: u32) -> Res<(ShapeId, ShapeKind)> {
        let id = shape_id(h)?;
        let k = self
            .sketch()
            .kind(id)
            .ok_or_else(|| Fault::from(loci::sketch::SketchError::NoShape(id)))?;
        Ok((id, k))
    }

    fn typed<T>(&self, h: u32, want: &str, f: impl Fn(&Sketch, ShapeId) -> Option<T>) -> Res<T> {
        let (id, k) = self.shape(h)?;
        f(self.sketch(), id).ok_or_else(|| Fault {
            class: crate::error::Class::Sketch,
            object: Some(format!("shape {h}")),
            message: format!("shape {h} is a {}, but {want} is expected", k.name()),
        })
    }

    /// A point handle.
    ///
    /// # Errors
    /// No such shape, or not a point.
    pub fn point(&self, h: u32) -> Res<PointId> {
        self.typed(h, "a point", Sketch::as_point)
    }

    fn line(&self, h: u32) -> Res<LineId> {
        self.typed(h, "a line", Sketch::as_line)
    }

    fn circle(&self, h: u32) -> Res<CircleId> {
        self.typed(h, "a circle", Sketch::as_circle)
    }

    fn arc(&self, h: u32) -> Res<ArcId> {
        self.typed(h, "an arc", Sketch::as_arc)
    }

    /// A shape's name: its own, or its kind and handle.
    fn shape_name(&self, id: ShapeId) -> String {
        self.shape_names
            .get(&id.entity().0)
            .cloned()
            .unwrap_or_else(|| {
                let kind = self.sketch().kind(id).map_or("shape", ShapeKind::name);
                format!("{kind}_{}", id.entity().0)
            })
    }

    /// The label of a constraint: its name, or what it says of which shapes (`length crank
    /// = 1`), so that a conflict reads by the drawing's names.
    fn label(&self, c: SketchConstraintId) -> String {
        let Some((spec, _)) = self.sketch().constraint(c) else {
            return c.to_string();
        };
        let kind = spec.name();
        if let Some(n) = self.constraint_names.get(&c.0) {
            return format!("{n} ({kind})");
        }
        let shapes: Vec<String> = spec
            .shapes()
            .iter()
            .map(|(_, s)| self.shape_name(**s))
            .collect();
        let value = spec.value().map_or(String::new(), |v| format!(" = {v}"));
        format!("{kind} {}{value}", shapes.join(", "))
    }

    fn name_for(&mut self, h: u32, kind: ShapeKind, name: Option<String>) -> Res<()> {
        let name = match name.filter(|n| !n.is_empty()) {
            Some(n) => {
                if self.taken.contains(&n) {
                    return Err(Fault {
                        class: crate::error::Class::Sketch,
                        object: Some(n.clone()),
                        message: format!("the name {n:?} is given twice"),
                    });
                }
                n
            }
            None => {
                let (slot, prefix) = match kind {
                    ShapeKind::Point => (0, "P"),
                    ShapeKind::Line => (1, "L"),
                    ShapeKind::Circle => (2, "C"),
                    ShapeKind::Arc => (3, "A"),
                    ShapeKind::Cubic => (4, "B"),
                };
                loop {
                    let n = format!("{prefix}{}", self.next_auto[slot]);
                    self.next_auto[slot] += 1;
                    if !self.taken.contains(&n) {
                        break n;
                    }
                }
            }
        };
        self.taken.insert(name.clone());
        self.shape_names.insert(h, name);
        Ok(())
    }

    /// Forgets the name of a removed shape.
    pub(crate) fn unname(&mut self, h: u32) {
        if let Some(n) = self.shape_names.remove(&h) {
            self.taken.remove(&n);
        }
    }

    /// Adds a shape made by `make` and names it.
    fn added(
        &mut self,
        kind: ShapeKind,
        name: Option<String>,
        make: impl FnOnce(&mut Sketch) -> Result<ShapeId, loci::sketch::SketchError>,
    ) -> Res<u32> {
        let id = make(self.sketch_mut())?;
        let h = id.entity().0;
        if let Err(e) = self.name_for(h, kind, name) {
            let _ = self.sketch_mut().remove_shape(id);
            return Err(e);
        }
        Ok(h)
    }

    /// The diagnosis of the shapes' group, by sketch handles.
    ///
    /// # Errors
    /// A sketch the diagnosis cannot start on.
    pub fn check_sketch(&self) -> Res<String> {
        let s = self.sketch();
        let d = loci::diagnose(s.system(), Sketch::SHAPE_GROUP, s.config())?;
        let mut names = BTreeMap::new();
        let mut users = |m: &[Member]| -> Vec<u32> {
            let mut v: Vec<u32> = m
                .iter()
                .filter_map(|m| match m {
                    Member::Constraint(c) => s.owner_of(*c),
                    Member::Entity(_) => None,
                })
                .map(|c| {
                    names.insert(c.0, self.label(c));
                    c.0
                })
                .collect();
            v.sort_unstable();
            v.dedup();
            v
        };
        let conflicting = d.conflicting.iter().map(|c| users(&c.members)).collect();
        let redundant = d.redundant.iter().map(|c| users(&c.members)).collect();
        let dof_of: BTreeMap<u32, usize> = d.freedoms.iter().map(|f| (f.entity.0, f.dof)).collect();
        let sys = s.system();
        let (mut free, mut fixed) = (Vec::new(), Vec::new());
        for (id, _) in s.shapes() {
            let mut ents = vec![id.entity()];
            ents.extend(s.defining_points(id).iter().map(|p| p.entity()));
            if let Some(e) = sys.entity(id.entity()) {
                ents.extend(e.kind.references().into_iter().map(|(_, r)| r));
            }
            ents.sort_unstable();
            ents.dedup();
            let n: usize = ents.iter().filter_map(|e| dof_of.get(&e.0)).sum();
            if n == 0 {
                fixed.push(id.entity().0);
            } else {
                free.push((id.entity().0, n));
            }
        }
        Ok(to_json(&CheckLine {
            outcome: d.outcome,
            dof: d.dof,
            conflicting,
            redundant,
            names,
            free,
            fixed,
        }))
    }

    /// Solves the sketch with soft constraints; the report with constraint names.
    ///
    /// # Errors
    /// A solve that cannot start.
    pub fn solve_sketch(&mut self) -> Res<String> {
        let r = self.sketch_mut().solve()?;
        Ok(to_json(&SolveLine {
            outcome: r.outcome,
            failed_names: r.failed.iter().map(|c| self.label(*c)).collect(),
            failed: r.failed.iter().map(|c| c.0).collect(),
            kept: r.kept,
            dropped: r.dropped,
            iterations: r.iterations,
            residual: r.residual,
        }))
    }

    /// Starts dragging a shape (ending a drag in progress).
    ///
    /// # Errors
    /// No such shape, or one with a fixed point.
    pub fn start(&mut self, h: u32) -> Res<()> {
        let (id, _) = self.shape(h)?;
        self.end();
        let State::Idle(s) = std::mem::replace(&mut self.state, State::Moving) else {
            unreachable!("the drag ended above")
        };
        match s.into_drag(id) {
            Ok(d) => {
                self.state = State::Dragging(d);
                Ok(())
            }
            Err((s, e)) => {
                self.state = State::Idle(*s);
                Err(e.into())
            }
        }
    }

    /// One drag step toward a target.
    ///
    /// # Errors
    /// No drag in progress, or a target that is not finite.
    pub fn step(&mut self, x: f64, y: f64) -> Res<String> {
        let State::Dragging(d) = &mut self.state else {
            return Err(Fault::input(
                None,
                "dragTo: no drag in progress; call beginDrag first",
            ));
        };
        let s = d.step([x, y])?;
        Ok(to_json(&StepLine {
            outcome: s.outcome,
            reached: s.reached,
            pieces: s.pieces,
            refused: s.refused,
            flips_prevented: s.flips_prevented,
            at: s.at,
            miss: s.miss,
        }))
    }

    /// Every shape's geometry, packed in the order of the shape list: a point's x, y; a
    /// line's two ends; a circle's centre and radius; an arc's centre, start and end; a
    /// cubic's four control points.
    #[must_use]
    pub fn packed_geometry(&self) -> Vec<f64> {
        let s = self.sketch();
        let mut out = Vec::new();
        for (id, kind) in s.shapes() {
            match kind {
                ShapeKind::Point => {
                    out.extend(s.as_point(id).map(|p| s.point(p)).into_iter().flatten())
                }
                ShapeKind::Line => {
                    if let Some(l) = s.as_line(id) {
                        out.extend(s.line(l).into_iter().flatten());
                    }
                }
                ShapeKind::Circle => {
                    if let Some(c) = s.as_circle(id) {
                        let (c, r) = s.circle(c);
                        out.extend([c[0], c[1], r]);
                    }
                }
                ShapeKind::Arc => {
                    if let Some(a) = s.as_arc(id) {
                        let g = s.arc(a);
                        out.extend([g.center, g.start, g.end].into_iter().flatten());
                    }
                }
                ShapeKind::Cubic => {
                    if let Some(c) = s.as_cubic(id) {
                        out.extend(s.cubic(c).into_iter().flatten());
                    }
                }
            }
        }
        out
    }

    fn shape_list(&self) -> String {
        let s = self.sketch();
        let v: Vec<ShapeLine> = s
            .shapes()
            .map(|(id, kind)| ShapeLine {
                id: id.entity().0,
                kind: kind.name(),
                name: self.shape_name(id),
                construction: s.is_construction(id.entity()),
                points: match kind {
                    ShapeKind::Point => Vec::new(),
                    _ => s.defining_points(id).iter().map(|p| p.entity().0).collect(),
                },
            })
            .collect();
        to_json(&v)
    }

    fn constraint_list(&self) -> String {
        let s = self.sketch();
        let v: Vec<ConstraintLine<'_>> = s
            .constraints()
            .map(|(id, spec)| ConstraintLine {
                id: id.0,
                name: self.label(id),
                reference: s.constraint(id).is_some_and(|(_, r)| r),
                spec,
            })
            .collect();
        to_json(&v)
    }

    fn add_spec(&mut self, json: &str, reference: bool, name: Option<String>) -> Res<u32> {
        let spec: Spec<ShapeId> = parse("constraint", json)?;
        if let Some(n) = &name {
            if self.constraint_names.values().any(|m| m == n) {
                return Err(Fault {
                    class: crate::error::Class::Sketch,
                    object: Some(n.clone()),
                    message: format!("the constraint name {n:?} is given twice"),
                });
            }
        }
        for (_, s) in spec.shapes() {
            self.shape(s.entity().0)?;
        }
        let s = self.sketch_mut();
        let id = if reference {
            s.add_reference(spec)?
        } else {
            s.add(spec)?
        };
        if let Some(n) = name.filter(|n| !n.is_empty()) {
            self.constraint_names.insert(id.0, n);
        }
        Ok(id.0)
    }
}
