//! Whole-model checks: every reference exists and has the right type.

use super::{
    Constraint, Entity, EntityId, EntityKind, EntityType, ObjectId, PlaneRule, System, FIELD_NAMES,
};
use crate::error::ModelError;

/// The largest size of a number in a model (a parameter's value, a constraint's dimension, a
/// constant an entity carries). The equations square and multiply coordinates: a distance
/// between points 1e160 apart overflows to infinity, and a solve read that as a conflict.
/// Far beyond any drawing, with the cube of a value still finite.
pub const MAX_MAGNITUDE: f64 = 1e100;

impl System {
    /// Checks every value and reference in the model: parameter and constraint values are
    /// finite and at most [`MAX_MAGNITUDE`] in size, parameters and entities exist, each has
    /// the type its field needs, a line joins two different points, 2D entities name a
    /// workplane, and constraints have the fields their type uses.
    ///
    /// # Errors
    /// The first problem found, naming the object and field.
    pub fn validate(&self) -> Result<(), ModelError> {
        self.validate_values()?;
        crate::par::first_error(self.entities(), |e| self.validate_entity(e))?;
        crate::par::first_error(self.constraints(), |c| self.validate_constraint(c))
    }

    /// The part of [`System::validate`] that value edits can break: every parameter value and
    /// constraint dimension is a finite number of size at most [`MAX_MAGNITUDE`].
    ///
    /// # Errors
    /// The first non-finite value, naming its object.
    pub fn validate_values(&self) -> Result<(), ModelError> {
        // `add_param` rejects non-finite values, but `set_value` and `values_mut` can still
        // store one, and a NaN would silently poison every equation that reads it.
        for p in self.params() {
            usable(ObjectId::Param(p.h), "val", p.val)?;
        }
        for c in self.constraints() {
            usable(ObjectId::Constraint(c.h), "val", c.val)?;
        }
        Ok(())
    }

    fn entity_of(
        &self,
        owner: ObjectId,
        field: &'static str,
        h: EntityId,
    ) -> Result<EntityType, ModelError> {
        self.entity(h)
            .map(|e| e.entity_type())
            .ok_or(ModelError::Dangling {
                owner,
                field,
                target: "entity",
                handle: h.0,
            })
    }

    fn expect(
        &self,
        owner: ObjectId,
        field: &'static str,
        h: EntityId,
        ok: impl Fn(EntityType) -> bool,
        expected: &'static str,
    ) -> Result<(), ModelError> {
        let found = self.entity_of(owner, field, h)?;
        if ok(found) {
            Ok(())
        } else {
            Err(ModelError::WrongKind {
                owner,
                field,
                entity: h,
                found,
                expected,
            })
        }
    }

    fn validate_entity(&self, e: &Entity) -> Result<(), ModelError> {
        let h = e.h;
        let owner = ObjectId::Entity(h);
        for (i, p) in e.kind.params().iter().enumerate() {
            if self.param(*p).is_none() {
                const NAMES: [&str; 4] = ["params[0]", "params[1]", "params[2]", "params[3]"];
                return Err(ModelError::Dangling {
                    owner,
                    field: NAMES[i],
                    target: "param",
                    handle: p.0,
                });
            }
        }
        for (i, p) in e.kind.read_params().iter().enumerate() {
            if self.param(*p).is_none() {
                const NAMES: [&str; 3] = ["translation[0]", "translation[1]", "translation[2]"];
                return Err(ModelError::Dangling {
                    owner,
                    field: NAMES[i],
                    target: "param",
                    handle: p.0,
                });
            }
        }
        let needs_wp = matches!(
            e.kind,
            EntityKind::PointIn2d { .. } | EntityKind::NormalIn2d | EntityKind::ArcOfCircle { .. }
        );
        match e.workplane {
            Some(wp) => {
                if wp == h {
                    return Err(ModelError::Cycle { entity: h });
                }
                self.expect(
                    owner,
                    "workplane",
                    wp,
                    |t| t == EntityType::Workplane,
                    "a workplane",
                )?;
            }
            None if needs_wp => {
                return Err(ModelError::MissingField {
                    owner,
                    field: "workplane",
                    expected: "a workplane",
                });
            }
            None => {}
        }
        let point = |t: EntityType| t.is_point();
        match &e.kind {
            EntityKind::Workplane { origin, normal } => {
                self.expect(
                    owner,
                    "origin",
                    *origin,
                    EntityType::is_point_3d,
                    "a 3D point",
                )?;
                self.expect(
                    owner,
                    "normal",
                    *normal,
                    EntityType::is_normal_3d,
                    "a 3D normal",
                )?;
            }
            EntityKind::PointNTrans { base, .. } => {
                if *base == h {
                    return Err(ModelError::Cycle { entity: h });
                }
                self.expect(owner, "base", *base, point, "a point")?;
            }
            EntityKind::PointNRotTrans { base, rotation, .. } => {
                finite(owner, "base", base)?;
                self.expect(
                    owner,
                    "rotation",
                    *rotation,
                    |t| t == EntityType::NormalIn3d,
                    "a 3D normal",
                )?;
            }
            EntityKind::NormalNRot { base, rotation, .. } => {
                finite(owner, "base", base)?;
                self.expect(
                    owner,
                    "rotation",
                    *rotation,
                    |t| t == EntityType::NormalIn3d,
                    "a 3D normal",
                )?;
            }
            EntityKind::LineSegment { .. } | EntityKind::Cubic { .. } => {
                let ps: &[EntityId] = match &e.kind {
                    EntityKind::LineSegment { points } => points,
                    EntityKind::Cubic { points } => points,
                    _ => &[],
                };
                const FIELDS: [&str; 4] = ["points[0]", "points[1]", "points[2]", "points[3]"];
                for (field, &r) in FIELDS.iter().zip(ps) {
                    self.expect(owner, field, r, point, "a point")?;
                }
                // A line from a point to itself has no direction: every equation that reads
                // one divides by its zero length, and its residual is not a number.
                if let EntityKind::LineSegment { points: [a, b] } = e.kind {
                    if a == b {
                        return Err(ModelError::WrongKind {
                            owner,
                            field: "points[1]",
                            entity: b,
                            found: self.entity_of(owner, "points[1]", b)?,
                            expected: "a point other than points[0]",
                        });
                    }
                }
            }
            EntityKind::Circle {
                center,
                normal,
                radius,
            } => {
                self.expect(owner, "center", *center, point, "a point")?;
                self.expect(owner, "normal", *normal, EntityType::is_normal, "a normal")?;
                self.expect(
                    owner,
                    "radius",
                    *radius,
                    |t| t == EntityType::Distance,
                    "a distance",
                )?;
            }
            EntityKind::ArcOfCircle {
                normal,
                center,
                start,
                end,
            } => {
                self.expect(owner, "normal", *normal, EntityType::is_normal, "a normal")?;
                self.expect(owner, "center", *center, point, "a point")?;
                self.expect(owner, "start", *start, point, "a point")?;
                self.expect(owner, "end", *end, point, "a point")?;
            }
            _ => {}
        }
        Ok(())
    }

    fn validate_constraint(&self, c: &Constraint) -> Result<(), ModelError> {
        let owner = ObjectId::Constraint(c.h);
        usable(owner, "val", c.val)?;
        let sig = c.kind.signature();
        match (sig.plane, c.workplane) {
            (PlaneRule::Required, None) => {
                return Err(ModelError::NeedsWorkplane {
                    constraint: c.h,
                    kind: c.kind,
                })
            }
            (PlaneRule::Either | PlaneRule::Required, Some(wp)) => {
                self.expect(
                    owner,
                    "workplane",
                    wp,
                    |t| t == EntityType::Workplane,
                    "a workplane",
                )?;
            }
            _ => {}
        }
        let fields = c.fields();
        for (i, want) in c.wants().iter().enumerate() {
            let Some(want) = *want else { continue };
            let field = FIELD_NAMES[i];
            let Some(h) = fields[i] else {
                let expected = if matches!(
                    c.kind,
                    super::ConstraintKind::Horizontal | super::ConstraintKind::Vertical
                ) {
                    "a line segment (or points in pt_a and pt_b)"
                } else {
                    want.describe()
                };
                return Err(ModelError::MissingField {
                    owner,
                    field,
                    expected,
                });
            };
            self.expect(owner, field, h, |t| want.accepts(t), want.describe())?;
        }
        Ok(())
    }
}

/// A constant an entity carries (a moved copy's base) must be a number loci solves with.
fn finite(owner: ObjectId, field: &'static str, vals: &[f64]) -> Result<(), ModelError> {
    vals.iter().try_for_each(|&v| usable(owner, field, v))
}

/// `value` of `owner`'s `field` is a finite number of size at most [`MAX_MAGNITUDE`].
pub(super) fn usable(owner: ObjectId, field: &'static str, value: f64) -> Result<(), ModelError> {
    if !value.is_finite() {
        Err(ModelError::NonFinite {
            owner,
            field,
            value,
        })
    } else if value.abs() > MAX_MAGNITUDE {
        Err(ModelError::OutOfRange {
            owner,
            field,
            value,
        })
    } else {
        Ok(())
    }
}
