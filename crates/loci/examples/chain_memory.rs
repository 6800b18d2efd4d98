//! Solves one chain of N segments (the criterion bench's chain: lengths, angles, first point
//! fixed, started up to 0.3 off) and prints the time; run under `/usr/bin/time -v` for the peak
//! resident memory: `cargo run --release -p loci --example chain_memory -- 100000`.
#![allow(missing_docs)]

#[path = "../tests/common/perturbed_chain.rs"]
mod chain;

use loci::Config;
use std::time::Instant;

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(100_000);
    let t = Instant::now();
    let mut ch = chain::chain(n, 1, 0.3);
    let built = t.elapsed().as_secs_f64() * 1e3;
    let t = Instant::now();
    let r = loci::solve(&mut ch.system, ch.group, &[], &Config::default()).expect("valid");
    println!(
        "chain {n}: built in {built:.0} ms, solved in {:.0} ms: {} (dof {}, {} iterations, residual {:.1e})",
        t.elapsed().as_secs_f64() * 1e3,
        r.outcome,
        r.dof,
        r.iterations,
        r.residual
    );
    if !r.failed.is_empty() {
        let kinds: Vec<String> = r
            .failed
            .iter()
            .take(8)
            .map(|&c| {
                format!(
                    "{} {}",
                    c.0,
                    ch.system.constraint(c).map_or("?", |k| k.kind.name())
                )
            })
            .collect();
        println!("{} failed: {}", r.failed.len(), kinds.join(", "));
    }
}
