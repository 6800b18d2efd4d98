//! Every benchmark family and variant, solved, then solved again from where the first solve
//! left it: the second solve reports the same outcome, DOF and named constraints, and a solved
//! sketch does not move. (A 2D angle with a negative value used to turn over on every solve,
//! and the 20x20 sheet of profiles solved again was reported inconsistent.)

use loci::{Config, Outcome};
use loci_bench::generate::generate;
use loci_bench::problem::{Family, Variant};
use loci_bench::slvs::{self, SOLVE_GROUP};

#[test]
fn a_second_solve_from_the_first_ones_answer_agrees_with_it() {
    let mut checked = 0;
    for family in Family::ALL {
        for variant in [Variant::Solvable, Variant::Redundant, Variant::Inconsistent] {
            for n in [5, 20] {
                let p = generate(family, variant, n);
                let mut sys = slvs::build(&p).expect("translates").system;
                let cfg = Config::default();
                let first = loci::solve(&mut sys, SOLVE_GROUP.into(), &[], &cfg).expect("solves");
                let values: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
                let again = loci::solve(&mut sys, SOLVE_GROUP.into(), &[], &cfg).expect("solves");
                let what = format!("{family:?} {variant:?} {n}");
                assert_eq!(first.outcome, again.outcome, "{what}");
                assert_eq!(first.dof, again.dof, "{what}");
                assert_eq!(first.failed, again.failed, "{what}");
                if matches!(first.outcome, Outcome::Okay | Outcome::RedundantOkay) {
                    assert_eq!(again.iterations, 0, "{what}");
                    let moved = sys
                        .params()
                        .iter()
                        .zip(&values)
                        .map(|(p, v)| (p.val - v).abs())
                        .fold(0.0f64, f64::max);
                    assert!(moved == 0.0, "{what}: moved {moved}");
                }
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 8 * 3 * 2);
}
