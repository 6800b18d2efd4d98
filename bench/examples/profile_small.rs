//! Times the solve of one loci JSON problem on a fresh system, many times over: the fixed
//! cost of a small solve. `cargo run --release -p loci-bench --example profile_small -- FILE [REPS]`.
use loci::format::json::Problem;
use std::time::Instant;

/// As in `loci-bench`, whose figures these loops break down.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    let mut args = std::env::args().skip(1);
    let path = args.next().expect("usage: profile_small FILE [REPS]");
    let reps: usize = args.next().map_or(20_000, |r| r.parse().expect("REPS"));
    let text = std::fs::read_to_string(&path).expect("reading the problem");
    let p = Problem::from_json(&text).expect("a loci JSON problem");
    let req = p.request();
    let cfg = req.config();
    let mut times = Vec::with_capacity(reps);
    let mut last = None;
    for _ in 0..reps {
        let mut sys = p.system.clone();
        let t = Instant::now();
        let r = loci::solve(&mut sys, req.group, &req.dragged, &cfg).expect("solve");
        times.push(t.elapsed().as_secs_f64() * 1e6);
        last = Some(r);
    }
    times.sort_by(f64::total_cmp);
    let r = last.expect("one solve");
    println!(
        "{path}: median {:.2} µs, best {:.2} µs over {reps}; {} (dof {}, {} iterations)",
        times[reps / 2],
        times[0],
        r.outcome,
        r.dof,
        r.iterations
    );
}
