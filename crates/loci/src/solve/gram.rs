//! The normal-equations matrix `G = J Jᵀ` of a component and its rank-revealing sparse
//! LDLᵀ factorisation.
//!
//! The Newton step of minimum norm is `dx = Jᵀ y` with `G y = -r`. With the rows of `J`
//! normalised to unit length, the pivot `d_k` of an LDLᵀ factorisation of `G` is the squared
//! distance of row `k` from the span of the rows eliminated before it. A pivot below the rank
//! tolerance therefore marks an equation that depends on earlier ones (a redundant or
//! conflicting constraint); faer's dynamic regularisation replaces it by a huge value, which
//! removes that equation from the step while the others are solved exactly. The structure
//! (pattern, fill-reducing ordering, symbolic factorisation) is computed once per component
//! and reused by every iteration.

use super::envelope::EnvelopeLdlt;
use super::order;

mod sparse;

use sparse::Pattern;
pub(crate) use sparse::SparseGram;

/// The value a dropped pivot is replaced by.
const DROPPED: f64 = 1e150;

/// The nonzeros of a Jacobian, column by column: `(row, index into the Jacobian's values)`,
/// in one compressed list.
pub(crate) struct Columns {
    /// Column `c` is `entries[ptr[c]..ptr[c + 1]]`.
    pub ptr: Vec<u32>,
    pub entries: Vec<(u32, u32)>,
}

impl Columns {
    /// From one list per column.
    pub fn from_lists(lists: &[Vec<(u32, u32)>]) -> Self {
        let mut ptr = Vec::with_capacity(lists.len() + 1);
        ptr.push(0u32);
        let mut entries = Vec::new();
        for l in lists {
            entries.extend_from_slice(l);
            ptr.push(entries.len() as u32);
        }
        Self { ptr, entries }
    }

    /// The number of columns.
    pub fn len(&self) -> usize {
        self.ptr.len().saturating_sub(1)
    }

    /// The entries of column `c`.
    #[inline]
    pub fn col(&self, c: usize) -> &[(u32, u32)] {
        &self.entries[self.ptr[c] as usize..self.ptr[c + 1] as usize]
    }

    /// Every column, in order.
    pub fn iter(&self) -> impl Iterator<Item = &[(u32, u32)]> + '_ {
        (0..self.len()).map(|c| self.col(c))
    }
}

/// The rows of `J` with their entries: row `i` is `entries[ptr[i]..ptr[i + 1]]`, each
/// `(column, index into J's values)`.
fn rows_of(nrows: usize, columns: &Columns) -> (Vec<usize>, Vec<(u32, u32)>) {
    let mut ptr = vec![0usize; nrows + 1];
    for col in columns.iter() {
        for &(r, _) in col {
            ptr[r as usize + 1] += 1;
        }
    }
    for i in 0..nrows {
        ptr[i + 1] += ptr[i];
    }
    let mut fill = ptr.clone();
    let mut entries = vec![(0u32, 0u32); ptr[nrows]];
    for (c, col) in columns.iter().enumerate() {
        for &(r, a) in col {
            entries[fill[r as usize]] = (c as u32, a);
            fill[r as usize] += 1;
        }
    }
    (ptr, entries)
}

/// Symmetric adjacency lists of the rows of `G` (rows of `J` sharing a column), diagonal left
/// out.
fn adjacency(nrows: usize, columns: &Columns) -> (Vec<usize>, Vec<u32>) {
    let (row_ptr, row_entries) = rows_of(nrows, columns);
    let mut mark = vec![u32::MAX; nrows];
    let mut ptr = Vec::with_capacity(nrows + 1);
    ptr.push(0usize);
    let mut adj = Vec::new();
    for i in 0..nrows {
        mark[i] = i as u32;
        for &(c, _) in &row_entries[row_ptr[i]..row_ptr[i + 1]] {
            for &(j, _) in columns.col(c as usize) {
                if mark[j as usize] != i as u32 {
                    mark[j as usize] = i as u32;
                    adj.push(j);
                }
            }
        }
        ptr.push(adj.len());
    }
    (ptr, adj)
}

/// Components up to this many equations are factorised within their envelope whatever its
/// shape: it holds no more than the whole triangle, and costs no more than a dense
/// factorisation.
const DENSE_MAX: usize = 24;

/// How the sparse path factorises `G` once its rows are in fill-reducing (AMD) order.
///
/// Both eliminate the rows in the same order and drop a row exactly when its pivot falls at or
/// below the tolerance, so they find the same dependent rows and the same step, to rounding.
/// They differ only in speed: column by column (simplicial) is quicker when the factor is thin
/// (few entries per column, as for a chain or a tree), dense blocks of columns sharing a
/// pattern (supernodal) when it is thick (a two-dimensional mesh, whose factor fills in around
/// its separators).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Sparse {
    /// Chosen from the symbolic analysis: supernodal when the predicted flops per entry of the
    /// factor are high enough for dense blocks to pay.
    Auto,
    /// Column by column.
    #[allow(dead_code)]
    Simplicial,
    /// Dense blocks of columns.
    #[allow(dead_code)]
    Supernodal,
}

/// `G = J Jᵀ` of one component and its rank-revealing factorisation: within its envelope when
/// small or banded as it stands, sparse with a fill-reducing ordering otherwise.
pub(crate) enum Gram {
    Banded(Box<Banded>),
    Sparse(Box<SparseGram>),
}

/// The most products of two Jacobian entries a component's `G` may be built from (a sparse
/// `G` keeps a list of them, 8 bytes each, and its entries and factor besides; a banded one
/// computes them at each factorisation): beyond it the normal equations would take gigabytes
/// or far too long.
pub(crate) const MAX_PRODUCTS: usize = 1 << 26;

impl Gram {
    /// The number of products of two Jacobian entries that build `G`: the sum over columns
    /// of `h (h + 1) / 2` for a column of `h` entries. A column shared by many equations (a
    /// point many constraints refer to) makes it grow as the square of their number.
    pub fn products(columns: &Columns) -> usize {
        columns
            .iter()
            .map(|c| c.len() * (c.len() + 1) / 2)
            .fold(0usize, usize::saturating_add)
    }

    /// Builds the structure from the nonzeros of `J`, given column by column as lists of
    /// `(row, index into J's values)`.
    pub fn new(nrows: usize, columns: &Columns) -> Option<Self> {
        Self::with(nrows, columns, Sparse::Auto)
    }

    /// Like [`Gram::new`], with the sparse factorisation (when the envelope does not win)
    /// chosen by `sparse`.
    pub fn with(nrows: usize, columns: &Columns, sparse: Sparse) -> Option<Self> {
        // Products of two entries of a column of J, each adding to one entry of G.
        let pairs = Self::products(columns);
        if pairs > MAX_PRODUCTS {
            return None;
        }
        // Equations given in a natural order (a chain, a 3D chain: each constraint meets only
        // its neighbours) make a banded G, whose LDLᵀ fills nothing outside its envelope (each
        // row from the first row it meets to the diagonal): when that is about the size of G
        // itself (counted as the products that make it), no ordering or symbolic analysis is
        // needed. Small components are factorised within their envelope whatever its shape.
        let first = envelope(nrows, columns, None);
        if nrows <= DENSE_MAX || bands(&first, pairs) {
            return Some(Gram::Banded(Box::new(Banded::new(first, columns, None))));
        }
        // Equations in another order (implicit ones last, a chain given shuffled) may still
        // band once renumbered.
        let (ptr, adj) = adjacency(nrows, columns);
        // A two-dimensional mesh (a truss) never bands: its envelope in any such order is
        // many times the size of G. Not worth ordering to find out (5-10 ms on a 100x100
        // truss); the estimate errs low, and only twice the threshold skips the attempt.
        if order::envelope_estimate(nrows, &ptr, &adj).is_some_and(|e| e > 4 * pairs) {
            let pattern = Pattern::new(nrows, columns);
            return SparseGram::new(nrows, pattern, sparse).map(|s| Gram::Sparse(Box::new(s)));
        }
        let order = order::reverse_cuthill_mckee(nrows, &ptr, &adj);
        let mut pos = vec![0u32; nrows];
        for (p, &r) in order.iter().enumerate() {
            pos[r as usize] = p as u32;
        }
        let first = envelope(nrows, columns, Some(&pos));
        if bands(&first, pairs) {
            return Some(Gram::Banded(Box::new(Banded::new(
                first,
                columns,
                Some((order, pos)),
            ))));
        }
        let pattern = Pattern::new(nrows, columns);
        SparseGram::new(nrows, pattern, sparse).map(|s| Gram::Sparse(Box::new(s)))
    }

    /// `K = Jᵀ J` instead, over the unknowns (the columns of `J`, given as for [`Gram::new`]
    /// with `nrows` rows): the normal equations of a least-squares step, for components with
    /// more equations than unknowns. A pivot of `K` is the squared distance of a column of `J`
    /// from the span of the columns eliminated before it, so the columns it drops are
    /// directions in which the equations do not move the unknowns (a mechanism's freedom).
    /// Built, assembled and solved as `G` is, the rows of `J` standing for its columns.
    pub fn of_unknowns(nrows: usize, columns: &Columns) -> Option<Self> {
        let (ptr, entries) = rows_of(nrows, columns);
        if ptr[nrows] > u32::MAX as usize {
            return None;
        }
        let transposed = Columns {
            ptr: ptr.iter().map(|&p| p as u32).collect(),
            entries,
        };
        Self::new(columns.len(), &transposed)
    }

    /// Computes `G` from the Jacobian values `jv`.
    pub fn assemble(&mut self, jv: &[f64]) {
        match self {
            Gram::Banded(b) => {
                b.jv.clear();
                b.jv.extend_from_slice(jv);
                b.kept_g.clear();
                b.formed = false;
            }
            Gram::Sparse(s) => s.assemble(jv),
        }
    }

    /// Factorises `G + lambda I`; pivots at or below `eps` are dropped. Returns false when the
    /// factorisation failed numerically.
    pub fn factor(&mut self, lambda: f64, eps: f64) -> bool {
        match self {
            Gram::Banded(b) => b.factor(lambda, eps),
            Gram::Sparse(s) => s.factor(lambda, eps),
        }
    }

    /// The number of rows (and columns) of `G`.
    pub fn rows(&self) -> usize {
        match self {
            Gram::Banded(b) => b.g.rows(),
            Gram::Sparse(s) => s.n,
        }
    }

    /// The smallest pivot the last factorisation kept (infinity when it kept none): the
    /// squared distance of the least independent kept row from the rows before it.
    pub fn smallest_kept_pivot(&self) -> f64 {
        match self {
            Gram::Banded(b) => b.g.smallest_kept_pivot(),
            Gram::Sparse(s) => s.smallest_kept_pivot(),
        }
    }

    /// The rows whose pivots were dropped in the last factorisation, ascending.
    pub fn dropped(&self) -> Vec<usize> {
        match self {
            Gram::Banded(b) => b.dropped(),
            Gram::Sparse(s) => s.dropped(),
        }
    }

    /// A copy of the last factorisation, for [`Gram::restore_factor`] once another has been
    /// made of the same `G` (`None` where factorising again costs little: an envelope).
    pub fn save_factor(&self) -> Option<Vec<f64>> {
        match self {
            Gram::Banded(_) => None,
            Gram::Sparse(s) => Some(s.l_values.clone()),
        }
    }

    /// Makes the factorisation of `G` with the tolerance `eps` current again, from `saved`
    /// (as [`Gram::save_factor`] kept it, with that tolerance) or by factorising afresh: the
    /// same values either way, as a factorisation of the same `G` is the same every time.
    pub fn restore_factor(&mut self, saved: Option<Vec<f64>>, eps: f64) {
        match (self, saved) {
            (Gram::Sparse(s), Some(values)) if values.len() == s.l_values.len() => {
                s.l_values = values;
            }
            (gram, _) => {
                gram.factor(0.0, eps);
            }
        }
    }

    /// Solves `G y = rhs` in place with the last factorisation.
    pub fn solve(&mut self, rhs: &mut [f64]) {
        match self {
            Gram::Banded(b) => b.solve(rhs),
            Gram::Sparse(s) => s.solve(rhs),
        }
    }

    /// Solves `G Y = B` in place for the `k` columns of `B`, stored one after another: the
    /// factor is read once for them all rather than once per column.
    pub fn solve_many(&mut self, rhs: &mut [f64], k: usize) {
        let n = rhs.len() / k.max(1);
        match self {
            Gram::Banded(b) => rhs.chunks_mut(n.max(1)).for_each(|c| b.solve(c)),
            Gram::Sparse(s) => s.solve_many(rhs, k),
        }
    }
}

/// The first row each row of `G` meets, with rows at positions `pos` (or as they are).
fn envelope(nrows: usize, columns: &Columns, pos: Option<&[u32]>) -> Vec<u32> {
    let at = |r: u32| pos.map_or(r, |p| p[r as usize]);
    let mut first: Vec<u32> = (0..nrows as u32).collect();
    for col in columns.iter() {
        if let Some(lo) = col.iter().map(|e| at(e.0)).min() {
            for &(i, _) in col {
                let p = at(i) as usize;
                first[p] = first[p].min(lo);
            }
        }
    }
    first
}

/// Whether `G`, its rows starting at `first`, is best factorised within its envelope: the
/// envelope is about the size of `G` itself (`pairs` products build it), and so is the work.
///
/// The work of an envelope LDLᵀ grows as the sum of the squared row widths. A chain's rows
/// are a few entries wide (the sum is 1.3 to 2 times `pairs` on the benchmark's chains and
/// fillets); a sheet of closed profiles renumbered by Cuthill-McKee has an envelope within
/// twice `pairs` but rows 40 wide, 50 to 190 times `pairs` of work, where the sparse
/// factorisation took 10-35% less time per solve (10x10 to 20x20 profiles).
fn bands(first: &[u32], pairs: usize) -> bool {
    let work = envelope_work(first);
    envelope_len(first) <= 2 * pairs
        && (work <= ENVELOPE_WORK * pairs as f64 || work <= ENVELOPE_SMALL_WORK)
}

/// The most work (sum of squared row widths) per product of `G` at which its envelope is
/// factorised rather than a fill-reducing sparse factorisation (see [`bands`]).
const ENVELOPE_WORK: f64 = 16.0;

/// Work (sum of squared row widths) up to which an envelope within twice the products is
/// factorised whatever its work per product: a tenth of a millisecond or less, where the
/// sparse factorisation's ordering and symbolic analysis cost more than they save. A 10x10
/// truss (work 23 times its products) solved in 0.30 ms this way against 0.39 ms, a 10x10
/// mesh in 0.37 against 0.69 ms, the redundant 5x5 profiles in 0.55 against 0.63 ms; above
/// it (20x20 trusses and meshes, 10x10 profiles: 0.6 to 2 million) the sparse one is as fast
/// or faster.
const ENVELOPE_SMALL_WORK: f64 = 131_072.0;

/// The sum of the squared widths of the envelope's rows.
fn envelope_work(first: &[u32]) -> f64 {
    first
        .iter()
        .enumerate()
        .map(|(c, &f)| {
            let w = (c + 1 - f as usize) as f64;
            w * w
        })
        .sum()
}

/// The number of entries in the envelope whose rows start at `first`.
fn envelope_len(first: &[u32]) -> usize {
    first
        .iter()
        .enumerate()
        .map(|(c, &f)| c + 1 - f as usize)
        .sum()
}

/// `G` factorised within its envelope, its rows possibly renumbered.
///
/// Neither `G` nor a list of the products that make it is stored: each factorisation computes
/// the row of `G` it reaches from the rows of `J`, products summed in the order of `J`'s
/// columns as [`Products`] sums them. A 10,000-link assembly chain's envelope holds millions of
/// entries, and `G` and its products took 45 MB of fresh pages; `J`'s structure twice is 10.
pub(crate) struct Banded {
    g: EnvelopeLdlt,
    /// The Jacobian values of the last [`Gram::assemble`].
    jv: Vec<f64>,
    /// The rows of `J`: row `i` is `row_entries[row_ptr[i]..row_ptr[i + 1]]`, each
    /// `(column, index into J's values)`, by column.
    row_ptr: Vec<usize>,
    row_entries: Vec<(u32, u32)>,
    /// The columns of `J`, each entry `(position of its row, index into J's values)`, by
    /// position: a row of `G` reads each column only up to its own position.
    columns: Columns,
    /// The row at each position and the position of each row, when renumbered.
    order: Option<(Vec<u32>, Vec<u32>)>,
    /// A right-hand side in position order.
    tmp: Vec<f64>,
    /// Whether `G` was formed for the Jacobian of the last [`Gram::assemble`].
    formed: bool,
    /// `G` within the envelope, row after row, as the second factorisation since the last
    /// [`Gram::assemble`] formed it (empty before, and always for an envelope of more than
    /// [`KEEP_G`] entries). Damped steps factorise `G + lambda I` for one `G` and several
    /// `lambda`, and a truncated step `G` at several thresholds: a fifth of the time of
    /// diagnosing a small sketch went into forming `G` again for them. Not at the first: most
    /// Jacobians are factorised once.
    kept_g: Vec<f64>,
}

/// The largest envelope whose `G` a [`Banded`] keeps between factorisations (2 MB): a long
/// chain's holds millions of entries, as many fresh pages to keep them.
const KEEP_G: usize = 1 << 18;

impl Banded {
    fn new(first: Vec<u32>, columns: &Columns, order: Option<(Vec<u32>, Vec<u32>)>) -> Self {
        let n = first.len();
        let g = EnvelopeLdlt::new(first);
        let (row_ptr, row_entries) = rows_of(n, columns);
        let tmp = if order.is_some() {
            vec![0.0; n]
        } else {
            Vec::new()
        };
        Self {
            g,
            jv: Vec::new(),
            row_ptr,
            row_entries,
            columns: by_position(columns, order.as_ref().map(|o| &o.1[..])),
            order,
            tmp,
            formed: false,
            kept_g: Vec::new(),
        }
    }

    /// Factorises `G + lambda I` from the Jacobian values of the last [`Gram::assemble`].
    fn factor(&mut self, lambda: f64, eps: f64) -> bool {
        let Self {
            g,
            jv,
            row_ptr,
            row_entries,
            columns,
            order,
            formed,
            kept_g,
            ..
        } = self;
        let len = g.len();
        if kept_g.len() == len && len > 0 {
            let mut at = 0;
            return g.factor_rows(lambda, eps, |_, _, out| {
                out.copy_from_slice(&kept_g[at..at + out.len()]);
                at += out.len();
            });
        }
        let keep = *formed && len <= KEEP_G;
        *formed = true;
        kept_g.clear();
        if keep {
            kept_g.reserve_exact(len);
        }
        let done = g.factor_rows(lambda, eps, |p, f, out| {
            row_of_g(p, f, out, jv, row_ptr, row_entries, columns, order.as_ref());
            if keep {
                kept_g.extend_from_slice(out);
            }
        });
        // A factorisation that stopped at a pivot that is not finite formed only part of `G`.
        if !done {
            kept_g.clear();
        }
        done
    }

    fn dropped(&self) -> Vec<usize> {
        let mut d = self.g.dropped();
        if let Some((order, _)) = &self.order {
            for p in &mut d {
                *p = order[*p] as usize;
            }
            d.sort_unstable();
        }
        d
    }

    fn solve(&mut self, rhs: &mut [f64]) {
        match &self.order {
            None => self.g.solve(rhs),
            Some((order, _)) => {
                for (t, &r) in self.tmp.iter_mut().zip(order) {
                    *t = rhs[r as usize];
                }
                self.g.solve(&mut self.tmp);
                for (t, &r) in self.tmp.iter().zip(order) {
                    rhs[r as usize] = *t;
                }
            }
        }
    }
}

/// The columns of `J` with each entry's row replaced by its position (`pos`, or the row
/// itself), sorted by position within each column.
fn by_position(columns: &Columns, pos: Option<&[u32]>) -> Columns {
    let mut entries: Vec<(u32, u32)> = columns
        .entries
        .iter()
        .map(|&(r, a)| (pos.map_or(r, |p| p[r as usize]), a))
        .collect();
    for c in 0..columns.len() {
        let (s, e) = (columns.ptr[c] as usize, columns.ptr[c + 1] as usize);
        entries[s..e].sort_unstable_by_key(|&(q, _)| q);
    }
    Columns {
        ptr: columns.ptr.clone(),
        entries,
    }
}

/// The entries of row `p` (in position order) of `G` from column `f` to the diagonal, into
/// `out`: the products of the row of `J` at `p` with each row at a position up to `p` sharing
/// a column (`by_pos`, sorted by position, read up to `p`), each entry's summed in the order
/// of the columns of `J` (a row meets a column once, so the order within a column does not
/// change any sum).
#[allow(clippy::too_many_arguments)]
#[inline]
fn row_of_g(
    p: usize,
    f: usize,
    out: &mut [f64],
    jv: &[f64],
    row_ptr: &[usize],
    row_entries: &[(u32, u32)],
    by_pos: &Columns,
    order: Option<&(Vec<u32>, Vec<u32>)>,
) {
    out.fill(0.0);
    let i = order.map_or(p, |o| o.0[p] as usize);
    for &(c, a) in &row_entries[row_ptr[i]..row_ptr[i + 1]] {
        let x = jv[a as usize];
        for &(q, b) in by_pos.col(c as usize) {
            let q = q as usize;
            if q > p {
                break;
            }
            out[q - f] += x * jv[b as usize];
        }
    }
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod timing;
#[cfg(test)]
mod truss;
