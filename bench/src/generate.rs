//! Seeded generators for the benchmark families.
//!
//! Each generator first builds an exact solution (the "truth"), writes every constraint's
//! value from it, then starts every free point from the truth moved by up to
//! [`PERTURBATION`] along each axis. The same seed always gives the same problem.

use crate::problem::{Arc, Con, Family, Plane, Point, Problem, Variant};

/// How far (per axis, uniformly) free points start from the solution.
pub const PERTURBATION: f64 = 0.3;

/// A small deterministic generator (splitmix64), so problems never depend on a crate's
/// version of a random stream.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }

    /// A fair coin.
    pub fn coin(&mut self) -> bool {
        self.next_u64() & 1 == 1
    }
}

/// The seed of a family at a size. The variant does not enter it: the redundant and
/// inconsistent variants are the solvable problem, same start, plus one constraint.
#[must_use]
pub fn seed_for(family: Family, size: usize) -> u64 {
    let f = Family::ALL.iter().position(|&x| x == family).unwrap_or(0) as u64;
    0x10C1_0000_0000 ^ (f << 40) ^ size as u64
}

/// Generates the problem of `family` and `variant` at `size` (at least 2; the grid, truss
/// and mesh take the side `n` of an `n x n` layout and report `n * n` as their size).
#[must_use]
pub fn generate(family: Family, variant: Variant, size: usize) -> Problem {
    let mut b = Builder::new(seed_for(family, size), family.is_2d());
    let size = size.max(2);
    let extra = match family {
        Family::Chain => chain(&mut b, size),
        Family::Triangles => triangles(&mut b, size),
        Family::Grid => grid(&mut b, size),
        Family::Fillets => fillets(&mut b, size),
        Family::Chain3d => chain_3d(&mut b, size),
        Family::Truss => truss(&mut b, size),
        Family::Mesh => mesh(&mut b, size),
        Family::Profiles => profiles(&mut b, size),
    };
    b.finish(family, variant, size, extra)
}

/// The size recorded for a generated problem of parameter `size` (the grid counts squares).
#[must_use]
pub fn recorded_size(family: Family, size: usize) -> usize {
    if family.takes_side() {
        size.max(2) * size.max(2)
    } else {
        size.max(2)
    }
}

/// An extra constraint implied by the rest: the redundant variant adds it as is, the
/// inconsistent one with its value moved by `bump`.
struct Extra {
    con: Con,
}

struct Builder {
    rng: Rng,
    planar: bool,
    truth: Vec<[f64; 3]>,
    fixed: Vec<bool>,
    lines: Vec<[usize; 2]>,
    arcs: Vec<Arc>,
    planes: Vec<Plane>,
    cons: Vec<Con>,
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    let d = sub(a, b);
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}

/// Unsigned angle between two directions, in degrees.
fn angle_deg(u: [f64; 3], v: [f64; 3]) -> f64 {
    let dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    let cross = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let c = (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]).sqrt();
    c.atan2(dot).to_degrees()
}

impl Builder {
    fn new(seed: u64, planar: bool) -> Self {
        Builder {
            rng: Rng::new(seed),
            planar,
            truth: Vec::new(),
            fixed: Vec::new(),
            lines: Vec::new(),
            arcs: Vec::new(),
            planes: Vec::new(),
            cons: Vec::new(),
        }
    }

    fn point(&mut self, at: [f64; 3], fixed: bool) -> usize {
        self.truth.push(at);
        self.fixed.push(fixed);
        self.truth.len() - 1
    }

    fn line(&mut self, a: usize, b: usize) -> usize {
        self.lines.push([a, b]);
        self.lines.len() - 1
    }

    fn distance(&self, a: usize, b: usize) -> Con {
        Con::Distance {
            a,
            b,
            d: dist(self.truth[a], self.truth[b]),
        }
    }

    /// The angle between two lines as the truth has it, signed in 2D.
    fn angle(&self, l1: usize, l2: usize) -> Con {
        let dir = |l: usize| sub(self.truth[self.lines[l][1]], self.truth[self.lines[l][0]]);
        let (u, v) = (dir(l1), dir(l2));
        let mut deg = angle_deg(u, v);
        if self.planar && u[0] * v[1] - u[1] * v[0] < 0.0 {
            deg = -deg;
        }
        Con::Angle { l1, l2, deg }
    }

    fn finish(mut self, family: Family, variant: Variant, size: usize, extra: Extra) -> Problem {
        match variant {
            Variant::Solvable => {}
            Variant::Redundant => self.cons.push(extra.con),
            Variant::Inconsistent => self.cons.push(match extra.con {
                Con::Distance { a, b, d } => Con::Distance { a, b, d: d + 1.0 },
                Con::Angle { l1, l2, deg } => Con::Angle {
                    l1,
                    l2,
                    deg: deg + 10.0_f64.copysign(deg),
                },
                other => other,
            }),
        }
        let points = self
            .truth
            .iter()
            .zip(&self.fixed)
            .map(|(&t, &fixed)| {
                let mut start = t;
                if !fixed {
                    let dims = if self.planar { 2 } else { 3 };
                    for s in start.iter_mut().take(dims) {
                        *s += self.rng.range(-PERTURBATION, PERTURBATION);
                    }
                }
                Point { start, fixed }
            })
            .collect();
        Problem {
            family,
            variant,
            size: recorded_size(family, size),
            planar: self.planar,
            points,
            lines: self.lines,
            arcs: self.arcs,
            planes: self.planes,
            cons: self.cons,
        }
    }
}

/// `n` segments, each with its own two points.
fn chain(b: &mut Builder, n: usize) -> Extra {
    let mut at = [0.0, 0.0, 0.0];
    let mut heading = b.rng.range(0.0, std::f64::consts::TAU);
    for i in 0..n {
        let len = b.rng.range(5.0, 15.0);
        let p = b.point(at, i == 0);
        at = [
            at[0] + len * heading.cos(),
            at[1] + len * heading.sin(),
            0.0,
        ];
        let q = b.point(at, false);
        let l = b.line(p, q);
        b.cons.push(Con::Distance { a: p, b: q, d: len });
        if i > 0 {
            b.cons.push(Con::Coincident { a: q - 2, b: p });
            b.cons.push(b.angle(l - 1, l));
        }
        let turn = b.rng.range(15f64.to_radians(), 75f64.to_radians());
        heading += if b.rng.coin() { turn } else { -turn };
    }
    // The span from the fixed start to the end of the second segment follows from two
    // lengths and an angle.
    Extra {
        con: b.distance(0, 3),
    }
}

/// `n` triangles of three separate lines each.
fn triangles(b: &mut Builder, n: usize) -> Extra {
    for t in 0..n {
        let o = [30.0 * (t % 100) as f64, 30.0 * (t / 100) as f64, 0.0];
        let base = b.rng.range(8.0, 16.0);
        let apex = [
            o[0] + base * b.rng.range(0.2, 0.8),
            o[1] + b.rng.range(5.0, 12.0),
            0.0,
        ];
        let corners = [o, [o[0] + base, o[1], 0.0], apex];
        let mut lines = [0; 3];
        for k in 0..3 {
            let p = b.point(corners[k], k == 0);
            let q = b.point(corners[(k + 1) % 3], false);
            lines[k] = b.line(p, q);
            b.cons.push(b.distance(p, q));
        }
        for k in 0..3 {
            let end = b.lines[lines[k]][1];
            let next = b.lines[lines[(k + 1) % 3]][0];
            b.cons.push(Con::Coincident { a: end, b: next });
        }
        b.cons.push(Con::Horizontal { l: lines[0] });
    }
    // A rigid triangle's corner angle follows from its sides.
    Extra { con: b.angle(0, 1) }
}

/// An `n x n` grid of squares of side 10 sharing corners.
fn grid(b: &mut Builder, n: usize) -> Extra {
    let side = 10.0;
    let m = n + 1;
    for j in 0..m {
        for i in 0..m {
            b.point([side * i as f64, side * j as f64, 0.0], i == 0 && j == 0);
        }
    }
    let at = |i: usize, j: usize| j * m + i;
    for j in 0..m {
        for i in 0..n {
            let l = b.line(at(i, j), at(i + 1, j));
            b.cons.push(Con::Horizontal { l });
            if j == 0 {
                b.cons.push(b.distance(at(i, j), at(i + 1, j)));
            }
        }
    }
    for i in 0..m {
        for j in 0..n {
            let l = b.line(at(i, j), at(i, j + 1));
            b.cons.push(Con::Vertical { l });
            if i == 0 {
                b.cons.push(b.distance(at(i, j), at(i, j + 1)));
            }
        }
    }
    // The diagonal of a fully constrained grid follows from its rows and columns.
    Extra {
        con: b.distance(at(0, 0), at(n, n)),
    }
}

/// `n` lines, each joined to the next by an arc tangent to both.
fn fillets(b: &mut Builder, n: usize) -> Extra {
    let mut start = [0.0, 0.0, 0.0];
    let mut heading = b.rng.range(0.0, std::f64::consts::TAU);
    let mut prev: Option<(usize, usize, bool)> = None; // (arc, its point joining the next line, whether that is its end)
    for i in 0..n {
        let len = b.rng.range(5.0, 15.0);
        let end = [
            start[0] + len * heading.cos(),
            start[1] + len * heading.sin(),
            0.0,
        ];
        let a = b.point(start, i == 0);
        let e = b.point(end, false);
        let l = b.line(a, e);
        b.cons.push(Con::Distance { a, b: e, d: len });
        if let Some((arc, joint, at_end)) = prev {
            b.cons.push(Con::Coincident { a: joint, b: a });
            b.cons.push(Con::Tangent { arc, at_end, l });
            b.cons.push(b.angle(l - 1, l));
        }
        if i + 1 == n {
            break;
        }
        // A fillet turning left or right by 20..100 degrees.
        let r = b.rng.range(1.0, 3.0);
        let turn = b.rng.range(20f64.to_radians(), 100f64.to_radians());
        let left = b.rng.coin();
        let side = if left { 1.0 } else { -1.0 };
        let normal = [-heading.sin() * side, heading.cos() * side];
        let c = [end[0] + r * normal[0], end[1] + r * normal[1], 0.0];
        let new_heading = heading + side * turn;
        // The far end: the centre minus r times the new line's normal on the same side.
        let far = [
            c[0] + r * new_heading.sin() * side,
            c[1] - r * new_heading.cos() * side,
            0.0,
        ];
        let cp = b.point(c, false);
        let near_p = b.point(end, false);
        let far_p = b.point(far, false);
        // Arcs run counter-clockwise: a left turn starts where the line ends.
        let (s, t) = if left {
            (near_p, far_p)
        } else {
            (far_p, near_p)
        };
        b.arcs.push(Arc {
            center: cp,
            start: s,
            end: t,
        });
        let arc = b.arcs.len() - 1;
        b.cons.push(Con::ArcRadius { arc, r });
        b.cons.push(Con::Coincident { a: e, b: near_p });
        b.cons.push(Con::Tangent {
            arc,
            at_end: !left,
            l,
        });
        prev = Some((arc, far_p, left));
        start = far;
        heading = new_heading;
    }
    // The span from the fixed start to the end of the second line follows from the lengths,
    // the radius and the angle.
    let second_end = b.lines[1.min(b.lines.len() - 1)][1];
    Extra {
        con: b.distance(0, second_end),
    }
}

/// `n` segments in space sharing their end points: lengths, angles between neighbours, and
/// every other point in one of three workplanes; the first point fixed.
fn chain_3d(b: &mut Builder, n: usize) -> Extra {
    for phi in [10.0f64, 70.0, 130.0] {
        // A plane containing the x axis: the xy plane turned about x by phi.
        let h = phi.to_radians() / 2.0;
        b.planes.push(Plane {
            origin: [0.0, 0.0, 0.0],
            quat: [h.cos(), h.sin(), 0.0, 0.0],
        });
    }
    for k in 0..=n {
        // The chain advances along x and wanders within a band around the x axis, which
        // every plane contains, so moving a point onto a plane moves it little.
        let mut p = [
            4.0 * k as f64 + b.rng.range(-1.5, 1.5),
            b.rng.range(-3.0, 3.0),
            b.rng.range(-3.0, 3.0),
        ];
        let plane = (k > 0 && k % 2 == 0).then_some((k / 2) % 3);
        if let Some(j) = plane {
            let nrm = b.planes[j].normal();
            let s = p[0] * nrm[0] + p[1] * nrm[1] + p[2] * nrm[2];
            p = [p[0] - s * nrm[0], p[1] - s * nrm[1], p[2] - s * nrm[2]];
        }
        let pi = b.point(p, k == 0);
        if k == 0 {
            continue;
        }
        let l = b.line(pi - 1, pi);
        b.cons.push(b.distance(pi - 1, pi));
        if let Some(j) = plane {
            b.cons.push(Con::InPlane { p: pi, plane: j });
        }
        if l > 0 {
            let con = b.angle(l - 1, l);
            // Angles near 0 or 180 degrees pin nothing to first order: leave them out.
            if matches!(con, Con::Angle { deg, .. } if (15.0..=165.0).contains(&deg)) {
                b.cons.push(con);
            }
        }
    }
    // With the first point fixed, two lengths and the angle between them fix the span.
    let has_angle = b
        .cons
        .iter()
        .any(|c| matches!(c, Con::Angle { l1: 0, l2: 1, .. }));
    Extra {
        con: if has_angle {
            b.distance(0, 2)
        } else {
            b.distance(0, 1)
        },
    }
}

/// `n x n` points on a square lattice of spacing 10, each moved by up to 2.5 along each axis,
/// the first fixed; `at(i, j)` is the point in column `i`, row `j`.
fn jittered_lattice(b: &mut Builder, n: usize) -> impl Fn(usize, usize) -> usize {
    for j in 0..n {
        for i in 0..n {
            let at = [
                10.0 * i as f64 + b.rng.range(-2.5, 2.5),
                10.0 * j as f64 + b.rng.range(-2.5, 2.5),
                0.0,
            ];
            b.point(at, i == 0 && j == 0);
        }
    }
    move |i, j| j * n + i
}

/// An `n x n` lattice of shared points with a distance on every bar between neighbours, and
/// one diagonal bracing the first cell.
fn truss(b: &mut Builder, n: usize) -> Extra {
    let at = jittered_lattice(b, n);
    for j in 0..n {
        for i in 0..n {
            if i + 1 < n {
                b.line(at(i, j), at(i + 1, j));
                b.cons.push(b.distance(at(i, j), at(i + 1, j)));
            }
            if j + 1 < n {
                b.line(at(i, j), at(i, j + 1));
                b.cons.push(b.distance(at(i, j), at(i, j + 1)));
            }
        }
    }
    b.cons.push(b.distance(at(0, 0), at(1, 1)));
    // The braced first cell is rigid: its other diagonal follows from its sides.
    Extra {
        con: b.distance(at(1, 0), at(0, 1)),
    }
}

/// An `n x n` lattice of points, each cell split into two triangles by a diagonal chosen at
/// random, with a distance on every edge.
fn mesh(b: &mut Builder, n: usize) -> Extra {
    let at = jittered_lattice(b, n);
    let mut first_diagonal = None;
    for j in 0..n {
        for i in 0..n {
            if i + 1 < n {
                b.line(at(i, j), at(i + 1, j));
                b.cons.push(b.distance(at(i, j), at(i + 1, j)));
            }
            if j + 1 < n {
                b.line(at(i, j), at(i, j + 1));
                b.cons.push(b.distance(at(i, j), at(i, j + 1)));
            }
            if i + 1 < n && j + 1 < n {
                let (p, q) = if b.rng.coin() {
                    (at(i, j), at(i + 1, j + 1))
                } else {
                    (at(i + 1, j), at(i, j + 1))
                };
                first_diagonal.get_or_insert((p, q));
                b.line(p, q);
                b.cons.push(b.distance(p, q));
            }
        }
    }
    // The mesh is rigid: the first cell's other diagonal follows from its triangles.
    let other = match first_diagonal {
        Some((0, _)) => (at(1, 0), at(0, 1)),
        _ => (at(0, 0), at(1, 1)),
    };
    Extra {
        con: b.distance(other.0, other.1),
    }
}

/// An `n x n` sketch of four-sided profiles sharing their edges (the cells of a jittered
/// lattice of `(n + 1) x (n + 1)` points), dimensioned as a drafter dimensions a row of
/// bays: along the bottom each edge's length and its angle to the edge before (the first
/// horizontal), up every column each edge's length and its angle to the edge below it (the
/// bottom edge for the first), and the edges across, shared by the profiles above and below
/// them, implied. Every third profile holds a slot.
fn profiles(b: &mut Builder, n: usize) -> Extra {
    let at = jittered_lattice(b, n + 1);
    let m = n + 1;
    // Per point: the lines leaving it rightwards and upwards.
    let mut right = vec![usize::MAX; m * m];
    let mut up = vec![usize::MAX; m * m];
    for j in 0..m {
        for i in 0..m {
            if i + 1 < m {
                right[at(i, j)] = b.line(at(i, j), at(i + 1, j));
            }
            if j + 1 < m {
                up[at(i, j)] = b.line(at(i, j), at(i, j + 1));
            }
        }
    }
    b.cons.push(Con::Horizontal { l: right[at(0, 0)] });
    for i in 0..n {
        b.cons.push(b.distance(at(i, 0), at(i + 1, 0)));
        if i > 0 {
            b.cons.push(b.angle(right[at(i - 1, 0)], right[at(i, 0)]));
        }
    }
    for i in 0..m {
        for j in 0..n {
            let edge = up[at(i, j)];
            b.cons.push(b.distance(at(i, j), at(i, j + 1)));
            let below = if j > 0 {
                up[at(i, j - 1)]
            } else {
                right[at(i.min(n - 1), 0)]
            };
            b.cons.push(b.angle(below, edge));
        }
    }
    for j in 0..n {
        for i in 0..n {
            if (i + 2 * j) % 3 == 0 {
                slot(b, at(i, j), at(i + 1, j), right[at(i, j)]);
            }
        }
    }
    // The first profile's top edge follows from its other sides and angles.
    Extra {
        con: b.distance(at(0, 1), at(1, 1)),
    }
}

/// A slot in the profile whose bottom edge `base` runs from `p` to `q`: two lines of equal
/// length joined at both ends by half circles tangent to both, its left centre placed by its
/// distances from `p` and `q` and its bottom line by its angle to `base`.
fn slot(b: &mut Builder, p: usize, q: usize, base: usize) {
    let o = b.truth[p];
    let theta = b.rng.range(-0.3, 0.3);
    let (len, r) = (b.rng.range(2.5, 3.5), b.rng.range(0.8, 1.2));
    let u = [theta.cos(), theta.sin()];
    let nrm = [-u[1], u[0]];
    let at = |c: [f64; 2], s: f64, v: [f64; 2]| [c[0] + s * v[0], c[1] + s * v[1]];
    let c2 = [
        o[0] + 3.0 + b.rng.range(-0.3, 0.3),
        o[1] + 4.5 + b.rng.range(-0.3, 0.3),
    ];
    let lo = at(c2, -r, nrm); // bottom left
    let lo_r = at(lo, len, u); // bottom right
    let c1 = at(lo_r, r, nrm);
    let hi_r = at(c1, r, nrm); // top right
    let hi = at(c2, r, nrm); // top left
    let pt = |b: &mut Builder, xy: [f64; 2]| b.point([xy[0], xy[1], 0.0], false);
    let (a, e) = (pt(b, lo), pt(b, lo_r));
    let (c, d) = (pt(b, hi_r), pt(b, hi));
    let bottom = b.line(a, e);
    let top = b.line(c, d);
    // The right half circle runs counter-clockwise from the bottom line's end to the top
    // line's start; the left one from the top line's end to the bottom line's start.
    let (rc, rs, re) = (pt(b, c1), pt(b, lo_r), pt(b, hi_r));
    let (lc, ls, le) = (pt(b, c2), pt(b, hi), pt(b, lo));
    b.arcs.push(Arc {
        center: rc,
        start: rs,
        end: re,
    });
    let right_arc = b.arcs.len() - 1;
    b.arcs.push(Arc {
        center: lc,
        start: ls,
        end: le,
    });
    let left_arc = right_arc + 1;
    for (x, y) in [(e, rs), (c, re), (d, ls), (a, le)] {
        b.cons.push(Con::Coincident { a: x, b: y });
    }
    for (arc, at_end, l) in [
        (right_arc, false, bottom),
        (right_arc, true, top),
        (left_arc, false, top),
        (left_arc, true, bottom),
    ] {
        b.cons.push(Con::Tangent { arc, at_end, l });
    }
    b.cons.push(Con::ArcRadius { arc: right_arc, r });
    b.cons.push(Con::ArcRadius { arc: left_arc, r });
    b.cons.push(b.distance(a, e));
    b.cons.push(b.distance(p, lc));
    b.cons.push(b.distance(q, lc));
    b.cons.push(b.angle(base, bottom));
}
