//! Building a solution up one constraint at a time, as the user drew it, when Newton cannot
//! reach one from the whole drawing at once.
//!
//! A sketch far from every solution (dimensions typed in after drawing freehand, a random
//! system) can send Newton's steps into a fold: a line collapses to a point, its angle and
//! its distances lose their directions, and the solve stops at a least-squares point where
//! some rows have become dependent. The rank test then sees a conflict where there is none.
//! Adding the constraints one at a time, each solved from where the last one left the sketch
//! with the least movement, keeps every intermediate sketch a solution of the constraints
//! added so far, so each step starts near a solution: this is how the sketch would move if
//! the user had added the constraints one by one. A constraint that cannot be added where it
//! comes is tried again once others have been added; when some still cannot be added, the
//! whole build starts again from the drawing with them first (the order matters: a dimension
//! added early can choose the branch a later one needs).
//!
//! On a sketch whose constraints truly conflict, some constraint can never be added and the
//! build gives up after [`ROUNDS`] orders; it is only tried on groups of at most
//! [`CONSTRUCT_UP_TO`] equations' owners, so a conflict in a large sketch costs no more than
//! before.

use super::minimal::solve_alone;
use super::report::Member;
use super::unmerged::Equations;
use crate::equations::{EqKind, Equation, Kernel, Owner};
use crate::model::ConstraintKind;
use crate::model::{GroupId, ParamId, System};
use crate::solve::Config;

/// The most kernels (constraints and entities' implicit conditions) a build is tried on:
/// each step is one solve of the constraints added so far, and a build of `n` takes up to
/// `ROUNDS * n` steps.
pub(crate) const CONSTRUCT_UP_TO: usize = 64;

/// How many orders are tried, each from the drawing, before the build gives up.
pub(crate) const ROUNDS: usize = 4;

/// The iterations each step gets: a step starts at a solution of all but one of its
/// constraints, so one that needs more is better tried later, from elsewhere.
const STEP_ITERATIONS: usize = 20;

/// Values (one per parameter) where every equation of `kernels` holds, built up from `start`
/// one constraint at a time; `None` if no order tried gets them all to hold. The iterations
/// of every solve it takes are added to `iterations`.
pub(crate) fn construct(
    eqs: &Equations,
    kernels: &[usize],
    start: &[f64],
    scale_of_param: &dyn Fn(usize) -> f64,
    cfg: &Config,
    iterations: &mut usize,
) -> Option<Vec<f64>> {
    if kernels.len() > CONSTRUCT_UP_TO {
        return None;
    }
    let cfg = &cfg
        .clone()
        .with_max_iterations(cfg.max_iterations.min(STEP_ITERATIONS))
        .with_find_failed(false);
    // Entities' implicit conditions (unit quaternions, equal arc radii) are part of every
    // sketch: they come first, all together. Then the constraints in the order given (the
    // order they were added, for a whole group).
    let (base, mut order): (Vec<usize>, Vec<usize>) = kernels
        .iter()
        .partition(|&&k| matches!(eqs.kernels[k].owner, Owner::Entity(_)));
    // Where they hold, solved once: every order starts from there, with the same equations.
    let mut from = start.to_vec();
    if !base.is_empty()
        && !solve_alone(
            eqs,
            &eqs.kernels,
            &base,
            &mut from,
            scale_of_param,
            cfg,
            iterations,
        )
    {
        return None;
    }
    for _ in 0..ROUNDS {
        let mut defs = eqs.kernels.clone();
        let mut values = from.clone();
        let mut have = base.clone();
        // Each constraint still to add, with the number of constraints added when it last
        // failed: tried again with nothing added since, it would start from the same values
        // with the same equations and fail the same way (a conflict's last member, the most
        // expensive step of a build that cannot succeed, was solved twice each order).
        let mut pending: Vec<(usize, Option<usize>)> = order.iter().map(|&k| (k, None)).collect();
        let mut added = 0usize;
        loop {
            let mut progressed = false;
            let mut rest = Vec::new();
            for (k, failed_at) in pending {
                if failed_at == Some(added) {
                    rest.push((k, failed_at));
                    continue;
                }
                have.push(k);
                if add(
                    eqs,
                    &mut defs,
                    &have,
                    k,
                    &mut values,
                    scale_of_param,
                    cfg,
                    iterations,
                ) {
                    progressed = true;
                    added += 1;
                } else {
                    have.pop();
                    rest.push((k, Some(added)));
                }
            }
            pending = rest;
            if pending.is_empty() || !progressed {
                break;
            }
        }
        if pending.is_empty() {
            return Some(values);
        }
        // Next time from the drawing with the ones that could not be added first.
        let pending: Vec<usize> = pending.into_iter().map(|(k, _)| k).collect();
        let mut next = pending.clone();
        next.extend(order.iter().filter(|k| !pending.contains(k)));
        if next == order {
            return None;
        }
        order = next;
    }
    None
}

/// Adds kernel `k` (the last of `have`) to the sketch at `values`, as if the user added it to
/// the sketch as it stands now: its branch (which way an angle turns, which side of a line an
/// arc touches) is the one the sketch shows now, not the drawing's; and if that one cannot
/// hold, the other way an angle can turn. On success `values` hold every kernel of `have`.
#[allow(clippy::too_many_arguments)]
fn add(
    eqs: &Equations,
    defs: &mut [Kernel],
    have: &[usize],
    k: usize,
    values: &mut [f64],
    scale_of_param: &dyn Fn(usize) -> f64,
    cfg: &Config,
    iterations: &mut usize,
) -> bool {
    let mut xs = Vec::new();
    let kern = &mut defs[k];
    kern.gather(values, &mut xs);
    kern.eq.choose(&xs);
    if kern.eq.rows(&xs) != kern.rows {
        kern.eq = eqs.kernels[k].eq.clone();
    }
    let other = other_turn(&kern.eq);
    if solve_alone(eqs, defs, have, values, scale_of_param, cfg, iterations) {
        return true;
    }
    let Some(eq) = other else {
        return false;
    };
    let chosen = std::mem::replace(&mut defs[k].eq, eq);
    let added = solve_alone(eqs, defs, have, values, scale_of_param, cfg, iterations);
    if !added {
        defs[k].eq = chosen;
    }
    added
}

/// A 2D angle (or equal angles) turning the other way: the other branch [`Equation::choose`]
/// picks between.
fn other_turn(eq: &Equation) -> Option<Equation> {
    let turns = matches!(
        eq.kind,
        EqKind::Constraint(ConstraintKind::Angle | ConstraintKind::EqualAngle)
    );
    if !turns || eq.wp.is_none() || eq.is_unsigned_angle() || eq.is_straight_angle() {
        return None;
    }
    let mut other = eq.clone();
    other.choice ^= 1;
    other.prepare();
    Some(other)
}

/// How [`construct_group`] looks for a solution of a group that Newton did not reach from
/// the drawing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Rescue {
    /// One solve of the equations as written, then the build one constraint at a time
    /// ([`construct`]).
    Build,
    /// One solve of the whole group with some of its 2D angles turned the other way
    /// ([`turned`]).
    Turn,
}

/// A solution of every equation of `group`, looked for `how`, from the values in `sys`, with
/// `dragged` parameters moving least: values for every parameter where all of them hold, and
/// the iterations of every solve taken to find them, or `None` (also for groups of more than
/// [`CONSTRUCT_UP_TO`] constraints and conditions).
pub(crate) fn construct_group(
    sys: &System,
    group: GroupId,
    dragged: &[ParamId],
    cfg: &Config,
    how: Rescue,
) -> Option<(Vec<f64>, usize)> {
    // Counted before anything is compiled: a large sketch in conflict pays nothing here.
    let constraints = sys
        .constraints()
        .iter()
        .filter(|c| c.group == group && !c.reference)
        .count();
    if constraints > CONSTRUCT_UP_TO {
        return None;
    }
    // Likewise a group without 2D angles to turn (an assembly, a 3D sketch).
    if how == Rescue::Turn
        && !sys.constraints().iter().any(|c| {
            c.group == group
                && !c.reference
                && c.workplane.is_some()
                && matches!(c.kind, ConstraintKind::Angle | ConstraintKind::EqualAngle)
        })
    {
        return None;
    }
    let start: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
    let eqs = Equations::new(sys, group, &start).ok()?;
    let kernels: Vec<usize> = (0..eqs.kernels.len()).collect();
    let dragged: Vec<usize> = dragged.iter().filter_map(|&h| sys.param_index(h)).collect();
    let scale = |p: usize| {
        if dragged.contains(&p) {
            cfg.dragged_scale
        } else {
            1.0
        }
    };
    let mut iterations = 0;
    if how == Rescue::Turn {
        let turning = turnable(&eqs, &kernels, MAX_TURNED)?;
        return turned(
            &eqs,
            &kernels,
            &turning,
            &start,
            &scale,
            cfg,
            &mut iterations,
        )
        .map(|v| (v, iterations));
    }
    // Newton on the equations as written first, from the drawing, as the diagnosis checks
    // whether a set can hold (its rows in the order of a report: the latest constraints
    // first, entities' conditions last): one solve, where the build is one per constraint.
    // The solve that failed took other steps, on equations merged by substitution and in
    // another order, which decides the rows dropped where some depend on others; the group
    // should not be given up on where the diagnosis's own check of it finds a solution (a
    // random assembly of five parts and twelve mates stopped 0.035 off after 10 iterations,
    // and its diagnosis, finding every part of it able to hold, named nothing).
    let mut members: Vec<Member> = kernels.iter().map(|&k| eqs.member(k)).collect();
    members.sort_by(Member::report_order);
    members.dedup();
    let as_checked: Vec<usize> = members.iter().filter_map(|&m| eqs.kernel_of(m)).collect();
    let mut values = start.clone();
    if as_checked.len() == kernels.len()
        && solve_alone(
            &eqs,
            &eqs.kernels,
            &as_checked,
            &mut values,
            &scale,
            cfg,
            &mut iterations,
        )
    {
        return Some((values, iterations));
    }
    construct(&eqs, &kernels, &start, &scale, cfg, &mut iterations).map(|v| (v, iterations))
}

/// The most 2D angles of a group whose turns [`turned`] tries, every combination of them.
const MAX_TURNED: usize = 4;

/// The iterations each combination of turns gets in [`turned`].
const TURNED_ITERATIONS: usize = 100;

/// Values where every equation of `kernels` holds with some of the 2D angles of `turning` (as
/// [`turnable`] gives them) turned the other way, solved whole from `start`; `None` when no
/// combination solves. An angle is drawn with a turn, and the equations keep it; a sketch
/// drawn far from its dimensions can need an angle to turn the other way, which Newton cannot
/// reach without passing through a straight angle, nor a build that adds the angle where the
/// sketch shows the same turn. Fewer angles turned are tried first. Of 20,000 random sketches
/// from a second start, one (seed 202236) solved only this way, with the first and third of
/// its four angles turned.
fn turned(
    eqs: &Equations,
    kernels: &[usize],
    turning: &[(usize, Equation)],
    start: &[f64],
    scale_of_param: &dyn Fn(usize) -> f64,
    cfg: &Config,
    iterations: &mut usize,
) -> Option<Vec<f64>> {
    let cfg = &cfg
        .clone()
        .with_max_iterations(cfg.max_iterations.min(TURNED_ITERATIONS))
        .with_find_failed(false);
    let mut masks: Vec<usize> = (1..1usize << turning.len()).collect();
    masks.sort_by_key(|m| m.count_ones());
    masks.into_iter().find_map(|mask| {
        let defs = with_turns(eqs, turning, mask);
        let mut values = start.to_vec();
        solve_alone(
            eqs,
            &defs,
            kernels,
            &mut values,
            scale_of_param,
            cfg,
            iterations,
        )
        .then_some(values)
    })
}

/// The 2D angles among `kernels` that can turn the other way, each with its equation turned
/// ([`other_turn`]); `None` when there are none, or more than `most`.
pub(crate) fn turnable(
    eqs: &Equations,
    kernels: &[usize],
    most: usize,
) -> Option<Vec<(usize, Equation)>> {
    let turning: Vec<(usize, Equation)> = kernels
        .iter()
        .filter_map(|&k| other_turn(&eqs.kernels[k].eq).map(|eq| (k, eq)))
        .collect();
    (!turning.is_empty() && turning.len() <= most).then_some(turning)
}

/// The kernels of `eqs` with the angles of `turning` whose bits are set in `mask` turned.
pub(crate) fn with_turns(
    eqs: &Equations,
    turning: &[(usize, Equation)],
    mask: usize,
) -> Vec<Kernel> {
    let mut defs = eqs.kernels.clone();
    for (i, (k, eq)) in turning.iter().enumerate() {
        if mask & (1 << i) != 0 {
            defs[*k].eq = eq.clone();
        }
    }
    defs
}
