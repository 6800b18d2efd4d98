//! Checking a candidate conflict on its own: Newton on just its equations, from where the
//! solve stopped and from the user's drawing, and a deletion filter that removes every member
//! the conflict does not need.

use super::construct::{construct, turnable, with_turns};
use super::report::Member;
use super::unmerged::{Equations, CONSTANT};
use crate::equations::{Kernel, Rows};
use crate::solve::newton::{Component, Scratch};
use crate::solve::Config;
use rustc_hash::{FxHashMap as HashMap, FxHashSet as HashSet};

/// Whether the equations of `kernels` can all hold: Newton on them alone converges from one
/// of `starts` (each a value for every parameter: where the solve stopped, the drawing), or
/// from a generic point near one.
///
/// A set that solves from any of them is not a conflict, however the full solve ended: a
/// solve that stalls far from the drawing can see dependent rows with residuals left at its
/// stopping point that say nothing about the constraints themselves.
pub(crate) fn consistent(
    eqs: &Equations,
    kernels: &[usize],
    starts: &[&[f64]],
    cfg: &Config,
) -> bool {
    check(eqs, kernels, starts, cfg, false, true, false)
}

/// [`consistent`], or with `quick` a check on SolveSpace's budget for a whole sketch and from
/// the given starts only: for large sets checked as they are found (a loop of hundreds of
/// constraints through a grid), whose failing solves rarely stall early and at the full budget
/// took 50 times as long to check as to find. Never for the deletion filter, whose verdicts on
/// parts of a set must be right for the set to be minimal.
///
/// With `build`, a set that fails from every start is also built up one constraint at a time
/// from the drawing ([`construct`]) before it counts as failing: Newton from the drawing can
/// fold the sketch where the set could hold (s0026: six constraints that hold together failed
/// from every start). The build costs a solve per member and order tried, so the deletion
/// filter uses it on the whole set and on the set it ends with only.
///
/// With `any_side`, the solves may also step through `Jᵀ J` (see [`solve_set`]): for a check
/// whose failure names nothing, where only a solution found counts.
fn check(
    eqs: &Equations,
    kernels: &[usize],
    starts: &[&[f64]],
    cfg: &Config,
    quick: bool,
    build: bool,
    any_side: bool,
) -> bool {
    // A set is called a conflict only when solves that could have succeeded fail: never on a
    // budget of iterations cut short by the caller.
    let budget = if quick {
        LARGE_SET_ITERATIONS
    } else {
        cfg.max_iterations.max(Config::default().max_iterations)
    };
    let cfg = &cfg.clone().with_max_iterations(budget);
    let with_background = with_implicit(eqs, kernels);
    let kernels = &with_background[..];
    let nudges: &[f64] = if quick { &[0.0] } else { &[0.0, 1e-3] };
    if starts
        .iter()
        .any(|values| consistent_from(eqs, kernels, values, cfg, nudges, any_side))
    {
        return true;
    }
    build
        && (starts.last().is_some_and(|start| {
            builds(eqs, kernels, start, cfg) || other_turns_hold(eqs, kernels, start, cfg)
        }) || solves_as_drawn(eqs, kernels, cfg))
}

/// Whether the set builds up one constraint at a time from `start` ([`construct`]): in the
/// order given (a report's, the latest constraints first), and failing that in the order the
/// constraints were added. Each order builds some sets the other cannot: of 20,000 random
/// sketches, one (seed 202236 from its second start) was built only in the first; of 4,000
/// random assemblies, one set (seed 1487) only in the second.
fn builds(eqs: &Equations, kernels: &[usize], start: &[f64], cfg: &Config) -> bool {
    if construct(eqs, kernels, start, &|_| 1.0, cfg, &mut 0).is_some() {
        return true;
    }
    let mut added = kernels.to_vec();
    added.sort_unstable();
    added != kernels && construct(eqs, &added, start, &|_| 1.0, cfg, &mut 0).is_some()
}

/// Whether the constraints of `kernels`, kept alone in a system of their own (with the
/// entities they refer to), solve as the solver solves a group: equalities merged and
/// carried entities read as expressions of their parts, from the drawing. Its steps are not
/// those of the checks above (which keep every row of their own and start where the whole
/// solve stopped), and a set a user would see solve when kept alone is no conflict: a random
/// assembly's lengthened distance with five mates was named impossible after the checks above
/// failed, and those mates alone solved in 48 iterations.
fn solves_as_drawn(eqs: &Equations, kernels: &[usize], cfg: &Config) -> bool {
    super::kept_alone(eqs.sys, kernels.iter().map(|&k| eqs.member(k)))
        .is_some_and(|part| crate::solve::holds_alone(&part, eqs.group, cfg))
}

/// `kernels` and the implicit conditions of the entities they read (and of the entities
/// those read, and so on): a set is checked against what its entities are, not only against
/// its own equations. An implicit condition is no constraint a user could change (a unit
/// quaternion, an arc's equal radii, a plane carried by a part's pose): without it a set
/// could hold only by breaking one (two angles about an axis a free part carries both held
/// once the plane they are measured in tilted off the part). Whether a member that is itself
/// an implicit condition is needed is then never in question, and the deletion filter leaves
/// it out of the named set.
fn with_implicit(eqs: &Equations, kernels: &[usize]) -> Vec<usize> {
    let mut out = kernels.to_vec();
    if eqs.implicit.is_empty() {
        return out;
    }
    let implicit: Vec<usize> = eqs
        .implicit
        .iter()
        .copied()
        .filter(|k| !kernels.contains(k))
        .collect();
    let mut cols: HashSet<u32> = kernels
        .iter()
        .flat_map(|&k| eqs.blocks[k].cols.iter().copied())
        .collect();
    let mut left = implicit;
    loop {
        let (reached, rest): (Vec<usize>, Vec<usize>) = left.into_iter().partition(|&k| {
            let own = &eqs.own_cols[k];
            let read = if own.is_empty() {
                &eqs.blocks[k].cols
            } else {
                own
            };
            read.iter().any(|c| cols.contains(c))
        });
        if reached.is_empty() {
            break;
        }
        for &k in &reached {
            cols.extend(eqs.blocks[k].cols.iter().copied());
        }
        out.extend(reached);
        left = rest;
    }
    out
}

/// The most 2D angles whose every combination of turns a check tries.
const MAX_TURNING: usize = 3;

/// Whether the set holds, solved from `start`, with some of its 2D angles turning the other
/// way: a 2D angle keeps the turn it is drawn with, but a conflict is named only when no way
/// of turning its angles lets the set hold (two angles that add up to a right angle between
/// a horizontal and a vertical line hold only when they turn the same way).
fn other_turns_hold(eqs: &Equations, kernels: &[usize], start: &[f64], cfg: &Config) -> bool {
    let Some(turning) = turnable(eqs, kernels, MAX_TURNING) else {
        return false;
    };
    let mut scratch = Scratch::default();
    (1..1usize << turning.len()).any(|mask| {
        let defs = with_turns(eqs, &turning, mask);
        let mut v = start.to_vec();
        matches!(
            solve_set(
                eqs,
                &defs,
                kernels,
                &mut v,
                &|_| 1.0,
                cfg,
                0.0,
                false,
                &mut scratch,
                &mut 0
            ),
            Alone::Converged
        )
    })
}

/// Sets of more constraints than this, checked whole, are checked quickly: from the given
/// starts on a short budget, and not built up one constraint at a time.
pub(crate) const LARGE_SET: usize = 16;

/// The iterations a solve of a large set gets before it counts as failing.
const LARGE_SET_ITERATIONS: usize = 50;

fn consistent_from(
    eqs: &Equations,
    kernels: &[usize],
    values: &[f64],
    cfg: &Config,
    nudges: &[f64],
    any_side: bool,
) -> bool {
    // From where the solve stopped, then from a generic point nearby: a stop at degenerate
    // geometry (a line collapsed to a point) says nothing about whether the set can hold.
    // Only whether the set holds is asked, so a crawl ends the solve (`Config::crawl_fails`).
    let cfg = &Config {
        crawl_fails: true,
        ..cfg.clone()
    };
    let mut scratch = Scratch::default();
    nudges.iter().any(|&nudge| {
        let mut v = values.to_vec();
        // Too large to try is no evidence that the set fails.
        !matches!(
            solve_set(
                eqs,
                &eqs.kernels,
                kernels,
                &mut v,
                &|_| 1.0,
                cfg,
                nudge,
                any_side,
                &mut scratch,
                &mut 0
            ),
            Alone::Failed
        )
    })
}

/// How a solve of some equations alone ended.
enum Alone {
    Converged,
    Failed,
    TooLarge,
}

/// Newton on the equations of `kernels` alone, from `values` (one per parameter; the other
/// parameters are constants), columns weighted by `scale_of_param`. On success the solution
/// is written into `values`; otherwise they are left as they were. Its iterations are added
/// to `iterations`.
pub(crate) fn solve_alone(
    eqs: &Equations,
    defs: &[Kernel],
    kernels: &[usize],
    values: &mut [f64],
    scale_of_param: &dyn Fn(usize) -> f64,
    cfg: &Config,
    iterations: &mut usize,
) -> bool {
    let mut scratch = Scratch::default();
    let end = solve_set(
        eqs,
        defs,
        kernels,
        values,
        scale_of_param,
        cfg,
        0.0,
        false,
        &mut scratch,
        iterations,
    );
    matches!(end, Alone::Converged)
}

/// [`solve_alone`], from `values` moved by `nudge` (relative) in a generic direction; with
/// `any_side`, by steps through `Jᵀ J` too where the solver would take them.
#[allow(clippy::too_many_arguments)]
fn solve_set(
    eqs: &Equations,
    defs: &[Kernel],
    kernels: &[usize],
    values: &mut [f64],
    scale_of_param: &dyn Fn(usize) -> f64,
    cfg: &Config,
    nudge: f64,
    any_side: bool,
    scratch: &mut Scratch,
    iterations: &mut usize,
) -> Alone {
    let mut local: HashMap<u32, u32> = HashMap::default();
    let mut globals = Vec::new();
    for &k in kernels {
        for &c in &eqs.blocks[k].cols {
            local.entry(c).or_insert_with(|| {
                globals.push(c);
                (globals.len() - 1) as u32
            });
        }
    }
    if globals.is_empty() {
        // Constants only: they hold or not as they are.
        let mut xs = Vec::new();
        let holds = kernels.iter().all(|&k| {
            let kern = &defs[k];
            kern.gather(values, &mut xs);
            let mut out = Rows::new();
            kern.eq.eval(&xs, &mut out);
            out.v[..out.n].iter().all(|v| v.abs() <= cfg.tolerance)
        });
        return if holds {
            Alone::Converged
        } else {
            Alone::Failed
        };
    }
    let map = |p: usize| {
        let c = eqs.col_of_param[p];
        if c == CONSTANT {
            None
        } else {
            local.get(&c).copied()
        }
    };
    let n = globals.len();
    let scale = globals
        .iter()
        .map(|&c| scale_of_param(eqs.param_of_col[c as usize]))
        .collect();
    let mut comp = Component::new(defs, kernels, &map, n, scale);
    let mut x: Vec<f64> = globals
        .iter()
        .enumerate()
        .map(|(i, &c)| {
            let v = values[eqs.param_of_col[c as usize]];
            v + nudge * (1.0 + v.abs()) * (((i as f64 + 1.0) * 0.618_034).fract() - 0.5)
        })
        .collect();
    // Through `J Jᵀ` alone, as a set was always judged: which parts fail is what names a
    // conflict, and steps through `Jᵀ J` (`solve::unknowns`) could carry a part from a start
    // where these fail to a solution; on a failing part they only add steps before giving way.
    // Where a failure names nothing, a solution reached either way is the answer (all of a
    // 100x100 mesh but one conflict: 10 factorisations of `J Jᵀ` fewer).
    let cfg = &Config {
        unknowns_side: any_side && cfg.unknowns_side,
        ..cfg.clone()
    };
    let fin = comp.solve(defs, &mut x, values, cfg, scratch);
    *iterations += fin.iterations;
    if fin.too_large {
        return Alone::TooLarge;
    }
    if !fin.converged {
        return Alone::Failed;
    }
    for (&c, &v) in globals.iter().zip(&x) {
        values[eqs.param_of_col[c as usize]] = v;
    }
    Alone::Converged
}

/// Whether the constraints of `set` can all hold: [`consistent`] on their equations. False
/// for a set with a member that has no equations here.
pub(crate) fn holds(eqs: &Equations, set: &[Member], starts: &[&[f64]], cfg: &Config) -> bool {
    let kernels: Option<Vec<usize>> = set.iter().map(|&m| eqs.kernel_of(m)).collect();
    kernels.is_some_and(|k| k.is_empty() || consistent(eqs, &k, starts, cfg))
}

/// Whether every equation of the group but those of the members `without` holds, from one of
/// `starts` on SolveSpace's budget for a whole sketch and without building it up: a quick
/// check that no other conflict is left once those are named. `false` says nothing (a solve
/// that needed more steps).
pub(crate) fn all_but_hold(
    eqs: &Equations,
    without: &[Member],
    starts: &[&[f64]],
    cfg: &Config,
) -> bool {
    let kernels: Vec<usize> = (0..eqs.kernels.len())
        .filter(|&k| !without.contains(&eqs.member(k)))
        .collect();
    kernels.is_empty() || check(eqs, &kernels, starts, cfg, true, false, true)
}

/// Whether `set` fails as a whole, without shrinking it: one check, for sets too large for the
/// deletion filter's one solve per member.
pub(crate) fn fails(eqs: &Equations, set: &[Member], starts: &[&[f64]], cfg: &Config) -> bool {
    let kernels: Option<Vec<usize>> = set.iter().map(|&m| eqs.kernel_of(m)).collect();
    kernels.is_some_and(|k| {
        let quick = k.len() > LARGE_SET;
        !check(eqs, &k, starts, cfg, quick, !quick, false)
    })
}

/// Shrinks `set` to a minimal conflict by the deletion filter: a member whose removal leaves
/// the rest still failing is not needed. Implicit conditions of entities, which a user
/// cannot remove, are tried first, then constraints from the oldest, so that the most recent
/// constraints are the ones kept when there is a choice.
///
/// Returns the set and whether it was verified (it fails as a whole; when it does not, it
/// is returned unchanged).
pub(crate) fn minimise(
    eqs: &Equations,
    set: &[Member],
    starts: &[&[f64]],
    cfg: &Config,
) -> (Vec<Member>, bool) {
    let mut keep: Vec<(Member, usize)> = set
        .iter()
        .filter_map(|&m| eqs.kernel_of(m).map(|k| (m, k)))
        .collect();
    let all: Vec<usize> = keep.iter().map(|x| x.1).collect();
    if keep.len() != set.len() || consistent(eqs, &all, starts, cfg) {
        let mut out = set.to_vec();
        out.sort_by(Member::report_order);
        return (out, false);
    }
    let mut trials: Vec<Member> = keep.iter().map(|x| x.0).collect();
    trials.sort_by_key(|m| match *m {
        Member::Entity(e) => (0, e.0),
        Member::Constraint(c) => (1, c.0),
    });
    // Parts judged by Newton alone first (cheap); the set kept must then also resist being
    // built. When it does not, a part was called failing that holds: the filter runs again
    // with every part built up too, so that what it keeps fails for certain.
    let removed = deletion_pass(eqs, &mut keep, &trials, starts, cfg, false);
    let kept: Vec<usize> = keep.iter().map(|x| x.1).collect();
    if !removed.is_empty() && consistent(eqs, &kept, starts, cfg) {
        // The members removed, put back from the last to go, make the set fail again by the
        // time all are back (the whole set fails): the second filter starts from the fewest
        // such, found by bisection, rather than from the whole set. Each of its checks builds
        // the part up one constraint at a time: a set of 40 members took 40 such checks of
        // sets of up to 59 equations (2 s).
        let with = |j: usize| -> Vec<(Member, usize)> {
            keep.iter().chain(&removed[j..]).copied().collect()
        };
        // `with(lo)` fails, `with(hi)` holds.
        let (mut lo, mut hi) = (0, removed.len());
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            let part: Vec<usize> = with(mid).iter().map(|x| x.1).collect();
            if consistent(eqs, &part, starts, cfg) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        keep = with(lo);
        deletion_pass(eqs, &mut keep, &trials, starts, cfg, true);
    }
    let mut out: Vec<Member> = keep.into_iter().map(|x| x.0).collect();
    out.sort_by(Member::report_order);
    (out, true)
}

/// One pass of the deletion filter over `keep` (members with their kernels), trying the
/// members of `trials` in turn: a member goes when the rest still fails ([`check`], each part
/// also built up with `build`). Returns the entries removed, in the order they went.
fn deletion_pass(
    eqs: &Equations,
    keep: &mut Vec<(Member, usize)>,
    trials: &[Member],
    starts: &[&[f64]],
    cfg: &Config,
    build: bool,
) -> Vec<(Member, usize)> {
    let mut removed = Vec::new();
    for &m in trials {
        if keep.len() <= 1 {
            break;
        }
        if !keep.iter().any(|x| x.0 == m) {
            continue;
        }
        let rest: Vec<usize> = keep.iter().filter(|x| x.0 != m).map(|x| x.1).collect();
        if !check(eqs, &rest, starts, cfg, false, build, false) {
            removed.extend(keep.iter().filter(|x| x.0 == m));
            keep.retain(|x| x.0 != m);
        }
    }
    removed
}
