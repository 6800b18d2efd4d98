//! Tangent sides: which side of a line a tangent circle or arc lies on, and whether two
//! tangent circles or arcs touch from outside or inside.
//!
//! An arc is tangent at one of its ends, so its side is read there: the sign of the cross
//! product of its radius to that end with the line's direction (which is the side of the
//! line its centre is on, once that end lies on the line), and for two arcs the sign of the
//! dot product of their radii to the touching ends (positive inside, negative outside). A
//! whole circle touches at a hidden point, so its side is its centre's.
//!
//! A tangency constraint is satisfied on either side, so a solve that starts far from its
//! previous configuration can land on the mirror one: the arc jumps across the line, or a
//! circle touching another from outside ends up inside it. A drag reads these sides before
//! and after each piece of a step, as a signed number each, and refuses a piece whose
//! sign changes (see [`super::Drag`]).

use super::{ArcId, CircleId, End, LineId, ShapeId, ShapeKind, Sketch, Spec};
use crate::model::Param;

/// Where a circle's or an arc's centre and radius are in the parameter vector.
#[derive(Clone, Copy, Debug)]
pub(super) enum RoundIx {
    /// A circle: its centre and its radius parameter.
    Circle { center: [usize; 2], radius: usize },
    /// An arc: its centre and its start point (the radius is their distance).
    Arc {
        center: [usize; 2],
        start: [usize; 2],
    },
}

impl RoundIx {
    fn center(self, v: &[Param]) -> [f64; 2] {
        let (Self::Circle { center: [i, j], .. } | Self::Arc { center: [i, j], .. }) = self;
        [v[i].val, v[j].val]
    }

    fn radius(self, v: &[Param]) -> f64 {
        match self {
            Self::Circle { radius, .. } => v[radius].val.abs(),
            Self::Arc { center, start } => {
                (v[start[0]].val - v[center[0]].val).hypot(v[start[1]].val - v[center[1]].val)
            }
        }
    }
}

/// One tangency whose side a drag keeps.
#[derive(Clone, Copy, Debug)]
pub(super) enum Side {
    /// A line's two ends and a circle tangent to it.
    LineCircle {
        line: [[usize; 2]; 2],
        round: RoundIx,
    },
    /// A line's two ends and an arc's centre and the end tangent to it.
    LineArc {
        line: [[usize; 2]; 2],
        arc: [[usize; 2]; 2],
    },
    /// Two arcs' centres and their tangent ends.
    ArcArc {
        a: [[usize; 2]; 2],
        b: [[usize; 2]; 2],
    },
    /// Two tangent circles (or a circle and an arc).
    RoundRound { a: RoundIx, b: RoundIx },
}

impl Side {
    /// A signed number whose sign is the side (see the module's notes); for a circle with
    /// another, positive when they touch from outside (the centres are nearer the sum of
    /// the radii than their difference) and negative when one is inside the other.
    pub(super) fn measure(self, v: &[Param]) -> f64 {
        let xy = |[i, j]: [usize; 2]| [v[i].val, v[j].val];
        let sub = |a: [f64; 2], b: [f64; 2]| [a[0] - b[0], a[1] - b[1]];
        match self {
            Self::LineCircle { line, round } => {
                let ([p, q], c) = (line.map(xy), round.center(v));
                let (d, r) = (sub(q, p), sub(c, p));
                d[0] * r[1] - d[1] * r[0]
            }
            Self::LineArc { line, arc } => {
                let ([p, q], [c, e]) = (line.map(xy), arc.map(xy));
                let (d, r) = (sub(q, p), sub(e, c));
                r[0] * d[1] - r[1] * d[0]
            }
            Self::ArcArc { a, b } => {
                let ([ca, ea], [cb, eb]) = (a.map(xy), b.map(xy));
                let (ra, rb) = (sub(ea, ca), sub(eb, cb));
                ra[0] * rb[0] + ra[1] * rb[1]
            }
            Self::RoundRound { a, b } => {
                let (ca, cb) = (a.center(v), b.center(v));
                let d = (cb[0] - ca[0]).hypot(cb[1] - ca[1]);
                let (ra, rb) = (a.radius(v), b.radius(v));
                (d - (ra - rb).abs()).abs() - (d - (ra + rb)).abs()
            }
        }
    }
}

impl Sketch {
    /// The tangencies between a line and a circle or arc, and between two circles or arcs
    /// (tangencies with a cubic have no side to keep here: its direction check is its own).
    pub(super) fn tangent_sides(&self) -> Vec<Side> {
        let round = |s: ShapeId| -> Option<RoundIx> {
            match self.kind(s)? {
                ShapeKind::Circle => {
                    let center = self.point_indexes(self.circle_center(CircleId(s.0)));
                    Some(RoundIx::Circle {
                        center,
                        radius: self.circle_radius_index(CircleId(s.0)),
                    })
                }
                ShapeKind::Arc => {
                    let [c, st, _] = self.arc_points(ArcId(s.0));
                    Some(RoundIx::Arc {
                        center: self.point_indexes(c),
                        start: self.point_indexes(st),
                    })
                }
                _ => None,
            }
        };
        // An arc's centre and the end of it that is tangent.
        let arc_end = |s: ShapeId, e: End| -> Option<[[usize; 2]; 2]> {
            (self.kind(s)? == ShapeKind::Arc).then(|| {
                let [c, st, en] = self.arc_points(ArcId(s.0));
                let end = if e == End::End { en } else { st };
                [c, end].map(|p| self.point_indexes(p))
            })
        };
        let line = |s: ShapeId| -> Option<[[usize; 2]; 2]> {
            (self.kind(s)? == ShapeKind::Line)
                .then(|| self.line_points(LineId(s.0)).map(|p| self.point_indexes(p)))
        };
        self.constraints()
            .filter_map(|(_, spec)| match spec {
                Spec::Tangent { a, b, a_end, b_end } => Some((*a, *b, *a_end, *b_end)),
                _ => None,
            })
            .filter_map(|(a, b, ea, eb)| {
                let (arc_a, arc_b) = (arc_end(a, ea), arc_end(b, eb));
                match (line(a), line(b), round(a), round(b)) {
                    (Some(line), _, _, Some(_)) | (_, Some(line), Some(_), _)
                        if arc_a.or(arc_b).is_some() =>
                    {
                        let arc = arc_a.or(arc_b)?;
                        Some(Side::LineArc { line, arc })
                    }
                    (Some(line), _, _, Some(round)) | (_, Some(line), Some(round), _) => {
                        Some(Side::LineCircle { line, round })
                    }
                    _ => match (arc_a, arc_b, round(a), round(b)) {
                        (Some(a), Some(b), _, _) => Some(Side::ArcArc { a, b }),
                        (_, _, Some(a), Some(b)) => Some(Side::RoundRound { a, b }),
                        _ => None,
                    },
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two quarter arcs meeting at (0, 1), tangent there, the second about `c2`.
    fn two_arcs(c2: [f64; 2], end2: [f64; 2]) -> Sketch {
        let mut s = Sketch::new();
        let c = s.add_point(0.0, 0.0).unwrap();
        let a0 = s.add_point(1.0, 0.0).unwrap();
        let joint = s.add_point(0.0, 1.0).unwrap();
        let a = s.add_arc(c, a0, joint).unwrap();
        let c2 = s.add_point(c2[0], c2[1]).unwrap();
        let e2 = s.add_point(end2[0], end2[1]).unwrap();
        let b = s.add_arc(c2, joint, e2).unwrap();
        s.tangent(a, End::End, b, End::Start).unwrap();
        s
    }

    #[test]
    fn arcs_touching_from_outside_read_negative_and_from_inside_positive() {
        let v = |s: &Sketch| s.tangent_sides()[0].measure(s.system().params());
        // An S: the second arc's centre beyond the joint.
        let outside = two_arcs([0.0, 2.0], [1.0, 2.0]);
        assert!(matches!(outside.tangent_sides()[..], [Side::ArcArc { .. }]));
        assert!((v(&outside) + 1.0).abs() < 1e-12);
        // A C: the second arc's centre on this side of the joint, half way.
        let inside = two_arcs([0.0, 0.5], [0.5, 0.5]);
        assert!((v(&inside) - 0.5).abs() < 1e-12);
    }

    #[test]
    fn a_line_reads_the_side_its_tangent_circle_is_on() {
        let mut s = Sketch::new();
        let c = s.add_point(0.0, 0.0).unwrap();
        let circle = s.add_circle(c, 1.0).unwrap();
        let p = s.add_point(-1.0, 1.0).unwrap();
        let q = s.add_point(1.0, 1.0).unwrap();
        let line = s.add_line(p, q).unwrap();
        s.tangent(line, End::Start, circle, End::Start).unwrap();
        let sides = s.tangent_sides();
        assert!(matches!(sides[..], [Side::LineCircle { .. }]));
        // The centre is to the right of the line's direction from p to q: negative.
        assert!((sides[0].measure(s.system().params()) + 2.0).abs() < 1e-12);
    }
}
