//! Rank on large meshes: a triangulated lattice of points with a distance on every edge and one
//! point pinned is rigid but for a rotation about the pin, so one degree of freedom is left
//! whatever the size, and the thousands of implied distances are named as redundant.
//!
//! Eliminating thousands of dependent rows leaves rounding in the pivots of those eliminated
//! late; a rank test that read such a pivot as an independent equation would report the
//! rotation as fixed (DOF 0).

mod common;

use common::Sketch;
use loci::{ConstraintKind, Outcome};

/// A deterministic generator of numbers in `[0, 1)`.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// An `n x n` jittered lattice, each cell split by a random diagonal, a distance on every edge
/// (its length drawn), the first point pinned. Returns the sketch, the group and the number of
/// distances.
fn mesh(n: usize, seed: u64) -> (Sketch, u32, usize) {
    const G: u32 = 2;
    let mut rng = Rng(seed);
    let mut sk = Sketch::new();
    let mut pts = Vec::with_capacity(n * n);
    for j in 0..n {
        for i in 0..n {
            let at = [
                10.0 * i as f64 + 5.0 * (rng.next() - 0.5),
                10.0 * j as f64 + 5.0 * (rng.next() - 0.5),
            ];
            let k = j * n + i;
            // Drawn a little off, so the solve has work to do; the pin where it is.
            let d = if k == 0 {
                0.0
            } else {
                0.05 * ((k % 7) as f64 - 3.0)
            };
            let h = 1000 + k as u32;
            pts.push((sk.point(h, G, [at[0] + d, at[1] - d]), at));
        }
    }
    let at = |i: usize, j: usize| j * n + i;
    let mut edges = Vec::new();
    for j in 0..n {
        for i in 0..n {
            if i + 1 < n {
                edges.push((at(i, j), at(i + 1, j)));
            }
            if j + 1 < n {
                edges.push((at(i, j), at(i, j + 1)));
            }
            if i + 1 < n && j + 1 < n {
                edges.push(if rng.next() < 0.5 {
                    (at(i, j), at(i + 1, j + 1))
                } else {
                    (at(i + 1, j), at(i, j + 1))
                });
            }
        }
    }
    for &(p, q) in &edges {
        let (a, b) = (pts[p].1, pts[q].1);
        let len = (a[0] - b[0]).hypot(a[1] - b[1]);
        sk.on_points(G, ConstraintKind::PtPtDistance, pts[p].0, pts[q].0, len);
    }
    sk.on_points(G, ConstraintKind::WhereDragged, pts[0].0, 0, 0.0);
    (sk, G, edges.len())
}

fn solve_mesh(n: usize, seed: u64) {
    let (mut sk, group, edges) = mesh(n, seed);
    let rep = sk.sys.solve_group(group).unwrap();
    assert_eq!(rep.outcome, Outcome::RedundantOkay, "{n}x{n}: {rep:?}");
    assert_eq!(
        rep.dof, 1,
        "{n}x{n}: only the rotation about the pin is free"
    );
    // 2n² - 2 unknowns, rank 2n² - 3: every distance beyond that is implied.
    let implied = edges - (2 * n * n - 3);
    assert!(
        rep.failed.len() > implied,
        "{n}x{n}: {} named for {implied} implied",
        rep.failed.len()
    );
}

#[test]
fn a_pinned_mesh_keeps_its_rotation_at_every_size() {
    for (n, seed) in [(5, 1), (10, 2), (20, 3), (30, 4), (30, 5), (40, 6)] {
        solve_mesh(n, seed);
    }
}

#[test]
fn diagnosis_counts_the_same_rotation() {
    let (sk, group, _) = mesh(30, 4);
    let d = loci::diagnose(&sk.sys, group.into(), &loci::Config::default()).unwrap();
    assert_eq!(d.outcome, Outcome::RedundantOkay);
    assert_eq!(d.dof, 1, "only the rotation about the pin is free");
    assert!(d.conflicting.is_empty());
    assert!(!d.redundant.is_empty());
}
