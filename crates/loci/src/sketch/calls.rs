//! The typed calls: one per user constraint, each taking the shapes it needs by type.

use super::{
    ArcId, Axis, CircleId, End, LineId, PointId, ShapeId, Sketch, SketchConstraintId, SketchError,
    Spec,
};

/// Makes `id` of a circle handle for the typed calls.
fn round(s: impl Into<ShapeId>) -> ShapeId {
    s.into()
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
            shape: round(s),
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
            shape: round(s),
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
            a: round(a),
            b: round(b),
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
            a: round(a),
            b: round(b),
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
            shape: round(s),
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
