//! Checking loci against SolveSpace's own answers: a file SolveSpace saved holds its solved
//! parameter values, so loci must (1) accept them as a solution, and (2) come back to them
//! from a small perturbation.
//!
//! For each group loci solves, in order:
//! - **agrees**: solving from the saved values leaves every parameter of the group within
//!   [`TOLERANCE`] of them, with outcome okay (or okay with redundant constraints where the
//!   group's `allowRedundant` is set). Any difference of convention (the sign of a signed
//!   distance, which end of a curve, an angle's branch) moves parameters and shows here.
//! - **recovers**: every parameter of the group is moved by a seeded random amount between
//!   1e-3 and 1e-2 (either sign), then solved; the outcome and degrees of freedom must be the
//!   same, and the parameters must be back within [`TOLERANCE`] of SolveSpace's values. In an
//!   under-constrained group the free directions have no preferred value, so the part of the
//!   perturbation along them is taken out: the start is corrected by the solution's
//!   difference from SolveSpace's values and solved again, a few times. A group with wrong
//!   equations or the wrong branch cannot pass this.
//!
//! The file I/O lives in the CLI (`loci conformance DIR`) and in the test suite; this module
//! only takes bytes.

use super::{solve_all, GroupKind, GroupResult, GroupStatus, SlvsFile};
use crate::geom::SplitMix;
use crate::model::{GroupId, ParamId};
use crate::solve::{Config, Outcome};
use std::collections::HashMap;
use std::fmt::Write;

/// How far a parameter may be from SolveSpace's value (SolveSpace saves about 1e-9).
pub const TOLERANCE: f64 = 1e-6;

/// Rounds of correcting the start in free directions before giving up.
const ANCHOR_ROUNDS: usize = 8;

/// The result for one file.
#[derive(Clone, Debug, PartialEq)]
pub struct FixtureCheck {
    /// The verdict.
    pub verdict: Verdict,
    /// Per group, in solve order (empty when the file did not load).
    pub groups: Vec<GroupCheck>,
}

/// The verdict for one file.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// Every group loci solves matches SolveSpace, and there is no group it cannot solve.
    Matched,
    /// Some group does not match, with the first reason.
    Mismatch(String),
    /// Loaded, but some group is not modelled (the reason); the others match.
    Unsupported(String),
    /// The file did not load.
    LoadError(String),
}

impl Verdict {
    /// Whether the file loaded.
    #[must_use]
    pub fn loaded(&self) -> bool {
        !matches!(self, Verdict::LoadError(_))
    }
}

/// The result for one group.
#[derive(Clone, Debug, PartialEq)]
pub struct GroupCheck {
    /// The group.
    pub group: GroupId,
    /// Its type.
    pub kind: GroupKind,
    /// The outcome from the saved values, or `None` when not solved.
    pub outcome: Option<Outcome>,
    /// Degrees of freedom loci finds.
    pub dof: Option<usize>,
    /// Largest parameter change when solving from the saved values.
    pub agree_error: f64,
    /// Largest difference from the saved values after the perturbed solve.
    pub recover_error: f64,
    /// What is wrong, if anything.
    pub problem: Option<String>,
}

/// A small seeded generator ([`SplitMix`]), so runs are repeatable without a dependency.
struct Rng(SplitMix);

impl Rng {
    /// Uniform in `[0, 1)`.
    fn next(&mut self) -> f64 {
        (self.0.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A perturbation between 1e-3 and 1e-2 in size, either sign.
    fn perturbation(&mut self) -> f64 {
        let size = 1e-3 + 9e-3 * self.next();
        if self.next() < 0.5 {
            -size
        } else {
            size
        }
    }
}

/// A seed for a file name, so every file gets its own repeatable perturbation.
#[must_use]
pub fn seed_for(name: &str) -> u64 {
    // FNV-1a.
    name.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// Checks one file against the values SolveSpace saved in it.
#[must_use]
pub fn check(bytes: &[u8], seed: u64) -> FixtureCheck {
    let file = match SlvsFile::parse(bytes) {
        Ok(f) => f,
        Err(e) => {
            return FixtureCheck {
                verdict: Verdict::LoadError(e.to_string()),
                groups: Vec::new(),
            }
        }
    };
    let cfg = Config::default();
    let saved: HashMap<ParamId, f64> = file.system.params().iter().map(|p| (p.h, p.val)).collect();
    let group_params = |g: GroupId| -> Vec<ParamId> {
        file.system
            .params()
            .iter()
            .filter(|p| p.group == g)
            .map(|p| p.h)
            .collect()
    };
    // A `where_dragged` point stays where it is when the equations are written: its position
    // is that constraint's data, like a dimension's value, so it is not perturbed.
    let locked: Vec<ParamId> = file
        .system
        .constraints()
        .iter()
        .filter(|c| c.kind == crate::ConstraintKind::WhereDragged && !c.reference)
        .filter_map(|c| c.pt_a.and_then(|p| file.system.entity(p)))
        .flat_map(|e| e.kind.params().to_vec())
        .collect();
    let error = |f: &SlvsFile, ps: &[ParamId]| -> f64 {
        ps.iter()
            .map(|p| (f.system.value(*p).unwrap_or(f64::NAN) - saved[p]).abs())
            .fold(0.0, f64::max)
    };

    // Agreement: solve every group from the saved values.
    let mut agree = file.clone();
    let results = solve_all(&mut agree, &cfg);
    let mut groups = Vec::new();
    let mut rng = Rng(SplitMix(seed));
    let mut recover = file.clone();
    for (g, res) in file.groups.iter().zip(&results) {
        let ps = group_params(g.h);
        let mut check = GroupCheck {
            group: g.h,
            kind: g.kind,
            outcome: None,
            dof: None,
            agree_error: 0.0,
            recover_error: 0.0,
            problem: None,
        };
        match &res.result {
            GroupResult::References => {}
            GroupResult::Unsupported(why) => check.problem = Some(why.clone()),
            GroupResult::Error(e) => check.problem = Some(format!("solve error: {e}")),
            GroupResult::Solved(r) => {
                check.outcome = Some(r.outcome);
                check.dof = Some(r.dof);
                check.agree_error = error(&agree, &ps);
                if !res.is_ok() {
                    check.problem = Some(outcome_problem(r, g.allow_redundant));
                } else if !(check.agree_error <= TOLERANCE) {
                    check.problem = Some(format!(
                        "solving from SolveSpace's values moves them by {:.1e}",
                        check.agree_error
                    ));
                }
                let free: Vec<ParamId> =
                    ps.iter().copied().filter(|p| !locked.contains(p)).collect();
                let (err, problem) =
                    recover_group(&mut recover, g.h, &ps, &free, &saved, r, &mut rng);
                check.recover_error = err;
                if check.problem.is_none() {
                    check.problem = problem;
                }
            }
        }
        groups.push(check);
    }
    let verdict = verdict(&file, &groups);
    FixtureCheck { verdict, groups }
}

fn outcome_problem(r: &crate::Report, allow_redundant: bool) -> String {
    let named: Vec<String> = r.failed.iter().map(|c| format!("{:08x}", c.0)).collect();
    let mut s = format!("outcome {}", r.outcome);
    if r.outcome == Outcome::RedundantOkay && !allow_redundant {
        s.push_str(" but the group does not allow redundant constraints");
    }
    if !named.is_empty() {
        let _ = write!(s, " (constraints {})", named.join(", "));
    }
    if !r.failed_entities.is_empty() {
        let _ = write!(s, " (entity conditions {:?})", r.failed_entities);
    }
    s
}

/// Perturbs the `perturbed` parameters of group `g` (of all its parameters `ps`), solves it, and measures how far it lands from `saved`;
/// leaves the solution in `file` for the groups after it.
fn recover_group(
    file: &mut SlvsFile,
    g: GroupId,
    ps: &[ParamId],
    perturbed: &[ParamId],
    saved: &HashMap<ParamId, f64>,
    expected: &crate::Report,
    rng: &mut Rng,
) -> (f64, Option<String>) {
    if !file.system.groups().contains(&g) {
        // Nothing in it to perturb or solve.
        return (0.0, None);
    }
    let cfg = Config::default();
    let mut start: Vec<f64> = ps
        .iter()
        .map(|p| {
            if perturbed.contains(p) {
                saved[p] + rng.perturbation()
            } else {
                saved[p]
            }
        })
        .collect();
    let mut err = f64::INFINITY;
    for round in 0..=ANCHOR_ROUNDS {
        for (p, v) in ps.iter().zip(&start) {
            file.system.set_value(*p, *v);
        }
        let r = match crate::solve(&mut file.system, g, &[], &cfg) {
            Ok(r) => r,
            Err(e) => return (err, Some(format!("perturbed solve error: {e}"))),
        };
        if r.outcome != expected.outcome || r.dof != expected.dof {
            return (
                err,
                Some(format!(
                    "after perturbation: outcome {} dof {} (unperturbed: {} dof {})",
                    r.outcome, r.dof, expected.outcome, expected.dof
                )),
            );
        }
        let diff: Vec<f64> = ps
            .iter()
            .map(|p| file.system.value(*p).unwrap_or(f64::NAN) - saved[p])
            .collect();
        err = diff.iter().map(|d| d.abs()).fold(0.0, f64::max);
        // A fully constrained group has nowhere else to go: one solve decides.
        if err <= TOLERANCE * 1e-3 || expected.dof == 0 || round == ANCHOR_ROUNDS {
            break;
        }
        for (s, d) in start.iter_mut().zip(&diff) {
            *s -= d;
        }
    }
    if err <= TOLERANCE {
        (err, None)
    } else {
        (
            err,
            Some(format!(
                "after perturbation the solution is {err:.1e} from SolveSpace's values"
            )),
        )
    }
}

fn verdict(file: &SlvsFile, groups: &[GroupCheck]) -> Verdict {
    let unsupported = file.groups.iter().find_map(|g| match &g.status {
        GroupStatus::Unsupported(why) => Some(format!("group {} ({}): {why}", g.h.0, g.name)),
        _ => None,
    });
    let mismatch = file
        .groups
        .iter()
        .zip(groups)
        .filter(|(g, _)| g.status == GroupStatus::Solve)
        .find_map(|(g, c)| {
            c.problem
                .as_ref()
                .map(|p| format!("group {} ({}): {p}", g.h.0, g.name))
        });
    match (mismatch, unsupported) {
        (Some(m), _) => Verdict::Mismatch(m),
        (None, Some(u)) => Verdict::Unsupported(u),
        (None, None) => Verdict::Matched,
    }
}

/// Counts over a set of files.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Summary {
    /// Files checked.
    pub total: usize,
    /// Files that loaded.
    pub loaded: usize,
    /// Files whose every group matched.
    pub matched: usize,
    /// Files with a group loci does not model (the rest matched).
    pub unsupported: usize,
    /// Files with a group that did not match.
    pub mismatched: usize,
}

impl Summary {
    /// Counts the verdicts.
    #[must_use]
    pub fn of(results: &[(String, FixtureCheck)]) -> Self {
        let mut s = Summary {
            total: results.len(),
            ..Summary::default()
        };
        for (_, r) in results {
            match r.verdict {
                Verdict::Matched => s.matched += 1,
                Verdict::Mismatch(_) => s.mismatched += 1,
                Verdict::Unsupported(_) => s.unsupported += 1,
                Verdict::LoadError(_) => {}
            }
            if r.verdict.loaded() {
                s.loaded += 1;
            }
        }
        s
    }
}

/// The conformance report as Markdown: totals, then every file that does not match with
/// the reason, then every file with its groups' outcomes and degrees of freedom.
#[must_use]
pub fn render_markdown(results: &[(String, FixtureCheck)], command: &str) -> String {
    let s = Summary::of(results);
    let mut out = String::new();
    let _ = writeln!(out, "# Conformance with SolveSpace's regression fixtures\n");
    let _ = writeln!(
        out,
        "Generated by `{command}`. Each fixture was saved by SolveSpace after it solved the \
         file, so its parameter values are SolveSpace's answer. For every group loci solves: \
         solving from the saved values must leave them within {TOLERANCE:e} (with outcome okay, \
         or redundant_okay where the group allows redundant constraints), and after a seeded \
         perturbation of 1e-3..1e-2 on every parameter of the group loci must come back to \
         them within {TOLERANCE:e} with the same outcome and degrees of freedom (free \
         directions of under-constrained groups are taken out of the perturbation; see \
         `crates/loci/src/format/slvs/conformance.rs`).\n"
    );
    let _ = writeln!(out, "| | files |\n| --- | ---: |");
    let _ = writeln!(out, "| fixtures | {} |", s.total);
    let _ = writeln!(out, "| load | {} |", s.loaded);
    let _ = writeln!(out, "| match SolveSpace in every group | {} |", s.matched);
    let _ = writeln!(
        out,
        "| match in every group loci solves, but have a group loci does not model | {} |",
        s.unsupported
    );
    let _ = writeln!(out, "| do not match | {} |", s.mismatched);
    let _ = writeln!(out, "| do not load | {} |\n", s.total - s.loaded);

    let _ = writeln!(out, "## Files that do not fully match\n");
    let mut any = false;
    for (name, r) in results {
        let why = match &r.verdict {
            Verdict::Matched => continue,
            Verdict::Mismatch(m) => format!("mismatch: {m}"),
            Verdict::Unsupported(u) => format!("not modelled: {u}"),
            Verdict::LoadError(e) => format!("does not load: {e}"),
        };
        any = true;
        let _ = writeln!(out, "- `{name}`: {}", why.replace('\n', " "));
    }
    if !any {
        let _ = writeln!(out, "None.");
    }
    let _ = writeln!(out, "\n## Every file\n");
    let _ = writeln!(
        out,
        "Groups in solve order: outcome and degrees of freedom, `-` for a group loci does not \
         solve (reference planes, or not modelled).\n"
    );
    let _ = writeln!(out, "| file | verdict | groups |\n| --- | --- | --- |");
    for (name, r) in results {
        let v = match r.verdict {
            Verdict::Matched => "match",
            Verdict::Mismatch(_) => "mismatch",
            Verdict::Unsupported(_) => "partly modelled",
            Verdict::LoadError(_) => "load error",
        };
        let gs: Vec<String> = r
            .groups
            .iter()
            .map(|g| match (g.outcome, g.dof) {
                (Some(o), Some(d)) => format!("{}: {o}, dof {d}", g.group.0),
                _ => format!("{}: -", g.group.0),
            })
            .collect();
        let _ = writeln!(out, "| `{name}` | {v} | {} |", gs.join("; "));
    }
    out
}
