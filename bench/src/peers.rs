//! Translations of a neutral problem to ezpz (a Rust call) and to PlaneGCS (JSON primitives
//! for the node runner). Both solvers are 2D only.
//!
//! Each uses the solver's own vocabulary where it has one. Where it has none, the
//! translation states the same geometry with what it does have: ezpz has no arc-line
//! tangency at an arc's end, so it receives "the radius to that end is perpendicular to the
//! line", which is what SolveSpace's tangency means too.

use crate::problem::{Con, Problem};
use ezpz::datatypes::inputs::{DatumCircularArc, DatumLineSegment, DatumPoint};
use ezpz::datatypes::{Angle, AngleKind};
use ezpz::{Constraint as Ez, ConstraintRequest, Id};
use serde_json::{json, Value};

/// An ezpz problem: the constraint requests and the initial guess of every variable.
pub struct EzpzProblem {
    /// Constraints, all at the highest priority.
    pub requests: Vec<ConstraintRequest>,
    /// Variable `2i` is point `i`'s x, `2i + 1` its y.
    pub guesses: Vec<(Id, f64)>,
}

fn ez_point(i: usize) -> DatumPoint {
    DatumPoint::new_xy(2 * i as Id, 2 * i as Id + 1)
}

/// Translates a planar problem to ezpz; `None` for a problem in space.
#[must_use]
pub fn to_ezpz(p: &Problem) -> Option<EzpzProblem> {
    if !p.planar {
        return None;
    }
    let line = |l: usize| DatumLineSegment::new(ez_point(p.lines[l][0]), ez_point(p.lines[l][1]));
    let arc = |a: usize| {
        let a = p.arcs[a];
        DatumCircularArc {
            center: ez_point(a.center),
            start: ez_point(a.start),
            end: ez_point(a.end),
        }
    };
    let mut cons = Vec::with_capacity(p.cons.len() + 2);
    for (i, pt) in p.points.iter().enumerate() {
        if pt.fixed {
            cons.push(Ez::Fixed(2 * i as Id, pt.start[0]));
            cons.push(Ez::Fixed(2 * i as Id + 1, pt.start[1]));
        }
    }
    for c in &p.cons {
        cons.push(match *c {
            Con::Coincident { a, b } => Ez::PointsCoincident(ez_point(a), ez_point(b)),
            Con::Distance { a, b, d } => Ez::Distance(ez_point(a), ez_point(b), d),
            Con::Angle { l1, l2, deg } => Ez::LinesAtAngle(
                line(l1),
                line(l2),
                AngleKind::Other(Angle::from_degrees(deg)),
            ),
            Con::Horizontal { l } => Ez::Horizontal(line(l)),
            Con::Vertical { l } => Ez::Vertical(line(l)),
            // Both ends at distance r: the radius and the arc's implicit equal radii.
            Con::ArcRadius { arc: a, r } => Ez::ArcRadius(arc(a), r),
            Con::Tangent { arc: a, at_end, l } => {
                let a = arc(a);
                let on = if at_end { a.end } else { a.start };
                Ez::LinesAtAngle(
                    DatumLineSegment::new(a.center, on),
                    line(l),
                    AngleKind::Perpendicular,
                )
            }
            Con::InPlane { .. } => return None,
        });
    }
    // Arcs without a radius constraint still need their ends equally far from the centre.
    for (ai, _) in p.arcs.iter().enumerate() {
        let has_radius = p
            .cons
            .iter()
            .any(|c| matches!(c, Con::ArcRadius { arc, .. } if *arc == ai));
        if !has_radius {
            cons.push(Ez::Arc(arc(ai)));
        }
    }
    let requests = cons
        .into_iter()
        .map(ConstraintRequest::highest_priority)
        .collect();
    let guesses = p
        .points
        .iter()
        .enumerate()
        .flat_map(|(i, pt)| [(2 * i as Id, pt.start[0]), (2 * i as Id + 1, pt.start[1])])
        .collect();
    Some(EzpzProblem { requests, guesses })
}

/// Translates a planar problem to PlaneGCS sketch primitives (the JSON array its
/// `GcsWrapper.push_primitives_and_params` takes); `None` for a problem in space.
///
/// Point `i` has id `p{i}`; geometry comes before the constraints that use it, as PlaneGCS
/// requires. Fixed points are PlaneGCS fixed points. Arcs carry their own radius and angles
/// (PlaneGCS unknowns) held to their end points by `arc_rules`.
#[must_use]
pub fn to_planegcs(p: &Problem) -> Option<Value> {
    if !p.planar {
        return None;
    }
    let mut prims =
        Vec::with_capacity(p.points.len() + p.lines.len() + 2 * p.arcs.len() + p.cons.len());
    for (i, pt) in p.points.iter().enumerate() {
        prims.push(json!({"id": format!("p{i}"), "type": "point", "x": pt.start[0], "y": pt.start[1], "fixed": pt.fixed}));
    }
    for (i, [a, b]) in p.lines.iter().enumerate() {
        prims.push(json!({"id": format!("l{i}"), "type": "line", "p1_id": format!("p{a}"), "p2_id": format!("p{b}")}));
    }
    for (i, a) in p.arcs.iter().enumerate() {
        let at = |k: usize| p.points[k].start;
        let (c, s, e) = (at(a.center), at(a.start), at(a.end));
        let radius = ((s[0] - c[0]).hypot(s[1] - c[1]) + (e[0] - c[0]).hypot(e[1] - c[1])) / 2.0;
        let a0 = (s[1] - c[1]).atan2(s[0] - c[0]);
        let mut a1 = (e[1] - c[1]).atan2(e[0] - c[0]);
        // PlaneGCS arcs run counter-clockwise from start_angle up to end_angle.
        if a1 < a0 {
            a1 += std::f64::consts::TAU;
        }
        prims.push(
            json!({"id": format!("a{i}"), "type": "arc", "c_id": format!("p{}", a.center),
            "radius": radius, "start_angle": a0, "end_angle": a1,
            "start_id": format!("p{}", a.start), "end_id": format!("p{}", a.end)}),
        );
        prims.push(json!({"id": format!("ar{i}"), "type": "arc_rules", "a_id": format!("a{i}")}));
    }
    for (i, c) in p.cons.iter().enumerate() {
        let id = format!("c{i}");
        let pid = |k: usize| format!("p{k}");
        prims.push(match *c {
            Con::Coincident { a, b } => {
                json!({"id": id, "type": "p2p_coincident", "p1_id": pid(a), "p2_id": pid(b)})
            }
            Con::Distance { a, b, d } => {
                json!({"id": id, "type": "p2p_distance", "p1_id": pid(a), "p2_id": pid(b), "distance": d})
            }
            Con::Angle { l1, l2, deg } => {
                json!({"id": id, "type": "l2l_angle_ll", "l1_id": format!("l{l1}"), "l2_id": format!("l{l2}"), "angle": deg.to_radians()})
            }
            Con::Horizontal { l } => json!({"id": id, "type": "horizontal_l", "l_id": format!("l{l}")}),
            Con::Vertical { l } => json!({"id": id, "type": "vertical_l", "l_id": format!("l{l}")}),
            Con::ArcRadius { arc, r } => {
                json!({"id": id, "type": "arc_radius", "a_id": format!("a{arc}"), "radius": r})
            }
            Con::Tangent { arc, at_end, l } => {
                let a = p.arcs[arc];
                let on = if at_end { a.end } else { a.start };
                let [l1, l2] = p.lines[l];
                json!({"id": id, "type": "perpendicular_pppp", "l1p1_id": pid(a.center), "l1p2_id": pid(on),
                    "l2p1_id": pid(l1), "l2p2_id": pid(l2)})
            }
            Con::InPlane { .. } => return None,
        });
    }
    Some(Value::Array(prims))
}
