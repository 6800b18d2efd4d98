//! The system: every parameter, entity and constraint, looked up by handle.

use super::index::HandleIndex;
use super::{Constraint, ConstraintId, Entity, EntityId, ObjectId, Param, ParamId};
use crate::error::ModelError;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// A whole problem: parameters, entities and constraints, kept in the order they were added.
///
/// Handles are checked for zero and duplicates as objects are added; references between
/// objects are checked by [`System::validate`], which every solve runs first.
#[derive(Clone, Debug, Default)]
pub struct System {
    params: Vec<Param>,
    entities: Vec<Entity>,
    constraints: Vec<Constraint>,
    param_ix: HandleIndex,
    entity_ix: HandleIndex,
    constraint_ix: HandleIndex,
}

impl System {
    /// An empty system.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a parameter.
    ///
    /// # Errors
    /// A zero or repeated handle, or a value that is not finite.
    pub fn add_param(&mut self, p: Param) -> Result<ParamId, ModelError> {
        if p.h.is_zero() {
            return Err(ModelError::ZeroHandle {
                what: "param",
                index: self.params.len(),
            });
        }
        if self.param_ix.contains(p.h.0) {
            return Err(ModelError::DuplicateHandle {
                object: ObjectId::Param(p.h),
            });
        }
        if !p.val.is_finite() {
            return Err(ModelError::NonFinite {
                owner: ObjectId::Param(p.h),
                field: "val",
                value: p.val,
            });
        }
        self.param_ix.insert(p.h.0, self.params.len());
        self.params.push(p);
        Ok(p.h)
    }

    /// Adds an entity. Its references are checked by [`System::validate`].
    ///
    /// # Errors
    /// A zero or repeated handle.
    pub fn add_entity(&mut self, e: Entity) -> Result<EntityId, ModelError> {
        if e.h.is_zero() {
            return Err(ModelError::ZeroHandle {
                what: "entity",
                index: self.entities.len(),
            });
        }
        if self.entity_ix.contains(e.h.0) {
            return Err(ModelError::DuplicateHandle {
                object: ObjectId::Entity(e.h),
            });
        }
        let h = e.h;
        self.entity_ix.insert(h.0, self.entities.len());
        self.entities.push(e);
        Ok(h)
    }

    /// Adds a constraint. Its references are checked by [`System::validate`].
    ///
    /// # Errors
    /// A zero or repeated handle, or a value that is not finite.
    pub fn add_constraint(&mut self, c: Constraint) -> Result<ConstraintId, ModelError> {
        if c.h.is_zero() {
            return Err(ModelError::ZeroHandle {
                what: "constraint",
                index: self.constraints.len(),
            });
        }
        if self.constraint_ix.contains(c.h.0) {
            return Err(ModelError::DuplicateHandle {
                object: ObjectId::Constraint(c.h),
            });
        }
        if !c.val.is_finite() {
            return Err(ModelError::NonFinite {
                owner: ObjectId::Constraint(c.h),
                field: "val",
                value: c.val,
            });
        }
        let h = c.h;
        self.constraint_ix.insert(h.0, self.constraints.len());
        self.constraints.push(c);
        Ok(h)
    }

    /// Removes a constraint; returns it if it was there.
    pub fn remove_constraint(&mut self, h: ConstraintId) -> Option<Constraint> {
        let i = self.constraint_ix.remove(h.0)?;
        let c = self.constraints.remove(i);
        self.constraint_ix
            .update_positions(|v| if v > i { v - 1 } else { v });
        Some(c)
    }

    /// All parameters, in the order added.
    #[must_use]
    pub fn params(&self) -> &[Param] {
        &self.params
    }

    /// All entities, in the order added.
    #[must_use]
    pub fn entities(&self) -> &[Entity] {
        &self.entities
    }

    /// All constraints, in the order added.
    #[must_use]
    pub fn constraints(&self) -> &[Constraint] {
        &self.constraints
    }

    /// The parameter with handle `h`.
    #[must_use]
    pub fn param(&self, h: ParamId) -> Option<&Param> {
        self.param_ix.get(h.0).map(|i| &self.params[i])
    }

    /// The entity with handle `h`.
    #[must_use]
    pub fn entity(&self, h: EntityId) -> Option<&Entity> {
        self.entity_ix.get(h.0).map(|i| &self.entities[i])
    }

    /// The constraint with handle `h`.
    #[must_use]
    pub fn constraint(&self, h: ConstraintId) -> Option<&Constraint> {
        self.constraint_ix.get(h.0).map(|i| &self.constraints[i])
    }

    /// Position of parameter `h` in [`System::params`].
    #[must_use]
    pub fn param_index(&self, h: ParamId) -> Option<usize> {
        self.param_ix.get(h.0)
    }

    /// Position of entity `h` in [`System::entities`].
    #[must_use]
    pub fn entity_index(&self, h: EntityId) -> Option<usize> {
        self.entity_ix.get(h.0)
    }

    /// The value of parameter `h`.
    #[must_use]
    pub fn value(&self, h: ParamId) -> Option<f64> {
        self.param(h).map(|p| p.val)
    }

    /// Sets the value of parameter `h`; returns false when there is no such parameter.
    pub fn set_value(&mut self, h: ParamId, val: f64) -> bool {
        match self.param_ix.get(h.0) {
            Some(i) => {
                self.params[i].val = val;
                true
            }
            None => false,
        }
    }

    /// Mutable access to every parameter value, in [`System::params`] order.
    pub fn params_mut(&mut self) -> impl Iterator<Item = &mut Param> {
        self.params.iter_mut()
    }

    /// Mutable access to a constraint, e.g. to change its value between solves.
    pub fn constraint_mut(&mut self, h: ConstraintId) -> Option<&mut Constraint> {
        self.constraint_ix
            .get(h.0)
            .map(|i| &mut self.constraints[i])
    }

    /// Builds a system from lists, checking handles as [`System::add_param`] and friends do.
    ///
    /// # Errors
    /// The first zero, repeated or non-finite item.
    pub fn from_parts(
        params: Vec<Param>,
        entities: Vec<Entity>,
        constraints: Vec<Constraint>,
    ) -> Result<Self, ModelError> {
        let mut s = System::new();
        for p in params {
            s.add_param(p)?;
        }
        for e in entities {
            s.add_entity(e)?;
        }
        for c in constraints {
            s.add_constraint(c)?;
        }
        Ok(s)
    }
}

#[derive(Serialize, Deserialize)]
struct Parts {
    #[serde(default)]
    params: Vec<Param>,
    #[serde(default)]
    entities: Vec<Entity>,
    #[serde(default)]
    constraints: Vec<Constraint>,
}

#[derive(Serialize)]
struct PartsRef<'a> {
    params: &'a [Param],
    entities: &'a [Entity],
    constraints: &'a [Constraint],
}

impl Serialize for System {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        PartsRef {
            params: &self.params,
            entities: &self.entities,
            constraints: &self.constraints,
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for System {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let p = Parts::deserialize(d)?;
        System::from_parts(p.params, p.entities, p.constraints).map_err(serde::de::Error::custom)
    }
}
