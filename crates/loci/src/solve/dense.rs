//! A dense LDLᵀ with dropped pivots, for the small components most sketches split into.
//!
//! Same contract as the sparse factorisation in [`super::gram`]: rows are eliminated in order,
//! and a row whose pivot (its squared distance from the span of the rows before it) is at or
//! below the tolerance is dropped from the solve. For a handful of equations the set-up cost of a
//! general sparse factorisation (ordering, symbolic analysis, workspace) is many times the
//! arithmetic, and we need to know which pivots were dropped, so this is written out here.

/// `G` as a dense symmetric matrix (lower triangle used) and its factors.
pub(crate) struct DenseLdlt {
    n: usize,
    /// Row-major `n x n`; `a[i * n + j]` for `j <= i`.
    a: Vec<f64>,
    /// Unit lower factor below the diagonal, `D` on it; row-major like `a`.
    l: Vec<f64>,
    dropped: Vec<bool>,
}

impl DenseLdlt {
    pub fn new(n: usize) -> Self {
        Self {
            n,
            a: vec![0.0; n * n],
            l: vec![0.0; n * n],
            dropped: vec![false; n],
        }
    }

    /// Position of entry (i, j) in the storage (any order of i, j).
    pub fn index(&self, i: usize, j: usize) -> usize {
        if i >= j {
            i * self.n + j
        } else {
            j * self.n + i
        }
    }

    pub fn values_mut(&mut self) -> &mut [f64] {
        &mut self.a
    }

    /// Factorises `G + lambda I`; pivots at or below `eps` are dropped.
    pub fn factor(&mut self, lambda: f64, eps: f64) -> bool {
        let n = self.n;
        for k in 0..n {
            let mut d = self.a[k * n + k] + lambda;
            for j in 0..k {
                // A dropped row contributes nothing (its column of L is zero).
                if !self.dropped[j] {
                    let lkj = self.l[k * n + j];
                    d -= lkj * lkj * self.l[j * n + j];
                }
            }
            if !d.is_finite() {
                return false;
            }
            if d <= eps {
                self.dropped[k] = true;
                self.l[k * n + k] = f64::INFINITY;
                for i in k + 1..n {
                    self.l[i * n + k] = 0.0;
                }
                continue;
            }
            self.dropped[k] = false;
            self.l[k * n + k] = d;
            for i in k + 1..n {
                let mut v = self.a[i * n + k];
                for j in 0..k {
                    if !self.dropped[j] {
                        v -= self.l[i * n + j] * self.l[k * n + j] * self.l[j * n + j];
                    }
                }
                self.l[i * n + k] = v / d;
            }
        }
        true
    }

    pub fn dropped(&self) -> Vec<usize> {
        (0..self.n).filter(|&k| self.dropped[k]).collect()
    }

    /// Solves `G y = b` in place with the factors; dropped rows get 0.
    pub fn solve(&self, b: &mut [f64]) {
        let n = self.n;
        for i in 0..n {
            let mut v = b[i];
            for j in 0..i {
                v -= self.l[i * n + j] * b[j];
            }
            b[i] = v;
        }
        for i in 0..n {
            b[i] = if self.dropped[i] {
                0.0
            } else {
                b[i] / self.l[i * n + i]
            };
        }
        for i in (0..n).rev() {
            let mut v = b[i];
            for j in i + 1..n {
                v -= self.l[j * n + i] * b[j];
            }
            b[i] = v;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_dropped_rows_leave_the_rest_finite() {
        // Three identical rows: the second and third depend on the first.
        let mut g = DenseLdlt::new(3);
        for a in 0..3 {
            for b in 0..=a {
                let idx = g.index(a, b);
                g.values_mut()[idx] = 1.0;
            }
        }
        assert!(g.factor(0.0, 1e-10));
        assert_eq!(g.dropped(), vec![1, 2]);
        let mut y = [4.0, 4.0, 4.0];
        g.solve(&mut y);
        assert_eq!(y, [4.0, 0.0, 0.0]);
    }

    #[test]
    fn solves_and_drops_a_dependent_row() {
        // Rows of J: r0 = (1, 0), r1 = (0, 1), r2 = (1, 1) = r0 + r1. G = J Jᵀ.
        let j = [[1.0, 0.0], [0.0, 1.0], [1.0, 1.0]];
        let mut g = DenseLdlt::new(3);
        for a in 0..3 {
            for b in 0..=a {
                let idx = g.index(a, b);
                g.values_mut()[idx] = j[a][0] * j[b][0] + j[a][1] * j[b][1];
            }
        }
        assert!(g.factor(0.0, 1e-10));
        assert_eq!(g.dropped(), vec![2]);
        let mut y = [2.0, 3.0, 5.0];
        g.solve(&mut y);
        assert!((y[0] - 2.0).abs() < 1e-12 && (y[1] - 3.0).abs() < 1e-12 && y[2] == 0.0);
    }
}
