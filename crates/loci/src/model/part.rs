//! A part of a system: some of its constraints and entities, with everything they refer to.

use super::{ConstraintId, EntityId, System};
use rustc_hash::FxHashSet as HashSet;

impl System {
    /// The constraints `constraints` and entities `entities` of this system as a system of
    /// their own, with the entities and parameters they refer to (directly or through other
    /// entities, workplanes included): the same handles, groups and values. This is what a
    /// user who kept only those constraints would solve. `None` if rebuilding fails, which a
    /// valid system never does.
    pub(crate) fn part(&self, constraints: &[ConstraintId], entities: &[EntityId]) -> Option<Self> {
        let mut seen: HashSet<EntityId> = HashSet::default();
        let mut stack: Vec<EntityId> = entities.to_vec();
        for c in constraints.iter().filter_map(|&h| self.constraint(h)) {
            stack.extend(c.fields().into_iter().flatten());
            stack.extend(c.workplane);
        }
        let mut params = HashSet::default();
        while let Some(h) = stack.pop() {
            if !seen.insert(h) {
                continue;
            }
            let Some(e) = self.entity(h) else {
                continue;
            };
            params.extend(e.kind.params().iter().copied());
            params.extend(e.kind.read_params().iter().copied());
            stack.extend(e.kind.references().into_iter().map(|(_, r)| r));
            stack.extend(e.workplane);
        }
        let kept: HashSet<ConstraintId> = constraints.iter().copied().collect();
        System::from_parts(
            self.params()
                .iter()
                .filter(|p| params.contains(&p.h))
                .cloned()
                .collect(),
            self.entities()
                .iter()
                .filter(|e| seen.contains(&e.h))
                .cloned()
                .collect(),
            self.constraints()
                .iter()
                .filter(|c| kept.contains(&c.h))
                .cloned()
                .collect(),
        )
        .ok()
    }
}
