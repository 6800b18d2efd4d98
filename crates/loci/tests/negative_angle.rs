//! A 2D angle whose value is negative, solved, then solved again from its own answer.
//!
//! In a workplane the target of an angle is `val` times the sign of the turn drawn at the start
//! (`choose_angle` in `equations/lines.rs`): a negative value asks for the turn opposite to the
//! drawn one, which the answer then has, so the next solve asks for the opposite again. The
//! sketch layer rewrites its signed angles before every solve and is not affected; a model
//! given straight to the solver is (the benchmark's sheets of profiles, whose angles have
//! signed values, move when solved again, and at 20x20 are reported inconsistent).

mod common;

use common::{uv, Sketch};
use loci::ConstraintKind as K;

#[test]
#[ignore = "a negative 2D angle turns over each time it is solved: its target is read against the drawn turn"]
fn a_negative_angle_stays_where_it_was_solved() {
    let mut s = Sketch::new();
    // Line A along x and the start of line B, fixed (group 1); B's end free (group 2), drawn
    // turning counter-clockwise from A.
    let a0 = s.point(301, 1, [0.0, 0.0]);
    let a1 = s.point(302, 1, [4.0, 0.0]);
    let b0 = s.point(303, 1, [0.0, 1.0]);
    let b1 = s.point(304, 2, [3.0, 1.5]);
    let a = s.line(401, 1, a0, a1);
    let b = s.line(402, 2, b0, b1);
    s.on_entities(2, K::Angle, a, b, -30.0);
    s.on_points(2, K::PtPtDistance, b0, b1, 3.0);
    let first = s.sys.solve_group(2).unwrap();
    assert!(first.outcome.is_ok(), "{first:?}");
    let answer = uv(&s.sys, b1);
    let again = s.sys.solve_group(2).unwrap();
    assert!(again.outcome.is_ok(), "{again:?}");
    let moved = common::dist(answer, uv(&s.sys, b1));
    assert!(
        again.iterations == 0 && moved <= 1e-9,
        "solved again: {} iterations, moved {moved} from {answer:?} to {:?}",
        again.iterations,
        uv(&s.sys, b1)
    );
}
