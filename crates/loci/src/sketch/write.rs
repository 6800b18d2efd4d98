//! How a user constraint is written as core constraints: the core constraint each kind
//! needs, and the hidden points and lines of a tangency.

use super::constraints::Rec;
use super::shapes::Geometry;
use super::{
    ArcId, Axis, End, LineId, PointId, ShapeId, ShapeKind as S, Sketch, SketchError, Spec,
    WORKPLANE, X_AXIS,
};
use crate::model::{Constraint, ConstraintId, ConstraintKind as K, Entity, EntityId};

/// A core constraint to write.
pub(super) struct Core {
    kind: K,
    pts: [Option<EntityId>; 2],
    ents: [Option<EntityId>; 2],
    val: f64,
    other: bool,
    other2: bool,
    signed: bool,
}

pub(super) fn core(kind: K) -> Core {
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
    /// Adds one core constraint for `rec`.
    pub(super) fn put(&mut self, rec: &mut Rec, c: Core) -> Result<ConstraintId, SketchError> {
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
    pub(super) fn put_angle(
        &mut self,
        rec: &mut Rec,
        a: EntityId,
        b: EntityId,
        deg: f64,
    ) -> Result<(), SketchError> {
        self.put(rec, core(K::Angle).ents(a, Some(b)).val(deg).signed())?;
        Ok(())
    }

    pub(super) fn fix_point(&mut self, rec: &mut Rec, p: PointId) -> Result<(), SketchError> {
        self.put(rec, core(K::WhereDragged).pts(p, None))?;
        rec.fixed.push((p, self.point(p)));
        Ok(())
    }

    pub(super) fn spokes(&self, arc: ShapeId) -> [EntityId; 2] {
        match &self.shapes[&arc.0].geometry {
            Geometry::Arc { spokes, .. } => *spokes,
            _ => unreachable!("checked: an arc"),
        }
    }

    /// Writes the core constraints of `spec` into `rec`.
    pub(super) fn write(&mut self, spec: &Spec<ShapeId>, rec: &mut Rec) -> Result<(), SketchError> {
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

    pub(super) fn write_tangent(
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

    pub(super) fn hidden_point(
        &mut self,
        rec: &mut Rec,
        at: [f64; 2],
    ) -> Result<PointId, SketchError> {
        let (x, y) = (self.param(at[0])?, self.param(at[1])?);
        rec.params.extend([x, y]);
        let h = self.entity_handle();
        let e = Entity::point_2d(h, Self::SHAPE_GROUP.0, WORKPLANE.0, [x.0, y.0]);
        rec.entities.push(self.sys.add_entity(e)?);
        Ok(PointId(EntityId(h)))
    }

    pub(super) fn hidden_line(
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
}
