//! Grading each answer against the truth, never against either solver's word:
//!
//! - a claim of success is right only if the independent residual check ([`crate::check`])
//!   passes on the returned values;
//! - on a satisfiable system (base and redundant variants) a claim of inconsistency is wrong;
//! - on a conflicting system inconsistency is right, and loci's named set is checked by
//!   solving those constraints alone (same entities, same start): if they hold together the
//!   set is wrong; where it still fails without one of its members (the solve's list is the
//!   constraints on the dependence where it stopped, not promised minimal), the sets the
//!   diagnosis names are checked the same way, and a note says whether they are minimal;
//! - not converging, a crash or a refusal is a failure, not a wrong answer.
//!
//! [`resolve`] runs the same case through one [`loci::Solver`] several times (a second start,
//! a dimension switched to contradict and back, the fixed plane moved), grading each answer
//! the same way and comparing it with a fresh [`loci::solve`] of the same state.

use crate::case::Case;
use crate::check::{values_of, values_with, violations};
use crate::peer::{self, Answer};
use crate::sketch::GROUP;
use loci::{Config, ConstraintId, Outcome, Report, Solver, System};

#[derive(Clone, Debug, PartialEq)]
pub enum Grade {
    Right,
    /// A false claim: solved when it is not, or in conflict when it is not.
    Wrong(String),
    /// No claim: did not converge, crashed, refused.
    Failed(String),
}

impl Grade {
    pub fn is_right(&self) -> bool {
        *self == Grade::Right
    }
}

fn handles(list: &[ConstraintId]) -> String {
    let v: Vec<String> = list.iter().map(|c| c.0.to_string()).collect();
    format!("[{}]", v.join(","))
}

pub fn loci_said(r: &Report) -> String {
    format!(
        "{} (dof {}, failed {})",
        r.outcome,
        r.dof,
        handles(&r.failed)
    )
}

/// The grade of a claim of success: right if every condition holds on `sys`'s values.
fn grade_solved(case: &Case, sys: &System, claim: &str, satisfiable: bool) -> Grade {
    let bad = violations(sys, &values_of(sys), case.size);
    if let Some((what, r)) = bad.first() {
        return Grade::Wrong(format!("{claim}, but {what} is off by {r:.1e}"));
    }
    assert!(
        satisfiable,
        "generator bug: seed {} ({}) is solved although built to conflict",
        case.seed,
        case.label()
    );
    Grade::Right
}

/// Solves `sys` with only the constraints `keep`, from the same start: loci's answer and
/// whether the check then passes.
fn solve_alone(sys: &System, keep: &[ConstraintId], size: f64) -> (Outcome, bool) {
    let mut sub = sys.clone();
    let drop: Vec<ConstraintId> = sub
        .constraints()
        .iter()
        .map(|c| c.h)
        .filter(|h| !keep.contains(h))
        .collect();
    for h in drop {
        sub.remove_constraint(h);
    }
    match loci::solve(&mut sub, GROUP.into(), &[], &Config::default()) {
        Ok(r) => {
            let holds = r.outcome.is_ok() && violations(&sub, &values_of(&sub), size).is_empty();
            (r.outcome, holds)
        }
        Err(_) => (Outcome::DidNotConverge, false),
    }
}

/// Whether every set with one member of `set` less holds alone.
fn minimal(case: &Case, set: &[ConstraintId]) -> bool {
    set.iter().all(|m| {
        let rest: Vec<ConstraintId> = set.iter().copied().filter(|c| c != m).collect();
        solve_alone(&case.system, &rest, case.size).1
    })
}

/// A note on a case whose solve named more constraints than a conflict needs. The solve's
/// list is the constraints on the dependence where it stopped (SolveSpace's is of the same
/// kind), not promised minimal; naming the guilty constraints is the diagnosis's work
/// (`loci::diagnose`), whose sets are checked here the same way: each fails alone and holds
/// without any one member. Where one does not, the note says so: a finding.
fn diagnosed_sets(case: &Case) -> String {
    let d = match loci::diagnose(&case.system, GROUP.into(), &Config::default()) {
        Ok(d) => d,
        Err(e) => return format!("conflict set of the diagnosis: error {e}"),
    };
    let sets: Vec<Vec<ConstraintId>> = d
        .conflicting
        .iter()
        .map(|c| {
            c.members
                .iter()
                .filter_map(|m| match m {
                    loci::Member::Constraint(c) => Some(*c),
                    loci::Member::Entity(_) => None,
                })
                .collect()
        })
        .collect();
    let bad: Vec<String> = sets
        .iter()
        .filter(|set| solve_alone(&case.system, set, case.size).1 || !minimal(case, set))
        .map(|set| handles(set))
        .collect();
    match (sets.is_empty(), bad.is_empty()) {
        (true, _) => "solver's list not minimal; the diagnosis names no conflict".into(),
        (false, true) => "solver's list not minimal; the diagnosis's sets are".into(),
        (false, false) => format!(
            "conflict set of the diagnosis {} not minimal",
            bad.join(" ")
        ),
    }
}

/// loci on the case with `loci::solve`: its grade, what it said, and notes.
pub fn loci(case: &Case) -> (Grade, String, Vec<String>) {
    let mut sys = case.system.clone();
    let r = match loci::solve(&mut sys, GROUP.into(), &[], &Config::default()) {
        Ok(r) => r,
        Err(e) => {
            return (
                Grade::Wrong(format!("error: {e}")),
                format!("error: {e}"),
                vec![],
            )
        }
    };
    let said = loci_said(&r);
    let mut notes = Vec::new();
    let grade = match r.outcome {
        Outcome::Okay | Outcome::RedundantOkay => {
            if case.variant == crate::case::Variant::Redundant && r.outcome == Outcome::Okay {
                notes.push("redundancy not reported".to_string());
            }
            grade_solved(case, &sys, r.outcome.name(), case.satisfiable())
        }
        Outcome::DidNotConverge => {
            Grade::Failed(format!("did_not_converge (residual {:.1e})", r.residual))
        }
        Outcome::Inconsistent => {
            let set = &r.failed;
            let (alone, holds) = solve_alone(&case.system, set, case.size);
            if case.satisfiable() {
                let why = if holds {
                    "; they hold together alone"
                } else {
                    ""
                };
                Grade::Wrong(format!(
                    "calls a satisfiable system inconsistent, naming {}{why}",
                    handles(set)
                ))
            } else if set.is_empty() {
                Grade::Wrong("inconsistent, but names no constraint".into())
            } else if holds {
                Grade::Wrong(format!(
                    "names {} in conflict, but they hold together alone",
                    handles(set)
                ))
            } else if alone.is_ok() {
                Grade::Wrong(format!(
                    "names {}; solving them alone claims {alone} but breaks the check",
                    handles(set)
                ))
            } else {
                if set.len() <= 8 && !minimal(case, set) {
                    notes.push(diagnosed_sets(case));
                }
                Grade::Right
            }
        }
    };
    (grade, said, notes)
}

/// SolveSpace's answer: its grade and what it said.
pub fn solvespace(case: &Case, a: &Answer) -> (Grade, String) {
    match a {
        Answer::Broken(why) => (Grade::Failed(why.clone()), why.clone()),
        Answer::Solved {
            result,
            dof,
            failed,
            values,
        } => {
            let name = match *result {
                peer::OKAY => "okay",
                peer::INCONSISTENT => "inconsistent",
                2 => "did_not_converge",
                3 => "too_many_unknowns",
                peer::REDUNDANT_OKAY => "redundant_okay",
                _ => "unknown result",
            };
            let said = format!("{name} (dof {dof}, failed {})", handles(failed));
            let grade = match *result {
                peer::OKAY | peer::REDUNDANT_OKAY => {
                    let mut sys = case.system.clone();
                    for (p, v) in values_with(&case.system, values) {
                        sys.set_value(p, v);
                    }
                    grade_solved(case, &sys, name, case.satisfiable())
                }
                peer::INCONSISTENT if case.satisfiable() => Grade::Wrong(format!(
                    "calls a satisfiable system inconsistent, naming {}",
                    handles(failed)
                )),
                peer::INCONSISTENT => Grade::Right,
                _ => Grade::Failed(name.to_string()),
            };
            (grade, said)
        }
    }
}

/// A problem found by [`resolve`].
pub struct Resolve {
    /// A false claim (else the verdict only differs from a fresh solve's).
    pub wrong: bool,
    pub what: String,
}

/// The grade of one solve (without checking a named conflict set) for the current truth.
fn grade_light(case: &Case, sys: &System, r: &Report, satisfiable: bool) -> Grade {
    match r.outcome {
        Outcome::Okay | Outcome::RedundantOkay => {
            let bad = violations(sys, &values_of(sys), case.size);
            match bad.first() {
                Some((what, x)) => Grade::Wrong(format!(
                    "claims {}, but {what} is off by {x:.1e}",
                    r.outcome
                )),
                None if !satisfiable => Grade::Wrong("solved a contradiction".into()),
                None => Grade::Right,
            }
        }
        Outcome::Inconsistent if satisfiable => {
            Grade::Wrong("calls a satisfiable system inconsistent".into())
        }
        Outcome::Inconsistent => Grade::Right,
        Outcome::DidNotConverge => Grade::Failed("did_not_converge".into()),
    }
}

/// One solve through a reused [`Solver`], checked against the truth and against a fresh
/// solve of the same state (itself checked too); `None` when all is fine.
fn resolve_step(
    case: &Case,
    solver: &mut Solver,
    sys: &mut System,
    satisfiable: bool,
    step: &str,
) -> Option<Resolve> {
    let mut fresh_sys = sys.clone();
    let fresh = loci::solve(&mut fresh_sys, GROUP.into(), &[], &Config::default()).ok()?;
    let r = match solver.solve(sys) {
        Ok(r) => r,
        Err(e) => {
            return Some(Resolve {
                wrong: true,
                what: format!("{step}: error {e}"),
            })
        }
    };
    if let Grade::Wrong(why) = grade_light(case, sys, &r, satisfiable) {
        let fresh_grade = match grade_light(case, &fresh_sys, &fresh, satisfiable) {
            Grade::Right => "right".to_string(),
            Grade::Wrong(w) | Grade::Failed(w) => w,
        };
        return Some(Resolve {
            wrong: true,
            what: format!(
                "{step}: the Solver {why} ({}); a fresh solve says {} -- {fresh_grade}",
                loci_said(&r),
                loci_said(&fresh)
            ),
        });
    }
    if let Grade::Wrong(why) = grade_light(case, &fresh_sys, &fresh, satisfiable) {
        return Some(Resolve {
            wrong: true,
            what: format!(
                "{step}: a fresh loci::solve {why} ({}); the Solver says {}",
                loci_said(&fresh),
                loci_said(&r)
            ),
        });
    }
    (r.outcome != fresh.outcome).then(|| Resolve {
        wrong: false,
        what: format!(
            "{step}: Solver says {} where a fresh solve says {}",
            loci_said(&r),
            loci_said(&fresh)
        ),
    })
}

/// The case through one reused [`Solver`]: from the start, from a second start, with its
/// switchable dimension set the other way and back, with the fixed plane moved. The first
/// problem found.
pub fn resolve(case: &Case) -> Option<Resolve> {
    let mut solver = Solver::new(GROUP, &[], Config::default());
    let mut sys = case.system.clone();
    let start: Vec<_> = case
        .truth
        .iter()
        .map(|&(p, _)| (p, case.system.value(p).unwrap()))
        .collect();
    let reset = |sys: &mut System, to: &[(loci::ParamId, f64)]| {
        for &(p, v) in to {
            sys.set_value(p, v);
        }
    };
    let sat = case.satisfiable();
    if let Some(p) = resolve_step(case, &mut solver, &mut sys, sat, "first solve") {
        return Some(p);
    }
    reset(&mut sys, &case.restart);
    if let Some(p) = resolve_step(case, &mut solver, &mut sys, sat, "second start") {
        return Some(p);
    }
    if let Some((h, good, bad)) = case.switch {
        let (other, back) = if sat { (bad, good) } else { (good, bad) };
        for (val, sat, step) in [
            (other, !sat, "value switched"),
            (back, sat, "value switched back"),
        ] {
            sys.constraint_mut(h).expect("the switched constraint").val = val;
            reset(&mut sys, &start);
            if let Some(p) = resolve_step(case, &mut solver, &mut sys, sat, step) {
                return Some(p);
            }
        }
    }
    // The fixed plane moved: every constraint is unchanged by a translation of everything,
    // so the truth moved with it still holds (and a contradiction stays one).
    let origin = sys
        .entities()
        .iter()
        .find_map(|e| match e.kind {
            loci::EntityKind::Workplane { origin, .. } => Some(origin),
            _ => None,
        })
        .and_then(|o| sys.entity(o))
        .map(|e| e.kind.params().to_vec())
        .expect("the plane's origin");
    for (k, p) in origin.into_iter().enumerate() {
        let v = sys.value(p).unwrap();
        sys.set_value(p, v + [1.5, -2.0, 0.75][k] * case.scale);
    }
    reset(&mut sys, &start);
    resolve_step(case, &mut solver, &mut sys, sat, "plane moved")
}
