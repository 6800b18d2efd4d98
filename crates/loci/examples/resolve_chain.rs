//! Times a first solve of a chain of N segments and re-solves after moving its fixed first
//! point slightly, with the same [`loci::Solver`]:
//! `cargo run --release -p loci --example resolve_chain -- 10000`.
#![allow(missing_docs)]

#[path = "../tests/common/perturbed_chain.rs"]
mod chain;

use loci::{Config, ParamId, Solver};
use std::time::Instant;

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(10_000);
    let ch = chain::chain(n, 1, 0.3);
    let mut sys = ch.system.clone();
    let mut solver = Solver::new(ch.group, &[], Config::default());
    let t = Instant::now();
    let r = solver.solve(&mut sys).expect("valid");
    let first = t.elapsed().as_secs_f64() * 1e3;
    println!(
        "first solve: {first:.2} ms, {} (dof {}, {} iterations)",
        r.outcome, r.dof, r.iterations
    );
    // The first point's x: moved by 0.01 back and forth, as a drag would.
    let p = ParamId(100);
    let mut times = Vec::new();
    let mut step = 0.01;
    for _ in 0..20 {
        let v = sys.value(p).expect("the first point's parameter");
        sys.set_value(p, v + step);
        step = -step;
        let t = Instant::now();
        let r = solver.solve(&mut sys).expect("valid");
        times.push(t.elapsed().as_secs_f64() * 1e3);
        assert!(r.outcome.is_ok(), "{}", r.outcome);
        if times.len() == 1 {
            println!(
                "re-solve: {} (dof {}, {} iterations, residual {:.1e})",
                r.outcome, r.dof, r.iterations, r.residual
            );
        }
    }
    times.sort_by(f64::total_cmp);
    let median = times[times.len() / 2];
    println!(
        "re-solve median of {}: {median:.2} ms ({:.1}x faster than the first solve)",
        times.len(),
        first / median
    );
}
