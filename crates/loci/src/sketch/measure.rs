//! Reading a user constraint back: the value it measures now and how far it is from holding.

use super::{
    ArcId, Axis, LineId, PointId, ShapeId, ShapeKind, Sketch, SketchConstraintId, SketchError, Spec,
};

/// A constraint read back from the current coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measured {
    /// The dimension as drawn (for constraints with a value; for `parallel` and
    /// `perpendicular` the signed angle between the lines, in degrees).
    pub value: Option<f64>,
    /// How far the drawing is from satisfying the constraint, 0 when it holds: a distance in
    /// model units, an angle difference in degrees for angles, or the sine (cosine) of the
    /// angle between lines for parallel (perpendicular). A reference dimension always has 0.
    pub residual: f64,
}

fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}
fn norm(a: [f64; 2]) -> f64 {
    a[0].hypot(a[1])
}
fn cross(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}
fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}
/// The signed angle from `a` to `b`, degrees in (-180, 180].
pub(crate) fn signed_angle(a: [f64; 2], b: [f64; 2]) -> f64 {
    cross(a, b).atan2(dot(a, b)).to_degrees()
}
/// `a - b` wrapped to (-180, 180] degrees.
pub(crate) fn wrap_deg(d: f64) -> f64 {
    let w = (d + 180.0).rem_euclid(360.0) - 180.0;
    if w == -180.0 {
        180.0
    } else {
        w
    }
}

impl Sketch {
    fn dir(&self, l: ShapeId) -> [f64; 2] {
        let [p, q] = self.line(LineId(l.0));
        sub(q, p)
    }

    /// Signed distance from `p` to line `l`, positive to the right of its direction.
    fn side(&self, p: [f64; 2], l: ShapeId) -> f64 {
        let [a, b] = self.line(LineId(l.0));
        let d = sub(b, a);
        -cross(d, sub(p, a)) / norm(d).max(1e-300)
    }

    fn pt(&self, s: &ShapeId) -> [f64; 2] {
        self.point(PointId(s.0))
    }

    /// A user constraint's value as drawn now, and its residual.
    ///
    /// # Errors
    /// No such constraint.
    pub fn measure(&self, id: SketchConstraintId) -> Result<Measured, SketchError> {
        let rec = self
            .constraints
            .get(&id)
            .ok_or(SketchError::NoConstraint(id))?;
        let (value, residual) = self.evaluate(&rec.spec, &rec.locked, &rec.fixed);
        Ok(Measured {
            value,
            residual: if rec.reference { 0.0 } else { residual },
        })
    }

    fn evaluate(
        &self,
        spec: &Spec<ShapeId>,
        locked: &[f64],
        fixed: &[(PointId, [f64; 2])],
    ) -> (Option<f64>, f64) {
        let len = |l: &ShapeId| norm(self.dir(*l));
        let diff = |v: f64, want: f64| (v - want).abs();
        match spec {
            Spec::Fix { .. } | Spec::FixShape { .. } => {
                let mut r = fixed
                    .iter()
                    .map(|(p, at)| norm(sub(self.point(*p), *at)))
                    .fold(0.0, f64::max);
                if let (Spec::FixShape { shape }, Some(&want)) = (spec, locked.first()) {
                    r = r.max(diff(self.radius_of(shape.0), want));
                }
                (None, r)
            }
            Spec::Length { line, value } => (Some(len(line)), diff(len(line), *value)),
            Spec::Horizontal { line } => (None, self.dir(*line)[1].abs()),
            Spec::Vertical { line } => (None, self.dir(*line)[0].abs()),
            Spec::Radius { shape, value } => {
                let r = self.radius_of(shape.0);
                (Some(r), diff(r, *value))
            }
            Spec::Diameter { shape, value } => {
                let d = 2.0 * self.radius_of(shape.0);
                (Some(d), diff(d, *value))
            }
            Spec::ArcSweep { arc, degrees } => {
                let g = self.arc(ArcId(arc.0));
                (Some(g.sweep), wrap_deg(g.sweep - degrees).abs())
            }
            Spec::Lock { shape } => match self.kind(*shape) {
                Some(ShapeKind::Line) => (None, diff(len(shape), locked[0])),
                Some(ShapeKind::Circle) => (None, diff(self.radius_of(shape.0), locked[0])),
                _ => {
                    let g = self.arc(ArcId(shape.0));
                    let r = diff(g.radius, locked[0])
                        .max(wrap_deg(g.start_angle - locked[1]).abs().to_radians() * g.radius)
                        .max(wrap_deg(g.end_angle - locked[2]).abs().to_radians() * g.radius);
                    (None, r)
                }
            },
            Spec::Distance { a, b, value } => {
                let d = norm(sub(self.pt(a), self.pt(b)));
                (Some(d), diff(d, *value))
            }
            Spec::Coincident { a, b } => (None, norm(sub(self.pt(a), self.pt(b)))),
            Spec::Concentric { a, b } => {
                let (ca, cb) = (self.center_of(a.0), self.center_of(b.0));
                (None, norm(sub(self.point(ca), self.point(cb))))
            }
            Spec::Parallel { a, b } => {
                let (u, v) = (self.dir(*a), self.dir(*b));
                let s = cross(u, v) / (norm(u) * norm(v)).max(1e-300);
                (Some(signed_angle(u, v)), s.abs())
            }
            Spec::Perpendicular { a, b } => {
                let (u, v) = (self.dir(*a), self.dir(*b));
                let c = dot(u, v) / (norm(u) * norm(v)).max(1e-300);
                (Some(signed_angle(u, v)), c.abs())
            }
            Spec::Angle { a, b, degrees } => {
                let t = signed_angle(self.dir(*a), self.dir(*b));
                (Some(t), wrap_deg(t - degrees).abs())
            }
            Spec::EqualLength { a, b } => {
                let d = len(a) - len(b);
                (Some(d), d.abs())
            }
            Spec::EqualRadius { a, b } => {
                let d = self.radius_of(a.0) - self.radius_of(b.0);
                (Some(d), d.abs())
            }
            Spec::Tangent { a, b, a_end, b_end } => {
                (None, self.tangent_residual(*a, *b, *a_end, *b_end))
            }
            Spec::PointOnLine { point, line } => (None, self.side(self.pt(point), *line).abs()),
            Spec::PointOnCircle { point, shape } => {
                let c = self.point(self.center_of(shape.0));
                (
                    None,
                    diff(norm(sub(self.pt(point), c)), self.radius_of(shape.0)),
                )
            }
            Spec::Midpoint { point, line } => {
                let [p, q] = self.line(LineId(line.0));
                let m = [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0];
                (None, norm(sub(self.pt(point), m)))
            }
            Spec::Symmetric { a, b, line } => {
                let (pa, pb) = (self.pt(a), self.pt(b));
                let m = [(pa[0] + pb[0]) / 2.0, (pa[1] + pb[1]) / 2.0];
                let d = self.dir(*line);
                let along = dot(sub(pb, pa), d) / norm(d).max(1e-300);
                (None, self.side(m, *line).abs().max(along.abs()))
            }
            Spec::SymmetricAxis { a, b, axis } => {
                let (pa, pb) = (self.pt(a), self.pt(b));
                let r = match axis {
                    Axis::Vertical => (pa[0] + pb[0]).abs().max((pa[1] - pb[1]).abs()),
                    Axis::Horizontal => (pa[1] + pb[1]).abs().max((pa[0] - pb[0]).abs()),
                };
                (None, r)
            }
            Spec::PointLineDistance { point, line, value } => {
                let d = self.side(self.pt(point), *line);
                (Some(d), diff(d, *value))
            }
            Spec::Collinear { a, b } => {
                let [p, q] = self.line(LineId(b.0));
                (None, self.side(p, *a).abs().max(self.side(q, *a).abs()))
            }
        }
    }

    /// How far two shapes are from tangent. With a circle: for a line, the distance of the
    /// centre from the line against the radius; for another circle or arc, the distance of
    /// the centres against the sum or difference of the radii (whichever is nearer).
    /// Between lines, arcs and cubics (tangent at their ends): the sine of the angle between
    /// their directions at the chosen ends.
    fn tangent_residual(
        &self,
        a: ShapeId,
        b: ShapeId,
        a_end: super::End,
        b_end: super::End,
    ) -> f64 {
        let (ka, kb) = (self.kind(a), self.kind(b));
        let circle = Some(ShapeKind::Circle);
        if ka == circle || kb == circle {
            if ka == Some(ShapeKind::Line) || kb == Some(ShapeKind::Line) {
                let (l, c) = if ka == Some(ShapeKind::Line) {
                    (a, b)
                } else {
                    (b, a)
                };
                let center = self.point(self.center_of(c.0));
                return (self.side(center, l).abs() - self.radius_of(c.0)).abs();
            }
            let (ca, cb) = (
                self.point(self.center_of(a.0)),
                self.point(self.center_of(b.0)),
            );
            let (ra, rb) = (self.radius_of(a.0), self.radius_of(b.0));
            let d = norm(sub(ca, cb));
            return (d - (ra + rb)).abs().min((d - (ra - rb).abs()).abs());
        }
        let (u, v) = (self.end_dir(a, a_end), self.end_dir(b, b_end));
        (cross(u, v) / (norm(u) * norm(v)).max(1e-300)).abs()
    }

    /// The direction of a line, arc or cubic at one end.
    fn end_dir(&self, s: ShapeId, e: super::End) -> [f64; 2] {
        let at_end = e == super::End::End;
        match self.kind(s) {
            Some(ShapeKind::Line) => self.dir(s),
            Some(ShapeKind::Cubic) => {
                let c = self.cubic(super::CubicId(s.0));
                if at_end {
                    sub(c[3], c[2])
                } else {
                    sub(c[1], c[0])
                }
            }
            _ => {
                let g = self.arc(ArcId(s.0));
                let p = if at_end { g.end } else { g.start };
                let r = sub(p, g.center);
                [-r[1], r[0]]
            }
        }
    }
}
