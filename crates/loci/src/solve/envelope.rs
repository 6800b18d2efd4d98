//! An envelope (profile) LDLᵀ with dropped pivots, for Gram matrices that are banded in the
//! order their equations come in.
//!
//! A chain of segments, a 3D chain or a row of fillets gives equations that each meet only
//! their neighbours: `G = J Jᵀ` is then banded as it stands, and the fill of its LDLᵀ stays
//! inside the envelope of each row (the entries from its first nonzero to the diagonal). So no
//! ordering and no symbolic analysis are needed, and each row is eliminated with dot products
//! of contiguous slices. Small components of any shape use it too: their envelope is at most
//! the whole triangle. Rows are eliminated in order, and a row whose pivot (its squared distance
//! from the span of the rows before it) is at or below the tolerance is dropped (its `D` is
//! infinite, its column of `L` zero).

/// `G`'s lower triangle within its envelope, and its factors in the same layout.
pub(crate) struct EnvelopeLdlt {
    /// Row `i` covers columns `first[i]..=i`.
    first: Vec<u32>,
    /// Row `i` is stored at `ptr[i]..ptr[i + 1]`, its diagonal last.
    ptr: Vec<usize>,
    /// The unit lower factor below the diagonal, `D` on it.
    l: Vec<f64>,
    /// `1 / D`, and 0 for a dropped row: its column of `L` and its part of the solution
    /// vanish without a branch.
    dinv: Vec<f64>,
}

impl EnvelopeLdlt {
    /// The envelope of rows whose first nonzero columns are `first` (each at most its row).
    /// `G` itself is not stored: [`Self::factor_rows`] is given it row by row as it
    /// factorises. A long chain's envelope holds millions of entries, and a copy of them all
    /// is as many fresh pages.
    pub fn new(first: Vec<u32>) -> Self {
        let n = first.len();
        let mut ptr = Vec::with_capacity(n + 1);
        ptr.push(0usize);
        for (i, &f) in first.iter().enumerate() {
            ptr.push(ptr[i] + i + 1 - f as usize);
        }
        let len = ptr[n];
        Self {
            first,
            ptr,
            l: vec![0.0; len],
            dinv: vec![0.0; n],
        }
    }

    /// The number of entries in the envelope (its size).
    pub fn len(&self) -> usize {
        self.l.len()
    }

    /// The first column row `i` covers.
    #[cfg(test)]
    pub fn first(&self, i: usize) -> usize {
        self.first[i] as usize
    }

    /// Position of entry (i, j), `first[i] <= j <= i`, in an envelope-sized array.
    #[cfg(test)]
    pub fn index(&self, i: usize, j: usize) -> usize {
        self.ptr[i] + j - self.first[i] as usize
    }

    /// Factorises `G + lambda I` with `G` given within the envelope, row by row (entries
    /// at [`Self::index`]); pivots at or below `eps` are dropped.
    #[cfg(test)]
    pub fn factor(&mut self, a: &[f64], lambda: f64, eps: f64) -> bool {
        let ptr = self.ptr.clone();
        self.factor_rows(lambda, eps, |i, _, row| {
            row.copy_from_slice(&a[ptr[i]..ptr[i + 1]]);
        })
    }

    /// Factorises `G + lambda I`, with `G` given row by row as the factorisation reaches it:
    /// `row_of_g(i, f, out)` writes the entries of row `i` from column `f` (its first) to the
    /// diagonal into `out`. Pivots at or below `eps` are dropped. Returns false when a pivot
    /// is not finite.
    pub fn factor_rows(
        &mut self,
        lambda: f64,
        eps: f64,
        mut row_of_g: impl FnMut(usize, usize, &mut [f64]),
    ) -> bool {
        let n = self.first.len();
        for i in 0..n {
            let fi = self.first[i] as usize;
            let (start, end) = (self.ptr[i], self.ptr[i + 1]);
            let w = end - start - 1;
            let (done, rest) = self.l.split_at_mut(start);
            let row = &mut rest[..=w];
            row_of_g(i, fi, row);
            // First (L D)[i][k] = G[i][k] - sum over m < k of (L D)[i][m] L[k][m], in place.
            for (t, (&fk, &pk)) in self.first[fi..i].iter().zip(&self.ptr[fi..i]).enumerate() {
                // Columns both rows cover: from max(fi, fk) to k - 1, with k = fi + t.
                let fk = fk as usize;
                let (lo, from) = if fk > fi {
                    (fk - fi, pk)
                } else {
                    (0, pk + fi - fk)
                };
                let s: f64 = row[lo..t]
                    .iter()
                    .zip(&done[from..from + t - lo])
                    .map(|(x, y)| x * y)
                    .sum();
                row[t] -= s;
            }
            // Then L[i][k] = (L D)[i][k] / D[k], and D[i].
            let mut d = row[w] + lambda;
            for (t, v) in row[..w].iter_mut().enumerate() {
                let u = *v;
                *v = u * self.dinv[fi + t];
                d -= u * *v;
            }
            if !d.is_finite() {
                return false;
            }
            row[w] = d;
            self.dinv[i] = if d <= eps { 0.0 } else { 1.0 / d };
        }
        true
    }

    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.first.len()
    }

    /// The smallest pivot the last factorisation kept (infinity when it kept none).
    pub fn smallest_kept_pivot(&self) -> f64 {
        (0..self.first.len())
            .filter(|&i| self.dinv[i] != 0.0)
            .map(|i| self.l[self.ptr[i + 1] - 1])
            .fold(f64::INFINITY, f64::min)
    }

    /// The rows whose pivots were dropped in the last factorisation, ascending.
    pub fn dropped(&self) -> Vec<usize> {
        (0..self.first.len())
            .filter(|&i| self.dinv[i] == 0.0)
            .collect()
    }

    /// Solves `G y = b` in place with the factors; dropped rows get 0.
    pub fn solve(&self, b: &mut [f64]) {
        let n = self.first.len();
        for i in 0..n {
            let fi = self.first[i] as usize;
            let row = &self.l[self.ptr[i]..self.ptr[i + 1] - 1];
            let s: f64 = row.iter().zip(&b[fi..i]).map(|(x, y)| x * y).sum();
            b[i] -= s;
        }
        for (v, dinv) in b.iter_mut().zip(&self.dinv) {
            *v *= dinv;
        }
        for i in (0..n).rev() {
            let fi = self.first[i] as usize;
            let yi = b[i];
            if yi == 0.0 {
                continue;
            }
            let row = &self.l[self.ptr[i]..self.ptr[i + 1] - 1];
            for (x, l) in b[fi..i].iter_mut().zip(row) {
                *x -= l * yi;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::dense::DenseLdlt;
    use super::*;

    /// A banded symmetric `G = J Jᵀ` from a chain-like `J` with a dependent row, factorised both
    /// ways.
    fn both(j: &[Vec<f64>], lambda: f64) -> (EnvelopeLdlt, DenseLdlt) {
        let m = j.len();
        let dot = |a: usize, b: usize| j[a].iter().zip(&j[b]).map(|(x, y)| x * y).sum::<f64>();
        let first: Vec<u32> = (0..m)
            .map(|i| (0..=i).find(|&k| dot(i, k) != 0.0).unwrap_or(i) as u32)
            .collect();
        let mut e = EnvelopeLdlt::new(first.clone());
        let mut d = DenseLdlt::new(m);
        let mut a = vec![0.0; e.len()];
        for i in 0..m {
            for k in first[i] as usize..=i {
                let (ie, id) = (e.index(i, k), d.index(i, k));
                a[ie] = dot(i, k);
                d.values_mut()[id] = dot(i, k);
            }
        }
        assert!(e.factor(&a, lambda, 1e-10));
        assert!(d.factor(lambda, 1e-10));
        (e, d)
    }

    fn chain_jacobian() -> Vec<Vec<f64>> {
        // Rows meeting only their neighbours; row 4 = row 2 + row 3 (dependent).
        vec![
            vec![1.0, 0.5, 0.0, 0.0, 0.0, 0.0],
            vec![0.0, 1.0, -0.3, 0.0, 0.0, 0.0],
            vec![0.0, 0.0, 0.7, 1.0, 0.0, 0.0],
            vec![0.0, 0.0, 0.0, 0.2, 1.0, 0.0],
            vec![0.0, 0.0, 0.7, 1.2, 1.0, 0.0],
            vec![0.0, 0.0, 0.0, 0.0, 0.4, 1.0],
        ]
    }

    #[test]
    fn matches_the_dense_factorisation_and_drops_the_dependent_row() {
        let (mut e, d) = both(&chain_jacobian(), 0.0);
        assert_eq!(e.dropped(), vec![4]);
        assert_eq!(d.dropped(), vec![4]);
        let rhs = [1.0, -2.0, 0.5, 3.0, 7.0, -1.0];
        let (mut ye, mut yd) = (rhs, rhs);
        e.solve(&mut ye);
        d.solve(&mut yd);
        for (a, b) in ye.iter().zip(&yd) {
            assert!((a - b).abs() < 1e-12, "{ye:?} vs {yd:?}");
        }
        assert_eq!(ye[4], 0.0);
        // Each row from its first nonzero to the diagonal: 1 + 2 + 2 + 2 + 4 + 3 entries.
        assert_eq!(e.len(), 14);
        assert!(!e.factor(&[f64::NAN; 14], 0.0, 1e-10));
    }

    #[test]
    fn damped_factorisation_solves_the_shifted_system() {
        let j = chain_jacobian();
        let (e, _) = both(&j, 0.5);
        assert!(e.dropped().is_empty());
        // (G + 0.5 I) y = b, checked by multiplying back.
        let b = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        let mut y = b;
        e.solve(&mut y);
        for i in 0..6 {
            let gy: f64 = (0..6)
                .map(|k| {
                    let g: f64 = j[i].iter().zip(&j[k]).map(|(x, z)| x * z).sum();
                    (g + if i == k { 0.5 } else { 0.0 }) * y[k]
                })
                .sum();
            assert!((gy - b[i]).abs() < 1e-12, "row {i}: {gy} vs {}", b[i]);
        }
    }
}
