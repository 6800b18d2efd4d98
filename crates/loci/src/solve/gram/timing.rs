//! `cargo test --release -p loci --lib gram::timing -- --ignored --nocapture`: where the
//! time of a large truss's normal equations goes.
use super::truss::truss;
use super::*;
use faer::sparse::linalg::SupernodalThreshold;
use std::time::Instant;

#[test]
#[ignore]
fn truss_pieces() {
    for n in [100usize, 200] {
        let (m, columns, rows) = truss(n, false);
        let jv: Vec<f64> = rows.iter().flatten().map(|&(_, x)| x).collect();
        let t = Instant::now();
        let (ptr, adj) = adjacency(m, &columns);
        let t_adj = t.elapsed();
        let t = Instant::now();
        let order = order::reverse_cuthill_mckee(m, &ptr, &adj);
        let t_rcm = t.elapsed();
        let mut pos = vec![0u32; m];
        for (p, &r) in order.iter().enumerate() {
            pos[r as usize] = p as u32;
        }
        let t = Instant::now();
        let first = envelope(m, &columns, Some(&pos));
        let _ = envelope_len(&first);
        let t_env = t.elapsed();
        let t = Instant::now();
        let _ = Pattern::new(m, &columns);
        let t_pat = t.elapsed();
        eprintln!("n={n}: adjacency {t_adj:?} rcm {t_rcm:?} envelope {t_env:?} pattern {t_pat:?}");
        for thr in [1.0, 0.5, 0.25, 0.1, 0.0] {
            let pattern = Pattern::new(m, &columns);
            let t = Instant::now();
            let mut g = SparseGram::new_with(m, pattern, SupernodalThreshold(thr)).unwrap();
            let t_sym = t.elapsed();
            g.assemble(&jv);
            let mut best = std::time::Duration::MAX;
            for _ in 0..3 {
                let t = Instant::now();
                assert!(g.factor(0.0, 1e-10));
                best = best.min(t.elapsed());
            }
            eprintln!(
                "  thr {thr}: symbolic {t_sym:?} factor {best:?} supernodal {}",
                g.is_supernodal()
            );
        }
    }
}

#[test]
#[ignore]
fn truss_structure_and_factorisation() {
    for n in [50usize, 100, 200] {
        let (m, columns, rows) = truss(n, false);
        let jv: Vec<f64> = rows.iter().flatten().map(|&(_, x)| x).collect();
        for kind in [Sparse::Auto, Sparse::Simplicial, Sparse::Supernodal] {
            let t = Instant::now();
            let mut g = Gram::with(m, &columns, kind).unwrap();
            let build = t.elapsed();
            let t = Instant::now();
            g.assemble(&jv);
            let asm = t.elapsed();
            let t = Instant::now();
            assert!(g.factor(0.0, 1e-10));
            let fac = t.elapsed();
            let mut y = vec![1.0; m];
            let mut sol = std::time::Duration::MAX;
            for _ in 0..5 {
                let t = Instant::now();
                g.solve(&mut y);
                sol = sol.min(t.elapsed());
            }
            let lnnz = match &g {
                Gram::Sparse(s) => s.l_values.len(),
                Gram::Banded(b) => b.g.len(),
            };
            eprintln!(
                "n={n} {kind:?}: build {build:?} assemble {asm:?} factor {fac:?} solve {sol:?} L {lnnz}"
            );
        }
    }
}
