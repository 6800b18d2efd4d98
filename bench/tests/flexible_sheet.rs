//! A sheet of closed profiles large enough that each of its columns, a chain of 190 edges held
//! by lengths and relative angles, bends more easily than the rank tolerance tells from a
//! dependency: the smallest squared singular value of its Jacobian falls under 1e-10. Built
//! from a solution, it must solve, fully constrained, rather than be reported inconsistent;
//! solved again from its answer, it must stay fully constrained, with nothing named.

use loci::{Config, Outcome, Report, System};
use loci_bench::generate::generate;
use loci_bench::problem::{Family, Variant};
use loci_bench::slvs::{self, SOLVE_GROUP};

/// The benchmark's `n` x `n` sheet of profiles of `variant`, in the SolveSpace model.
fn sheet(variant: Variant, n: usize) -> System {
    let p = generate(Family::Profiles, variant, n);
    slvs::build(&p)
        .expect("translates to the SolveSpace model")
        .system
}

/// Solves the sheet's group in place with the default configuration.
fn solve(sys: &mut System) -> Report {
    loci::solve(sys, SOLVE_GROUP.into(), &[], &Config::default()).expect("solves")
}

#[test]
fn a_190x190_sheet_of_profiles_solves_with_no_freedom_left() {
    let mut sys = sheet(Variant::Solvable, 190);
    let r = solve(&mut sys);
    // It was `did_not_converge` with 192,902 constraints named (and sizes 199 to 210
    // `inconsistent`): the row dropped at the start was left out of every plain step.
    assert_eq!(
        r.outcome,
        Outcome::Okay,
        "{:?}",
        (r.outcome, r.dof, r.failed.len())
    );
    assert_eq!(r.dof, 0);
    assert!(r.failed.is_empty());
    assert!(r.residual <= 1e-10, "{}", r.residual);
    assert!(r.iterations <= 10, "{}", r.iterations);
    // From the answer, where every row holds (the marginal one too), the rank is read as
    // before: it was `redundant_okay` with 1 DOF and two distances named.
    let again = solve(&mut sys);
    assert_eq!(
        (
            again.outcome,
            again.dof,
            again.failed.len(),
            again.iterations
        ),
        (Outcome::Okay, 0, 0, 0)
    );
}

#[test]
fn the_same_sheet_with_one_redundant_constraint_solves_and_names_it() {
    let mut sys = sheet(Variant::Redundant, 190);
    let r = solve(&mut sys);
    // One row depends on the others for certain, and one only just: the rank tolerance is
    // tightened where no more than a few rows depend on the others.
    assert_eq!(
        r.outcome,
        Outcome::RedundantOkay,
        "{:?}",
        (r.outcome, r.dof, r.failed.len())
    );
    assert_eq!(r.dof, 0);
    assert!(r.residual <= 1e-10, "{}", r.residual);
    let extra = sys.constraints().last().expect("constraints").h;
    assert!(r.failed.contains(&extra), "{:?}", r.failed);
    let again = solve(&mut sys);
    assert_eq!(
        (again.outcome, again.dof, again.iterations),
        (Outcome::RedundantOkay, 0, 0)
    );
    assert_eq!(again.failed, r.failed);
}

/// At 200x200 the marginal pivot is smaller still: the diagnosis read the solvable sheet with
/// 1 DOF and a redundant set of 54,651 constraints, and the redundant sheet's solve named 128
/// constraints (its coefficients, solved with the nearly singular kept rows, spread over a
/// whole column) for the 7 that close a cell with the extra distance.
#[test]
fn at_200x200_the_diagnosis_and_the_named_constraints_are_those_of_smaller_sheets() {
    let sys = sheet(Variant::Solvable, 200);
    let d = sys.diagnose(SOLVE_GROUP).expect("diagnoses");
    assert_eq!(
        (d.outcome, d.dof, d.redundant.len()),
        (Outcome::Okay, 0, 0),
        "{:?}",
        d.redundant
            .iter()
            .map(|s| s.members.len())
            .collect::<Vec<_>>()
    );

    let mut sys = sheet(Variant::Redundant, 200);
    let r = solve(&mut sys);
    assert_eq!((r.outcome, r.dof), (Outcome::RedundantOkay, 0));
    let extra = sys.constraints().last().expect("constraints").h;
    assert!(r.failed.contains(&extra), "{:?}", r.failed);
    assert_eq!(r.failed.len(), 7, "{:?}", r.failed);
}
