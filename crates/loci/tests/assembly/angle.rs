//! The angle mate, one test per behaviour the seed lists.

use super::parts;
use loci::assembly::{
    angle::{angle_tolerance, normalise_degrees},
    Assembly, Mate, MateKind, MateStatus, Options, Pose, Reference, Selection, ANGLE_TOLERANCE,
    MAX_ROTATION_PER_ITERATION,
};

/// Ground `g` and part `b` turned `start` degrees about z, an angle mate of `target` degrees
/// from g's edge (x) to b's edge (x).
fn door(start: f64, target: f64, grounded: bool) -> (Assembly, String) {
    let mut asm = Assembly::new();
    let mut g = parts("g", Pose::IDENTITY);
    g.grounded = grounded;
    asm.add_component(g).unwrap();
    asm.add_component(parts(
        "b",
        Pose::from_axis_angle([0.0; 3], [0.0, 0.0, 1.0], start),
    ))
    .unwrap();
    // A hinge keeps the angle about z, as the seed's usage tips advise.
    asm.add_mate(Mate::new(
        MateKind::Revolute,
        Selection::on("g", "axis"),
        Selection::on("b", "axis"),
    ))
    .unwrap();
    let id = asm
        .add_mate(Mate::new(
            MateKind::Angle { degrees: target },
            Selection::on("g", "edge"),
            Selection::on("b", "edge"),
        ))
        .unwrap();
    (asm, id)
}

fn angle(kind_degrees: f64, a: (&str, &str), b: (&str, &str)) -> Mate {
    Mate::new(
        MateKind::Angle {
            degrees: kind_degrees,
        },
        Selection::on(a.0, a.1),
        Selection::on(b.0, b.1),
    )
}

#[test]
fn ids_are_assigned_by_the_solver_per_kind() {
    let mut asm = Assembly::new();
    asm.add_component(parts("g", Pose::IDENTITY).grounded())
        .unwrap();
    asm.add_component(parts("b", Pose::IDENTITY)).unwrap();
    let mut ids = Vec::new();
    for _ in 0..3 {
        ids.push(
            asm.add_mate(angle(10.0, ("g", "edge"), ("b", "edge")))
                .unwrap(),
        );
    }
    assert_eq!(
        asm.add_mate(Mate::new(
            MateKind::Parallel,
            Selection::on("g", "axis"),
            Selection::on("b", "axis")
        ))
        .unwrap(),
        "PARA1"
    );
    assert_eq!(ids, ["ANGL1", "ANGL2", "ANGL3"]);
    // A user's id is kept; a repeated one is refused.
    assert_eq!(
        asm.add_mate(angle(1.0, ("g", "edge"), ("b", "edge")).with_id("hinge"))
            .unwrap(),
        "hinge"
    );
    assert!(asm
        .add_mate(angle(1.0, ("g", "edge"), ("b", "edge")).with_id("ANGL3"))
        .is_err());
}

#[test]
fn faces_use_their_normals_and_edges_their_directions() {
    let mut asm = Assembly::new();
    asm.add_component(parts("g", Pose::IDENTITY).grounded())
        .unwrap();
    // b turned 25 degrees about y: its top normal leans 25 degrees from g's, its x edge too.
    asm.add_component(parts(
        "b",
        Pose::from_axis_angle([0.0; 3], [0.0, 1.0, 0.0], 25.0),
    ))
    .unwrap();
    let faces = asm
        .add_mate(angle(25.0, ("g", "top"), ("b", "top")))
        .unwrap();
    let edges = asm
        .add_mate(angle(25.0, ("g", "edge"), ("b", "edge")))
        .unwrap();
    let mixed = asm
        .add_mate(angle(90.0 - 25.0, ("g", "edge"), ("b", "top")))
        .unwrap();
    for id in [faces, edges, mixed] {
        let r = asm.measure_angle(&id).unwrap();
        assert!(r.error.abs() < 1e-12, "{id}: {r:?}");
    }
}

#[test]
fn targets_are_normalised_to_the_seed_range() {
    // As the seed: clamped to [-360, 360] first, then wrapped to (-180, 180].
    assert_eq!(normalise_degrees(390.0), 0.0);
    assert_eq!(normalise_degrees(330.0), -30.0);
    assert_eq!(normalise_degrees(-330.0), 30.0);
    assert_eq!(normalise_degrees(200.0), -160.0);
    assert_eq!(normalise_degrees(1000.0), 0.0);
    // And the solve reaches the normalised angle.
    let (mut asm, id) = door(-20.0, 330.0, true);
    let r = asm.solve().unwrap();
    assert!(
        (r.mate(&id).unwrap().value.unwrap() + 30.0).abs() < 1e-9,
        "{r}"
    );
}

#[test]
fn a_selection_without_a_direction_is_rejected_with_its_own_status() {
    let mut asm = Assembly::new();
    asm.add_component(parts("g", Pose::IDENTITY).grounded())
        .unwrap();
    asm.add_component(parts("b", Pose::IDENTITY)).unwrap();
    let id = asm
        .add_mate(angle(10.0, ("g", "edge"), ("b", "corner")))
        .unwrap();
    let r = asm.solve().unwrap();
    let m = r.mate(&id).unwrap();
    assert_eq!(m.status, MateStatus::NoDirection);
    assert!(
        m.message.contains("b.corner") && m.message.contains("vertex"),
        "{}",
        m.message
    );
}

#[test]
fn selections_on_one_component_are_rejected_with_their_own_status() {
    let mut asm = Assembly::new();
    asm.add_component(parts("b", Pose::IDENTITY)).unwrap();
    let id = asm
        .add_mate(angle(10.0, ("b", "edge"), ("b", "axis")))
        .unwrap();
    let r = asm.solve().unwrap();
    assert_eq!(r.mate(&id).unwrap().status, MateStatus::SameComponent);
}

#[test]
fn selections_not_on_components_are_rejected_with_their_own_status() {
    let mut asm = Assembly::new();
    asm.add_component(parts("b", Pose::IDENTITY)).unwrap();
    asm.add_world_reference(
        "datum",
        Reference::Axis {
            point: [0.0; 3],
            direction: [1.0, 0.0, 0.0],
        },
    );
    let id = asm
        .add_mate(Mate::new(
            MateKind::Angle { degrees: 10.0 },
            Selection::world("datum"),
            Selection::on("b", "edge"),
        ))
        .unwrap();
    let r = asm.solve().unwrap();
    assert_eq!(r.mate(&id).unwrap().status, MateStatus::NotAttached);
    // Other mates accept world references: the world is a constant.
    let p = asm
        .add_mate(Mate::new(
            MateKind::Parallel,
            Selection::world("datum"),
            Selection::on("b", "yedge"),
        ))
        .unwrap();
    let r = asm.solve().unwrap();
    assert_eq!(r.mate(&p).unwrap().status, MateStatus::Adjusted, "{r}");
}

#[test]
fn the_signed_angle_is_kept_in_radians_and_degrees() {
    let (mut asm, id) = door(10.0, -40.0, true);
    let r = asm.solve().unwrap();
    assert!(r.all_hold(), "{r}");
    let p = &asm.mate(&id).unwrap().persistent;
    assert!((p.angle_deg.unwrap() + 40.0).abs() < 1e-9);
    assert!((p.angle_rad.unwrap() + 40f64.to_radians()).abs() < 1e-11);
    let reading = asm.measure_angle(&id).unwrap();
    assert!((reading.signed_deg + 40.0).abs() < 1e-9 && (reading.angle_deg - 40.0).abs() < 1e-9);
}

#[test]
fn the_error_is_compared_with_the_requested_or_derived_tolerance() {
    // 0.2 degrees off: within an angle tolerance of 0.01 rad, so nothing has to move.
    let (mut asm, id) = door(30.2, 30.0, true);
    asm.options.angle_tolerance = Some(0.01);
    assert_eq!(
        asm.solve().unwrap().mate(&id).unwrap().status,
        MateStatus::Satisfied
    );
    let (mut asm, id) = door(30.2, 30.0, true);
    assert_eq!(
        asm.solve().unwrap().mate(&id).unwrap().status,
        MateStatus::Adjusted
    );
    // Derived: ten times the positional tolerance, never below the seed's floor.
    let (mut asm, id) = door(30.2, 30.0, true);
    asm.options.tolerance = 1e-3;
    assert_eq!(
        asm.solve().unwrap().mate(&id).unwrap().status,
        MateStatus::Satisfied
    );
    assert_eq!(angle_tolerance(None, 1e-3), 1e-2);
    assert_eq!(angle_tolerance(None, 1e-10), ANGLE_TOLERANCE);
    // The stepped mode stops at once when the error is within tolerance.
    let (mut asm, _) = door(30.2, 30.0, true);
    asm.options.angle_tolerance = Some(0.01);
    let run = asm.solve_stepped().unwrap();
    assert!(run.converged && run.iterations.is_empty());
}

fn turned(p: &Pose, q: &Pose) -> f64 {
    // The angle of the rotation taking p to q.
    let d = super::mul(
        q.rotation,
        [
            p.rotation[0],
            -p.rotation[1],
            -p.rotation[2],
            -p.rotation[3],
        ],
    );
    2.0 * (d[1] * d[1] + d[2] * d[2] + d[3] * d[3])
        .sqrt()
        .atan2(d[0].abs())
}

/// Two components joined only by an angle mate, one stepped pass.
fn one_pass(start: f64, target: f64, ground_a: bool, gain: f64) -> (Assembly, Vec<Pose>, String) {
    let mut asm = Assembly::new();
    let mut a = parts("a", Pose::IDENTITY);
    a.grounded = ground_a;
    asm.add_component(a).unwrap();
    asm.add_component(parts(
        "b",
        Pose::from_axis_angle([5.0, 0.0, 0.0], [0.0, 0.0, 1.0], start),
    ))
    .unwrap();
    let id = asm
        .add_mate(angle(target, ("a", "edge"), ("b", "edge")))
        .unwrap();
    asm.options.rotation_gain = gain;
    asm.options.max_steps = 1;
    let before: Vec<Pose> = asm.components.iter().map(|c| c.pose).collect();
    asm.solve_stepped().unwrap();
    (asm, before, id)
}

#[test]
fn the_correction_is_split_evenly_or_all_on_the_movable_one() {
    // Both free: each turns the same amount (half of the correction, scaled by half the gain
    // as the seed does).
    let (asm, before, _) = one_pass(30.0, 26.0, false, 1.0);
    let (ta, tb) = (
        turned(&before[0], &asm.components[0].pose),
        turned(&before[1], &asm.components[1].pose),
    );
    assert!((ta - tb).abs() < 1e-12 && ta > 0.0, "{ta} {tb}");
    assert!((ta - 1f64.to_radians()).abs() < 1e-9, "{}", ta.to_degrees());
    // A grounded: B takes all of it.
    let (asm, before, id) = one_pass(30.0, 26.0, true, 1.0);
    assert_eq!(asm.components[0].pose, before[0]);
    let tb = turned(&before[1], &asm.components[1].pose);
    assert!((tb - 4f64.to_radians()).abs() < 1e-9, "{}", tb.to_degrees());
    let mut asm = asm;
    assert!(asm.measure_angle(&id).unwrap().error.abs() < 1e-9);
}

#[test]
fn steps_are_scaled_by_the_gain_and_capped() {
    let (asm, before, _) = one_pass(30.0, 22.0, true, 0.5);
    let tb = turned(&before[1], &asm.components[1].pose);
    assert!((tb - 4f64.to_radians()).abs() < 1e-9, "{}", tb.to_degrees());
    let (asm, before, _) = one_pass(80.0, 20.0, true, 1.0);
    let tb = turned(&before[1], &asm.components[1].pose);
    assert!(
        (tb - MAX_ROTATION_PER_ITERATION).abs() < 1e-9,
        "{}",
        tb.to_degrees()
    );
    assert!((MAX_ROTATION_PER_ITERATION.to_degrees() - 10.0).abs() < 1e-12);
}

#[test]
fn every_applied_rotation_is_recorded() {
    let (asm, before, id) = one_pass(30.0, 26.0, false, 1.0);
    let rots = &asm.mate(&id).unwrap().persistent.last_applied_rotations;
    assert_eq!(rots.len(), 2);
    for r in rots {
        let i = if r.component == "a" { 0 } else { 1 };
        let want = super::mul(r.quaternion, before[i].rotation);
        let got = asm.components[i].pose.rotation;
        for k in 0..4 {
            assert!((want[k] - got[k]).abs() < 1e-12);
        }
    }
    let (asm, _, id) = one_pass(30.0, 26.0, true, 1.0);
    let rots = &asm.mate(&id).unwrap().persistent.last_applied_rotations;
    assert_eq!(rots.len(), 1);
    assert_eq!(rots[0].component, "b");
}

#[test]
fn the_sign_does_not_flip_through_zero_or_half_a_turn() {
    // Through 0: from +10 to -10 degrees, by the short way.
    let (mut asm, id) = door(10.0, -10.0, true);
    let r = asm.solve().unwrap();
    assert!(
        (r.mate(&id).unwrap().value.unwrap() + 10.0).abs() < 1e-9,
        "{r}"
    );
    // Through 180: from 170 to -170 (190), turning 20 degrees, not 340.
    let (mut asm, id) = door(170.0, -170.0, true);
    let before = asm.components[1].pose;
    let r = asm.solve().unwrap();
    assert!(
        (r.mate(&id).unwrap().value.unwrap() + 170.0).abs() < 1e-9,
        "{r}"
    );
    assert!((turned(&before, &asm.components[1].pose) - 20f64.to_radians()).abs() < 1e-9);
    // Step by step the reading moves steadily through 0: no jump to the mirror angle.
    let (mut asm, id) = door(25.0, -25.0, true);
    asm.options.rotation_gain = 0.1;
    let run = asm.solve_stepped().unwrap();
    assert!(run.converged);
    let mut last = 25.0;
    for it in &run.iterations {
        asm.components[1].pose = it.poses[1];
        let a = asm.measure_angle(&id).unwrap().signed_deg;
        assert!(a <= last + 1e-9 && a >= -25.0 - 1e-6, "{a} after {last}");
        last = a;
    }
    assert!((last + 25.0).abs() < 1e-3);
    // The simultaneous solve from a start far on the other side still takes the signed branch.
    let (mut asm, id) = door(-150.0, 30.0, true);
    let r = asm.solve().unwrap();
    assert!(
        (r.mate(&id).unwrap().value.unwrap() - 30.0).abs() < 1e-9,
        "{r}"
    );
    let _ = Options::default();
}
