//! A conflict named by a sketch solve, or what a solve that did not converge left unsatisfied,
//! is checked the way a user would check it: those constraints alone, in a sketch of their own
//! with the soft constraints every solve adds.
//!
//! The core checks a set before naming it by solving the set alone from the drawing and from
//! starts scattered about it. Without the soft constraints that keep the other lines' lengths,
//! a set that holds only once the drawing is scaled many times over escapes that check: a
//! right triangle whose hypotenuse must make 89.4 degrees with one leg while a circle of
//! radius 1.4 touches one end of that leg and its centre stays 6.1 from the other. Only a
//! locked length on the hypotenuse made it impossible (random sketch 31,931), and the lock
//! was left out of the named set; since, the core names no set there (its solves of the set
//! alone creep towards the far placement until their iterations run out, which shows
//! nothing) and the solve reads `did_not_converge`. Alone, with the soft constraints, the set
//! solves with the triangle 60 times its size. The whole sketch then starts again from there,
//! where the set holds and Newton meets what truly stands in the way.

use super::measure::wrap_deg;
use super::{Sketch, SketchConstraintId, SketchError, SketchReport, Soft};
use crate::solve::Outcome;
use std::collections::BTreeSet;

/// How many times a named set that holds alone sends the solve to start again from where the
/// set holds.
const RESTARTS: usize = 2;

/// How many levels down a set that fails alone is checked in turn ([`Sketch::solved_alone`]).
const NESTED: usize = 1;

/// How far, relative to its size (or to 1, if larger), a soft constraint's value may end from
/// the one drawn and still be reported kept ([`Sketch::kept_as_drawn`]): a solve holds what it
/// keeps to its tolerance, 1e-10.
const KEPT: f64 = 1e-8;

impl Sketch {
    /// `first`, the report of [`Sketch::solve_soft`], or, when the conflict it names (or the
    /// constraints it left unsatisfied) hold in a sketch of their own, the report of the
    /// sketch solved again from where they hold:
    /// a solution, or a conflict named from there. Where the set fails alone and its solve
    /// there names a part of it, that part is the conflict. Where the restarts end short of a
    /// solution, every constraint named or left unsatisfied on the way is solved alone, and a
    /// conflict named there is the sketch's: random sketch 50,704 moved off, an angle changed,
    /// read `did_not_converge`; nine constraints of its pentagon hold alone with the drawing 50
    /// times its size, and only with the equal length of two of its sides do they conflict,
    /// which no one set on the way showed. The drawing is left as it was unless a solve
    /// succeeds. Only with failure checks on ([`crate::Config::with_failure_checks`]).
    pub(super) fn recheck_conflict(
        &mut self,
        first: SketchReport,
    ) -> Result<SketchReport, SketchError> {
        self.recheck_nested(first, NESTED)
    }

    /// [`Sketch::recheck_conflict`], with sets checked alone `depth` levels down (see
    /// [`Sketch::solved_alone`]).
    fn recheck_nested(
        &mut self,
        first: SketchReport,
        depth: usize,
    ) -> Result<SketchReport, SketchError> {
        let mut r = first;
        if !self.cfg.name_conflicts || !failed_naming(&r) {
            return Ok(r);
        }
        // What the soft constraints keep as drawn: a solve started again from where a set
        // holds keeps the lengths and angles of that place.
        let as_drawn: Vec<(Soft, f64)> = self
            .soft_constraints()
            .into_iter()
            .map(|k| (k, self.soft_value(k)))
            .collect();
        // Every constraint named or left unsatisfied on the way: where the restarts end short
        // of a solution, the conflict may be among them all rather than in any one set.
        let mut seen: BTreeSet<SketchConstraintId> = BTreeSet::new();
        for _ in 0..RESTARTS {
            if !failed_naming(&r) {
                return Ok(r);
            }
            seen.extend(r.failed.iter().copied());
            let alone = match self.solved_alone(&r.failed, depth)? {
                Alone::Held(alone) => alone,
                Alone::Conflict(set) => return Ok(named(r, set)),
                Alone::Failed => break,
            };
            let drawn = self.values_from(&alone);
            let again = self.solve_soft()?;
            if again.outcome.is_ok() {
                return Ok(self.kept_as_drawn(again, &as_drawn));
            }
            for (v, d) in self.sys.values_mut().zip(drawn) {
                *v = d;
            }
            r = again;
        }
        if r.outcome != Outcome::DidNotConverge {
            return Ok(r);
        }
        seen.extend(r.failed.iter().copied());
        if seen.len() == r.failed.len() {
            return Ok(r);
        }
        let seen: Vec<SketchConstraintId> = seen.into_iter().collect();
        Ok(match self.solved_alone(&seen, depth)? {
            Alone::Conflict(set) => named(r, set),
            Alone::Held(_) | Alone::Failed => r,
        })
    }

    /// The constraints `set` alone, in a sketch of their own with the soft constraints every
    /// solve adds, solved if they hold there, or the part of them named a conflict there.
    ///
    /// Without the failure checks: the core ran them on the set before naming it, and what
    /// they miss is what the soft constraints add. A set that truly conflicts then costs one
    /// solve of its own (inconsistent sketches of random seeds 0-399: 34 ms on average where
    /// they took 25, against 42 with the checks). Where that solve fails and `depth` is not
    /// zero, the set is solved as a sketch is, with the checks and this recheck of what they
    /// name, one level down: nine constraints of a pentagon (random sketch 50,704 moved off,
    /// an angle changed) close only with the drawing 50 times its size; their solve alone
    /// left some unsatisfied, those held alone, and from there the nine hold. They were named
    /// a conflict. Solved without the checks at both levels, the nine failed again from where
    /// a part of them held.
    fn solved_alone(&self, set: &[SketchConstraintId], depth: usize) -> Result<Alone, SketchError> {
        let mut alone = self.clone();
        alone.cfg = self.cfg.clone().with_failure_checks(false);
        for &id in self.constraints.keys() {
            if !set.contains(&id) {
                alone.remove_constraint(id)?;
            }
        }
        if alone.solve_soft()?.outcome.is_ok() {
            return Ok(Alone::Held(Box::new(alone)));
        }
        if depth == 0 {
            return Ok(Alone::Failed);
        }
        alone.cfg = self.cfg.clone();
        let full = alone.solve_soft()?;
        let r = alone.recheck_nested(full, depth - 1)?;
        Ok(if r.outcome.is_ok() {
            Alone::Held(Box::new(alone))
        } else if r.outcome == Outcome::Inconsistent && !r.failed.is_empty() {
            Alone::Conflict(r.failed)
        } else {
            Alone::Failed
        })
    }

    /// `r`, a solve started again from where a set holds, with every soft constraint it kept
    /// whose value is no longer the one drawn (`as_drawn`) reported dropped instead: that
    /// solve kept the length or angle of the place it started from, not the user's. Random
    /// sketch 94,989 changed: a distance from a fixed point to a line went from 0 to 1, the two
    /// lines before it folded back on each other had to unfold, and the sketch solved from
    /// where the constraints in the way held, with line 107 1.019 long where it was drawn
    /// 4.166; it was reported kept.
    fn kept_as_drawn(&self, mut r: SketchReport, as_drawn: &[(Soft, f64)]) -> SketchReport {
        let (kept, moved): (Vec<Soft>, Vec<Soft>) = r.kept.iter().partition(|&&k| {
            as_drawn
                .iter()
                .find(|(s, _)| *s == k)
                .is_some_and(|&(_, drawn)| {
                    let now = self.soft_value(k);
                    let off = match k {
                        Soft::ArcStart(_) | Soft::ArcEnd(_) => wrap_deg(now - drawn).abs(),
                        _ => (now - drawn).abs(),
                    };
                    off <= KEPT * drawn.abs().max(1.0)
                })
        });
        r.kept = kept;
        r.dropped.extend(moved);
        r
    }

    /// Takes every parameter's value from `other` where it has that parameter; returns the
    /// values as they were.
    fn values_from(&mut self, other: &Sketch) -> Vec<f64> {
        let at: Vec<f64> = self
            .sys
            .params()
            .iter()
            .map(|p| other.sys.param(p.h).map_or(p.val, |q| q.val))
            .collect();
        let drawn: Vec<f64> = self.sys.params().iter().map(|p| p.val).collect();
        for (v, a) in self.sys.values_mut().zip(at) {
            *v = a;
        }
        drawn
    }
}

/// What solving a set of constraints alone ([`Sketch::solved_alone`]) found.
enum Alone {
    /// The set holds: the sketch of the set alone, solved.
    Held(Box<Sketch>),
    /// A part of the set conflicts, named by the solve of the set alone with the failure
    /// checks and checked there as every named conflict is: a conflict of any sketch that
    /// holds the set.
    Conflict(Vec<SketchConstraintId>),
    /// Neither.
    Failed,
}

/// Whether `r` failed and named constraints: those to check alone.
fn failed_naming(r: &SketchReport) -> bool {
    matches!(r.outcome, Outcome::Inconsistent | Outcome::DidNotConverge) && !r.failed.is_empty()
}

/// `r`, a solve that failed, reporting `set` as the conflict instead.
fn named(mut r: SketchReport, set: Vec<SketchConstraintId>) -> SketchReport {
    r.outcome = Outcome::Inconsistent;
    r.failed = set;
    r
}
