//! Degrees of freedom with a place: how each entity can still move.
//!
//! The motions that keep every equation holding to first order are the null space of the
//! Jacobian. With `P = I - Jnᵀ G⁻¹ Jn` (the projector onto it, through the solver's
//! rank-revealing factorisation of `G = Jn Jnᵀ`), a few deterministic pseudo-random vectors
//! projected and orthonormalised span the null space when it is small, and sample it when it
//! is large. Either way, restricted to one entity's parameters they span exactly the motions
//! that entity has, as long as there are more samples than the entity has parameters: a
//! random combination of the null space, seen through a few coordinates, misses none of the
//! directions those coordinates can take. So one small SVD per entity says how it moves, at
//! the cost of a handful of sparse solves for the whole sketch.

use super::circuits::Rank;
use super::eigen::symmetric_eigen;
use super::motion::{direction, direction3, Motion};
use super::report::EntityFreedom;
use super::unmerged::{Equations, Linear, CONSTANT};
use crate::geom::SplitMix;
use crate::model::{EntityId, EntityKind, GroupId, ParamId, System};
use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

/// Samples of a large null space; more than any entity has parameters.
const SAMPLES: usize = 16;
/// Extra samples, so that a small null space is spanned with a margin.
const OVERSAMPLE: usize = 2;
/// A motion counts when the entity moves at least this much per unit of motion of the whole
/// system (the samples are orthonormal); below it, it is rounding.
const FREE_EPS: f64 = 1e-7;

/// Orthonormal vectors (over the columns) spanning or sampling the null space of `Jn`.
pub(crate) fn sketch(
    eqs: &Equations,
    lin: &Linear,
    mut rank: Option<&mut Rank>,
    dof: usize,
) -> Vec<Vec<f64>> {
    let n = eqs.columns.len();
    if dof == 0 || n == 0 {
        return Vec::new();
    }
    let k = (dof.min(SAMPLES) + OVERSAMPLE).min(n);
    let mut rng = SplitMix(0x10C1_D1A6);
    let mut t = vec![0.0; eqs.rows];
    let mut g = vec![0.0; n];
    let mut raw = Vec::with_capacity(k);
    for _ in 0..k {
        let mut v: Vec<f64> = (0..n).map(|_| rng.uniform()).collect();
        // Twice: the second pass removes what rounding left of the first.
        for _ in 0..2 {
            if let Some(r) = rank.as_deref_mut() {
                eqs.mul(lin, &v, &mut t);
                r.gram.solve(&mut t);
                eqs.mul_t(lin, &t, &mut g);
                v.iter_mut().zip(&g).for_each(|(a, b)| *a -= b);
            }
        }
        raw.push(v);
    }
    let keep = if dof <= SAMPLES { dof } else { k };
    orthonormalise(raw, keep)
}

/// Modified Gram–Schmidt, twice over, dropping vectors that are (numerically) combinations of
/// earlier ones; at most `keep` are kept.
fn orthonormalise(raw: Vec<Vec<f64>>, keep: usize) -> Vec<Vec<f64>> {
    let mut out: Vec<Vec<f64>> = Vec::new();
    for mut v in raw {
        if out.len() >= keep {
            break;
        }
        let before = norm(&v);
        if before == 0.0 || !before.is_finite() {
            continue;
        }
        for _ in 0..2 {
            for q in &out {
                let d: f64 = v.iter().zip(q).map(|(a, b)| a * b).sum();
                v.iter_mut().zip(q).for_each(|(a, b)| *a -= d * b);
            }
        }
        let after = norm(&v);
        if after > 1e-6 * before {
            v.iter_mut().for_each(|a| *a /= after);
            out.push(v);
        }
    }
    out
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|a| a * a).sum::<f64>().sqrt()
}

/// The motions one set of columns has: an orthonormal basis of the samples restricted to
/// them, and the weights of the samples that realise each basis vector.
struct Span {
    basis: Vec<Vec<f64>>,
    weights: Vec<Vec<f64>>,
}

impl Span {
    /// From the eigenpairs of `W Wᵀ`, with `W` the samples restricted to `cols`: its
    /// eigenvectors are the motions, and `Wᵀ u / λ` the weights that make `u`.
    fn new(cols: &[u32], vectors: &[Vec<f64>]) -> Self {
        let (p, k) = (cols.len(), vectors.len());
        let mut out = Self {
            basis: Vec::new(),
            weights: Vec::new(),
        };
        if p == 0 || k == 0 {
            return out;
        }
        let w = |i: usize, l: usize| vectors[l][cols[i] as usize];
        let mut m = vec![0.0; p * p];
        for i in 0..p {
            for j in i..p {
                let d: f64 = (0..k).map(|l| w(i, l) * w(j, l)).sum();
                m[i * p + j] = d;
                m[j * p + i] = d;
            }
        }
        let (values, vecs) = symmetric_eigen(m, p);
        for (i, &l) in values.iter().enumerate() {
            if !(l > FREE_EPS * FREE_EPS) {
                break;
            }
            let u: Vec<f64> = (0..p).map(|r| vecs[r * p + i]).collect();
            out.weights.push(
                (0..k)
                    .map(|c| (0..p).map(|r| w(r, c) * u[r]).sum::<f64>() / l)
                    .collect(),
            );
            out.basis.push(u);
        }
        out
    }

    fn dof(&self) -> usize {
        self.basis.len()
    }
}

/// An entity's unknown columns, those parameters, and its span.
struct Entry {
    cols: Vec<u32>,
    params: Vec<ParamId>,
    span: Span,
}

/// Context for describing entities.
struct Ctx<'a> {
    sys: &'a System,
    eqs: &'a Equations<'a>,
    values: &'a [f64],
    vectors: &'a [Vec<f64>],
    /// Spans already computed: a point is both an entity and a part of its lines.
    seen: RefCell<HashMap<EntityId, Rc<Entry>>>,
}

impl Ctx<'_> {
    fn entry(&self, h: EntityId) -> Rc<Entry> {
        if let Some(e) = self.seen.borrow().get(&h) {
            return e.clone();
        }
        let (cols, params) = self.cols(h);
        let span = Span::new(&cols, self.vectors);
        let e = Rc::new(Entry { cols, params, span });
        self.seen.borrow_mut().insert(h, e.clone());
        e
    }

    /// The parameters an entity reads, in order, without repeats.
    fn params(&self, h: EntityId, out: &mut Vec<ParamId>, depth: u32) {
        let Some(e) = self.sys.entity(h) else { return };
        if depth > 6 {
            return;
        }
        let push = |p: ParamId, out: &mut Vec<ParamId>| {
            if !out.contains(&p) {
                out.push(p);
            }
        };
        match &e.kind {
            EntityKind::PointIn3d { params }
            | EntityKind::PointNTrans { params, .. }
            | EntityKind::PointNRotTrans { params, .. } => {
                params.iter().for_each(|&p| push(p, out))
            }
            EntityKind::PointIn2d { params } => params.iter().for_each(|&p| push(p, out)),
            EntityKind::NormalIn3d { params } | EntityKind::NormalNRot { params, .. } => {
                params.iter().for_each(|&p| push(p, out))
            }
            EntityKind::Distance { param } => push(*param, out),
            EntityKind::NormalIn2d => {
                if let Some(EntityKind::Workplane { normal, .. }) = e
                    .workplane
                    .and_then(|w| self.sys.entity(w))
                    .map(|w| &w.kind)
                {
                    self.params(*normal, out, depth + 1);
                }
            }
            _ => {
                for (_, part) in parts(&e.kind) {
                    self.params(part, out, depth + 1);
                }
            }
        }
    }

    /// The unknown columns among an entity's parameters, and those parameters.
    fn cols(&self, h: EntityId) -> (Vec<u32>, Vec<ParamId>) {
        let mut ps = Vec::new();
        self.params(h, &mut ps, 0);
        let mut cols = Vec::new();
        let mut params = Vec::new();
        for p in ps {
            if let Some(i) = self.sys.param_index(p) {
                let c = self.eqs.col_of_param[i];
                if c != CONSTANT {
                    cols.push(c);
                    params.push(p);
                }
            }
        }
        (cols, params)
    }

    /// A basis vector over `cols` spread onto an entity's own coordinates `own` (zero where
    /// a coordinate is a constant).
    fn embed(&self, own: &[ParamId], params: &[ParamId], v: &[f64]) -> Vec<f64> {
        own.iter()
            .map(|p| params.iter().position(|q| q == p).map_or(0.0, |i| v[i]))
            .collect()
    }

    fn value(&self, p: ParamId) -> f64 {
        self.sys.param_index(p).map_or(0.0, |i| self.values[i])
    }

    /// How a point, a normal or a distance moves, given its span.
    fn leaf(&self, h: EntityId, span: &Span, params: &[ParamId]) -> Vec<Motion> {
        let Some(e) = self.sys.entity(h) else {
            return Vec::new();
        };
        let r = span.dof();
        if r == 0 {
            return Vec::new();
        }
        let mut own = Vec::new();
        self.params(h, &mut own, 0);
        match &e.kind {
            EntityKind::PointIn2d { .. }
            | EntityKind::PointIn3d { .. }
            | EntityKind::PointNTrans { .. }
            | EntityKind::PointNRotTrans { .. } => {
                let b: Vec<Vec<f64>> = span
                    .basis
                    .iter()
                    .map(|v| self.embed(&own, params, v))
                    .collect();
                match (own.len(), r) {
                    (_, 1) => vec![Motion::Along {
                        direction: direction(&b[0]),
                    }],
                    (3, 2) => vec![Motion::InPlane {
                        normal: direction3(cross(&b[0], &b[1])),
                    }],
                    (2, _) => vec![Motion::InItsPlane],
                    _ => vec![Motion::InSpace],
                }
            }
            EntityKind::NormalIn3d { .. }
            | EntityKind::NormalIn2d
            | EntityKind::NormalNRot { .. } => {
                if r == 1 && own.len() == 4 {
                    let q: Vec<f64> = own.iter().map(|&p| self.value(p)).collect();
                    let dq = self.embed(&own, params, &span.basis[0]);
                    vec![Motion::TurnAbout {
                        axis: direction3(angular_velocity(&q, &dq)),
                    }]
                } else {
                    vec![Motion::Turn { dof: r.min(3) }]
                }
            }
            EntityKind::Distance { .. } => vec![Motion::ValueFree],
            _ => vec![Motion::Coupled { dof: r }],
        }
    }

    /// The motions of any entity of the group.
    fn describe(&self, h: EntityId, span: &Span, params: &[ParamId]) -> Vec<Motion> {
        let Some(e) = self.sys.entity(h) else {
            return Vec::new();
        };
        let r = span.dof();
        if r == 0 {
            return Vec::new();
        }
        let ps = parts(&e.kind);
        if ps.is_empty() {
            return self.leaf(h, span, params);
        }
        if let (EntityKind::LineSegment { points }, 1) = (&e.kind, r) {
            if let Some(m) = self.line_motion(*points, span, params) {
                return vec![m];
            }
        }
        let mut out = Vec::new();
        let (mut sum, mut full) = (0, 0);
        for (role, part) in ps {
            let e = self.entry(part);
            if e.cols.is_empty() {
                continue;
            }
            full += full_dof(self.sys, part, e.cols.len());
            sum += e.span.dof();
            for m in self.leaf(part, &e.span, &e.params) {
                out.push(Motion::Part {
                    role: role.to_string(),
                    part,
                    motion: Box::new(m),
                });
            }
        }
        if r >= full && full > 0 {
            return vec![Motion::Free];
        }
        if sum > r {
            out.push(Motion::Coupled { dof: r });
        }
        out
    }

    /// A line with one motion: a pivot about an end, a slide, or a change of length.
    fn line_motion(
        &self,
        points: [EntityId; 2],
        span: &Span,
        params: &[ParamId],
    ) -> Option<Motion> {
        let own: Vec<Vec<ParamId>> = points
            .iter()
            .map(|&p| {
                let mut v = Vec::new();
                self.params(p, &mut v, 0);
                v
            })
            .collect();
        let (ea, eb) = (self.sys.entity(points[0])?, self.sys.entity(points[1])?);
        // Only ends in the same coordinates can be compared.
        if own[0].len() != own[1].len() || ea.workplane != eb.workplane {
            return None;
        }
        let da = self.embed(&own[0], params, &span.basis[0]);
        let db = self.embed(&own[1], params, &span.basis[0]);
        let pa: Vec<f64> = own[0].iter().map(|&p| self.value(p)).collect();
        let pb: Vec<f64> = own[1].iter().map(|&p| self.value(p)).collect();
        let d: Vec<f64> = pb.iter().zip(&pa).map(|(b, a)| b - a).collect();
        let (na, nb, nd) = (norm(&da), norm(&db), norm(&d));
        const EPS: f64 = 1e-6;
        let along = |v: &[f64], nv: f64| {
            nd > 0.0
                && (v.iter().zip(&d).map(|(a, b)| a * b).sum::<f64>().abs() - nv * nd).abs()
                    <= EPS * nv * nd
        };
        let across = |v: &[f64], nv: f64| {
            nd > 0.0 && v.iter().zip(&d).map(|(a, b)| a * b).sum::<f64>().abs() <= EPS * nv * nd
        };
        let end = |i: usize| if i == 0 { "start" } else { "end" }.to_string();
        for (i, (still, moving, nm)) in [(na, &db, nb), (nb, &da, na)].into_iter().enumerate() {
            if still <= EPS * nm {
                if across(moving, nm) {
                    return Some(Motion::PivotAbout {
                        end: end(i),
                        point: points[i],
                    });
                }
                if along(moving, nm) {
                    return Some(Motion::Stretch {
                        end: end(i),
                        point: points[i],
                    });
                }
            }
        }
        let diff: Vec<f64> = da.iter().zip(&db).map(|(a, b)| a - b).collect();
        if norm(&diff) <= EPS * na.max(nb) {
            return Some(Motion::Slide {
                direction: direction(&da),
            });
        }
        None
    }
}

/// The sub-entities of a composite entity, with their roles.
fn parts(kind: &EntityKind) -> Vec<(&'static str, EntityId)> {
    match kind {
        EntityKind::LineSegment { points } => vec![("start", points[0]), ("end", points[1])],
        EntityKind::Cubic { points } => vec![
            ("control point 1", points[0]),
            ("control point 2", points[1]),
            ("control point 3", points[2]),
            ("control point 4", points[3]),
        ],
        EntityKind::Circle {
            center,
            normal,
            radius,
        } => vec![
            ("centre", *center),
            ("normal", *normal),
            ("radius", *radius),
        ],
        EntityKind::ArcOfCircle {
            normal,
            center,
            start,
            end,
        } => vec![
            ("centre", *center),
            ("start", *start),
            ("end", *end),
            ("normal", *normal),
        ],
        EntityKind::Workplane { origin, normal } => vec![("origin", *origin), ("normal", *normal)],
        _ => Vec::new(),
    }
}

/// The most motions a leaf entity with `unknowns` unknown parameters can have.
fn full_dof(sys: &System, h: EntityId, unknowns: usize) -> usize {
    match sys.entity(h).map(|e| &e.kind) {
        // A unit quaternion turns three ways.
        Some(
            EntityKind::NormalIn3d { .. } | EntityKind::NormalIn2d | EntityKind::NormalNRot { .. },
        ) => unknowns.min(3),
        _ => unknowns,
    }
}

fn cross(a: &[f64], b: &[f64]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The rotation (axis times rate, in space) that changes the unit quaternion `q` by `dq`:
/// `ω = 2 vec(dq q*)`.
fn angular_velocity(q: &[f64], dq: &[f64]) -> [f64; 3] {
    let (w, x, y, z) = (q[0], -q[1], -q[2], -q[3]);
    let (a, b, c, d) = (dq[0], dq[1], dq[2], dq[3]);
    [
        2.0 * (a * x + b * w + c * z - d * y),
        2.0 * (a * y - b * z + c * w + d * x),
        2.0 * (a * z + b * y - c * x + d * w),
    ]
}

/// How every entity of `group` with unknowns can move, given the null-space samples.
pub(crate) fn freedoms(
    sys: &System,
    group: GroupId,
    eqs: &Equations,
    values: &[f64],
    vectors: &[Vec<f64>],
) -> Vec<EntityFreedom> {
    let ctx = Ctx {
        sys,
        eqs,
        values,
        vectors,
        seen: RefCell::new(HashMap::new()),
    };
    let mut out = Vec::new();
    for e in sys.entities() {
        if e.group != group {
            continue;
        }
        let entry = ctx.entry(e.h);
        if entry.cols.is_empty() {
            continue;
        }
        let motions = ctx.describe(e.h, &entry.span, &entry.params);
        out.push(EntityFreedom {
            entity: e.h,
            kind: e.entity_type(),
            dof: entry.span.dof(),
            motions,
            params: entry.params.clone(),
            basis: entry.span.basis.clone(),
            weights: entry.span.weights.clone(),
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn turning_about_z_is_seen_as_such() {
        // Identity orientation, turned about z: dq = (0, 0, 0, 1/2) per radian.
        let w = angular_velocity(&[1.0, 0.0, 0.0, 0.0], &[0.0, 0.0, 0.0, 0.5]);
        assert!((w[2] - 1.0).abs() < 1e-12 && w[0].abs() < 1e-12 && w[1].abs() < 1e-12);
    }

    #[test]
    fn orthonormalise_drops_dependent_vectors() {
        let v = orthonormalise(vec![vec![1.0, 0.0], vec![2.0, 0.0], vec![1.0, 1.0]], 5);
        assert_eq!(v.len(), 2);
        assert!((v[1][1] - 1.0).abs() < 1e-12);
    }
}
