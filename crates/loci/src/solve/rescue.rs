//! Where a solve looks when Newton from the drawing reaches no solution and no set of
//! constraints is shown to fail on its own: the sketch built up one constraint at a time,
//! with steps of least movement, with angles turned, and from starts further off (where a
//! dropped set held, or drawn at random). A solution found any of these ways is one where every
//! constraint holds; the alternative is a false `inconsistent`. The diagnosis uses the same
//! searches to check a set before it names it.

use super::{check_group, solve_values, solve_values_checked, Cache, Config, Report};
use crate::error::SolveError;
use crate::model::{ConstraintKind, GroupId, ParamId, System};

/// Whether `group` of `sys` solves as it stands: one solve from its values, as [`super::solve`]
/// runs it (equalities merged, carried entities read as expressions) but naming nothing and
/// building nothing up, for the diagnosis to check a set it is about to call impossible
/// against what solving the set alone gives.
pub(crate) fn holds_alone(sys: &System, group: GroupId, cfg: &Config) -> bool {
    if sys.validate().is_err() || check_group(sys, group).is_err() {
        return false;
    }
    solution_as_it_stands(sys, group, cfg).is_some()
}

/// The values of every parameter where [`holds_alone`] solves `group` of `sys` (already
/// validated for it), if it does.
fn solution_as_it_stands(sys: &System, group: GroupId, cfg: &Config) -> Option<Vec<f64>> {
    match ending_as_it_stands(sys, group, cfg) {
        Ending::Held(values) => Some(values),
        Ending::Stopped | Ending::OutOfIterations => None,
    }
}

/// How one solve of a set ended.
enum Ending {
    /// Every constraint holds: every parameter's value there.
    Held(Vec<f64>),
    /// It stopped on its own, short of a solution.
    Stopped,
    /// It was still going when it ran out of iterations.
    OutOfIterations,
}

/// How [`holds_alone`]'s solve of `group` of `sys` (already validated for it) ends.
fn ending_as_it_stands(sys: &System, group: GroupId, cfg: &Config) -> Ending {
    let cfg = Config {
        name_conflicts: false,
        ..cfg.clone()
    };
    let mut cache = Cache::default();
    let ending = match solve_values_checked(sys, group, &[], &cfg, &mut cache) {
        Ok((report, values, _)) if report.outcome.is_ok() => Ending::Held(values),
        Ok((report, _, _)) if report.iterations >= cfg.max_iterations => Ending::OutOfIterations,
        _ => Ending::Stopped,
    };
    cache.discard();
    ending
}

/// Whether `group` of `sys` solves by one of the ways [`rescued`] looks for a solution when
/// Newton from the drawing reaches none: the last check of a set before it is named, so that
/// no set is named that [`super::solve`] solves alone. Built up with steps of least movement
/// ([`built_least`]) only, a set of 30 constraints of a fuzzed sketch (searched again from
/// where a smaller set held) was named that solved alone with some angles turned.
pub(crate) fn rescued_alone(sys: &System, group: GroupId, cfg: &Config) -> bool {
    if sys.validate().is_err() || check_group(sys, group).is_err() {
        return false;
    }
    let mut cache = Cache::default();
    let built = rescued(sys, group, &[], cfg, &mut cache).is_ok_and(|found| found.is_some());
    cache.discard();
    built
}

/// Starts drawn at random that [`holds_scattered`] solves a set from: two at each of four
/// spreads, from a quarter of each parameter's size to twice it.
const SCATTERED_STARTS: [f64; 8] = [0.25, 0.25, 0.5, 0.5, 1.0, 1.0, 2.0, 2.0];

/// A group of at most this many constraints is tried from [`SMALL_ROUNDS`] rounds of
/// [`SCATTERED_STARTS`]: a solve of so few costs microseconds, and a small set is where one
/// unknown can lie past a fold from every start near the drawing. A corner sliding on a
/// horizontal, held at a distance from a fixed point's line (`bench/data/false_conflict_fold.json`
/// without its length), reaches that distance only on the far side of where the distance peaks;
/// none of the first eight starts found it, and the satisfiable sketch read `inconsistent`.
const SMALL_GROUP: usize = 16;
const SMALL_ROUNDS: usize = 8;

/// Whether `group` of `sys` solves, as [`holds_alone`] solves it, from one of
/// [`SCATTERED_STARTS`]: each of the group's parameters `v` moved by up to `s (1 + |v|)`
/// either way (the same starts on every run). Every start near the drawing can lead Newton
/// into the same fold: a horizontal line 0.9 long whose end a 51-degree angle to a line 9
/// long must turn, the least movement towards the angle runs the short line through zero
/// length, where its angle's row and the horizontal's become dependent, and the pair was named
/// a conflict (SolveSpace stops there too, without claiming one). From a start drawn further
/// off the pair solves: a set that does is no conflict. Only a set about to be named pays.
///
/// Returns the values of every parameter of `sys` where the group holds, if it does.
pub(crate) fn holds_scattered(sys: &System, group: GroupId, cfg: &Config) -> Option<Vec<f64>> {
    match checked_scattered(sys, group, cfg) {
        Scattered::Held(values) => Some(values),
        Scattered::Failed | Scattered::Undecided => None,
    }
}

/// What the solves of [`holds_scattered`] found.
#[derive(Clone)]
pub(crate) enum Scattered {
    /// A solution: the values of every parameter of the system there.
    Held(Vec<f64>),
    /// None, and some solve stopped on its own short of one.
    Failed,
    /// None, but every solve was still going when it ran out of iterations: no sign either
    /// way. Five constraints that hold only with a right triangle whose long leg is 73 times
    /// its drawn length (the hypotenuse at 89.37 degrees to the short leg, whose ends lie on
    /// a circle of diameter 2.8 and 6.1 from its centre) are reached by creeping for 3,285
    /// iterations from the drawing, and from none of the 64 starts within 1,000; they were
    /// named a conflict.
    Undecided,
}

/// [`holds_scattered`], telling a set that failed from one whose solves all ran out of
/// iterations (see [`Scattered::Undecided`]).
pub(crate) fn checked_scattered(sys: &System, group: GroupId, cfg: &Config) -> Scattered {
    if sys.validate().is_err() || check_group(sys, group).is_err() {
        return Scattered::Failed;
    }
    // Its solves name no conflicts, whatever the caller's configuration says.
    let cfg = &Config {
        name_conflicts: false,
        ..cfg.clone()
    };
    super::scattered_memo::remembered(sys, group, cfg, || scattered(sys, group, cfg))
}

/// [`checked_scattered`] of a valid group, found afresh.
fn scattered(sys: &System, group: GroupId, cfg: &Config) -> Scattered {
    let rounds = if constraints_of(sys, group) <= SMALL_GROUP {
        SMALL_ROUNDS
    } else {
        1
    };
    let mut out_of_iterations = true;
    // Moved by finite amounts, the values stay numbers: validated once, above.
    let held = from_scattered(sys, group, rounds * SCATTERED_STARTS.len(), |moved| {
        match ending_as_it_stands(moved, group, cfg) {
            Ending::Held(values) => Some(values),
            Ending::Stopped => {
                out_of_iterations = false;
                None
            }
            Ending::OutOfIterations => None,
        }
    });
    match held {
        Some(values) => Scattered::Held(values),
        None if out_of_iterations => Scattered::Undecided,
        None => Scattered::Failed,
    }
}

/// How many of [`SCATTERED_STARTS`] [`rescued_scattered`] looks for a solution from.
const RESCUED_STARTS: usize = 4;

/// Whether a group of more than [`SMALL_GROUP`] constraints solves by the ways [`rescued`]
/// looks for a solution, from the first [`RESCUED_STARTS`] of the starts [`holds_scattered`]
/// solves from: the last check of a large set before it is named, and the last search of a
/// large group that fails every other way. A set of 24 constraints of a fuzzed sketch
/// (`bench/data/fuzzed_conflict.json`) failed from the drawing by every rescue and from its
/// eight scattered starts by Newton alone (from 64 too, tried), and was named a conflict;
/// built up one constraint at a time with steps of least movement from the second scattered
/// start, it holds. A small set has [`SMALL_ROUNDS`] rounds of starts already, and building
/// it up from each would cost more than its check is worth.
///
/// Returns the values of every parameter of `sys` where the group holds, if it does.
pub(crate) fn rescued_scattered(sys: &System, group: GroupId, cfg: &Config) -> Option<Vec<f64>> {
    if sys.validate().is_err()
        || check_group(sys, group).is_err()
        || constraints_of(sys, group) <= SMALL_GROUP
    {
        return None;
    }
    from_scattered(sys, group, RESCUED_STARTS, |moved| {
        let mut cache = Cache::default();
        let found = rescued(moved, group, &[], cfg, &mut cache).ok().flatten();
        cache.discard();
        found.map(|(_, values)| values)
    })
}

/// The number of constraints of `group`.
fn constraints_of(sys: &System, group: GroupId) -> usize {
    sys.constraints()
        .iter()
        .filter(|c| c.group == group)
        .count()
}

/// The first of the first `starts` scattered starts (see [`holds_scattered`]) that `solve`
/// finds a solution from, `solve` given `sys` with the group's parameters moved there.
fn from_scattered(
    sys: &System,
    group: GroupId,
    starts: usize,
    mut solve: impl FnMut(&System) -> Option<Vec<f64>>,
) -> Option<Vec<f64>> {
    // A point held where it is dragged stays: moved, it would be held somewhere else.
    let held: Vec<ParamId> = sys
        .constraints()
        .iter()
        .filter(|c| c.group == group && c.kind == ConstraintKind::WhereDragged)
        .filter_map(|c| c.pt_a.and_then(|e| sys.entity(e)))
        .flat_map(|e| e.kind.params().iter().copied())
        .collect();
    let spreads = SCATTERED_STARTS.iter().cycle().take(starts);
    spreads.enumerate().find_map(|(k, &spread)| {
        let mut moved = sys.clone();
        for p in moved
            .params_mut()
            .filter(|p| p.group == group && !held.contains(&p.h))
        {
            p.val += spread * (1.0 + p.val.abs()) * scatter(k, p.h, p.val);
        }
        solve(&moved)
    })
}

/// How far start `k` moves a parameter, in (-1, 1): drawn from the start, the parameter's
/// handle and its value alone, so that a set checked in a system of its own (as the diagnosis
/// checks a set before naming it) and the same constraints solved among other entities (a
/// user deleting every other constraint) start each of its parameters at the same place. Drawn
/// in turn from one sequence, the two saw different starts, and a fuzzed set of 15
/// constraints that one found a solution from was named by the other.
fn scatter(k: usize, h: ParamId, val: f64) -> f64 {
    let seed = (0x5CA7_7E2E_D5EEu64 ^ (k as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15))
        .wrapping_mul(0x100_0000_01B3)
        ^ u64::from(h.0).rotate_left(29)
        ^ val.to_bits().rotate_left(7);
    crate::geom::SplitMix(seed).uniform()
}

/// The solve of `group` from a solution found another way when Newton from the drawing
/// reached none, if one is found: built up one constraint at a time; failing that, built with
/// steps of least movement from where the sketch stands rather than towards the drawing
/// (`Config::nearest` off, SolveSpace's steps), as each step's pull back towards the drawing
/// can hold a constraint that is being added short of holding (of 20,000 random systems, one,
/// 19 constraints started up to 2.4 off a solution, solved only this way, as SolveSpace solved
/// it); failing that too, solved whole with some 2D angles turned the other way (see
/// [`crate::diagnose::Rescue`]).
pub(super) fn rescued(
    sys: &System,
    group: GroupId,
    dragged: &[ParamId],
    cfg: &Config,
    cache: &mut Cache,
) -> Result<Option<(Report, Vec<f64>)>, SolveError> {
    use crate::diagnose::Rescue;
    if let Some(found) = constructed(sys, group, dragged, cfg, Rescue::Build, cache)? {
        return Ok(Some(found));
    }
    if cfg.nearest {
        if let Some(found) = built_least(sys, group, dragged, cfg, cache)? {
            return Ok(Some(found));
        }
    }
    constructed(sys, group, dragged, cfg, Rescue::Turn, cache)
}

/// [`constructed`] by the build one constraint at a time with steps of least movement from
/// where the sketch stands (`Config::nearest` off, SolveSpace's steps).
fn built_least(
    sys: &System,
    group: GroupId,
    dragged: &[ParamId],
    cfg: &Config,
    cache: &mut Cache,
) -> Result<Option<(Report, Vec<f64>)>, SolveError> {
    let least = cfg.clone().with_nearest(false);
    constructed(
        sys,
        group,
        dragged,
        &least,
        crate::diagnose::Rescue::Build,
        cache,
    )
}

/// The solve of `group` from a solution found `how` ([`crate::diagnose::construct_group`]),
/// when one is found: its report (its iterations those of the search too) and values.
/// `cache` then holds the equations compiled at that solution, whose branches (which way an
/// angle turns) are the ones it holds with.
fn constructed(
    sys: &System,
    group: GroupId,
    dragged: &[ParamId],
    cfg: &Config,
    how: crate::diagnose::Rescue,
    cache: &mut Cache,
) -> Result<Option<(Report, Vec<f64>)>, SolveError> {
    let Some((built, building)) = crate::diagnose::construct_group(sys, group, dragged, cfg, how)
    else {
        return Ok(None);
    };
    *cache = Cache::default();
    let (mut report, values) = solve_values(sys, group, dragged, cfg, cache, Some(&built))?;
    report.iterations += building;
    if report.outcome.is_ok() {
        Ok(Some((report, values)))
    } else {
        // Not expected (every equation held where the build ended); the next solve starts
        // from the drawing's branches again.
        *cache = Cache::default();
        Ok(None)
    }
}

/// The solve of `group` from the first of `held` it succeeds from, if any: values where a set
/// of its constraints holds alone, found from a start drawn at random after Newton from the
/// drawing folded the sketch on its way (a horizontal line and an angle of 51 degrees from it,
/// seed 430,180 of the random sketches: every start near the drawing runs the short line
/// through zero length; see [`holds_scattered`]). A solution far from the drawing is still one
/// where every constraint holds, where the alternative is none.
fn from_held(
    sys: &System,
    group: GroupId,
    dragged: &[ParamId],
    cfg: &Config,
    cache: &mut Cache,
    held: &[Vec<f64>],
) -> Result<Option<(Report, Vec<f64>)>, SolveError> {
    for start in held.iter().take(MAX_HELD_STARTS) {
        // Compiled afresh: the branches the equations chose at the drawing (an angle's
        // sense, a symmetry's side) need not be those of the start.
        *cache = Cache::default();
        let (report, values) = solve_values(sys, group, dragged, cfg, cache, Some(start))?;
        if report.outcome.is_ok() {
            return Ok(Some((report, values)));
        }
    }
    if !held.is_empty() {
        // The next solve starts from the drawing's branches again.
        *cache = Cache::default();
    }
    Ok(None)
}

/// The solve of `group` from further off than the drawing, when nothing else found one: from
/// where a set the search for conflicts dropped holds ([`from_held`]); failing that, for a
/// group that is not being dragged and has at most [`SCATTERED_WHOLE_UP_TO`] unknowns, from
/// starts drawn at random ([`holds_scattered`]: eight solves, or 64 for a small group; a
/// large one is also built up from four of them, [`rescued_scattered`]), paid only by a
/// group that fails every other way. Six constraints of a random sketch (seed 473,644 less its
/// constraint 9: two vertical lines, a symmetry, two distances and an angle) stopped short
/// from the drawing, naming nothing, and solve from a start moved a few percent.
pub(super) fn found_further_off(
    sys: &System,
    group: GroupId,
    dragged: &[ParamId],
    cfg: &Config,
    cache: &mut Cache,
    held: &[Vec<f64>],
) -> Result<Option<(Report, Vec<f64>)>, SolveError> {
    if let Some(found) = from_held(sys, group, dragged, cfg, cache, held)? {
        return Ok(Some(found));
    }
    let unknowns = sys.params().iter().filter(|p| p.group == group).count();
    if !dragged.is_empty() || unknowns > SCATTERED_WHOLE_UP_TO {
        return Ok(None);
    }
    match holds_scattered(sys, group, cfg).or_else(|| rescued_scattered(sys, group, cfg)) {
        Some(start) => from_held(sys, group, dragged, cfg, cache, &[start]),
        None => Ok(None),
    }
}

/// The values where `group` of `sys` (validated) holds, found further off than the drawing
/// as the solve finds them ([`found_further_off`]), if they are.
pub(crate) fn solution_further_off(
    sys: &System,
    group: GroupId,
    cfg: &Config,
    held: &[Vec<f64>],
) -> Option<Vec<f64>> {
    let mut cache = Cache::default();
    let found = found_further_off(sys, group, &[], cfg, &mut cache, held)
        .ok()
        .flatten();
    cache.discard();
    found.map(|(_, values)| values)
}

/// The most unknowns of a group that [`found_further_off`] solves from random starts.
const SCATTERED_WHOLE_UP_TO: usize = 200;

/// How many of the solutions of dropped sets [`from_held`] solves the whole from.
const MAX_HELD_STARTS: usize = 4;
