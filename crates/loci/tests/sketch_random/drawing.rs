//! The random sketches: drawn so that every constraint they are given holds as drawn.

use super::common::rng::Rng;
use loci::sketch::{ArcId, Axis, CircleId, End, LineId, PointId, Sketch, SketchConstraintId, Spec};

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
pub(crate) fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
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
pub(crate) fn drawing(seed: u64) -> (Sketch, Vec<SketchConstraintId>, Vec<PointId>) {
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
pub(crate) fn far_off(name: &str, v: f64) -> f64 {
    match name {
        "angle" => v + 40.0,
        "arc_sweep" => (v + 100.0).rem_euclid(360.0).max(10.0),
        "point_line_distance" => v * 1.7 + 1.0,
        _ => v * 1.7 + 0.5,
    }
}
