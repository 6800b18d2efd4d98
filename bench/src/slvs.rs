//! Translation to the SolveSpace model, shared by loci and both SolveSpace runners.
//!
//! loci implements the SolveSpace model, so the translation builds a [`loci::System`]; the
//! SolveSpace runners (the C program over libslvs and the Python one over PyPI `slvs`) read
//! the same system written as plain records by [`to_records`]. Fixed points and workplanes
//! are in group 1; everything solved is in group 2.

use crate::problem::{Con, Problem};
use loci::{Constraint, ConstraintKind as K, Entity, EntityKind, Param, System};
use std::fmt::Write as _;

/// The group holding the unknowns.
pub const SOLVE_GROUP: u32 = 2;
/// The group of fixed points and workplanes.
const FIXED_GROUP: u32 = 1;
/// The xy workplane of 2D problems, and its normal, which arcs name as SolveSpace's own
/// examples do (PyPI `slvs` insists on a 3D normal there).
const XY_PLANE: u32 = 3;
const XY_NORMAL: u32 = 2;

/// A problem in the SolveSpace model, with the entity of each problem point.
#[derive(Clone, Debug)]
pub struct SlvsProblem {
    /// The system; solve group [`SOLVE_GROUP`].
    pub system: System,
    /// The point entity of each problem point, in problem order.
    pub points: Vec<u32>,
}

struct Handles {
    param: u32,
    entity: u32,
}

impl Handles {
    fn param(&mut self) -> u32 {
        self.param += 1;
        self.param
    }
    fn entity(&mut self) -> u32 {
        self.entity += 1;
        self.entity
    }
}

/// Adds a fixed 3D workplane through `origin` with orientation `quat`; returns its handle.
fn add_plane(
    sys: &mut System,
    h: &mut Handles,
    origin: [f64; 3],
    quat: [f64; 4],
) -> anyhow::Result<u32> {
    let o = [h.param(), h.param(), h.param()];
    for (p, v) in o.iter().zip(origin) {
        sys.add_param(Param::new(*p, FIXED_GROUP, v))?;
    }
    let q = [h.param(), h.param(), h.param(), h.param()];
    for (p, v) in q.iter().zip(quat) {
        sys.add_param(Param::new(*p, FIXED_GROUP, v))?;
    }
    let (pe, ne, we) = (h.entity(), h.entity(), h.entity());
    sys.add_entity(Entity::point_3d(pe, FIXED_GROUP, o))?;
    sys.add_entity(Entity::normal_3d(ne, FIXED_GROUP, q))?;
    sys.add_entity(Entity::workplane(we, FIXED_GROUP, pe, ne))?;
    Ok(we)
}

/// The angle constraint between lines `l1` and `l2` whose intended angle is `deg` (signed in
/// 2D, counter-clockwise from `l1` to `l2`).
///
/// In a workplane it is a signed angle, as ezpz's and PlaneGCS's are: the intended sign holds
/// even where the start has turned a small angle the other way. (SolveSpace's angle, with
/// `|deg|` alone, keeps the drawn turn: a different sketch, and for the `profiles` family an
/// impossible one.) In space the angle has no sign.
fn angle(c: Constraint, planar: bool, deg: f64) -> Constraint {
    if planar {
        c.with_val(deg).as_signed()
    } else {
        c.with_val(deg.abs())
    }
}

/// Builds the SolveSpace-model system of a problem.
///
/// # Errors
/// Only if the problem refers to objects it does not have (a generator bug).
pub fn build(p: &Problem) -> anyhow::Result<SlvsProblem> {
    let mut sys = System::new();
    let mut h = Handles {
        param: 0,
        entity: 0,
    };
    // Handles 1..=3 name the xy plane's origin, normal and workplane.
    let xy = add_plane(&mut sys, &mut h, [0.0; 3], [1.0, 0.0, 0.0, 0.0])?;
    debug_assert_eq!(xy, XY_PLANE);
    let planes = p
        .planes
        .iter()
        .map(|pl| add_plane(&mut sys, &mut h, pl.origin, pl.quat))
        .collect::<anyhow::Result<Vec<_>>>()?;
    let wp = p.planar.then_some(XY_PLANE);
    let mut points = Vec::with_capacity(p.points.len());
    for pt in &p.points {
        let g = if pt.fixed { FIXED_GROUP } else { SOLVE_GROUP };
        let e = h.entity();
        if p.planar {
            let (u, v) = (h.param(), h.param());
            sys.add_param(Param::new(u, g, pt.start[0]))?;
            sys.add_param(Param::new(v, g, pt.start[1]))?;
            sys.add_entity(Entity::point_2d(e, g, XY_PLANE, [u, v]))?;
        } else {
            let ps = [h.param(), h.param(), h.param()];
            for (ph, v) in ps.iter().zip(pt.start) {
                sys.add_param(Param::new(*ph, g, v))?;
            }
            sys.add_entity(Entity::point_3d(e, g, ps))?;
        }
        points.push(e);
    }
    let mut lines = Vec::with_capacity(p.lines.len());
    for [a, b] in &p.lines {
        let e = h.entity();
        sys.add_entity(Entity::line(e, SOLVE_GROUP, wp, points[*a], points[*b]))?;
        lines.push(e);
    }
    let mut arcs = Vec::with_capacity(p.arcs.len());
    for a in &p.arcs {
        let e = h.entity();
        sys.add_entity(Entity::arc(
            e,
            SOLVE_GROUP,
            XY_PLANE,
            XY_NORMAL,
            points[a.center],
            points[a.start],
            points[a.end],
        ))?;
        arcs.push(e);
    }
    for (i, c) in p.cons.iter().enumerate() {
        let ch = i as u32 + 1;
        let new = |kind| Constraint::new(ch, SOLVE_GROUP, kind).in_workplane(wp);
        let con = match *c {
            Con::Coincident { a, b } => new(K::PointsCoincident).with_points(points[a], points[b]),
            Con::Distance { a, b, d } => new(K::PtPtDistance)
                .with_points(points[a], points[b])
                .with_val(d),
            Con::Angle { l1, l2, deg } => angle(
                new(K::Angle).with_entities([lines[l1], lines[l2], 0, 0]),
                p.planar,
                deg,
            ),
            Con::Horizontal { l } => new(K::Horizontal).with_entities([lines[l], 0, 0, 0]),
            Con::Vertical { l } => new(K::Vertical).with_entities([lines[l], 0, 0, 0]),
            Con::ArcRadius { arc, r } => new(K::Diameter)
                .with_entities([arcs[arc], 0, 0, 0])
                .with_val(2.0 * r),
            Con::Tangent { arc, at_end, l } => new(K::ArcLineTangent)
                .with_entities([arcs[arc], lines[l], 0, 0])
                .with_flags(at_end, false),
            Con::InPlane { p: pi, plane } => Constraint::new(ch, SOLVE_GROUP, K::PtInPlane)
                .with_points(points[pi], 0)
                .with_entities([planes[plane], 0, 0, 0]),
        };
        sys.add_constraint(con)?;
    }
    Ok(SlvsProblem {
        system: sys,
        points,
    })
}

/// The coordinates of each problem point in a (solved) system.
#[must_use]
pub fn read_points(sp: &SlvsProblem) -> Vec<[f64; 3]> {
    let sys = &sp.system;
    sp.points
        .iter()
        .map(|&e| {
            let mut xyz = [0.0; 3];
            if let Some(ent) = sys.entity(e.into()) {
                for (slot, ph) in xyz.iter_mut().zip(ent.kind.params()) {
                    *slot = sys.value(*ph).unwrap_or(f64::NAN);
                }
            }
            xyz
        })
        .collect()
}

/// The libslvs `SLVS_E_*` number of an entity.
fn entity_code(k: &EntityKind) -> u32 {
    match k {
        // libslvs has no translated or moved copies; the generated families never make one.
        EntityKind::PointIn3d { .. }
        | EntityKind::PointNTrans { .. }
        | EntityKind::PointNRotTrans { .. } => 50000,
        EntityKind::PointIn2d { .. } => 50001,
        EntityKind::NormalIn3d { .. } | EntityKind::NormalNRot { .. } => 60000,
        EntityKind::NormalIn2d => 60001,
        EntityKind::Distance { .. } => 70000,
        EntityKind::Workplane { .. } => 80000,
        EntityKind::LineSegment { .. } => 80001,
        EntityKind::Cubic { .. } => 80002,
        EntityKind::Circle { .. } => 80003,
        EntityKind::ArcOfCircle { .. } => 80004,
    }
}

/// Writes the system as libslvs records, one a line, for the SolveSpace runners:
///
/// ```text
/// G group                                   the group to solve
/// P h group val                             a parameter
/// E h group type wrkpl p0 p1 p2 p3 normal distance q0 q1 q2 q3
/// C h group type wrkpl valA ptA ptB entA entB entC entD other other2
/// O e ...                                   point entities to report, in problem order
/// ```
///
/// Fields are the `Slvs_Param`, `Slvs_Entity` and `Slvs_Constraint` members, 0 when unset.
#[must_use]
pub fn to_records(sp: &SlvsProblem) -> String {
    let sys = &sp.system;
    let mut s = String::with_capacity(64 * (sys.params().len() + sys.constraints().len()));
    let _ = writeln!(s, "G {SOLVE_GROUP}");
    for p in sys.params() {
        let _ = writeln!(s, "P {} {} {:?}", p.h.0, p.group.0, p.val);
    }
    for e in sys.entities() {
        let mut pt = [0u32; 4];
        let (mut normal, mut distance) = (0u32, 0u32);
        match &e.kind {
            EntityKind::Workplane { origin, normal: n } => {
                pt[0] = origin.0;
                normal = n.0;
            }
            EntityKind::LineSegment { points } => {
                pt[0] = points[0].0;
                pt[1] = points[1].0;
            }
            EntityKind::Cubic { points } => {
                for (s, p) in pt.iter_mut().zip(points) {
                    *s = p.0;
                }
            }
            EntityKind::Circle {
                center,
                normal: n,
                radius,
            } => {
                pt[0] = center.0;
                normal = n.0;
                distance = radius.0;
            }
            EntityKind::ArcOfCircle {
                normal: n,
                center,
                start,
                end,
            } => {
                pt = [center.0, start.0, end.0, 0];
                normal = n.0;
            }
            _ => {}
        }
        let mut q = [0u32; 4];
        for (s, p) in q.iter_mut().zip(e.kind.params()) {
            *s = p.0;
        }
        let _ = writeln!(
            s,
            "E {} {} {} {} {} {} {} {} {} {} {} {} {} {}",
            e.h.0,
            e.group.0,
            entity_code(&e.kind),
            e.workplane.map_or(0, |w| w.0),
            pt[0],
            pt[1],
            pt[2],
            pt[3],
            normal,
            distance,
            q[0],
            q[1],
            q[2],
            q[3]
        );
    }
    for c in sys.constraints() {
        let f = c.fields().map(|x| x.map_or(0, |e| e.0));
        let _ = writeln!(
            s,
            "C {} {} {} {} {:?} {} {} {} {} {} {} {} {}",
            c.h.0,
            c.group.0,
            c.kind.slvs_code(),
            c.workplane.map_or(0, |w| w.0),
            c.val,
            f[0],
            f[1],
            f[2],
            f[3],
            f[4],
            f[5],
            u8::from(c.other),
            u8::from(c.other2)
        );
    }
    s.push('O');
    for e in &sp.points {
        let _ = write!(s, " {e}");
    }
    s.push('\n');
    s
}
