//! Soft constraints: while solving, every line keeps its length and every arc its radius and
//! its start and end angles, except where user constraints already decide them. When the
//! sketch cannot hold them all, only those that a verified conflict shows in the way are
//! dropped; all are dropped only when that is not enough. They never outlive the solve.

use super::measure::wrap_deg;
use super::shapes::Geometry;
use super::{
    ArcId, LineId, PointId, ShapeId, Sketch, SketchConstraintId, SketchError, Spec, X_AXIS,
};
use crate::diagnose::Member;
use crate::model::{Constraint, ConstraintId, ConstraintKind as K, EntityId};
use crate::solve::{Outcome, Report};
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;

/// A soft constraint: what it keeps, of which shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(tag = "keeps", content = "shape", rename_all = "snake_case")]
pub enum Soft {
    /// A line's length.
    LineLength(LineId),
    /// An arc's radius.
    ArcRadius(ArcId),
    /// The direction of an arc's start from its centre.
    ArcStart(ArcId),
    /// The direction of an arc's end from its centre.
    ArcEnd(ArcId),
}

/// A soft constraint written into the system.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SoftRec {
    pub soft: Soft,
    pub core: ConstraintId,
    /// Positions in the parameter vector of the coordinates it reads: a line's ends, or an
    /// arc's centre and the end it keeps (the start for its radius), x then y.
    pub ix: [usize; 4],
}

/// The result of a sketch solve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SketchReport {
    /// How it ended. Redundancy among soft constraints alone is not reported.
    pub outcome: Outcome,
    /// The user constraints the core solver named (redundant, conflicting or unsatisfied),
    /// in the order added.
    pub failed: Vec<SketchConstraintId>,
    /// Soft constraints that held, each at its value as drawn.
    pub kept: Vec<Soft>,
    /// Soft constraints dropped because they stood in the way, or that a solve started again
    /// from elsewhere held at another value than the one drawn.
    pub dropped: Vec<Soft>,
    /// Newton iterations of the last solve.
    pub iterations: usize,
    /// Largest residual left.
    pub residual: f64,
}

impl Sketch {
    /// The soft constraints a solve adds now: one per line length, arc radius and arc end
    /// angle that no user constraint decides already.
    #[must_use]
    pub fn soft_constraints(&self) -> Vec<Soft> {
        let mut fixed: BTreeSet<PointId> = self.fixed_points().into_iter().collect();
        let mut sized: BTreeSet<EntityId> = BTreeSet::new();
        for (_, r) in self.constraints.iter().filter(|(_, r)| !r.reference) {
            match &r.spec {
                Spec::Length { line: s, .. }
                | Spec::Radius { shape: s, .. }
                | Spec::Diameter { shape: s, .. }
                | Spec::Lock { shape: s }
                | Spec::FixShape { shape: s } => {
                    sized.insert(s.0);
                }
                Spec::Fix { point } => {
                    fixed.insert(PointId(point.0));
                }
                _ => {}
            }
        }
        let mut out = Vec::new();
        for (h, s) in &self.shapes {
            if sized.contains(h) && !matches!(s.geometry, Geometry::Arc { .. }) {
                continue;
            }
            match &s.geometry {
                // A line between two fixed points has its length decided.
                Geometry::Line { points }
                    if !(fixed.contains(&points[0]) && fixed.contains(&points[1])) =>
                {
                    out.push(Soft::LineLength(LineId(*h)));
                }
                Geometry::Arc {
                    center, start, end, ..
                } => {
                    let locked = self.constraints.values().any(|r| {
                        !r.reference
                            && matches!(r.spec, Spec::Lock { shape } | Spec::FixShape { shape } if shape.0 == *h)
                    });
                    if locked {
                        continue;
                    }
                    let a = ArcId(*h);
                    if !sized.contains(h) {
                        out.push(Soft::ArcRadius(a));
                    }
                    let c = fixed.contains(center);
                    if !(c && fixed.contains(start)) {
                        out.push(Soft::ArcStart(a));
                    }
                    if !(c && fixed.contains(end)) {
                        out.push(Soft::ArcEnd(a));
                    }
                }
                _ => {}
            }
        }
        out
    }

    /// What a soft constraint keeps, as drawn now (a length, a radius, or an angle in
    /// degrees).
    pub(super) fn soft_value(&self, s: Soft) -> f64 {
        match s {
            Soft::LineLength(l) => {
                let [p, q] = self.line(l);
                (q[0] - p[0]).hypot(q[1] - p[1])
            }
            Soft::ArcRadius(a) => self.arc(a).radius,
            Soft::ArcStart(a) => self.arc(a).start_angle,
            Soft::ArcEnd(a) => self.arc(a).end_angle,
        }
    }

    /// Writes the soft constraints into the system at their current values. On an error,
    /// those already written are taken out again.
    pub(crate) fn add_soft(&mut self) -> Result<Vec<SoftRec>, SketchError> {
        let mut out = Vec::new();
        for s in self.soft_constraints() {
            let h = self.core_handle();
            let v = self.soft_value(s);
            let c = Constraint::new(h, Self::SHAPE_GROUP.0, K::PtPtDistance)
                .in_workplane(Some(super::WORKPLANE.0));
            let c = match s {
                Soft::LineLength(l) => {
                    let [a, b] = self.line_points(l);
                    Constraint {
                        kind: K::PtPtDistance,
                        pt_a: Some(a.0),
                        pt_b: Some(b.0),
                        val: v,
                        ..c
                    }
                }
                Soft::ArcRadius(a) => Constraint {
                    kind: K::Diameter,
                    entity_a: Some(a.0),
                    val: 2.0 * v,
                    ..c
                },
                Soft::ArcStart(a) | Soft::ArcEnd(a) => {
                    let Geometry::Arc { spokes, .. } = &self.shapes[&a.0].geometry else {
                        unreachable!("an arc")
                    };
                    let spoke = spokes[usize::from(matches!(s, Soft::ArcEnd(_)))];
                    Constraint {
                        kind: K::Angle,
                        entity_a: Some(X_AXIS),
                        entity_b: Some(spoke),
                        val: wrap_deg(v),
                        signed: true,
                        ..c
                    }
                }
            };
            match self.sys.add_constraint(c) {
                Ok(core) => {
                    let pts = match s {
                        Soft::LineLength(l) => self.line_points(l),
                        Soft::ArcRadius(a) | Soft::ArcStart(a) => {
                            let [c, st, _] = self.arc_points(a);
                            [c, st]
                        }
                        Soft::ArcEnd(a) => {
                            let [c, _, en] = self.arc_points(a);
                            [c, en]
                        }
                    };
                    let [a, b] = pts.map(|p| self.point_indexes(p));
                    out.push(SoftRec {
                        soft: s,
                        core,
                        ix: [a[0], a[1], b[0], b[1]],
                    });
                }
                Err(e) => {
                    self.remove_soft(&out);
                    return Err(e.into());
                }
            }
        }
        Ok(out)
    }

    /// Takes soft constraints out of the system (those already out are skipped).
    pub(crate) fn remove_soft(&mut self, recs: &[SoftRec]) {
        for r in recs {
            self.sys.remove_constraint(r.core);
        }
    }

    /// The values the soft constraints keep in the next solve: the shapes as drawn now.
    pub(crate) fn soft_values(&self, recs: &[SoftRec]) -> Vec<f64> {
        let v = self.sys.params();
        recs.iter()
            .map(|r| {
                let [ax, ay, bx, by] = r.ix.map(|i| v[i].val);
                let (dx, dy) = (bx - ax, by - ay);
                match r.soft {
                    Soft::LineLength(_) | Soft::ArcRadius(_) => dx.hypot(dy),
                    Soft::ArcStart(_) | Soft::ArcEnd(_) => dy.atan2(dx).to_degrees(),
                }
            })
            .collect()
    }

    /// Writes soft values (value edits).
    pub(crate) fn write_soft(&mut self, recs: &[SoftRec], values: &[f64]) {
        for (r, &v) in recs.iter().zip(values) {
            let val = match r.soft {
                Soft::LineLength(_) => v,
                Soft::ArcRadius(_) => 2.0 * v,
                // Both the axis and the spoke run backwards in the core (end to start, centre
                // to point): the angle between them is the arc's own.
                Soft::ArcStart(_) | Soft::ArcEnd(_) => wrap_deg(v),
            };
            // Most soft constraints of a drag keep their value from step to step: only
            // those that changed are written.
            if self
                .sys
                .constraint(r.core)
                .is_some_and(|c| c.val.to_bits() != val.to_bits())
            {
                if let Some(mut c) = self.sys.constraint_mut(r.core) {
                    c.val = val;
                }
            }
        }
    }

    /// Solves the sketch with its soft constraints (see the module's notes). Parameter values
    /// change only when every user constraint holds. A conflict is named only when its
    /// constraints fail in a sketch of their own too; where they hold, the sketch is solved
    /// again from there.
    ///
    /// # Errors
    /// The solver could not start (a bad setting in [`Sketch::set_config`]). No soft
    /// constraint is left in the system then either.
    pub fn solve(&mut self) -> Result<SketchReport, SketchError> {
        let first = self.solve_soft()?;
        self.recheck_conflict(first)
    }

    /// [`Sketch::solve`] without the check of a conflict it names.
    pub(super) fn solve_soft(&mut self) -> Result<SketchReport, SketchError> {
        if self.shapes.is_empty() {
            return Ok(SketchReport {
                outcome: Outcome::Okay,
                failed: Vec::new(),
                kept: Vec::new(),
                dropped: Vec::new(),
                iterations: 0,
                residual: 0.0,
            });
        }
        let mut soft = self.add_soft()?;
        let out = self.solve_with(&mut soft);
        self.remove_soft(&soft);
        if out.as_ref().is_ok_and(|r| r.outcome.is_ok()) {
            self.positive_radii(&self.circle_radii());
        }
        out
    }

    fn solve_once(&mut self, soft: &mut [SoftRec]) -> Result<Report, SketchError> {
        // Fixed points go back first: the lengths and angles soft constraints keep are those
        // of the drawing the solve starts from. Read before, a point moved off where it was
        // fixed gave its lines the lengths of the moved drawing in a first solve and the
        // fixed one in a second (after a soft constraint in the way was dropped), and the
        // line kept neither that it was reported to keep.
        self.restore_fixed();
        let values = self.soft_values(soft);
        self.write_soft(soft, &values);
        Ok(crate::solve(
            &mut self.sys,
            Self::SHAPE_GROUP,
            &[],
            &self.cfg,
        )?)
    }

    fn solve_with(&mut self, soft: &mut [SoftRec]) -> Result<SketchReport, SketchError> {
        let mut active: Vec<usize> = (0..soft.len()).collect();
        let mut dropped: Vec<Soft> = Vec::new();
        // Whether to diagnose the sketch for the soft constraint in the way: not once a
        // diagnosis has shown no set failing (see `in_the_way`).
        let mut diagnosing = self.cfg.name_conflicts;
        for _ in 0..8 {
            let r = self.solve_once(soft)?;
            if r.outcome.is_ok() || active.is_empty() {
                return Ok(self.report(&r, soft, &active, dropped));
            }
            let chosen = self.in_the_way(soft, &active, &r, &mut diagnosing)?;
            if chosen.is_empty() {
                break;
            }
            for i in &chosen {
                self.sys.remove_constraint(soft[*i].core);
                dropped.push(soft[*i].soft);
            }
            active.retain(|i| !chosen.contains(i));
        }
        // The soft constraints in the way could not be told apart: without any of them.
        for i in active.drain(..) {
            self.sys.remove_constraint(soft[i].core);
            dropped.push(soft[i].soft);
        }
        let r = self.solve_once(&mut [])?;
        Ok(self.report(&r, soft, &active, dropped))
    }

    /// One active soft constraint from each conflict set that has any: those checked by
    /// solving them alone first, the others only when no checked set has one.
    ///
    /// Without the failure checks (a caller that answers a failure itself, as the check of a
    /// named conflict does), the constraints the solve `r` found dependent stand in for the
    /// diagnosis's checked sets, whose checks cost many solves: the sketch of random seed 212,
    /// its conflict checked alone, spent 0.21 of its 0.32 s diagnosing that sketch of its own.
    /// Where the diagnosis shows no set failing (its solves of a set alone crept until their
    /// iterations ran out, say), the solve's list stands in the same way (the constraints it
    /// left unsatisfied), rather than every soft constraint dropped at once; and `diagnosing`
    /// turns off, as diagnosing the same sketch less one soft constraint shows nothing more
    /// (random sketch 123 spent 150 ms a round finding so).
    fn in_the_way(
        &self,
        soft: &[SoftRec],
        active: &[usize],
        r: &Report,
        diagnosing: &mut bool,
    ) -> Result<Vec<usize>, SketchError> {
        let of_the_solve = || {
            let members: Vec<Member> = r.failed.iter().map(|&c| Member::Constraint(c)).collect();
            self.pick(soft, active, &members, &[]).into_iter().collect()
        };
        if !*diagnosing {
            return Ok(of_the_solve());
        }
        let d = crate::diagnose(&self.sys, Self::SHAPE_GROUP, &self.cfg)?;
        for verified in [true, false] {
            let mut chosen: Vec<usize> = Vec::new();
            for set in d.conflicting.iter().filter(|s| s.verified == verified) {
                if let Some(pick) = self.pick(soft, active, &set.members, &chosen) {
                    chosen.push(pick);
                }
            }
            if !chosen.is_empty() {
                return Ok(chosen);
            }
        }
        if !d.conflicting.is_empty() {
            // The user constraints conflict among themselves: no soft constraint is in the way.
            return Ok(Vec::new());
        }
        *diagnosing = false;
        Ok(of_the_solve())
    }

    /// The active soft constraint to drop from a conflict of `members`, if it has one and none
    /// already `chosen`: the last whose shape no user constraint of the set names (the user
    /// spoke of the others), or the last.
    fn pick(
        &self,
        soft: &[SoftRec],
        active: &[usize],
        members: &[Member],
        chosen: &[usize],
    ) -> Option<usize> {
        let mine: Vec<usize> = active
            .iter()
            .copied()
            .filter(|&i| members.contains(&Member::Constraint(soft[i].core)))
            .collect();
        if mine.iter().any(|i| chosen.contains(i)) {
            return None;
        }
        let named: BTreeSet<EntityId> = members
            .iter()
            .filter_map(|m| match m {
                Member::Constraint(c) => self.owner.get(c),
                Member::Entity(_) => None,
            })
            .filter_map(|id| self.constraints.get(id))
            .flat_map(|r| {
                r.spec
                    .shapes()
                    .into_iter()
                    .map(|(_, s)| s.0)
                    .collect::<Vec<_>>()
            })
            .collect();
        mine.iter()
            .copied()
            .rev()
            .find(|&i| !named.contains(&soft_shape(soft[i].soft)))
            .or_else(|| mine.last().copied())
    }

    /// Of the user constraints `named` redundant in a solve with soft constraints, those still
    /// redundant without them. A user constraint that only agrees with what soft constraints
    /// keep (an equal radius on two arcs drawn alike) makes rows dependent, but the user's
    /// sketch holds nothing redundant: the soft constraints stand aside for it.
    fn redundant_without_soft(
        &self,
        named: &[ConstraintId],
        soft: &[SoftRec],
        active: &[usize],
    ) -> Vec<ConstraintId> {
        if !named.iter().any(|c| self.owner.contains_key(c)) {
            return named.to_vec();
        }
        let mut plain = self.sys.clone();
        for &i in active {
            plain.remove_constraint(soft[i].core);
        }
        let Ok(d) = crate::diagnose(&plain, Self::SHAPE_GROUP, &self.cfg) else {
            return named.to_vec();
        };
        let still: BTreeSet<ConstraintId> = d
            .redundant
            .iter()
            .flat_map(|set| set.members.iter().chain(&set.involved))
            .filter_map(|m| match m {
                Member::Constraint(c) => Some(*c),
                Member::Entity(_) => None,
            })
            .collect();
        named
            .iter()
            .copied()
            .filter(|c| still.contains(c))
            .collect()
    }

    fn report(
        &self,
        r: &Report,
        soft: &[SoftRec],
        active: &[usize],
        dropped: Vec<Soft>,
    ) -> SketchReport {
        let mut core_failed: Vec<ConstraintId> = r.failed.clone();
        if r.outcome == Outcome::RedundantOkay && !active.is_empty() {
            core_failed = self.redundant_without_soft(&core_failed, soft, active);
        }
        let failed: BTreeSet<SketchConstraintId> = core_failed
            .iter()
            .filter_map(|c| self.owner.get(c).copied())
            .collect();
        let outcome = match r.outcome {
            Outcome::RedundantOkay if failed.is_empty() => Outcome::Okay,
            o => o,
        };
        SketchReport {
            outcome,
            failed: failed.into_iter().collect(),
            kept: active.iter().map(|&i| soft[i].soft).collect(),
            dropped,
            iterations: r.iterations,
            residual: r.residual,
        }
    }
}

fn soft_shape(s: Soft) -> EntityId {
    match s {
        Soft::LineLength(l) => l.0,
        Soft::ArcRadius(a) | Soft::ArcStart(a) | Soft::ArcEnd(a) => a.0,
    }
}

impl From<Soft> for ShapeId {
    fn from(s: Soft) -> ShapeId {
        ShapeId(soft_shape(s))
    }
}
