//! Constraints written more than once: the same kind on the same references with the same
//! value and flags, under another handle.
//!
//! Every copy is the same equation, so all but the first are redundant, whatever the rest of
//! the sketch says; and every copy shares the first one's unknowns, so n copies would make an
//! n × n block of `J Jᵀ` (10,000 copies of one distance asked for 800 MB). They are set aside
//! before the equations are built and reported as redundant with the first.

use crate::model::{Constraint, ConstraintId, ConstraintKind, EntityId};
use rustc_hash::FxHashMap;

/// What makes two constraints the same equation: all but the handle and group (both are of
/// the group being compiled). Points of kinds symmetric in their two points, and lines of
/// kinds symmetric in their two lines, are put in order.
#[derive(PartialEq, Eq, Hash)]
struct Key {
    kind: ConstraintKind,
    workplane: Option<EntityId>,
    pts: [Option<EntityId>; 2],
    ents: [Option<EntityId>; 4],
    val: u64,
    other: bool,
    other2: bool,
    signed: bool,
}

impl Key {
    fn of(c: &Constraint) -> Self {
        use ConstraintKind as K;
        let mut pts = [c.pt_a, c.pt_b];
        let mut ents = [c.entity_a, c.entity_b, c.entity_c, c.entity_d];
        match c.kind {
            K::PtPtDistance | K::PointsCoincident => pts.sort_unstable(),
            K::EqualLengthLines | K::EqualRadius | K::Parallel | K::Perpendicular => {
                ents[..2].sort_unstable();
            }
            _ => {}
        }
        Self {
            kind: c.kind,
            workplane: c.workplane,
            pts,
            ents,
            // -0.0 and 0.0 are the same value.
            val: (c.val + 0.0).to_bits(),
            other: c.other,
            other2: c.other2,
            signed: c.signed,
        }
    }
}

impl Key {
    /// A hash of every field, one step per field: equal keys have equal signatures.
    fn signature(&self) -> u64 {
        let id = |e: Option<EntityId>| e.map_or(0, |e| u64::from(e.0) + 1);
        let mut h = 0u64;
        let mut add = |x: u64| {
            h = (h.rotate_left(5) ^ x).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
        };
        add(self.kind as u64);
        add(id(self.workplane));
        self.pts.iter().for_each(|&p| add(id(p)));
        self.ents.iter().for_each(|&e| add(id(e)));
        add(self.val);
        add(u64::from(self.other) | (u64::from(self.other2) << 1) | (u64::from(self.signed) << 2));
        h
    }
}

/// Each constraint of `cs` that repeats an earlier one, with the earlier one:
/// `(position of the copy, handle of the first)`, in order.
pub(crate) fn duplicates(cs: &[&Constraint]) -> Vec<(usize, ConstraintId)> {
    // Copies have equal keys, so equal signatures: when no two signatures are equal (nearly
    // every sketch), there is no copy, found without the table, whose keys cost a small
    // sketch as much as the rest of its compilation.
    let mut sigs: Vec<u64> = cs.iter().map(|c| Key::of(c).signature()).collect();
    sigs.sort_unstable();
    if sigs.windows(2).all(|w| w[0] != w[1]) {
        return Vec::new();
    }
    // Sized for every constraint at once: growing the table rehashes every key so far, which
    // cost a small sketch as much as the rest of its compilation.
    let mut first: FxHashMap<Key, ConstraintId> =
        FxHashMap::with_capacity_and_hasher(cs.len(), rustc_hash::FxBuildHasher);
    let mut out = Vec::new();
    for (i, c) in cs.iter().enumerate() {
        match first.entry(Key::of(c)) {
            std::collections::hash_map::Entry::Occupied(e) => out.push((i, *e.get())),
            std::collections::hash_map::Entry::Vacant(e) => {
                e.insert(c.h);
            }
        }
    }
    out
}

/// Whether the copies recorded in `dups` are still copies in `sys`: a value edit can make two
/// copies different equations again.
pub(crate) fn still_duplicates(
    sys: &crate::model::System,
    dups: &[(ConstraintId, ConstraintId)],
) -> bool {
    dups.iter().all(
        |&(copy, first)| match (sys.constraint(copy), sys.constraint(first)) {
            (Some(a), Some(b)) => Key::of(a) == Key::of(b),
            _ => false,
        },
    )
}

/// The constraints of `group` (not reference ones) written more than once: each first one
/// with its copies, in the order of the system.
pub(crate) fn duplicate_groups(
    sys: &crate::model::System,
    group: crate::model::GroupId,
) -> Vec<(ConstraintId, Vec<ConstraintId>)> {
    let mine: Vec<&Constraint> = sys
        .constraints()
        .iter()
        .filter(|c| c.group == group && !c.reference)
        .collect();
    let mut out: Vec<(ConstraintId, Vec<ConstraintId>)> = Vec::new();
    let mut slot: FxHashMap<ConstraintId, usize> = FxHashMap::default();
    for (i, first) in duplicates(&mine) {
        let at = *slot.entry(first).or_insert_with(|| {
            out.push((first, Vec::new()));
            out.len() - 1
        });
        out[at].1.push(mine[i].h);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{ConstraintKind as K, GroupId};

    fn c(h: u32, kind: K, pts: [u32; 2], ents: [u32; 2], val: f64) -> Constraint {
        let id = |x: u32| (x != 0).then_some(EntityId(x));
        let mut c = Constraint::new(h, 2, kind);
        c.pt_a = id(pts[0]);
        c.pt_b = id(pts[1]);
        c.entity_a = id(ents[0]);
        c.entity_b = id(ents[1]);
        c.val = val;
        c.group = GroupId(2);
        c
    }

    #[test]
    fn copies_are_named_with_the_first_of_their_kind() {
        let cs = [
            c(1, K::PtPtDistance, [5, 6], [0, 0], 10.0),
            c(2, K::Horizontal, [0, 0], [20, 0], 0.0),
            c(3, K::PtPtDistance, [6, 5], [0, 0], 10.0),
            c(4, K::PtPtDistance, [5, 6], [0, 0], 11.0),
            c(5, K::Parallel, [0, 0], [21, 20], 0.0),
            c(6, K::Horizontal, [0, 0], [20, 0], 0.0),
            c(7, K::Parallel, [0, 0], [20, 21], 0.0),
            c(8, K::PtPtDistance, [5, 6], [0, 0], -0.0),
            c(9, K::PtPtDistance, [5, 6], [0, 0], 0.0),
            c(10, K::Horizontal, [0, 0], [20, 0], 0.0),
            c(11, K::PtPtDistance, [5, 6], [0, 0], 10.0),
        ];
        let refs: Vec<&Constraint> = cs.iter().collect();
        let got = duplicates(&refs);
        let first = |h| ConstraintId(h);
        assert_eq!(
            got,
            vec![
                (2, first(1)),
                (5, first(2)),
                (6, first(5)),
                (8, first(8)),
                (9, first(2)),
                (10, first(1)),
            ]
        );
        let distinct: Vec<&Constraint> = [0, 1, 3, 4].iter().map(|&i| &cs[i]).collect();
        assert!(duplicates(&distinct).is_empty());
        assert!(duplicates(&[]).is_empty());
        assert!(duplicates(&refs[..1]).is_empty());
    }
}
