//! Solving a chain of line segments (coincident joints, lengths, angles) from a perturbed
//! start, at 100, 1,000 and 10,000 segments; and re-solving the 10,000-segment chain with a
//! [`loci::Solver`] after its fixed first point moves by 0.01 (the structure is reused).
//!
//! Run: `cargo bench -p loci --bench chain`; for a quick look,
//! `cargo bench -p loci --bench chain -- --sample-size 10 --warm-up-time 1 --measurement-time 5`.

// criterion_group! generates an undocumented public function.
#![allow(missing_docs)]

#[path = "../tests/common/perturbed_chain.rs"]
mod chain;

use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion};
use loci::{Config, Outcome, ParamId, Solver};

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

fn bench_resolve(c: &mut Criterion) {
    let mut group = c.benchmark_group("chain_resolve");
    group.sample_size(10);
    let ch = chain::chain(10_000, 1, 0.3);
    let mut sys = ch.system.clone();
    let mut solver = Solver::new(ch.group, &[], Config::default());
    let rep = solver.solve(&mut sys).expect("valid");
    assert_eq!((rep.outcome, rep.dof), (Outcome::Okay, 0));
    // The first point's u coordinate: moving it drags the whole chain along.
    let first = ParamId(100);
    let mut step = 0.01;
    group.bench_function("10000", |b| {
        b.iter(|| {
            let v = sys.value(first).expect("the first point's parameter");
            sys.set_value(first, v + step);
            step = -step;
            let rep = solver.solve(&mut sys).expect("valid");
            assert!(rep.outcome.is_ok());
            rep
        });
    });
    group.finish();
}

criterion_group!(benches, bench_chain, bench_resolve);
criterion_main!(benches);
