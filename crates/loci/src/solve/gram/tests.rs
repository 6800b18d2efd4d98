use super::truss::truss;
use super::*;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::cholesky::LdltRef;
use faer::{Conj, MatMut, Par, Side};

fn values(rows: &[Vec<(usize, f64)>]) -> Vec<f64> {
    rows.iter().flatten().map(|&(_, x)| x).collect()
}

/// `Jᵀ y`, the step the solver takes from the solution `y` of `G y = rhs`.
fn step(rows: &[Vec<(usize, f64)>], y: &[f64], ncols: usize) -> Vec<f64> {
    let mut dx = vec![0.0; ncols];
    for (row, &yi) in rows.iter().zip(y) {
        for &(c, x) in row {
            dx[c] += x * yi;
        }
    }
    dx
}

fn factor_and_solve(g: &mut Gram, jv: &[f64], rhs: &[f64]) -> (Vec<usize>, Vec<f64>) {
    g.assemble(jv);
    assert!(g.factor(0.0, 1e-10));
    let mut y = rhs.to_vec();
    g.solve(&mut y);
    (g.dropped(), y)
}

/// `J v` for a fixed `v` over `ncols` unknowns: a right-hand side the rows can all meet.
fn consistent_rhs(rows: &[Vec<(usize, f64)>], ncols: usize) -> Vec<f64> {
    let v: Vec<f64> = (0..ncols).map(|c| ((c * 7) % 11) as f64 - 5.0).collect();
    rows.iter()
        .map(|row| row.iter().map(|&(c, x)| x * v[c]).sum())
        .collect()
}

#[test]
fn supernodal_and_simplicial_agree_on_a_truss_with_a_dependent_row() {
    for extra in [false, true] {
        let n = 14;
        let (m, columns, rows) = truss(n, extra);
        let jv = values(&rows);
        let ncols = 2 * n * n - 2;
        // A consistent right-hand side (J v for some v) and an inconsistent one.
        let consistent = consistent_rhs(&rows, ncols);
        let inconsistent: Vec<f64> = (0..m).map(|r| ((r * 5) % 9) as f64 - 4.0).collect();
        let mut simplicial = Gram::with(m, &columns, Sparse::Simplicial).unwrap();
        let mut supernodal = Gram::with(m, &columns, Sparse::Supernodal).unwrap();
        let mut auto = Gram::new(m, &columns).unwrap();
        let Gram::Sparse(s) = &supernodal else {
            panic!("a truss does not band")
        };
        assert!(s.is_supernodal());
        let Gram::Sparse(s) = &simplicial else {
            panic!("a truss does not band")
        };
        assert!(!s.is_supernodal());
        for rhs in [&consistent, &inconsistent] {
            let (d1, y1) = factor_and_solve(&mut simplicial, &jv, rhs);
            let (d2, y2) = factor_and_solve(&mut supernodal, &jv, rhs);
            let (d3, y3) = factor_and_solve(&mut auto, &jv, rhs);
            // The same rows, in the same order, are eliminated: the same one is dropped.
            assert_eq!(d1, d2);
            assert_eq!(d1, d3);
            assert_eq!(d1.len(), usize::from(extra), "{d1:?}");
            if extra {
                // One of the first cell's six rows: the four sides and two diagonals.
                let cell = [0, 1, 2, 2 * n - 1, m - 2, m - 1];
                assert!(cell.contains(&d1[0]), "{d1:?}");
            }
            let scale = y1.iter().fold(1.0f64, |a, x| a.max(x.abs()));
            for (a, b) in y1.iter().zip(&y2).chain(y1.iter().zip(&y3)) {
                assert!((a - b).abs() <= 1e-9 * scale, "{a} vs {b}");
            }
        }
        // On a consistent system the step J^T y is the minimum-norm solution of J dx = rhs
        // whichever dependent row was dropped: it satisfies every row, the dropped one too.
        let (_, y) = factor_and_solve(&mut supernodal, &jv, &consistent);
        let dx = step(&rows, &y, ncols);
        for (row, &b) in rows.iter().zip(&consistent) {
            let jdx: f64 = row.iter().map(|&(c, x)| x * dx[c]).sum();
            assert!((jdx - b).abs() < 1e-8, "{jdx} vs {b}");
        }
    }
}

#[test]
fn a_small_truss_keeps_its_envelope_and_steps_as_the_sparse_one_does() {
    // A 10x10 truss's envelope (renumbered) holds about 20 times its products of work,
    // over `ENVELOPE_WORK`, but little in all: it is factorised within it. A 40x40 one is
    // not.
    let (m, columns, rows) = truss(10, true);
    let mut banded = Gram::new(m, &columns).unwrap();
    assert!(matches!(banded, Gram::Banded(_)));
    let (m40, columns40, _) = truss(40, false);
    assert!(matches!(
        Gram::new(m40, &columns40).unwrap(),
        Gram::Sparse(_)
    ));
    let mut sparse = Gram::Sparse(Box::new(
        SparseGram::new(m, Pattern::new(m, &columns), Sparse::Auto).unwrap(),
    ));
    let jv = values(&rows);
    let n = 10;
    let ncols = 2 * n * n - 2;
    let rhs = consistent_rhs(&rows, ncols);
    let (d1, y1) = factor_and_solve(&mut banded, &jv, &rhs);
    let (d2, y2) = factor_and_solve(&mut sparse, &jv, &rhs);
    // Each drops one row of the first cell's circuit (its four sides and two diagonals),
    // the last it reaches in its own order: which one is no part of the answer.
    let cell = [0, 1, 2, 2 * n - 1, m - 2, m - 1];
    for d in [&d1, &d2] {
        assert_eq!(d.len(), 1, "{d:?}");
        assert!(cell.contains(&d[0]), "{d:?}");
    }
    // The step, the minimum-norm solution of J dx = rhs, is the same either way.
    let (dx1, dx2) = (step(&rows, &y1, ncols), step(&rows, &y2, ncols));
    let scale = dx1.iter().fold(1.0f64, |a, x| a.max(x.abs()));
    for (a, b) in dx1.iter().zip(&dx2) {
        assert!((a - b).abs() <= 1e-9 * scale, "{a} vs {b}");
    }
}

/// The pivots, dropped rows and solution of `g`'s last factorisation, bit for bit.
fn outcome(g: &mut Gram, rhs: &[f64]) -> (Vec<usize>, u64, Vec<u64>) {
    let mut y = rhs.to_vec();
    g.solve(&mut y);
    (
        g.dropped(),
        g.smallest_kept_pivot().to_bits(),
        y.iter().map(|v| v.to_bits()).collect(),
    )
}

#[test]
fn a_banded_g_kept_between_factorisations_factorises_as_a_fresh_one() {
    // Damped steps factorise one `G` for several `lambda`: from the second on, from the
    // `G` the envelope keeps. Each must be the factorisation a fresh `Gram` makes.
    let (m, columns, rows) = truss(6, true);
    let jv = values(&rows);
    let rhs: Vec<f64> = (0..m).map(|r| ((r * 5) % 9) as f64 - 4.0).collect();
    let mut kept = Gram::new(m, &columns).unwrap();
    assert!(matches!(kept, Gram::Banded(_)));
    kept.assemble(&jv);
    for (lambda, eps) in [(0.0, 1e-10), (1e-3, 1e-10), (0.0, 1e-4), (1e2, 1e-10)] {
        assert!(kept.factor(lambda, eps));
        let mut fresh = Gram::new(m, &columns).unwrap();
        fresh.assemble(&jv);
        assert!(fresh.factor(lambda, eps));
        assert_eq!(outcome(&mut kept, &rhs), outcome(&mut fresh, &rhs));
    }
    // A new Jacobian is formed anew, not read from the `G` kept for the last one.
    let jv2: Vec<f64> = jv.iter().map(|v| 1.5 * v).collect();
    kept.assemble(&jv2);
    assert!(kept.factor(1e-3, 1e-10));
    let mut fresh = Gram::new(m, &columns).unwrap();
    fresh.assemble(&jv2);
    assert!(fresh.factor(1e-3, 1e-10));
    assert_eq!(outcome(&mut kept, &rhs), outcome(&mut fresh, &rhs));
}

#[test]
fn a_threshold_below_every_kept_pivot_drops_the_same_rows() {
    // A truncated step is not tried again at a threshold under which the factorisation
    // it was tried with keeps no pivot: every pivot is kept or dropped as before, so the
    // factorisation is the same. Envelope and sparse alike.
    let (m, columns, rows) = truss(10, true);
    let jv = values(&rows);
    let rhs: Vec<f64> = (0..m).map(|r| ((r * 7) % 11) as f64 - 5.0).collect();
    let sparse = || {
        Gram::Sparse(Box::new(
            SparseGram::new(m, Pattern::new(m, &columns), Sparse::Auto).unwrap(),
        ))
    };
    for make in [
        &(|| Gram::new(m, &columns).unwrap()) as &dyn Fn() -> Gram,
        &sparse,
    ] {
        let mut g = make();
        g.assemble(&jv);
        assert!(g.factor(0.0, 1e-10));
        let least = g.smallest_kept_pivot();
        assert_eq!(g.dropped().len(), 1);
        let before = outcome(&mut g, &rhs);
        let raised = 0.5 * least;
        assert!(raised > 1e-10);
        assert!(g.factor(0.0, raised));
        assert_eq!(outcome(&mut g, &rhs), before);
        // At the smallest kept pivot itself, that row goes too.
        assert!(g.factor(0.0, least));
        assert_eq!(g.dropped().len(), 2);
    }
}

/// `G[i][j]` as the sum over the columns both rows meet, in column order: the order in
/// which `G`'s products are summed, so assembled entries must equal it bit for bit.
fn reference(rows: &[Vec<(usize, f64)>], i: usize, j: usize) -> f64 {
    let mut acc = 0.0;
    for &(c, x) in &rows[i] {
        for &(d, y) in &rows[j] {
            if c == d {
                acc += x * y;
            }
        }
    }
    acc
}

/// Rows of a chain: row `k` meets columns `k` and `k + 1`, and every fifth row column
/// `k + 2` too; the rows listed in the order `perm`.
fn chain(m: usize, perm: &[usize]) -> (Columns, Vec<Vec<(usize, f64)>>) {
    let rows: Vec<Vec<(usize, f64)>> = perm
        .iter()
        .map(|&k| {
            let mut row = vec![(k, 1.0 + k as f64 * 0.1), (k + 1, -0.7 + k as f64 * 0.03)];
            if k % 5 == 0 {
                row.push((k + 2, 0.3));
            }
            row
        })
        .collect();
    let mut lists = vec![Vec::new(); m + 2];
    let mut v = 0u32;
    for (r, row) in rows.iter().enumerate() {
        for &(c, _) in row {
            lists[c].push((r as u32, v));
            v += 1;
        }
    }
    (Columns::from_lists(&lists), rows)
}

#[test]
fn the_supernodal_solve_agrees_with_faers_own() {
    // A truss, and the same with the first cell's other diagonal, whose pivot is dropped.
    for extra in [false, true] {
        let (m, columns, rows) = truss(30, extra);
        let mut g = Gram::with(m, &columns, Sparse::Supernodal).unwrap();
        g.assemble(&values(&rows));
        assert!(g.factor(0.0, 1e-10));
        assert_eq!(g.dropped().len(), usize::from(extra));
        let Gram::Sparse(s) = &mut g else {
            panic!("a truss does not band")
        };
        assert!(s.is_supernodal());
        // Right-hand sides: an irregular one, and two at once through `solve_many`.
        let b: Vec<f64> = (0..m).map(|i| ((i * 7919) % 1013) as f64 - 500.0).collect();
        let mut ours = b.clone();
        s.solve(&mut ours);
        // faer's solve, on the factor (which is in the fill-reducing order) with `b` put
        // in that order and the answer put back.
        let mut faers: Vec<f64> = s.fwd.iter().map(|&r| b[r]).collect();
        let ldlt = LdltRef::new(&s.symbolic, &s.l_values);
        let req = s.symbolic.solve_in_place_scratch::<f64>(1, Par::Seq);
        let mut mem = MemBuffer::new(req);
        ldlt.solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(&mut faers, m, 1),
            Par::Seq,
            MemStack::new(&mut mem),
        );
        let faers: Vec<f64> = s.inv.iter().map(|&p| faers[p]).collect();
        let scale = faers.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        assert!(scale > 1.0);
        for (a, f) in ours.iter().zip(&faers) {
            assert!((a - f).abs() <= 1e-12 * scale, "{a} vs {f}");
        }
        let mut two = [b.clone(), b.iter().map(|x| -2.0 * x).collect()].concat();
        s.solve_many(&mut two, 2);
        for (k, f) in faers.iter().enumerate() {
            assert!((two[k] - f).abs() <= 1e-12 * scale);
            assert!((two[m + k] + 2.0 * f).abs() <= 2e-12 * scale);
        }
    }
}

#[test]
fn every_entry_of_g_is_the_sum_of_its_products_in_column_order() {
    // Sparse: a truss, with and without the dependent row.
    for extra in [false, true] {
        let (m, columns, rows) = truss(14, extra);
        let mut g = Gram::new(m, &columns).unwrap();
        g.assemble(&values(&rows));
        let Gram::Sparse(s) = &g else {
            panic!("a truss does not band")
        };
        // The pattern is in the factor's order, as the triangle the factorisation reads;
        // entry (i, j) of `G`, i >= j, is at the positions of rows i and j.
        let (ptr, idx) = (s.pattern.col_ptr(), s.pattern.row_idx());
        let mut seen = 0;
        let mut per_row = vec![0usize; m];
        for c in 0..m {
            for e in ptr[c]..ptr[c + 1] {
                let r = idx[e];
                assert!(if s.side == Side::Upper {
                    r <= c
                } else {
                    r >= c
                });
                let (a, b) = (s.fwd[c], s.fwd[r]);
                let (i, j) = (a.max(b), a.min(b));
                assert_eq!(s.vals[e].to_bits(), reference(&rows, i, j).to_bits());
                per_row[i] += 1;
                seen += 1;
            }
        }
        for (i, &have) in per_row.iter().enumerate() {
            // Every nonzero of row i up to the diagonal is in the pattern.
            let nonzero = (0..=i).filter(|&j| reference(&rows, i, j) != 0.0).count();
            assert!(have >= nonzero);
        }
        assert_eq!(seen, ptr[m]);
    }
    // Banded, in the given order and renumbered (a chain listed shuffled).
    let m = 60;
    let shuffled: Vec<usize> = (0..m).map(|k| (k * 37) % m).collect();
    for perm in [(0..m).collect::<Vec<usize>>(), shuffled] {
        let (columns, rows) = chain(m, &perm);
        let mut g = Gram::new(m, &columns).unwrap();
        g.assemble(&values(&rows));
        let Gram::Banded(b) = &mut g else {
            panic!("a chain bands")
        };
        let mut entries = Vec::new();
        for p in 0..m {
            let f = b.g.first(p);
            let mut row = vec![0.0; p + 1 - f];
            row_of_g(
                p,
                f,
                &mut row,
                &b.jv,
                &b.row_ptr,
                &b.row_entries,
                &b.columns,
                b.order.as_ref(),
            );
            entries.extend(row);
        }
        let pos: Vec<usize> = match &b.order {
            Some((_, pos)) => pos.iter().map(|&p| p as usize).collect(),
            None => (0..m).collect(),
        };
        let mut row_at = vec![0; m];
        for (r, &p) in pos.iter().enumerate() {
            row_at[p] = r;
        }
        for p in 0..m {
            for q in b.g.first(p)..=p {
                let e = b.g.index(p, q);
                let want = reference(&rows, row_at[p], row_at[q]);
                assert_eq!(entries[e].to_bits(), want.to_bits(), "({p}, {q})");
            }
            // Nothing outside the envelope.
            for q in 0..b.g.first(p) {
                assert_eq!(reference(&rows, row_at[p], row_at[q]), 0.0);
            }
        }
    }
}

#[test]
fn a_damped_supernodal_factorisation_drops_nothing_and_solves_the_shifted_system() {
    let n = 12;
    let (m, columns, rows) = truss(n, true);
    let jv = values(&rows);
    let mut g = Gram::with(m, &columns, Sparse::Supernodal).unwrap();
    g.assemble(&jv);
    assert!(g.factor(0.5, 1e-10));
    assert!(g.dropped().is_empty());
    let b: Vec<f64> = (0..m).map(|r| (r % 5) as f64 - 2.0).collect();
    let mut y = b.clone();
    g.solve(&mut y);
    // (J Jᵀ + 0.5 I) y = b, multiplied back.
    let dx = step(&rows, &y, 2 * n * n - 2);
    for (r, row) in rows.iter().enumerate() {
        let gy: f64 = row.iter().map(|&(c, x)| x * dx[c]).sum::<f64>() + 0.5 * y[r];
        assert!((gy - b[r]).abs() < 1e-9, "row {r}: {gy} vs {}", b[r]);
    }
}

#[test]
fn solving_many_right_hand_sides_at_once_matches_solving_each() {
    let n = 12;
    let (m, columns, rows) = truss(n, true);
    let jv = values(&rows);
    for kind in [Sparse::Simplicial, Sparse::Supernodal] {
        let mut g = Gram::with(m, &columns, kind).unwrap();
        g.assemble(&jv);
        assert!(g.factor(0.0, 1e-10));
        let k = 3;
        let mut block: Vec<f64> = (0..m * k).map(|i| ((i * 13) % 7) as f64 - 3.0).collect();
        let singles: Vec<Vec<f64>> = block
            .chunks(m)
            .map(|c| {
                let mut y = c.to_vec();
                g.solve(&mut y);
                y
            })
            .collect();
        g.solve_many(&mut block, k);
        for (c, y) in block.chunks(m).zip(&singles) {
            for (a, b) in c.iter().zip(y) {
                assert!((a - b).abs() <= 1e-9 * (1.0 + b.abs()), "{a} vs {b}");
            }
        }
    }
}
