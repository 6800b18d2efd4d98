//! Random sketches of every kind of user constraint, drawn so that each constraint holds, then
//! moved off and solved. Whatever a solve says is checked here from the coordinates (each
//! constraint's [`Sketch::measure`]), not taken from the solver's word:
//!
//! - a sketch that holds at its drawing solves again from a start moved off it (its
//!   constraints are consistent, however redundant): `okay` or `redundant_okay`, every user
//!   constraint holds, every circle's radius is positive, and every soft constraint reported
//!   kept still has the length, radius or angle it had at the start of the solve; solved
//!   again, nothing moves; a free point dragged ten steps leaves every constraint holding;
//! - then one dimension is changed by a lot. A solve that says `okay` must hold every
//!   constraint at the new value; one that fails leaves the drawing where it was, names some
//!   constraints, and those named fail again on their own (every other user constraint
//!   removed).
//!
//! The sketches: a closed polygon whose sides are horizontal, vertical, parallel or
//! perpendicular to earlier sides or of equal length by construction, some corners joined by a
//! shared point and some by a coincident constraint; circles centred on corners, concentric,
//! of equal radii, through a corner, tangent to a side or to another circle; arcs with a line
//! or another arc tangent at an end; points on sides, at midpoints, mirrored about a side or
//! an axis, at a distance from a side; a line along a side; a cubic with a line tangent at
//! its start; locked and fixed shapes; dimensions (lengths, distances, signed angles, radii,
//! diameters, sweeps) read from the drawing; and reference dimensions of the wrong value, which
//! must not drive.
//!
//! `LOCI_RANDOM_SKETCHES=N` solves N sketches (150 by default, and the [`PINNED`] seeds), from
//! `LOCI_RANDOM_FIRST_SKETCH`; `LOCI_RANDOM_SKETCH_NUDGE=D` moves the free points by up to D
//! (0.05 by default; from further off only wrong answers count, not a solve that gives up);
//! `LOCI_RANDOM_SKETCH_VERBOSE=1` prints each one's constraints and outcomes.

mod common;

use common::rng::Rng;
use loci::sketch::{
    ArcId, Axis, CircleId, End, LineId, PointId, Sketch, SketchConstraintId, SketchReport, Soft,
    Spec,
};
use loci::Outcome;

/// How far a constraint may miss (model units; degrees for angles) once solved.
const HOLDS: f64 = 1e-6;

/// How far a point may move when a sketch that holds is solved again.
const STILL: f64 = 1e-9;

/// How far every free point is moved off the drawing before the first solve.
const NUDGE: f64 = 0.05;

fn add(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] + b[0], a[1] + b[1]]
}
fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}
fn scale(a: [f64; 2], k: f64) -> [f64; 2] {
    [a[0] * k, a[1] * k]
}
fn polar(r: f64, t: f64) -> [f64; 2] {
    [r * t.cos(), r * t.sin()]
}
fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// A sketch being drawn, with every constraint that holds on it by construction.
struct Drawing {
    rng: Rng,
    sketch: Sketch,
    points: Vec<PointId>,
    /// The polygon's sides, and each side's direction in radians.
    sides: Vec<(LineId, f64)>,
    circles: Vec<CircleId>,
    arcs: Vec<ArcId>,
    /// Constraints that hold as drawn, added or not at the end.
    true_of_it: Vec<Spec<loci::sketch::ShapeId>>,
    /// Points the drawing fixes.
    fixed: Vec<PointId>,
}

impl Drawing {
    fn point(&mut self, at: [f64; 2]) -> PointId {
        let p = self.sketch.add_point(at[0], at[1]).expect("a finite point");
        self.points.push(p);
        p
    }

    fn holds(&mut self, spec: Spec<loci::sketch::ShapeId>) {
        self.true_of_it.push(spec);
    }

    /// A closed polygon of 3 to 6 sides from `at`, its sides' directions and lengths drawn
    /// from earlier sides' where a relation is wanted; the last side closes it.
    fn polygon(&mut self, at: [f64; 2]) {
        let n = 3 + self.rng.below(4);
        let mut corners = vec![at];
        let mut dirs: Vec<f64> = Vec::new();
        let mut lengths: Vec<f64> = Vec::new();
        let mut relations: Vec<(usize, u8, usize)> = Vec::new();
        for i in 0..n - 1 {
            // 0 free, 1 horizontal, 2 vertical, 3 parallel, 4 perpendicular to an earlier side.
            let kind = if i == 0 {
                self.rng.below(3)
            } else {
                self.rng.below(5)
            };
            let j = if i == 0 { 0 } else { self.rng.below(i) };
            let flip = if self.rng.chance(0.5) {
                std::f64::consts::PI
            } else {
                0.0
            };
            let t = match kind {
                1 => flip,
                2 => std::f64::consts::FRAC_PI_2 + flip,
                3 => dirs[j] + flip,
                4 => dirs[j] + std::f64::consts::FRAC_PI_2 + flip,
                _ => self.rng.uniform(-3.1, 3.1),
            };
            let len = if i > 0 && self.rng.chance(0.25) {
                relations.push((i, 5, j));
                lengths[j]
            } else {
                self.rng.uniform(2.0, 6.0)
            };
            if kind > 0 {
                relations.push((i, kind as u8, j));
            }
            dirs.push(t);
            lengths.push(len);
            corners.push(add(corners[i], polar(len, t)));
        }
        // The closing side must not be too short for a direction to mean anything.
        if dist(corners[n - 1], corners[0]) < 1.0 {
            corners[n - 1] = add(corners[n - 1], polar(2.0, dirs[n - 2] + 1.0));
            relations.retain(|r| r.0 != n - 2 && r.2 != n - 2);
        }
        let close = sub(corners[0], corners[n - 1]);
        dirs.push(close[1].atan2(close[0]));
        // Each corner a point; where a corner is a coincident pair, the side leaving it starts
        // at a point of its own.
        let first: Vec<PointId> = corners.iter().map(|&c| self.point(c)).collect();
        let mut starts = first.clone();
        for (i, c) in corners.iter().enumerate() {
            if self.rng.chance(0.3) {
                starts[i] = self.point(*c);
                self.holds(Spec::Coincident {
                    a: first[i].into(),
                    b: starts[i].into(),
                });
            }
        }
        let base = self.sides.len();
        for i in 0..n {
            let l = self
                .sketch
                .add_line(starts[i], first[(i + 1) % n])
                .expect("two points");
            self.sides.push((l, dirs[i]));
        }
        for (i, kind, j) in relations {
            let (a, b) = (self.sides[base + j].0.into(), self.sides[base + i].0.into());
            self.holds(match kind {
                1 => Spec::Horizontal { line: b },
                2 => Spec::Vertical { line: b },
                3 => Spec::Parallel { a, b },
                4 => Spec::Perpendicular { a, b },
                _ => Spec::EqualLength { a, b },
            });
        }
        if self.rng.chance(0.6) {
            self.fixed.push(first[0]);
        }
    }

    fn side(&mut self) -> (LineId, f64) {
        self.sides[self.rng.below(self.sides.len())]
    }

    fn corner(&mut self) -> PointId {
        let l = self.side().0;
        self.sketch.line_points(l)[self.rng.below(2)]
    }

    fn circles(&mut self) {
        for _ in 0..self.rng.below(3) {
            let r = self.rng.uniform(0.5, 3.0);
            let c = match self.rng.below(4) {
                0 => {
                    let p = self.corner();
                    self.sketch.add_circle(p, r).expect("a circle")
                }
                1 => {
                    // Through a corner.
                    let p = self.corner();
                    let at = add(self.sketch.point(p), polar(r, self.rng.uniform(-3.1, 3.1)));
                    let center = self.point(at);
                    let c = self.sketch.add_circle(center, r).expect("a circle");
                    self.holds(Spec::PointOnCircle {
                        point: p.into(),
                        shape: c.into(),
                    });
                    c
                }
                2 => {
                    // Tangent to a side, on either side of it.
                    let (l, t) = self.side();
                    let [a, b] = self.sketch.line(l);
                    let along = add(a, scale(sub(b, a), self.rng.uniform(0.0, 1.0)));
                    let normal = t + if self.rng.chance(0.5) { 1.0 } else { -1.0 }
                        * std::f64::consts::FRAC_PI_2;
                    let at = add(along, polar(r, normal));
                    let center = self.point(at);
                    // The exact distance from the line, whatever rounding the normal had.
                    let d = {
                        let u = sub(b, a);
                        let w = sub(at, a);
                        (u[0] * w[1] - u[1] * w[0]).abs() / u[0].hypot(u[1])
                    };
                    let c = self.sketch.add_circle(center, d).expect("a circle");
                    self.holds(Spec::Tangent {
                        a: l.into(),
                        b: c.into(),
                        a_end: End::Start,
                        b_end: End::Start,
                    });
                    c
                }
                _ => {
                    let at = [self.rng.uniform(-8.0, 8.0), self.rng.uniform(-8.0, 8.0)];
                    let center = self.point(at);
                    self.sketch.add_circle(center, r).expect("a circle")
                }
            };
            if let Some(&other) = self.circles.last() {
                if self.rng.chance(0.3) {
                    // Concentric with the last one, with a centre of its own.
                    let at = self.sketch.circle(other).0;
                    let center = self.point(at);
                    let rr = self.rng.uniform(0.5, 3.0);
                    let d = self.sketch.add_circle(center, rr).expect("a circle");
                    self.holds(Spec::Concentric {
                        a: other.into(),
                        b: d.into(),
                    });
                    self.circles.push(d);
                }
                if self.rng.chance(0.3) {
                    // Tangent to the last one, outside or inside it.
                    let (at, ro) = self.sketch.circle(other);
                    let rr = self.rng.uniform(0.3, 0.9) * ro;
                    let d = if self.rng.chance(0.5) {
                        ro + rr
                    } else {
                        ro - rr
                    };
                    let towards = self.rng.uniform(-3.1, 3.1);
                    let center = self.point(add(at, polar(d, towards)));
                    let t = self.sketch.add_circle(center, rr).expect("a circle");
                    self.holds(Spec::Tangent {
                        a: other.into(),
                        b: t.into(),
                        a_end: End::Start,
                        b_end: End::Start,
                    });
                    self.circles.push(t);
                }
                if self.rng.chance(0.3) {
                    let ro = self.sketch.circle(other).1;
                    let at = [self.rng.uniform(-8.0, 8.0), self.rng.uniform(-8.0, 8.0)];
                    let center = self.point(at);
                    let e = self.sketch.add_circle(center, ro).expect("a circle");
                    self.holds(Spec::EqualRadius {
                        a: other.into(),
                        b: e.into(),
                    });
                    self.circles.push(e);
                }
            }
            self.circles.push(c);
        }
    }

    fn arcs(&mut self) {
        for _ in 0..self.rng.below(3) {
            let c = [self.rng.uniform(-8.0, 8.0), self.rng.uniform(-8.0, 8.0)];
            let r = self.rng.uniform(1.0, 3.0);
            let t0 = self.rng.uniform(-3.1, 3.1);
            let sweep = self.rng.uniform(0.4, 5.0);
            let center = self.point(c);
            let start = self.point(add(c, polar(r, t0)));
            let end_at = add(c, polar(r, t0 + sweep));
            let end = self.point(end_at);
            let a = self.sketch.add_arc(center, start, end).expect("an arc");
            self.arcs.push(a);
            if self.rng.chance(0.3) {
                // A second arc leaving this one's end smoothly, curving either way: its centre
                // on the radius through that end.
                let r2 = self.rng.uniform(1.0, 3.0);
                let toward = if self.rng.chance(0.5) { 1.0 } else { -1.0 };
                let c2 = add(end_at, scale(sub(c, end_at), toward * r2 / r));
                let center2 = self.point(c2);
                let t2 = (end_at[1] - c2[1]).atan2(end_at[0] - c2[0]);
                // Counter-clockwise from the shared end when it curves the same way, so that
                // both arcs run on in the same direction there; clockwise from it otherwise.
                let sweep2 = self.rng.uniform(0.4, 2.5);
                let a2 = if toward > 0.0 {
                    let end2 = self.point(add(c2, polar(r2, t2 + sweep2)));
                    self.sketch.add_arc(center2, end, end2).expect("an arc")
                } else {
                    let start2 = self.point(add(c2, polar(r2, t2 - sweep2)));
                    self.sketch.add_arc(center2, start2, end).expect("an arc")
                };
                self.holds(Spec::Tangent {
                    a: a.into(),
                    b: a2.into(),
                    a_end: End::End,
                    b_end: if toward > 0.0 { End::Start } else { End::End },
                });
                self.arcs.push(a2);
            }
            if self.rng.chance(0.3) {
                // A line arriving at the arc's start along its direction there.
                let start_at = add(c, polar(r, t0));
                let len = self.rng.uniform(1.0, 4.0);
                let tail = self.point(add(start_at, polar(len, t0 - std::f64::consts::FRAC_PI_2)));
                let l = self.sketch.add_line(tail, start).expect("a line");
                self.holds(Spec::Tangent {
                    a: a.into(),
                    b: l.into(),
                    a_end: End::Start,
                    b_end: End::Start,
                });
            }
            if self.rng.chance(0.5) {
                // A line leaving the arc's end along its direction there.
                let len = self.rng.uniform(1.0, 4.0);
                let tip = self.point(add(
                    end_at,
                    polar(len, t0 + sweep + std::f64::consts::FRAC_PI_2),
                ));
                let l = self.sketch.add_line(end, tip).expect("a line");
                self.holds(Spec::Tangent {
                    a: l.into(),
                    b: a.into(),
                    a_end: End::Start,
                    b_end: End::End,
                });
            }
        }
    }

    /// A cubic or none, now and then with a line tangent to it at its start.
    fn cubic(&mut self) {
        if !self.rng.chance(0.3) {
            return;
        }
        let mut at = [self.rng.uniform(-8.0, 8.0), self.rng.uniform(-8.0, 8.0)];
        let mut ps = Vec::new();
        for _ in 0..4 {
            ps.push(self.point(at));
            let t = self.rng.uniform(-3.1, 3.1);
            at = add(at, polar(self.rng.uniform(1.0, 3.0), t));
        }
        let c = self
            .sketch
            .add_cubic([ps[0], ps[1], ps[2], ps[3]])
            .expect("a cubic");
        if self.rng.chance(0.6) {
            // Leaving the start backwards along the first control leg.
            let [p0, p1] = [self.sketch.point(ps[0]), self.sketch.point(ps[1])];
            let k = self.rng.uniform(0.5, 1.5);
            let tail = self.point(add(p0, scale(sub(p0, p1), k)));
            let l = self.sketch.add_line(tail, ps[0]).expect("a line");
            self.holds(Spec::Tangent {
                a: l.into(),
                b: c.into(),
                a_end: End::Start,
                b_end: End::Start,
            });
        }
    }

    /// Points on sides, at midpoints, mirrored, at a distance from a side; a line along a side.
    fn points_on_sides(&mut self) {
        for _ in 0..self.rng.below(4) {
            let (l, _) = self.side();
            let [a, b] = self.sketch.line(l);
            match self.rng.below(5) {
                0 => {
                    let t = self.rng.uniform(-0.5, 1.5);
                    let p = self.point(add(a, scale(sub(b, a), t)));
                    self.holds(Spec::PointOnLine {
                        point: p.into(),
                        line: l.into(),
                    });
                }
                1 => {
                    let p = self.point(scale(add(a, b), 0.5));
                    self.holds(Spec::Midpoint {
                        point: p.into(),
                        line: l.into(),
                    });
                }
                2 => {
                    // Mirrored about the side's line.
                    let x = add(a, scale(sub(b, a), self.rng.uniform(-0.5, 1.5)));
                    let u = sub(b, a);
                    let n = scale(
                        [-u[1], u[0]],
                        self.rng.uniform(-1.0, 1.0) / u[0].hypot(u[1]),
                    );
                    let p = self.point(add(x, n));
                    let q = self.point(sub(x, n));
                    self.holds(Spec::Symmetric {
                        a: p.into(),
                        b: q.into(),
                        line: l.into(),
                    });
                }
                3 => {
                    let at = [self.rng.uniform(-8.0, 8.0), self.rng.uniform(-8.0, 8.0)];
                    let (mirror, axis) = if self.rng.chance(0.5) {
                        ([-at[0], at[1]], Axis::Vertical)
                    } else {
                        ([at[0], -at[1]], Axis::Horizontal)
                    };
                    let p = self.point(at);
                    let q = self.point(mirror);
                    self.holds(Spec::SymmetricAxis {
                        a: p.into(),
                        b: q.into(),
                        axis,
                    });
                }
                _ => {
                    // A line along the side's line.
                    let (t, u) = (self.rng.uniform(-1.0, 0.4), self.rng.uniform(0.6, 2.0));
                    let p = self.point(add(a, scale(sub(b, a), t)));
                    let q = self.point(add(a, scale(sub(b, a), u)));
                    let m = self.sketch.add_line(p, q).expect("a line");
                    self.holds(Spec::Collinear {
                        a: l.into(),
                        b: m.into(),
                    });
                }
            }
        }
    }

    /// Dimensions read from the drawing.
    fn dimensions(&mut self) {
        let shapes = |d: &Self| (d.sides.len(), d.circles.len(), d.arcs.len(), d.points.len());
        for _ in 0..2 + self.rng.below(5) {
            let (ns, nc, na, np) = shapes(self);
            let spec = match self.rng.below(7) {
                0 => {
                    let (l, _) = self.side();
                    let [a, b] = self.sketch.line(l);
                    Spec::Length {
                        line: l.into(),
                        value: dist(a, b),
                    }
                }
                1 => {
                    let (a, b) = (
                        self.points[self.rng.below(np)],
                        self.points[self.rng.below(np)],
                    );
                    let d = dist(self.sketch.point(a), self.sketch.point(b));
                    if a == b || d < 0.5 {
                        continue;
                    }
                    Spec::Distance {
                        a: a.into(),
                        b: b.into(),
                        value: d,
                    }
                }
                2 if ns > 1 => {
                    let (a, b) = (self.side().0, self.side().0);
                    if a == b {
                        continue;
                    }
                    let (u, v) = (self.sketch.line(a), self.sketch.line(b));
                    let (du, dv) = (sub(u[1], u[0]), sub(v[1], v[0]));
                    let deg = (du[0] * dv[1] - du[1] * dv[0])
                        .atan2(du[0] * dv[0] + du[1] * dv[1])
                        .to_degrees();
                    // An angle near 0 or 180 is a parallel in disguise; those come as such.
                    if deg.abs() < 5.0 || deg.abs() > 175.0 {
                        continue;
                    }
                    Spec::Angle {
                        a: a.into(),
                        b: b.into(),
                        degrees: deg,
                    }
                }
                3 if nc > 0 => {
                    let c = self.circles[self.rng.below(nc)];
                    let r = self.sketch.circle(c).1;
                    if self.rng.chance(0.5) {
                        Spec::Radius {
                            shape: c.into(),
                            value: r,
                        }
                    } else {
                        Spec::Diameter {
                            shape: c.into(),
                            value: 2.0 * r,
                        }
                    }
                }
                4 if na > 0 => {
                    let a = self.arcs[self.rng.below(na)];
                    let g = self.sketch.arc(a);
                    if self.rng.chance(0.5) {
                        Spec::ArcSweep {
                            arc: a.into(),
                            degrees: g.sweep,
                        }
                    } else {
                        Spec::Radius {
                            shape: a.into(),
                            value: g.radius,
                        }
                    }
                }
                5 => {
                    let (l, _) = self.side();
                    let p = self.points[self.rng.below(np)];
                    let [a, b] = self.sketch.line(l);
                    let x = self.sketch.point(p);
                    let (u, w) = (sub(b, a), sub(x, a));
                    // Positive to the right of the line's direction.
                    let d = -(u[0] * w[1] - u[1] * w[0]) / u[0].hypot(u[1]);
                    if self.sketch.line_points(l).contains(&p) {
                        continue;
                    }
                    Spec::PointLineDistance {
                        point: p.into(),
                        line: l.into(),
                        value: d,
                    }
                }
                _ => continue,
            };
            self.holds(spec);
        }
    }
}

/// A random sketch and the constraints it was given (each holds as drawn).
fn drawing(seed: u64) -> (Sketch, Vec<SketchConstraintId>, Vec<PointId>) {
    let mut d = Drawing {
        rng: Rng(seed ^ 0x5EED_5CE7),
        sketch: Sketch::new(),
        points: Vec::new(),
        sides: Vec::new(),
        circles: Vec::new(),
        arcs: Vec::new(),
        true_of_it: Vec::new(),
        fixed: Vec::new(),
    };
    let at = [d.rng.uniform(-5.0, 5.0), d.rng.uniform(-5.0, 5.0)];
    d.polygon(at);
    if d.rng.chance(0.3) {
        let at = [d.rng.uniform(-5.0, 5.0), d.rng.uniform(-5.0, 5.0)];
        d.polygon(at);
    }
    d.circles();
    d.arcs();
    d.cubic();
    d.points_on_sides();
    d.dimensions();
    // A lock or two (a shape keeps its size as drawn), and now and then a shape fixed whole.
    for _ in 0..d.rng.below(3) {
        let shape: loci::sketch::ShapeId = match d.rng.below(3) {
            0 => d.side().0.into(),
            1 if !d.circles.is_empty() => d.circles[d.rng.below(d.circles.len())].into(),
            2 if !d.arcs.is_empty() => d.arcs[d.rng.below(d.arcs.len())].into(),
            _ => continue,
        };
        if d.rng.chance(0.2) {
            d.holds(Spec::FixShape { shape });
        } else {
            d.holds(Spec::Lock { shape });
        }
    }
    let mut ids = Vec::new();
    let specs = std::mem::take(&mut d.true_of_it);
    // A dimension or two as a reference, its value wrong on purpose: it measures and never
    // drives, so nothing else may notice it.
    for spec in specs.iter().filter(|s| s.value().is_some()) {
        if d.rng.chance(0.2) {
            let mut wrong = spec.clone();
            let v = wrong.value().expect("a dimension");
            wrong.set_value(far_off(spec.name(), v));
            d.sketch.add_reference(wrong).expect("a dimension");
        }
    }
    for spec in specs {
        if d.rng.chance(0.75)
            && !(matches!(spec, Spec::Lock { .. })
                && ids
                    .iter()
                    .any(|&id| d.sketch.constraint(id).is_some_and(|c| *c.0 == spec)))
        {
            ids.push(
                d.sketch
                    .add(spec)
                    .expect("a constraint on shapes of the sketch"),
            );
        }
    }
    for p in d.fixed.clone() {
        ids.push(d.sketch.fix(p).expect("a point"));
    }
    (d.sketch, ids, d.points)
}

/// A value far from `v` that a dimension of kind `name` takes: a length 70% longer, an angle
/// 40 degrees more, a sweep 100 degrees more (within a turn).
fn far_off(name: &str, v: f64) -> f64 {
    match name {
        "angle" => v + 40.0,
        "arc_sweep" => (v + 100.0).rem_euclid(360.0).max(10.0),
        "point_line_distance" => v * 1.7 + 1.0,
        _ => v * 1.7 + 0.5,
    }
}

/// What a soft constraint keeps, read from the drawing.
fn kept_value(s: &Sketch, soft: Soft) -> f64 {
    match soft {
        Soft::LineLength(l) => {
            let [a, b] = s.line(l);
            dist(a, b)
        }
        Soft::ArcRadius(a) => s.arc(a).radius,
        Soft::ArcStart(a) => s.arc(a).start_angle,
        Soft::ArcEnd(a) => s.arc(a).end_angle,
    }
}

fn coordinates(s: &Sketch, points: &[PointId]) -> Vec<[f64; 2]> {
    points.iter().map(|&p| s.point(p)).collect()
}

/// The constraints that miss by more than [`HOLDS`], with their residuals.
fn missing(s: &Sketch, ids: &[SketchConstraintId]) -> Vec<(SketchConstraintId, f64)> {
    ids.iter()
        .map(|&id| {
            (
                id,
                s.measure(id).expect("a constraint of the sketch").residual,
            )
        })
        .filter(|&(_, r)| !(r <= HOLDS))
        .collect()
}

/// Checks one solve against the drawing; the findings, if any.
fn check_solve(
    s: &mut Sketch,
    ids: &[SketchConstraintId],
    points: &[PointId],
    must_hold: bool,
) -> (SketchReport, Vec<String>) {
    let before = coordinates(s, points);
    let soft_before: Vec<(Soft, f64)> = s
        .soft_constraints()
        .into_iter()
        .map(|k| (k, kept_value(s, k)))
        .collect();
    let r = s.solve().expect("the default settings are valid");
    let mut found = Vec::new();
    if r.outcome.is_ok() {
        for (id, res) in missing(s, ids) {
            found.push(format!(
                "said {:?}, but {} {:?} misses by {res:e}",
                r.outcome,
                s.constraint(id).map_or("?", |c| c.0.name()),
                id
            ));
        }
        for (shape, _) in s.shapes().collect::<Vec<_>>() {
            if let Some(c) = s.as_circle(shape) {
                let radius = s.circle(c).1;
                if !(radius > 0.0) {
                    found.push(format!(
                        "said {:?}, with a circle of radius {radius}",
                        r.outcome
                    ));
                }
            }
        }
        for k in &r.kept {
            let Some(&(_, v)) = soft_before.iter().find(|(w, _)| w == k) else {
                found.push(format!("kept {k:?}, which was not a soft constraint"));
                continue;
            };
            let now = kept_value(s, *k);
            let off = match k {
                // Degrees, either way round.
                Soft::ArcStart(_) | Soft::ArcEnd(_) => {
                    ((now - v + 180.0).rem_euclid(360.0) - 180.0).abs()
                }
                _ => (now - v).abs(),
            };
            if !(off <= HOLDS) {
                found.push(format!("kept {k:?}, but it moved by {off:e}"));
            }
        }
    } else {
        if must_hold {
            found.push(format!(
                "a sketch that holds as drawn read {:?} (failed {:?})",
                r.outcome, r.failed
            ));
        }
        // Within rounding: a point fixed where merged coordinates (a horizontal line between
        // two fixed points) agree only to the last bit is put back exactly where it was fixed.
        let moved = coordinates(s, points)
            .iter()
            .zip(&before)
            .map(|(a, b)| dist(*a, *b))
            .fold(0.0, f64::max);
        if !(moved <= STILL) {
            found.push(format!("read {:?} and moved the drawing", r.outcome));
        }
        if r.failed.is_empty() {
            found.push(format!("read {:?} and named nothing", r.outcome));
        }
    }
    (r, found)
}

/// Drags a free point ten steps of up to a tenth of the drawing each way: after every step,
/// every user constraint holds and every circle's radius is positive (a drag keeps a step only
/// when its solve succeeds).
fn dragged(
    s: &mut Sketch,
    ids: &[SketchConstraintId],
    fixed: &[PointId],
    points: &[PointId],
    rng: &mut Rng,
) -> Vec<String> {
    let free: Vec<PointId> = points
        .iter()
        .copied()
        .filter(|p| !fixed.contains(p))
        .collect();
    if free.is_empty() {
        return Vec::new();
    }
    let p = free[rng.below(free.len())];
    let Ok(mut drag) = s.begin_drag(p) else {
        // A point of a locked or fixed shape the test did not see as fixed: nothing to drag.
        return Vec::new();
    };
    let mut found = Vec::new();
    for k in 0..10 {
        let g = drag.grip();
        let target = [g[0] + rng.uniform(-1.0, 1.0), g[1] + rng.uniform(-1.0, 1.0)];
        let step = drag.step(target).expect("a finite target");
        let sk = drag.sketch();
        for (id, r) in missing(sk, ids) {
            found.push(format!(
                "drag step {k} ({:?}): {} {id:?} misses by {r:e}",
                step.outcome,
                sk.constraint(id).map_or("?", |c| c.0.name())
            ));
        }
        for (shape, _) in sk.shapes().collect::<Vec<_>>() {
            if let Some(c) = sk.as_circle(shape) {
                let radius = sk.circle(c).1;
                if !(radius > 0.0) {
                    found.push(format!("drag step {k}: a circle of radius {radius}"));
                }
            }
        }
    }
    found
}

/// Runs one seed; the findings, if any.
fn run(seed: u64, nudge: f64, verbose: bool) -> Vec<String> {
    let (mut s, ids, points) = drawing(seed);
    let mut found: Vec<String> = missing(&s, &ids)
        .into_iter()
        .map(|(id, r)| {
            format!(
                "drawn to hold, but {:?} misses by {r:e} (a fault of this test)",
                s.constraint(id).map(|c| c.0)
            )
        })
        .collect();
    if !found.is_empty() {
        return found;
    }
    // The free points move; fixed ones would go back before the solve starts.
    let fixed: Vec<PointId> = ids
        .iter()
        .flat_map(|&id| match s.constraint(id) {
            Some((Spec::Fix { point }, _)) => s.as_point(*point).into_iter().collect(),
            Some((Spec::FixShape { shape }, _)) => s.defining_points(*shape),
            _ => Vec::new(),
        })
        .collect();
    let mut rng = Rng(seed ^ 0xAB0F_F5E7);
    for &p in &points {
        if !fixed.contains(&p) {
            let [x, y] = s.point(p);
            s.move_point(
                p,
                [
                    x + rng.uniform(-nudge, nudge),
                    y + rng.uniform(-nudge, nudge),
                ],
            )
            .expect("a point of the sketch");
        }
    }
    // From further off than the default, a sketch may fold onto another branch that cannot
    // close, and Newton may say so: only wrong answers count there.
    let (r, f) = check_solve(&mut s, &ids, &points, nudge <= NUDGE);
    let f: Vec<String> = f.into_iter().map(|f| format!("moved off: {f}")).collect();
    if verbose {
        println!(
            "seed {seed}: {} constraints {:?}: {:?}, failed {:?}, {} soft kept, {} dropped",
            ids.len(),
            ids.iter()
                .map(|&id| s.constraint(id).map_or("?", |c| c.0.name()))
                .collect::<Vec<_>>(),
            r.outcome,
            r.failed,
            r.kept.len(),
            r.dropped.len()
        );
    }
    found.extend(f);
    if !r.outcome.is_ok() {
        return found;
    }
    // Solved again where it holds, nothing moves.
    let solved = coordinates(&s, &points);
    let again = s.solve().expect("the default settings are valid");
    let moved = coordinates(&s, &points)
        .iter()
        .zip(&solved)
        .map(|(a, b)| dist(*a, *b))
        .fold(0.0, f64::max);
    if !again.outcome.is_ok() || !(moved <= STILL) {
        found.push(format!(
            "solved again where it holds: {:?}, a point moved by {moved:e}",
            again.outcome
        ));
    }
    found.extend(dragged(&mut s, &ids, &fixed, &points, &mut rng));
    // One dimension changed by a lot.
    let dims: Vec<SketchConstraintId> = ids
        .iter()
        .copied()
        .filter(|&id| s.constraint(id).is_some_and(|c| c.0.value().is_some()))
        .collect();
    if dims.is_empty() {
        return found;
    }
    let id = dims[rng.below(dims.len())];
    let v = s
        .constraint(id)
        .and_then(|c| c.0.value())
        .expect("a dimension");
    let changed = far_off(s.constraint(id).map_or("?", |c| c.0.name()), v);
    s.set_value(id, changed).expect("a dimension takes a value");
    let (r, f) = check_solve(&mut s, &ids, &points, false);
    let f: Vec<String> = f
        .into_iter()
        .map(|f| format!("{id:?} changed to {changed}: {f}"))
        .collect();
    if verbose {
        println!(
            "  {id:?} to {changed}: {:?}, failed {:?}",
            r.outcome, r.failed
        );
    }
    found.extend(f);
    if !r.outcome.is_ok() && !r.failed.is_empty() {
        // The named constraints fail on their own.
        let mut alone = s.clone();
        for &other in &ids {
            if !r.failed.contains(&other) {
                alone
                    .remove_constraint(other)
                    .expect("a constraint of the sketch");
            }
        }
        let again = alone.solve().expect("the default settings are valid");
        if again.outcome.is_ok() && r.outcome == Outcome::Inconsistent {
            found.push(format!(
                "named {:?} as inconsistent, but they hold on their own",
                r.failed
            ));
        }
    }
    found
}

/// Seeds that found a wrong answer, run besides the range asked for: 742, a fixed point held
/// where a solve from a solution built another way had moved it (`okay`, the point off its
/// place); 1,274, a circle whose radius went negative in the first solve; 105, a dimension
/// changed and a circle's radius taken through zero (`okay`, the circle drawn at a negative
/// radius); 1,169, a circle's radius taken through zero by a drag step; 8,300, a satisfiable
/// set named in a conflict, its solution past a fold that the first scattered starts missed.
const PINNED: [u64; 5] = [742, 1274, 105, 1169, 8300];

#[test]
fn random_sketches_solve_back_and_their_verdicts_hold() {
    let count: u64 = std::env::var("LOCI_RANDOM_SKETCHES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(150);
    let first: u64 = std::env::var("LOCI_RANDOM_FIRST_SKETCH")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0);
    let verbose = std::env::var("LOCI_RANDOM_SKETCH_VERBOSE").is_ok_and(|v| v == "1");
    let nudge: f64 = std::env::var("LOCI_RANDOM_SKETCH_NUDGE")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(NUDGE);
    let mut failures = Vec::new();
    for seed in (first..first + count).chain(PINNED) {
        for f in run(seed, nudge, verbose) {
            failures.push(format!("seed {seed}: {f}"));
        }
    }
    for f in &failures {
        println!("{f}");
    }
    println!(
        "{} sketches, {} findings",
        count as usize + PINNED.len(),
        failures.len()
    );
    assert!(failures.is_empty(), "{} findings", failures.len());
}
