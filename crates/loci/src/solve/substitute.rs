//! Substitution: equations `a = b` and `a = value` between parameters are removed by merging
//! parameters (union-find) instead of being solved. A merge that closes a cycle, or a second
//! value for a merged set, is still an equation: it is counted as redundant (when it agrees)
//! or conflicting (when it does not), with the chain of constraints that caused it.

use crate::equations::Owner;
use std::collections::VecDeque;

/// No arc.
const NONE: u32 = u32::MAX;

/// The merged parameter sets of one solve.
pub(crate) struct Substitution {
    parent: Vec<u32>,
    /// For a root: the value its set is fixed at, the parameter the value was applied to, and
    /// the equation that applied it.
    fixed: Vec<Option<(f64, u32, Owner)>>,
    /// Spanning forest of accepted merges, as adjacency lists threaded through one array (no
    /// list per parameter): the first arc out of each parameter, or `NONE`.
    head: Vec<u32>,
    /// Arcs: (neighbour, equation, next arc out of the same parameter).
    arcs: Vec<(u32, Owner, u32)>,
    /// Equations that depend on others here, each with the set of equations involved.
    pub redundant: Vec<Vec<Owner>>,
    /// Equations that contradict others here, each with the set involved.
    pub conflicts: Vec<Vec<Owner>>,
    /// How many unknowns the merges and fixes removed.
    pub removed: usize,
}

impl Substitution {
    /// `n` parameters, with room for `links` merges.
    pub fn new(n: usize, links: usize) -> Self {
        Self {
            parent: (0..n as u32).collect(),
            fixed: vec![None; n],
            head: vec![NONE; n],
            arcs: Vec::with_capacity(links),
            redundant: Vec::new(),
            conflicts: Vec::new(),
            removed: 0,
        }
    }

    pub fn find(&mut self, mut a: usize) -> usize {
        while self.parent[a] as usize != a {
            let g = self.parent[self.parent[a] as usize];
            self.parent[a] = g;
            a = g as usize;
        }
        a
    }

    /// The value a parameter's set is fixed at, if any.
    pub fn fixed_value(&mut self, p: usize) -> Option<f64> {
        let r = self.find(p);
        self.fixed[r].map(|f| f.0)
    }

    /// The equations on the path between `a` and `b` in the forest of merges.
    fn path(&self, a: usize, b: usize) -> Vec<Owner> {
        if a == b {
            return Vec::new();
        }
        let mut prev: std::collections::HashMap<u32, (u32, Owner)> =
            std::collections::HashMap::new();
        let mut q = VecDeque::from([a as u32]);
        prev.insert(
            a as u32,
            (a as u32, Owner::Entity(crate::model::EntityId(0))),
        );
        while let Some(x) = q.pop_front() {
            if x as usize == b {
                break;
            }
            let mut arc = self.head[x as usize];
            while arc != NONE {
                let (y, o, next) = self.arcs[arc as usize];
                if let std::collections::hash_map::Entry::Vacant(e) = prev.entry(y) {
                    e.insert((x, o));
                    q.push_back(y);
                }
                arc = next;
            }
        }
        let mut out = Vec::new();
        let mut x = b as u32;
        while x as usize != a {
            let Some(&(p, o)) = prev.get(&x) else { break };
            out.push(o);
            x = p;
        }
        out
    }

    fn record(&mut self, agree: bool, mut set: Vec<Owner>) {
        set.sort_unstable();
        set.dedup();
        if agree {
            self.redundant.push(set);
        } else {
            self.conflicts.push(set);
        }
    }

    /// Unknown `a` equals unknown `b`.
    pub fn merge(&mut self, a: usize, b: usize, owner: Owner, tol: f64) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            let mut set = self.path(a, b);
            set.push(owner);
            self.record(true, set);
            return;
        }
        match (self.fixed[ra], self.fixed[rb]) {
            (Some((va, pa, oa)), Some((vb, pb, ob))) => {
                let mut set = self.path(a, pa as usize);
                set.extend(self.path(b, pb as usize));
                set.extend([oa, ob, owner]);
                self.record((va - vb).abs() <= tol, set);
                // Keep the sets apart: the equation is not applied.
                return;
            }
            (None, Some(f)) => self.fixed[ra] = Some(f),
            _ => {}
        }
        self.parent[rb] = ra as u32;
        for (from, to) in [(a, b), (b, a)] {
            self.arcs.push((to as u32, owner, self.head[from]));
            self.head[from] = (self.arcs.len() - 1) as u32;
        }
        self.removed += 1;
    }

    /// Unknown `a` equals `value`.
    pub fn fix(&mut self, a: usize, value: f64, owner: Owner, tol: f64) {
        let r = self.find(a);
        match self.fixed[r] {
            Some((v, p, o)) => {
                let mut set = self.path(a, p as usize);
                set.extend([o, owner]);
                self.record((v - value).abs() <= tol, set);
            }
            None => {
                self.fixed[r] = Some((value, a as u32, owner));
                self.removed += 1;
            }
        }
    }

    /// An equation between two constants.
    pub fn constant(&mut self, agree: bool, owner: Owner) {
        self.record(agree, vec![owner]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ConstraintId;

    fn c(i: u32) -> Owner {
        Owner::Constraint(ConstraintId(i))
    }

    #[test]
    fn cycle_is_redundant_with_its_whole_loop() {
        let mut s = Substitution::new(4, 0);
        s.merge(0, 1, c(1), 1e-9);
        s.merge(1, 2, c(2), 1e-9);
        s.merge(3, 3, c(9), 1e-9);
        s.merge(2, 0, c(3), 1e-9);
        assert_eq!(s.removed, 2);
        assert_eq!(s.redundant.len(), 2);
        assert_eq!(s.redundant[1], vec![c(1), c(2), c(3)]);
    }

    #[test]
    fn two_values_for_one_set_conflict() {
        let mut s = Substitution::new(3, 0);
        s.fix(0, 1.0, c(1), 1e-9);
        s.merge(0, 1, c(2), 1e-9);
        s.fix(1, 2.0, c(3), 1e-9);
        assert_eq!(s.conflicts, vec![vec![c(1), c(2), c(3)]]);
        assert_eq!(s.fixed_value(1), Some(1.0));
    }
}
