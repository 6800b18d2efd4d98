//! The sign of a 2D angle: SolveSpace's angle has a size and keeps the turn it is drawn with;
//! a `signed` angle has its turn in its value. Either way, solving again from an answer leaves
//! it where it is.

mod common;

use common::{uv, Sketch};
use loci::format::json::Problem;
use loci::{Constraint, ConstraintKind as K};

/// Line A along +x, fixed, and line B from (0, 1) of length 3, its far end free and drawn at
/// `start_deg` from A: `(sketch, B's free end)`, with the angle `c` between A and B added.
fn two_lines(start_deg: f64, angle: impl FnOnce(Constraint) -> Constraint) -> (Sketch, u32) {
    let mut s = Sketch::new();
    let a0 = s.point(301, 1, [0.0, 0.0]);
    let a1 = s.point(302, 1, [4.0, 0.0]);
    let b0 = s.point(303, 1, [0.0, 1.0]);
    let t = start_deg.to_radians();
    // Slightly off the length, so that the first solve has work to do.
    let b1 = s.point(304, 2, [2.8 * t.cos(), 1.0 + 2.8 * t.sin()]);
    let a = s.line(401, 1, a0, a1);
    let b = s.line(402, 2, b0, b1);
    s.constrain(angle(
        Constraint::new(0, 2, K::Angle).with_entities([a, b, 0, 0]),
    ));
    s.on_points(2, K::PtPtDistance, b0, b1, 3.0);
    (s, b1)
}

/// The angle from A (+x) to B in degrees, counter-clockwise, in (-180, 180].
fn b_angle(s: &Sketch, b1: u32) -> f64 {
    let p = uv(&s.sys, b1);
    (p[1] - 1.0).atan2(p[0]).to_degrees()
}

/// Solves group 2 and returns B's angle; then solves again and checks nothing moves.
fn solve_twice(s: &mut Sketch, b1: u32) -> f64 {
    let first = s.sys.solve_group(2).unwrap();
    assert!(first.outcome.is_ok(), "{first:?}");
    let answer = uv(&s.sys, b1);
    let again = s.sys.solve_group(2).unwrap();
    assert!(again.outcome.is_ok(), "{again:?}");
    let moved = common::dist(answer, uv(&s.sys, b1));
    assert!(
        again.iterations == 0 && moved <= 1e-12,
        "solved again: {} iterations, moved {moved} from {answer:?} to {:?}",
        again.iterations,
        uv(&s.sys, b1)
    );
    b_angle(s, b1)
}

fn near(got: f64, want: f64) {
    assert!((got - want).abs() < 1e-6, "angle {got}, want {want}");
}

#[test]
fn solvespace_angle_keeps_the_drawn_turn_whatever_the_sign_of_its_value() {
    // Drawn counter-clockwise (25 degrees) and clockwise (-25): 30 and -30 give the same
    // answer, on the side drawn.
    for val in [30.0, -30.0] {
        let (mut s, b1) = two_lines(25.0, |c| c.with_val(val));
        near(solve_twice(&mut s, b1), 30.0);
        let (mut s, b1) = two_lines(-25.0, |c| c.with_val(val));
        near(solve_twice(&mut s, b1), -30.0);
    }
}

#[test]
fn solvespace_angle_past_half_a_turn_is_its_size() {
    // 200 degrees is an angle of 160 between the lines (cos 200 = cos 160), and 390 one of 30.
    let (mut s, b1) = two_lines(150.0, |c| c.with_val(200.0));
    near(solve_twice(&mut s, b1), 160.0);
    let (mut s, b1) = two_lines(-150.0, |c| c.with_val(200.0));
    near(solve_twice(&mut s, b1), -160.0);
    let (mut s, b1) = two_lines(25.0, |c| c.with_val(390.0));
    near(solve_twice(&mut s, b1), 30.0);
}

#[test]
fn solvespace_supplementary_angle_keeps_the_drawn_turn() {
    let (mut s, b1) = two_lines(-140.0, |c| c.with_val(-30.0).with_flags(true, false));
    near(solve_twice(&mut s, b1), -150.0);
}

#[test]
fn signed_angle_turns_a_line_over_to_its_side() {
    // Drawn counter-clockwise, asked clockwise: B crosses A's direction to reach -30.
    let (mut s, b1) = two_lines(25.0, |c| c.with_val(-30.0).as_signed());
    near(solve_twice(&mut s, b1), -30.0);
    // Drawn clockwise, asked counter-clockwise.
    let (mut s, b1) = two_lines(-25.0, |c| c.with_val(30.0).as_signed());
    near(solve_twice(&mut s, b1), 30.0);
}

#[test]
fn signed_angle_is_read_modulo_a_full_turn() {
    // 270 counter-clockwise is 90 clockwise; -200 is 160.
    let (mut s, b1) = two_lines(-80.0, |c| c.with_val(270.0).as_signed());
    near(solve_twice(&mut s, b1), -90.0);
    let (mut s, b1) = two_lines(150.0, |c| c.with_val(-200.0).as_signed());
    near(solve_twice(&mut s, b1), 160.0);
}

#[test]
fn signed_supplementary_angle_is_measured_against_b_reversed() {
    // 30 from A to B reversed: B itself at 30 - 180 = -150.
    let (mut s, b1) = two_lines(-140.0, |c| {
        c.with_val(30.0).with_flags(true, false).as_signed()
    });
    near(solve_twice(&mut s, b1), -150.0);
}

#[test]
fn signed_and_unsigned_angles_on_the_same_lines_are_not_duplicates() {
    // At 30 degrees counter-clockwise both hold; the signed one is not the unsigned one again.
    let (mut s, b1) = two_lines(25.0, |c| c.with_val(30.0));
    let signed = s.constrain(
        Constraint::new(0, 2, K::Angle)
            .with_entities([401, 402, 0, 0])
            .with_val(30.0)
            .as_signed(),
    );
    let r = s.sys.solve_group(2).unwrap();
    // Two angles on the same lines: one is redundant, and the report says so, naming them.
    assert_eq!(r.outcome, loci::Outcome::RedundantOkay, "{r:?}");
    assert!(r.failed.contains(&signed.into()), "{r:?}");
    near(b_angle(&s, b1), 30.0);
}

#[test]
fn a_signed_reference_angle_measures_with_its_sign() {
    // B solved at -30 degrees (clockwise from A); references on the same lines read it.
    let (mut s, _) = two_lines(25.0, |c| c.with_val(-30.0).as_signed());
    let reference = |s: &mut Sketch, other: bool, signed: bool| {
        let mut c = Constraint::new(0, 2, K::Angle)
            .with_entities([401, 402, 0, 0])
            .with_flags(other, false)
            .as_reference();
        c.signed = signed;
        s.constrain(c)
    };
    let plain = reference(&mut s, false, true);
    let reversed = reference(&mut s, true, true);
    let size = reference(&mut s, false, false);
    let supplement = reference(&mut s, true, false);
    assert!(s.sys.solve_group(2).unwrap().outcome.is_ok());
    let d = s.sys.diagnose(2).unwrap();
    let read = |h: u32| {
        d.measurements
            .iter()
            .find(|m| m.constraint.0 == h)
            .map(|m| m.value)
            .unwrap()
    };
    near(read(plain), -30.0);
    near(read(reversed), 150.0);
    near(read(size), 30.0);
    near(read(supplement), 150.0);
}

#[test]
fn signed_is_read_and_written_by_the_json_format() {
    let (s, _) = two_lines(25.0, |c| c.with_val(-30.0).as_signed());
    let text = Problem {
        system: s.sys,
        solve: None,
    }
    .to_json();
    assert!(text.contains("\"signed\": true"), "{text}");
    let back = Problem::from_json(&text).unwrap();
    let c = back
        .system
        .constraints()
        .iter()
        .find(|c| c.kind == K::Angle)
        .unwrap();
    assert!(c.signed && c.val == -30.0, "{c:?}");
}
