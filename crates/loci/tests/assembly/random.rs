//! Random assemblies built from a known placement, judged by geometry written out here, not by
//! the solver's own measures.
//!
//! Each case places two to five components at random (the first grounded), then adds random
//! mates and joints made to hold at that placement: a vertex put where another component's
//! face, edge or vertex is, a distance or an angle as measured there, a hinge through a shared
//! point. The free components are moved off it (up to 0.3 in position and 10 degrees in
//! rotation) and the assembly is solved. Then, in this file's own terms:
//! - the solve must succeed (every mate holds, whatever placement it found),
//! - every mate's relation is computed from the reported poses and must hold,
//! - the grounded component must not have moved at all,
//! - the degrees of freedom must equal six per free component less the rank of the
//!   relations' Jacobian, taken by finite differences on the reported poses;
//! - written as a file and read back, the solved assembly must solve where it is.
//!
//! A second pass lengthens one point-to-point distance. Whatever loci answers is checked: a
//! solve by the relations again; a conflict by the named sets, each of which must hold the
//! lengthened distance (every other mate holds at the known placement), must fail when solved
//! alone, and must solve once any one of its mates is taken out.
//!
//! `LOCI_RANDOM_ASSEMBLIES=N` sets how many cases run (default 150, and the pinned ones),
//! `LOCI_RANDOM_FIRST_ASSEMBLY=K` starts them at seed `K` (default 0),
//! `LOCI_RANDOM_ASSEMBLY=K` runs case `K` alone and prints it. Each case is also solved again
//! from far away (see `far_start_check`); `LOCI_RANDOM_FAR_STARTS=0` leaves that out.
//! `LOCI_RANDOM_CONFLICT_STARTS=N` also solves each named conflict alone from `N` starts
//! scattered about the placement (default 0: each failing solve costs up to a second, and a
//! run names a conflict in a third of its cases); a set that holds from one is a false
//! conflict. Ten mates of seed 374, named with too few random starts in loci's own check,
//! held from none of the poses this test tried by default, and from 95 of 100 random starts.

use loci::assembly::{
    Assembly, AssemblyReport, Component, Mate, MateKind as K, Pose, Reference, Selection,
};
use loci::Outcome;

type V = [f64; 3];
type Q = [f64; 4];

/// `SplitMix64`: a small, fixed sequence per seed.
pub(super) struct Rng(pub(super) u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next() >> 11) as f64 / (1u64 << 53) as f64)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn coin(&mut self) -> bool {
        self.next() & 1 == 1
    }

    pub(super) fn point(&mut self, r: f64) -> V {
        [self.range(-r, r), self.range(-r, r), self.range(-r, r)]
    }

    fn unit(&mut self) -> V {
        loop {
            let v = self.point(1.0);
            let n = norm(v);
            if (0.2..=1.0).contains(&n) {
                return scale(v, 1.0 / n);
            }
        }
    }

    /// A unit vector normal to the unit `d`.
    fn normal_to(&mut self, d: V) -> V {
        loop {
            let c = cross(d, self.unit());
            let n = norm(c);
            if n > 0.3 {
                return scale(c, 1.0 / n);
            }
        }
    }

    pub(super) fn rotation(&mut self) -> Q {
        loop {
            let q = [
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            ];
            let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
            if (0.2..=1.0).contains(&n) {
                return q.map(|x| x / n);
            }
        }
    }
}

fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn scale(a: V, s: f64) -> V {
    a.map(|x| x * s)
}
fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn norm(a: V) -> f64 {
    dot(a, a).sqrt()
}

fn qmul(a: Q, b: Q) -> Q {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}
fn conj(q: Q) -> Q {
    [q[0], -q[1], -q[2], -q[3]]
}
fn rotate(q: Q, v: V) -> V {
    let r = qmul(qmul(q, [0.0, v[0], v[1], v[2]]), conj(q));
    [r[1], r[2], r[3]]
}
/// The rotation by `angle` radians about the unit `axis`.
fn turn(axis: V, angle: f64) -> Q {
    let s = (angle / 2.0).sin();
    [(angle / 2.0).cos(), axis[0] * s, axis[1] * s, axis[2] * s]
}

/// A placement: world = `t + q local q*`.
#[derive(Clone, Copy, Debug)]
struct Place {
    t: V,
    q: Q,
}

impl Place {
    fn of(p: &Pose) -> Self {
        Self {
            t: p.translation,
            q: p.rotation,
        }
    }
    fn point(&self, p: V) -> V {
        add(self.t, rotate(self.q, p))
    }
    fn dir(&self, d: V) -> V {
        rotate(self.q, d)
    }
    fn local_point(&self, p: V) -> V {
        rotate(conj(self.q), sub(p, self.t))
    }
    fn local_dir(&self, d: V) -> V {
        rotate(conj(self.q), d)
    }
    /// Moved by a small world translation `dt` and world rotation vector `dw`.
    fn moved(&self, dt: V, dw: V) -> Self {
        let a = norm(dw);
        let q = if a == 0.0 {
            self.q
        } else {
            qmul(turn(scale(dw, 1.0 / a), a), self.q)
        };
        Self {
            t: add(self.t, dt),
            q,
        }
    }
}

/// What a mate asks, in world terms, with its references in their components' frames.
#[derive(Clone, Debug)]
enum Relation {
    /// Two points coincide.
    Points { pa: V, pb: V },
    /// B's point lies in A's plane, `offset` along A's normal.
    InPlane { pa: V, na: V, pb: V, offset: f64 },
    /// B's point lies on A's line, `dist` from it (0: on it).
    OnLine { pa: V, da: V, pb: V, dist: f64 },
    /// Two points `value` apart.
    Distance { pa: V, pb: V, value: f64 },
    /// Two directions parallel (either sense).
    /// A's and B's directions along one line, B's pointing `sense` (1 or -1) times A's.
    Parallel { da: V, db: V, sense: f64 },
    /// Two directions perpendicular.
    Perpendicular { da: V, db: V },
    /// The signed angle from A's direction to B's about A's `axis` is `angle` radians.
    Angle { da: V, db: V, axis: V, angle: f64 },
    /// B's frame at `t`, `q` in A's frame.
    Fastened { t: V, q: Q },
}

/// A mate of the case: the loci mate, its components and what it asks.
#[derive(Clone, Debug)]
struct Case {
    mate: Mate,
    a: usize,
    b: usize,
    relations: Vec<Relation>,
}

/// The residuals of `r` between A at `pa` and B at `pb`.
fn residuals(r: &Relation, pa: &Place, pb: &Place, out: &mut Vec<f64>) {
    match *r {
        Relation::Points { pa: a, pb: b } => out.extend(sub(pa.point(a), pb.point(b))),
        Relation::InPlane {
            pa: a,
            na,
            pb: b,
            offset,
        } => out.push(dot(sub(pb.point(b), pa.point(a)), pa.dir(na)) - offset),
        Relation::OnLine {
            pa: a,
            da,
            pb: b,
            dist,
        } => {
            let c = cross(sub(pb.point(b), pa.point(a)), pa.dir(da));
            if dist == 0.0 {
                out.extend(c);
            } else {
                out.push(norm(c) - dist);
            }
        }
        Relation::Distance {
            pa: a,
            pb: b,
            value,
        } => {
            out.push(norm(sub(pa.point(a), pb.point(b))) - value);
        }
        // The difference, not the cross product: a mate asks for a sense, and the cross
        // product also vanishes with B's direction reversed. Its rank is the cross
        // product's at a solution (the component along the direction is of second order).
        Relation::Parallel { da, db, sense } => {
            out.extend(sub(pa.dir(da), scale(pb.dir(db), sense)));
        }
        Relation::Perpendicular { da, db } => out.push(dot(pa.dir(da), pb.dir(db))),
        Relation::Angle {
            da,
            db,
            axis,
            angle,
        } => {
            let (a, b, n) = (pa.dir(da), pb.dir(db), pa.dir(axis));
            let (ap, bp) = (sub(a, scale(n, dot(a, n))), sub(b, scale(n, dot(b, n))));
            let got = dot(cross(ap, bp), n).atan2(dot(ap, bp));
            let mut e = got - angle;
            while e > std::f64::consts::PI {
                e -= 2.0 * std::f64::consts::PI;
            }
            while e < -std::f64::consts::PI {
                e += 2.0 * std::f64::consts::PI;
            }
            out.push(e);
        }
        Relation::Fastened { t, q } => {
            out.extend(sub(pa.point(t), pb.t));
            // B's axes against A's axes carried by q.
            for e in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
                out.extend(sub(pa.dir(rotate(q, e)), pb.dir(e)));
            }
        }
    }
}

fn all_residuals(cases: &[Case], places: &[Place]) -> Vec<f64> {
    let mut out = Vec::new();
    for c in cases {
        for r in &c.relations {
            residuals(r, &places[c.a], &places[c.b], &mut out);
        }
    }
    out
}

/// The numerical rank of the `rows x cols` matrix `m` (row-major), from its singular values,
/// and whether it is clear-cut: no singular value between `1e-9` and `1e-4` of the largest.
/// Singular values, not elimination's pivots, which can stay well above the smallest of them:
/// seed 25,373 (a planar joint and a vertex on a face among axes nearly in line) has one at
/// 3e-6 of the largest, which complete pivoting kept as a pivot over 1e-5, and loci's own
/// rank test, judging the rows dependent, counts one freedom more.
fn rank(m: Vec<f64>, rows: usize, cols: usize) -> (usize, bool) {
    let a = faer::Mat::from_fn(rows, cols, |i, j| m[i * cols + j]);
    let Ok(sv) = a.singular_values() else {
        return (0, false);
    };
    let big = sv.first().copied().unwrap_or(0.0);
    if big == 0.0 {
        return (0, true);
    }
    let r = sv.iter().filter(|&&s| s > 1e-7 * big).count();
    let clear = !sv.iter().any(|&s| s > 1e-9 * big && s < 1e-4 * big);
    (r, clear)
}

/// Six less the rank of the relations, per free component, by central differences in
/// small world translations and rotations of each free component; and whether the rank
/// is clear-cut.
fn dof(cases: &[Case], places: &[Place], free: &[usize]) -> (usize, bool) {
    let h = 1e-6;
    let base = all_residuals(cases, places);
    let rows = base.len();
    let cols = 6 * free.len();
    let mut jac = vec![0.0; rows * cols];
    for (k, &c) in free.iter().enumerate() {
        for d in 0..6 {
            let mut e = [0.0; 3];
            e[d % 3] = h;
            let (plus, minus) = if d < 3 {
                (
                    places[c].moved(e, [0.0; 3]),
                    places[c].moved(scale(e, -1.0), [0.0; 3]),
                )
            } else {
                (
                    places[c].moved([0.0; 3], e),
                    places[c].moved([0.0; 3], scale(e, -1.0)),
                )
            };
            let mut p = places.to_vec();
            p[c] = plus;
            let fp = all_residuals(cases, &p);
            p[c] = minus;
            let fm = all_residuals(cases, &p);
            for i in 0..rows {
                jac[i * cols + 6 * k + d] = (fp[i] - fm[i]) / (2.0 * h);
            }
        }
    }
    let (r, clear) = rank(jac, rows, cols);
    (cols - r, clear)
}

/// A random mate from A to B holding at `places`; its references are pushed onto `refs`.
fn random_mate(
    rng: &mut Rng,
    k: usize,
    a: usize,
    b: usize,
    places: &[Place],
    refs: &mut [Vec<(String, Reference)>],
) -> Case {
    let (pa, pb) = (places[a], places[b]);
    let (na, nb) = (format!("r{k}a"), format!("r{k}b"));
    let mut put = |c: usize, name: &str, r: Reference| refs[c].push((name.into(), r));
    let on = |c: usize, name: &str| Selection::on(&format!("c{c}"), name);
    // A's reference in the world, then B's made to hold there.
    let wa = rng.point(2.0);
    let (la, wda) = (pa.local_point(wa), rng.unit());
    let lda = pa.local_dir(wda);
    // Two directions in A's plane normal to `wda`.
    let e1 = rng.normal_to(wda);
    let e2 = cross(wda, e1);
    let in_plane = add(
        wa,
        add(
            scale(e1, rng.range(-1.5, 1.5)),
            scale(e2, rng.range(-1.5, 1.5)),
        ),
    );
    let flip = rng.coin();
    let sense = if flip { -1.0 } else { 1.0 };
    let kinds = 19;
    let pick = rng.below(kinds);
    let face = |point: V, normal: V| Reference::Face { point, normal };
    let edge = |point: V, direction: V| Reference::Edge { point, direction };
    let axis = |point: V, direction: V| Reference::Axis { point, direction };
    let vertex = |point: V| Reference::Vertex { point };
    let mate_of = |kind: K| Mate::new(kind, on(a, &na), on(b, &nb)).with_id(&format!("m{k}"));
    let (mate, relations) = match pick {
        // Coincident, point on point (a ball joint is the same three rows).
        0 | 1 => {
            put(a, &na, vertex(la));
            put(b, &nb, vertex(pb.local_point(wa)));
            let kind = if pick == 0 { K::Coincident } else { K::Ball };
            let r = Relation::Points {
                pa: la,
                pb: pb.local_point(wa),
            };
            (mate_of(kind), vec![r])
        }
        // Coincident, B's vertex in A's face.
        2 => {
            put(a, &na, face(la, lda));
            let lb = pb.local_point(in_plane);
            put(b, &nb, vertex(lb));
            let r = Relation::InPlane {
                pa: la,
                na: lda,
                pb: lb,
                offset: 0.0,
            };
            (mate_of(K::Coincident), vec![r])
        }
        // Coincident, B's vertex on A's edge.
        3 => {
            put(a, &na, edge(la, lda));
            let lb = pb.local_point(add(wa, scale(wda, rng.range(-2.0, 2.0))));
            put(b, &nb, vertex(lb));
            let r = Relation::OnLine {
                pa: la,
                da: lda,
                pb: lb,
                dist: 0.0,
            };
            (mate_of(K::Coincident), vec![r])
        }
        // Coincident faces, a planar joint, touch align: coplanar faces.
        4..=6 => {
            put(a, &na, face(la, lda));
            let (kind, s) = match pick {
                4 => (K::Coincident, sense),
                5 => (K::Planar, sense),
                // Touch align: faces opposed, whatever `flip` says.
                _ => (K::TouchAlign, -1.0),
            };
            let (lb, ldb) = (pb.local_point(in_plane), pb.local_dir(scale(wda, s)));
            put(b, &nb, face(lb, ldb));
            let rs = vec![
                Relation::Parallel {
                    da: lda,
                    db: ldb,
                    sense: s,
                },
                Relation::InPlane {
                    pa: la,
                    na: lda,
                    pb: lb,
                    offset: 0.0,
                },
            ];
            (mate_of(kind).flipped(flip && pick != 6), rs)
        }
        // Collinear lines: coincident edges, concentric and cylindrical axes.
        7..=9 => {
            let lb = pb.local_point(add(wa, scale(wda, rng.range(-2.0, 2.0))));
            let ldb = pb.local_dir(scale(wda, sense));
            let (kind, ra, rb) = match pick {
                7 => (K::Coincident, edge(la, lda), edge(lb, ldb)),
                8 => (K::Concentric, axis(la, lda), axis(lb, ldb)),
                _ => (K::Cylindrical, axis(la, lda), axis(lb, ldb)),
            };
            put(a, &na, ra);
            put(b, &nb, rb);
            let rs = vec![
                Relation::Parallel {
                    da: lda,
                    db: ldb,
                    sense,
                },
                Relation::OnLine {
                    pa: la,
                    da: lda,
                    pb: lb,
                    dist: 0.0,
                },
            ];
            (mate_of(kind).flipped(flip), rs)
        }
        // Distance between vertices.
        10 => {
            let wb = add(wa, scale(rng.unit(), rng.range(0.3, 3.0)));
            let lb = pb.local_point(wb);
            put(a, &na, vertex(la));
            put(b, &nb, vertex(lb));
            let value = norm(sub(wb, wa));
            let r = Relation::Distance {
                pa: la,
                pb: lb,
                value,
            };
            (mate_of(K::Distance { value }), vec![r])
        }
        // Signed distance of B's vertex from A's face.
        11 => {
            let offset = rng.range(-2.0, 2.0);
            let lb = pb.local_point(add(in_plane, scale(wda, offset)));
            put(a, &na, face(la, lda));
            put(b, &nb, vertex(lb));
            let r = Relation::InPlane {
                pa: la,
                na: lda,
                pb: lb,
                offset,
            };
            (mate_of(K::Distance { value: offset }), vec![r])
        }
        // Distance of B's vertex from A's edge.
        12 => {
            let dist = rng.range(0.3, 2.0);
            let wb = add(add(wa, scale(wda, rng.range(-2.0, 2.0))), scale(e1, dist));
            let lb = pb.local_point(wb);
            put(a, &na, edge(la, lda));
            put(b, &nb, vertex(lb));
            let r = Relation::OnLine {
                pa: la,
                da: lda,
                pb: lb,
                dist,
            };
            (mate_of(K::Distance { value: dist }), vec![r])
        }
        // Parallel and perpendicular directions, of edges or faces.
        13 | 14 => {
            let wdb = if pick == 13 { scale(wda, sense) } else { e1 };
            let ldb = pb.local_dir(wdb);
            let lb = pb.local_point(rng.point(2.0));
            if rng.coin() {
                put(a, &na, edge(la, lda));
                put(b, &nb, edge(lb, ldb));
            } else {
                put(a, &na, face(la, lda));
                put(b, &nb, face(lb, ldb));
            }
            if pick == 13 {
                let r = Relation::Parallel {
                    da: lda,
                    db: ldb,
                    sense,
                };
                (mate_of(K::Parallel).flipped(flip), vec![r])
            } else {
                let r = Relation::Perpendicular { da: lda, db: ldb };
                (mate_of(K::Perpendicular), vec![r])
            }
        }
        // The angle mate, about the axis normal to both directions (held from the start).
        15 => {
            let degrees: f64 = rng.range(15.0, 165.0);
            let wdb = rotate(turn(e1, degrees.to_radians()), wda);
            let ldb = pb.local_dir(wdb);
            put(a, &na, edge(la, lda));
            put(b, &nb, edge(pb.local_point(rng.point(2.0)), ldb));
            let held = pa.local_dir(e1);
            let mut m = mate_of(K::Angle { degrees });
            m.persistent.axis = Some(held);
            let r = Relation::Angle {
                da: lda,
                db: ldb,
                axis: held,
                angle: degrees.to_radians(),
            };
            (m, vec![r])
        }
        // Revolute: a shared pivot and parallel axes.
        16 => {
            let ldb = pb.local_dir(scale(wda, sense));
            let lb = pb.local_point(wa);
            put(a, &na, axis(la, lda));
            put(b, &nb, axis(lb, ldb));
            let rs = vec![
                Relation::Points { pa: la, pb: lb },
                Relation::Parallel {
                    da: lda,
                    db: ldb,
                    sense,
                },
            ];
            (mate_of(K::Revolute).flipped(flip), rs)
        }
        // Slider: collinear axes, no turn about them from the placement.
        17 => {
            let lb = pb.local_point(add(wa, scale(wda, rng.range(-2.0, 2.0))));
            let ldb = pb.local_dir(wda);
            put(a, &na, axis(la, lda));
            put(b, &nb, axis(lb, ldb));
            let zero = pa.local_dir(e1);
            let mut m = mate_of(K::Slider);
            m.persistent.axis = Some(zero);
            m.persistent.axis_b = Some(pb.local_dir(e1));
            let rs = vec![
                Relation::Parallel {
                    da: lda,
                    db: ldb,
                    sense: 1.0,
                },
                Relation::OnLine {
                    pa: la,
                    da: lda,
                    pb: lb,
                    dist: 0.0,
                },
                Relation::Perpendicular {
                    da: pa.local_dir(e2),
                    db: pb.local_dir(e1),
                },
            ];
            (m, rs)
        }
        // Fastened: B held where the placement has it, relative to A.
        _ => {
            put(a, &na, vertex(la));
            put(b, &nb, vertex(pb.local_point(wa)));
            let t = pa.local_point(pb.t);
            let q = qmul(conj(pa.q), pb.q);
            let mut m = mate_of(K::Fastened);
            m.persistent.relative = Some((t, q));
            (m, vec![Relation::Fastened { t, q }])
        }
    };
    Case {
        mate,
        a,
        b,
        relations,
    }
}

/// A random case: the placement, the components' references and the mates.
struct Built {
    places: Vec<Place>,
    refs: Vec<Vec<(String, Reference)>>,
    cases: Vec<Case>,
    start: Vec<Pose>,
}

fn build(seed: u64) -> Built {
    let mut rng = Rng(seed.wrapping_mul(0x2545_f491_4f6c_dd1d) ^ 0x5eed);
    let n = 2 + rng.below(4);
    let mut places = vec![Place {
        t: [0.0; 3],
        q: [1.0, 0.0, 0.0, 0.0],
    }];
    for _ in 1..n {
        places.push(Place {
            t: rng.point(3.0),
            q: rng.rotation(),
        });
    }
    let mut refs = vec![Vec::new(); n];
    let m = 1 + rng.below(3 * (n - 1));
    let mut cases = Vec::new();
    for k in 0..m {
        let a = rng.below(n);
        let b = (a + 1 + rng.below(n - 1)) % n;
        cases.push(random_mate(&mut rng, k, a, b, &places, &mut refs));
    }
    let start = places
        .iter()
        .enumerate()
        .map(|(c, p)| {
            if c == 0 {
                return Pose::IDENTITY;
            }
            let moved = Place {
                t: add(p.t, rng.point(0.3)),
                q: qmul(turn(rng.unit(), rng.range(0.0, 10.0).to_radians()), p.q),
            };
            Pose::new(moved.t, moved.q)
        })
        .collect();
    Built {
        places,
        refs,
        cases,
        start,
    }
}

fn assembly(b: &Built, cases: &[Case], start: &[Pose]) -> Assembly {
    let mut asm = Assembly::new();
    for (c, refs) in b.refs.iter().enumerate() {
        let mut comp = Component::new(format!("c{c}"), start[c]);
        if c == 0 {
            comp = comp.grounded();
        }
        for (name, r) in refs {
            comp = comp.with(name.clone(), r.clone());
        }
        asm.add_component(comp).unwrap();
    }
    for c in cases {
        asm.add_mate(c.mate.clone()).unwrap();
    }
    asm
}

fn places_of(r: &AssemblyReport) -> Vec<Place> {
    r.components.iter().map(|c| Place::of(&c.pose)).collect()
}

fn largest(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |a, x| a.max(x.abs()))
}

/// How far from the origin a solved part may be. Parts are placed within a few units of it; one
/// sent further holds its angles and parallels only as lines that meet far off look parallel,
/// which is no answer however small the residuals.
const FAR: f64 = 1e4;

/// How far an answer `places` misses `cases`: the largest residual, or infinity when a part
/// ran off beyond [`FAR`].
fn missed_by(cases: &[Case], places: &[Place]) -> f64 {
    if places.iter().any(|p| !(norm(p.t) <= FAR)) {
        return f64::INFINITY;
    }
    largest(&all_residuals(cases, places))
}

/// How many scattered starts ([`scattered`]) a set is solved from before a member is called
/// not needed: a set the two starts above cannot solve may hold far from both. Of 8,000
/// cases, one conflict of a ball, two distances and a coincidence (seed 1185) was called not
/// minimal this way; its ball and two distances alone do hold (a scan of every rotation about
/// the ball's point that keeps the first distance finds the second one's length among them),
/// yet Newton from either start stopped 0.03 off.
const SCATTERED_STARTS: usize = 24;

/// The `k`-th scattered start for leaving out member `i`: every free component at a random
/// rotation, up to a unit from its placement.
fn scattered(b: &Built, seed: u64, i: usize, k: usize) -> Vec<Pose> {
    let mut rng = Rng(seed ^ ((i as u64) << 40) ^ ((k as u64 + 1) << 48) ^ 0x5ca7);
    spread(b, &mut rng, 1.0)
}

/// Every free component at a random rotation, up to `r` along each axis from its placement;
/// the grounded one where it is.
fn spread(b: &Built, rng: &mut Rng, r: f64) -> Vec<Pose> {
    b.places
        .iter()
        .enumerate()
        .map(|(c, p)| {
            if c == 0 {
                Pose::IDENTITY
            } else {
                Pose::new(add(p.t, rng.point(r)), rng.rotation())
            }
        })
        .collect()
}

/// The far-start check of [`run`] (see there), its findings into `wrong`.
fn far_start_check(
    asm: &Assembly,
    b: &Built,
    seed: u64,
    seen: &mut Seen,
    verbose: bool,
    wrong: &mut Vec<String>,
) {
    let mut far = asm.clone();
    for (c, p) in far.components.iter_mut().zip(far_start(b, seed)) {
        c.pose = p;
    }
    if verbose {
        eprintln!("far: {}", serde_json::to_string(&far).unwrap());
    }
    let rf = far.solve().unwrap();
    match rf.outcome {
        Outcome::Inconsistent => wrong.push(format!(
            "seed {seed}: from a far start, a conflict among mates that hold together: {rf}"
        )),
        Outcome::DidNotConverge => {
            seen.far_failed += 1;
            eprintln!("seed {seed}: from a far start, given up on (did_not_converge)");
            // Counted only, but for a case pinned because it gave up there.
            if PINNED.contains(&seed) {
                wrong.push(format!("seed {seed}: from a far start, given up on: {rf}"));
            }
        }
        _ => {
            seen.far_solved += 1;
            let miss = missed_by(&b.cases, &places_of(&rf));
            if miss > 1e-8 {
                wrong.push(format!(
                    "seed {seed}: from a far start, solved, but a relation misses by {miss:e}: {rf}"
                ));
            }
        }
    }
}

/// A start far from the placement: every free component within 3 units of where it belongs,
/// at any rotation.
fn far_start(b: &Built, seed: u64) -> Vec<Pose> {
    spread(b, &mut Rng(seed ^ 0xfa75_7a27), 3.0)
}

/// Whether `cases` solve from `start` with every relation holding.
fn solves(b: &Built, cases: &[Case], start: &[Pose]) -> bool {
    let mut asm = assembly(b, cases, start);
    asm.options.diagnose = false;
    let Ok(r) = asm.solve() else {
        return false;
    };
    r.outcome.is_ok() && missed_by(cases, &places_of(&r)) < 1e-8
}

/// What one case found wrong, if anything; counts what it saw into `seen`.
fn run(seed: u64, seen: &mut Seen, verbose: bool) -> Vec<String> {
    let b = build(seed);
    let mut wrong = Vec::new();
    let free: Vec<usize> = (1..b.places.len()).collect();
    // The placement itself satisfies every relation: the generator's own check.
    let at_answer = largest(&all_residuals(&b.cases, &b.places));
    assert!(
        at_answer < 1e-9,
        "seed {seed}: the placement misses by {at_answer}"
    );
    let mut asm = assembly(&b, &b.cases, &b.start);
    if verbose {
        eprintln!("{}", serde_json::to_string_pretty(&asm).unwrap());
        for m in &asm.mates {
            eprintln!("{}: {:?}", m.id, m.persistent);
        }
    }
    let r = asm.solve().unwrap();
    if verbose {
        eprintln!("{r}");
    }
    seen.cases += 1;
    let got = places_of(&r);
    if r.components[0].pose != Pose::IDENTITY {
        wrong.push(format!("seed {seed}: the grounded component moved: {r}"));
    }
    if !r.outcome.is_ok() {
        seen.failed += 1;
        wrong.push(format!(
            "seed {seed}: satisfiable by construction, but {}: {r}",
            r.outcome.name()
        ));
        return wrong;
    }
    // Written out as a file and read back, the solved assembly solves where it is: what its
    // mates hold from the first solve (an angle's axis, a joint's zero) goes with it.
    let text = serde_json::to_string(&asm).unwrap();
    let mut back: Assembly = serde_json::from_str(&text).unwrap();
    let again = back.solve().unwrap();
    for (c, d) in again.components.iter().zip(&r.components) {
        let moved = norm(sub(c.pose.translation, d.pose.translation))
            + (0..4)
                .map(|i| (c.pose.rotation[i] - d.pose.rotation[i]).abs())
                .sum::<f64>();
        if moved > 1e-9 || !again.outcome.is_ok() {
            wrong.push(format!(
                "seed {seed}: read back, {} moves by {moved:e} ({}): {again}",
                c.name,
                again.outcome.name()
            ));
        }
    }
    // The report agrees with itself: a solve that succeeded has every mate holding.
    for m in &r.mates {
        if !m.status.holds() {
            wrong.push(format!(
                "seed {seed}: {} is {} after a solve that succeeded: {r}",
                m.id,
                m.status.name()
            ));
        }
    }
    let miss = missed_by(&b.cases, &got);
    if miss > 1e-8 {
        wrong.push(format!(
            "seed {seed}: solved, but a relation misses by {miss:e}: {r}"
        ));
    }
    let (want, clear) = dof(&b.cases, &got, &free);
    if clear {
        seen.dof_checked += 1;
        if want != r.dof {
            wrong.push(format!(
                "seed {seed}: dof {} where the relations leave {want}: {r}",
                r.dof
            ));
        }
    }
    if r.outcome == Outcome::RedundantOkay {
        seen.redundant += 1;
    }
    // From far away too (every free part within 3 units of its placement, at any rotation):
    // the solve may give up, but the mates hold together by construction, so it never names a
    // conflict, and a solve that succeeds holds every relation. The solved assembly is moved
    // there, as a user drags its parts: what its mates took from the first solve (a fastened
    // joint's relative pose, an angle's axis) stays, else they would ask for the far start.
    // Seeds 0-999 all solve from there (docs/differential.md).
    if std::env::var("LOCI_RANDOM_FAR_STARTS").map_or(true, |v| v.trim() != "0") {
        far_start_check(&asm, &b, seed, seen, verbose, &mut wrong);
    }
    // Lengthen one distance between vertices, or add one, and judge whatever comes back.
    let mut rng = Rng(seed ^ 0xd157_a4ce);
    let n = b.places.len();
    let k = b.cases.len();
    let (a, bb) = (0, 1 + rng.below(n - 1));
    let (wa, wb) = (rng.point(2.0), rng.point(2.0));
    let (pa, pb) = (b.places[a], b.places[bb]);
    let value = norm(sub(wa, wb)) + 0.5;
    let mut b2 = Built {
        places: b.places.clone(),
        refs: b.refs.clone(),
        cases: b.cases.clone(),
        start: b.start.clone(),
    };
    let (la, lb) = (pa.local_point(wa), pb.local_point(wb));
    b2.refs[a].push((format!("r{k}a"), Reference::Vertex { point: la }));
    b2.refs[bb].push((format!("r{k}b"), Reference::Vertex { point: lb }));
    let longer = Case {
        mate: Mate::new(
            K::Distance { value },
            Selection::on(&format!("c{a}"), &format!("r{k}a")),
            Selection::on(&format!("c{bb}"), &format!("r{k}b")),
        )
        .with_id("longer"),
        a,
        b: bb,
        relations: vec![Relation::Distance {
            pa: la,
            pb: lb,
            value,
        }],
    };
    b2.cases.push(longer);
    let mut asm = assembly(&b2, &b2.cases, &b2.start);
    if verbose {
        eprintln!("{}", serde_json::to_string_pretty(&asm).unwrap());
    }
    let r = asm.solve().unwrap();
    if verbose {
        eprintln!("lengthened: {r}");
    }
    match r.outcome {
        Outcome::Okay | Outcome::RedundantOkay => {
            seen.longer_solved += 1;
            let miss = missed_by(&b2.cases, &places_of(&r));
            if miss > 1e-8 {
                wrong.push(format!(
                    "seed {seed}: lengthened, solved, but a relation misses by {miss:e}: {r}"
                ));
            }
        }
        Outcome::Inconsistent => {
            seen.longer_conflict += 1;
            let conflict_starts = env("LOCI_RANDOM_CONFLICT_STARTS").unwrap_or(0) as usize;
            if r.conflicts.is_empty() {
                wrong.push(format!(
                    "seed {seed}: lengthened: inconsistent, no set named: {r}"
                ));
            }
            for set in &r.conflicts {
                let chosen: Vec<Case> = b2
                    .cases
                    .iter()
                    .filter(|c| set.contains(&c.mate.id))
                    .cloned()
                    .collect();
                if !set.iter().any(|id| id == "longer") {
                    wrong.push(format!(
                        "seed {seed}: conflict {set:?} leaves out the lengthened distance, \
                         and every other mate holds at the placement"
                    ));
                }
                if solves(&b2, &chosen, &b2.start)
                    || solves(&b2, &chosen, &b.start)
                    || (0..conflict_starts)
                        .any(|k| solves(&b2, &chosen, &scattered(&b, seed, usize::MAX, k)))
                {
                    wrong.push(format!("seed {seed}: conflict {set:?} solves alone"));
                }
                // A member is needed when the set holds without it: a solution found from
                // the start, or from the placement (where every mate but the lengthened
                // distance holds), or from scattered poses, shows that.
                let placed: Vec<Pose> = b.places.iter().map(|p| Pose::new(p.t, p.q)).collect();
                for i in 0..chosen.len() {
                    let mut less = chosen.clone();
                    less.remove(i);
                    if !solves(&b2, &less, &b2.start)
                        && !solves(&b2, &less, &placed)
                        && !(0..SCATTERED_STARTS)
                            .any(|k| solves(&b2, &less, &scattered(&b, seed, i, k)))
                    {
                        seen.not_minimal += 1;
                        wrong.push(format!(
                            "seed {seed}: conflict {set:?} without {} does not solve either",
                            chosen[i].mate.id
                        ));
                    }
                }
            }
        }
        Outcome::DidNotConverge => {
            seen.longer_failed += 1;
            eprintln!("seed {seed}: lengthened, given up on (did_not_converge)");
            // Counted only, but for a case pinned because it gave up there.
            if PINNED.contains(&seed) {
                wrong.push(format!("seed {seed}: lengthened, given up on"));
            }
        }
    }
    wrong
}

#[derive(Default, Debug)]
struct Seen {
    cases: usize,
    failed: usize,
    redundant: usize,
    dof_checked: usize,
    longer_solved: usize,
    longer_conflict: usize,
    longer_failed: usize,
    not_minimal: usize,
    far_solved: usize,
    far_failed: usize,
}

/// Cases beyond the default count that the default run checks too: each once named a set
/// of mates impossible that solves when kept alone (the lengthened distance of 1344 with
/// three mates, 1487 with eight, 1554 with seven, 3632 with nine). In the last five the set
/// failed inside the whole assembly and held alone, as an assembly of its own mates; solved
/// again from there, four name a set that fails alone, and 3383 names none (every set it
/// names holds alone; since, it names eight mates found one at a time, as 27766 names four). 7935 named seven mates, six of which could not hold either: the core
/// gave a set it had not shrunk, and the mates were not shrunk in its place. 23796 named five
/// mates whose solve alone ended with a pair of edges the wrong way round (and read `okay`).
/// 27969 read dof 0 where a part still slides: rounding had hidden a dependent row. 28202
/// named a hinge, a distance it cannot reach and a third mate the two fail without. 265, 383
/// and 393 named false conflicts from far away (a floating group, rings of parts), and so did
/// 27527 (a ring closed by a part on two cylindrical joints, left where it was drawn) and
/// 32718 (a loop of two concentric pairs, a hinge and a slider, solved only from starts
/// drawn at random). 38107, lengthened, read `did_not_converge` naming nothing: its equations
/// held only with a direction the wrong way round. 39505 (a loop of three parts) read
/// `did_not_converge` from far away. 42051 and 42616, lengthened, read `did_not_converge`
/// naming nothing: solved with every angle written exactly, a hinge's axes ended opposed.
const PINNED: [u64; 23] = [
    1344, 1487, 1554, 3632, 2547, 3383, 4538, 6293, 7906, 7935, 23796, 27969, 28202, 265, 383, 393,
    27527, 27766, 32718, 38107, 39505, 42051, 42616,
];

/// Runs the cases (or the one `LOCI_RANDOM_ASSEMBLY` names, printed) and fails on any finding.
fn run_all() -> Seen {
    let mut seen = Seen::default();
    if let Some(k) = std::env::var("LOCI_RANDOM_ASSEMBLY")
        .ok()
        .and_then(|v| v.parse().ok())
    {
        let wrong = run(k, &mut seen, true);
        assert!(wrong.is_empty(), "{}", wrong.join("\n"));
        return seen;
    }
    let count = env("LOCI_RANDOM_ASSEMBLIES");
    let first = env("LOCI_RANDOM_FIRST_ASSEMBLY");
    let from = first.unwrap_or(0);
    let mut seeds: Vec<u64> = (from..from + count.unwrap_or(150)).collect();
    if count.is_none() && first.is_none() {
        seeds.extend(PINNED);
    }
    let mut wrong = Vec::new();
    for seed in seeds {
        wrong.extend(run(seed, &mut seen, false));
    }
    eprintln!("random assemblies: {seen:?}");
    assert!(
        wrong.is_empty(),
        "{} findings:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
    // Nearly every case has a rank clear enough to check its degrees of freedom.
    assert!(seen.dof_checked * 10 >= seen.cases * 9, "{seen:?}");
    seen
}

/// Conflicts are also minimal among mates: the core names them minimal among its constraints,
/// and a mate written as several constraints (a fastened joint's point and orientation) could
/// stand in for part of another (seed 83 named a fastened joint, a concentric mate and the
/// lengthened distance, where the fastened joint and the distance conflict alone; 8 of the 52
/// conflicts of seeds 0-149 were not minimal among mates before they were shrunk whole).
#[test]
fn random_assemblies_solve_and_name_minimal_conflicts_that_fail_alone() {
    let seen = run_all();
    // Both outcomes of the lengthened distance occur, and some first solves are redundant.
    if seen.cases >= 100 {
        assert!(
            seen.longer_conflict > 10 && seen.longer_solved > 10,
            "{seen:?}"
        );
        assert!(seen.redundant > 10, "{seen:?}");
    }
}

/// The number an environment variable gives, if any.
fn env(name: &str) -> Option<u64> {
    std::env::var(name).ok()?.trim().parse().ok()
}
