//! Carried entities: points and normals whose place is a function of other parameters.
//!
//! A `point_n_rot_trans` is its base carried by a translation and a rotation, a `normal_n_rot`
//! its base turned by a rotation, a `point_n_trans` a point moved by a multiple of a
//! translation. Each has parameters of its own and an implicit equation tying them to what
//! carries it. When the solve of a group owns those parameters, the entity is read instead as
//! the expression itself (`PointRef::Moved`, `PointRef::Shifted`, `NormalRef::Turned`): every
//! equation on it reads the pose directly, its own parameters are no unknowns and its implicit
//! equation is gone (as many equations as unknowns, so the degrees of freedom do not change),
//! and its parameters are written from the solved pose afterwards. On a linked part or an
//! assembly component, a dozen unknowns per rigid body, all coupled through the four rotation
//! parameters, become none.
//!
//! An entity stays as it was (its own unknowns, its implicit equation) when anything else
//! reads its parameters, when a workplane is built on it (a workplane reads plain
//! coordinates), when what carries it is not a plain normal or 3D point, or when one of its
//! parameters is dragged (the solve moves that parameter least, so it must be an unknown).

use super::refs::{Ent, Locals, Resolver};
use crate::model::{EntityKind, GroupId, ParamId, System};
use std::cell::Cell;

thread_local! {
    /// Whether solves on this thread read carried entities as expressions.
    static ENABLED: Cell<bool> = const { Cell::new(true) };
}

/// Runs `f` with carried entities kept as unknowns with their implicit equations, as every
/// solve did before they were read as expressions: tests compare the two.
#[cfg(test)]
pub(crate) fn without<R>(f: impl FnOnce() -> R) -> R {
    struct Restore(bool);
    impl Drop for Restore {
        fn drop(&mut self) {
            ENABLED.with(|e| e.set(self.0));
        }
    }
    let _restore = Restore(ENABLED.with(|e| e.replace(false)));
    f()
}

/// The entities of one group's solve read as expressions.
#[derive(Clone, Debug, Default)]
pub(crate) struct Carried {
    /// By entity position: whether it is read as an expression.
    entity: Vec<bool>,
    /// By parameter position: whether it is the own parameter of such an entity.
    param: Vec<bool>,
    /// Positions of those entities, in model order.
    list: Vec<usize>,
}

/// Whether solves on this thread read carried entities as expressions (always, outside the
/// tests that compare the two ways).
pub(crate) fn as_expressions() -> bool {
    ENABLED.with(Cell::get)
}

impl Carried {
    /// The carried entities of `group` in `sys` when `dragged` parameters move least (none
    /// when expressions are switched off).
    pub fn of(sys: &System, group: GroupId, dragged: &[ParamId]) -> Self {
        if !ENABLED.with(Cell::get) {
            return Self::default();
        }
        let entities = sys.entities();
        // Most sketches have no carried entity at all: then nothing below is worth counting.
        let carried_kind = |k: &EntityKind| {
            matches!(
                k,
                EntityKind::PointNRotTrans { .. }
                    | EntityKind::NormalNRot { .. }
                    | EntityKind::PointNTrans { .. }
            )
        };
        if !entities
            .iter()
            .any(|e| e.group == group && carried_kind(&e.kind))
        {
            return Self::default();
        }
        let params = sys.params();
        // How many entities hold or read each parameter: an own parameter read by anything
        // else must stay an unknown.
        let mut uses = vec![0u8; params.len()];
        // A dragged parameter counts as a use of its own.
        for p in dragged {
            if let Some(i) = sys.param_index(*p) {
                uses[i] = uses[i].saturating_add(1);
            }
        }
        let mut on_plane = vec![false; entities.len()];
        for e in entities {
            for p in e.kind.params().iter().chain(e.kind.read_params()) {
                if let Some(i) = sys.param_index(*p) {
                    uses[i] = uses[i].saturating_add(1);
                }
            }
            if let EntityKind::Workplane { origin, normal } = &e.kind {
                for h in [origin, normal] {
                    if let Some(i) = sys.entity_index(*h) {
                        on_plane[i] = true;
                    }
                }
            }
        }
        let kind_of = |h| sys.entity(h).map(|e| &e.kind);
        let mut out = Self {
            entity: vec![false; entities.len()],
            param: vec![false; params.len()],
            list: Vec::new(),
        };
        for (i, e) in entities.iter().enumerate() {
            if e.group != group || on_plane[i] {
                continue;
            }
            let carrier_ok = match &e.kind {
                EntityKind::PointNRotTrans { rotation, .. }
                | EntityKind::NormalNRot { rotation, .. } => {
                    matches!(kind_of(*rotation), Some(EntityKind::NormalIn3d { .. }))
                }
                EntityKind::PointNTrans { base, .. } => {
                    matches!(kind_of(*base), Some(EntityKind::PointIn3d { .. }))
                }
                _ => false,
            };
            if !carrier_ok {
                continue;
            }
            // At most four own parameters (a normal's quaternion): on the stack.
            let mut own = [0usize; 4];
            let ps = e.kind.params();
            let mut found = ps.len() <= own.len();
            for (o, p) in own.iter_mut().zip(ps) {
                match sys.param_index(*p) {
                    Some(i) => *o = i,
                    None => found = false,
                }
            }
            let own = &own[..ps.len().min(4)];
            if !found
                || !own
                    .iter()
                    .all(|&p| params[p].group == group && uses[p] == 1)
            {
                continue;
            }
            out.entity[i] = true;
            for &p in own {
                out.param[p] = true;
            }
            out.list.push(i);
        }
        out
    }

    /// Whether the entity at position `index` is read as an expression.
    #[inline]
    pub fn entity(&self, index: usize) -> bool {
        self.entity.get(index).copied().unwrap_or(false)
    }

    /// Whether the parameter at position `index` is the own parameter of a carried entity
    /// (no unknown of the solve).
    #[inline]
    pub fn param(&self, index: usize) -> bool {
        self.param.get(index).copied().unwrap_or(false)
    }

    /// Whether no entity is carried.
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// The positions of the carried entities, in model order.
    #[cfg(test)]
    pub fn entities(&self) -> &[usize] {
        &self.list
    }

    /// Writes the own parameters of every carried entity from the values of what carries it
    /// (`values` by position in [`System::params`]), so that each implicit condition holds.
    pub fn write_back(&self, sys: &System, values: &mut [f64]) {
        if self.list.is_empty() {
            return;
        }
        let r = Resolver::carrying(sys, self);
        let mut x = Vec::new();
        for &i in &self.list {
            let e = &sys.entities()[i];
            let mut l = Locals::default();
            // The model was validated and resolved by the compile before this.
            let Ok(ent) = r.entity(crate::model::ObjectId::Entity(e.h), e.h, &mut l) else {
                continue;
            };
            x.clear();
            x.extend(l.params.iter().map(|&p| values[p as usize]));
            let g = super::refs::Geo {
                x: &x[..],
                k: &l.consts,
            };
            let (v, n) = match ent {
                Ent::Point(p) => {
                    let p = g.pos(&p);
                    ([p.x, p.y, p.z, 0.0], 3)
                }
                Ent::Normal(n) => {
                    let q = g.normal(&n);
                    ([q.w, q.x, q.y, q.z], 4)
                }
                _ => continue,
            };
            let own = e.kind.params().iter().filter_map(|p| sys.param_index(*p));
            for (p, &v) in own.zip(&v[..n]) {
                values[p] = v;
            }
        }
    }
}
