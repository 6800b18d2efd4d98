//! The random construction steps of a base system. Each step derives new geometry from the
//! geometry already there (never moving it) and adds the constraints that the construction
//! makes true, with values measured from it: so the whole system holds at the true
//! configuration, whatever steps were drawn.

use crate::geom::{add, cross, dot, lerp, norm, scale, sub};
use crate::sketch::Sketch;
use loci::ConstraintKind as K;

/// The kinds of step, with their weights for planar and spatial systems.
#[derive(Clone, Copy, Debug)]
enum Step {
    Line,
    Distance,
    OnLine,
    Midpoint,
    Coincident,
    PtLineDistance,
    Circle,
    OnCircle,
    Arc,
    EqualRadius,
    Symmetric,
    Angle,
    InPlane,
}

const STEPS: [(Step, u32, u32); 13] = [
    (Step::Line, 30, 30),
    (Step::Distance, 8, 8),
    (Step::OnLine, 8, 9),
    (Step::Midpoint, 5, 5),
    (Step::Coincident, 5, 5),
    (Step::PtLineDistance, 6, 6),
    (Step::Circle, 6, 5),
    (Step::OnCircle, 6, 6),
    (Step::Arc, 5, 3),
    (Step::EqualRadius, 3, 3),
    (Step::Symmetric, 5, 5),
    (Step::Angle, 4, 4),
    (Step::InPlane, 0, 6),
];

/// Draws one step and applies it (a step whose prerequisites are missing adds a line).
pub fn step(s: &mut Sketch) {
    let weights: Vec<u32> = STEPS
        .iter()
        .map(|&(_, p, q)| if s.planar() { p } else { q })
        .collect();
    let kind = STEPS[s.rng.weighted(&weights)].0;
    let done = match kind {
        Step::Line => false,
        Step::Distance => distance(s),
        Step::OnLine => on_line(s, false),
        Step::Midpoint => on_line(s, true),
        Step::Coincident => coincident(s),
        Step::PtLineDistance => pt_line_distance(s),
        Step::Circle => circle(s),
        Step::OnCircle => on_circle(s),
        Step::Arc => arc(s),
        Step::EqualRadius => equal_radius(s),
        Step::Symmetric => symmetric(s),
        Step::Angle => angle(s),
        Step::InPlane => in_plane(s),
    };
    if !done {
        line(s);
    }
}

/// A new line from an existing (or new) point, in one of several relations to the rest.
pub fn line(s: &mut Sketch) {
    let a = s.some_point(0.7);
    let at = s.pts[a].at;
    let len = s.rng.range(2.0, 10.0) * s.rng.sign();
    let other = (!s.lines.is_empty()).then(|| s.rng.below(s.lines.len()));
    let (_, u, v, n) = s.frame;
    match (s.rng.below(7), other) {
        (1 | 2, _) => {
            // Horizontal or vertical in the plane; a spatial line may leave the plane.
            let (axis, kind) = if s.rng.chance(0.5) {
                (u, K::Horizontal)
            } else {
                (v, K::Vertical)
            };
            let lift = if s.planar() {
                0.0
            } else {
                s.rng.range(-5.0, 5.0)
            };
            let b = s.point(add(add(at, scale(axis, len)), scale(n, lift)));
            let l = s.line(a, b);
            s.axis_aligned(kind, l);
        }
        (3, Some(o)) => {
            let d = crate::geom::unit(s.dir(o));
            let b = s.point(add(at, scale(d, len)));
            let l = s.line(a, b);
            s.between_lines(K::Parallel, l, o);
        }
        (4, Some(o)) => {
            let d = crate::geom::unit(s.dir(o));
            let p = s.perp_dir(d);
            let b = s.point(add(at, scale(p, len)));
            let l = s.line(a, b);
            s.between_lines(K::Perpendicular, l, o);
        }
        (5, Some(o)) => {
            let d = s.random_dir();
            let b = s.point(add(at, scale(d, norm(s.dir(o)))));
            let l = s.line(a, b);
            s.between_lines(K::EqualLengthLines, l, o);
        }
        (6, Some(o)) => {
            let d = crate::geom::unit(s.dir(o));
            let deg = s.rng.range(20.0, 160.0);
            let e = s.dir_at_angle(d, deg);
            let b = s.point(add(at, scale(e, len.abs())));
            let l = s.line(a, b);
            let measured = s.angle_between(o, l);
            s.angle(o, l, measured);
        }
        _ => {
            let d = s.random_dir();
            let b = s.point(add(at, scale(d, len)));
            s.line(a, b);
            if s.rng.chance(0.6) {
                s.distance(a, b);
            }
        }
    }
}

fn pick_line(s: &mut Sketch) -> Option<usize> {
    (!s.lines.is_empty()).then(|| s.rng.below(s.lines.len()))
}

fn pick_circle(s: &mut Sketch) -> Option<usize> {
    (!s.circles.is_empty()).then(|| s.rng.below(s.circles.len()))
}

fn distance(s: &mut Sketch) -> bool {
    if s.pts.len() < 2 {
        return false;
    }
    let (a, b) = (s.rng.below(s.pts.len()), s.rng.below(s.pts.len()));
    if norm(sub(s.pts[a].at, s.pts[b].at)) < 0.5 {
        return false;
    }
    s.distance(a, b);
    true
}

/// A new point on a line (3D `pt_on_line` in spatial systems), or at its midpoint.
fn on_line(s: &mut Sketch, mid: bool) -> bool {
    let Some(l) = pick_line(s) else {
        return false;
    };
    let t = if mid { 0.5 } else { s.rng.range(-0.5, 1.5) };
    let (a, b) = (s.pts[s.lines[l].a].at, s.pts[s.lines[l].b].at);
    let p = s.point(lerp(a, b, t));
    if mid {
        s.midpoint(p, l);
    } else {
        s.on_line(p, l);
    }
    true
}

/// A second point entity where a point is: joined by a coincident constraint, and the start
/// of a new free line so that it is not left alone (unless it is a 2D point of a spatial
/// system, which no 3D line may join).
fn coincident(s: &mut Sketch) -> bool {
    if s.pts.is_empty() {
        return false;
    }
    let a = s.rng.below(s.pts.len());
    let b = s.point_as(s.pts[a].at, s.pts[a].flat);
    s.coincident(a, b);
    if s.pts[b].flat {
        return true;
    }
    let d = s.random_dir();
    let len = s.rng.range(2.0, 8.0);
    let c = s.point(add(s.pts[b].at, scale(d, len)));
    s.line(b, c);
    true
}

/// The distance from a point to a line: signed in a workplane (positive to the right of the
/// line's direction, SolveSpace's convention), unsigned in 3D.
fn pt_line_distance(s: &mut Sketch) -> bool {
    let Some(l) = pick_line(s) else {
        return false;
    };
    let p = s.some_point(0.6);
    let (a, d) = (s.pts[s.lines[l].a].at, s.dir(l));
    let c = cross(d, sub(s.pts[p].at, a));
    let val = if s.planar() {
        -c[2] / norm(d)
    } else {
        norm(c) / norm(d)
    };
    if val.abs() < 0.5 {
        return false;
    }
    let con = s
        .con(K::PtLineDistance)
        .with_points(s.pt_h(p), 0)
        .with_entities([s.lines[l].h, 0, 0, 0])
        .with_val(val);
    s.push(con);
    true
}

fn circle(s: &mut Sketch) -> bool {
    let c = s.center(0.5);
    let r = s.rng.range(1.0, 5.0);
    let ci = s.circle(c, r);
    if s.rng.chance(0.7) {
        let h = s.circles[ci].h;
        s.unplaned(K::Diameter, None, [h, 0], 2.0 * r);
    }
    true
}

/// A new point on a circle or arc; in 3D a 3D point, sometimes off the circle's plane, since
/// SolveSpace's point-on-circle holds the point on the circle's cylinder.
fn on_circle(s: &mut Sketch) -> bool {
    let Some(c) = pick_circle(s) else {
        return false;
    };
    let t = s.rng.range(0.0, std::f64::consts::TAU);
    let lift = if !s.planar() && s.rng.chance(0.3) {
        s.rng.range(-3.0, 3.0)
    } else {
        0.0
    };
    let p = s.point(s.on_circle(c, t, lift));
    let h = s.circles[c].h;
    s.unplaned(K::PtOnCircle, Some(p), [h, 0], 0.0);
    true
}

fn arc(s: &mut Sketch) -> bool {
    let c = s.center(0.4);
    let r = s.rng.range(1.5, 5.0);
    let t0 = s.rng.range(0.0, std::f64::consts::TAU);
    let t1 = t0 + s.rng.range(0.5, 5.0);
    let a = s.arc(c, r, t0, t1);
    if s.rng.chance(0.5) {
        let h = s.circles[a].h;
        s.unplaned(K::Diameter, None, [h, 0], 2.0 * r);
    }
    true
}

fn equal_radius(s: &mut Sketch) -> bool {
    let Some(c) = pick_circle(s) else {
        return false;
    };
    let center = s.center(0.3);
    let r = s.circles[c].r;
    let n = s.circle(center, r);
    let (hn, hc) = (s.circles[n].h, s.circles[c].h);
    s.unplaned(K::EqualRadius, None, [hn, hc], 0.0);
    true
}

/// A new point mirroring an existing one: about a line or the plane's axes in a workplane,
/// about the reference plane in 3D.
fn symmetric(s: &mut Sketch) -> bool {
    let ok = s.joinable();
    if ok.is_empty() {
        return false;
    }
    let p = ok[s.rng.below(ok.len())];
    let at = s.pts[p].at;
    if !s.planar() {
        let n = s.frame.3;
        let q = s.point(sub(at, scale(n, 2.0 * s.plane_height(at))));
        let c = s
            .con(K::Symmetric)
            .with_points(s.pt_h(p), s.pt_h(q))
            .with_entities([s.plane, 0, 0, 0]);
        s.push(c);
        return true;
    }
    let c = match (s.rng.below(3), pick_line(s)) {
        (0, Some(l)) => {
            let (a, d) = (s.pts[s.lines[l].a].at, s.dir(l));
            let foot = add(a, scale(d, dot(sub(at, a), d) / dot(d, d)));
            let q = s.point(sub(scale(foot, 2.0), at));
            s.con(K::SymmetricLine)
                .with_points(s.pt_h(p), s.pt_h(q))
                .with_entities([s.lines[l].h, 0, 0, 0])
        }
        (1, _) => {
            let q = s.point([-at[0], at[1], 0.0]);
            s.con(K::SymmetricHoriz).with_points(s.pt_h(p), s.pt_h(q))
        }
        _ => {
            let q = s.point([at[0], -at[1], 0.0]);
            s.con(K::SymmetricVert).with_points(s.pt_h(p), s.pt_h(q))
        }
    };
    s.push(c);
    true
}

/// The measured angle between two existing lines, when it is well away from 0 and 180.
fn angle(s: &mut Sketch) -> bool {
    if s.lines.len() < 2 {
        return false;
    }
    let (a, b) = (s.rng.below(s.lines.len()), s.rng.below(s.lines.len()));
    let deg = s.angle_between(a, b);
    if a == b || !(20.0..=160.0).contains(&deg) {
        return false;
    }
    s.angle(a, b, deg);
    true
}

/// A new point in the reference plane, or the measured height of a point above it.
fn in_plane(s: &mut Sketch) -> bool {
    if s.planar() {
        return false;
    }
    let (o, u, v, _) = s.frame;
    let ok = s.joinable();
    if ok.is_empty() || s.rng.chance(0.5) {
        let (x, y) = (s.rng.range(-10.0, 10.0), s.rng.range(-10.0, 10.0));
        let p = s.point(add(o, add(scale(u, x), scale(v, y))));
        s.unplaned(K::PtInPlane, Some(p), [s.plane, 0], 0.0);
    } else {
        let p = ok[s.rng.below(ok.len())];
        let h = s.plane_height(s.pts[p].at);
        s.unplaned(K::PtPlaneDistance, Some(p), [s.plane, 0], h);
    }
    true
}
