//! The stepped mode: the seed's relaxation, one mate at a time (Gauss–Seidel), each nudging
//! its components by a capped, gain-scaled rotation and then a translation, so that a
//! program can animate the parts moving into place. It shares the mates' primitive relations
//! and measurements with the simultaneous solve.

use super::component::Pose;
use super::mate::AppliedRotation;
use super::math::{self, Q4, V3};
use super::prim::{line_offset, plane_offset, signed_angle, wrap, Body, Prim, World};
use super::{measure, Assembly, AssemblyError, MateReport, SteppedRun};
use serde::{Deserialize, Serialize};

/// One iteration of the stepped mode: where every component is after it, and how far each
/// mate is from holding.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Iteration {
    /// 1 for the first pass.
    pub index: usize,
    /// Every component's pose, in the assembly's order.
    pub poses: Vec<Pose>,
    /// Per mate, in the assembly's order: its largest error (length, or radians).
    pub errors: Vec<f64>,
}

/// Settings of one pass.
pub(crate) struct StepSettings {
    pub rotation_gain: f64,
    pub max_rotation: f64,
}

/// The rotation taking unit `from` toward unit `to`: the shortest one, scaled by `gain`
/// and capped at `cap` (the seed's `computeRotationTowards`); `None` when already there.
pub(crate) fn rotation_towards(from: V3, to: V3, gain: f64, cap: f64) -> Option<Q4> {
    let angle = math::angle_between(from, to);
    if !angle.is_finite() || angle <= 1e-12 {
        return None;
    }
    let axis = math::unit(math::cross(from, to)).unwrap_or_else(|| math::perpendicular(from));
    let applied = (angle * gain.clamp(0.0, 1.0)).min(cap).min(angle);
    (applied > 1e-12).then(|| math::axis_angle(axis, applied))
}

/// Applies one mate's primitive relations once: rotations first, then translations, each
/// split evenly when both bodies can move and all on the movable one otherwise. Returns the
/// rotations applied.
pub(crate) fn step_prims(
    prims: &[Prim],
    poses: &mut [Pose],
    movable: &[bool],
    names: &[String],
    s: &StepSettings,
) -> Vec<AppliedRotation> {
    let mut applied = Vec::new();
    let can = |b: Body| b.is_some_and(|i| movable[i]);
    for prim in prims {
        let (ba, bb) = prim.bodies();
        let (ma, mb) = (can(ba), can(bb));
        if !ma && !mb {
            continue;
        }
        let (sa, sb) = match (ma, mb) {
            (true, true) => (0.5, 0.5),
            (true, false) => (1.0, 0.0),
            _ => (0.0, 1.0),
        };
        let w = World { poses };
        // Rotations: the targets for each body's direction.
        let mut turns: Vec<(Body, V3, V3, f64)> = Vec::new();
        match *prim {
            Prim::Parallel(a, b, flip) => {
                let (da, db) = (w.dir(&a), w.dir(&b));
                let sign = if flip { -1.0 } else { 1.0 };
                turns.push((ba, da, math::scale(db, sign), sa));
                turns.push((bb, db, math::scale(da, sign), sb));
            }
            Prim::Perpendicular(a, b) => {
                let (da, db) = (w.dir(&a), w.dir(&b));
                let c = math::dot(da, db);
                if let Some(t) = math::unit(math::sub(db, math::scale(da, c))) {
                    turns.push((bb, db, t, sb));
                }
                if let Some(t) = math::unit(math::sub(da, math::scale(db, c))) {
                    turns.push((ba, da, t, sa));
                }
            }
            Prim::SignedAngle { a, b, axis, target } => {
                let (da, db) = (w.dir(&a), w.dir(&b));
                let n = w.pose(a.body).direction(axis);
                let u = math::cross(n, da);
                let phi = signed_angle(da, db, n);
                let delta = wrap(phi - target);
                let at = |angle: f64| {
                    math::add(math::scale(da, angle.cos()), math::scale(u, angle.sin()))
                };
                // The seed's split: half of the correction each, or all on the movable one.
                let (ta, tb) = match (ma, mb) {
                    (true, true) => (delta / 2.0, phi - delta / 2.0),
                    (true, false) => (phi - target, phi),
                    _ => (0.0, target),
                };
                // Directions off the plane normal to the axis keep their height along it.
                let h = math::dot(db, n);
                let r = (1.0 - h * h).max(0.0).sqrt();
                // As in the seed, each share also scales the gain.
                if ma {
                    turns.push((ba, da, at(ta), sa));
                }
                if mb {
                    let t = math::add(math::scale(at(tb), r), math::scale(n, h));
                    turns.push((bb, db, t, sb));
                }
            }
            Prim::SameOrientation(a, b, rel) => {
                let want = math::qmul(w.pose(a).rotation, rel);
                let have = w.pose(b).rotation;
                // The error rotation e with e·have = want, as an axis and angle.
                let mut e = math::qmul(want, math::qconj(have));
                if e[0] < 0.0 {
                    e = e.map(|x| -x);
                }
                let v = [e[1], e[2], e[3]];
                if let Some(axis) = math::unit(v) {
                    let angle = 2.0 * math::norm(v).atan2(e[0]);
                    for (body, share, sign) in [(bb, sb, 1.0), (ba, sa, -1.0)] {
                        let turn = (angle * share * s.rotation_gain).min(s.max_rotation);
                        if share > 0.0 && turn > 1e-12 {
                            let q = math::axis_angle(math::scale(axis, sign), turn);
                            apply(poses, body, q, names, &mut applied);
                        }
                    }
                }
                continue;
            }
            _ => {}
        }
        for (body, from, to, share) in turns {
            if share <= 0.0 || !can(body) {
                continue;
            }
            if let Some(q) = rotation_towards(from, to, s.rotation_gain * share, s.max_rotation) {
                apply(poses, body, q, names, &mut applied);
            }
        }
        // Translations: B's point moves by `v`, A's by `-v`, shared.
        let w = World { poses };
        let v: Option<V3> = match prim {
            Prim::Coincident(a, b) => Some(math::sub(w.point(a), w.point(b))),
            Prim::InPlane(p, l) => Some(math::scale(w.dir(&l.dir()), -plane_offset(&w, p, l))),
            Prim::PtPlaneDistance(p, l, d) => {
                Some(math::scale(w.dir(&l.dir()), d - plane_offset(&w, p, l)))
            }
            Prim::OnLine(p, l) | Prim::PtLineDistance(p, l, _) => {
                let want = if let Prim::PtLineDistance(_, _, d) = prim {
                    *d
                } else {
                    0.0
                };
                let dir = w.dir(&l.dir());
                let rel = math::sub(w.point(p), w.point(&l.point()));
                let radial = math::sub(rel, math::scale(dir, math::dot(rel, dir)));
                let off = line_offset(&w, p, l);
                math::unit(radial)
                    .map(|r| math::scale(r, want - off))
                    .or(Some([0.0; 3]))
            }
            Prim::PtPtDistance(a, b, d) => {
                let rel = math::sub(w.point(b), w.point(a));
                let r = math::unit(rel).unwrap_or([1.0, 0.0, 0.0]);
                Some(math::scale(r, d - math::norm(rel)))
            }
            _ => None,
        };
        if let Some(v) = v {
            // For point–plane and point–line relations the point is on the second body.
            let (pb, lb) = match prim {
                Prim::InPlane(p, l)
                | Prim::OnLine(p, l)
                | Prim::PtPlaneDistance(p, l, _)
                | Prim::PtLineDistance(p, l, _) => (p.body, l.body),
                _ => (bb, ba),
            };
            let (mp, ml) = (can(pb), can(lb));
            let (sp, sl) = match (mp, ml) {
                (true, true) => (0.5, 0.5),
                (true, false) => (1.0, 0.0),
                _ => (0.0, 1.0),
            };
            if let Some(i) = pb.filter(|_| mp) {
                poses[i].translation = math::add(poses[i].translation, math::scale(v, sp));
            }
            if let Some(i) = lb.filter(|_| ml) {
                poses[i].translation = math::sub(poses[i].translation, math::scale(v, sl));
            }
        }
    }
    applied
}

fn apply(poses: &mut [Pose], body: Body, q: Q4, names: &[String], out: &mut Vec<AppliedRotation>) {
    let Some(i) = body else { return };
    let p = poses[i];
    poses[i] = Pose::new(p.translation, math::qmul(q, p.rotation));
    out.push(AppliedRotation {
        component: names[i].clone(),
        quaternion: q,
    });
}

impl Assembly {
    /// The seed's stepped relaxation: passes over the mates in order, each applying its
    /// capped, gain-scaled rotations and its translations, until every mate is within
    /// tolerance or [`super::Options::max_steps`] passes. Each pass is reported with the poses
    /// and every mate's error; each mate's rotations of the last pass are kept in its
    /// `persistent.last_applied_rotations`. The components end where the last pass left them.
    ///
    /// # Errors
    /// A malformed assembly.
    pub fn solve_stepped(&mut self) -> Result<SteppedRun, AssemblyError> {
        self.check()?;
        let compiled = self.compile_all();
        let movable = self.movable();
        let names: Vec<String> = self.components.iter().map(|c| c.name.clone()).collect();
        let mut poses = self.poses();
        let s = StepSettings {
            rotation_gain: self.options.rotation_gain.clamp(0.0, 1.0),
            max_rotation: self.options.max_rotation_per_iteration,
        };
        let tol = self.options.step_tolerance.max(self.position_tol());
        let atol = self.angle_tol().max(tol);
        let errors = |poses: &[Pose]| -> (Vec<f64>, bool) {
            let w = World { poses };
            let mut all = true;
            let e = compiled
                .iter()
                .map(|c| match c {
                    Ok(p) => p
                        .iter()
                        .map(|x| {
                            let e = x.error(&w);
                            let (a, b) = x.bodies();
                            let can =
                                a.is_some_and(|i| movable[i]) || b.is_some_and(|i| movable[i]);
                            if can && e > if x.is_angular() { atol } else { tol } {
                                all = false;
                            }
                            e
                        })
                        .fold(0.0, f64::max),
                    Err(_) => f64::NAN,
                })
                .collect();
            (e, all)
        };
        let mut iterations = Vec::new();
        let (_, mut converged) = errors(&poses);
        let mut index = 0;
        while !converged && index < self.options.max_steps {
            index += 1;
            for (i, c) in compiled.iter().enumerate() {
                if let Ok(p) = c {
                    self.mates[i].persistent.last_applied_rotations =
                        step_prims(p, &mut poses, &movable, &names, &s);
                }
            }
            let (e, ok) = errors(&poses);
            converged = ok;
            iterations.push(Iteration {
                index,
                poses: poses.clone(),
                errors: e,
            });
        }
        for (c, p) in self.components.iter_mut().zip(&poses) {
            c.pose = *p;
        }
        for (i, c) in compiled.iter().enumerate() {
            if let Ok(p) = c {
                let mut r = MateReport::unmeasured(String::new(), String::new());
                measure(&mut self.mates[i], p, &poses, &mut r);
            }
        }
        Ok(SteppedRun {
            iterations,
            converged,
        })
    }
}
