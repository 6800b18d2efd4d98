//! Times a full diagnosis of a chain of N segments with one conflict:
//! `cargo run --release -p loci --example diag_chain -- 1000`.
#![allow(missing_docs)]

#[path = "../tests/common/chain.rs"]
mod chain;

use loci::{diagnose, Config, GroupId};
use std::time::Instant;

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1000);
    let reps: usize = std::env::args()
        .nth(2)
        .and_then(|a| a.parse().ok())
        .unwrap_or(5);
    let (sys, _) = chain::chain(n, true);
    let mut s2 = sys.clone();
    let t = Instant::now();
    let r = loci::solve(&mut s2, GroupId(2), &[], &Config::default()).expect("solve runs");
    println!(
        "solve alone: {} in {} iterations, {:.2} ms",
        r.outcome,
        r.iterations,
        t.elapsed().as_secs_f64() * 1e3
    );
    let mut times = Vec::new();
    for _ in 0..reps {
        let t = Instant::now();
        let d = diagnose(&sys, GroupId(2), &Config::default()).expect("diagnosis runs");
        times.push(t.elapsed().as_secs_f64() * 1e3);
        if times.len() == 1 {
            println!("{} conflicting set(s), dof {}", d.conflicting.len(), d.dof);
            if std::env::var_os("SHOW").is_some() {
                for c in &d.conflicting {
                    println!("  {:?} verified {}", c.members, c.verified);
                }
            }
        }
    }
    times.sort_by(f64::total_cmp);
    println!(
        "diagnose chain {n}: median {:.2} ms (min {:.2})",
        times[times.len() / 2],
        times[0]
    );
}
