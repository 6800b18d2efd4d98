//! Diagnosis: what is wrong with a group, and where.
//!
//! 1. **Counting.** A maximum matching of equations to unknowns finds blocks with more
//!    equations than unknowns before any numerics ([`structure`]).
//! 2. **Solving.** The group is solved as [`crate::solve`] would, without changing the system.
//! 3. **Circuits.** Where the solve stopped, the equations — unmerged, so that equalities
//!    such as `horizontal` or `points_coincident` are rows that can be named — are factorised
//!    with the solver's rank-revealing LDLᵀ. Each dependent row and the rows it is a
//!    combination of form a minimal dependent set ([`circuits`]): redundant when its residuals
//!    agree, conflicting when they do not. Conflicts are checked, and shrunk to minimal sets
//!    of constraints, by solving them on their own ([`minimal`]); redundant circuits that
//!    overlap are grouped ([`redundant`]).
//! 4. **Freedom.** The null space of the Jacobian, sampled through the same factorisation,
//!    says how each entity can still move ([`freedom`]).
//! 5. **Measurements** of reference constraints ([`measure`]).

mod circuits;
mod construct;
mod eigen;
mod focus;
mod freedom;
mod groups;
mod measure;
mod minimal;
#[cfg(test)]
mod minimal_tests;
mod motion;
mod redundant;
mod remembered;
mod report;
mod shrunk;
mod structure;
#[cfg(test)]
mod tests;
mod unmerged;

pub(crate) use construct::{construct_group, Rescue};
pub use groups::minimal_groups;
pub use motion::Motion;
pub use report::{
    ConflictSet, Diagnosis, EntityFreedom, Measurement, Member, OverConstrained, RedundantSet,
};

use crate::equations::{Kernel, Link, Owner};
use crate::error::SolveError;
use crate::model::{GroupId, System};
use crate::solve::{solve_core, Config, Outcome, Report, Scattered};
use circuits::{Circuit, Rank};
use remembered::{remembered, Alone};
use report::NullSketch;
use shrunk::Shrunk;
use std::collections::HashSet;
use unmerged::{Equations, Linear};

/// Diagnoses `group` of `sys`: counts, solves (without changing `sys`), and reports degrees of
/// freedom entity by entity, redundant and conflicting constraints, and the values of
/// reference constraints.
///
/// # Errors
/// An invalid model or a bad option, as [`crate::solve`].
pub fn diagnose(sys: &System, group: GroupId, cfg: &Config) -> Result<Diagnosis, SolveError> {
    diagnosed(sys, group, cfg, true)
}

/// [`diagnose`]; `elsewhere`: whether it may diagnose the sketch at a solution found from
/// where a set it dropped holds, rather than where the solve stopped.
fn diagnosed(
    sys: &System,
    group: GroupId,
    cfg: &Config,
    elsewhere: bool,
) -> Result<Diagnosis, SolveError> {
    cfg.check()?;
    sys.validate()?;
    let cfg = &*cfg.for_group(sys, group);
    let start: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
    let eqs = Equations::new(sys, group, &start)?;

    // 1. Counting, on the pattern of the Jacobian at a generic point near the start (where no
    // derivative vanishes by accident, as the vertical one of a horizontal distance does).
    let structural = {
        let generic = eqs.linearise(&perturbed(&eqs, &start));
        structure::over_constrained(&eqs, &structure::pattern(&eqs, &generic))
    };

    // 2. Solve; the lists are ours to make.
    let (report, values) = solve_core(sys, group, &[], &cfg.clone().with_find_failed(false))?;

    // 3. Circuits where it stopped.
    let lin = eqs.linearise(&values);
    let mut rank = Rank::new(&eqs, &lin, cfg);
    let circuits = match rank.as_mut() {
        Some(r) => circuits::circuits(&eqs, &lin, r, cfg),
        None => Vec::new(),
    };
    // Conflicts are looked for off a point where an equation that does not hold has no
    // gradient (see there); everything else is read where the solve stopped.
    let moved = eqs.linearise_off_singular(&values, &lin, cfg.tolerance);
    let moved_circuits = moved
        .as_ref()
        .map(|m| match Rank::new(&eqs, m, cfg).as_mut() {
            Some(r) => circuits::circuits(&eqs, m, r, cfg),
            None => Vec::new(),
        });
    // As the solve names them: none that holds alone by the solve's rescues or from random
    // starts, searched again from where a dropped set holds ([`searched_again`]).
    let mut shrunk = Shrunk::default();
    let (mut conflicting, found) = searched_again(&[&values, &start], |starts, solutions| {
        let (mut conflicting, _) = conflict_sets(
            &eqs,
            moved.as_ref().unwrap_or(&lin),
            moved_circuits.as_ref().unwrap_or(&circuits),
            starts,
            report.outcome,
            cfg,
            usize::MAX,
            &mut shrunk,
        );
        if ran_off(&eqs, &start, report.residual) {
            conflicting.retain(|s| s.members.len() <= minimal::LARGE_SET);
        }
        let failed = !report.outcome.is_ok();
        let mut whole = || failed.then(|| whole_shrunk(&eqs, starts, cfg)).flatten();
        failing_alone_or_whole(sys, group, conflicting, &mut whole, cfg, &shrunk, solutions).0
    });
    // Nothing fails, and the whole solves from where a set dropped above holds: the solve
    // finds that solution too ([`crate::solve`]), and the diagnosis is of the sketch there.
    if elsewhere && !report.outcome.is_ok() && conflicting.is_empty() {
        if let Some(at) = crate::solve::solution_further_off(sys, group, cfg, &found) {
            let mut solved = sys.clone();
            solved.write_group_values(group, &at);
            let mut there = diagnosed(&solved, group, cfg, false)?;
            if there.outcome.is_ok() {
                there.iterations += report.iterations;
                return Ok(there);
            }
        }
    }
    let tolerance = rank.as_ref().map_or(cfg.rank_tolerance, |r| r.tolerance);
    let mut redundant = redundant::redundant_sets(&eqs, &lin, &circuits, tolerance);
    // Constraints written more than once never reach the equations: each copy is redundant.
    for (first, copies) in crate::equations::duplicate_groups(sys, group) {
        let mut members: Vec<Member> = std::iter::once(first)
            .chain(copies.iter().copied())
            .map(Member::Constraint)
            .collect();
        members.sort_by(Member::report_order);
        redundant.push(RedundantSet {
            members,
            excess: copies.len(),
            involved: Vec::new(),
        });
    }
    let mut outcome = report.outcome;
    if outcome == Outcome::DidNotConverge && !conflicting.is_empty() {
        outcome = Outcome::Inconsistent;
    }
    if outcome == Outcome::Okay && !redundant.is_empty() {
        outcome = Outcome::RedundantOkay;
    }
    // A conflict is only reported once a set of constraints is shown to fail on its own. The
    // search here and the solver's (which starts from the constraints it found dependent) can
    // find different sets; when this one finds none, the solver's checked verdict stands: its
    // sets, or did_not_converge when none of them failed on its own either.
    if outcome == Outcome::Inconsistent && conflicting.is_empty() {
        let r = crate::solve::solve(
            &mut sys.clone(),
            group,
            &[],
            &cfg.clone().with_find_failed(true),
        )?;
        let members = solver_members(&r);
        if r.outcome == Outcome::Inconsistent && !members.is_empty() {
            conflicting.push(ConflictSet {
                members,
                verified: false,
            });
        } else {
            outcome = Outcome::DidNotConverge;
        }
    }
    // The numbers here and the solver's can disagree at the edge of the rank tolerance; the
    // solver's own list then stands in, so that a redundancy never comes without names.
    if outcome == Outcome::RedundantOkay && redundant.is_empty() {
        let (r, _) = solve_core(sys, group, &[], &cfg.clone().with_find_failed(true))?;
        let members = solver_members(&r);
        if !members.is_empty() {
            redundant.push(RedundantSet {
                members,
                excess: 1,
                involved: Vec::new(),
            });
        }
    }
    let unsatisfied = if outcome == Outcome::DidNotConverge {
        let mut u: Vec<Member> = (0..eqs.rows)
            .filter(|&i| !(lin.r[i].abs() <= cfg.tolerance))
            .map(|i| eqs.member(eqs.row_kernel[i] as usize))
            .collect();
        u.sort_by(Member::report_order);
        u.dedup();
        u
    } else {
        Vec::new()
    };

    // 4. Freedom.
    let unknowns = eqs.columns.len();
    let rank_n = rank.as_ref().map_or(0, |r| r.rank(eqs.rows));
    let dof = unknowns.saturating_sub(rank_n);
    let vectors = freedom::sketch(&eqs, &lin, rank.as_mut(), dof);
    let freedoms = freedom::freedoms(sys, group, &eqs, &values, &vectors);
    let params = sys.params();
    let sketch = NullSketch {
        params: eqs.param_of_col.iter().map(|&p| params[p].h).collect(),
        vectors,
    };

    // 5. Measurements, at the solution when there is one.
    let at = if outcome.is_ok() { &values } else { &start };
    let measurements = measure::measurements(sys, group, &start, at)?;

    Ok(Diagnosis {
        group,
        outcome,
        dof,
        unknowns,
        equations: eqs.rows,
        rank: rank_n,
        iterations: report.iterations,
        residual: report.residual,
        structural,
        conflicting,
        redundant,
        unsatisfied,
        freedoms,
        measurements,
        sketch,
    })
}

impl System {
    /// Diagnoses `group` with default settings. See [`diagnose`].
    ///
    /// # Errors
    /// As [`diagnose`].
    pub fn diagnose(&self, group: impl Into<GroupId>) -> Result<Diagnosis, SolveError> {
        diagnose(self, group.into(), &Config::default())
    }
}

/// Checks and names the conflicts of a solve the rank test called inconsistent: the union of
/// the conflict sets found where it stopped (`values`), each shown to fail on its own from
/// there and from the drawing, replaces the solver's list. When no set fails on its own, the
/// verdict was a guess: the outcome becomes `did_not_converge`, with the constraints left
/// unsatisfied where the solve stopped. Returns whether some set was shown to fail.
///
/// A set dropped because it holds alone from a start drawn at random leaves the values there
/// on `held` (every parameter of `sys`): starts from which the whole may solve.
#[allow(clippy::too_many_arguments)]
pub(crate) fn name_conflicts(
    sys: &System,
    group: GroupId,
    values: &[f64],
    cfg: &Config,
    report: &mut Report,
    kernels: &[Kernel],
    links: &[Link],
    held: &mut Vec<Vec<f64>>,
) -> bool {
    let start: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
    // The sets, and whether they were found only by shrinking the whole group: no dependence
    // where the solve stopped shows them, only solves that fail.
    let sets_in =
        |eqs: &Equations, starts: &[&[f64]], shrunk: &mut Shrunk| -> (Vec<ConflictSet>, bool) {
            let lin = eqs.linearise(values);
            let lin = eqs
                .linearise_off_singular(values, &lin, cfg.tolerance)
                .unwrap_or(lin);
            let Some(mut rank) = Rank::new(eqs, &lin, cfg) else {
                return (Vec::new(), false);
            };
            let mut rows = circuits::may_conflict(eqs, &lin, &mut rank, cfg);
            let sets_of = |circuits: &[Circuit], shrunk: &mut Shrunk| {
                conflict_sets(
                    eqs,
                    &lin,
                    circuits,
                    starts,
                    report.outcome,
                    cfg,
                    cfg.verify_conflicts_up_to,
                    shrunk,
                )
            };
            if rows.len() > LAZY_FROM {
                // The circuits of the rows with the largest residuals first: when the sets they
                // give are minimal and everything else holds without the members those sets
                // share, no other conflict is left to find. The one impossible diagonal of a 75x75
                // mesh: one batch of 32 circuits and one solve of all the rest (0.8 s in all),
                // where the 3,385 circuits that could conflict took 2.8 s.
                let first =
                    circuits::circuits_of(eqs, &lin, &mut rank, cfg, &rows[..circuits::BATCH]);
                let (sets, searched) = sets_of(&first, shrunk);
                if let Some(shared) = shared_members(&sets) {
                    if sets.iter().all(|s| s.verified)
                        && minimal::all_but_hold(eqs, &shared, starts, cfg)
                    {
                        return (sets, searched);
                    }
                }
            }
            rows.sort_unstable();
            let circuits = circuits::circuits_of(eqs, &lin, &mut rank, cfg, &rows);
            sets_of(&circuits, shrunk)
        };
    // First among the constraints the solver named and the equalities joining them, then, if
    // that names nothing, in the whole group.
    let seed: HashSet<Owner> = report
        .failed
        .iter()
        .map(|&c| Owner::Constraint(c))
        .chain(report.failed_entities.iter().map(|&e| Owner::Entity(e)))
        .collect();
    // A set dropped below because it holds from a start drawn at random leaves its solution:
    // the search runs again with that among its starts, so that the deletion filter, which
    // solves near the drawing only, sees the part hold there and keeps the member that makes
    // the real conflict (seed 451,288 of the random sketches: an angle of 140 degrees from a
    // horizontal line to a vertical one, shrunk to the horizontal and the angle, which fold
    // near the drawing like the pair of `checked_scattered`, and then named nothing).
    let mut shrunk = Shrunk::default();
    let (searched_sets, found) = searched_again(&[values, &start], |starts, solutions| {
        let (mut sets, mut searched) = (Vec::new(), false);
        if !seed.is_empty() {
            let keep = focus::focus(sys, group, &seed, kernels, links);
            if let Ok(eqs) = Equations::only(sys, group, &start, &|o| keep.contains(&o)) {
                (sets, searched) = sets_in(&eqs, starts, &mut shrunk);
            }
        }
        let mut whole = None;
        if sets.is_empty() {
            let all = Equations::new(sys, group, &start).ok()?;
            (sets, searched) = sets_in(&all, starts, &mut shrunk);
            whole = Some(all);
        }
        // Only a large set can be dropped for a solve that ran off: the whole group's
        // equations are compiled for the test only then.
        if sets.iter().any(|s| s.members.len() > minimal::LARGE_SET) {
            if whole.is_none() {
                whole = Equations::new(sys, group, &start).ok();
            }
            if whole
                .as_ref()
                .is_some_and(|all| ran_off(all, &start, report.residual))
            {
                sets.retain(|s| s.members.len() <= minimal::LARGE_SET);
            }
        }
        // Before a set is named, its constraints are kept alone in a system of their own and
        // solved by the ways of looking for a solution that `solve` takes and the checks above
        // do not; a set too large to shrink, only checked quickly so far, is also checked
        // every way. A set that holds alone is no conflict, whatever the solve of the whole
        // did: kept alone, 6 constraints of a fuzzed sketch solved that way, and 17 of another
        // that only the quick check had looked at.
        if !sets.is_empty() {
            let quick = |s: &ConflictSet| !s.verified && s.members.len() > minimal::LARGE_SET;
            if whole.is_none() && sets.iter().any(quick) {
                whole = Equations::new(sys, group, &start).ok();
            }
            // A set that holds either way is dropped.
            let (failing, in_whole) = failing_alone_or_whole(
                sys,
                group,
                sets,
                &mut || {
                    if whole.is_none() {
                        whole = Equations::new(sys, group, &start).ok();
                    }
                    whole_shrunk(whole.as_ref()?, starts, cfg)
                },
                cfg,
                &shrunk,
                solutions,
            );
            searched |= in_whole;
            sets = failing
                .into_iter()
                .filter(|s| {
                    !(quick(s)
                        && whole
                            .as_ref()
                            .is_some_and(|all| minimal::holds(all, &s.members, starts, cfg)))
                })
                .collect();
        }
        Some((sets, searched, whole))
    });
    held.extend(found);
    let Some((sets, searched, whole)) = searched_sets else {
        return false;
    };
    report.failed.clear();
    report.failed_entities.clear();
    // Shown only by a set that failed on its own from where the solve stopped, from the
    // drawing and built up one constraint at a time: a large set, checked quickly, may fail
    // only because Newton folded the sketch on its way. Nor by a set found only by shrinking
    // the whole group: its solves may fail where the build-up succeeds (18 constraints of a
    // random sketch that SolveSpace solves were named, each 17 of them solving).
    let proven = !searched
        && sets
            .iter()
            .any(|s| s.verified || s.members.len() <= minimal::LARGE_SET);
    let members: Vec<Member> = if sets.is_empty() {
        report.outcome = Outcome::DidNotConverge;
        let eqs = match whole {
            Some(eqs) => eqs,
            None => match Equations::new(sys, group, &start) {
                Ok(eqs) => eqs,
                Err(_) => return false,
            },
        };
        let lin = eqs.linearise(values);
        (0..eqs.rows)
            .filter(|&i| !(lin.r[i].abs() <= cfg.tolerance))
            .map(|i| eqs.member(eqs.row_kernel[i] as usize))
            .collect()
    } else {
        report.outcome = Outcome::Inconsistent;
        sets.into_iter().flat_map(|s| s.members).collect()
    };
    if !cfg.find_failed {
        return proven;
    }
    for m in members {
        match m {
            Member::Constraint(c) => report.failed.push(c),
            Member::Entity(e) => report.failed_entities.push(e),
        }
    }
    report.failed.sort_unstable();
    report.failed.dedup();
    report.failed_entities.sort_unstable();
    report.failed_entities.dedup();
    proven
}

/// What [`checked_alone`] found of a set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Checked {
    /// It holds (or is rescued) alone.
    Holds,
    /// It stopped short of holding.
    Fails,
    /// Every solve from the scattered starts was still going when its iterations ran out.
    Undecided,
}

/// Whether the members of `set`, kept alone in a system of their own (with the entities and
/// parameters they refer to), solve by one of the solve's rescues
/// ([`crate::solve::rescued_alone`]), or from starts drawn at random
/// ([`crate::solve::checked_scattered`]; a large set by the rescues from there too,
/// [`crate::solve::rescued_scattered`]); or are not shown to fail, every solve from those
/// starts still going when its iterations ran out ([`Scattered::Undecided`]): a set is
/// named only once its solves have stopped short of holding.
///
/// Where only a random start solves it, the values there are pushed on `solutions`: every
/// parameter of `sys` as it stands but those of the set, which are where it holds.
pub(super) fn checked_alone(
    sys: &System,
    group: GroupId,
    set: &[Member],
    cfg: &Config,
    solutions: &mut Vec<Vec<f64>>,
) -> Checked {
    let Some(part) = kept_alone(sys, set.iter().copied()) else {
        return Checked::Fails;
    };
    let alone = remembered(&part, group, cfg, || {
        if crate::solve::rescued_alone(&part, group, cfg) {
            return Alone::Rescued;
        }
        let scattered = crate::solve::checked_scattered(&part, group, cfg);
        if let Scattered::Held(held) = scattered {
            return Alone::Held(held);
        }
        match crate::solve::rescued_scattered(&part, group, cfg) {
            Some(held) => Alone::Held(held),
            None if matches!(scattered, Scattered::Undecided) => Alone::Undecided,
            None => Alone::Fails,
        }
    });
    let held = match alone {
        Alone::Rescued => return Checked::Holds,
        Alone::Undecided => return Checked::Undecided,
        Alone::Fails => return Checked::Fails,
        Alone::Held(held) => held,
    };
    let mut values: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
    for (p, v) in part.params().iter().zip(held) {
        if let Some(i) = sys.param_index(p.h) {
            values[i] = v;
        }
    }
    solutions.push(values);
    Checked::Holds
}

/// `search` from the starts `base`; then, while it leaves solutions on its second argument
/// (of sets it dropped because they hold from a start drawn at random, see [`checked_alone`]),
/// again with those among its starts, at most [`REGROWN`] more times. Its last result, and
/// every solution left.
fn searched_again<T>(
    base: &[&[f64]],
    mut search: impl FnMut(&[&[f64]], &mut Vec<Vec<f64>>) -> T,
) -> (T, Vec<Vec<f64>>) {
    let mut found: Vec<Vec<f64>> = Vec::new();
    let mut round = 0;
    loop {
        let mut starts = base.to_vec();
        starts.extend(found.iter().map(Vec::as_slice));
        let mut solutions = Vec::new();
        let out = search(&starts, &mut solutions);
        round += 1;
        let last = solutions.is_empty() || round > REGROWN;
        found.extend(solutions);
        if last {
            return (out, found);
        }
    }
}

/// How many times [`searched_again`] searches again from the solutions of sets dropped.
const REGROWN: usize = 2;

/// The members of a set kept alone in a system of their own, with the entities and
/// parameters they refer to ([`System::part`]).
pub(crate) fn kept_alone(sys: &System, set: impl Iterator<Item = Member>) -> Option<System> {
    let mut constraints = Vec::new();
    let mut entities = Vec::new();
    for m in set {
        match m {
            Member::Constraint(c) => constraints.push(c),
            Member::Entity(e) => entities.push(e),
        }
    }
    sys.part(&constraints, &entities)
}

/// Dependent rows from which [`name_conflicts`] first names conflicts from the most
/// conflicting circuits only.
const LAZY_FROM: usize = 4 * circuits::BATCH;

/// The members every one of `sets` has, when there are sets and such members.
fn shared_members(sets: &[ConflictSet]) -> Option<Vec<Member>> {
    let first = sets.first()?;
    let shared: Vec<Member> = first
        .members
        .iter()
        .filter(|m| sets.iter().all(|s| s.members.contains(m)))
        .copied()
        .collect();
    (!shared.is_empty()).then_some(shared)
}

/// Whether a solve that ended with largest residual `end` ran off: it ended many times
/// farther from holding than the drawing (`start`) was. Newton on a staircase of
/// perpendicular segments drawn flat along a line ends with residuals of 10²⁹, where its rows
/// depend on one another and large sets of them fail alone as well (Newton on them runs off
/// too); but every one of its constraints can hold with the others. Where a solve ran off,
/// only sets small enough to be checked every way (built up one constraint at a time, angles
/// turned) are named: a true conflict found there (seed 976, a solve that ended at 3·10⁷)
/// still is.
fn ran_off(eqs: &Equations, start: &[f64], end: f64) -> bool {
    let mut r = vec![0.0; eqs.rows];
    eqs.residuals(start, &mut r);
    let before = r.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    !(end <= RAN_OFF * before.max(1.0))
}

/// How many times the drawing's largest residual (or 1, if larger) a solve must end beyond
/// to have run off.
const RAN_OFF: f64 = 1e3;

/// The most constraints a conflict is searched among, one solve per member, when no
/// dependence found where the solve stopped fails on its own.
const WHOLE_SEARCH_LIMIT: usize = 64;

/// Minimal conflict sets from the conflicting circuits; for a solve that stopped at a
/// least-squares minimum with no dependent row, from the rows with residuals left. Each is
/// reported only once it fails on its own from one of `starts` (where the solve stopped, the
/// drawing); those of up to `minimise_up_to` members are also shrunk to minimal sets. Also
/// whether the one set was found by shrinking the whole group, no dependence showing it.
#[allow(clippy::too_many_arguments)]
fn conflict_sets(
    eqs: &Equations,
    lin: &Linear,
    circuits: &[Circuit],
    starts: &[&[f64]],
    outcome: Outcome,
    cfg: &Config,
    minimise_up_to: usize,
    shrunk: &mut Shrunk,
) -> (Vec<ConflictSet>, bool) {
    let members_of = |rows: &mut dyn Iterator<Item = usize>| {
        let mut m: Vec<Member> = rows
            .map(|r| eqs.member(eqs.row_kernel[r] as usize))
            .collect();
        m.sort_by(Member::report_order);
        m.dedup();
        m
    };
    let mut candidates: Vec<Vec<Member>> = Vec::new();
    let mut seen = HashSet::new();
    for c in circuits.iter().filter(|c| c.conflicting) {
        let m = members_of(&mut c.rows.iter().copied());
        if seen.insert(m.clone()) {
            candidates.push(m);
        }
    }
    if candidates.is_empty()
        && !outcome.is_ok()
        && circuits::stationary_with_residual(eqs, lin, cfg)
    {
        let m = members_of(&mut (0..eqs.rows).filter(|&i| !(lin.r[i].abs() <= cfg.tolerance)));
        if !m.is_empty() {
            candidates.push(m);
        }
    }
    let mut out: Vec<ConflictSet> = Vec::new();
    let mut done = HashSet::new();
    // Smallest first, and a candidate that holds a conflict already shown is not checked: it
    // fails for that conflict's sake and says nothing more (at the least-squares point of one
    // impossible dimension in a mesh, every circuit through it reads as conflicting, and each
    // failing check runs a solve to its end).
    candidates.sort_by_key(Vec::len);
    // The candidate less the constraints every conflict shown so far shares (of the first
    // one's), when it has any of them.
    let rest_of = |c: &[Member], out: &[ConflictSet]| -> Option<Vec<Member>> {
        let shared: Vec<Member> = shared_members(out)?
            .into_iter()
            .filter(|m| c.contains(m))
            .collect();
        (!shared.is_empty()).then(|| c.iter().filter(|m| !shared.contains(m)).copied().collect())
    };
    // Whether every candidate from here on that has a rest was found to hold without the
    // shared constraints, all at once; and how many conflicts were shown when that was last
    // tried (it is tried again only once another is shown).
    let mut rests_hold = false;
    let mut union_tried: Option<usize> = None;
    // The candidates shown to hold (each is part of a set that holds), and how many conflicts
    // were shown when candidates that share nothing with them were last checked together.
    let mut holding = vec![false; candidates.len()];
    let mut apart_tried: Option<usize> = None;
    let shows = |c: &[Member], out: &[ConflictSet]| {
        out.iter().any(|o| o.members.iter().all(|m| c.contains(m)))
    };
    for (i, c) in candidates.iter().enumerate() {
        if holding[i] || shows(c, &out) {
            continue;
        }
        // Once a conflict is shown, the other circuits that read as conflicting are mostly the
        // least-squares point spreading its residual: sets apart from it that hold (one
        // impossible length in a 10x10 mesh: 33 such sets of 10 to 64 constraints, each solved
        // alone, half of naming the conflict). This candidate and every later one that shares
        // nothing with the conflicts shown are solved together first: when they hold, so does
        // each. When they do not, each is checked as before.
        if !out.is_empty() && rest_of(c, &out).is_none() && apart_tried != Some(out.len()) {
            apart_tried = Some(out.len());
            let apart: Vec<usize> = (i..candidates.len())
                .filter(|&j| {
                    let d = &candidates[j];
                    !holding[j] && !shows(d, &out) && rest_of(d, &out).is_none()
                })
                .collect();
            if apart.len() > 1 {
                let mut union: Vec<Member> = apart
                    .iter()
                    .flat_map(|&j| candidates[j].iter().copied())
                    .collect();
                union.sort_by(Member::report_order);
                union.dedup();
                if minimal::holds(eqs, &union, starts, cfg) {
                    for &j in &apart {
                        holding[j] = true;
                    }
                    continue;
                }
            }
        }
        // A candidate through the constraints every conflict shown so far shares, which holds
        // without them, is one more conflict that changing those constraints ends: it names
        // nothing new to change, and one check here saves the deletion filter's solve per
        // member (one wrong diagonal in a 10x10 mesh: 45 sets of 6 to 124 constraints named,
        // each shrunk, 0.2 s; a 30x30 mesh took over 20 s).
        if let Some(rest) = rest_of(c, &out) {
            if rests_hold {
                continue;
            }
            // The rests of this candidate and of every later one together first: when they
            // hold, so does each (a subset of constraints that hold together holds), and one
            // solve replaces one per candidate (a 20x20 mesh: 400 candidates). Named sets
            // change the rests only when a check fails, and then each is checked as before.
            if union_tried != Some(out.len()) {
                union_tried = Some(out.len());
                let mut union: Vec<Member> = rest.clone();
                let mut others = 0;
                for later in &candidates[i + 1..] {
                    if let Some(r) = rest_of(later, &out) {
                        union.extend(r);
                        others += 1;
                    }
                }
                union.sort_by(Member::report_order);
                union.dedup();
                if others > 0 && minimal::holds(eqs, &union, starts, cfg) {
                    rests_hold = true;
                    continue;
                }
            }
            if minimal::holds(eqs, &rest, starts, cfg) {
                continue;
            }
        }
        // A set too large to shrink is kept when it fails as a whole, but not called
        // verified: no one checked that every member is needed.
        let (members, verified, fails) = if c.len() <= minimise_up_to {
            let (m, v) = minimal::minimise(eqs, c, starts, cfg);
            (m, v, v)
        } else {
            let fails = minimal::fails(eqs, c, starts, cfg);
            (c.clone(), false, fails)
        };
        if fails && done.insert(members.clone()) {
            shrunk.record(&members, c);
            out.push(ConflictSet { members, verified });
        }
    }
    // No candidate holds up, yet the solve failed: the dependence may run through constraints
    // that hold where it stopped (the ones that pin a line on which a point cannot be), or
    // show only at a point the solve did not reach. Shrink the whole set of equations to a
    // minimal set that fails while each of its parts solves, if it is small enough to try.
    // Wherever the solve stopped: damped steps that end short of the least-squares point (not
    // yet stationary there) leave the rank full, and a distance, a midpoint and the distance
    // to it that cannot agree went unnamed beside an angle that made Newton wander (a random
    // sketch against SolveSpace, which names them; 17 such in 5,000).
    let mut whole = false;
    if out.is_empty() && !outcome.is_ok() {
        if let Some(set) = whole_shrunk(eqs, starts, cfg) {
            out.push(set);
            whole = true;
        }
    }
    out.sort_by(|a, b| {
        a.members.len().cmp(&b.members.len()).then_with(|| {
            a.members
                .iter()
                .zip(&b.members)
                .map(|(x, y)| Member::report_order(x, y))
                .find(|o| o.is_ne())
                .unwrap_or(std::cmp::Ordering::Equal)
        })
    });
    (out, whole)
}

/// The whole group's equations shrunk by the deletion filter to a minimal set that fails while
/// each of its parts solves, when the group has at most [`WHOLE_SEARCH_LIMIT`] members. Every
/// member is needed (the set less any one of them solves): evidence even when the set is all
/// there is.
fn whole_shrunk(eqs: &Equations, starts: &[&[f64]], cfg: &Config) -> Option<ConflictSet> {
    let mut all: Vec<Member> = (0..eqs.rows)
        .map(|r| eqs.member(eqs.row_kernel[r] as usize))
        .collect();
    all.sort_by(Member::report_order);
    all.dedup();
    if all.len() > WHOLE_SEARCH_LIMIT {
        return None;
    }
    let (members, verified) = minimal::minimise(eqs, &all, starts, cfg);
    verified.then_some(ConflictSet { members, verified })
}

/// The sets of `sets` that fail alone ([`Shrunk::failing_alone`]). Where there were some and
/// every one holds alone, the solve stopped where a dependence that holds elsewhere read as the
/// conflict: then the set the whole group shrinks to (`whole`, [`whole_shrunk`]), when it
/// shares no member with those that hold and fails alone too. Seed 590,044 of the random
/// systems against SolveSpace stopped where a loop of six angles was dependent with residuals
/// left; alone, the six hold, and the conflict, a midpoint and two distances along its line
/// that cannot agree, showed in no dependence there. Shrinking the whole group drops the
/// oldest angle of the loop first, and the loop with it, and ends on the three. A set that
/// shares members with one that holds is left alone: it may fail near the drawing only where
/// Newton folds the sketch (nine constraints of a pentagon that close only with the drawing 50
/// times its size, `tests/sketch_named_conflicts.rs`, fail every check of the core alone).
/// Returns the sets, and whether they came from the whole group.
#[allow(clippy::too_many_arguments)]
fn failing_alone_or_whole(
    sys: &System,
    group: GroupId,
    sets: Vec<ConflictSet>,
    whole: &mut dyn FnMut() -> Option<ConflictSet>,
    cfg: &Config,
    shrunk: &Shrunk,
    solutions: &mut Vec<Vec<f64>>,
) -> (Vec<ConflictSet>, bool) {
    let mut held: Vec<Member> = Vec::new();
    let mut failing = Vec::new();
    for s in sets {
        let members = s.members.clone();
        match shrunk.failing_alone(sys, group, s, cfg, solutions) {
            Some(f) => failing.push(f),
            None => held.extend(members),
        }
    }
    if !failing.is_empty() || held.is_empty() {
        return (failing, false);
    }
    let found = whole()
        .filter(|s| !s.members.iter().any(|m| held.contains(m)))
        .and_then(|s| shrunk.failing_alone(sys, group, s, cfg, solutions));
    let from_whole = found.is_some();
    (found.into_iter().collect(), from_whole)
}

/// The solver's failed constraints and entities as members.
fn solver_members(r: &Report) -> Vec<Member> {
    let mut m: Vec<Member> = r
        .failed
        .iter()
        .map(|&c| Member::Constraint(c))
        .chain(r.failed_entities.iter().map(|&e| Member::Entity(e)))
        .collect();
    m.sort_by(Member::report_order);
    m
}

/// The starting values with every unknown moved a little, deterministically: a point where no
/// derivative vanishes by accident.
fn perturbed(eqs: &Equations, start: &[f64]) -> Vec<f64> {
    let mut v = start.to_vec();
    for (c, &p) in eqs.param_of_col.iter().enumerate() {
        let t = ((c as f64 + 1.0) * 0.618_033_988_749_895).fract() - 0.5;
        v[p] += 1e-3 * (1.0 + v[p].abs()) * t;
    }
    v
}
