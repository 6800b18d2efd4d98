//! Times `Assembly::solve` on the benchmark's revolute chain of N links (a fresh copy each
//! time, as `loci-bench assembly` does), many times over, to profile its fixed costs:
//! `cargo run --release -p loci-bench --example profile_assembly -- [N] [REPS]`.
use std::time::Instant;

/// As in `loci-bench`, whose figures these loops break down.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    let mut args = std::env::args().skip(1);
    let n: usize = args.next().map_or(10, |v| v.parse().expect("N"));
    let reps: usize = args.next().map_or(5_000, |v| v.parse().expect("REPS"));
    let proto = loci_bench::assembly::chain(n, 1);
    let mut times = Vec::with_capacity(reps);
    let mut last = None;
    for _ in 0..reps {
        let mut asm = proto.clone();
        let t = Instant::now();
        let r = asm.solve().expect("a generated assembly is valid");
        times.push(t.elapsed().as_secs_f64() * 1e6);
        last = Some(r);
    }
    times.sort_by(f64::total_cmp);
    let r = last.expect("one solve");
    println!(
        "chain of {n}: median {:.1} µs, best {:.1} µs over {reps}; {} iterations, residual {:.1e}",
        times[reps / 2],
        times[0],
        r.iterations,
        r.residual
    );
}
