//! Dragging keeps tangent shapes on their side: an arc tangent to a line stays on the same
//! side of it, and two circles touching from outside never end up one inside the other, even
//! when one step of the drag would land nearer the mirror configuration.

use loci::sketch::{End, Sketch};

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Which side of the line from `p` to `q` the point `c` is on.
fn side(p: [f64; 2], q: [f64; 2], c: [f64; 2]) -> f64 {
    ((q[0] - p[0]) * (c[1] - p[1]) - (q[1] - p[1]) * (c[0] - p[0])).signum()
}

#[test]
fn a_line_tangent_to_an_arc_at_its_end_never_turns_over() {
    // A fixed arc about the origin, radius 1, from 0 degrees round to 270; a line of length
    // 3 from the arc's start runs down from it, tangent to it there, the centre on the left
    // of the line's direction from its far end.
    let mut s = Sketch::new();
    let c = s.add_point(0.0, 0.0).unwrap();
    let a0 = s.add_point(1.0, 0.0).unwrap();
    let a1 = s.add_point(0.0, -1.0).unwrap();
    let arc = s.add_arc(c, a0, a1).unwrap();
    let p = s.add_point(1.0, -3.0).unwrap();
    let line = s.add_line(p, a0).unwrap();
    s.fix(c).unwrap();
    s.fix(a0).unwrap();
    s.fix(a1).unwrap();
    s.tangent(line, End::Start, arc, End::Start).unwrap();
    let r = s.solve().unwrap();
    assert!(r.outcome.is_ok(), "{r:?}");
    let want = side(s.point(p), s.point(a0), s.point(c));
    assert_eq!(want, 1.0);
    // The far end is dragged straight up past the arc. The line keeps its length and its
    // tangency, so the only place it can reach up there is the mirror one, turned over
    // about the touching point with the arc on its right: the drag must stop short.
    let mut prevented = 0;
    let mut drag = s.begin_drag(p).unwrap();
    for k in 1..=6 {
        let target = [1.0, -3.0 + k as f64];
        let st = drag.step(target).unwrap();
        prevented += st.flips_prevented;
        let sk = drag.sketch();
        let (pp, q, cc) = (sk.point(p), sk.point(a0), sk.point(c));
        assert_eq!(side(pp, q, cc), want, "step {k}: {st:?}");
        // Still tangent and still 3 long: the radius at the touching point is square to it.
        let (d, rad) = ([q[0] - pp[0], q[1] - pp[1]], [q[0] - cc[0], q[1] - cc[1]]);
        assert!((d[0] * rad[0] + d[1] * rad[1]).abs() < 1e-7, "step {k}");
        assert!((dist(pp, q) - 3.0).abs() < 1e-7, "step {k}");
        assert!(pp[1] < 0.0, "step {k}: {pp:?}");
    }
    assert!(prevented > 0, "the path would have turned the line over");
}

#[test]
fn a_line_dragged_across_a_tangent_circle_keeps_the_circle_on_its_side() {
    // A fixed circle under a free line tangent to it; the line is dragged whole, by its
    // middle, down through the circle to below it.
    let mut s = Sketch::new();
    let c = s.add_point(0.0, 0.0).unwrap();
    let circle = s.add_circle(c, 1.0).unwrap();
    let p = s.add_point(-1.5, 1.0).unwrap();
    let q = s.add_point(1.5, 1.0).unwrap();
    let line = s.add_line(p, q).unwrap();
    s.fix(c).unwrap();
    s.radius(circle, 1.0).unwrap();
    s.tangent(line, End::Start, circle, End::Start).unwrap();
    assert!(s.solve().unwrap().outcome.is_ok());
    let want = side(s.point(p), s.point(q), s.point(c));
    let mut drag = s.begin_drag(line).unwrap();
    for (k, y) in [0.5, -0.5, -1.5, -2.5].into_iter().enumerate() {
        let st = drag.step([0.0, y]).unwrap();
        assert!(st.outcome.is_ok(), "step {k}: {st:?}");
        let sk = drag.sketch();
        let (pp, qq, cc) = (sk.point(p), sk.point(q), sk.point(c));
        assert_eq!(side(pp, qq, cc), want, "step {k}: {st:?}");
        // Tangent: the centre is one radius from the line.
        let d = [qq[0] - pp[0], qq[1] - pp[1]];
        let off = (d[0] * (cc[1] - pp[1]) - d[1] * (cc[0] - pp[0])).abs() / d[0].hypot(d[1]);
        assert!((off - 1.0).abs() < 1e-7, "step {k}: {off}");
    }
}

#[test]
fn circles_touching_from_outside_never_end_up_one_inside_the_other() {
    let mut s = Sketch::new();
    let ca = s.add_point(0.0, 0.0).unwrap();
    let a = s.add_circle(ca, 1.0).unwrap();
    let cb = s.add_point(1.5, 0.0).unwrap();
    let b = s.add_circle(cb, 0.5).unwrap();
    s.fix(ca).unwrap();
    s.radius(a, 1.0).unwrap();
    s.radius(b, 0.5).unwrap();
    s.tangent(a, End::Start, b, End::Start).unwrap();
    assert!(s.solve().unwrap().outcome.is_ok());
    // Dragged by its centre through the other's: nearest the cursor near the middle is the
    // small circle inside the big one, touching it from within.
    let mut prevented = 0;
    let mut drag = s.begin_drag(b).unwrap();
    for (k, x) in [0.2, -0.2, -1.5].into_iter().enumerate() {
        let st = drag.step([x, 0.05]).unwrap();
        assert!(st.outcome.is_ok(), "step {k}: {st:?}");
        prevented += st.flips_prevented;
        let sk = drag.sketch();
        let d = dist(sk.point(ca), sk.point(cb));
        assert!(
            (d - 1.5).abs() < 1e-7,
            "step {k}: centres {d} apart, {st:?}"
        );
    }
    assert!(
        prevented > 0,
        "the path would have put one circle inside the other"
    );
}
