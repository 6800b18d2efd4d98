//! The residual checker: measures, independently of every solver, how far returned
//! coordinates are from satisfying a problem.
//!
//! Each residual is in model units (lengths) or radians (angles), so one threshold,
//! [`TOLERANCE`], applies to all of them. Fixed points must stay where they started and an
//! arc's two ends must stay equally far from its centre.

use crate::problem::{Con, Problem};

/// A result whose largest residual is at or above this is recorded as wrong.
pub const TOLERANCE: f64 = 1e-6;

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

fn cross(u: [f64; 3], v: [f64; 3]) -> [f64; 3] {
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

/// The largest residual of `pts` (one entry per problem point) over every constraint, fixed
/// point and arc; `f64::INFINITY` when a coordinate is not finite or the count is wrong.
#[must_use]
pub fn max_residual(p: &Problem, pts: &[[f64; 3]]) -> f64 {
    if pts.len() != p.points.len() || pts.iter().flatten().any(|v| !v.is_finite()) {
        return f64::INFINITY;
    }
    let mut worst: f64 = 0.0;
    let mut see = |r: f64| {
        // NaN must count as the worst possible, never be skipped by max.
        worst = if r.is_nan() {
            f64::INFINITY
        } else {
            worst.max(r.abs())
        };
    };
    for (pt, got) in p.points.iter().zip(pts) {
        if pt.fixed {
            see(norm(sub(*got, pt.start)));
        }
    }
    if p.planar {
        for got in pts {
            see(got[2]);
        }
    }
    let dir = |l: usize| sub(pts[p.lines[l][1]], pts[p.lines[l][0]]);
    for a in &p.arcs {
        let c = pts[a.center];
        see(norm(sub(pts[a.start], c)) - norm(sub(pts[a.end], c)));
    }
    for c in &p.cons {
        match *c {
            Con::Coincident { a, b } => see(norm(sub(pts[a], pts[b]))),
            Con::Distance { a, b, d } => see(norm(sub(pts[a], pts[b])) - d),
            Con::Angle { l1, l2, deg } => {
                let (u, v) = (dir(l1), dir(l2));
                let got = norm(cross(u, v)).atan2(dot(u, v));
                see(got - deg.abs().to_radians());
            }
            Con::Horizontal { l } => see(dir(l)[1]),
            Con::Vertical { l } => see(dir(l)[0]),
            Con::ArcRadius { arc, r } => {
                let a = p.arcs[arc];
                see(norm(sub(pts[a.start], pts[a.center])) - r);
            }
            Con::Tangent { arc, at_end, l } => {
                let a = p.arcs[arc];
                let on = if at_end { a.end } else { a.start };
                let radius = sub(pts[on], pts[a.center]);
                let d = dir(l);
                // The sine of the angle between line and tangent.
                see(dot(radius, d) / (norm(radius) * norm(d)));
            }
            Con::InPlane { p: pi, plane } => {
                let pl = p.planes[plane];
                see(dot(sub(pts[pi], pl.origin), pl.normal()));
            }
        }
    }
    worst
}

/// The problem's starting coordinates, as a solver would receive them.
#[must_use]
pub fn start_points(p: &Problem) -> Vec<[f64; 3]> {
    p.points.iter().map(|q| q.start).collect()
}
