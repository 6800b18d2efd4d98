//! Solves one generated benchmark problem with loci, with the default settings and a few
//! others, and with `--diagnose` also diagnoses it.
//! `cargo run --release -p loci-bench --example diag_family -- FAMILY VARIANT SIZE [--diagnose]`.
use loci::Config;
use loci_bench::generate::generate;
use loci_bench::problem::{Family, Variant};
use loci_bench::slvs::SOLVE_GROUP;
use std::time::Instant;

fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let family = Family::ALL
        .into_iter()
        .find(|f| f.name() == a[0])
        .expect("family");
    let variant = Variant::ALL
        .into_iter()
        .find(|v| v.name() == a[1])
        .expect("variant");
    let p = generate(family, variant, a[2].parse().expect("size"));
    let sp = loci_bench::slvs::build(&p).expect("builds");
    for (name, cfg) in [
        ("default", Config::default()),
        ("nearest off", Config::default().with_nearest(false)),
        (
            "SolveSpace's angles",
            Config::default().with_solvespace_angles(true),
        ),
    ] {
        let mut sys = sp.system.clone();
        let t = Instant::now();
        let r = loci::solve(&mut sys, SOLVE_GROUP.into(), &[], &cfg).expect("solves");
        println!(
            "{name}: {} in {:.1} ms, dof {}, {} iterations, residual {:e}, {} failed",
            r.outcome,
            t.elapsed().as_secs_f64() * 1e3,
            r.dof,
            r.iterations,
            r.residual,
            r.failed.len()
        );
    }
    if a.iter().any(|x| x == "--failed") {
        let mut sys = sp.system.clone();
        let r = loci::solve(&mut sys, SOLVE_GROUP.into(), &[], &Config::default()).expect("solves");
        for c in &r.failed {
            let k = sp.system.constraint(*c).expect("named");
            println!(
                "{c:?} {:?} {:?} {:?} {:?} {:?} {}",
                k.kind, k.pt_a, k.pt_b, k.entity_a, k.entity_b, k.val
            );
        }
    }
    if a.iter().any(|x| x == "--diagnose") {
        let d = sp.system.diagnose(SOLVE_GROUP).expect("diagnoses");
        println!(
            "diagnosis: {} dof {} rank {} of {}, conflicting {:?}, redundant sets of {:?} constraints",
            d.outcome,
            d.dof,
            d.rank,
            d.equations,
            d.conflicting,
            d.redundant.iter().map(|s| s.members.len()).collect::<Vec<_>>()
        );
    }
}
