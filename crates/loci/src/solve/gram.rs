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

use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::cholesky::ldlt::factor::LdltRegularization;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, LdltRef, SymbolicCholesky,
    SymbolicCholeskyRaw, SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::{SparseColMatRef, SymbolicSparseColMat};
use faer::{Conj, MatMut, Par, Side};

/// The value a dropped pivot is replaced by.
const DROPPED: f64 = 1e150;

/// `G = J Jᵀ` for one component, with its factorisation.
pub(crate) struct Gram {
    n: usize,
    pattern: SymbolicSparseColMat<usize>,
    vals: Vec<f64>,
    /// `(entry of G, entry of J, entry of J)`: `G[e] += J[a] * J[b]`.
    contrib: Vec<(u32, u32, u32)>,
    symbolic: SymbolicCholesky<usize>,
    l_values: Vec<f64>,
    signs: Vec<i8>,
    mem: MemBuffer,
    /// Index into `vals` of each diagonal entry (the last entry of its upper-triangle column).
    diag: Vec<u32>,
}

impl Gram {
    /// Builds the structure from the nonzeros of `J`, given column by column as lists of
    /// `(row, index into J's values)`.
    pub fn new(nrows: usize, columns: &[Vec<(u32, u32)>]) -> Option<Self> {
        // Upper-triangle pattern: for every column, every pair of rows in it.
        let mut pairs: Vec<(u32, u32, u32, u32)> = Vec::new(); // (col of G, row of G, a, b)
        for col in columns {
            for (i, &(ri, ai)) in col.iter().enumerate() {
                for &(rj, aj) in &col[i..] {
                    let (lo, hi, a, b) = if ri <= rj {
                        (ri, rj, ai, aj)
                    } else {
                        (rj, ri, aj, ai)
                    };
                    pairs.push((hi, lo, a, b));
                }
            }
        }
        // Every row has a diagonal even if its Jacobian row is empty.
        let mut diag_seen = vec![false; nrows];
        for p in &pairs {
            if p.0 == p.1 {
                diag_seen[p.0 as usize] = true;
            }
        }
        pairs.sort_unstable();
        let mut col_ptr = vec![0usize; nrows + 1];
        let mut row_idx = Vec::new();
        let mut contrib = Vec::with_capacity(pairs.len());
        let mut k = 0;
        for c in 0..nrows {
            let start = row_idx.len();
            while k < pairs.len() && pairs[k].0 as usize == c {
                let r = pairs[k].1 as usize;
                if row_idx.len() == start || *row_idx.last().unwrap_or(&usize::MAX) != r {
                    row_idx.push(r);
                }
                contrib.push(((row_idx.len() - 1) as u32, pairs[k].2, pairs[k].3));
                k += 1;
            }
            if !diag_seen[c] {
                // An empty Jacobian row: a lone diagonal entry (the largest row index in its
                // column), which will be a zero pivot and so a dropped equation.
                row_idx.push(c);
            }
            col_ptr[c + 1] = row_idx.len();
        }
        let nnz = row_idx.len();
        let diag: Vec<u32> = col_ptr[1..].iter().map(|&end| (end - 1) as u32).collect();
        let pattern = SymbolicSparseColMat::new_checked(nrows, nrows, col_ptr, None, row_idx);
        let symbolic = factorize_symbolic_cholesky(
            pattern.as_ref(),
            Side::Upper,
            SymmetricOrdering::Amd,
            CholeskySymbolicParams {
                supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SIMPLICIAL,
                ..Default::default()
            },
        )
        .ok()?;
        let req = StackReq::any_of(&[
            symbolic.factorize_numeric_ldlt_scratch::<f64>(Par::Seq, Default::default()),
            symbolic.solve_in_place_scratch::<f64>(1, Par::Seq),
        ]);
        let mem = MemBuffer::try_new(req).ok()?;
        let l_values = vec![0.0; symbolic.len_val()];
        Some(Self {
            n: nrows,
            pattern,
            vals: vec![0.0; nnz],
            contrib,
            symbolic,
            l_values,
            signs: vec![1; nrows],
            mem,
            diag,
        })
    }

    /// Factorises `G` for the Jacobian values `jv`; pivots at or below `eps` are dropped.
    /// Returns false when the factorisation failed numerically.
    pub fn factor(&mut self, jv: &[f64], eps: f64) -> bool {
        self.factor_damped(jv, eps, 0.0)
    }

    /// Factorises `G + damping I`: the Levenberg–Marquardt system in the row space, whose
    /// step `Jᵀ y` shortens towards steepest descent as `damping` grows.
    pub fn factor_damped(&mut self, jv: &[f64], eps: f64, damping: f64) -> bool {
        self.vals.iter_mut().for_each(|v| *v = 0.0);
        for &(e, a, b) in &self.contrib {
            self.vals[e as usize] += jv[a as usize] * jv[b as usize];
        }
        for &d in &self.diag {
            self.vals[d as usize] += damping;
        }
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
                Side::Upper,
                reg,
                Par::Seq,
                stack,
                Default::default(),
            )
            .is_ok()
    }

    /// The rows whose pivots were dropped in the last factorisation, ascending.
    pub fn dropped(&self) -> Vec<usize> {
        let SymbolicCholeskyRaw::Simplicial(s) = self.symbolic.raw() else {
            return Vec::new();
        };
        let col_ptr = s.col_ptr();
        let mut out = Vec::new();
        for k in 0..self.n {
            if self.l_values[col_ptr[k]] >= DROPPED {
                let row = match self.symbolic.perm() {
                    Some(p) => p.arrays().0[k],
                    None => k,
                };
                out.push(row);
            }
        }
        out.sort_unstable();
        out
    }

    /// Solves `G y = rhs` in place with the last factorisation.
    pub fn solve(&mut self, rhs: &mut [f64]) {
        let ldlt = LdltRef::new(&self.symbolic, &self.l_values);
        let stack = MemStack::new(&mut self.mem);
        let m = MatMut::from_column_major_slice_mut(rhs, self.n, 1);
        ldlt.solve_in_place_with_conj(Conj::No, m, Par::Seq, stack);
    }
}
