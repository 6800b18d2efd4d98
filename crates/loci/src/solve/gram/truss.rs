//! A truss's Jacobian, for the tests of the normal equations.

use super::*;

/// The Jacobian of a truss: an `n x n` lattice of jittered points with a unit-normalised
/// distance row on every bar, a diagonal bracing the first cell, and (when `extra`) the
/// first cell's other diagonal, which depends on the cell's other rows. The first point is
/// fixed (its columns left out). Returns the rows, the column lists and the dense rows.
pub(super) fn truss(n: usize, extra: bool) -> (usize, Columns, Vec<Vec<(usize, f64)>>) {
    let mut seed = 0x5eed_u64;
    let mut jitter = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 5.0
    };
    let at = |i: usize, j: usize| j * n + i;
    let pts: Vec<[f64; 2]> = (0..n * n)
        .map(|k| {
            [
                10.0 * (k % n) as f64 + jitter(),
                10.0 * (k / n) as f64 + jitter(),
            ]
        })
        .collect();
    let mut bars = Vec::new();
    for j in 0..n {
        for i in 0..n {
            if i + 1 < n {
                bars.push((at(i, j), at(i + 1, j)));
            }
            if j + 1 < n {
                bars.push((at(i, j), at(i, j + 1)));
            }
        }
    }
    bars.push((at(0, 0), at(1, 1)));
    if extra {
        bars.push((at(1, 0), at(0, 1)));
    }
    let mut rows = Vec::new();
    for &(p, q) in &bars {
        let d = [pts[p][0] - pts[q][0], pts[p][1] - pts[q][1]];
        let len = d[0].hypot(d[1]);
        let mut row = Vec::new();
        for (pt, s) in [(p, 1.0), (q, -1.0)] {
            if pt != 0 {
                // Point k has columns 2k - 2 and 2k - 1.
                row.push((2 * pt - 2, s * d[0] / len));
                row.push((2 * pt - 1, s * d[1] / len));
            }
        }
        rows.push(row);
    }
    let mut lists = vec![Vec::new(); 2 * n * n - 2];
    let mut v = 0u32;
    for (r, row) in rows.iter().enumerate() {
        for &(c, _) in row {
            lists[c].push((r as u32, v));
            v += 1;
        }
    }
    (rows.len(), Columns::from_lists(&lists), rows)
}
