//! A conflict in a mesh large enough for rounding to decide the rank of `J Jᵀ`: its thousands
//! of dependent rows leave the last one's pivot just above the rank tolerance. The count of
//! free directions through `Jᵀ J` and refined circuits keep the answer what it is on small
//! meshes.

use loci::{Config, Outcome};
use loci_bench::generate::generate;
use loci_bench::problem::{Family, Variant};
use loci_bench::slvs::{self, SOLVE_GROUP};

#[test]
fn one_impossible_diagonal_in_a_75x75_mesh_is_named_with_its_cell_and_the_rotation_stays_free() {
    let p = generate(Family::Mesh, Variant::Inconsistent, 75);
    let sp = slvs::build(&p).expect("translates to the SolveSpace model");
    let mut sys = sp.system.clone();
    let r = loci::solve(&mut sys, SOLVE_GROUP.into(), &[], &Config::default()).expect("solves");
    assert_eq!(r.outcome, Outcome::Inconsistent);
    // A mesh pinned at one point still turns about it: 16,577 equations of rank 11,247 in
    // 11,248 unknowns (it read 0 when the last dependent row was kept).
    assert_eq!(r.dof, 1, "{r:?}");
    // The first cell's impossible second diagonal, its four sides and its first diagonal (248
    // constraints were named when the circuits were read against a nearly singular basis).
    let extra = sp.system.constraints().last().expect("constraints").h;
    assert_eq!(r.failed.len(), 6, "{:?}", r.failed);
    assert!(r.failed.contains(&extra), "{:?}", r.failed);
}
