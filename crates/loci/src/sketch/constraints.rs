//! User constraints: typed calls that write core constraints, and their removal.

use super::shapes::Geometry;
use super::{
    ArcId, Axis, CircleId, End, LineId, PointId, ShapeId, ShapeKind as S, Sketch,
    SketchConstraintId, SketchError, Spec, WORKPLANE, X_AXIS,
};
use crate::model::{Constraint, ConstraintId, ConstraintKind as K, Entity, EntityId, ParamId};

/// A user constraint and everything it wrote.
#[derive(Clone, Debug)]
pub(crate) struct Rec {
    pub spec: Spec<ShapeId>,
    pub reference: bool,
    /// The core constraints, in the order written.
    pub core: Vec<ConstraintId>,
    /// Hidden entities (tangency points and lines), removed with the constraint, last first.
    pub entities: Vec<EntityId>,
    /// Hidden parameters.
    pub params: Vec<ParamId>,
    /// Points held in place, with where.
    pub fixed: Vec<(PointId, [f64; 2])>,
    /// For a lock: the values it holds (length; or radius, start and end angles).
    pub locked: Vec<f64>,
}

/// Shapes a circle-or-arc argument accepts.
const ROUND: &[S] = &[S::Circle, S::Arc];

/// A core constraint to write.
struct Core {
    kind: K,
    pts: [Option<EntityId>; 2],
    ents: [Option<EntityId>; 2],
    val: f64,
    other: bool,
    other2: bool,
    signed: bool,
}

fn core(kind: K) -> Core {
    Core {
        kind,
        pts: [None, None],
        ents: [None, None],
        val: 0.0,
        other: false,
        other2: false,
        signed: false,
    }
}

impl Core {
    fn pts(mut self, a: PointId, b: Option<PointId>) -> Self {
        self.pts = [Some(a.0), b.map(|p| p.0)];
        self
    }
    fn ents(mut self, a: EntityId, b: Option<EntityId>) -> Self {
        self.ents = [Some(a), b];
        self
    }
    fn val(mut self, v: f64) -> Self {
        self.val = v;
        self
    }
    fn signed(mut self) -> Self {
        self.signed = true;
        self
    }
}

impl Sketch {
    /// Adds a user constraint described as data (the form sketch files use).
    ///
    /// # Errors
    /// A shape that does not exist or is of the wrong kind, the same shape twice, or a
    /// dimension that is not finite (or not positive where it must be).
    pub fn add(&mut self, spec: Spec<ShapeId>) -> Result<SketchConstraintId, SketchError> {
        self.add_as(spec, false)
    }

    /// Adds a reference (driven) dimension: it measures and never drives. Its value is read
    /// back with [`Sketch::measure`].
    ///
    /// # Errors
    /// As [`Sketch::add`], and a constraint that has no value to measure.
    pub fn add_reference(
        &mut self,
        spec: Spec<ShapeId>,
    ) -> Result<SketchConstraintId, SketchError> {
        if spec.value().is_none() {
            return Err(SketchError::NotADimension(spec.name()));
        }
        self.add_as(spec, true)
    }

    fn add_as(
        &mut self,
        spec: Spec<ShapeId>,
        reference: bool,
    ) -> Result<SketchConstraintId, SketchError> {
        self.check(&spec)?;
        let id = SketchConstraintId(self.next_constraint);
        self.next_constraint += 1;
        let mut rec = Rec {
            spec: spec.clone(),
            reference,
            core: Vec::new(),
            entities: Vec::new(),
            params: Vec::new(),
            fixed: Vec::new(),
            locked: Vec::new(),
        };
        if let Err(e) = self.write(&spec, &mut rec) {
            self.unwrite(&rec)?;
            return Err(e);
        }
        for c in &rec.core {
            self.owner.insert(*c, id);
        }
        self.constraints.insert(id, rec);
        Ok(id)
    }

    /// Removes a user constraint and what it wrote; returns what it said.
    ///
    /// # Errors
    /// No such constraint.
    pub fn remove_constraint(
        &mut self,
        id: SketchConstraintId,
    ) -> Result<Spec<ShapeId>, SketchError> {
        let rec = self
            .constraints
            .remove(&id)
            .ok_or(SketchError::NoConstraint(id))?;
        for c in &rec.core {
            self.owner.remove(c);
        }
        self.unwrite(&rec)?;
        Ok(rec.spec)
    }

    fn unwrite(&mut self, rec: &Rec) -> Result<(), SketchError> {
        for c in &rec.core {
            self.sys.remove_constraint(*c);
        }
        for e in rec.entities.iter().rev() {
            self.sys.remove_entity(*e)?;
        }
        for p in &rec.params {
            self.sys.remove_param(*p)?;
        }
        if !rec.params.is_empty() {
            self.reindex();
        }
        Ok(())
    }

    /// What a user constraint says, and whether it is a reference dimension.
    #[must_use]
    pub fn constraint(&self, id: SketchConstraintId) -> Option<(&Spec<ShapeId>, bool)> {
        self.constraints.get(&id).map(|r| (&r.spec, r.reference))
    }

    /// Every user constraint, in the order added.
    pub fn constraints(&self) -> impl Iterator<Item = (SketchConstraintId, &Spec<ShapeId>)> + '_ {
        self.constraints.iter().map(|(id, r)| (*id, &r.spec))
    }

    /// The core constraints a user constraint wrote (none for a removed one).
    #[must_use]
    pub fn core_constraints(&self, id: SketchConstraintId) -> &[ConstraintId] {
        self.constraints.get(&id).map_or(&[], |r| &r.core)
    }

    /// The user constraint that wrote a core constraint.
    #[must_use]
    pub fn owner_of(&self, c: ConstraintId) -> Option<SketchConstraintId> {
        self.owner.get(&c).copied()
    }

    /// "What constrains this shape?": the user constraints that name it, or (for a line,
    /// circle, arc or cubic) one of its defining points, in the order added.
    #[must_use]
    pub fn constraints_on(&self, shape: impl Into<ShapeId>) -> Vec<SketchConstraintId> {
        let s = shape.into();
        let mut mine: Vec<EntityId> = vec![s.0];
        mine.extend(self.defining_points(s).iter().map(|p| p.0));
        self.constraints
            .iter()
            .filter(|(_, r)| r.spec.shapes().iter().any(|(_, x)| mine.contains(&x.0)))
            .map(|(id, _)| *id)
            .collect()
    }

    /// Changes a constraint's dimension: a value edit, so that a drag's solver is kept.
    ///
    /// # Errors
    /// No such constraint, one without a value, or a value out of range.
    pub fn set_value(&mut self, id: SketchConstraintId, v: f64) -> Result<(), SketchError> {
        let rec = self
            .constraints
            .get(&id)
            .ok_or(SketchError::NoConstraint(id))?;
        let mut spec = rec.spec.clone();
        if !spec.set_value(v) {
            return Err(SketchError::NotADimension(spec.name()));
        }
        check_value(&spec)?;
        let core = rec.core.clone();
        let val = core_value(&spec);
        let rec = self.constraints.get_mut(&id).expect("looked up above");
        rec.spec = spec;
        if let (Some(val), Some(c)) = (val, core.first()) {
            if let Some(mut c) = self.sys.constraint_mut(*c) {
                c.val = val;
            }
        }
        Ok(())
    }

    /// The lock of a line, circle or arc: locks it when it has none (returning the new
    /// constraint), removes the lock when it has one (returning `None`), as the lock button
    /// of a sketcher does.
    ///
    /// # Errors
    /// No such shape, or a point or cubic (which have no size to keep).
    pub fn lock(
        &mut self,
        shape: impl Into<ShapeId>,
    ) -> Result<Option<SketchConstraintId>, SketchError> {
        let s = shape.into();
        let existing = self
            .constraints
            .iter()
            .find(|(_, r)| r.spec == Spec::Lock { shape: s })
            .map(|(id, _)| *id);
        match existing {
            Some(id) => {
                self.remove_constraint(id)?;
                Ok(None)
            }
            None => self.add(Spec::Lock { shape: s }).map(Some),
        }
    }

    /// Whether a shape is locked.
    #[must_use]
    pub fn is_locked(&self, shape: impl Into<ShapeId>) -> bool {
        let s = shape.into();
        self.constraints
            .values()
            .any(|r| r.spec == Spec::Lock { shape: s })
    }

    /// Checks the kinds of the shapes a constraint names, and its value.
    fn check(&self, spec: &Spec<ShapeId>) -> Result<(), SketchError> {
        let n = spec.name();
        let point = |s: &ShapeId, f| self.want(*s, n, f, &[S::Point], "a point");
        let line = |s: &ShapeId, f| self.want(*s, n, f, &[S::Line], "a line");
        let round = |s: &ShapeId, f| self.want(*s, n, f, ROUND, "a circle or an arc");
        let two = |a: &ShapeId, b: &ShapeId| {
            if a == b {
                Err(SketchError::SameShape {
                    constraint: n,
                    shape: *a,
                })
            } else {
                Ok(())
            }
        };
        match spec {
            Spec::Fix { point: p } => point(p, "point").map(drop)?,
            Spec::FixShape { shape } => {
                self.kind(*shape).ok_or(SketchError::NoShape(*shape))?;
            }
            Spec::Length { line: l, .. }
            | Spec::Horizontal { line: l }
            | Spec::Vertical { line: l } => line(l, "line").map(drop)?,
            Spec::Radius { shape, .. } | Spec::Diameter { shape, .. } => {
                round(shape, "shape").map(drop)?;
            }
            Spec::ArcSweep { arc, .. } => {
                self.want(*arc, n, "arc", &[S::Arc], "an arc").map(drop)?;
            }
            Spec::Lock { shape } => self
                .want(
                    *shape,
                    n,
                    "shape",
                    &[S::Line, S::Circle, S::Arc],
                    "a line, circle or arc",
                )
                .map(drop)?,
            Spec::Distance { a, b, .. } | Spec::Coincident { a, b } => {
                point(a, "a")?;
                point(b, "b")?;
                two(a, b)?;
            }
            Spec::SymmetricAxis { a, b, .. } => {
                point(a, "a")?;
                point(b, "b")?;
                two(a, b)?;
            }
            Spec::Concentric { a, b } | Spec::EqualRadius { a, b } => {
                round(a, "a")?;
                round(b, "b")?;
                two(a, b)?;
            }
            Spec::Parallel { a, b }
            | Spec::Perpendicular { a, b }
            | Spec::Angle { a, b, .. }
            | Spec::EqualLength { a, b }
            | Spec::Collinear { a, b } => {
                line(a, "a")?;
                line(b, "b")?;
                two(a, b)?;
            }
            Spec::Tangent { a, b, .. } => {
                let any = [S::Line, S::Circle, S::Arc, S::Cubic];
                let ka = self.want(*a, n, "a", &any, "a line, circle, arc or cubic")?;
                let kb = self.want(*b, n, "b", &any, "a line, circle, arc or cubic")?;
                two(a, b)?;
                if ka == S::Line && kb == S::Line {
                    return Err(SketchError::WrongShape {
                        constraint: n,
                        field: "b",
                        shape: *b,
                        found: kb,
                        expected: "a circle, arc or cubic (two lines are never tangent)",
                    });
                }
                let cubic_ok = |k: S| matches!(k, S::Line | S::Arc | S::Cubic);
                if (ka == S::Cubic && !cubic_ok(kb)) || (kb == S::Cubic && !cubic_ok(ka)) {
                    let (f, s, k) = if ka == S::Cubic {
                        ("b", *b, kb)
                    } else {
                        ("a", *a, ka)
                    };
                    return Err(SketchError::WrongShape {
                        constraint: n,
                        field: f,
                        shape: s,
                        found: k,
                        expected: "a line, arc or cubic (tangent to a cubic)",
                    });
                }
            }
            Spec::PointOnLine { point: p, line: l }
            | Spec::Midpoint { point: p, line: l }
            | Spec::PointLineDistance {
                point: p, line: l, ..
            } => {
                point(p, "point")?;
                line(l, "line")?;
            }
            Spec::PointOnCircle { point: p, shape } => {
                point(p, "point")?;
                round(shape, "shape")?;
            }
            Spec::Symmetric { a, b, line: l } => {
                point(a, "a")?;
                point(b, "b")?;
                line(l, "line")?;
                two(a, b)?;
            }
        }
        check_value(spec)
    }

    /// Adds one core constraint for `rec`.
    fn put(&mut self, rec: &mut Rec, c: Core) -> Result<ConstraintId, SketchError> {
        let h = self.core_handle();
        let mut con = Constraint::new(h, Self::SHAPE_GROUP.0, c.kind)
            .in_workplane(Some(WORKPLANE.0))
            .with_val(c.val)
            .with_flags(c.other, c.other2);
        con.pt_a = c.pts[0];
        con.pt_b = c.pts[1];
        con.entity_a = c.ents[0];
        con.entity_b = c.ents[1];
        con.reference = rec.reference;
        con.signed = c.signed;
        let id = self.sys.add_constraint(con)?;
        rec.core.push(id);
        Ok(id)
    }

    /// A signed angle from line `a` to line `b` (core entities), `deg` counter-clockwise.
    fn put_angle(
        &mut self,
        rec: &mut Rec,
        a: EntityId,
        b: EntityId,
        deg: f64,
    ) -> Result<(), SketchError> {
        self.put(rec, core(K::Angle).ents(a, Some(b)).val(deg).signed())?;
        Ok(())
    }

    fn fix_point(&mut self, rec: &mut Rec, p: PointId) -> Result<(), SketchError> {
        self.put(rec, core(K::WhereDragged).pts(p, None))?;
        rec.fixed.push((p, self.point(p)));
        Ok(())
    }

    fn spokes(&self, arc: ShapeId) -> [EntityId; 2] {
        match &self.shapes[&arc.0].geometry {
            Geometry::Arc { spokes, .. } => *spokes,
            _ => unreachable!("checked: an arc"),
        }
    }

    /// Writes the core constraints of `spec` into `rec`.
    fn write(&mut self, spec: &Spec<ShapeId>, rec: &mut Rec) -> Result<(), SketchError> {
        let pt = |s: &ShapeId| PointId(s.0);
        match spec {
            Spec::Fix { point } => self.fix_point(rec, pt(point))?,
            Spec::FixShape { shape } => {
                for p in self.defining_points(*shape) {
                    self.fix_point(rec, p)?;
                }
                if self.kind(*shape) == Some(S::Circle) {
                    let d = 2.0 * self.radius_of(shape.0);
                    rec.locked.push(d / 2.0);
                    self.put(rec, core(K::Diameter).ents(shape.0, None).val(d))?;
                }
            }
            Spec::Length { line, value } => {
                let [a, b] = self.line_points(LineId(line.0));
                self.put(rec, core(K::PtPtDistance).pts(a, Some(b)).val(*value))?;
            }
            Spec::Horizontal { line } => {
                self.put(rec, core(K::Horizontal).ents(line.0, None))?;
            }
            Spec::Vertical { line } => {
                self.put(rec, core(K::Vertical).ents(line.0, None))?;
            }
            Spec::Radius { shape, value } => {
                self.put(rec, core(K::Diameter).ents(shape.0, None).val(2.0 * value))?;
            }
            Spec::Diameter { shape, value } => {
                self.put(rec, core(K::Diameter).ents(shape.0, None).val(*value))?;
            }
            Spec::ArcSweep { arc, degrees } => {
                let [s0, s1] = self.spokes(*arc);
                self.put_angle(rec, s0, s1, *degrees)?;
            }
            Spec::Lock { shape } => match self.kind(*shape) {
                Some(S::Line) => {
                    let [a, b] = self.line_points(LineId(shape.0));
                    let [p, q] = [self.point(a), self.point(b)];
                    let len = (q[0] - p[0]).hypot(q[1] - p[1]);
                    rec.locked.push(len);
                    self.put(rec, core(K::PtPtDistance).pts(a, Some(b)).val(len))?;
                }
                Some(S::Circle) => {
                    let r = self.radius_of(shape.0);
                    rec.locked.push(r);
                    self.put(rec, core(K::Diameter).ents(shape.0, None).val(2.0 * r))?;
                }
                _ => {
                    let g = self.arc(ArcId(shape.0));
                    rec.locked.extend([g.radius, g.start_angle, g.end_angle]);
                    self.put(
                        rec,
                        core(K::Diameter).ents(shape.0, None).val(2.0 * g.radius),
                    )?;
                    let [s0, s1] = self.spokes(*shape);
                    self.put_angle(rec, X_AXIS, s0, g.start_angle)?;
                    self.put_angle(rec, X_AXIS, s1, g.end_angle)?;
                }
            },
            Spec::Distance { a, b, value } => {
                self.put(
                    rec,
                    core(K::PtPtDistance).pts(pt(a), Some(pt(b))).val(*value),
                )?;
            }
            Spec::Coincident { a, b } => {
                self.put(rec, core(K::PointsCoincident).pts(pt(a), Some(pt(b))))?;
            }
            Spec::Concentric { a, b } => {
                let (ca, cb) = (self.center_of(a.0), self.center_of(b.0));
                self.put(rec, core(K::PointsCoincident).pts(ca, Some(cb)))?;
            }
            Spec::Parallel { a, b } => {
                self.put(rec, core(K::Parallel).ents(a.0, Some(b.0)))?;
            }
            Spec::Perpendicular { a, b } => {
                self.put(rec, core(K::Perpendicular).ents(a.0, Some(b.0)))?;
            }
            Spec::Angle { a, b, degrees } => self.put_angle(rec, a.0, b.0, *degrees)?,
            Spec::EqualLength { a, b } => {
                self.put(rec, core(K::EqualLengthLines).ents(a.0, Some(b.0)))?;
            }
            Spec::EqualRadius { a, b } => {
                self.put(rec, core(K::EqualRadius).ents(a.0, Some(b.0)))?;
            }
            Spec::Tangent { a, b, a_end, b_end } => {
                self.write_tangent(rec, *a, *b, *a_end, *b_end)?
            }
            Spec::PointOnLine { point, line } => {
                self.put(
                    rec,
                    core(K::PtOnLine).pts(pt(point), None).ents(line.0, None),
                )?;
            }
            Spec::PointOnCircle { point, shape } => {
                self.put(
                    rec,
                    core(K::PtOnCircle).pts(pt(point), None).ents(shape.0, None),
                )?;
            }
            Spec::Midpoint { point, line } => {
                self.put(
                    rec,
                    core(K::AtMidpoint).pts(pt(point), None).ents(line.0, None),
                )?;
            }
            Spec::Symmetric { a, b, line } => {
                let c = core(K::SymmetricLine)
                    .pts(pt(a), Some(pt(b)))
                    .ents(line.0, None);
                self.put(rec, c)?;
            }
            Spec::SymmetricAxis { a, b, axis } => {
                // The core names these by the direction the points lie apart in.
                let kind = match axis {
                    Axis::Vertical => K::SymmetricHoriz,
                    Axis::Horizontal => K::SymmetricVert,
                };
                self.put(rec, core(kind).pts(pt(a), Some(pt(b))))?;
            }
            Spec::PointLineDistance { point, line, value } => {
                let c = core(K::PtLineDistance)
                    .pts(pt(point), None)
                    .ents(line.0, None);
                self.put(rec, c.val(*value))?;
            }
            Spec::Collinear { a, b } => {
                for p in self.line_points(LineId(b.0)) {
                    self.put(rec, core(K::PtOnLine).pts(p, None).ents(a.0, None))?;
                }
            }
        }
        Ok(())
    }

    fn write_tangent(
        &mut self,
        rec: &mut Rec,
        a: ShapeId,
        b: ShapeId,
        a_end: End,
        b_end: End,
    ) -> Result<(), SketchError> {
        let (ka, kb) = (
            self.kind(a).expect("checked"),
            self.kind(b).expect("checked"),
        );
        let end = |e: End| e == End::End;
        match (ka, kb) {
            (S::Line, S::Arc) | (S::Arc, S::Line) => {
                let (arc, line, e) = if ka == S::Arc {
                    (a, b, a_end)
                } else {
                    (b, a, b_end)
                };
                let mut c = core(K::ArcLineTangent).ents(arc.0, Some(line.0));
                c.other = end(e);
                self.put(rec, c)?;
            }
            (S::Line, S::Cubic) | (S::Cubic, S::Line) => {
                let (cu, line, e) = if ka == S::Cubic {
                    (a, b, a_end)
                } else {
                    (b, a, b_end)
                };
                let mut c = core(K::CubicLineTangent).ents(cu.0, Some(line.0));
                c.other = end(e);
                self.put(rec, c)?;
            }
            (S::Arc | S::Cubic, S::Arc | S::Cubic) => {
                let mut c = core(K::CurveCurveTangent).ents(a.0, Some(b.0));
                c.other = end(a_end);
                c.other2 = end(b_end);
                self.put(rec, c)?;
            }
            (S::Line, _) | (_, S::Line) => {
                // A line and a whole circle touch at a hidden point on both, where the radius
                // is perpendicular to the line.
                let (line, circle) = if ka == S::Line { (a, b) } else { (b, a) };
                let [p, q] = self.line(LineId(line.0));
                let c = self.point(self.center_of(circle.0));
                let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
                let t = ((c[0] - p[0]) * dx + (c[1] - p[1]) * dy) / (dx * dx + dy * dy).max(1e-300);
                let foot = [p[0] + t * dx, p[1] + t * dy];
                let touch = self.hidden_point(rec, foot)?;
                self.put(rec, core(K::PtOnLine).pts(touch, None).ents(line.0, None))?;
                self.put(
                    rec,
                    core(K::PtOnCircle).pts(touch, None).ents(circle.0, None),
                )?;
                let radius = self.hidden_line(rec, self.center_of(circle.0), touch)?;
                self.put(rec, core(K::Perpendicular).ents(radius, Some(line.0)))?;
            }
            _ => {
                // Two circles (or a circle and an arc) touch at a hidden point on both, in
                // line with the centres: outside or inside, as they are drawn.
                let (ca, cb) = (self.center_of(a.0), self.center_of(b.0));
                let (pa, pb) = (self.point(ca), self.point(cb));
                let (ra, rb) = (self.radius_of(a.0), self.radius_of(b.0));
                let d = (pb[0] - pa[0]).hypot(pb[1] - pa[1]);
                let u = if d > 0.0 {
                    [(pb[0] - pa[0]) / d, (pb[1] - pa[1]) / d]
                } else {
                    [1.0, 0.0]
                };
                let inside = d < ra.max(rb);
                let s = if inside && rb > ra { -ra } else { ra };
                let touch = self.hidden_point(rec, [pa[0] + s * u[0], pa[1] + s * u[1]])?;
                self.put(rec, core(K::PtOnCircle).pts(touch, None).ents(a.0, None))?;
                self.put(rec, core(K::PtOnCircle).pts(touch, None).ents(b.0, None))?;
                let axis = self.hidden_line(rec, ca, cb)?;
                self.put(rec, core(K::PtOnLine).pts(touch, None).ents(axis, None))?;
            }
        }
        Ok(())
    }

    fn hidden_point(&mut self, rec: &mut Rec, at: [f64; 2]) -> Result<PointId, SketchError> {
        let (x, y) = (self.param(at[0])?, self.param(at[1])?);
        rec.params.extend([x, y]);
        let h = self.entity_handle();
        let e = Entity::point_2d(h, Self::SHAPE_GROUP.0, WORKPLANE.0, [x.0, y.0]);
        rec.entities.push(self.sys.add_entity(e)?);
        Ok(PointId(EntityId(h)))
    }

    fn hidden_line(
        &mut self,
        rec: &mut Rec,
        a: PointId,
        b: PointId,
    ) -> Result<EntityId, SketchError> {
        let h = self.entity_handle();
        let e = Entity::line(h, Self::SHAPE_GROUP.0, Some(WORKPLANE.0), a.0 .0, b.0 .0);
        rec.entities.push(self.sys.add_entity(e)?);
        Ok(EntityId(h))
    }

    /// Puts fixed points back where they were fixed (a value edit).
    pub(crate) fn restore_fixed(&mut self) {
        let fixed: Vec<(PointId, [f64; 2])> = self
            .constraints
            .values()
            .flat_map(|r| r.fixed.iter().copied())
            .collect();
        for (p, at) in fixed {
            let [x, y] = self.point_params(p);
            self.sys.set_value(x, at[0]);
            self.sys.set_value(y, at[1]);
        }
    }

    /// Points held by a fixed constraint.
    pub(crate) fn fixed_points(&self) -> Vec<PointId> {
        self.constraints
            .values()
            .flat_map(|r| r.fixed.iter().map(|f| f.0))
            .collect()
    }

    /// Makes `id` of a circle handle for the typed calls.
    fn round(s: impl Into<ShapeId>) -> ShapeId {
        s.into()
    }
}

/// The value the core constraint holds for a dimension (a radius becomes a diameter).
fn core_value(spec: &Spec<ShapeId>) -> Option<f64> {
    match spec {
        Spec::Radius { value, .. } => Some(2.0 * value),
        s => s.value(),
    }
}

fn check_value<R>(spec: &Spec<R>) -> Result<(), SketchError> {
    let Some(v) = spec.value() else {
        return Ok(());
    };
    let bad = |expected| {
        Err(SketchError::BadValue {
            what: spec.name(),
            value: v,
            expected,
        })
    };
    if !v.is_finite() {
        return bad("a finite number");
    }
    match spec {
        Spec::Length { .. } | Spec::Distance { .. } if v < 0.0 => bad("a distance of 0 or more"),
        Spec::Radius { .. } | Spec::Diameter { .. } if v <= 0.0 => bad("a positive size"),
        Spec::ArcSweep { .. } if !(v > 0.0 && v < 360.0) => bad("a sweep in (0, 360) degrees"),
        _ => Ok(()),
    }
}

/// The typed calls: one per user constraint, each checking its shapes' kinds by type.
impl Sketch {
    /// Holds a point where it is.
    ///
    /// # Errors
    /// No such point.
    pub fn fix(&mut self, p: PointId) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Fix { point: p.into() })
    }
    /// Holds every point of a shape where it is (and a circle's radius).
    ///
    /// # Errors
    /// No such shape.
    pub fn fix_shape(&mut self, s: impl Into<ShapeId>) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::FixShape { shape: s.into() })
    }
    /// A line's length.
    ///
    /// # Errors
    /// No such line, or a negative length.
    pub fn length(&mut self, l: LineId, value: f64) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Length {
            line: l.into(),
            value,
        })
    }
    /// A horizontal line.
    ///
    /// # Errors
    /// No such line.
    pub fn horizontal(&mut self, l: LineId) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Horizontal { line: l.into() })
    }
    /// A vertical line.
    ///
    /// # Errors
    /// No such line.
    pub fn vertical(&mut self, l: LineId) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Vertical { line: l.into() })
    }
    /// A circle's or arc's radius.
    ///
    /// # Errors
    /// No such circle or arc, or a radius that is not positive.
    pub fn radius(&mut self, s: impl Round, value: f64) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Radius {
            shape: Self::round(s),
            value,
        })
    }
    /// A circle's or arc's diameter.
    ///
    /// # Errors
    /// As [`Sketch::radius`].
    pub fn diameter(
        &mut self,
        s: impl Round,
        value: f64,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Diameter {
            shape: Self::round(s),
            value,
        })
    }
    /// An arc's sweep, counter-clockwise from start to end, in degrees.
    ///
    /// # Errors
    /// No such arc, or a sweep outside (0, 360).
    pub fn arc_sweep(&mut self, a: ArcId, degrees: f64) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::ArcSweep {
            arc: a.into(),
            degrees,
        })
    }
    /// The distance between two points of any shapes.
    ///
    /// # Errors
    /// No such point, the same point twice, or a negative distance.
    pub fn distance(
        &mut self,
        a: PointId,
        b: PointId,
        value: f64,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Distance {
            a: a.into(),
            b: b.into(),
            value,
        })
    }
    /// Two coincident points.
    ///
    /// # Errors
    /// No such point, or the same point twice.
    pub fn coincident(
        &mut self,
        a: PointId,
        b: PointId,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Coincident {
            a: a.into(),
            b: b.into(),
        })
    }
    /// Two circles or arcs with one centre.
    ///
    /// # Errors
    /// No such shape, or the same twice.
    pub fn concentric(
        &mut self,
        a: impl Round,
        b: impl Round,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Concentric {
            a: Self::round(a),
            b: Self::round(b),
        })
    }
    /// Two parallel lines.
    ///
    /// # Errors
    /// No such line, or the same line twice.
    pub fn parallel(&mut self, a: LineId, b: LineId) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Parallel {
            a: a.into(),
            b: b.into(),
        })
    }
    /// Two perpendicular lines.
    ///
    /// # Errors
    /// No such line, or the same line twice.
    pub fn perpendicular(
        &mut self,
        a: LineId,
        b: LineId,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Perpendicular {
            a: a.into(),
            b: b.into(),
        })
    }
    /// The signed angle from line `a` to line `b`, counter-clockwise, in degrees.
    ///
    /// # Errors
    /// No such line, the same line twice, or an angle that is not finite.
    pub fn angle(
        &mut self,
        a: LineId,
        b: LineId,
        degrees: f64,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Angle {
            a: a.into(),
            b: b.into(),
            degrees,
        })
    }
    /// Two lines of equal length.
    ///
    /// # Errors
    /// No such line, or the same line twice.
    pub fn equal_length(
        &mut self,
        a: LineId,
        b: LineId,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::EqualLength {
            a: a.into(),
            b: b.into(),
        })
    }
    /// Two circles or arcs of equal radius.
    ///
    /// # Errors
    /// No such shape, or the same twice.
    pub fn equal_radius(
        &mut self,
        a: impl Round,
        b: impl Round,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::EqualRadius {
            a: Self::round(a),
            b: Self::round(b),
        })
    }
    /// Two tangent shapes; `a_end` and `b_end` choose the ends of arcs and cubics.
    ///
    /// # Errors
    /// No such shape, two lines, or a cubic with a circle.
    pub fn tangent(
        &mut self,
        a: impl Into<ShapeId>,
        a_end: End,
        b: impl Into<ShapeId>,
        b_end: End,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Tangent {
            a: a.into(),
            b: b.into(),
            a_end,
            b_end,
        })
    }
    /// A point on a line (extended).
    ///
    /// # Errors
    /// No such point or line.
    pub fn point_on_line(
        &mut self,
        p: PointId,
        l: LineId,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::PointOnLine {
            point: p.into(),
            line: l.into(),
        })
    }
    /// A point on a circle or arc.
    ///
    /// # Errors
    /// No such point or shape.
    pub fn point_on_circle(
        &mut self,
        p: PointId,
        s: impl Round,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::PointOnCircle {
            point: p.into(),
            shape: Self::round(s),
        })
    }
    /// A point at a line's midpoint.
    ///
    /// # Errors
    /// No such point or line.
    pub fn midpoint(&mut self, p: PointId, l: LineId) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Midpoint {
            point: p.into(),
            line: l.into(),
        })
    }
    /// Two points mirrored about a line.
    ///
    /// # Errors
    /// No such point or line, or the same point twice.
    pub fn symmetric(
        &mut self,
        a: PointId,
        b: PointId,
        l: LineId,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Symmetric {
            a: a.into(),
            b: b.into(),
            line: l.into(),
        })
    }
    /// Two points mirrored about an axis of the sketch.
    ///
    /// # Errors
    /// No such point, or the same point twice.
    pub fn symmetric_axis(
        &mut self,
        a: PointId,
        b: PointId,
        axis: Axis,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::SymmetricAxis {
            a: a.into(),
            b: b.into(),
            axis,
        })
    }
    /// The signed distance from a point to a line (positive to the right of its direction).
    ///
    /// # Errors
    /// No such point or line.
    pub fn point_line_distance(
        &mut self,
        p: PointId,
        l: LineId,
        value: f64,
    ) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::PointLineDistance {
            point: p.into(),
            line: l.into(),
            value,
        })
    }
    /// Line `b` on line `a` (extended).
    ///
    /// # Errors
    /// No such line, or the same line twice.
    pub fn collinear(&mut self, a: LineId, b: LineId) -> Result<SketchConstraintId, SketchError> {
        self.add(Spec::Collinear {
            a: a.into(),
            b: b.into(),
        })
    }
}

/// A circle or an arc: the shapes that have a radius.
pub trait Round: Into<ShapeId> {}
impl Round for CircleId {}
impl Round for ArcId {}
