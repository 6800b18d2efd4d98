//! Small constructions that make a constraint follow from others, for the `redundant` and
//! `conflicting` variants. Each builds its geometry from the true configuration, adds the
//! constraints that pin the relation down, and then plants the implied constraint: with the
//! value that holds (redundant) or with one that cannot (conflicting).
//!
//! A conflicting value must contradict every solution of the other constraints, not only the
//! true one, so each gadget also fixes the lengths that keep its lines from collapsing to a
//! point (where directions stop meaning anything).

use crate::geom::{add, lerp, norm, scale, sub, unit};
use crate::sketch::Sketch;
use loci::ConstraintKind as K;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Gadget {
    /// A copy of an existing constraint.
    Duplicate,
    /// Three sides of a triangle fix the angle between two of them.
    Triangle,
    /// A point at the midpoint of a line of known length is half that length from its start.
    Midpoint,
    /// A point on a circle of known diameter, both in its plane, is a radius from its centre.
    Circle,
    /// L2 = L1 and L3 = L2 in length, with L1's length given, fix L3's length.
    EqualChain,
    /// a = b and b = c make a = c.
    CoincidentChain,
    /// L2 parallel to L1 and L3 parallel to L2 (none of them of zero length) make L3 parallel
    /// to L1.
    ParallelChain,
    /// A horizontal and a vertical line (planar only) are perpendicular.
    HorizVert,
    /// Points symmetric about the reference plane are at opposite heights (spatial only).
    PlaneSymmetry,
    /// Two points on a line make a segment parallel to it (no value: redundant only).
    OnLinePair,
}

/// What a gadget planted: the constraint's index, and for a dimension the value that holds
/// with the others and one that contradicts them.
pub struct Planted {
    pub index: usize,
    pub values: Option<(f64, f64)>,
}

impl Gadget {
    pub const REDUNDANT: [Gadget; 10] = [
        Gadget::Duplicate,
        Gadget::Triangle,
        Gadget::Midpoint,
        Gadget::Circle,
        Gadget::EqualChain,
        Gadget::CoincidentChain,
        Gadget::ParallelChain,
        Gadget::HorizVert,
        Gadget::PlaneSymmetry,
        Gadget::OnLinePair,
    ];

    /// Whether the gadget can be built in a system of this kind, and (for the conflicting
    /// variant) whether it plants a dimension whose value can contradict.
    pub fn fits(self, planar: bool, conflicting: bool) -> bool {
        match self {
            Gadget::HorizVert => planar,
            Gadget::PlaneSymmetry => !planar,
            Gadget::OnLinePair => !conflicting,
            _ => true,
        }
    }
}

/// Builds `g` and plants its implied constraint, contradicting when `conflicting`.
pub fn build(s: &mut Sketch, g: Gadget, conflicting: bool) -> Planted {
    let planted = match g {
        Gadget::Duplicate => return duplicate(s, conflicting),
        Gadget::Triangle => triangle(s),
        Gadget::Midpoint => midpoint(s),
        Gadget::Circle => circle(s),
        Gadget::EqualChain => equal_chain(s, conflicting),
        Gadget::CoincidentChain => coincident_chain(s, conflicting),
        Gadget::ParallelChain => parallel_chain(s, conflicting),
        Gadget::HorizVert => horiz_vert(s, conflicting),
        Gadget::PlaneSymmetry => plane_symmetry(s),
        Gadget::OnLinePair => on_line_pair(s),
    };
    if conflicting {
        if let Some((_, bad)) = planted.values {
            s.cons[planted.index].val = bad;
        }
    }
    s.planted.push(planted.index);
    planted
}

/// A line from an existing or new point, of a random direction and length; with its length
/// constrained when `fixed`.
fn segment(s: &mut Sketch, len: f64, fixed: bool) -> usize {
    let a = s.some_point(0.5);
    let d = s.random_dir();
    let b = s.point(add(s.pts[a].at, scale(d, len)));
    let l = s.line(a, b);
    if fixed {
        s.distance(a, b);
    }
    l
}

/// A value changed by a factor: enough to contradict, never enough to change its sign.
fn off(s: &mut Sketch, v: f64) -> f64 {
    let f = if s.rng.chance(0.5) { 1.3 } else { 0.7 };
    apart(v, f)
}

/// `v` times `f`, or, for a `v` that is zero but for rounding (a point in a plane, measured
/// at -2e-16), `v` moved by `f - 1`: a multiple of it would contradict nothing (seed 8169
/// called a copy at -2.9e-16 of a distance at -2.2e-16 a contradiction).
fn apart(v: f64, f: f64) -> f64 {
    if v.abs() < 1e-6 {
        v + (f - 1.0)
    } else {
        v * f
    }
}

fn duplicate(s: &mut Sketch, conflicting: bool) -> Planted {
    let valued = |k| {
        matches!(
            k,
            K::PtPtDistance | K::Diameter | K::PtLineDistance | K::PtPlaneDistance | K::Angle
        )
    };
    let candidates: Vec<usize> = (0..s.cons.len())
        .filter(|&i| !s.planted.contains(&i) && (!conflicting || valued(s.cons[i].kind)))
        .collect();
    if candidates.is_empty() {
        return build(s, Gadget::Midpoint, conflicting);
    }
    let i = candidates[s.rng.below(candidates.len())];
    let c = s.cons[i].clone();
    let values = valued(c.kind).then(|| {
        let bad = if c.kind == K::Angle {
            // Keep a contradicting angle inside (0, 180): its cosine then differs.
            if c.val > 90.0 {
                c.val * 0.8
            } else {
                apart(c.val, 1.3)
            }
        } else {
            apart(c.val, 1.3)
        };
        (c.val, bad)
    });
    let index = s.push(c);
    if conflicting {
        s.cons[index].val = values.expect("a valued constraint").1;
    }
    s.planted.push(index);
    Planted { index, values }
}

fn triangle(s: &mut Sketch) -> Planted {
    let a = s.some_point(0.5);
    let d1 = s.random_dir();
    let deg = s.rng.range(35.0, 145.0);
    let d2 = s.dir_at_angle(d1, deg);
    let at = s.pts[a].at;
    let (l1, l2) = (s.rng.range(3.0, 10.0), s.rng.range(3.0, 10.0));
    let b = s.point(add(at, scale(d1, l1)));
    let c = s.point(add(at, scale(d2, l2)));
    s.distance(a, b);
    s.distance(a, c);
    s.distance(b, c);
    let (ab, ac) = (s.line(a, b), s.line(a, c));
    let measured = s.angle_between(ab, ac);
    let delta = s.rng.range(15.0, 30.0);
    let bad = if measured + delta < 170.0 {
        measured + delta
    } else {
        measured - delta
    };
    let index = s.angle(ab, ac, measured);
    Planted {
        index,
        values: Some((measured, bad)),
    }
}

fn midpoint(s: &mut Sketch) -> Planted {
    let len = s.rng.range(3.0, 10.0);
    let l = segment(s, len, true);
    let (a, b) = (s.lines[l].a, s.lines[l].b);
    let m = s.point(lerp(s.pts[a].at, s.pts[b].at, 0.5));
    s.midpoint(m, l);
    let index = s.distance(a, m);
    let half = s.cons[index].val;
    let bad = off(s, half);
    Planted {
        index,
        values: Some((half, bad)),
    }
}

fn circle(s: &mut Sketch) -> Planted {
    let c = s.center(0.5);
    let r = s.rng.range(2.0, 5.0);
    let ci = s.circle(c, r);
    let h = s.circles[ci].h;
    s.unplaned(K::Diameter, None, [h, 0], 2.0 * r);
    let t = s.rng.range(0.0, std::f64::consts::TAU);
    let p = s.point_as(s.on_circle(ci, t, 0.0), true);
    s.unplaned(K::PtOnCircle, Some(p), [h, 0], 0.0);
    let index = s.distance(c, p);
    let bad = off(s, r);
    Planted {
        index,
        values: Some((s.cons[index].val, bad)),
    }
}

fn equal_chain(s: &mut Sketch, conflicting: bool) -> Planted {
    let len = s.rng.range(3.0, 10.0);
    let l1 = segment(s, len, true);
    let l2 = segment(s, len, false);
    s.between_lines(K::EqualLengthLines, l2, l1);
    let l3 = segment(s, len, false);
    s.between_lines(K::EqualLengthLines, l3, l2);
    if !conflicting && s.rng.chance(0.5) {
        let index = s.between_lines(K::EqualLengthLines, l1, l3);
        return Planted {
            index,
            values: None,
        };
    }
    let index = s.distance(s.lines[l3].a, s.lines[l3].b);
    let bad = off(s, len);
    Planted {
        index,
        values: Some((s.cons[index].val, bad)),
    }
}

fn coincident_chain(s: &mut Sketch, conflicting: bool) -> Planted {
    let a = s.some_point(0.7);
    let at = s.pts[a].at;
    let b = s.point(at);
    s.coincident(a, b);
    let c = s.point(at);
    s.coincident(b, c);
    // Lines from the copies, so that each is part of the drawing.
    for p in [b, c] {
        let d = s.random_dir();
        let e = s.point(add(at, scale(d, 4.0)));
        s.line(p, e);
    }
    if conflicting {
        // A distance between points that must coincide: no value of it holds but zero, which
        // is not a dimension a solver can meet smoothly, so there is no consistent value.
        let dist = s.rng.range(0.5, 2.0);
        let con = s
            .con(K::PtPtDistance)
            .with_points(s.pt_h(a), s.pt_h(c))
            .with_val(dist);
        let index = s.push(con);
        return Planted {
            index,
            values: None,
        };
    }
    let index = s.coincident(a, c);
    Planted {
        index,
        values: None,
    }
}

fn parallel_chain(s: &mut Sketch, conflicting: bool) -> Planted {
    let len = s.rng.range(3.0, 10.0);
    let l1 = segment(s, len, true);
    let d = unit(s.dir(l1));
    let mut prev = l1;
    for _ in 0..2 {
        let a = s.some_point(0.3);
        let len = s.rng.range(3.0, 10.0) * s.rng.sign();
        let b = s.point(add(s.pts[a].at, scale(d, len)));
        let l = s.line(a, b);
        s.between_lines(K::Parallel, l, prev);
        s.distance(a, b);
        prev = l;
    }
    if conflicting {
        // Parallel lines meet at 0 or 180 degrees; any angle well between contradicts. (The
        // value that holds, 0 or 180, is degenerate for an angle: no consistent value.)
        let deg = s.rng.range(30.0, 150.0);
        let index = s.angle(l1, prev, deg);
        return Planted {
            index,
            values: None,
        };
    }
    let index = s.between_lines(K::Parallel, l1, prev);
    Planted {
        index,
        values: None,
    }
}

fn horiz_vert(s: &mut Sketch, conflicting: bool) -> Planted {
    let mut lines = [0; 2];
    for (slot, (axis, kind)) in lines
        .iter_mut()
        .zip([(s.frame.1, K::Horizontal), (s.frame.2, K::Vertical)])
    {
        let a = s.some_point(0.5);
        let len = s.rng.range(3.0, 10.0) * s.rng.sign();
        let b = s.point(add(s.pts[a].at, scale(axis, len)));
        let l = s.line(a, b);
        s.axis_aligned(kind, l);
        s.distance(a, b);
        *slot = l;
    }
    if !conflicting && s.rng.chance(0.5) {
        let index = s.between_lines(K::Perpendicular, lines[0], lines[1]);
        return Planted {
            index,
            values: None,
        };
    }
    let bad = if s.rng.chance(0.5) {
        s.rng.range(30.0, 60.0)
    } else {
        s.rng.range(120.0, 150.0)
    };
    let index = s.angle(lines[0], lines[1], 90.0);
    Planted {
        index,
        values: Some((90.0, bad)),
    }
}

fn plane_symmetry(s: &mut Sketch) -> Planted {
    let (o, u, v, n) = s.frame;
    let h = s.rng.range(1.0, 5.0) * s.rng.sign();
    let (x, y) = (s.rng.range(-8.0, 8.0), s.rng.range(-8.0, 8.0));
    let at = add(add(o, add(scale(u, x), scale(v, y))), scale(n, h));
    let p = s.point(at);
    s.unplaned(K::PtPlaneDistance, Some(p), [s.plane, 0], h);
    let q = s.point(sub(at, scale(n, 2.0 * h)));
    let c = s
        .con(K::Symmetric)
        .with_points(s.pt_h(p), s.pt_h(q))
        .with_entities([s.plane, 0, 0, 0]);
    s.push(c);
    let index = s.unplaned(K::PtPlaneDistance, Some(q), [s.plane, 0], -h);
    let bad = off(s, -h);
    Planted {
        index,
        values: Some((-h, bad)),
    }
}

fn on_line_pair(s: &mut Sketch) -> Planted {
    let len = s.rng.range(3.0, 10.0);
    let l = segment(s, len, false);
    let (a, b) = (s.pts[s.lines[l].a].at, s.pts[s.lines[l].b].at);
    let t1 = s.rng.range(-0.5, 1.5);
    let t2 = t1 + s.rng.range(0.3, 1.0) * s.rng.sign();
    let p = s.point(lerp(a, b, t1));
    let q = s.point(lerp(a, b, t2));
    s.on_line(p, l);
    s.on_line(q, l);
    let pq = s.line(p, q);
    debug_assert!(norm(s.dir(pq)) > 0.1);
    let index = s.between_lines(K::Parallel, pq, l);
    Planted {
        index,
        values: None,
    }
}
