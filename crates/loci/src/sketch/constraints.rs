//! User constraints: adding, checking, finding, locking and removing them, with everything
//! each wrote (the typed calls are in `calls`, the writing of core constraints in `write`).

use super::{PointId, ShapeId, ShapeKind as S, Sketch, SketchConstraintId, SketchError, Spec};
use crate::model::{ConstraintId, EntityId, ParamId};

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
    if !(v.is_finite() && v.abs() <= crate::MAX_MAGNITUDE) {
        return bad("a finite number of size at most 1e100");
    }
    match spec {
        Spec::Length { .. } | Spec::Distance { .. } if v < 0.0 => bad("a distance of 0 or more"),
        Spec::Radius { .. } | Spec::Diameter { .. } if v <= 0.0 => bad("a positive size"),
        Spec::ArcSweep { .. } if !(v > 0.0 && v < 360.0) => bad("a sweep in (0, 360) degrees"),
        _ => Ok(()),
    }
}
