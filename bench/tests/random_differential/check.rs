//! The independent residual check: from parameter values alone, with plain f64 geometry,
//! whether every constraint of the solved group and every implicit condition of its
//! entities holds. It reads the model's structure (which entity a constraint names, which
//! parameters a point has) and nothing of loci's equations: each rule below is the
//! geometric condition SolveSpace documents for the constraint, e.g. 3D parallel as the full
//! cross product of the two directions.
//!
//! Residuals of lengths are divided by the system's scale (the largest coordinate, at least
//! 1), so [`TOLERANCE`] is relative; residuals of directions are sines and cosines.

use crate::geom::{add, cross, dot, norm, quat_axes, scale, sub, V3};
use crate::sketch::GROUP;
use loci::{Constraint, ConstraintKind as K, EntityId, EntityKind, ParamId, System};
use std::collections::HashMap;

/// The largest residual an answer may leave.
pub const TOLERANCE: f64 = 1e-6;

/// How many times the system's scale a parameter may reach in an answer. Parallel and
/// perpendicular are judged by sines and cosines, and two lines that meet can be parallel to
/// within any sine once their corner runs off towards infinity: such an answer holds nothing
/// in the sense meant, however small its residuals.
pub const FAR: f64 = 1e4;

/// Parameter values by handle.
pub type Values = HashMap<ParamId, f64>;

/// The values of every parameter of `sys`, with `answer` replacing those it names.
pub fn values_with(sys: &System, answer: &Values) -> Values {
    sys.params()
        .iter()
        .map(|p| (p.h, answer.get(&p.h).copied().unwrap_or(p.val)))
        .collect()
}

/// The current values of every parameter of `sys`.
pub fn values_of(sys: &System) -> Values {
    sys.params().iter().map(|p| (p.h, p.val)).collect()
}

/// A plane: origin and axes U, V, N.
type Frame = (V3, V3, V3, V3);

struct Geo<'a> {
    sys: &'a System,
    v: &'a Values,
    /// Below this length a direction is degenerate.
    tiny: f64,
}

impl Geo<'_> {
    fn val(&self, p: ParamId) -> f64 {
        *self.v.get(&p).expect("a value for every parameter")
    }

    fn kind(&self, e: EntityId) -> &EntityKind {
        &self.sys.entity(e).expect("a valid handle").kind
    }

    fn point(&self, e: EntityId) -> V3 {
        let ent = self.sys.entity(e).expect("a valid handle");
        match &ent.kind {
            EntityKind::PointIn3d { params } => params.map(|p| self.val(p)),
            EntityKind::PointIn2d { params } => {
                let (o, u, v, _) = self.frame(ent.workplane.expect("a 2D point's workplane"));
                add(
                    o,
                    add(scale(u, self.val(params[0])), scale(v, self.val(params[1]))),
                )
            }
            k => panic!("the checker has no rule for a point of kind {k:?}"),
        }
    }

    fn quat(&self, e: EntityId) -> [f64; 4] {
        let ent = self.sys.entity(e).expect("a valid handle");
        match &ent.kind {
            EntityKind::NormalIn3d { params } => params.map(|p| self.val(p)),
            EntityKind::NormalIn2d => match self.kind(ent.workplane.expect("its workplane")) {
                EntityKind::Workplane { normal, .. } => self.quat(*normal),
                k => panic!("not a workplane: {k:?}"),
            },
            k => panic!("the checker has no rule for a normal of kind {k:?}"),
        }
    }

    fn frame(&self, wp: EntityId) -> Frame {
        match self.kind(wp) {
            EntityKind::Workplane { origin, normal } => {
                let (u, v, n) = quat_axes(self.quat(*normal));
                (self.point(*origin), u, v, n)
            }
            k => panic!("not a workplane: {k:?}"),
        }
    }

    fn line(&self, e: EntityId) -> (V3, V3) {
        match self.kind(e) {
            EntityKind::LineSegment { points } => (self.point(points[0]), self.point(points[1])),
            k => panic!("not a line: {k:?}"),
        }
    }

    /// Centre, radius (as SolveSpace measures it: |r| of a circle, |start - centre| of an
    /// arc) and the axes U, V of the plane of a circle or arc.
    fn circle(&self, e: EntityId) -> (V3, f64, V3, V3) {
        match self.kind(e) {
            EntityKind::Circle {
                center,
                normal,
                radius,
            } => {
                let r = match self.kind(*radius) {
                    EntityKind::Distance { param } => self.val(*param).abs(),
                    k => panic!("not a distance: {k:?}"),
                };
                let (u, v, _) = quat_axes(self.quat(*normal));
                (self.point(*center), r, u, v)
            }
            EntityKind::ArcOfCircle {
                normal,
                center,
                start,
                ..
            } => {
                let c = self.point(*center);
                let (u, v, _) = quat_axes(self.quat(*normal));
                (c, norm(sub(self.point(*start), c)), u, v)
            }
            k => panic!("not a circle or arc: {k:?}"),
        }
    }

    /// Sine of the angle between two directions; 0 when one has no length.
    fn sine(&self, a: V3, b: V3) -> f64 {
        let (na, nb) = (norm(a), norm(b));
        if na < self.tiny || nb < self.tiny {
            return 0.0;
        }
        norm(cross(a, b)) / (na * nb)
    }

    /// Cosine of the angle between two directions; 0 when one has no length.
    fn cosine(&self, a: V3, b: V3) -> f64 {
        let (na, nb) = (norm(a), norm(b));
        if na < self.tiny || nb < self.tiny {
            return 0.0;
        }
        dot(a, b) / (na * nb)
    }
}

/// Coordinates in the constraint's workplane (u, v, 0), or the 3D point when it has none.
fn proj(wp: Option<Frame>, p: V3) -> V3 {
    match wp {
        Some((o, u, v, _)) => [dot(sub(p, o), u), dot(sub(p, o), v), 0.0],
        None => p,
    }
}

/// A direction in the constraint's workplane, or in 3D.
fn pdir(wp: Option<Frame>, d: V3) -> V3 {
    match wp {
        Some((_, u, v, _)) => [dot(d, u), dot(d, v), 0.0],
        None => d,
    }
}

/// The residual components of one constraint: lengths in model units, the rest unitless.
/// Returns (lengths, unitless).
fn constraint(g: &Geo, c: &Constraint) -> (Vec<f64>, Vec<f64>) {
    let wp = c.workplane.map(|w| g.frame(w));
    let pt = |f: Option<EntityId>| proj(wp, g.point(f.expect("a point field")));
    let ln = |f: Option<EntityId>| {
        let (a, b) = g.line(f.expect("a line field"));
        (proj(wp, a), proj(wp, b))
    };
    let dir = |f: Option<EntityId>| {
        let (a, b) = g.line(f.expect("a line field"));
        pdir(wp, sub(b, a))
    };
    let plane = |f: Option<EntityId>| g.frame(f.expect("a plane field"));
    let (l, u): (Vec<f64>, Vec<f64>) = match c.kind {
        K::PointsCoincident => (vec![norm(sub(pt(c.pt_a), pt(c.pt_b)))], vec![]),
        K::PtPtDistance => (vec![norm(sub(pt(c.pt_a), pt(c.pt_b))) - c.val], vec![]),
        K::PtPlaneDistance | K::PtInPlane => {
            let (o, _, _, n) = plane(c.entity_a);
            let h = dot(sub(g.point(c.pt_a.unwrap()), o), n);
            let want = if c.kind == K::PtInPlane { 0.0 } else { c.val };
            (vec![h - want], vec![])
        }
        K::PtLineDistance | K::PtOnLine => {
            let p = pt(c.pt_a);
            let (a, b) = ln(c.entity_a);
            let d = sub(b, a);
            let dist = if norm(d) < g.tiny {
                norm(sub(p, a))
            } else if wp.is_some() {
                // Signed, positive to the right of the line's direction (SolveSpace's sign).
                -cross(d, sub(p, a))[2] / norm(d)
            } else {
                norm(cross(d, sub(p, a))) / norm(d)
            };
            let want = if c.kind == K::PtOnLine { 0.0 } else { c.val };
            (vec![dist - want], vec![])
        }
        K::EqualLengthLines => (vec![norm(dir(c.entity_a)) - norm(dir(c.entity_b))], vec![]),
        K::Symmetric => {
            assert!(
                wp.is_none(),
                "the checker has no rule for a projected symmetric"
            );
            let (o, u, v, n) = plane(c.entity_a);
            let (a, b) = (g.point(c.pt_a.unwrap()), g.point(c.pt_b.unwrap()));
            let mid = scale(add(a, b), 0.5);
            let ab = sub(a, b);
            (vec![dot(sub(mid, o), n), dot(ab, u), dot(ab, v)], vec![])
        }
        K::SymmetricHoriz | K::SymmetricVert => {
            let (a, b) = (pt(c.pt_a), pt(c.pt_b));
            if c.kind == K::SymmetricHoriz {
                (vec![a[1] - b[1], a[0] + b[0]], vec![])
            } else {
                (vec![a[0] - b[0], a[1] + b[1]], vec![])
            }
        }
        K::SymmetricLine => {
            let (a, b) = (pt(c.pt_a), pt(c.pt_b));
            let (la, lb) = ln(c.entity_a);
            let d = sub(lb, la);
            if norm(d) < g.tiny {
                (vec![norm(sub(a, la)), norm(sub(b, la))], vec![])
            } else {
                let mid = scale(add(a, b), 0.5);
                (
                    vec![
                        dot(d, sub(b, a)) / norm(d),
                        cross(d, sub(mid, la))[2] / norm(d),
                    ],
                    vec![],
                )
            }
        }
        K::AtMidpoint => {
            let (a, b) = ln(c.entity_a);
            (vec![norm(sub(pt(c.pt_a), scale(add(a, b), 0.5)))], vec![])
        }
        K::Horizontal | K::Vertical => {
            let (a, b) = ln(c.entity_a);
            let i = usize::from(c.kind == K::Horizontal);
            (vec![a[i] - b[i]], vec![])
        }
        K::Diameter => {
            let (_, r, _, _) = g.circle(c.entity_a.unwrap());
            (vec![2.0 * r - c.val], vec![])
        }
        K::PtOnCircle => {
            // On the circle's cylinder: the distance from the centre within its plane.
            let (ctr, r, u, v) = g.circle(c.entity_a.unwrap());
            let d = sub(g.point(c.pt_a.unwrap()), ctr);
            (vec![dot(d, u).hypot(dot(d, v)) - r], vec![])
        }
        K::EqualRadius => {
            let (_, r1, _, _) = g.circle(c.entity_a.unwrap());
            let (_, r2, _, _) = g.circle(c.entity_b.unwrap());
            (vec![r1 - r2], vec![])
        }
        K::Angle => {
            let (mut a, b) = (dir(c.entity_a), dir(c.entity_b));
            if c.other {
                a = scale(a, -1.0);
            }
            let degenerate = norm(a) < g.tiny || norm(b) < g.tiny;
            let r = if degenerate {
                f64::INFINITY
            } else {
                g.cosine(a, b) - c.val.to_radians().cos()
            };
            (vec![], vec![r])
        }
        K::Parallel => (vec![], vec![g.sine(dir(c.entity_a), dir(c.entity_b))]),
        K::Perpendicular => (vec![], vec![g.cosine(dir(c.entity_a), dir(c.entity_b))]),
        k => panic!("the checker has no rule for {k}"),
    };
    (l, u)
}

/// Every condition that does not hold, as (what, normalised residual), worst first: each
/// constraint of the solved group and the implicit conditions of its entities (a free
/// normal's unit quaternion, an arc's equal radii).
pub fn violations(sys: &System, v: &Values, size: f64) -> Vec<(String, f64)> {
    let g = Geo {
        sys,
        v,
        tiny: 1e-9 * size,
    };
    let mut out = Vec::new();
    for p in sys.params() {
        let x = g.val(p.h);
        if p.group.0 == GROUP && x.abs() > FAR * size {
            out.push((format!("param {} ran off to {x:e}", p.h.0), x.abs() / size));
        }
    }
    let mut judge = |what: String, lengths: &[f64], unitless: &[f64]| {
        let worst = lengths
            .iter()
            .map(|x| x.abs() / size)
            .chain(unitless.iter().map(|x| x.abs()))
            .fold(
                0.0f64,
                |m, x| if x.is_nan() { f64::INFINITY } else { m.max(x) },
            );
        if worst > TOLERANCE {
            out.push((what, worst));
        }
    };
    for c in sys.constraints() {
        if c.group.0 != GROUP {
            continue;
        }
        let (l, u) = constraint(&g, c);
        judge(format!("{} {}", c.kind, c.h.0), &l, &u);
    }
    for e in sys.entities() {
        if e.group.0 != GROUP {
            continue;
        }
        match &e.kind {
            EntityKind::NormalIn3d { params } => {
                let q = params.map(|p| g.val(p));
                let m = q.iter().map(|c| c * c).sum::<f64>().sqrt();
                judge(format!("unit normal {}", e.h.0), &[], &[m - 1.0]);
            }
            EntityKind::ArcOfCircle {
                center, start, end, ..
            } => {
                let c = g.point(*center);
                let r = norm(sub(g.point(*start), c)) - norm(sub(g.point(*end), c));
                judge(format!("arc radii {}", e.h.0), &[r], &[]);
            }
            _ => {}
        }
    }
    out.sort_by(|a, b| b.1.total_cmp(&a.1));
    out
}
