//! The stepped mode: the seed's relaxation, every iteration reported.

use super::parts;
use loci::assembly::{Assembly, Mate, MateKind as K, Pose, Selection};

fn hinge_with_angle() -> Assembly {
    let mut asm = Assembly::new();
    asm.add_component(parts("g", Pose::IDENTITY).grounded())
        .unwrap();
    asm.add_component(parts(
        "b",
        Pose::from_axis_angle([0.2, 0.1, -0.1], [0.0, 0.1, 1.0], 70.0),
    ))
    .unwrap();
    asm.add_mate(Mate::new(
        K::Coincident,
        Selection::on("g", "corner"),
        Selection::on("b", "corner"),
    ))
    .unwrap();
    asm.add_mate(Mate::new(
        K::Parallel,
        Selection::on("g", "axis"),
        Selection::on("b", "axis"),
    ))
    .unwrap();
    asm.add_mate(Mate::new(
        K::Angle { degrees: 30.0 },
        Selection::on("g", "edge"),
        Selection::on("b", "edge"),
    ))
    .unwrap();
    asm
}

#[test]
fn every_iteration_is_reported_with_poses_and_errors() {
    let mut asm = hinge_with_angle();
    let run = asm.solve_stepped().unwrap();
    assert!(run.converged, "{} passes", run.iterations.len());
    // 40 degrees to turn, at most 10 per pass.
    assert!(
        run.iterations.len() >= 4,
        "capped steps take several passes"
    );
    for (i, it) in run.iterations.iter().enumerate() {
        assert_eq!(it.index, i + 1);
        assert_eq!(it.poses.len(), 2);
        assert_eq!(it.errors.len(), 3);
        assert_eq!(it.poses[0], Pose::IDENTITY, "the grounded part stays");
    }
    let last = run.iterations.last().unwrap();
    assert!(last.errors.iter().all(|&e| e < 1e-5), "{:?}", last.errors);
    // The simultaneous solve agrees with where the steps end.
    let stepped = asm.components[1].pose;
    let mut again = hinge_with_angle();
    let r = again.solve().unwrap();
    assert!(r.all_hold(), "{r}");
    let solved = again.components[1].pose;
    for k in 0..3 {
        assert!((stepped.translation[k] - solved.translation[k]).abs() < 1e-4);
    }
}
