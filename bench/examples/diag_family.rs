//! Diagnoses one generated benchmark problem with loci and prints the report.
//! `cargo run --release -p loci-bench --example diag_family -- FAMILY VARIANT SIZE`.
use loci_bench::generate::generate;
use loci_bench::problem::{Family, Variant};

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
    let mut sys = sp.system.clone();
    let r = sys
        .solve_group(loci_bench::slvs::SOLVE_GROUP)
        .expect("solves");
    println!("{r:?}");
    let d = sp
        .system
        .diagnose(loci_bench::slvs::SOLVE_GROUP)
        .expect("diagnoses");
    println!("{:?} conflicting {:?}", d.outcome, d.conflicting);
    for c in r.failed.iter().take(12) {
        println!(
            "{c:?}: {:?}",
            sp.system
                .constraint(*c)
                .map(|c| (c.kind, c.pt_a, c.pt_b, c.entity_a, c.entity_b, c.val))
        );
    }
}
