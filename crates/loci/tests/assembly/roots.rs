//! No spurious roots: every mate kind measures (almost) nothing where it holds and clearly
//! something where it does not, so the solver can never stop at a pose that only looks
//! satisfied.

use super::parts;
use loci::assembly::{Assembly, Mate, MateKind as K, Pose, Selection};

/// One mate kind between references of the ground and of the part, a pose of the part that
/// satisfies it and one that breaks it.
struct Case {
    kind: K,
    ra: &'static str,
    rb: &'static str,
    flip: bool,
    holds: Pose,
    breaks: Pose,
}

fn at(t: [f64; 3]) -> Pose {
    Pose::new(t, [1.0, 0.0, 0.0, 0.0])
}

fn turned(t: [f64; 3], axis: [f64; 3], degrees: f64) -> Pose {
    Pose::from_axis_angle(t, axis, degrees)
}

/// The mate's error at `pose` of the part. Both components are grounded, so nothing moves
/// and the report measures the pose as given.
fn error_at(asm: &mut Assembly, pose: Pose) -> f64 {
    asm.components[1].pose = pose;
    let r = asm.solve().unwrap();
    assert_eq!(asm.components[1].pose, pose, "a grounded part moved");
    r.mates[0].error
}

fn cases() -> Vec<Case> {
    let c = |kind, ra, rb, flip, holds, breaks| Case {
        kind,
        ra,
        rb,
        flip,
        holds,
        breaks,
    };
    let z = [0.0, 0.0, 1.0];
    let x = [1.0, 0.0, 0.0];
    let y = [0.0, 1.0, 0.0];
    vec![
        c(
            K::Fixed,
            "frame",
            "frame",
            false,
            at([1.0, 2.0, 3.0]),
            at([1.0, 2.0, 3.1]),
        ),
        c(
            K::Fixed,
            "frame",
            "frame",
            false,
            at([1.0, 2.0, 3.0]),
            turned([1.0, 2.0, 3.0], z, 2.0),
        ),
        c(
            K::Fastened,
            "frame",
            "frame",
            false,
            turned([0.5, 0.0, 0.0], y, 40.0),
            turned([0.5, 0.0, 0.0], y, 43.0),
        ),
        c(
            K::Coincident,
            "corner",
            "corner",
            false,
            turned([0.0; 3], x, 25.0),
            at([0.0, 0.1, 0.0]),
        ),
        c(
            K::Coincident,
            "top",
            "corner",
            false,
            at([0.3, 0.2, 1.0]),
            at([0.3, 0.2, 1.2]),
        ),
        c(
            K::Coincident,
            "edge",
            "corner",
            false,
            at([0.7, 0.0, 0.0]),
            at([0.7, 0.0, 0.3]),
        ),
        c(
            K::Coincident,
            "top",
            "top",
            false,
            at([0.4, -0.2, 0.0]),
            at([0.4, -0.2, 0.2]),
        ),
        c(
            K::Coincident,
            "top",
            "top",
            false,
            at([0.4, -0.2, 0.0]),
            turned([0.4, -0.2, 0.0], x, 5.0),
        ),
        c(
            K::Coincident,
            "top",
            "bottom",
            true,
            at([0.4, -0.2, 1.0]),
            turned([0.4, -0.2, 1.0], y, 5.0),
        ),
        c(
            K::Coincident,
            "edge",
            "edge",
            false,
            at([0.5, 0.0, 0.0]),
            at([0.5, 0.2, 0.0]),
        ),
        c(
            K::Coincident,
            "edge",
            "edge",
            false,
            at([0.5, 0.0, 0.0]),
            turned([0.0; 3], z, 4.0),
        ),
        c(
            K::Coincident,
            "top",
            "edge",
            false,
            at([0.3, 0.5, 1.0]),
            at([0.3, 0.5, 1.1]),
        ),
        c(
            K::Coincident,
            "top",
            "edge",
            false,
            at([0.3, 0.5, 1.0]),
            turned([0.0, 0.5, 1.0], y, 6.0),
        ),
        c(
            K::Distance { value: 2.0 },
            "corner",
            "corner",
            false,
            at([0.0, 2.0, 0.0]),
            at([0.0, 2.3, 0.0]),
        ),
        c(
            K::Distance { value: 1.5 },
            "top",
            "corner",
            false,
            at([0.0, 0.0, 2.5]),
            at([0.0, 0.0, 2.2]),
        ),
        c(
            K::Distance { value: 3.0 },
            "top",
            "top",
            false,
            at([0.1, 0.0, 3.0]),
            at([0.1, 0.0, 3.4]),
        ),
        c(
            K::Distance { value: 3.0 },
            "top",
            "top",
            false,
            at([0.1, 0.0, 3.0]),
            turned([0.0, 0.0, 3.0], x, 3.0),
        ),
        c(
            K::Distance { value: 2.0 },
            "edge",
            "edge",
            false,
            at([0.3, 2.0, 0.0]),
            at([0.3, 1.7, 0.0]),
        ),
        c(
            K::Distance { value: 2.0 },
            "edge",
            "edge",
            false,
            at([0.3, 2.0, 0.0]),
            turned([0.0, 2.0, 0.0], z, 3.0),
        ),
        c(
            K::Distance { value: 2.0 },
            "edge",
            "corner",
            false,
            at([0.3, 0.0, 2.0]),
            at([0.3, 0.0, 1.6]),
        ),
        c(
            K::Parallel,
            "axis",
            "axis",
            false,
            at([1.0, 2.0, 3.0]),
            turned([1.0, 2.0, 3.0], x, 4.0),
        ),
        // Parallel with the directions opposed, asked for aligned, is broken by half a turn.
        c(
            K::Parallel,
            "axis",
            "axis",
            false,
            at([1.0, 2.0, 3.0]),
            turned([1.0, 2.0, 3.0], x, 180.0),
        ),
        c(
            K::Parallel,
            "top",
            "bottom",
            true,
            at([1.0, 2.0, 3.0]),
            turned([1.0, 2.0, 3.0], y, 4.0),
        ),
        c(
            K::Perpendicular,
            "axis",
            "edge",
            false,
            at([1.0, 2.0, 3.0]),
            turned([1.0, 2.0, 3.0], y, 10.0),
        ),
        c(
            K::Angle { degrees: 30.0 },
            "edge",
            "edge",
            false,
            turned([1.0, 0.0, 0.0], z, 30.0),
            turned([1.0, 0.0, 0.0], z, 35.0),
        ),
        // The mirror of the requested angle is not a root: the angle is signed.
        c(
            K::Angle { degrees: 30.0 },
            "edge",
            "edge",
            false,
            turned([1.0, 0.0, 0.0], z, 30.0),
            turned([1.0, 0.0, 0.0], z, -30.0),
        ),
        c(
            K::TouchAlign,
            "top",
            "bottom",
            false,
            at([0.2, 0.1, 1.0]),
            at([0.2, 0.1, 1.05]),
        ),
        c(
            K::TouchAlign,
            "top",
            "bottom",
            false,
            at([0.2, 0.1, 1.0]),
            turned([0.0, 0.0, 1.0], x, 180.0),
        ),
        c(
            K::TouchAlign,
            "edge",
            "edge",
            false,
            at([0.6, 0.0, 0.0]),
            at([0.6, 0.0, 0.1]),
        ),
        c(
            K::TouchAlign,
            "corner",
            "corner",
            false,
            turned([0.0; 3], z, 50.0),
            at([0.05, 0.0, 0.0]),
        ),
        c(
            K::Concentric,
            "hole",
            "hole",
            false,
            at([0.0, 0.0, 0.4]),
            at([0.1, 0.0, 0.4]),
        ),
        c(
            K::Concentric,
            "hole",
            "hole",
            false,
            at([0.0, 0.0, 0.4]),
            turned([0.0, 0.0, 0.4], x, 3.0),
        ),
        c(
            K::Revolute,
            "axis",
            "axis",
            false,
            turned([0.0; 3], z, 20.0),
            turned([0.0, 0.0, 0.1], z, 20.0),
        ),
        c(
            K::Revolute,
            "axis",
            "axis",
            false,
            turned([0.0; 3], z, 20.0),
            turned([0.0; 3], x, 3.0),
        ),
        c(
            K::Slider,
            "edge",
            "edge",
            false,
            at([0.7, 0.0, 0.0]),
            at([0.7, 0.1, 0.0]),
        ),
        c(
            K::Slider,
            "edge",
            "edge",
            false,
            at([0.7, 0.0, 0.0]),
            turned([0.7, 0.0, 0.0], x, 5.0),
        ),
        c(
            K::Cylindrical,
            "axis",
            "axis",
            false,
            at([0.0, 0.0, 0.5]),
            at([0.1, 0.0, 0.5]),
        ),
        c(
            K::Ball,
            "corner",
            "corner",
            false,
            turned([0.0; 3], x, 10.0),
            at([0.0, 0.0, 0.1]),
        ),
        c(
            K::Planar,
            "top",
            "top",
            false,
            at([0.3, 0.3, 0.0]),
            at([0.3, 0.3, 0.1]),
        ),
        c(
            K::Planar,
            "top",
            "top",
            false,
            at([0.3, 0.3, 0.0]),
            turned([0.3, 0.3, 0.0], y, 5.0),
        ),
        c(
            K::PinSlot,
            "edge",
            "axis",
            false,
            at([0.4, 0.0, 0.0]),
            at([0.4, 0.1, 0.0]),
        ),
        c(
            K::PinSlot,
            "edge",
            "axis",
            false,
            at([0.4, 0.0, 0.0]),
            turned([0.4, 0.0, 0.0], y, 5.0),
        ),
    ]
}

#[test]
fn every_mate_kind_measures_zero_where_it_holds_and_clearly_more_where_it_breaks() {
    let mut kinds = std::collections::BTreeSet::new();
    for case in cases() {
        let mut asm = Assembly::new();
        asm.add_component(parts("g", Pose::IDENTITY).grounded())
            .unwrap();
        asm.add_component(parts("b", case.holds).grounded())
            .unwrap();
        asm.add_mate(
            Mate::new(
                case.kind.clone(),
                Selection::on("g", case.ra),
                Selection::on("b", case.rb),
            )
            .flipped(case.flip),
        )
        .unwrap();
        let what = format!("{:?} {} {} flip={}", case.kind, case.ra, case.rb, case.flip);
        let held = error_at(&mut asm, case.holds);
        assert!(held < 1e-12, "{what} where it holds: {held:e}");
        // The same mate (what it captured where it held stays) at the breaking pose.
        let broken = error_at(&mut asm, case.breaks);
        assert!(broken > 1e-3, "{what} where it breaks: {broken:e}");
        kinds.insert(case.kind.name());
    }
    // Every kind of mate and joint is covered.
    assert_eq!(kinds.len(), 15, "{kinds:?}");
}
