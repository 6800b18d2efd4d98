//! A plain dense LDLᵀ with dropped pivots: the reference the envelope factorisation
//! ([`super::envelope`]) is tested against.
//!
//! Rows are eliminated in order, and a row whose pivot (its squared distance from the span of
//! the rows before it) is at or below the tolerance is dropped from the solve.

/// `G` as a dense symmetric matrix (lower triangle used) and its factors.
pub(crate) struct DenseLdlt {
    n: usize,
    /// `G` then its factors, one allocation: `G` row-major `n x n` (`[i * n + j]` for `j <= i`),
    /// then the unit lower factor below the diagonal with `D` on it (infinite for a dropped
    /// row), row-major alike.
    m: Vec<f64>,
}

impl DenseLdlt {
    pub fn new(n: usize) -> Self {
        Self {
            n,
            m: vec![0.0; 2 * n * n],
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
        let nn = self.n * self.n;
        &mut self.m[..nn]
    }

    /// Factorises `G + lambda I`; pivots at or below `eps` are dropped.
    pub fn factor(&mut self, lambda: f64, eps: f64) -> bool {
        let n = self.n;
        let (a, l) = self.m.split_at_mut(n * n);
        // A dropped row contributes nothing (its column of L is zero): its D is infinite.
        let kept = |l: &[f64], j: usize| l[j * n + j] != f64::INFINITY;
        for k in 0..n {
            let mut d = a[k * n + k] + lambda;
            for j in 0..k {
                if kept(l, j) {
                    let lkj = l[k * n + j];
                    d -= lkj * lkj * l[j * n + j];
                }
            }
            if !d.is_finite() {
                return false;
            }
            if d <= eps {
                l[k * n + k] = f64::INFINITY;
                for i in k + 1..n {
                    l[i * n + k] = 0.0;
                }
                continue;
            }
            l[k * n + k] = d;
            for i in k + 1..n {
                let mut v = a[i * n + k];
                for j in 0..k {
                    if kept(l, j) {
                        v -= l[i * n + j] * l[k * n + j] * l[j * n + j];
                    }
                }
                l[i * n + k] = v / d;
            }
        }
        true
    }

    fn l(&self) -> &[f64] {
        &self.m[self.n * self.n..]
    }

    pub fn dropped(&self) -> Vec<usize> {
        let (n, l) = (self.n, self.l());
        (0..n).filter(|&k| l[k * n + k] == f64::INFINITY).collect()
    }

    /// Solves `G y = b` in place with the factors; dropped rows get 0.
    pub fn solve(&self, b: &mut [f64]) {
        let (n, l) = (self.n, self.l());
        for i in 0..n {
            let mut v = b[i];
            for j in 0..i {
                v -= l[i * n + j] * b[j];
            }
            b[i] = v;
        }
        for i in 0..n {
            let d = l[i * n + i];
            b[i] = if d == f64::INFINITY { 0.0 } else { b[i] / d };
        }
        for i in (0..n).rev() {
            let mut v = b[i];
            for j in i + 1..n {
                v -= l[j * n + i] * b[j];
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
