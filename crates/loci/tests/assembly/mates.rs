//! Every mate and joint: it holds on a satisfying configuration, it brings a perturbed part
//! back, the grounded part never moves, and the degrees of freedom left are the ones the
//! mate documents.

use super::{nudge, pair};
use loci::assembly::{MateKind as K, MateStatus, Pose};

/// Checks one mate from `ra` on the ground to `rb` on the part, satisfied at `pose`, with
/// `dof` left to the part.
fn check(kind: K, ra: &str, rb: &str, flip: bool, pose: Pose, dof: usize) {
    let (mut asm, id) = pair(kind.clone(), ra, rb, flip, pose);
    let r = asm.solve().unwrap();
    let m = r.mate(&id).unwrap();
    assert!(
        matches!(m.status, MateStatus::Satisfied | MateStatus::Redundant),
        "{kind:?} at a satisfying pose: {r}"
    );
    assert!(m.error <= 1e-10, "{kind:?}: {}", m.error);
    assert_eq!(r.dof, dof, "{kind:?}: {r}");
    assert_eq!(r.component("b").unwrap().dof, Some(dof), "{kind:?}: {r}");
    // From a perturbed start (the same mate: what it captured on its first solve stays).
    asm.components[1].pose = nudge(pose);
    let r = asm.solve().unwrap();
    let m = r.mate(&id).unwrap();
    assert_eq!(m.status, MateStatus::Adjusted, "{kind:?} perturbed: {r}");
    assert!(m.error <= 1e-9, "{kind:?}: {}", m.error);
    assert_eq!(r.dof, dof, "{kind:?}: {r}");
    assert_eq!(asm.component("g").unwrap().pose, Pose::IDENTITY);
    assert!(r.residual <= 1e-10);
    if dof == 0 {
        let p = asm.component("b").unwrap().pose;
        for i in 0..3 {
            assert!((p.translation[i] - pose.translation[i]).abs() < 1e-9);
        }
    }
}

fn at(t: [f64; 3]) -> Pose {
    Pose::new(t, [1.0, 0.0, 0.0, 0.0])
}

#[test]
fn coincident_point_point_removes_three() {
    check(K::Coincident, "corner", "corner", false, Pose::IDENTITY, 3);
}

#[test]
fn coincident_point_plane_removes_one() {
    check(
        K::Coincident,
        "top",
        "corner",
        false,
        at([0.3, 0.2, 1.0]),
        5,
    );
}

#[test]
fn coincident_point_line_removes_two() {
    check(
        K::Coincident,
        "edge",
        "corner",
        false,
        at([0.7, 0.0, 0.0]),
        4,
    );
}

#[test]
fn coincident_plane_plane_removes_three_aligned_or_flipped() {
    check(K::Coincident, "top", "top", false, at([0.4, -0.2, 0.0]), 3);
    // B's bottom (normal -z) against A's top (normal +z): opposed.
    check(
        K::Coincident,
        "top",
        "bottom",
        true,
        at([0.4, -0.2, 1.0]),
        3,
    );
}

#[test]
fn coincident_line_line_is_collinear() {
    check(K::Coincident, "edge", "edge", false, at([0.5, 0.0, 0.0]), 2);
}

#[test]
fn distance_point_point_removes_one() {
    check(
        K::Distance { value: 2.0 },
        "corner",
        "corner",
        false,
        at([0.0, 2.0, 0.0]),
        5,
    );
}

#[test]
fn distance_point_plane_removes_one() {
    check(
        K::Distance { value: 1.5 },
        "top",
        "corner",
        false,
        at([0.0, 0.0, 2.5]),
        5,
    );
}

#[test]
fn distance_plane_plane_keeps_them_parallel() {
    check(
        K::Distance { value: 3.0 },
        "top",
        "top",
        false,
        at([0.1, 0.0, 3.0]),
        3,
    );
}

#[test]
fn distance_line_line_keeps_them_parallel() {
    check(
        K::Distance { value: 2.0 },
        "edge",
        "edge",
        false,
        at([0.3, 2.0, 0.0]),
        3,
    );
}

#[test]
fn distance_point_line_removes_one() {
    check(
        K::Distance { value: 2.0 },
        "edge",
        "corner",
        false,
        at([0.3, 0.0, 2.0]),
        5,
    );
}

#[test]
fn parallel_removes_two_either_way() {
    check(K::Parallel, "axis", "axis", false, at([1.0, 2.0, 3.0]), 4);
    check(K::Parallel, "top", "bottom", true, at([1.0, 2.0, 3.0]), 4);
}

#[test]
fn perpendicular_removes_one() {
    check(
        K::Perpendicular,
        "axis",
        "edge",
        false,
        at([1.0, 2.0, 3.0]),
        5,
    );
}

#[test]
fn angle_removes_one() {
    let pose = Pose::from_axis_angle([1.0, 0.0, 0.0], [0.0, 0.0, 1.0], 30.0);
    check(K::Angle { degrees: 30.0 }, "edge", "edge", false, pose, 5);
}

#[test]
fn touch_align_faces_are_opposed_and_coplanar() {
    check(
        K::TouchAlign,
        "top",
        "bottom",
        false,
        at([0.2, 0.1, 1.0]),
        3,
    );
    check(K::TouchAlign, "edge", "edge", false, at([0.6, 0.0, 0.0]), 2);
    check(K::TouchAlign, "corner", "corner", false, Pose::IDENTITY, 3);
}

#[test]
fn concentric_removes_four() {
    check(K::Concentric, "hole", "hole", false, at([0.0, 0.0, 0.4]), 2);
}

#[test]
fn fixed_and_fastened_remove_six() {
    check(K::Fixed, "frame", "frame", false, at([1.0, 2.0, 3.0]), 0);
    check(
        K::Fastened,
        "frame",
        "frame",
        false,
        Pose::from_axis_angle([1.0, 0.0, 0.0], [1.0, 1.0, 0.0], 40.0),
        0,
    );
}

#[test]
fn revolute_leaves_one_rotation() {
    check(
        K::Revolute,
        "axis",
        "axis",
        false,
        Pose::from_axis_angle([0.0; 3], [0.0, 0.0, 1.0], 20.0),
        1,
    );
}

#[test]
fn slider_leaves_one_translation() {
    check(K::Slider, "edge", "edge", false, at([0.7, 0.0, 0.0]), 1);
}

#[test]
fn cylindrical_leaves_slide_and_turn() {
    check(
        K::Cylindrical,
        "axis",
        "axis",
        false,
        at([0.0, 0.0, 0.5]),
        2,
    );
}

#[test]
fn ball_leaves_three_rotations() {
    check(
        K::Ball,
        "corner",
        "corner",
        false,
        Pose::from_axis_angle([0.0; 3], [1.0, 0.0, 0.0], 10.0),
        3,
    );
}

#[test]
fn planar_leaves_three() {
    check(K::Planar, "top", "top", false, at([0.3, 0.3, 0.0]), 3);
}

#[test]
fn pin_slot_leaves_slide_and_turn() {
    // The slot along x, the pin along z through a point of it.
    check(K::PinSlot, "edge", "axis", false, at([0.4, 0.0, 0.0]), 2);
}

#[test]
fn a_grounded_component_never_moves_whatever_the_mates_ask() {
    let (mut asm, _) = pair(
        K::Distance { value: 5.0 },
        "corner",
        "corner",
        false,
        Pose::IDENTITY,
    );
    asm.components[1].grounded = true;
    let r = asm.solve().unwrap();
    assert_eq!(r.mates[0].status, MateStatus::Blocked, "{r}");
    assert_eq!(asm.components[0].pose, Pose::IDENTITY);
    assert_eq!(asm.components[1].pose, Pose::IDENTITY);
}

#[test]
fn touch_align_point_point_removes_three() {
    // The part turned about its corner: the corners still touch, so the mate holds as it
    // stands, and a nudge is pulled back onto the ground's corner with three turns left.
    check(
        K::TouchAlign,
        "corner",
        "corner",
        false,
        Pose::from_axis_angle([0.0; 3], [1.0, 2.0, -1.0], 35.0),
        3,
    );
    // Another vertex of the part onto the ground's corner.
    check(
        K::TouchAlign,
        "corner",
        "far",
        false,
        at([-1.0, -1.0, 0.0]),
        3,
    );
}

#[test]
fn distance_line_line_holds_turned_about_the_line_and_shifted_along_it() {
    // B's edge parallel to A's, 2 apart, B turned about its own edge and slid along it: every
    // one of those motions keeps the mate, so the three left are the slide, the turn about
    // the edge and the swing of B's edge about A's.
    let pose = Pose::from_axis_angle([-0.8, 0.0, 2.0], [1.0, 0.0, 0.0], 70.0);
    check(K::Distance { value: 2.0 }, "edge", "edge", false, pose, 3);
    // Apart along z instead of y.
    check(
        K::Distance { value: 2.0 },
        "edge",
        "edge",
        false,
        at([0.0, 0.0, -2.0]),
        3,
    );
}

#[test]
fn coincident_line_plane_removes_two() {
    // B's edge (along x) in A's top plane (z = 1), anywhere in it.
    check(K::Coincident, "top", "edge", false, at([0.3, 0.5, 1.0]), 4);
    // The other way round: A's edge (the x axis) in B's top plane, B turned 30° about x and
    // shifted so that its plane goes through the axis.
    let c = 30f64.to_radians();
    let pose = Pose::from_axis_angle([0.0, c.sin(), -c.cos()], [1.0, 0.0, 0.0], 30.0);
    check(K::Coincident, "edge", "top", false, pose, 4);
}
