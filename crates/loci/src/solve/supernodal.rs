//! Solves with a supernodal LDLᵀ factor, for one or a few right-hand sides.
//!
//! faer's own solve treats every supernode as a dense matrix problem: a triangular solve and a
//! matrix product through its general kernels, each with a fixed cost. The factor of a
//! two-dimensional sketch (a truss, a mesh) has tens of thousands of supernodes of a few
//! columns, so that fixed cost dominates: a 200x200 truss's `G` (2.8 million entries in its
//! factor) took 10.4-10.9 ms to solve with, now 4.9 ms, about the time reading the factor
//! twice takes. The loops below read each supernode's block once, column by column, in the
//! order it is stored, and apply it to each right-hand side in turn. Many right-hand sides at
//! once are left to faer's blocked kernels (see `FAER_BLOCK` in `gram.rs`).
//!
//! Each supernode `s` covers the columns `begin..end` of the (permuted) factor. Its values are
//! one column-major block of `ncols + pattern` rows: the top square holds the unit lower
//! triangle of `L` with `D` on its diagonal, the rows below are `L`'s entries in the rows
//! listed by the supernode's pattern.

use faer::sparse::linalg::cholesky::supernodal::SymbolicSupernodalCholesky;

/// One supernode's columns and rows, and its block of values.
struct Supernode<'a> {
    start: usize,
    ncols: usize,
    pattern: &'a [usize],
    block: &'a [f64],
}

impl<'a> Supernode<'a> {
    fn of(symbolic: &'a SymbolicSupernodalCholesky<usize>, values: &'a [f64], s: usize) -> Self {
        let start = symbolic.supernode_begin()[s];
        let ncols = symbolic.supernode_end()[s] - start;
        let p0 = symbolic.col_ptr_for_row_idx()[s];
        let pattern = &symbolic.row_idx()[p0..p0 + symbolic.nnz_per_super()[s]];
        let v = symbolic.col_ptr_for_val();
        Self {
            start,
            ncols,
            pattern,
            block: &values[v[s]..v[s + 1]],
        }
    }

    /// Rows of the block.
    fn nrows(&self) -> usize {
        self.ncols + self.pattern.len()
    }
}

/// The dot product of two slices of one length, in four running sums (a fixed order, so the
/// result is the same on every run).
#[inline]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let mut acc = [0.0f64; 4];
    let (a4, a1) = a.split_at(a.len() - a.len() % 4);
    let (b4, b1) = b.split_at(a4.len());
    for (x, y) in a4.chunks_exact(4).zip(b4.chunks_exact(4)) {
        for k in 0..4 {
            acc[k] += x[k] * y[k];
        }
    }
    let mut sum = (acc[0] + acc[1]) + (acc[2] + acc[3]);
    for (x, y) in a1.iter().zip(b1) {
        sum += x * y;
    }
    sum
}

/// The longest pattern of any supernode: the length of the work vector [`solve`] needs.
pub(crate) fn work_len(symbolic: &SymbolicSupernodalCholesky<usize>) -> usize {
    symbolic.nnz_per_super().iter().copied().max().unwrap_or(0)
}

/// Solves `L D Lᵀ X = B` in place for the `k` columns of `B` (`x` holds them one after
/// another, in the factor's own order), with `work` at least [`work_len`] long. Each supernode
/// is applied to every column in turn, so that its block is read from memory once for all.
pub(crate) fn solve(
    symbolic: &SymbolicSupernodalCholesky<usize>,
    values: &[f64],
    x: &mut [f64],
    k: usize,
    work: &mut [f64],
) {
    let n = symbolic.nrows();
    let count = symbolic.n_supernodes();
    if n == 0 {
        return;
    }
    // L Z = B: within the supernode, then its contribution to the rows below.
    for s in 0..count {
        let sn = Supernode::of(symbolic, values, s);
        let (nr, nc, st) = (sn.nrows(), sn.ncols, sn.start);
        for x in x.chunks_mut(n).take(k) {
            let below = &mut work[..sn.pattern.len()];
            below.fill(0.0);
            for j in 0..nc {
                let col = &sn.block[j * nr..(j + 1) * nr];
                let xj = x[st + j];
                for i in j + 1..nc {
                    x[st + i] -= col[i] * xj;
                }
                for (w, l) in below.iter_mut().zip(&col[nc..]) {
                    *w += l * xj;
                }
            }
            for (&i, w) in sn.pattern.iter().zip(below.iter()) {
                x[i] -= w;
            }
        }
    }
    // D W = Z.
    for s in 0..count {
        let sn = Supernode::of(symbolic, values, s);
        let nr = sn.nrows();
        for j in 0..sn.ncols {
            let d = sn.block[j * nr + j].recip();
            for x in x.chunks_mut(n).take(k) {
                x[sn.start + j] *= d;
            }
        }
    }
    // Lᵀ X = W, from the last supernode back.
    for s in (0..count).rev() {
        let sn = Supernode::of(symbolic, values, s);
        let (nr, nc, st) = (sn.nrows(), sn.ncols, sn.start);
        for x in x.chunks_mut(n).take(k) {
            let below = &mut work[..sn.pattern.len()];
            for (w, &i) in below.iter_mut().zip(sn.pattern) {
                *w = x[i];
            }
            for j in (0..nc).rev() {
                let col = &sn.block[j * nr..(j + 1) * nr];
                let mut acc = x[st + j] - dot(&col[nc..], below);
                for i in j + 1..nc {
                    acc -= col[i] * x[st + i];
                }
                x[st + j] = acc;
            }
        }
    }
}
