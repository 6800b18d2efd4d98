//! Redundant circuits grouped into sets a user can act on.
//!
//! Circuits that share a row belong together (they are one connected part of the row
//! matroid); in such a part every row lies on a circuit, so removing any one of its rows
//! leaves the rank unchanged, and the part has as many removable rows as it has dependent
//! ones. A constraint with several rows is removable only if all of them can go at once,
//! which a small dense rank test decides.

use super::circuits::Circuit;
use super::report::{Member, RedundantSet};
use super::unmerged::{Equations, Linear};
use faer::Mat;
use std::cmp::Ordering;
use std::collections::{BTreeMap, HashMap};

/// Above this many rows or columns the dense test is skipped.
const DENSE_LIMIT: usize = 400;

/// Groups the redundant (not conflicting) circuits.
pub(crate) fn redundant_sets(
    eqs: &Equations,
    lin: &Linear,
    circuits: &[Circuit],
    rank_tolerance: f64,
) -> Vec<RedundantSet> {
    // Ordered maps: the sets, and so the report, come out the same on every run.
    let mut parent: BTreeMap<usize, usize> = BTreeMap::new();
    fn find(p: &mut BTreeMap<usize, usize>, a: usize) -> usize {
        let mut r = a;
        while let Some(&q) = p.get(&r) {
            if q == r {
                break;
            }
            r = q;
        }
        p.insert(a, r);
        r
    }
    let redundant: Vec<&Circuit> = circuits.iter().filter(|c| !c.conflicting).collect();
    for c in &redundant {
        for &r in &c.rows {
            parent.entry(r).or_insert(r);
        }
        let a = find(&mut parent, c.rows[0]);
        for &r in &c.rows[1..] {
            let b = find(&mut parent, r);
            if a != b {
                parent.insert(b, a);
            }
        }
    }
    // A constraint's rows belong to one set even when they lie on separate circuits (the x
    // and y rows of a cycle of coincident points).
    let mut first_of_kernel: BTreeMap<u32, usize> = BTreeMap::new();
    let rows: Vec<usize> = parent.keys().copied().collect();
    for r in rows {
        let k = eqs.row_kernel[r];
        match first_of_kernel.get(&k) {
            None => {
                first_of_kernel.insert(k, r);
            }
            Some(&f) => {
                let (a, b) = (find(&mut parent, f), find(&mut parent, r));
                if a != b {
                    parent.insert(b, a);
                }
            }
        }
    }
    // root -> (rows, excess)
    let mut groups: BTreeMap<usize, (Vec<usize>, usize)> = BTreeMap::new();
    let rows: Vec<usize> = parent.keys().copied().collect();
    for r in rows {
        let root = find(&mut parent, r);
        groups.entry(root).or_default().0.push(r);
    }
    for c in &redundant {
        let root = find(&mut parent, c.rows[0]);
        if let Some(g) = groups.get_mut(&root) {
            g.1 += 1;
        }
    }
    let mut out: Vec<RedundantSet> = groups
        .into_values()
        .map(|(rows, excess)| group_set(eqs, lin, rows, excess, rank_tolerance))
        .collect();
    out.sort_by(report_order);
    out
}

/// Smallest sets first; among sets of one size, by their members in report order, then by
/// the constraints involved. A total order (a set with no removable member is compared by
/// its lists like any other), as sorting requires.
fn report_order(a: &RedundantSet, b: &RedundantSet) -> Ordering {
    let size = |s: &RedundantSet| s.members.len() + s.involved.len();
    size(a)
        .cmp(&size(b))
        .then_with(|| lists(&a.members, &b.members))
        .then_with(|| lists(&a.involved, &b.involved))
        .then_with(|| a.excess.cmp(&b.excess))
}

/// Lexicographic comparison of two lists in [`Member::report_order`].
fn lists(a: &[Member], b: &[Member]) -> Ordering {
    for (x, y) in a.iter().zip(b) {
        match Member::report_order(x, y) {
            Ordering::Equal => {}
            o => return o,
        }
    }
    a.len().cmp(&b.len())
}

fn group_set(
    eqs: &Equations,
    lin: &Linear,
    rows: Vec<usize>,
    excess: usize,
    rank_tolerance: f64,
) -> RedundantSet {
    let mut kernels: Vec<usize> = rows.iter().map(|&r| eqs.row_kernel[r] as usize).collect();
    kernels.sort_unstable();
    kernels.dedup();
    let in_group: std::collections::HashSet<usize> = rows.iter().copied().collect();
    let all_rows: Vec<usize> = kernels
        .iter()
        .flat_map(|&k| {
            let b = &eqs.blocks[k];
            b.row0..b.row0 + eqs.kernels[k].rows
        })
        .collect();
    let dense = DenseRows::new(eqs, lin, &all_rows);
    let full = dense.as_ref().map(|d| d.rank(&|_| false, rank_tolerance));
    let (mut members, mut involved) = (Vec::new(), Vec::new());
    for &k in &kernels {
        let b = &eqs.blocks[k];
        let own = b.row0..b.row0 + eqs.kernels[k].rows;
        let all_dependent = own.clone().all(|r| in_group.contains(&r));
        let removable = if own.len() == 1 {
            true
        } else if !all_dependent {
            false
        } else {
            match (&dense, full) {
                (Some(d), Some(full)) => d.rank(&|r| own.contains(&r), rank_tolerance) == full,
                _ => true,
            }
        };
        if removable {
            members.push(eqs.member(k));
        } else {
            involved.push(eqs.member(k));
        }
    }
    members.sort_by(Member::report_order);
    involved.sort_by(Member::report_order);
    // How many whole constraints can go together: remove them one by one, the most recent
    // first, while the rank holds. Rows on separate circuits may belong to one constraint,
    // so this can be fewer than the dependent rows.
    let excess = match (&dense, full) {
        (Some(d), Some(full)) => {
            let mut gone: std::collections::HashSet<usize> = std::collections::HashSet::new();
            let mut count = 0;
            for m in &members {
                let Some(k) = eqs.kernel_of(*m) else { continue };
                let b = &eqs.blocks[k];
                let own = b.row0..b.row0 + eqs.kernels[k].rows;
                if d.rank(&|r| gone.contains(&r) || own.contains(&r), rank_tolerance) == full {
                    gone.extend(own);
                    count += 1;
                }
            }
            count
        }
        _ => excess,
    };
    RedundantSet {
        members,
        excess,
        involved,
    }
}

/// A few rows of the normalised Jacobian as a dense matrix.
struct DenseRows {
    rows: Vec<usize>,
    mat: Mat<f64>,
}

impl DenseRows {
    fn new(eqs: &Equations, lin: &Linear, rows: &[usize]) -> Option<Self> {
        let mut cols: HashMap<u32, usize> = HashMap::new();
        for &r in rows {
            for (c, _) in eqs.row_entries(r) {
                let n = cols.len();
                cols.entry(c).or_insert(n);
            }
        }
        if rows.len() > DENSE_LIMIT || cols.len() > DENSE_LIMIT {
            return None;
        }
        let mut mat = Mat::<f64>::zeros(rows.len(), cols.len().max(1));
        for (i, &r) in rows.iter().enumerate() {
            for (c, idx) in eqs.row_entries(r) {
                mat[(i, cols[&c])] = lin.jn[idx as usize];
            }
        }
        Some(Self {
            rows: rows.to_vec(),
            mat,
        })
    }

    /// The rank of the rows, without those `skip` says. A singular value counts when its
    /// square is above the rank tolerance, the solver's test for a pivot of `J Jᵀ`.
    fn rank(&self, skip: &dyn Fn(usize) -> bool, rank_tolerance: f64) -> usize {
        let keep: Vec<usize> = (0..self.rows.len())
            .filter(|&i| !skip(self.rows[i]))
            .collect();
        if keep.is_empty() {
            return 0;
        }
        let m = Mat::<f64>::from_fn(keep.len(), self.mat.ncols(), |i, j| self.mat[(keep[i], j)]);
        match m.singular_values() {
            Ok(s) => s.iter().filter(|&&v| v * v > rank_tolerance).count(),
            Err(_) => 0,
        }
    }
}
