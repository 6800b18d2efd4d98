//! The assembly layer: components, mates, joints, the angle mate as the seed describes it,
//! the stepped mode and the report.

mod angle;
mod conflicts;
mod examples;
mod far_starts;
mod mates;
mod random;
mod report;
mod roots;
mod stepped;

use loci::assembly::{Assembly, Component, Mate, MateKind, Pose, Reference, Selection};

/// References every test component carries, in its own frame.
pub fn parts(name: &str, pose: Pose) -> Component {
    Component::new(name, pose)
        .with(
            "top",
            Reference::Face {
                point: [0.0, 0.0, 1.0],
                normal: [0.0, 0.0, 1.0],
            },
        )
        .with(
            "bottom",
            Reference::Face {
                point: [0.0, 0.0, 0.0],
                normal: [0.0, 0.0, -1.0],
            },
        )
        .with(
            "side",
            Reference::Face {
                point: [1.0, 0.0, 0.0],
                normal: [1.0, 0.0, 0.0],
            },
        )
        .with(
            "edge",
            Reference::Edge {
                point: [0.0, 0.0, 0.0],
                direction: [1.0, 0.0, 0.0],
            },
        )
        .with(
            "yedge",
            Reference::Edge {
                point: [0.0, 0.0, 0.0],
                direction: [0.0, 1.0, 0.0],
            },
        )
        .with(
            "axis",
            Reference::Axis {
                point: [0.0, 0.0, 0.0],
                direction: [0.0, 0.0, 1.0],
            },
        )
        .with(
            "hole",
            Reference::CircularEdge {
                center: [0.0, 0.0, 0.0],
                axis: [0.0, 0.0, 1.0],
                radius: 2.0,
            },
        )
        .with(
            "corner",
            Reference::Vertex {
                point: [0.0, 0.0, 0.0],
            },
        )
        .with(
            "far",
            Reference::Vertex {
                point: [1.0, 1.0, 0.0],
            },
        )
}

/// Ground `g` (grounded, at the identity) and free part `b` at `pose`, with one mate.
pub fn pair(kind: MateKind, ra: &str, rb: &str, flip: bool, pose: Pose) -> (Assembly, String) {
    let mut asm = Assembly::new();
    asm.add_component(parts("g", Pose::IDENTITY).grounded())
        .unwrap();
    asm.add_component(parts("b", pose)).unwrap();
    let id = asm
        .add_mate(Mate::new(kind, Selection::on("g", ra), Selection::on("b", rb)).flipped(flip))
        .unwrap();
    (asm, id)
}

/// A small turn and shift of `p`.
pub fn nudge(p: Pose) -> Pose {
    let q = Pose::from_axis_angle([0.0; 3], [0.3, -0.5, 0.8], 3.0);
    Pose::new(
        [
            p.translation[0] + 0.05,
            p.translation[1] - 0.04,
            p.translation[2] + 0.03,
        ],
        mul(q.rotation, p.rotation),
    )
}

/// The Hamilton product.
pub fn mul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}
