//! Solving a chain of line segments (coincident joints, lengths, angles) from a perturbed
//! start, at 100, 1,000 and 10,000 segments.
//!
//! Run: `cargo bench -p loci --bench chain`; for a quick look,
//! `cargo bench -p loci --bench chain -- --sample-size 10 --warm-up-time 1 --measurement-time 5`.

// criterion_group! generates an undocumented public function.
#![allow(missing_docs)]

#[path = "../tests/common/perturbed_chain.rs"]
mod chain;

use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion};
use loci::{Config, Outcome};

fn bench_chain(c: &mut Criterion) {
    let mut group = c.benchmark_group("chain");
    group.sample_size(10);
    for n in [100usize, 1_000, 10_000] {
        let ch = chain::chain(n, 1, 0.3);
        // Check once, outside the timing, that the benchmark measures a successful solve.
        let mut probe = ch.system.clone();
        let rep = loci::solve(&mut probe, ch.group, &[], &Config::default()).expect("valid");
        assert_eq!((rep.outcome, rep.dof), (Outcome::Okay, 0));
        group.bench_with_input(BenchmarkId::from_parameter(n), &ch, |b, ch| {
            b.iter_batched(
                || ch.system.clone(),
                |mut sys| loci::solve(&mut sys, ch.group, &[], &Config::default()),
                BatchSize::LargeInput,
            );
        });
    }
    group.finish();
}

criterion_group!(benches, bench_chain);
criterion_main!(benches);
