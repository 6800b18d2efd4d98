//! The solver pipeline: equations, substitution, decomposition, Newton, rank and report.
//!
//! 1. Every constraint of the group (and every implicit condition of its entities) is compiled
//!    into equations with exact derivatives ([`crate::equations`]).
//! 2. Equations `a = b` and `a = value` between parameters are removed by merging parameters.
//! 3. The remaining equations split into independent components (connected through shared
//!    unknowns); each is solved on its own, on all cores when there are many.
//! 4. Newton steps of minimum weighted norm move the drawing as little as possible; dragged
//!    parameters weigh more, so they move least.
//! 5. The rank of each component's Jacobian at the end gives the degrees of freedom and the
//!    redundant or conflicting constraints.

mod config;
#[cfg(test)]
mod dense;
mod envelope;
pub(crate) mod gram;
pub(crate) mod newton;
mod order;
#[cfg(test)]
mod pinned_tests;
mod plan;
pub(crate) mod rank;
#[cfg(test)]
mod rank_tests;
mod report;
mod rescue;
mod runaway;
mod scattered_memo;
#[cfg(test)]
mod slide_tests;
mod substitute;
mod supernodal;
#[cfg(test)]
mod test_support;
mod unknowns;
#[cfg(test)]
mod unknowns_tests;

pub use config::Config;
pub(crate) use gram::MAX_PRODUCTS;
pub use report::{Outcome, Report};
pub(crate) use rescue::{
    checked_scattered, holds_alone, rescued_alone, rescued_scattered, solution_further_off,
    Scattered,
};
use rescue::{found_further_off, rescued};

use crate::equations::{compile_group, still_duplicates, Carried, Link, Owner};
use crate::error::SolveError;
use crate::model::{ConstraintId, GroupId, ParamId, System};
use crate::par;
use newton::Component;
use plan::{substitute, Plan};

/// Solves `group` of `sys` in place: parameters of the group are unknowns, all others are
/// constants. `dragged` parameters move as little as possible.
///
/// Parameter values are written back only when the outcome is okay (possibly with redundant
/// constraints); after an inconsistent or non-converged solve every parameter keeps its
/// starting value, as with libslvs.
///
/// # Errors
/// An invalid model (dangling or zero handles, wrong entity types, NaN values, a 2D-only
/// constraint with no workplane), an unknown dragged parameter, or a bad option.
pub fn solve(
    sys: &mut System,
    group: GroupId,
    dragged: &[ParamId],
    cfg: &Config,
) -> Result<Report, SolveError> {
    cfg.check()?;
    sys.validate()?;
    check_group(sys, group)?;
    let cfg = cfg.for_group(sys, group);
    let mut cache = Cache::default();
    let report = solve_cached(sys, group, dragged, &cfg, &mut cache);
    cache.discard();
    report
}

/// Solves `group` without touching `sys`: the report, and the value of every parameter where
/// the solve stopped (in [`System::params`] order), whether or not it succeeded.
pub(crate) fn solve_core(
    sys: &System,
    group: GroupId,
    dragged: &[ParamId],
    cfg: &Config,
) -> Result<(Report, Vec<f64>), SolveError> {
    cfg.check()?;
    sys.validate()?;
    check_group(sys, group)?;
    let cfg = &*cfg.for_group(sys, group);
    let mut cache = Cache::default();
    let (report, values, _) = solve_values_checked(sys, group, dragged, cfg, &mut cache)?;
    if !report.outcome.is_ok() {
        if let Some((mut again, at)) = rescued(sys, group, dragged, cfg, &mut cache)? {
            again.iterations += report.iterations;
            return Ok((again, at));
        }
    }
    Ok((report, values))
}

/// A solve of a group that nothing belongs to is a mistake (a wrong number, an empty file),
/// not a sketch with nothing to do: say so, with the groups there are.
pub(crate) fn check_group(sys: &System, group: GroupId) -> Result<(), SolveError> {
    // The sorted list of groups is only built for the error: most solves name a group that
    // has objects, and sorting every object's group was a visible part of a small solve.
    if sys.has_group(group) {
        return Ok(());
    }
    Err(SolveError::UnknownGroup {
        group,
        existing: sys.groups(),
    })
}

/// What a [`Solver`] keeps between solves of a system whose structure has not changed: the
/// compiled equations (with the branches they chose) and each component with its symbolic
/// factorisation.
#[derive(Default)]
struct Cache {
    /// The system and structural revision the cache was built for.
    key: Option<(u64, u64)>,
    links: Vec<Link>,
    kernels: Vec<crate::equations::Kernel>,
    /// Constraints left out as copies of others: `(copy, first)`.
    duplicates: Vec<(ConstraintId, ConstraintId)>,
    /// Entities read as expressions of their carriers, written back after the solve.
    carried: Carried,
    /// Every carried entity kept as its own unknowns with its implicit equation.
    plain: bool,
    /// Merged and fixed parameters, columns and components.
    plan: Option<Plan>,
    components: Vec<Component>,
    /// Newton's work vectors, kept for the next solve on this thread.
    scratch: newton::Scratch,
    /// Whether, in the last solve, damped steps of some component stopped short of the
    /// least-squares point they were creeping towards ([`Config::settle`]).
    settled: bool,
}

impl Cache {
    /// Drops the cache, its many small components and kernels freed on the thread pool when
    /// there are many (see [`par::discard`]), so that a one-off solve returns first.
    fn discard(self) {
        par::discard(self.components);
        par::discard(self.kernels);
    }
}

/// A reusable solver for one group: the first solve compiles the equations, splits them into
/// components and analyses each component's sparsity; later solves of the same system (after
/// the user drags a point, moves a fixed point or edits a dimension) reuse all of it.
///
/// Values may change freely between solves: parameter values, constraint values (`val`). Any
/// structural edit (adding or removing objects, changing a constraint's kind, references,
/// workplane, group or flags, a parameter's group) advances [`System::revision`], and the next
/// solve rebuilds the structure; so does solving another system, a clone included. Branches
/// chosen from the starting configuration (the sign of a 2D angle, `where_dragged` targets of
/// points that are not in their constraint's workplane) are kept from the first solve.
pub struct Solver {
    group: GroupId,
    dragged: Vec<ParamId>,
    cfg: Config,
    cache: Cache,
}

impl Solver {
    /// A solver for `group`, with `dragged` parameters moving least.
    #[must_use]
    pub fn new(group: impl Into<GroupId>, dragged: &[ParamId], cfg: Config) -> Self {
        Self {
            group: group.into(),
            dragged: dragged.to_vec(),
            cfg,
            cache: Cache::default(),
        }
    }

    /// Forgets the compiled structure; the next solve rebuilds it.
    pub fn invalidate(&mut self) {
        self.cache = Cache::default();
    }

    /// Solves the group in place, reusing the structure from earlier solves.
    ///
    /// # Errors
    /// As [`solve`].
    pub fn solve(&mut self, sys: &mut System) -> Result<Report, SolveError> {
        if self.cache.key != Some(sys.structure_key()) {
            self.cfg.check()?;
            sys.validate()?;
            check_group(sys, self.group)?;
            self.cache = Cache::default();
        } else {
            // Values may have changed since: they must still be numbers.
            sys.validate_values()?;
        }
        let cfg = self.cfg.for_group(sys, self.group);
        solve_cached(sys, self.group, &self.dragged, &cfg, &mut self.cache)
    }
}

fn solve_cached(
    sys: &mut System,
    group: GroupId,
    dragged: &[ParamId],
    cfg: &Config,
    cache: &mut Cache,
) -> Result<Report, SolveError> {
    let (mut report, mut values, plain) = solve_values_checked(sys, group, dragged, cfg, cache)?;
    if cfg.name_conflicts
        && matches!(
            report.outcome,
            Outcome::Inconsistent | Outcome::DidNotConverge
        )
    {
        // Check the verdict and name the sets that cannot hold together, found on the
        // unmerged equations where the solve stopped (those of the constraints it found
        // dependent, or left unsatisfied, first) and each shown to fail on its own; only
        // failures pay for it. A solve that did not converge becomes inconsistent when such a
        // set is found: the rows of an impossible system become dependent only at its
        // least-squares point, which Newton may not reach.
        let used = plain.as_ref().unwrap_or(cache);
        let mut held = Vec::new();
        let mut proven = crate::diagnose::name_conflicts(
            sys,
            group,
            &values,
            cfg,
            &mut report,
            &used.kernels,
            &used.links,
            &mut held,
        );
        // Damped steps may have stopped short of that point, once what was left to gain at
        // their rate was small (`Config::settle`); where nothing was shown from there, they
        // creep on to it and the search runs again. Three of 5,000 random systems against
        // SolveSpace were named from the point itself and not from the early stop.
        if !proven && cfg.settle && plain.as_ref().unwrap_or(cache).settled {
            let full = Config {
                settle: false,
                ..cfg.clone()
            };
            let (mut again, at, plain) = solve_values_checked(sys, group, dragged, &full, cache)?;
            // A crawl that went on to a solution after all is the answer too.
            let settled = again.outcome.is_ok() || {
                let used = plain.as_ref().unwrap_or(cache);
                crate::diagnose::name_conflicts(
                    sys,
                    group,
                    &at,
                    &full,
                    &mut again,
                    &used.kernels,
                    &used.links,
                    &mut held,
                )
            };
            if settled {
                (report, values, proven) = (again, at, true);
            }
        }
        // Nothing shown to fail on its own: Newton from the whole drawing may have folded the
        // sketch on its way. Look for a solution another way ([`rescued`]), then from further
        // off ([`found_further_off`]).
        if !proven {
            let mut found = rescued(sys, group, dragged, cfg, cache)?;
            if found.is_none() {
                found = found_further_off(sys, group, dragged, cfg, cache, &held)?;
            }
            if let Some((mut again, at)) = found {
                again.iterations += report.iterations;
                (report, values) = (again, at);
            }
        }
    }
    // Values are written back only when every constraint holds, as libslvs does: a failed
    // solve leaves the caller's parameters as they were.
    if report.outcome.is_ok() {
        sys.write_group_values(group, &values);
    }
    Ok(report)
}

/// [`solve_values`], and when it fails with carried entities read as expressions, the solve
/// again with each of them its own unknowns and implicit equation (the cache of that solve
/// returned too). An impossible system has no solution for the two to agree on: Newton
/// stops at the least-squares point of different equations, and a point carried off its
/// part is what lets the dependent rows of the conflict show; the verdict and the names are
/// then those a solve without expressions gives. Only failures pay for it.
fn solve_values_checked(
    sys: &System,
    group: GroupId,
    dragged: &[ParamId],
    cfg: &Config,
    cache: &mut Cache,
) -> Result<(Report, Vec<f64>, Option<Cache>), SolveError> {
    let (report, values) = solve_values(sys, group, dragged, cfg, cache, None)?;
    let failed = matches!(
        report.outcome,
        Outcome::Inconsistent | Outcome::DidNotConverge
    );
    if !failed || cache.carried.is_empty() {
        return Ok((report, values, None));
    }
    let mut plain = Cache {
        plain: true,
        ..Cache::default()
    };
    let (report, values) = solve_values(sys, group, dragged, cfg, &mut plain, None)?;
    Ok((report, values, Some(plain)))
}

/// The solve itself: the report and the value of every parameter where it stopped.
fn solve_values(
    sys: &System,
    group: GroupId,
    dragged: &[ParamId],
    cfg: &Config,
    cache: &mut Cache,
    start: Option<&[f64]>,
) -> Result<(Report, Vec<f64>), SolveError> {
    let params = sys.params();
    let np = params.len();
    let mut values: Vec<f64> = match start {
        Some(v) => v.to_vec(),
        None => params.iter().map(|p| p.val).collect(),
    };
    let key = sys.structure_key();
    if cache.key == Some(key) && !still_duplicates(sys, &cache.duplicates) {
        // A value edit made copies of a constraint different equations again.
        cache.key = None;
    }
    if cache.key != Some(key) {
        *cache = Cache {
            plain: cache.plain,
            ..Cache::default()
        };
        // The drawing's own values, where the solve starts elsewhere.
        let own: Vec<f64>;
        let drawn = match start {
            Some(_) => {
                own = params.iter().map(|p| p.val).collect();
                &own[..]
            }
            None => &values[..],
        };
        let compiled = compile_group(sys, group, dragged, !cache.plain, &values, drawn)?;
        cache.kernels = compiled.kernels;
        cache.links = compiled.links;
        cache.duplicates = compiled.duplicates;
        cache.carried = compiled.carried;
        cache.key = Some(key);
    } else {
        refresh(sys, cache);
    }
    if cfg.solvespace_angles {
        let mut x = Vec::new();
        for k in cache.kernels.iter_mut().filter(|k| k.eq.is_planar_angle()) {
            k.gather(&values, &mut x);
            k.eq.write_angle_as_solvespace(&x);
        }
    }
    let tol = cfg.tolerance;

    // 2. Substitution: which parameters merge or are fixed depends on the structure only (the
    // plan, kept between solves); the values they take, and whether they agree, on the values.
    let (plan, mut sub) = match &mut cache.plan {
        Some(plan) => {
            let sub = substitute(&cache.links, &plan.unknown, &values, tol);
            (&*plan, sub)
        }
        slot @ None => {
            let (plan, sub) = Plan::new(
                sys,
                group,
                dragged,
                &cache.kernels,
                &cache.links,
                &cache.carried,
                &values,
                tol,
            )?;
            (&*slot.insert(plan), sub)
        }
    };
    let kernels = &cache.kernels;
    // Starting value of each merged set: the mean of its dragged members if any, else of all.
    let mut sum = vec![(0.0f64, 0u32); np];
    for p in 0..np {
        let r = plan.root_of[p];
        if r == usize::MAX || (plan.root_dragged[r] && !plan.dragged[p]) {
            continue;
        }
        sum[r].0 += values[p];
        sum[r].1 += 1;
    }
    // Fixed sets start at their value and are constants of the solve.
    let mut start = vec![0.0; np];
    for p in 0..np {
        let r = plan.root_of[p];
        if r == usize::MAX {
            continue;
        }
        start[p] = match sub.fixed_value(p) {
            Some(v) => v,
            None => sum[r].0 / f64::from(sum[r].1),
        };
        // Constants take their (merged or fixed) starting values.
        values[p] = start[p];
    }
    let Plan {
        unknown,
        root_dragged,
        col_root,
        comps,
        local,
        constant_kernels,
        n_unknown,
        ..
    } = plan;
    let col_of_param = |p: usize| plan.col(p);
    let ncomps = comps.col_ptr.len() - 1;

    // 4. Newton per component.
    let mut report = Report {
        unknowns: n_unknown - sub.removed,
        equations: kernels.iter().map(|k| k.rows).sum(),
        components: ncomps,
        ..Report::empty()
    };
    let mut rank_total = 0usize;
    let mut redundant: Vec<Owner> = Vec::new();
    let mut conflicting: Vec<Owner> = Vec::new();
    let mut unsatisfied: Vec<Owner> = Vec::new();
    let mut x_all: Vec<f64> = col_root.iter().map(|&r| start[r]).collect();
    let parallel = report.equations >= par::MIN_PARALLEL && ncomps > 1;
    if cache.components.len() != ncomps {
        let build = |_: &mut (), ci: usize, _: ()| {
            let (members, cols) = (comps.members(ci), comps.cols(ci));
            let scale: Vec<f64> = cols
                .iter()
                .map(|&c| {
                    if root_dragged[col_root[c]] {
                        cfg.dragged_scale
                    } else {
                        1.0
                    }
                })
                .collect();
            let map = |p: usize| col_of_param(p).map(|c| local[c as usize]);
            Component::new(kernels, members, &map, cols.len(), scale)
        };
        cache.components = par::map_items(vec![(); ncomps], parallel, || (), build);
    }
    // The unknowns of every component, in component order, cut into one slice per component.
    let mut x_grouped: Vec<f64> = comps.cols.iter().map(|&c| x_all[c]).collect();
    let mut work = Vec::with_capacity(ncomps);
    let mut rest = &mut x_grouped[..];
    for comp in cache.components.iter_mut() {
        let (x, tail) = rest.split_at_mut(comp.scale.len());
        work.push((comp, x));
        rest = tail;
    }
    let mut finishes: Vec<newton::Finish> = if parallel {
        par::map_items(
            work,
            true,
            newton::Scratch::default,
            |scratch, _, (comp, x)| comp.solve(kernels, x, &values, cfg, scratch),
        )
    } else {
        // On this thread, with the work vectors of the last solve: a re-solve allocates none.
        let scratch = &mut cache.scratch;
        work.into_iter()
            .map(|(comp, x)| comp.solve(kernels, x, &values, cfg, scratch))
            .collect()
    };
    runaway::reject_runaways(
        &cache.components,
        &mut finishes,
        &x_grouped,
        &comps.cols,
        col_root,
        params,
        kernels,
    );
    cache.settled = finishes.iter().any(|f| f.settled);
    if let Some(ci) = finishes.iter().position(|f| f.too_large) {
        let comp = &cache.components[ci];
        return Err(SolveError::TooLarge {
            equations: comp.rows,
            unknowns: comp.scale.len(),
            products: crate::solve::gram::Gram::products(&comp.columns),
        });
    }
    for (ci, fin) in finishes.into_iter().enumerate() {
        let comp = &cache.components[ci];
        report.iterations = report.iterations.max(fin.iterations);
        report.residual = report.residual.max(fin.residual);
        rank_total += comp.rows - fin.dependent;
        let owner_of = |row: usize| {
            let (b, _) = comp.row_block[row];
            kernels[comp.blocks[b as usize].kernel].owner
        };
        // Kept even when the component failed: the diagnosis starts where Newton stopped.
        let x = &x_grouped[comps.col_ptr[ci]..comps.col_ptr[ci + 1]];
        for (i, &c) in comps.cols(ci).iter().enumerate() {
            x_all[c] = x[i];
        }
        if fin.converged {
            for dep in &fin.dependencies {
                redundant.extend(dep.iter().map(|&r| owner_of(r)));
            }
            if !cfg.find_failed {
                redundant.extend(fin.dropped.iter().map(|&r| owner_of(r)));
            }
        } else if !fin.dropped.is_empty() {
            for dep in &fin.dependencies {
                conflicting.extend(dep.iter().map(|&r| owner_of(r)));
            }
            if conflicting.is_empty() {
                conflicting.extend(fin.dropped.iter().map(|&r| owner_of(r)));
            }
        } else {
            unsatisfied.extend(fin.unsatisfied.iter().map(|&r| owner_of(r)));
        }
    }
    for &ki in constant_kernels {
        let k = &kernels[ki];
        let mut xs = Vec::new();
        k.gather(&values, &mut xs);
        let mut out = crate::equations::Rows::new();
        k.eq.eval(&xs, &mut out);
        let bad = out.v[..out.n].iter().any(|v| !(v.abs() <= tol));
        if bad {
            conflicting.push(k.owner);
        } else {
            redundant.push(k.owner);
        }
    }
    for s in &sub.redundant {
        redundant.extend(s);
    }
    for &(copy, first) in &cache.duplicates {
        redundant.push(Owner::Constraint(copy));
        redundant.push(Owner::Constraint(first));
    }
    for s in &sub.conflicts {
        conflicting.extend(s);
    }

    // 5. Outcome, DOF, write-back.
    report.dof = report.unknowns.saturating_sub(rank_total);
    let failed = if !conflicting.is_empty() {
        report.outcome = Outcome::Inconsistent;
        conflicting
    } else if !unsatisfied.is_empty() {
        report.outcome = Outcome::DidNotConverge;
        unsatisfied
    } else if !redundant.is_empty() {
        report.outcome = Outcome::RedundantOkay;
        redundant
    } else {
        Vec::new()
    };
    if cfg.find_failed {
        for o in failed {
            match o {
                Owner::Constraint(c) => report.failed.push(c),
                Owner::Entity(e) => report.failed_entities.push(e),
            }
        }
        report.failed.sort_unstable();
        report.failed.dedup();
        report.failed_entities.sort_unstable();
        report.failed_entities.dedup();
    }
    let mut out = values;
    for p in 0..np {
        if unknown[p] {
            out[p] = match col_of_param(p) {
                Some(c) => x_all[c as usize],
                None => start[p],
            };
        }
    }
    // Carried entities follow what carries them, wherever the solve stopped.
    cache.carried.write_back(sys, &mut out);
    Ok((report, out))
}

/// Brings cached equations up to date with the system's current values: constraint values,
/// and the values that `where_dragged` and circle diameters fix parameters at.
fn refresh(sys: &System, cache: &mut Cache) {
    for k in &mut cache.kernels {
        if let Owner::Constraint(h) = k.owner {
            if let Some(c) = sys.constraint(h) {
                if k.eq.val.to_bits() != c.val.to_bits() {
                    k.eq.val = c.val;
                    k.eq.prepare();
                }
            }
        }
    }
    for l in &mut cache.links {
        if let Link::Fix {
            owner: Owner::Constraint(h),
            p,
            value,
        } = l
        {
            if let Some(c) = sys.constraint(*h) {
                // A point held where it is dragged: where the drawing has it now, not where
                // the solve starts.
                *value = match c.kind {
                    crate::model::ConstraintKind::Diameter => c.val / 2.0,
                    _ => sys.params()[*p].val,
                };
            }
        }
    }
}

impl System {
    /// Solves `group` with default settings and no dragged parameters. See [`solve`].
    ///
    /// # Errors
    /// As [`solve`].
    pub fn solve_group(&mut self, group: impl Into<GroupId>) -> Result<Report, SolveError> {
        solve(self, group.into(), &[], &Config::default())
    }
}
