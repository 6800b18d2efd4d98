//! The plan of a solve: which parameters are unknowns, which merge or are fixed by the
//! equalities, the column of each merged set, and the independent components. It depends on
//! the structure of the system only, so a [`super::Solver`] keeps it between solves.

use super::substitute::Substitution;
use crate::equations::{Carried, Kernel, Link};
use crate::error::SolveError;
use crate::model::{GroupId, ParamId, System};

pub(super) struct Plan {
    /// Whether each parameter is an unknown of the group.
    pub unknown: Vec<bool>,
    /// Whether each parameter is dragged.
    pub dragged: Vec<bool>,
    /// The root of each unknown's merged set (`usize::MAX` for constants).
    pub root_of: Vec<usize>,
    /// Whether a root's set has a dragged member.
    pub root_dragged: Vec<bool>,
    /// The column of each parameter (`u32::MAX`: none, a constant or fixed).
    pub col_of: Vec<u32>,
    /// The root of each column's set.
    pub col_root: Vec<usize>,
    pub comps: Groups,
    /// Each column's position within its component.
    pub local: Vec<u32>,
    /// Kernels with no unknowns.
    pub constant_kernels: Vec<usize>,
    /// Unknowns before substitution.
    pub n_unknown: usize,
}

/// The column of parameter `p` in `col_of` (`u32::MAX`: none).
fn column(col_of: &[u32], p: usize) -> Option<u32> {
    let c = col_of[p];
    (c != u32::MAX).then_some(c)
}

impl Plan {
    /// The column of parameter `p`, if it is an unknown of the solve.
    pub fn col(&self, p: usize) -> Option<u32> {
        column(&self.col_of, p)
    }
}

/// Applies the equalities and fixes of `links` at `values`.
pub(super) fn substitute(
    links: &[Link],
    unknown: &[bool],
    values: &[f64],
    tol: f64,
) -> Substitution {
    let mut sub = Substitution::new(unknown.len(), links.len());
    for c in links {
        match *c {
            Link::Equal { owner, a, b } => match (unknown[a], unknown[b]) {
                (true, true) => sub.merge(a, b, owner, tol),
                (true, false) => sub.fix(a, values[b], owner, tol),
                (false, true) => sub.fix(b, values[a], owner, tol),
                (false, false) => sub.constant((values[a] - values[b]).abs() <= tol, owner),
            },
            Link::Fix { owner, p, value } => {
                if unknown[p] {
                    sub.fix(p, value, owner, tol);
                } else {
                    sub.constant((values[p] - value).abs() <= tol, owner);
                }
            }
        }
    }
    sub
}

impl Plan {
    /// The plan, and the substitution it was read from (at `values`).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        sys: &System,
        group: GroupId,
        dragged: &[ParamId],
        kernels: &[Kernel],
        links: &[Link],
        carried: &Carried,
        values: &[f64],
        tol: f64,
    ) -> Result<(Self, Substitution), SolveError> {
        let params = sys.params();
        let np = params.len();
        // A carried entity's own parameters are read from its carrier after the solve.
        let unknown: Vec<bool> = params
            .iter()
            .enumerate()
            .map(|(i, p)| p.group == group && !carried.param(i))
            .collect();
        let mut is_dragged = vec![false; np];
        for h in dragged {
            let i = sys.param_index(*h).ok_or(SolveError::UnknownDragged(h.0))?;
            is_dragged[i] = true;
        }
        let mut sub = substitute(links, &unknown, values, tol);
        let mut root_of = vec![usize::MAX; np];
        let mut fixed = vec![false; np];
        let mut root_dragged = vec![false; np];
        let mut n_unknown = 0;
        for p in 0..np {
            if !unknown[p] {
                continue;
            }
            n_unknown += 1;
            let r = sub.find(p);
            root_of[p] = r;
            fixed[p] = sub.fixed_value(r).is_some();
            root_dragged[r] |= is_dragged[p];
        }

        // Columns, in order of first appearance in the kernels.
        let mut col_of_root = vec![u32::MAX; np];
        let mut col_root: Vec<usize> = Vec::new();
        for k in kernels {
            for &p in &k.locals {
                let p = p as usize;
                if unknown[p] && !fixed[p] && col_of_root[root_of[p]] == u32::MAX {
                    col_of_root[root_of[p]] = col_root.len() as u32;
                    col_root.push(root_of[p]);
                }
            }
        }
        let col_of: Vec<u32> = (0..np)
            .map(|p| {
                if unknown[p] && !fixed[p] {
                    col_of_root[root_of[p]]
                } else {
                    u32::MAX
                }
            })
            .collect();
        let col_of_param = |p: usize| column(&col_of, p);

        // Components: columns joined by the kernels that share them.
        let ncols = col_root.len();
        let mut comp_of_col: Vec<u32> = (0..ncols as u32).collect();
        fn find(v: &mut [u32], mut a: u32) -> u32 {
            while v[a as usize] != a {
                let g = v[v[a as usize] as usize];
                v[a as usize] = g;
                a = g;
            }
            a
        }
        let mut constant_kernels = Vec::new();
        for (ki, k) in kernels.iter().enumerate() {
            let mut first: Option<u32> = None;
            for &p in &k.locals {
                if let Some(c) = col_of_param(p as usize) {
                    match first {
                        None => first = Some(c),
                        Some(f) => {
                            let (a, b) = (find(&mut comp_of_col, f), find(&mut comp_of_col, c));
                            if a != b {
                                comp_of_col[b.max(a) as usize] = a.min(b);
                            }
                        }
                    }
                }
            }
            if first.is_none() {
                constant_kernels.push(ki);
            }
        }
        // Kernels and columns grouped by component, in order of first appearance, as compressed
        // lists (two allocations, however many components).
        let mut comp_index = vec![u32::MAX; ncols];
        let mut ncomps = 0usize;
        let col_comp: Vec<u32> = (0..ncols as u32)
            .map(|c| {
                let r = find(&mut comp_of_col, c) as usize;
                if comp_index[r] == u32::MAX {
                    comp_index[r] = ncomps as u32;
                    ncomps += 1;
                }
                comp_index[r]
            })
            .collect();
        let kernel_comp: Vec<u32> = kernels
            .iter()
            .map(|k| {
                k.locals
                    .iter()
                    .find_map(|&p| col_of_param(p as usize))
                    .map_or(u32::MAX, |c| col_comp[c as usize])
            })
            .collect();
        let comps = Groups::new(ncomps, &col_comp, &kernel_comp);
        let mut local = vec![0u32; ncols];
        for ci in 0..ncomps {
            for (i, &c) in comps.cols(ci).iter().enumerate() {
                local[c] = i as u32;
            }
        }
        let plan = Self {
            unknown,
            dragged: is_dragged,
            root_of,
            root_dragged,
            col_of,
            col_root,
            comps,
            local,
            constant_kernels,
            n_unknown,
        };
        Ok((plan, sub))
    }
}

/// Columns and kernels grouped by component: component `i` has columns
/// `cols[col_ptr[i]..col_ptr[i + 1]]` and kernels `members[member_ptr[i]..member_ptr[i + 1]]`,
/// each in ascending order.
pub(super) struct Groups {
    pub col_ptr: Vec<usize>,
    pub cols: Vec<usize>,
    member_ptr: Vec<usize>,
    members: Vec<usize>,
}

impl Groups {
    /// From the component of each column and of each kernel (`u32::MAX`: none).
    pub fn new(n: usize, col_comp: &[u32], kernel_comp: &[u32]) -> Self {
        let bucket = |of: &[u32]| -> (Vec<usize>, Vec<usize>) {
            let mut ptr = vec![0usize; n + 1];
            for &c in of.iter().filter(|&&c| c != u32::MAX) {
                ptr[c as usize + 1] += 1;
            }
            for i in 0..n {
                ptr[i + 1] += ptr[i];
            }
            // Filled through `ptr` itself (each start moves up to the next one's), then
            // shifted back: one table less to allocate.
            let mut items = vec![0usize; ptr[n]];
            for (i, &c) in of.iter().enumerate().filter(|x| *x.1 != u32::MAX) {
                items[ptr[c as usize]] = i;
                ptr[c as usize] += 1;
            }
            ptr.copy_within(0..n, 1);
            ptr[0] = 0;
            (ptr, items)
        };
        let (col_ptr, cols) = bucket(col_comp);
        let (member_ptr, members) = bucket(kernel_comp);
        Self {
            col_ptr,
            cols,
            member_ptr,
            members,
        }
    }

    pub fn cols(&self, i: usize) -> &[usize] {
        &self.cols[self.col_ptr[i]..self.col_ptr[i + 1]]
    }

    pub fn members(&self, i: usize) -> &[usize] {
        &self.members[self.member_ptr[i]..self.member_ptr[i + 1]]
    }
}
