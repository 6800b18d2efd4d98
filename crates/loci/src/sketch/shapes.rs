//! Shapes: points, lines, circles, arcs and cubics, their parameters and how they are read.

use super::{
    ArcId, CircleId, CubicId, LineId, PointId, ShapeId, ShapeKind, Sketch, SketchConstraintId,
    SketchError, NORMAL_2D, WORKPLANE,
};
use crate::model::{Entity, EntityId, ParamId};
use std::collections::BTreeSet;

/// What a shape is made of.
#[derive(Clone, Debug)]
pub(crate) enum Geometry {
    /// Its two coordinates and their positions in the parameter vector.
    Point {
        params: [ParamId; 2],
        ix: [usize; 2],
    },
    Line {
        points: [PointId; 2],
    },
    /// The radius is a distance entity holding one parameter.
    Circle {
        center: PointId,
        radius: EntityId,
        param: ParamId,
        ix: usize,
    },
    /// `spokes` are hidden lines from the centre to the start and to the end, which angle
    /// constraints on the arc's ends are written on.
    Arc {
        center: PointId,
        start: PointId,
        end: PointId,
        spokes: [EntityId; 2],
    },
    Cubic {
        points: [PointId; 4],
    },
}

#[derive(Clone, Debug)]
pub(crate) struct Shape {
    pub geometry: Geometry,
    pub construction: bool,
}

impl Geometry {
    pub fn kind(&self) -> ShapeKind {
        match self {
            Geometry::Point { .. } => ShapeKind::Point,
            Geometry::Line { .. } => ShapeKind::Line,
            Geometry::Circle { .. } => ShapeKind::Circle,
            Geometry::Arc { .. } => ShapeKind::Arc,
            Geometry::Cubic { .. } => ShapeKind::Cubic,
        }
    }

    /// The points that define it (a point itself).
    pub fn points(&self, me: EntityId) -> Vec<PointId> {
        match self {
            Geometry::Point { .. } => vec![PointId(me)],
            Geometry::Line { points } => points.to_vec(),
            Geometry::Circle { center, .. } => vec![*center],
            Geometry::Arc {
                center, start, end, ..
            } => vec![*center, *start, *end],
            Geometry::Cubic { points } => points.to_vec(),
        }
    }
}

/// The centre, ends and angles of an arc, read from the parameter vector.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArcGeometry {
    /// Centre.
    pub center: [f64; 2],
    /// Start point.
    pub start: [f64; 2],
    /// End point.
    pub end: [f64; 2],
    /// Distance from the centre to the start.
    pub radius: f64,
    /// Direction of the start from the centre, degrees in (-180, 180].
    pub start_angle: f64,
    /// Direction of the end from the centre, degrees in (-180, 180].
    pub end_angle: f64,
    /// Counter-clockwise sweep from start to end, degrees in [0, 360).
    pub sweep: f64,
}

/// What a removal took away besides the object asked for.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Removed {
    /// Shapes removed (the one asked for first, then those built on it).
    pub shapes: Vec<ShapeId>,
    /// User constraints removed because they referred to a removed shape.
    pub constraints: Vec<SketchConstraintId>,
}

fn finite(what: &'static str, v: f64) -> Result<f64, SketchError> {
    if v.is_finite() && v.abs() <= crate::MAX_MAGNITUDE {
        Ok(v)
    } else {
        Err(SketchError::BadValue {
            what,
            value: v,
            expected: "a finite number of size at most 1e100",
        })
    }
}

impl Sketch {
    fn insert(&mut self, e: Entity, geometry: Geometry) -> Result<EntityId, SketchError> {
        let h = self.sys.add_entity(e)?;
        self.shapes.insert(
            h,
            Shape {
                geometry,
                construction: false,
            },
        );
        Ok(h)
    }

    /// Adds a point at (x, y).
    ///
    /// # Errors
    /// A coordinate that is not finite.
    pub fn add_point(&mut self, x: f64, y: f64) -> Result<PointId, SketchError> {
        finite("x", x)?;
        finite("y", y)?;
        let params = [self.param(x)?, self.param(y)?];
        let ix = [self.index_of(params[0]), self.index_of(params[1])];
        let h = self.entity_handle();
        let e = Entity::point_2d(h, Self::SHAPE_GROUP.0, WORKPLANE.0, params.map(|p| p.0));
        Ok(PointId(self.insert(e, Geometry::Point { params, ix })?))
    }

    /// Adds a line segment from `a` to `b`.
    ///
    /// # Errors
    /// A point that does not exist, or the same point twice.
    pub fn add_line(&mut self, a: PointId, b: PointId) -> Result<LineId, SketchError> {
        self.want_point(a.into(), "line", "a")?;
        self.want_point(b.into(), "line", "b")?;
        if a == b {
            return Err(SketchError::SameShape {
                constraint: "line",
                shape: a.into(),
            });
        }
        let h = self.entity_handle();
        let e = Entity::line(h, Self::SHAPE_GROUP.0, Some(WORKPLANE.0), a.0 .0, b.0 .0);
        Ok(LineId(self.insert(e, Geometry::Line { points: [a, b] })?))
    }

    /// Adds a circle about `center`.
    ///
    /// # Errors
    /// A centre that does not exist, or a radius that is not a positive finite number.
    pub fn add_circle(&mut self, center: PointId, radius: f64) -> Result<CircleId, SketchError> {
        self.want_point(center.into(), "circle", "center")?;
        if !(radius.is_finite() && radius > 0.0) {
            return Err(SketchError::BadValue {
                what: "radius",
                value: radius,
                expected: "a positive finite number",
            });
        }
        let param = self.param(radius)?;
        let ix = self.index_of(param);
        let dh = self.entity_handle();
        let radius_e = self.sys.add_entity(Entity::distance(
            dh,
            Self::SHAPE_GROUP.0,
            Some(WORKPLANE.0),
            param.0,
        ))?;
        let h = self.entity_handle();
        let e = Entity::circle(
            h,
            Self::SHAPE_GROUP.0,
            Some(WORKPLANE.0),
            center.0 .0,
            NORMAL_2D.0,
            dh,
        );
        Ok(CircleId(self.insert(
            e,
            Geometry::Circle {
                center,
                radius: radius_e,
                param,
                ix,
            },
        )?))
    }

    /// Adds an arc about `center`, counter-clockwise from `start` to `end`. The end is kept at
    /// the start's distance from the centre by the arc itself.
    ///
    /// # Errors
    /// A point that does not exist, or the same point twice.
    pub fn add_arc(
        &mut self,
        center: PointId,
        start: PointId,
        end: PointId,
    ) -> Result<ArcId, SketchError> {
        for (f, p) in [("center", center), ("start", start), ("end", end)] {
            self.want_point(p.into(), "arc", f)?;
        }
        for (x, y) in [(center, start), (center, end), (start, end)] {
            if x == y {
                return Err(SketchError::SameShape {
                    constraint: "arc",
                    shape: x.into(),
                });
            }
        }
        let g = Self::SHAPE_GROUP.0;
        let (s0, s1) = (self.entity_handle(), self.entity_handle());
        self.sys.add_entity(Entity::line(
            s0,
            g,
            Some(WORKPLANE.0),
            center.0 .0,
            start.0 .0,
        ))?;
        self.sys.add_entity(Entity::line(
            s1,
            g,
            Some(WORKPLANE.0),
            center.0 .0,
            end.0 .0,
        ))?;
        let h = self.entity_handle();
        let e = Entity::arc(
            h,
            g,
            WORKPLANE.0,
            NORMAL_2D.0,
            center.0 .0,
            start.0 .0,
            end.0 .0,
        );
        Ok(ArcId(self.insert(
            e,
            Geometry::Arc {
                center,
                start,
                end,
                spokes: [EntityId(s0), EntityId(s1)],
            },
        )?))
    }

    /// Adds a cubic Bézier with control points `p0` .. `p3`.
    ///
    /// # Errors
    /// A point that does not exist.
    pub fn add_cubic(&mut self, points: [PointId; 4]) -> Result<CubicId, SketchError> {
        for p in points {
            self.want_point(p.into(), "cubic", "points")?;
        }
        let h = self.entity_handle();
        let e = Entity::cubic(
            h,
            Self::SHAPE_GROUP.0,
            Some(WORKPLANE.0),
            points.map(|p| p.0 .0),
        );
        Ok(CubicId(self.insert(e, Geometry::Cubic { points })?))
    }

    /// Marks a shape as construction geometry (drawn dashed, not part of the profile) or not.
    /// It is solved like any other shape.
    ///
    /// # Errors
    /// No such shape.
    pub fn set_construction(
        &mut self,
        shape: impl Into<ShapeId>,
        construction: bool,
    ) -> Result<(), SketchError> {
        let s = shape.into();
        self.shapes
            .get_mut(&s.0)
            .ok_or(SketchError::NoShape(s))?
            .construction = construction;
        Ok(())
    }

    /// Whether entity `e` is a shape marked as construction geometry.
    #[must_use]
    pub fn is_construction(&self, e: EntityId) -> bool {
        self.shapes.get(&e).is_some_and(|s| s.construction)
    }

    /// The kind of a shape, or `None` when there is no such shape.
    #[must_use]
    pub fn kind(&self, shape: impl Into<ShapeId>) -> Option<ShapeKind> {
        self.shapes.get(&shape.into().0).map(|s| s.geometry.kind())
    }

    /// Every shape, in the order made.
    pub fn shapes(&self) -> impl Iterator<Item = (ShapeId, ShapeKind)> + '_ {
        self.shapes
            .iter()
            .map(|(h, s)| (ShapeId(*h), s.geometry.kind()))
    }

    /// The shape as a point, when it is one.
    #[must_use]
    pub fn as_point(&self, s: ShapeId) -> Option<PointId> {
        (self.kind(s) == Some(ShapeKind::Point)).then_some(PointId(s.0))
    }

    /// The shape as a line, when it is one.
    #[must_use]
    pub fn as_line(&self, s: ShapeId) -> Option<LineId> {
        (self.kind(s) == Some(ShapeKind::Line)).then_some(LineId(s.0))
    }

    /// The shape as a circle, when it is one.
    #[must_use]
    pub fn as_circle(&self, s: ShapeId) -> Option<CircleId> {
        (self.kind(s) == Some(ShapeKind::Circle)).then_some(CircleId(s.0))
    }

    /// The shape as an arc, when it is one.
    #[must_use]
    pub fn as_arc(&self, s: ShapeId) -> Option<ArcId> {
        (self.kind(s) == Some(ShapeKind::Arc)).then_some(ArcId(s.0))
    }

    /// The shape as a cubic, when it is one.
    #[must_use]
    pub fn as_cubic(&self, s: ShapeId) -> Option<CubicId> {
        (self.kind(s) == Some(ShapeKind::Cubic)).then_some(CubicId(s.0))
    }

    /// The points that define a shape (a point itself; a circle its centre; an arc its
    /// centre, start and end), or none when there is no such shape.
    #[must_use]
    pub fn defining_points(&self, shape: impl Into<ShapeId>) -> Vec<PointId> {
        let s = shape.into();
        self.shapes
            .get(&s.0)
            .map(|sh| sh.geometry.points(s.0))
            .unwrap_or_default()
    }

    /// The two ends of a line.
    ///
    /// # Panics
    /// A handle from another sketch, or of a removed line.
    #[must_use]
    pub fn line_points(&self, l: LineId) -> [PointId; 2] {
        match &self.shapes[&l.0].geometry {
            Geometry::Line { points } => *points,
            _ => unreachable!("a line handle names a line"),
        }
    }

    /// Centre, start and end of an arc.
    ///
    /// # Panics
    /// A handle from another sketch, or of a removed arc.
    #[must_use]
    pub fn arc_points(&self, a: ArcId) -> [PointId; 3] {
        match &self.shapes[&a.0].geometry {
            Geometry::Arc {
                center, start, end, ..
            } => [*center, *start, *end],
            _ => unreachable!("an arc handle names an arc"),
        }
    }

    /// The centre of a circle.
    ///
    /// # Panics
    /// A handle from another sketch, or of a removed circle.
    #[must_use]
    pub fn circle_center(&self, c: CircleId) -> PointId {
        match &self.shapes[&c.0].geometry {
            Geometry::Circle { center, .. } => *center,
            _ => unreachable!("a circle handle names a circle"),
        }
    }

    /// The positions of a point's x and y in the parameter vector ([`System::params`]).
    ///
    /// [`System::params`]: crate::System::params
    ///
    /// # Panics
    /// A handle from another sketch, or of a removed point.
    #[must_use]
    pub fn point_indexes(&self, p: PointId) -> [usize; 2] {
        match &self.shapes[&p.0].geometry {
            Geometry::Point { ix, .. } => *ix,
            _ => unreachable!("a point handle names a point"),
        }
    }

    /// The parameters holding a point's x and y.
    ///
    /// # Panics
    /// A handle from another sketch, or of a removed point.
    #[must_use]
    pub fn point_params(&self, p: PointId) -> [ParamId; 2] {
        match &self.shapes[&p.0].geometry {
            Geometry::Point { params, .. } => *params,
            _ => unreachable!("a point handle names a point"),
        }
    }

    /// A point's coordinates, read by index from the parameter vector.
    ///
    /// # Panics
    /// A handle from another sketch, or of a removed point.
    #[must_use]
    pub fn point(&self, p: PointId) -> [f64; 2] {
        let [i, j] = self.point_indexes(p);
        let v = self.sys.params();
        [v[i].val, v[j].val]
    }

    /// A line's start and end.
    ///
    /// # Panics
    /// As [`Sketch::line_points`].
    #[must_use]
    pub fn line(&self, l: LineId) -> [[f64; 2]; 2] {
        self.line_points(l).map(|p| self.point(p))
    }

    /// A circle's centre and radius.
    ///
    /// # Panics
    /// As [`Sketch::circle_center`].
    #[must_use]
    pub fn circle(&self, c: CircleId) -> ([f64; 2], f64) {
        match &self.shapes[&c.0].geometry {
            Geometry::Circle { center, ix, .. } => {
                (self.point(*center), self.sys.params()[*ix].val)
            }
            _ => unreachable!("a circle handle names a circle"),
        }
    }

    /// An arc's centre, ends and angles.
    ///
    /// # Panics
    /// As [`Sketch::arc_points`].
    #[must_use]
    pub fn arc(&self, a: ArcId) -> ArcGeometry {
        let [c, s, e] = self.arc_points(a).map(|p| self.point(p));
        let ang = |p: [f64; 2]| (p[1] - c[1]).atan2(p[0] - c[0]).to_degrees();
        let (a0, a1) = (ang(s), ang(e));
        ArcGeometry {
            center: c,
            start: s,
            end: e,
            radius: (s[0] - c[0]).hypot(s[1] - c[1]),
            start_angle: a0,
            end_angle: a1,
            sweep: (a1 - a0).rem_euclid(360.0),
        }
    }

    /// A cubic's four control points.
    ///
    /// # Panics
    /// A handle from another sketch, or of a removed cubic.
    #[must_use]
    pub fn cubic(&self, c: CubicId) -> [[f64; 2]; 4] {
        match &self.shapes[&c.0].geometry {
            Geometry::Cubic { points } => points.map(|p| self.point(p)),
            _ => unreachable!("a cubic handle names a cubic"),
        }
    }

    /// Turns positive every circle radius a solve left negative. The core holds a circle's
    /// points at |r| (SolveSpace writes `d² - r²`), so Newton can take a free radius through
    /// zero and read `okay` with the same circle drawn at -r; a user reads a radius as a
    /// length, and so does every measure of the sketch. Each equation a sketch writes on a
    /// circle's radius reads |r|, holds a positive value, or equates two radii (which went
    /// negative together, and turn together), so the drawing is unchanged.
    /// `radii` are the circles' ([`Sketch::circle_radii`]), read once by a drag for all its
    /// steps.
    pub(crate) fn positive_radii(&mut self, radii: &[(ParamId, usize)]) {
        for &(p, ix) in radii {
            let r = self.sys.params()[ix].val;
            if r < 0.0 {
                self.sys.set_value(p, -r);
            }
        }
    }

    /// Every circle's radius parameter and its position in the parameter vector.
    pub(crate) fn circle_radii(&self) -> Vec<(ParamId, usize)> {
        self.shapes
            .values()
            .filter_map(|s| match s.geometry {
                Geometry::Circle { param, ix, .. } => Some((param, ix)),
                _ => None,
            })
            .collect()
    }

    /// The position of a circle's radius in the parameter vector.
    pub(crate) fn circle_radius_index(&self, c: CircleId) -> usize {
        match &self.shapes[&c.0].geometry {
            Geometry::Circle { ix, .. } => *ix,
            _ => unreachable!("a circle handle names a circle"),
        }
    }

    /// The radius of a circle or arc.
    pub(crate) fn radius_of(&self, shape: EntityId) -> f64 {
        match &self.shapes[&shape].geometry {
            Geometry::Circle { ix, .. } => self.sys.params()[*ix].val,
            Geometry::Arc { .. } => self.arc(ArcId(shape)).radius,
            _ => unreachable!("checked: a circle or arc"),
        }
    }

    /// The centre of a circle or arc.
    pub(crate) fn center_of(&self, shape: EntityId) -> PointId {
        match &self.shapes[&shape].geometry {
            Geometry::Circle { center, .. } | Geometry::Arc { center, .. } => *center,
            _ => unreachable!("checked: a circle or arc"),
        }
    }

    /// Moves a point (a value edit: a drag in progress elsewhere keeps its compiled solver).
    ///
    /// # Errors
    /// No such point, or a coordinate that is not finite.
    pub fn move_point(&mut self, p: PointId, to: [f64; 2]) -> Result<(), SketchError> {
        self.want_point(p.into(), "move_point", "point")?;
        finite("x", to[0])?;
        finite("y", to[1])?;
        let params = self.point_params(p);
        self.sys.set_value(params[0], to[0]);
        self.sys.set_value(params[1], to[1]);
        Ok(())
    }

    pub(crate) fn want_point(
        &self,
        s: ShapeId,
        constraint: &'static str,
        field: &'static str,
    ) -> Result<(), SketchError> {
        self.want(s, constraint, field, &[ShapeKind::Point], "a point")
            .map(drop)
    }

    /// Checks that `s` exists and is one of `kinds`.
    pub(crate) fn want(
        &self,
        s: ShapeId,
        constraint: &'static str,
        field: &'static str,
        kinds: &[ShapeKind],
        expected: &'static str,
    ) -> Result<ShapeKind, SketchError> {
        let found = self.kind(s).ok_or(SketchError::NoShape(s))?;
        if kinds.contains(&found) {
            Ok(found)
        } else {
            Err(SketchError::WrongShape {
                constraint,
                field,
                shape: s,
                found,
                expected,
            })
        }
    }

    fn index_of(&self, p: ParamId) -> usize {
        self.sys.param_index(p).expect("just added")
    }

    /// Brings every shape's parameter indexes up to date after parameters were removed.
    pub(crate) fn reindex(&mut self) {
        let sys = &self.sys;
        for s in self.shapes.values_mut() {
            match &mut s.geometry {
                Geometry::Point { params, ix } => {
                    *ix = params.map(|p| sys.param_index(p).expect("a shape's parameter"));
                }
                Geometry::Circle { param, ix, .. } => {
                    *ix = sys.param_index(*param).expect("a shape's parameter");
                }
                _ => {}
            }
        }
        self.indexed_at = self.sys.revision();
    }

    /// Removes a shape, every shape built on it (the lines, circles, arcs and cubics through
    /// a removed point) and every user constraint that refers to any of them. A line's
    /// points are shapes of their own and stay.
    ///
    /// # Errors
    /// No such shape.
    pub fn remove_shape(&mut self, shape: impl Into<ShapeId>) -> Result<Removed, SketchError> {
        let s = shape.into();
        if !self.shapes.contains_key(&s.0) {
            return Err(SketchError::NoShape(s));
        }
        let mut gone: Vec<EntityId> = vec![s.0];
        if matches!(self.shapes[&s.0].geometry, Geometry::Point { .. }) {
            for (h, sh) in &self.shapes {
                if *h != s.0 && sh.geometry.points(*h).contains(&PointId(s.0)) {
                    gone.push(*h);
                }
            }
        }
        let set: BTreeSet<EntityId> = gone.iter().copied().collect();
        let users: Vec<SketchConstraintId> = self
            .constraints
            .iter()
            .filter(|(_, r)| r.spec.shapes().iter().any(|(_, x)| set.contains(&x.0)))
            .map(|(id, _)| *id)
            .collect();
        for id in &users {
            self.remove_constraint(*id)?;
        }
        // Shapes built on others go first, so that nothing refers to what is removed.
        for h in gone.iter().rev() {
            let sh = self.shapes.remove(h).expect("listed above");
            self.sys.remove_entity(*h)?;
            match sh.geometry {
                Geometry::Point { params, .. } => {
                    for p in params {
                        self.sys.remove_param(p)?;
                    }
                }
                Geometry::Circle { radius, param, .. } => {
                    self.sys.remove_entity(radius)?;
                    self.sys.remove_param(param)?;
                }
                Geometry::Arc { spokes, .. } => {
                    for e in spokes {
                        self.sys.remove_entity(e)?;
                    }
                }
                Geometry::Line { .. } | Geometry::Cubic { .. } => {}
            }
        }
        self.reindex();
        Ok(Removed {
            shapes: gone.into_iter().map(ShapeId).collect(),
            constraints: users,
        })
    }
}
