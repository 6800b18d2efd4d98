//! Handle → position look-up, fast for the handles programs actually use.
//!
//! Handles are chosen by the caller. Most number their objects 1, 2, 3 ... (libslvs examples,
//! generated sketches), so a plain table indexed by handle answers a look-up with one load;
//! a solve of a large sketch makes several look-ups per constraint, and a hash map made them
//! the largest cost of setting up a solve. Handles far beyond the number of objects (SolveSpace
//! files put the group in the high bits, `0x80020000`) go to a hash map instead, so memory
//! stays proportional to the number of objects.

use rustc_hash::FxHashMap;

/// Below this many table slots per stored object, handles use the table.
const SPREAD: usize = 4;
/// Handles below this always use the table.
const SMALL: usize = 1024;
/// Marks an empty table slot.
const NONE: u32 = u32::MAX;

/// Maps handles (non-zero `u32`) to positions.
#[derive(Clone, Debug, Default)]
pub(crate) struct HandleIndex {
    table: Vec<u32>,
    map: FxHashMap<u32, u32>,
    len: usize,
}

impl HandleIndex {
    /// The position of handle `h`.
    #[inline]
    pub fn get(&self, h: u32) -> Option<usize> {
        match self.table.get(h as usize) {
            Some(&NONE) => None,
            Some(&i) => Some(i as usize),
            None => self.map.get(&h).map(|&i| i as usize),
        }
    }

    /// Whether handle `h` is stored.
    pub fn contains(&self, h: u32) -> bool {
        self.get(h).is_some()
    }

    /// Stores handle `h` at position `i` (replacing any earlier position).
    pub fn insert(&mut self, h: u32, i: usize) {
        let i = u32::try_from(i).unwrap_or(NONE - 1);
        let hu = h as usize;
        if hu >= self.table.len() && hu < SMALL.max(SPREAD * (self.len + 1)) {
            self.grow(hu + 1);
        }
        let fresh = match self.table.get_mut(hu) {
            Some(slot) => std::mem::replace(slot, i) == NONE,
            None => self.map.insert(h, i).is_none(),
        };
        if fresh {
            self.len += 1;
        }
    }

    /// Removes handle `h`; returns its position.
    pub fn remove(&mut self, h: u32) -> Option<usize> {
        let old = match self.table.get_mut(h as usize) {
            Some(slot) => match std::mem::replace(slot, NONE) {
                NONE => None,
                i => Some(i as usize),
            },
            None => self.map.remove(&h).map(|i| i as usize),
        };
        if old.is_some() {
            self.len -= 1;
        }
        old
    }

    /// Applies `f` to every stored position.
    pub fn update_positions(&mut self, mut f: impl FnMut(usize) -> usize) {
        for slot in self.table.iter_mut().filter(|s| **s != NONE) {
            *slot = f(*slot as usize) as u32;
        }
        for v in self.map.values_mut() {
            *v = f(*v as usize) as u32;
        }
    }

    /// Grows the table to at least `n` slots (doubling, so inserts stay amortised constant),
    /// moving the hash map's handles that now fit.
    fn grow(&mut self, n: usize) {
        let cap = n.max(2 * self.table.len()).max(64);
        self.table.resize(cap, NONE);
        let moved: Vec<u32> = self
            .map
            .keys()
            .copied()
            .filter(|&h| (h as usize) < cap)
            .collect();
        for h in moved {
            if let Some(i) = self.map.remove(&h) {
                self.table[h as usize] = i;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::HandleIndex;

    #[test]
    fn small_and_scattered_handles_both_resolve() {
        let mut ix = HandleIndex::default();
        let handles = [1u32, 2, 3, 0x8002_0000, 700, 0x0003_0010, 5000, 40];
        for (i, &h) in handles.iter().enumerate() {
            ix.insert(h, i);
        }
        for (i, &h) in handles.iter().enumerate() {
            assert_eq!(ix.get(h), Some(i), "handle {h:#x}");
        }
        assert_eq!(ix.get(4), None);
        assert_eq!(ix.get(0x8002_0001), None);
        assert_eq!(ix.remove(700), Some(4));
        assert_eq!(ix.get(700), None);
        assert!(ix.contains(5000));
        ix.update_positions(|p| p + 10);
        assert_eq!(ix.get(0x8002_0000), Some(13));
        assert_eq!(ix.get(1), Some(10));
    }

    #[test]
    fn many_sequential_handles_move_into_the_table() {
        let mut ix = HandleIndex::default();
        for h in 1..=100_000u32 {
            ix.insert(h, (h - 1) as usize);
        }
        assert!(
            ix.map.is_empty(),
            "sequential handles must all be in the table"
        );
        assert_eq!(ix.get(99_999), Some(99_998));
        assert_eq!(ix.len, 100_000);
    }
}
