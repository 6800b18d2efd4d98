//! Test systems: two tilted workplanes, builders for points, lines, curves and normals, and
//! helpers that compile one constraint (or one entity's implicit condition) the way the solver
//! does and evaluate it at any parameter values.

use super::super::compile::{compile_group, resolve_constraint};
use super::super::refs::{Geo, Resolver};
use super::super::{EqKind, Equation, Owner, Rows};
use crate::geom::{Quat, SplitMix, Vec3};
use crate::model::{
    Constraint, ConstraintKind, Entity, EntityId, EntityKind, GroupId, Param, ParamId, System,
};

/// Group of the geometry a test holds still (workplanes, references).
pub(super) const FIXED: u32 = 1;
/// Group of the geometry a test moves and solves.
pub(super) const MOVING: u32 = 2;

/// How a case places its geometry.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(super) enum Form {
    /// 2D: points of the workplane, constraint in the workplane.
    Plane,
    /// 3D: points in space, constraint free in space.
    Free,
    /// Constraint in the workplane on points that are not its own: 3D points off the plane and
    /// 2D points of the second workplane, taking turns.
    Mixed,
}

/// How a case breaks its satisfied configuration.
#[derive(Clone, Debug)]
pub(super) enum Break {
    /// New parameter values (handle, value).
    Set(Vec<(u32, f64)>),
    /// A new dimension.
    Val(f64),
    /// New `other` and `other2` flags.
    Flags(bool, bool),
}

/// What the broken configuration's residuals must be, row by row.
#[derive(Clone, Debug)]
pub(super) enum Expect {
    Rows(Vec<f64>),
}

/// What a case checks: a constraint, or an entity with an implicit condition.
#[derive(Clone, Debug)]
pub(super) enum Target {
    Constraint(Constraint),
    Entity(u32),
}

/// A satisfied configuration (already in the system), with a way to break it.
pub(super) struct Built {
    pub target: Target,
    pub brk: Break,
    pub expect: Expect,
}

impl Built {
    pub fn new(c: Constraint, brk: Break, expect: Expect) -> Self {
        Self {
            target: Target::Constraint(c),
            brk,
            expect,
        }
    }
}

/// One row of a family's table: a kind (or implicit condition), the forms it is built in, and
/// a builder that makes a satisfied configuration in a fresh fixture.
pub(super) struct Case {
    pub name: &'static str,
    /// `None` for an implicit condition.
    pub kind: Option<ConstraintKind>,
    pub forms: &'static [Form],
    pub build: fn(&mut Fx, Form) -> Built,
}

/// Rotation by `angle` radians about `axis`, as a quaternion (w, x, y, z).
pub(super) fn axis_angle(axis: [f64; 3], angle: f64) -> [f64; 4] {
    let n = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let s = (angle / 2.0).sin() / n;
    [(angle / 2.0).cos(), axis[0] * s, axis[1] * s, axis[2] * s]
}

pub(super) fn v3(a: [f64; 3]) -> Vec3<f64> {
    Vec3::new(a[0], a[1], a[2])
}

pub(super) fn arr(v: Vec3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// A deterministic generator ([`SplitMix`]), so every run checks the same points.
pub(super) struct Rng(SplitMix);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(SplitMix(seed))
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0.next_u64()
    }

    /// Uniform in `[lo, hi)`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
    }

    /// Magnitude in `[lo, hi)` with a random sign.
    pub fn signed(&mut self, lo: f64, hi: f64) -> f64 {
        let m = self.range(lo, hi);
        if self.next_u64() & 1 == 0 {
            m
        } else {
            -m
        }
    }
}

/// A system under construction, with two workplanes in [`FIXED`]: `wp` (tilted and offset, so
/// that projection mistakes show) and `wp2` (oriented differently, for mixed inputs).
pub(super) struct Fx {
    pub sys: System,
    next_param: u32,
    next_entity: u32,
    next_constraint: u32,
    mixed_turn: bool,
    pub wp: u32,
    pub wp2: u32,
}

impl Fx {
    pub fn new() -> Self {
        let mut fx = Self {
            sys: System::new(),
            next_param: 1,
            next_entity: 1,
            next_constraint: 1,
            mixed_turn: false,
            wp: 0,
            wp2: 0,
        };
        fx.wp = fx.workplane(FIXED, [1.0, -2.0, 0.5], axis_angle([1.0, 2.0, 3.0], 0.7));
        fx.wp2 = fx.workplane(FIXED, [0.5, 1.0, -1.0], axis_angle([-2.0, 1.0, 0.5], 1.1));
        fx
    }

    pub fn param(&mut self, g: u32, v: f64) -> u32 {
        let h = self.next_param;
        self.next_param += 1;
        self.sys
            .add_param(Param::new(h, g, v))
            .expect("fresh param");
        h
    }

    fn add(&mut self, make: impl FnOnce(u32) -> Entity) -> u32 {
        let h = self.next_entity;
        self.next_entity += 1;
        self.sys.add_entity(make(h)).expect("fresh entity");
        h
    }

    pub fn p3(&mut self, g: u32, p: [f64; 3]) -> u32 {
        let ps = p.map(|v| self.param(g, v));
        self.add(|h| Entity::point_3d(h, g, ps))
    }

    pub fn p2(&mut self, g: u32, wp: u32, uv: [f64; 2]) -> u32 {
        let ps = uv.map(|v| self.param(g, v));
        self.add(|h| Entity::point_2d(h, g, wp, ps))
    }

    pub fn normal3(&mut self, g: u32, q: [f64; 4]) -> u32 {
        let ps = q.map(|v| self.param(g, v));
        self.add(|h| Entity::normal_3d(h, g, ps))
    }

    /// A rigid motion in group `g`: a translation vector's parameters and a normal holding
    /// the rotation `q`.
    pub fn motion(&mut self, g: u32, t: [f64; 3], q: [f64; 4]) -> ([u32; 3], u32) {
        let t = t.map(|v| self.param(g, v));
        (t, self.normal3(g, q))
    }

    /// A `point_n_rot_trans` in group `g` with base `base`, moved by `translation` and the
    /// normal `rotation`, its own coordinates at `at`.
    pub fn moved_point(
        &mut self,
        g: u32,
        at: [f64; 3],
        base: [f64; 3],
        translation: [u32; 3],
        rotation: u32,
    ) -> u32 {
        let ps = at.map(|v| self.param(g, v));
        self.add(|h| Entity::point_n_rot_trans(h, g, ps, base, translation, rotation))
    }

    /// A `normal_n_rot` in group `g` with base `base`, turned by the normal `rotation`, its own
    /// quaternion at `at`.
    pub fn rotated_normal(&mut self, g: u32, at: [f64; 4], base: [f64; 4], rotation: u32) -> u32 {
        let ps = at.map(|v| self.param(g, v));
        self.add(|h| Entity::normal_n_rot(h, g, ps, base, rotation))
    }

    pub fn normal2(&mut self, wp: u32) -> u32 {
        self.add(|h| Entity::normal_2d(h, FIXED, wp))
    }

    pub fn workplane(&mut self, g: u32, origin: [f64; 3], q: [f64; 4]) -> u32 {
        let o = self.p3(g, origin);
        let n = self.normal3(g, q);
        self.add(|h| Entity::workplane(h, g, o, n))
    }

    /// A point at `c`: in the workplane at (c0, c1) for [`Form::Plane`], in space at `c` for
    /// [`Form::Free`], and for [`Form::Mixed`] alternately a 3D point at height c2 over the
    /// workplane or a point of `wp2`, both projecting to (c0, c1).
    pub fn pt(&mut self, g: u32, form: Form, c: [f64; 3]) -> u32 {
        match form {
            Form::Plane => self.p2(g, self.wp, [c[0], c[1]]),
            Form::Free => self.p3(g, c),
            Form::Mixed => {
                self.mixed_turn = !self.mixed_turn;
                if self.mixed_turn {
                    self.lift(g, c)
                } else {
                    self.p2_over(g, [c[0], c[1]])
                }
            }
        }
    }

    /// A 3D point at (u, v) of the workplane and height `c[2]` along its normal.
    pub fn lift(&mut self, g: u32, c: [f64; 3]) -> u32 {
        let p = self.over_to_world(c);
        self.p3(g, p)
    }

    /// A point of `wp2` whose projection into the workplane is `uv`.
    pub fn p2_over(&mut self, g: u32, uv: [f64; 2]) -> u32 {
        let st = self.wp2_coords_over(uv);
        self.p2(g, self.wp2, st)
    }

    pub fn line(&mut self, g: u32, form: Form, a: [f64; 3], b: [f64; 3]) -> u32 {
        let (pa, pb) = (self.pt(g, form, a), self.pt(g, form, b));
        let wp = (form == Form::Plane).then_some(self.wp);
        self.add(|h| Entity::line(h, g, wp, pa, pb))
    }

    pub fn cubic(&mut self, g: u32, form: Form, p: [[f64; 3]; 4]) -> u32 {
        let ps = p.map(|c| self.pt(g, form, c));
        let wp = (form == Form::Plane).then_some(self.wp);
        self.add(|h| Entity::cubic(h, g, wp, ps))
    }

    /// An arc of workplane `wp`; the centre is fixed, start and end are in group `g`.
    pub fn arc(&mut self, g: u32, wp: u32, c: [f64; 2], start: [f64; 2], end: [f64; 2]) -> u32 {
        let n = self.normal2(wp);
        let pc = self.p2(FIXED, wp, c);
        let (ps, pe) = (self.p2(g, wp, start), self.p2(g, wp, end));
        self.add(|h| Entity::arc(h, g, wp, n, pc, ps, pe))
    }

    /// An arc of `wp` centred at `c` with radius `r` from `from` to `to` degrees (counter-clockwise).
    pub fn arc_deg(&mut self, g: u32, wp: u32, c: [f64; 2], r: f64, from: f64, to: f64) -> u32 {
        let at = |deg: f64| {
            let t = deg.to_radians();
            [c[0] + r * t.cos(), c[1] + r * t.sin()]
        };
        self.arc(g, wp, c, at(from), at(to))
    }

    /// A circle of radius `r` (in group `g`) centred at `c` (fixed): in the workplane for
    /// [`Form::Plane`], otherwise in space with a fixed 3D normal `q`.
    pub fn circle(&mut self, g: u32, form: Form, c: [f64; 3], q: [f64; 4], r: f64) -> u32 {
        let center = self.pt(FIXED, form, c);
        let normal = match form {
            Form::Plane => self.normal2(self.wp),
            _ => self.normal3(FIXED, q),
        };
        let rp = self.param(g, r);
        let wp = (form == Form::Plane).then_some(self.wp);
        let dist = self.add(|h| Entity::distance(h, g, wp, rp));
        self.add(|h| Entity::circle(h, g, wp, center, normal, dist))
    }

    /// A constraint of `kind` in group [`MOVING`], in the workplane unless `form` is free.
    pub fn con(&mut self, kind: ConstraintKind, form: Form) -> Constraint {
        let h = self.next_constraint;
        self.next_constraint += 1;
        let wp = (form != Form::Free).then_some(self.wp);
        Constraint::new(h, MOVING, kind).in_workplane(wp)
    }

    pub fn entity(&self, h: u32) -> &Entity {
        self.sys.entity(EntityId(h)).expect("entity exists")
    }

    /// The parameters of entity `h`.
    pub fn params(&self, h: u32) -> Vec<u32> {
        self.entity(h).kind.params().iter().map(|p| p.0).collect()
    }

    pub fn value(&self, p: u32) -> f64 {
        self.sys.value(ParamId(p)).expect("param exists")
    }

    /// Point `i` of a line, cubic or arc (arcs: centre, start, end).
    pub fn point_of(&self, h: u32, i: usize) -> u32 {
        match &self.entity(h).kind {
            EntityKind::LineSegment { points } => points[i].0,
            EntityKind::Cubic { points } => points[i].0,
            EntityKind::ArcOfCircle {
                center, start, end, ..
            } => [*center, *start, *end][i].0,
            k => panic!("no points in {k:?}"),
        }
    }

    /// The radius parameter of a circle.
    pub fn radius_param(&self, h: u32) -> u32 {
        match &self.entity(h).kind {
            EntityKind::Circle { radius, .. } => self.params(radius.0)[0],
            k => panic!("not a circle: {k:?}"),
        }
    }

    /// Origin, U, V and N of workplane `wp`, from the current values.
    pub fn frame(&self, wp: u32) -> [Vec3<f64>; 4] {
        let EntityKind::Workplane { origin, normal } = self.entity(wp).kind else {
            panic!("not a workplane")
        };
        let o = self
            .params(origin.0)
            .iter()
            .map(|&p| self.value(p))
            .collect::<Vec<_>>();
        let q = self
            .params(normal.0)
            .iter()
            .map(|&p| self.value(p))
            .collect::<Vec<_>>();
        let q = Quat {
            w: q[0],
            x: q[1],
            y: q[2],
            z: q[3],
        };
        [Vec3::new(o[0], o[1], o[2]), q.u(), q.v(), q.n()]
    }

    /// (u, v, height) over the workplane to a position in space.
    pub fn over_to_world(&self, c: [f64; 3]) -> [f64; 3] {
        let [o, u, v, n] = self.frame(self.wp);
        arr(o
            .plus(u.scale(c[0]))
            .plus(v.scale(c[1]))
            .plus(n.scale(c[2])))
    }

    /// A position in space to (u, v, height) over the workplane.
    pub fn world_to_over(&self, p: [f64; 3]) -> [f64; 3] {
        let [o, u, v, n] = self.frame(self.wp);
        let d = v3(p).minus(o);
        [d.dot(u), d.dot(v), d.dot(n)]
    }

    /// The height over the workplane of the point of `wp2` that projects to `uv`.
    pub fn wp2_height_over(&self, uv: [f64; 2]) -> f64 {
        let st = self.wp2_coords_over(uv);
        let [o2, u2, v2, _] = self.frame(self.wp2);
        self.world_to_over(arr(o2.plus(u2.scale(st[0])).plus(v2.scale(st[1]))))[2]
    }

    /// The normal entity of workplane `wp`.
    pub fn normal_of(&self, wp: u32) -> u32 {
        match self.entity(wp).kind {
            EntityKind::Workplane { normal, .. } => normal.0,
            ref k => panic!("not a workplane: {k:?}"),
        }
    }

    /// A line between existing points `a` and `b` (in the workplane for [`Form::Plane`]).
    pub fn line_of(&mut self, g: u32, form: Form, a: u32, b: u32) -> u32 {
        let wp = (form == Form::Plane).then_some(self.wp);
        self.add(|h| Entity::line(h, g, wp, a, b))
    }

    /// Coordinates (s, t) in `wp2` of the point that projects to `uv` in the workplane.
    fn wp2_coords_over(&self, uv: [f64; 2]) -> [f64; 2] {
        let [o, u, v, _] = self.frame(self.wp);
        let [o2, u2, v2, _] = self.frame(self.wp2);
        // (o2 + s U2 + t V2 - o) . (U, V) = uv: two equations in s, t.
        let (a, b, c, d) = (u2.dot(u), v2.dot(u), u2.dot(v), v2.dot(v));
        let (r0, r1) = (uv[0] - o2.minus(o).dot(u), uv[1] - o2.minus(o).dot(v));
        let det = a * d - b * c;
        assert!(det.abs() > 0.1, "wp2 must not be edge-on to wp");
        [(r0 * d - b * r1) / det, (a * r1 - c * r0) / det]
    }

    /// The position of point `h` in space.
    pub fn world(&self, h: u32) -> [f64; 3] {
        let e = self.entity(h);
        let vals: Vec<f64> = self.params(h).iter().map(|&p| self.value(p)).collect();
        match e.kind {
            EntityKind::PointIn3d { .. } => [vals[0], vals[1], vals[2]],
            EntityKind::PointIn2d { .. } => {
                let [o, u, v, _] = self.frame(e.workplane.expect("2D point").0);
                arr(o.plus(u.scale(vals[0])).plus(v.scale(vals[1])))
            }
            ref k => panic!("not a point: {k:?}"),
        }
    }

    /// The coordinates a case of `form` uses for point `h` (see [`Fx::pt`]).
    pub fn coords(&self, form: Form, h: u32) -> [f64; 3] {
        match form {
            Form::Free => self.world(h),
            Form::Plane | Form::Mixed => self.world_to_over(self.world(h)),
        }
    }

    /// Parameter values that put point `h` at `c` (form coordinates; the height of a point of
    /// a workplane cannot change and is ignored).
    pub fn place(&self, form: Form, h: u32, c: [f64; 3]) -> Vec<(u32, f64)> {
        let e = self.entity(h);
        let ps = self.params(h);
        let vals: Vec<f64> = match (&e.kind, form) {
            (EntityKind::PointIn3d { .. }, Form::Free) => c.to_vec(),
            (EntityKind::PointIn3d { .. }, _) => self.over_to_world(c).to_vec(),
            (EntityKind::PointIn2d { .. }, _) if e.workplane == Some(EntityId(self.wp)) => {
                vec![c[0], c[1]]
            }
            (EntityKind::PointIn2d { .. }, _) if e.workplane == Some(EntityId(self.wp2)) => {
                self.wp2_coords_over([c[0], c[1]]).to_vec()
            }
            (k, _) => panic!("cannot place {k:?}"),
        };
        ps.into_iter().zip(vals).collect()
    }

    /// Parameter values that move point `h` by `d` (form coordinates).
    pub fn shift(&self, form: Form, h: u32, d: [f64; 3]) -> Vec<(u32, f64)> {
        let c = self.coords(form, h);
        self.place(form, h, [c[0] + d[0], c[1] + d[1], c[2] + d[2]])
    }

    pub fn set(&mut self, values: &[(u32, f64)]) {
        for &(p, v) in values {
            assert!(self.sys.set_value(ParamId(p), v), "param {p} exists");
        }
    }
}

/// An equation compiled like the solver compiles it, with the parameters it reads.
pub(super) struct One {
    pub eq: Equation,
    /// Positions in [`System::params`] of the equation's local slots.
    pub locals: Vec<u32>,
}

impl One {
    /// The local slot values from the system's current values.
    pub fn x(&self, sys: &System) -> Vec<f64> {
        let ps = sys.params();
        self.locals.iter().map(|&i| ps[i as usize].val).collect()
    }

    pub fn residuals(&self, x: &[f64]) -> Vec<f64> {
        let mut r = Rows::new();
        self.eq.eval(x, &mut r);
        r.v[..r.n].to_vec()
    }

    /// The local slots of entity `h`'s parameters.
    pub fn cols(&self, sys: &System, h: u32) -> Vec<usize> {
        let e = sys.entity(EntityId(h)).expect("entity exists");
        e.kind
            .params()
            .iter()
            .map(|p| {
                let i = sys.param_index(*p).expect("param exists") as u32;
                self.locals.iter().position(|&l| l == i).expect("a local")
            })
            .collect()
    }

    /// Residuals and the row-major Jacobian from [`Equation::jacobian`].
    pub fn jacobian(&self, x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let rows = self.eq.rows(x);
        let mut res = vec![f64::NAN; rows];
        let mut jac = vec![f64::NAN; rows * x.len()];
        self.eq.jacobian(x, &mut res, &mut jac);
        (res, jac)
    }
}

/// Compiles constraint `c` at the system's current values: resolves it, picks its branch with
/// [`Equation::choose`] and, for `where_dragged`, records the position to keep.
pub(super) fn compile(sys: &System, c: &Constraint) -> One {
    sys.validate().expect("the fixture builds a valid model");
    let (eq, l) = resolve_constraint(&Resolver::new(sys), c).expect("constraint resolves");
    let mut one = One {
        eq,
        locals: l.params.to_vec(),
    };
    let x = one.x(sys);
    one.eq.choose(&x);
    if one.eq.kind == EqKind::Constraint(ConstraintKind::WhereDragged) {
        let p = Geo {
            x: &x[..],
            k: &one.eq.consts,
        }
        .at(one.eq.pt(0), one.eq.wp());
        one.eq.target = [p.x, p.y, p.z];
    }
    one
}

/// The implicit condition of entity `h` (a 3D normal, an arc, a moved point or a rotated
/// normal), compiled by
/// [`compile_group`] at the system's current values.
pub(super) fn compile_implicit(sys: &System, h: u32) -> One {
    sys.validate().expect("the fixture builds a valid model");
    let e = sys.entity(EntityId(h)).expect("entity exists");
    let values: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
    // The condition itself, as a solve that keeps the entity's own unknowns has it (a solve
    // reads a carried entity as its expression instead, with no condition).
    let compiled =
        super::super::carried::without(|| compile_group(sys, e.group, &[], true, &values, &values))
            .expect("group compiles");
    compiled
        .kernels
        .into_iter()
        .find(|k| k.owner == Owner::Entity(EntityId(h)))
        .map(|k| One {
            eq: k.eq,
            locals: k.locals,
        })
        .expect("the entity has an implicit condition")
}

/// Compiles a case's target.
pub(super) fn compile_target(sys: &System, t: &Target) -> One {
    match t {
        Target::Constraint(c) => compile(sys, c),
        Target::Entity(h) => compile_implicit(sys, *h),
    }
}

/// Every equation of group `g` (constraints that are not references, and implicit
/// conditions), compiled at the current values.
pub(super) fn compile_all(sys: &System, g: u32) -> Vec<(String, One)> {
    let mut out = Vec::new();
    for c in sys.constraints() {
        if c.group == GroupId(g) && !c.reference {
            out.push((
                format!("constraint {} ({})", c.h.0, c.kind),
                compile(sys, c),
            ));
        }
    }
    for e in sys.entities() {
        let implicit = matches!(
            e.kind,
            EntityKind::NormalIn3d { .. }
                | EntityKind::ArcOfCircle { .. }
                | EntityKind::PointNRotTrans { .. }
                | EntityKind::NormalNRot { .. }
        );
        if e.group == GroupId(g) && implicit {
            out.push((format!("entity {}", e.h.0), compile_implicit(sys, e.h.0)));
        }
    }
    out
}

/// Asserts `|a - b| <= tol (1 + |b|)` for each pair, naming `what`.
pub(super) fn assert_close(what: &str, got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "{what}: {got:?} vs {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!(
            (g - w).abs() <= tol * (1.0 + w.abs()),
            "{what}: got {got:?}, want {want:?}"
        );
    }
}

/// The rank of the columns `cols` of a row-major `rows x n` matrix (Gaussian elimination with
/// partial pivoting; pivots below 1e-9 of the largest entry count as zero).
pub(super) fn rank(jac: &[f64], n: usize, cols: &[usize]) -> usize {
    let rows = jac.len() / n;
    let mut m: Vec<Vec<f64>> = (0..rows)
        .map(|r| cols.iter().map(|&c| jac[r * n + c]).collect())
        .collect();
    let scale = m.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs()));
    let mut rank = 0;
    for c in 0..cols.len() {
        let Some(p) = (rank..rows).max_by(|&a, &b| m[a][c].abs().total_cmp(&m[b][c].abs())) else {
            break;
        };
        if m[p][c].abs() <= 1e-9 * scale {
            continue;
        }
        m.swap(rank, p);
        let pivot = m[rank].clone();
        for row in &mut m[rank + 1..] {
            let k = row[c] / pivot[c];
            for (x, p) in row.iter_mut().zip(&pivot).skip(c) {
                *x -= k * p;
            }
        }
        rank += 1;
    }
    rank
}
