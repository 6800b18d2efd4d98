//! The system: every parameter, entity and constraint, looked up by handle.

use super::index::HandleIndex;
use super::{Constraint, ConstraintId, Entity, EntityId, GroupId, ObjectId, Param, ParamId};
use crate::error::ModelError;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::ops::{Deref, DerefMut};
use std::sync::atomic::{AtomicU64, Ordering};

/// A whole problem: parameters, entities and constraints, kept in the order they were added.
///
/// Handles are checked for zero and duplicates as objects are added; references between
/// objects are checked by [`System::validate`], which every solve runs first.
///
/// Every structural edit (adding or removing an object, changing what a constraint is or
/// refers to, moving a parameter to another group) advances [`System::revision`]; value edits
/// (parameter values, constraint dimensions) do not. A [`crate::Solver`] keeps its compiled
/// structure exactly as long as the system and its revision are the ones it compiled.
#[derive(Debug)]
pub struct System {
    params: Vec<Param>,
    entities: Vec<Entity>,
    constraints: Vec<Constraint>,
    param_ix: HandleIndex,
    entity_ix: HandleIndex,
    constraint_ix: HandleIndex,
    /// Which system this is: unique among the systems of the process, a clone included.
    id: u64,
    /// Advanced by every structural edit.
    revision: u64,
}

/// The source of [`System`] identities.
static NEXT_SYSTEM: AtomicU64 = AtomicU64::new(1);

fn fresh_id() -> u64 {
    NEXT_SYSTEM.fetch_add(1, Ordering::Relaxed)
}

impl Default for System {
    fn default() -> Self {
        Self {
            params: Vec::new(),
            entities: Vec::new(),
            constraints: Vec::new(),
            param_ix: HandleIndex::default(),
            entity_ix: HandleIndex::default(),
            constraint_ix: HandleIndex::default(),
            id: fresh_id(),
            revision: 0,
        }
    }
}

impl Clone for System {
    /// A copy with an identity of its own: a solver that compiled the original does not take
    /// the copy for it.
    fn clone(&self) -> Self {
        Self {
            params: self.params.clone(),
            entities: self.entities.clone(),
            constraints: self.constraints.clone(),
            param_ix: self.param_ix.clone(),
            entity_ix: self.entity_ix.clone(),
            constraint_ix: self.constraint_ix.clone(),
            id: fresh_id(),
            revision: self.revision,
        }
    }
}

impl System {
    /// An empty system.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// The structural revision: advanced by every edit that changes what the equations are
    /// (adding or removing objects, changing a constraint's kind, references, workplane, group
    /// or flags, a parameter's group), and by nothing that changes values only.
    #[must_use]
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// This system's identity and revision: equal for two calls exactly when nothing
    /// structural changed in between, on the same system.
    pub(crate) fn structure_key(&self) -> (u64, u64) {
        (self.id, self.revision)
    }

    fn touch(&mut self) {
        self.revision += 1;
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
        super::validate::usable(ObjectId::Param(p.h), "val", p.val)?;
        self.param_ix.insert(p.h.0, self.params.len());
        self.params.push(p);
        self.touch();
        Ok(p.h)
    }

    /// Adds the xy plane as a workplane in `group`, the setup every 2D sketch of the SolveSpace
    /// model starts with: the origin (0, 0, 0) and the identity quaternion (1, 0, 0, 0) in the
    /// seven parameters `first_param..=first_param + 6`, then the origin point
    /// `entities[0]`, the normal `entities[1]` and the workplane `entities[2]`, whose handle
    /// it returns.
    ///
    /// ```
    /// # use loci::System;
    /// let mut sys = System::new();
    /// let wp = sys.add_xy_workplane(1, 1, [101, 102, 200])?;
    /// assert_eq!((wp.0, sys.params().len(), sys.entities().len()), (200, 7, 3));
    /// # Ok::<(), loci::ModelError>(())
    /// ```
    ///
    /// # Errors
    /// A zero or repeated handle (nothing is added then), as [`System::add_param`] and
    /// [`System::add_entity`] say.
    pub fn add_xy_workplane(
        &mut self,
        group: u32,
        first_param: u32,
        entities: [u32; 3],
    ) -> Result<EntityId, ModelError> {
        let params: Vec<u32> = (0..7)
            .map(|i| first_param.checked_add(i))
            .collect::<Option<_>>()
            .ok_or(ModelError::ZeroHandle {
                what: "param",
                index: self.params.len(),
            })?;
        // Check every handle first, so that a failure leaves the system as it was.
        for &h in &params {
            if h == 0 {
                return Err(ModelError::ZeroHandle {
                    what: "param",
                    index: self.params.len(),
                });
            }
            if self.param_ix.contains(h) {
                return Err(ModelError::DuplicateHandle {
                    object: ObjectId::Param(ParamId(h)),
                });
            }
        }
        for (i, &h) in entities.iter().enumerate() {
            if h == 0 {
                return Err(ModelError::ZeroHandle {
                    what: "entity",
                    index: self.entities.len() + i,
                });
            }
            if self.entity(EntityId(h)).is_some() || entities[..i].contains(&h) {
                return Err(ModelError::DuplicateHandle {
                    object: ObjectId::Entity(EntityId(h)),
                });
            }
        }
        let values = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0];
        for (&h, v) in params.iter().zip(values) {
            self.add_param(Param::new(h, group, v))?;
        }
        let p = |i: usize| params[i];
        self.add_entity(Entity::point_3d(entities[0], group, [p(0), p(1), p(2)]))?;
        self.add_entity(Entity::normal_3d(
            entities[1],
            group,
            [p(3), p(4), p(5), p(6)],
        ))?;
        self.add_entity(Entity::workplane(
            entities[2],
            group,
            entities[0],
            entities[1],
        ))
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
        self.touch();
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
        super::validate::usable(ObjectId::Constraint(c.h), "val", c.val)?;
        let h = c.h;
        self.constraint_ix.insert(h.0, self.constraints.len());
        self.constraints.push(c);
        self.touch();
        Ok(h)
    }

    /// Removes a constraint; returns it if it was there.
    pub fn remove_constraint(&mut self, h: ConstraintId) -> Option<Constraint> {
        let i = self.constraint_ix.remove(h.0)?;
        let c = self.constraints.remove(i);
        self.constraint_ix
            .update_positions(|v| if v > i { v - 1 } else { v });
        self.touch();
        Some(c)
    }

    /// Removes an entity that nothing refers to any more; returns it, or `None` when there is
    /// no such entity. A structural edit. Its parameters stay (remove them with
    /// [`System::remove_param`]).
    ///
    /// # Errors
    /// [`ModelError::InUse`] naming the first entity (as workplane or reference) or constraint
    /// that still refers to it; nothing is removed then.
    pub fn remove_entity(&mut self, h: EntityId) -> Result<Option<Entity>, ModelError> {
        let Some(i) = self.entity_ix.get(h.0) else {
            return Ok(None);
        };
        let in_use = |user| ModelError::InUse {
            object: ObjectId::Entity(h),
            user,
        };
        if let Some(e) = self.entities.iter().find(|e| {
            e.h != h && (e.workplane == Some(h) || e.kind.references().iter().any(|&(_, r)| r == h))
        }) {
            return Err(in_use(ObjectId::Entity(e.h)));
        }
        if let Some(c) = self
            .constraints
            .iter()
            .find(|c| c.workplane == Some(h) || c.fields().contains(&Some(h)))
        {
            return Err(in_use(ObjectId::Constraint(c.h)));
        }
        self.entity_ix.remove(h.0);
        let e = self.entities.remove(i);
        self.entity_ix
            .update_positions(|v| if v > i { v - 1 } else { v });
        self.touch();
        Ok(Some(e))
    }

    /// Removes a parameter that no entity holds or reads any more; returns it, or `None` when
    /// there is no such parameter. A structural edit.
    ///
    /// # Errors
    /// [`ModelError::InUse`] naming the first entity that still holds or reads it.
    pub fn remove_param(&mut self, h: ParamId) -> Result<Option<Param>, ModelError> {
        let Some(i) = self.param_ix.get(h.0) else {
            return Ok(None);
        };
        if let Some(e) = self
            .entities
            .iter()
            .find(|e| e.kind.params().contains(&h) || e.kind.read_params().contains(&h))
        {
            return Err(ModelError::InUse {
                object: ObjectId::Param(h),
                user: ObjectId::Entity(e.h),
            });
        }
        self.param_ix.remove(h.0);
        let p = self.params.remove(i);
        self.param_ix
            .update_positions(|v| if v > i { v - 1 } else { v });
        self.touch();
        Ok(Some(p))
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
    // This and the look-ups below are made per reference in validation and compilation; the
    // WebAssembly build called them out of line (`entity` alone was 3% of a small solve).
    #[must_use]
    #[inline]
    pub fn param(&self, h: ParamId) -> Option<&Param> {
        self.param_ix.get(h.0).map(|i| &self.params[i])
    }

    /// The entity with handle `h`.
    #[must_use]
    #[inline]
    pub fn entity(&self, h: EntityId) -> Option<&Entity> {
        self.entity_ix.get(h.0).map(|i| &self.entities[i])
    }

    /// The constraint with handle `h`.
    #[must_use]
    #[inline]
    pub fn constraint(&self, h: ConstraintId) -> Option<&Constraint> {
        self.constraint_ix.get(h.0).map(|i| &self.constraints[i])
    }

    /// Position of parameter `h` in [`System::params`].
    #[must_use]
    #[inline]
    pub fn param_index(&self, h: ParamId) -> Option<usize> {
        self.param_ix.get(h.0)
    }

    /// Position of entity `h` in [`System::entities`].
    #[must_use]
    #[inline]
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

    /// Mutable access to every parameter, in [`System::params`] order. A parameter may change
    /// group here, so this counts as a structural edit; to change values only, use
    /// [`System::values_mut`] or [`System::set_value`].
    pub fn params_mut(&mut self) -> impl Iterator<Item = &mut Param> {
        self.touch();
        self.params.iter_mut()
    }

    /// Mutable access to every parameter value, in [`System::params`] order: a value edit,
    /// which keeps a [`crate::Solver`]'s compiled structure.
    pub fn values_mut(&mut self) -> impl Iterator<Item = &mut f64> {
        self.params.iter_mut().map(|p| &mut p.val)
    }

    /// Every group that a parameter, entity or constraint belongs to, in increasing order.
    #[must_use]
    pub fn groups(&self) -> Vec<GroupId> {
        let mut g: Vec<GroupId> = self
            .params
            .iter()
            .map(|p| p.group)
            .chain(self.entities.iter().map(|e| e.group))
            .chain(self.constraints.iter().map(|c| c.group))
            .collect();
        g.sort_unstable();
        g.dedup();
        g
    }

    /// Whether a parameter, entity or constraint belongs to `group`: `groups().contains(&group)`
    /// without building the list.
    pub(crate) fn has_group(&self, group: GroupId) -> bool {
        self.constraints.iter().any(|c| c.group == group)
            || self.params.iter().any(|p| p.group == group)
            || self.entities.iter().any(|e| e.group == group)
    }

    /// Writes `values` (one per parameter, in [`System::params`] order) into the parameters of
    /// `group`: a value edit.
    pub(crate) fn write_group_values(&mut self, group: GroupId, values: &[f64]) {
        for (p, &v) in self.params.iter_mut().zip(values) {
            if p.group == group {
                p.val = v;
            }
        }
    }

    /// Mutable access to a constraint. Changing only `val` is a value edit; changing anything
    /// else (kind, workplane, references, group, flags) is a structural one, noticed when the
    /// returned guard is dropped. The handle cannot change here: an edited `h` is put back.
    pub fn constraint_mut(&mut self, h: ConstraintId) -> Option<ConstraintMut<'_>> {
        let i = self.constraint_ix.get(h.0)?;
        let before = self.constraints[i].clone();
        Some(ConstraintMut {
            sys: self,
            i,
            before,
        })
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

/// A constraint borrowed for editing from [`System::constraint_mut`]; on drop it advances the
/// system's revision if anything but the value changed.
pub struct ConstraintMut<'a> {
    sys: &'a mut System,
    i: usize,
    before: Constraint,
}

impl Deref for ConstraintMut<'_> {
    type Target = Constraint;
    fn deref(&self) -> &Constraint {
        &self.sys.constraints[self.i]
    }
}

impl DerefMut for ConstraintMut<'_> {
    fn deref_mut(&mut self) -> &mut Constraint {
        &mut self.sys.constraints[self.i]
    }
}

impl Drop for ConstraintMut<'_> {
    fn drop(&mut self) {
        let now = &mut self.sys.constraints[self.i];
        now.h = self.before.h;
        let structural = Constraint {
            val: self.before.val,
            ..now.clone()
        } != self.before;
        if structural {
            self.sys.touch();
        }
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
