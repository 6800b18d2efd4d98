//! Full diagnosis (counting, solve, circuits, conflicts checked minimal, redundancy, the
//! motions of every entity, measurements) of long chains of segments.
//!
//! `cargo bench -p loci --bench diagnose`
#![allow(missing_docs)]

#[path = "../tests/common/chain.rs"]
mod chain;

use criterion::{criterion_group, criterion_main, BatchSize, Criterion};
use loci::{diagnose, Config, GroupId, Outcome};

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("diagnose");
    g.sample_size(10);
    let (conflicted, _) = chain::chain(1000, true);
    let d = diagnose(&conflicted, GroupId(2), &Config::default()).unwrap();
    assert_eq!(d.outcome, Outcome::Inconsistent);
    assert_eq!(d.conflicting.len(), 1);
    g.bench_function("chain_1000_one_conflict", |b| {
        b.iter_batched(
            || conflicted.clone(),
            |s| diagnose(&s, GroupId(2), &Config::default()).unwrap(),
            BatchSize::LargeInput,
        )
    });
    let (long, _) = chain::chain(10_000, false);
    let d = diagnose(&long, GroupId(2), &Config::default()).unwrap();
    assert!(d.outcome.is_ok());
    assert_eq!(d.dof, 1);
    g.bench_function("chain_10000", |b| {
        b.iter_batched(
            || long.clone(),
            |s| diagnose(&s, GroupId(2), &Config::default()).unwrap(),
            BatchSize::LargeInput,
        )
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
