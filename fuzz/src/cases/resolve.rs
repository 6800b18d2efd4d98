//! `resolve`: random but well-formed systems built through loci's Rust API — a workplane,
//! 2D and 3D points, lines, circles, arcs, cubics and normals, constraints of every type
//! with valid references and random values (redundant and conflicting ones too) — solved
//! with a [`Solver`], edited (parameter values, constraint values, constraints added,
//! removed, retyped or re-pointed) and solved again with the same `Solver`.
//!
//! Asserted, besides "no panic":
//! - every `okay` / `redundant_okay` answer satisfies each constraint, as read independently
//!   by [`super::geometry`] (for the types it models), and the implicit conditions (unit
//!   quaternions, arcs' equal radii);
//! - a failed solve leaves every parameter as it was;
//! - the `Solver`'s answer after edits equals a fresh [`loci::solve`] of the same system
//!   (outcome, degrees of freedom and, when solved, the values), except where the `Solver`
//!   documents that it keeps a branch chosen at its first solve (see [`branch_kept`]);
//! - a well-formed system is never rejected.

use super::bytes::Bytes;
use super::geometry::{Geo, Unit};
use loci::format::json::{Problem, SolveRequest};
use loci::{
    Config, Constraint, ConstraintId, ConstraintKind as K, Entity, EntityId, EntityKind, Param,
    ParamId, PlaneRule, Report, Solver, System, Want,
};
use std::fmt::Write;

/// Known bug: a [`Solver`] keys its cache on the numbers of params, entities and
/// constraints, so an edit that keeps them (a constraint removed and another added, a
/// constraint retyped or re-pointed through `constraint_mut`) is solved with the old
/// equations. When `true`, the target calls [`Solver::invalidate`] after such edits, so that
/// the rest keeps being checked while the bug is open.
pub const KNOWN_BUG_STALE_SOLVER_CACHE: bool = false;

/// Known bug: 3D `parallel`, `pt_on_line` (and the other constraints written as two
/// components of a cross product: `cubic_line_tangent`, `same_orientation` and `symmetric`
/// in 3D) accept geometry that breaks them, where both vectors are perpendicular to the axis
/// dropped at the start. When `true`, their residuals are not checked.
pub const KNOWN_BUG_3D_TWO_COMPONENT_CROSS: bool = false;

/// Which checks run: [`Skips::FUZZ`] for the fuzz target (known bugs skipped, so that the
/// rest keeps being checked), [`Skips::NONE`] for the regression test (everything checked;
/// the inputs a known bug fails are listed there).
#[derive(Clone, Copy, Debug)]
pub struct Skips {
    /// See [`KNOWN_BUG_STALE_SOLVER_CACHE`].
    pub stale_solver_cache: bool,
    /// See [`KNOWN_BUG_3D_TWO_COMPONENT_CROSS`].
    pub two_component_cross: bool,
}

impl Skips {
    /// The fuzz targets' setting.
    pub const FUZZ: Skips = Skips {
        stale_solver_cache: KNOWN_BUG_STALE_SOLVER_CACHE,
        two_component_cross: KNOWN_BUG_3D_TWO_COMPONENT_CROSS,
    };
    /// Every check on.
    pub const NONE: Skips = Skips {
        stale_solver_cache: false,
        two_component_cross: false,
    };
}

/// Newton iterations per component.
const MAX_ITERATIONS: usize = 30;

/// Group of the fixed geometry (the workplane and a few fixed points).
const FIXED: u32 = 1;
/// The group solved.
const G: u32 = 2;
/// The workplane's entities.
const ORIGIN: u32 = 1;
const WP_NORMAL: u32 = 2;
const WP: u32 = 3;
const NORMAL_2D: u32 = 4;

/// Relative tolerance of the independent residual check: loci's own is 1e-10 on its
/// (differently scaled) residuals.
const CHECK_TOL: f64 = 1e-7;

#[derive(Default)]
struct Pools {
    pts2: Vec<u32>,
    pts3: Vec<u32>,
    lines: Vec<u32>,
    circles: Vec<u32>,
    arcs: Vec<u32>,
    cubics: Vec<u32>,
    normals3: Vec<u32>,
}

impl Pools {
    fn of(&self, want: Want) -> Vec<u32> {
        let cat = |a: &[&Vec<u32>]| a.iter().flat_map(|v| v.iter().copied()).collect();
        match want {
            Want::Point => cat(&[&self.pts2, &self.pts3]),
            Want::Line => self.lines.clone(),
            Want::Workplane => vec![WP],
            Want::Normal => {
                let mut v = self.normals3.clone();
                v.push(NORMAL_2D);
                v
            }
            Want::LineOrNormal => {
                let mut v = self.lines.clone();
                v.extend(&self.normals3);
                v.push(NORMAL_2D);
                v
            }
            Want::CircleOrArc => cat(&[&self.circles, &self.arcs]),
            Want::Arc => self.arcs.clone(),
            Want::Cubic => self.cubics.clone(),
            Want::Curve => cat(&[&self.arcs, &self.cubics]),
        }
    }
}

struct Case {
    sys: System,
    pools: Pools,
    next_param: u32,
    next_entity: u32,
    next_constraint: u32,
    /// Only constraints whose equations keep no branch between solves.
    branch_free: bool,
    trace: String,
}

fn unit_quat(q: [f64; 4]) -> [f64; 4] {
    let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
    if n < 1e-3 {
        [1.0, 0.0, 0.0, 0.0]
    } else {
        q.map(|x| x / n)
    }
}

impl Case {
    fn param(&mut self, group: u32, val: f64) -> u32 {
        let h = self.next_param;
        self.next_param += 1;
        self.sys
            .add_param(Param::new(h, group, val))
            .expect("fresh handle");
        h
    }

    fn entity(&mut self, e: impl FnOnce(u32) -> Entity) -> u32 {
        let h = self.next_entity;
        self.next_entity += 1;
        self.sys.add_entity(e(h)).expect("fresh handle");
        h
    }

    fn quaternion(b: &mut Bytes) -> [f64; 4] {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        match b.below(5) {
            0 => [1.0, 0.0, 0.0, 0.0],
            1 => [s, s, 0.0, 0.0],
            2 => [s, 0.0, s, 0.0],
            3 => {
                let t = b.range(-3.2, 3.2);
                [t.cos(), 0.0, 0.0, t.sin()]
            }
            _ => unit_quat([0; 4].map(|_: u8| b.range(-1.0, 1.0))),
        }
    }

    /// The geometry: the workplane in group 1, points, lines, circles, arcs, cubics and
    /// normals in group 2 (a few points fixed in group 1).
    fn geometry(b: &mut Bytes) -> Self {
        let mut c = Case {
            sys: System::new(),
            pools: Pools::default(),
            next_param: 1,
            next_entity: 1,
            next_constraint: 1,
            branch_free: b.bool(),
            trace: String::new(),
        };
        let o = [0; 3].map(|_: u8| if b.bool() { 0.0 } else { b.coord() });
        let o = o.map(|v| c.param(FIXED, v));
        let q = Self::quaternion(b).map(|v| c.param(FIXED, v));
        assert_eq!(c.entity(|h| Entity::point_3d(h, FIXED, o)), ORIGIN);
        assert_eq!(c.entity(|h| Entity::normal_3d(h, FIXED, q)), WP_NORMAL);
        assert_eq!(
            c.entity(|h| Entity::workplane(h, FIXED, ORIGIN, WP_NORMAL)),
            WP
        );
        assert_eq!(c.entity(|h| Entity::normal_2d(h, FIXED, WP)), NORMAL_2D);
        c.pools.normals3.push(WP_NORMAL);

        for _ in 0..2 + b.below(7) {
            let group = if b.one_in(8) { FIXED } else { G };
            if b.below(3) != 0 {
                let uv = [0; 2].map(|_: u8| b.coord());
                let uv = uv.map(|v| c.param(group, v));
                let h = c.entity(|h| Entity::point_2d(h, group, WP, uv));
                c.pools.pts2.push(h);
            } else {
                let xyz = [0; 3].map(|_: u8| b.coord());
                let xyz = xyz.map(|v| c.param(group, v));
                let h = c.entity(|h| Entity::point_3d(h, group, xyz));
                c.pools.pts3.push(h);
            }
        }
        let points = c.pools.of(Want::Point);
        let is2 = |c: &Case, p: u32| c.pools.pts2.contains(&p);
        for _ in 0..b.below(5) {
            let (p, q) = (b.pick(&points), b.pick(&points));
            // A line from a point to itself is malformed (it has no direction), and
            // rejected: `bad_input` tests that.
            if p == q {
                continue;
            }
            let wp = (is2(&c, p) && is2(&c, q)).then_some(WP);
            let h = c.entity(|h| Entity::line(h, G, wp, p, q));
            c.pools.lines.push(h);
        }
        for _ in 0..b.below(2) {
            let q = Self::quaternion(b).map(|v| c.param(G, v));
            let h = c.entity(|h| Entity::normal_3d(h, G, q));
            c.pools.normals3.push(h);
        }
        for _ in 0..b.below(3) {
            let center = b.pick(&points);
            let r = b.range(0.5, 30.0);
            let r = c.param(G, r);
            let (wp, normal) = if is2(&c, center) {
                (Some(WP), NORMAL_2D)
            } else {
                (None, b.pick(&c.pools.normals3))
            };
            let d = c.entity(|h| Entity::distance(h, G, wp, r));
            let h = c.entity(|h| Entity::circle(h, G, wp, center, normal, d));
            c.pools.circles.push(h);
        }
        if !c.pools.pts2.is_empty() {
            let pts2 = c.pools.pts2.clone();
            for _ in 0..b.below(3) {
                let (m, s, e) = (b.pick(&pts2), b.pick(&pts2), b.pick(&pts2));
                if (m == s || m == e || s == e) && !b.one_in(8) {
                    continue;
                }
                let h = c.entity(|h| Entity::arc(h, G, WP, NORMAL_2D, m, s, e));
                c.pools.arcs.push(h);
            }
        }
        for _ in 0..b.below(2) {
            let ps = [0; 4].map(|_: u8| b.pick(&points));
            let wp = ps.iter().all(|&p| is2(&c, p)).then_some(WP);
            let h = c.entity(|h| Entity::cubic(h, G, wp, ps));
            c.pools.cubics.push(h);
        }
        c
    }

    fn is_2d_point(&self, p: EntityId) -> bool {
        self.pools.pts2.contains(&p.0)
    }

    /// A well-formed constraint with handle `h`: of `kind`, or of a random one.
    fn constraint(&self, b: &mut Bytes, h: u32, kind: Option<K>) -> Option<Constraint> {
        let kind = kind.unwrap_or_else(|| b.pick(K::ALL));
        let sig = kind.signature();
        let mut wp = match sig.plane {
            PlaneRule::Required => Some(WP),
            PlaneRule::Either => b.bool().then_some(WP),
            PlaneRule::Ignored => b.one_in(8).then_some(WP),
        };
        if self.branch_free {
            match kind {
                K::Parallel | K::PtOnLine | K::CubicLineTangent => wp = Some(WP),
                K::Angle | K::EqualAngle => wp = None,
                K::SameOrientation => return None,
                _ => {}
            }
        }
        let mut c = Constraint::new(h, G, kind).in_workplane(wp);
        let pick = |want: Want, b: &mut Bytes| -> Option<EntityId> {
            let pool = self.pools.of(want);
            (!pool.is_empty()).then(|| EntityId(b.pick(&pool)))
        };
        if matches!(kind, K::Horizontal | K::Vertical) && b.bool() {
            c.pt_a = pick(Want::Point, b);
            c.pt_b = pick(Want::Point, b);
        } else if kind == K::AtMidpoint && b.one_in(4) {
            c.entity_a = pick(Want::Line, b);
            c.entity_b = Some(EntityId(WP));
        } else {
            for (i, want) in sig.fields.iter().enumerate() {
                let Some(want) = *want else { continue };
                let e = pick(want, b)?;
                match i {
                    0 => c.pt_a = Some(e),
                    1 => c.pt_b = Some(e),
                    2 => c.entity_a = Some(e),
                    3 => c.entity_b = Some(e),
                    4 => c.entity_c = Some(e),
                    _ => c.entity_d = Some(e),
                }
            }
        }
        if c.wants()
            .iter()
            .zip(c.fields())
            .any(|(w, f)| w.is_some() && f.is_none())
        {
            return None;
        }
        if c.pt_a.is_some() && c.pt_a == c.pt_b && !b.one_in(8) {
            return None;
        }
        if kind == K::WhereDragged && self.branch_free {
            // Native coordinates only: the target of any other is kept from the first solve.
            c.workplane = self.is_2d_point(c.pt_a?).then_some(EntityId(WP));
        }
        c.other = b.one_in(4);
        c.other2 = b.one_in(4);
        c.val = self.value(b, &c);
        if kind.has_value() && b.one_in(10) {
            c.reference = true;
        }
        Some(c)
    }

    /// A value for `c`: often what the geometry measures now (so that the system starts
    /// near a solution), else a plausible or a wild one.
    fn value(&self, b: &mut Bytes, c: &Constraint) -> f64 {
        if c.kind.has_value() && b.below(3) == 0 {
            if let Some(m) = (Geo { sys: &self.sys }).measure(c) {
                return if b.one_in(4) {
                    m + b.range(-1.0, 1.0)
                } else {
                    m
                };
            }
        }
        match c.kind {
            K::Angle => {
                if b.bool() {
                    b.pick(&[0.0, 30.0, 45.0, 60.0, 90.0, 120.0, 180.0])
                } else {
                    b.range(-10.0, 370.0)
                }
            }
            K::PtPtDistance | K::Diameter => {
                let r = b.range(-5.0, 60.0);
                b.pick(&[0.0, 1.0, 5.0, 10.0, r])
            }
            K::PtLineDistance
            | K::PtPlaneDistance
            | K::PtFaceDistance
            | K::ProjPtDistance
            | K::LengthDifference
            | K::ArcArcDifference
            | K::ArcLineDifference => b.range(-30.0, 30.0),
            K::LengthRatio | K::ArcArcLenRatio | K::ArcLineLenRatio => {
                let r = b.range(-1.0, 5.0);
                b.pick(&[1.0, 2.0, 0.5, r])
            }
            // Kinds that have no dimension ignore it.
            _ => {
                if b.one_in(8) {
                    b.coord()
                } else {
                    0.0
                }
            }
        }
    }

    fn add_constraints(&mut self, b: &mut Bytes, n: usize) {
        for _ in 0..n {
            let h = self.next_constraint;
            self.next_constraint += 1;
            if let Some(c) = self.constraint(b, h, None) {
                let _ = writeln!(self.trace, "  add {}", describe(&c));
                self.sys.add_constraint(c).expect("fresh handle");
            }
        }
    }
}

fn describe(c: &Constraint) -> String {
    let mut s = format!("c{} {}", c.h.0, c.kind.name());
    if let Some(w) = c.workplane {
        let _ = write!(s, " wp={}", w.0);
    }
    for (name, f) in loci::FIELD_NAMES.iter().zip(c.fields()) {
        if let Some(f) = f {
            let _ = write!(s, " {name}={}", f.0);
        }
    }
    let _ = write!(s, " val={}", c.val);
    if c.other {
        s.push_str(" other");
    }
    if c.other2 {
        s.push_str(" other2");
    }
    if c.reference {
        s.push_str(" reference");
    }
    s
}

/// Whether a [`Solver`] keeps a choice made from the configuration at its first solve for
/// `c` (documented: which two components of a cross product to keep in 3D, the sign of a 2D
/// angle, the target of a `where_dragged` on a point not in its own coordinates), so that
/// its later answers may rightly differ from a fresh solve's.
pub fn branch_kept(sys: &System, c: &Constraint) -> bool {
    if c.reference {
        return false;
    }
    let in_wp = c.workplane.is_some() && c.kind.signature().plane != PlaneRule::Ignored;
    match c.kind {
        K::Parallel | K::PtOnLine | K::CubicLineTangent => !in_wp,
        K::Angle | K::EqualAngle => in_wp,
        K::SameOrientation => true,
        K::WhereDragged => !native(sys, c),
        _ => false,
    }
}

/// Whether a `where_dragged` holds its point in the point's own coordinates (a 2D point in
/// its workplane, a 3D point in space): then its target follows the values at each solve.
fn native(sys: &System, c: &Constraint) -> bool {
    let Some(p) = c.pt_a.and_then(|p| sys.entity(p)) else {
        return false;
    };
    match (&p.kind, c.workplane) {
        (EntityKind::PointIn3d { .. }, None) => true,
        (EntityKind::PointIn2d { .. }, Some(w)) => p.workplane == Some(w),
        _ => false,
    }
}

fn any_branch_kept(sys: &System) -> bool {
    sys.constraints().iter().any(|c| branch_kept(sys, c))
}

/// Constraints whose residuals [`KNOWN_BUG_3D_TWO_COMPONENT_CROSS`] leaves unchecked.
pub fn two_component_cross(c: &Constraint) -> bool {
    let in_wp = c.workplane.is_some() && c.kind.signature().plane != PlaneRule::Ignored;
    match c.kind {
        K::Parallel | K::PtOnLine | K::CubicLineTangent | K::Symmetric => !in_wp,
        K::SameOrientation => true,
        _ => false,
    }
}

struct Run {
    case: Case,
    dragged: Vec<ParamId>,
    cfg: Config,
    solver: Solver,
    /// Counts when the solver last compiled, and whether a kept branch was in it then.
    compiled: Option<((usize, usize, usize), bool)>,
    skips: Skips,
}

fn shape(sys: &System) -> (usize, usize, usize) {
    (
        sys.params().len(),
        sys.entities().len(),
        sys.constraints().len(),
    )
}

impl Run {
    fn fail(&self, what: &str, before: &System) -> ! {
        let problem = Problem {
            system: before.clone(),
            solve: Some(SolveRequest {
                group: G.into(),
                dragged: self.dragged.clone(),
                calculate_failed: true,
                options: Default::default(),
            }),
        };
        panic!(
            "{what}\n--- what was done:\n{}--- the system before this solve (loci JSON):\n{}",
            self.case.trace,
            problem.to_json()
        );
    }

    /// Checks an answer against the system it started from.
    fn check(&self, label: &str, before: &System, after: &System, rep: &Report, cached: bool) {
        if rep.dof > rep.unknowns {
            self.fail(
                &format!("{label}: dof {} > {} unknowns", rep.dof, rep.unknowns),
                before,
            );
        }
        if !rep.outcome.is_ok() {
            if before.params() != after.params() {
                self.fail(
                    &format!("{label}: a {} solve changed parameter values", rep.outcome),
                    before,
                );
            }
            return;
        }
        let (g, start) = (Geo { sys: after }, Geo { sys: before });
        let size = g.size().max(start.size());
        let tol = |u: Unit| match u {
            Unit::Length => CHECK_TOL * size,
            Unit::Pure => CHECK_TOL,
        };
        for c in after.constraints() {
            if cached && c.kind == K::WhereDragged && !native(after, c) {
                continue; // its target is the position at the first solve
            }
            if self.skips.two_component_cross && two_component_cross(c) {
                continue;
            }
            let Some(rs) = g.residuals(c, &start) else {
                continue;
            };
            for (r, u) in rs {
                if !(r.abs() <= tol(u)) {
                    self.fail(
                        &format!(
                            "{label}: outcome {} but {} does not hold: residual {r:e} (tolerance {:e})",
                            rep.outcome,
                            describe(c),
                            tol(u)
                        ),
                        before,
                    );
                }
            }
        }
        for (e, r, u) in g.implicit_residuals(G) {
            if !(r.abs() <= tol(u)) {
                self.fail(
                    &format!(
                        "{label}: outcome {} but the implicit condition of entity {} does not hold: residual {r:e}",
                        rep.outcome, e.0
                    ),
                    before,
                );
            }
        }
    }

    /// Solves with the kept `Solver` and afresh, and checks both.
    fn solve(&mut self, label: &str) {
        let before = self.case.sys.clone();
        let now = shape(&before);
        let rebuilt = self.compiled.is_none_or(|(s, _)| s != now);
        if rebuilt {
            self.compiled = Some((now, any_branch_kept(&before)));
        }
        let kept_branch = self.compiled.is_some_and(|(_, k)| k) || any_branch_kept(&before);
        let comparable = rebuilt || !kept_branch;

        let cached = self.solver.solve(&mut self.case.sys);
        let mut fresh_sys = before.clone();
        let fresh = loci::solve(&mut fresh_sys, G.into(), &self.dragged, &self.cfg);
        let (cached, fresh) = match (cached, fresh) {
            (Ok(c), Ok(f)) => (c, f),
            // A group that owns nothing (every edit removed its objects) is an error for both,
            // naming the groups there are.
            (
                Err(loci::SolveError::UnknownGroup { group, .. }),
                Err(loci::SolveError::UnknownGroup { .. }),
            ) if !before.groups().contains(&group) => return,
            (Err(e), _) => self.fail(
                &format!("{label}: the Solver rejects a well-formed system: {e}"),
                &before,
            ),
            (_, Err(e)) => self.fail(
                &format!("{label}: loci::solve rejects a well-formed system: {e}"),
                &before,
            ),
        };
        let _ = writeln!(
            self.case.trace,
            "{label}: Solver {} dof {}, fresh {} dof {}{}",
            cached.outcome,
            cached.dof,
            fresh.outcome,
            fresh.dof,
            if comparable { "" } else { " (branches kept)" }
        );
        self.check(
            &format!("{label} (fresh solve)"),
            &before,
            &fresh_sys,
            &fresh,
            false,
        );
        if comparable {
            if (cached.outcome, cached.dof) != (fresh.outcome, fresh.dof) {
                self.fail(
                    &format!(
                        "{label}: the Solver answers {} (dof {}) but a fresh solve of the same system {} (dof {})",
                        cached.outcome, cached.dof, fresh.outcome, fresh.dof
                    ),
                    &before,
                );
            }
            if cached.outcome.is_ok() {
                let size = Geo { sys: &before }.size();
                for (a, f) in self.case.sys.params().iter().zip(fresh_sys.params()) {
                    if !((a.val - f.val).abs() <= 1e-6 * size) {
                        self.fail(
                            &format!(
                                "{label}: the Solver puts {} at {} but a fresh solve at {}",
                                a.h, a.val, f.val
                            ),
                            &before,
                        );
                    }
                }
            }
        }
        self.check(
            &format!("{label} (Solver)"),
            &before,
            &self.case.sys.clone(),
            &cached,
            !rebuilt,
        );
    }

    fn pick_constraint(&self, b: &mut Bytes) -> Option<ConstraintId> {
        let cs = self.case.sys.constraints();
        (!cs.is_empty()).then(|| cs[b.below(cs.len())].h)
    }

    /// One random edit; returns whether it changed the constraints other than by value.
    fn edit(&mut self, b: &mut Bytes) -> bool {
        let op = b.below(9);
        match op {
            0 | 1 => {
                // A parameter value (not the workplane's orientation: its quaternion stays
                // a rotation, so that 2D coordinates mean what they say).
                let ps: Vec<ParamId> = self
                    .case
                    .sys
                    .params()
                    .iter()
                    .map(|p| p.h)
                    .filter(|h| !(4..=7).contains(&h.0))
                    .collect();
                let h = ps[b.below(ps.len())];
                let v = b.coord();
                let _ = writeln!(self.case.trace, "  set {h} = {v}");
                self.case.sys.set_value(h, v);
                false
            }
            2 => {
                let Some(h) = self.pick_constraint(b) else {
                    return false;
                };
                let c = self.case.sys.constraint(h).expect("present").clone();
                let v = self.case.value(b, &c);
                let _ = writeln!(self.case.trace, "  val of c{} = {v}", h.0);
                self.case.sys.constraint_mut(h).expect("present").val = v;
                false
            }
            3 => {
                self.case.add_constraints(b, 1);
                true
            }
            4 => {
                if let Some(h) = self.pick_constraint(b) {
                    let _ = writeln!(self.case.trace, "  remove c{}", h.0);
                    self.case.sys.remove_constraint(h);
                }
                true
            }
            5 => {
                // Remove one and add another: the counts stay.
                let Some(h) = self.pick_constraint(b) else {
                    return false;
                };
                let n = self.case.next_constraint;
                let Some(c) = self.case.constraint(b, n, None) else {
                    return false;
                };
                self.case.next_constraint += 1;
                let _ = writeln!(self.case.trace, "  remove c{}, add {}", h.0, describe(&c));
                self.case.sys.remove_constraint(h);
                self.case.sys.add_constraint(c).expect("fresh handle");
                true
            }
            6 | 7 => {
                // Retype (6) or re-point (7) a constraint in place.
                let Some(h) = self.pick_constraint(b) else {
                    return false;
                };
                let kind = self.case.sys.constraint(h).expect("present").kind;
                let kind = if op == 6 { None } else { Some(kind) };
                let Some(c) = self.case.constraint(b, h.0, kind) else {
                    return false;
                };
                let _ = writeln!(self.case.trace, "  replace c{} by {}", h.0, describe(&c));
                *self.case.sys.constraint_mut(h).expect("present") = c;
                true
            }
            _ => {
                // A copy of a constraint, the same or with another value: redundant or in
                // conflict.
                let Some(h) = self.pick_constraint(b) else {
                    return false;
                };
                let mut c = self.case.sys.constraint(h).expect("present").clone();
                c.h = ConstraintId(self.case.next_constraint);
                self.case.next_constraint += 1;
                if b.bool() {
                    c.val = self.case.value(b, &c);
                }
                let _ = writeln!(self.case.trace, "  add {}", describe(&c));
                self.case.sys.add_constraint(c).expect("fresh handle");
                true
            }
        }
    }
}

/// Runs one input as the fuzz target does; panics on a finding.
pub fn run(data: &[u8]) {
    run_with(data, Skips::FUZZ);
}

/// Runs one input with the given checks; panics on a finding.
pub fn run_with(data: &[u8], skips: Skips) {
    let mut b = Bytes::new(data);
    let mut case = Case::geometry(&mut b);
    let n = 1 + b.below(10);
    case.add_constraints(&mut b, n);
    let mut dragged = Vec::new();
    if b.one_in(3) {
        let g2: Vec<ParamId> = case
            .sys
            .params()
            .iter()
            .filter(|p| p.group.0 == G)
            .map(|p| p.h)
            .collect();
        for _ in 0..1 + b.below(3) {
            if !g2.is_empty() {
                dragged.push(g2[b.below(g2.len())]);
            }
        }
        dragged.dedup();
    }
    let cfg = Config::default().with_max_iterations(MAX_ITERATIONS);
    let mut run = Run {
        solver: Solver::new(G, &dragged, cfg.clone()),
        case,
        dragged,
        cfg,
        compiled: None,
        skips,
    };
    run.solve("first solve");
    for round in 0..b.below(5) {
        let counts = shape(&run.case.sys);
        let mut structural = false;
        for _ in 0..1 + b.below(3) {
            structural |= run.edit(&mut b);
        }
        // The counts the Solver keys its cache on did not change, but the constraints did.
        if structural && shape(&run.case.sys) == counts && skips.stale_solver_cache {
            run.solver.invalidate();
            run.compiled = None;
        }
        run.solve(&format!("re-solve {}", round + 1));
    }
    if b.one_in(4) {
        let _ = loci::diagnose(&run.case.sys, G.into(), &run.cfg);
    }
}
