//! `G = J Jᵀ` held sparse, for components whose `G` does not band: its pattern and the
//! products of Jacobian entries that make each entry, renumbered once into a fill-reducing
//! (AMD) order, and faer's `LDLᵀ` factorisation of it, simplicial or supernodal.

use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::cholesky::ldlt::factor::LdltRegularization;
use faer::sparse::linalg::amd;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, LdltRef, SymbolicCholesky,
    SymbolicCholeskyRaw, SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::{SparseColMatRef, SymbolicSparseColMat, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par, Side};

use super::{rows_of, Columns, Gram, Sparse, DROPPED};
use crate::solve::supernodal;

/// The structure of `G = J Jᵀ`: an upper-triangular CSC pattern, and the products of two
/// Jacobian entries that make each of its entries.
pub(super) struct Pattern {
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    products: Products,
}

impl Pattern {
    /// From the nonzeros of `J`, given column by column as `(row, index into J's values)`.
    ///
    /// Column `i` of the upper triangle of `G` holds the rows `j <= i` that share a column of
    /// `J` with row `i`, and all of its products come from row `i`'s entries: each column is
    /// built on its own, its products counted and then placed, into arrays sized beforehand
    /// (a 200x200 truss makes 800,000 products; growing lists of them cost more in copying
    /// and fresh pages than the arithmetic did).
    pub(super) fn new(nrows: usize, columns: &Columns) -> Self {
        let (row_ptr, row_entries) = rows_of(nrows, columns);
        let total = Gram::products(columns);
        // Per row j of the column being built: its products so far (0: not met yet), then
        // where its next product goes.
        let mut count = vec![0u32; nrows];
        let mut at = vec![0u32; nrows];
        let mut touched: Vec<u32> = Vec::new();
        let mut col_ptr = Vec::with_capacity(nrows + 1);
        col_ptr.push(0usize);
        // At most one entry per product, and a diagonal for each empty row besides.
        let mut row_idx: Vec<usize> = Vec::with_capacity(total.min(nrows * nrows) + nrows);
        let mut ptr: Vec<u32> = Vec::with_capacity(total.min(nrows * nrows) + nrows + 1);
        ptr.push(0);
        let mut pairs = vec![(0u32, 0u32); total];
        let mut next = 0u32;
        for i in 0..nrows {
            let entries = &row_entries[row_ptr[i]..row_ptr[i + 1]];
            touched.clear();
            for &(c, _) in entries {
                for &(j, _) in columns.col(c as usize) {
                    if j as usize <= i {
                        if count[j as usize] == 0 {
                            touched.push(j);
                        }
                        count[j as usize] += 1;
                    }
                }
            }
            // An empty Jacobian row still gets its diagonal: a zero pivot, a dropped equation.
            if count[i] == 0 {
                touched.push(i as u32);
            }
            touched.sort_unstable();
            for &j in &touched {
                row_idx.push(j as usize);
                at[j as usize] = next;
                next += count[j as usize];
                ptr.push(next);
                count[j as usize] = 0;
            }
            // The products of each entry in the order of the columns of J they come from.
            for &(c, b) in entries {
                for &(j, a) in columns.col(c as usize) {
                    if j as usize <= i {
                        let f = &mut at[j as usize];
                        pairs[*f as usize] = (a, b);
                        *f += 1;
                    }
                }
            }
            col_ptr.push(row_idx.len());
        }
        debug_assert_eq!(next as usize, total);
        Self {
            col_ptr,
            row_idx,
            products: Products { ptr, pairs },
        }
    }
}

/// An upper-triangular pattern (`col_ptr`, `row_idx`, rows ascending in each column) with row
/// and column `r` moved to `pos[r]`: as its upper triangle or (with `lower`) its lower one,
/// rows ascending in each column, and where each entry went. Two counting sorts, by row and
/// then stably by column.
fn renumbered(
    col_ptr: &[usize],
    row_idx: &[usize],
    pos: &[usize],
    lower: bool,
) -> (Vec<usize>, Vec<usize>, Vec<u32>) {
    let n = col_ptr.len() - 1;
    let nnz = row_idx.len();
    let (mut cols, mut rows) = (vec![0u32; nnz], vec![0u32; nnz]);
    let (mut col_ptr_new, mut row_start) = (vec![0usize; n + 1], vec![0usize; n + 1]);
    for j in 0..n {
        for k in col_ptr[j]..col_ptr[j + 1] {
            let (a, b) = (pos[row_idx[k]], pos[j]);
            let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
            let (c, r) = if lower { (lo, hi) } else { (hi, lo) };
            (cols[k], rows[k]) = (c as u32, r as u32);
            col_ptr_new[c + 1] += 1;
            row_start[r + 1] += 1;
        }
    }
    for i in 0..n {
        col_ptr_new[i + 1] += col_ptr_new[i];
        row_start[i + 1] += row_start[i];
    }
    let mut by_row = vec![0u32; nnz];
    for (k, &r) in rows.iter().enumerate() {
        let at = &mut row_start[r as usize];
        by_row[*at] = k as u32;
        *at += 1;
    }
    let mut next = col_ptr_new.clone();
    let mut row_idx_new = vec![0usize; nnz];
    let mut moved = vec![0u32; nnz];
    for &k in &by_row {
        let (c, r) = (cols[k as usize] as usize, rows[k as usize]);
        let at = &mut next[c];
        row_idx_new[*at] = r as usize;
        moved[k as usize] = *at as u32;
        *at += 1;
    }
    (col_ptr_new, row_idx_new, moved)
}

impl Products {
    /// The same products with entry `k` moved to `moved[k]`, each keeping its products in
    /// their order (so every entry of `G` is summed exactly as before).
    fn renumbered(&self, moved: &[u32]) -> Self {
        let nnz = moved.len();
        let mut ptr = vec![0u32; nnz + 1];
        for (k, &e) in moved.iter().enumerate() {
            ptr[e as usize + 1] = self.ptr[k + 1] - self.ptr[k];
        }
        for e in 0..nnz {
            ptr[e + 1] += ptr[e];
        }
        let mut pairs = vec![(0u32, 0u32); self.pairs.len()];
        for (k, &e) in moved.iter().enumerate() {
            let from = &self.pairs[self.ptr[k] as usize..self.ptr[k + 1] as usize];
            let at = ptr[e as usize] as usize;
            // Element by element: a slice copy calls memcpy for the few pairs of an entry.
            for (to, &p) in pairs[at..at + from.len()].iter_mut().zip(from) {
                *to = p;
            }
        }
        Self { ptr, pairs }
    }
}

/// The products of Jacobian entries that make `G`, grouped by the entry of `G` they add to:
/// entry `e` is the sum of `jv[a] * jv[b]` over `pairs[ptr[e]..ptr[e + 1]]`. Every entry is
/// written once, so none is cleared first, and entries can be computed in parallel runs.
struct Products {
    ptr: Vec<u32>,
    pairs: Vec<(u32, u32)>,
}

/// From this many products on, `G` is assembled on all cores.
#[cfg(feature = "parallel")]
const PARALLEL_PRODUCTS: usize = 1 << 16;

impl Products {
    /// The entries `e0..e0 + v.len()` into `v`, from the Jacobian values `jv`.
    #[inline]
    fn fill(&self, v: &mut [f64], e0: usize, jv: &[f64]) {
        for (k, x) in v.iter_mut().enumerate() {
            let (s, t) = (self.ptr[e0 + k] as usize, self.ptr[e0 + k + 1] as usize);
            let mut acc = 0.0;
            for &(a, b) in &self.pairs[s..t] {
                acc += jv[a as usize] * jv[b as usize];
            }
            *x = acc;
        }
    }

    /// `v[e]` for every entry, from the Jacobian values `jv`.
    fn assemble(&self, v: &mut [f64], jv: &[f64]) {
        let run = |v: &mut [f64], e0: usize| self.fill(v, e0, jv);
        #[cfg(feature = "parallel")]
        if self.pairs.len() >= PARALLEL_PRODUCTS {
            use rayon::prelude::*;
            let chunk = v.len().div_ceil(4 * rayon::current_num_threads()).max(1024);
            v.par_chunks_mut(chunk)
                .enumerate()
                .for_each(|(i, c)| run(c, i * chunk));
            return;
        }
        run(v, 0);
    }
}

/// When the automatic choice takes dense blocks of columns: at a quarter of faer's own
/// threshold on the predicted flops per entry of the factor. A 100x100 truss factorised in
/// 9 ms in blocks and 13-19 ms column by column, which faer's own threshold would have chosen.
/// With the blocks solved by [`supernodal::solve`], a quarter (rather than half) also sends
/// mid-sized components to the blocks: the 20x20 mesh solves 11% faster (2.51 against
/// 2.81 ms, best median of eight alternated runs), its inconsistent variant 17%, the 50x50
/// truss 8% and the 50x50 profiles 6%; the 20x20 truss is unchanged.
const SUPERNODAL_THRESHOLD: SupernodalThreshold = SupernodalThreshold(0.25);

/// faer's factor of its threshold on the flops per entry of the factor at which it factorises
/// in dense blocks of columns: `flops / entries > threshold * 40` (faer 0.24,
/// `CHOLESKY_SUPERNODAL_RATIO_FACTOR`). The choice is made here, with faer's own rule, as the
/// order is found here.
const SUPERNODAL_RATIO_FACTOR: f64 = 40.0;

/// From this many right-hand sides on, a supernodal factor is solved with faer's own blocked
/// kernels, whose matrix products win once a supernode's block serves that many columns (the
/// circuits of an inconsistent 50x50 mesh, 32 at a time, took 2-3% longer through
/// [`supernodal::solve`]).
const FAER_BLOCK: usize = 8;

/// `G = J Jᵀ` for one component, with its sparse factorisation.
pub(crate) struct SparseGram {
    pub(super) n: usize,
    pub(super) pattern: SymbolicSparseColMat<usize>,
    pub(super) vals: Vec<f64>,
    /// The products that make each entry of `G`.
    products: Products,
    pub(super) symbolic: SymbolicCholesky<usize>,
    pub(super) l_values: Vec<f64>,
    signs: Vec<i8>,
    shifted: Vec<f64>,
    /// Position of each diagonal entry in `vals`: the last of its column in the upper
    /// triangle, the first in the lower (rows are sorted).
    diag: Vec<usize>,
    /// Which triangle `pattern` holds: the one the factorisation reads (faer's simplicial
    /// factorisation the upper, its supernodal one the lower), so that it copies nothing.
    pub(super) side: Side,
    /// The row of `G` at each position of the fill-reducing order, and the position of each
    /// row: `pattern` is already in that order.
    pub(super) fwd: Vec<usize>,
    pub(super) inv: Vec<usize>,
    mem: MemBuffer,
    /// A right-hand side in the factor's order, and the work vector of a supernodal solve.
    permuted: Vec<f64>,
    below: Vec<f64>,
}

impl SparseGram {
    pub(super) fn new(nrows: usize, pattern: Pattern, sparse: Sparse) -> Option<Self> {
        Self::new_with(
            nrows,
            pattern,
            match sparse {
                Sparse::Auto => SUPERNODAL_THRESHOLD,
                Sparse::Simplicial => SupernodalThreshold::FORCE_SIMPLICIAL,
                Sparse::Supernodal => SupernodalThreshold::FORCE_SUPERNODAL,
            },
        )
    }

    pub(super) fn new_with(
        nrows: usize,
        pattern: Pattern,
        threshold: SupernodalThreshold,
    ) -> Option<Self> {
        // The fill-reducing order is found first, as faer would find it, and `G`'s pattern
        // and products renumbered into it once: faer then factorises `G` as it is given,
        // where it would otherwise permute it at every factorisation (5% of a 10x10 sheet of
        // profiles' solve).
        let nnz = pattern.row_idx.len();
        let (mut fwd, mut inv) = (vec![0usize; nrows], vec![0usize; nrows]);
        let flops = {
            let upper = SymbolicSparseColMatRef::new_checked(
                nrows,
                nrows,
                &pattern.col_ptr,
                None,
                &pattern.row_idx,
            );
            let mut mem =
                MemBuffer::try_new(amd::order_maybe_unsorted_scratch::<usize>(nrows, nnz)).ok()?;
            amd::order_maybe_unsorted(
                &mut fwd,
                &mut inv,
                upper,
                amd::Control::default(),
                MemStack::new(&mut mem),
            )
            .ok()?
        };
        // The factorisation's structure, from the upper triangle in that order: dense blocks
        // of columns (supernodal) where faer would choose them, by its rule on the flops per
        // entry of the factor.
        let (col_ptr, row_idx, moved) = renumbered(&pattern.col_ptr, &pattern.row_idx, &inv, false);
        let upper = SymbolicSparseColMat::new_checked(nrows, nrows, col_ptr, None, row_idx);
        // AMD counts, as it orders, the factor's entries below the diagonal (`n_div`) and its
        // multiply-adds; the factor holds `n_div` entries and the diagonal (exactly so on
        // every benchmark family: both figures are estimates only where AMD sets dense rows
        // aside).
        let supernodal = (flops.n_div + flops.n_mult_subs_ldl) / (flops.n_div + nrows as f64)
            > threshold.0 * SUPERNODAL_RATIO_FACTOR;
        let symbolic = factorize_symbolic_cholesky(
            upper.as_ref(),
            Side::Upper,
            SymmetricOrdering::Identity,
            CholeskySymbolicParams {
                supernodal_flop_ratio_threshold: if supernodal {
                    SupernodalThreshold::FORCE_SUPERNODAL
                } else {
                    SupernodalThreshold::FORCE_SIMPLICIAL
                },
                ..Default::default()
            },
        )
        .ok()?;
        // `G` itself as the factorisation reads it: the upper triangle for the simplicial
        // one, the lower for the supernodal one.
        let (pattern, products, side, diag) = if supernodal {
            let (col_ptr, row_idx, moved) =
                renumbered(&pattern.col_ptr, &pattern.row_idx, &inv, true);
            let diag = col_ptr[..nrows].to_vec();
            let lower = SymbolicSparseColMat::new_checked(nrows, nrows, col_ptr, None, row_idx);
            (
                lower,
                pattern.products.renumbered(&moved),
                Side::Lower,
                diag,
            )
        } else {
            let diag = (0..nrows).map(|c| upper.col_ptr()[c + 1] - 1).collect();
            (
                upper,
                pattern.products.renumbered(&moved),
                Side::Upper,
                diag,
            )
        };
        let req = StackReq::any_of(&[
            symbolic.factorize_numeric_ldlt_scratch::<f64>(Par::Seq, Default::default()),
            symbolic.solve_in_place_scratch::<f64>(1, Par::Seq),
        ]);
        let mem = MemBuffer::try_new(req).ok()?;
        let l_values = vec![0.0; symbolic.len_val()];
        let below = match symbolic.raw() {
            SymbolicCholeskyRaw::Supernodal(s) => vec![0.0; supernodal::work_len(s)],
            SymbolicCholeskyRaw::Simplicial(_) => Vec::new(),
        };
        Some(Self {
            n: nrows,
            pattern,
            vals: vec![0.0; nnz],
            products,
            symbolic,
            l_values,
            signs: vec![1; nrows],
            shifted: vec![0.0; nrows],
            diag,
            side,
            fwd,
            inv,
            mem,
            permuted: vec![0.0; nrows],
            below,
        })
    }

    /// Computes `G` from the Jacobian values `jv`.
    pub fn assemble(&mut self, jv: &[f64]) {
        self.products.assemble(&mut self.vals, jv);
    }

    /// Factorises `G + lambda I` (with `G` from the last [`Gram::assemble`]); pivots at or
    /// below `eps` are dropped. Returns false when the factorisation failed numerically.
    pub fn factor(&mut self, lambda: f64, eps: f64) -> bool {
        if lambda == 0.0 {
            return self.factor_current(eps);
        }
        for (c, &d) in self.diag.iter().enumerate() {
            self.shifted[c] = self.vals[d];
            self.vals[d] += lambda;
        }
        let ok = self.factor_current(eps);
        for (c, &d) in self.diag.iter().enumerate() {
            self.vals[d] = self.shifted[c];
        }
        ok
    }

    fn factor_current(&mut self, eps: f64) -> bool {
        let a = SparseColMatRef::new(self.pattern.as_ref(), &self.vals);
        let reg = LdltRegularization {
            dynamic_regularization_signs: Some(&self.signs),
            dynamic_regularization_delta: DROPPED,
            dynamic_regularization_epsilon: eps,
        };
        let stack = MemStack::new(&mut self.mem);
        self.symbolic
            .factorize_numeric_ldlt(
                &mut self.l_values,
                a,
                self.side,
                reg,
                Par::Seq,
                stack,
                Default::default(),
            )
            .is_ok()
    }

    /// The rows whose pivots were dropped in the last factorisation, ascending.
    pub fn dropped(&self) -> Vec<usize> {
        let mut out = Vec::new();
        self.each_pivot(|k, d| {
            if d >= DROPPED {
                out.push(self.fwd[k]);
            }
        });
        out.sort_unstable();
        out
    }

    /// The smallest pivot the last factorisation kept (infinity when it kept none).
    pub fn smallest_kept_pivot(&self) -> f64 {
        let mut least = f64::INFINITY;
        self.each_pivot(|_, d| {
            if d < DROPPED {
                least = least.min(d);
            }
        });
        least
    }

    /// Calls `keep(k, d)` with the pivot `d` of each position `k` of the ordering.
    fn each_pivot(&self, mut keep: impl FnMut(usize, f64)) {
        match self.symbolic.raw() {
            SymbolicCholeskyRaw::Simplicial(s) => {
                // D is the first entry of each column.
                let col_ptr = s.col_ptr();
                for k in 0..self.n {
                    keep(k, self.l_values[col_ptr[k]]);
                }
            }
            SymbolicCholeskyRaw::Supernodal(s) => {
                // Each supernode is a dense column-major block whose top square holds D on its
                // diagonal.
                let val_ptr = s.col_ptr_for_val();
                let (begin, end) = (s.supernode_begin(), s.supernode_end());
                for sn in 0..s.n_supernodes() {
                    let ncols = end[sn] - begin[sn];
                    let base = val_ptr[sn];
                    let nrows = (val_ptr[sn + 1] - base) / ncols.max(1);
                    for j in 0..ncols {
                        keep(begin[sn] + j, self.l_values[base + j * nrows + j]);
                    }
                }
            }
        }
    }

    /// Whether the factorisation works in dense blocks of columns.
    #[cfg(test)]
    pub fn is_supernodal(&self) -> bool {
        matches!(self.symbolic.raw(), SymbolicCholeskyRaw::Supernodal(_))
    }

    /// Solves `G Y = B` in place for the `k` columns of `B`, one after another.
    pub(super) fn solve_many(&mut self, rhs: &mut [f64], k: usize) {
        let n = self.n;
        // Into the factor's order, solved there, and back.
        let mut x = std::mem::take(&mut self.permuted);
        x.resize(n * k, 0.0);
        for (xc, bc) in x.chunks_mut(n.max(1)).zip(rhs.chunks(n.max(1))) {
            for (xi, &f) in xc.iter_mut().zip(&self.fwd) {
                *xi = bc[f];
            }
        }
        self.solve_in_order(&mut x, k);
        for (xc, bc) in x.chunks(n.max(1)).zip(rhs.chunks_mut(n.max(1))) {
            for (b, &i) in bc.iter_mut().zip(&self.inv) {
                *b = xc[i];
            }
        }
        x.truncate(n);
        self.permuted = x;
    }

    /// [`SparseGram::solve_many`] for right-hand sides already in the factor's order.
    fn solve_in_order(&mut self, x: &mut [f64], k: usize) {
        match self.symbolic.raw() {
            SymbolicCholeskyRaw::Supernodal(s) if k < FAER_BLOCK => {
                supernodal::solve(s, &self.l_values, x, k, &mut self.below);
            }
            _ => {
                let ldlt = LdltRef::new(&self.symbolic, &self.l_values);
                let m = MatMut::from_column_major_slice_mut(x, self.n, k);
                if k == 1 {
                    let stack = MemStack::new(&mut self.mem);
                    ldlt.solve_in_place_with_conj(Conj::No, m, Par::Seq, stack);
                    return;
                }
                let req = self.symbolic.solve_in_place_scratch::<f64>(k, Par::Seq);
                match MemBuffer::try_new(req) {
                    Ok(mut mem) => {
                        ldlt.solve_in_place_with_conj(
                            Conj::No,
                            m,
                            Par::Seq,
                            MemStack::new(&mut mem),
                        );
                    }
                    Err(_) => {
                        // One column at a time, in the scratch space kept for one.
                        for c in x.chunks_mut(self.n.max(1)) {
                            let m = MatMut::from_column_major_slice_mut(c, self.n, 1);
                            let stack = MemStack::new(&mut self.mem);
                            ldlt.solve_in_place_with_conj(Conj::No, m, Par::Seq, stack);
                        }
                    }
                }
            }
        }
    }

    /// Solves `G y = rhs` in place with the last factorisation.
    pub fn solve(&mut self, rhs: &mut [f64]) {
        self.solve_many(rhs, 1);
    }
}
