//! `loci-bench wasm`: loci compiled to WebAssembly (the npm package of `crates/loci-wasm`)
//! under node, side by side in one run with native loci (in this process) and PlaneGCS (npm
//! `@salusoft89/planegcs`, also WebAssembly under node), on the chain and grid families.
//!
//! Every solver gets the same generated problem: loci (native and wasm) the same loci JSON
//! problem, PlaneGCS its translation ([`crate::peers::to_planegcs`]). Each answer is checked
//! by the harness ([`crate::run::judge`]). Times are the solve call alone, the median over
//! the repetitions; the build (reading the problem into the solver) is listed apart for wasm.
//! Both WebAssembly runners first solve untimed for a second (`LOCI_BENCH_WARMUP_S`), so that
//! node's optimising compiler has taken over the hot functions, as in a page that has been
//! dragging for a moment; native loci is compiled ahead of time.

use crate::generate::generate;
use crate::problem::{Family, Problem, Variant};
use crate::run::{self, judge, median, ProblemFiles, RunOutput, Runners, Solver, Verdict};
use crate::slvs;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

/// One solver on one problem.
#[derive(Clone, Debug)]
pub enum Timing {
    /// It ran: median solve and build times (milliseconds) and the harness's verdict.
    Ran {
        /// Median solve time.
        solve_ms: f64,
        /// Median build time.
        build_ms: f64,
        /// The harness's verdict on the answer.
        verdict: Verdict,
    },
    /// It did not run, and why.
    Skipped(String),
}

impl Timing {
    fn solved_ms(&self) -> Option<f64> {
        match self {
            Timing::Ran {
                solve_ms,
                verdict: Verdict::Solved,
                ..
            } => Some(*solve_ms),
            _ => None,
        }
    }

    fn cell(&self) -> String {
        match self {
            Timing::Ran {
                solve_ms,
                verdict: Verdict::Solved,
                ..
            } => format!("{solve_ms:.3}"),
            Timing::Ran {
                verdict: Verdict::Crashed { detail },
                ..
            } if detail.contains("out of memory") => "out of memory".into(),
            Timing::Ran {
                verdict: Verdict::Timeout { limit_s },
                ..
            } => format!("time limit ({limit_s} s)"),
            Timing::Ran { verdict, .. } => {
                let v = format!("{verdict:?}");
                v.chars().take(60).collect()
            }
            Timing::Skipped(why) => format!("– ({why})"),
        }
    }

    fn from_output(p: &Problem, out: &RunOutput) -> Self {
        let (verdict, _) = judge(p, out);
        Timing::Ran {
            solve_ms: median(&out.solve_ms).unwrap_or(f64::NAN),
            build_ms: median(&out.build_ms).unwrap_or(f64::NAN),
            verdict,
        }
    }
}

/// One row: a problem and the three solvers on it.
#[derive(Clone, Debug)]
pub struct Row {
    /// The family.
    pub family: Family,
    /// The size as generated (segments for the chain, the side for the grid).
    pub size: usize,
    /// Unknowns of the problem (two per point).
    pub unknowns: usize,
    /// Native loci.
    pub native: Timing,
    /// loci as WebAssembly under node.
    pub wasm: Timing,
    /// PlaneGCS under node.
    pub planegcs: Timing,
}

/// What a run needs.
pub struct Setup<'a> {
    /// `node`.
    pub node: PathBuf,
    /// The repository's root.
    pub repo: &'a Path,
    /// Runners (PlaneGCS's `node`, if installed).
    pub runners: &'a Runners,
    /// Repetitions (at most).
    pub reps: usize,
    /// Stop repeating once the solves add up to this many seconds.
    pub budget_s: f64,
    /// Time limit of one peer process.
    pub limit: Duration,
    /// Where problem files go.
    pub work: &'a Path,
}

/// The loci JSON problem and each point's parameters, as `loci_wasm_runner.mjs` reads them.
///
/// # Errors
/// A problem the SolveSpace model cannot take.
pub fn wasm_input(p: &Problem) -> anyhow::Result<String> {
    let sp = slvs::build(p)?;
    let points: Vec<Vec<u32>> = sp
        .points
        .iter()
        .map(|&e| {
            sp.system
                .entity(e.into())
                .map(|ent| ent.kind.params().iter().map(|h| h.0).collect())
                .unwrap_or_default()
        })
        .collect();
    let problem = loci::format::json::Problem {
        system: sp.system,
        solve: Some(loci::format::json::SolveRequest {
            group: slvs::SOLVE_GROUP.into(),
            dragged: Vec::new(),
            calculate_failed: true,
            options: loci::format::json::Options::default(),
        }),
    };
    Ok(serde_json::to_string(
        &serde_json::json!({ "problem": problem, "points": points }),
    )?)
}

fn run_wasm(s: &Setup<'_>, p: &Problem, budget_s: f64) -> Timing {
    let pkg = s.repo.join("crates/loci-wasm/pkg/web.js");
    if !pkg.exists() {
        return Timing::Skipped("not built: run scripts/build-wasm.sh".into());
    }
    let stem = s.work.join(p.label().replace('/', "_"));
    let (input, out) = (
        stem.with_extension("wasm.json"),
        stem.with_extension("wasm.out.json"),
    );
    let text = match wasm_input(p) {
        Ok(t) => t,
        Err(e) => return Timing::Skipped(format!("could not write its input: {e}")),
    };
    if let Err(e) = std::fs::write(&input, text) {
        return Timing::Skipped(format!("could not write its input: {e}"));
    }
    let mut c = Command::new(&s.node);
    c.arg(s.repo.join("bench/runners/loci_wasm_runner.mjs"))
        .arg(&input)
        .arg(s.reps.to_string())
        .arg(budget_s.to_string())
        .arg(&out);
    let end = run::run_with_limit(c, s.limit);
    let _ = std::fs::remove_file(&input);
    let timing = match end {
        Ok(end) if end.status.is_some_and(|st| st.success()) => {
            match std::fs::read_to_string(&out)
                .ok()
                .and_then(|t| serde_json::from_str::<RunOutput>(&t).ok())
            {
                Some(o) => Timing::from_output(p, &o),
                None => Timing::Skipped("no output".into()),
            }
        }
        Ok(end) if end.status.is_none() => Timing::Ran {
            solve_ms: f64::NAN,
            build_ms: f64::NAN,
            verdict: Verdict::Timeout {
                limit_s: s.limit.as_secs_f64(),
            },
        },
        Ok(end) => Timing::Skipped(run::describe_death(end.status, &end.stderr)),
        Err(e) => Timing::Skipped(format!("could not start node: {e}")),
    };
    let _ = std::fs::remove_file(&out);
    timing
}

/// Sizes whose solves all take less than this (milliseconds) are timed in [`ROUNDS`] rounds.
const ROUNDS_BELOW_MS: f64 = 50.0;

/// Rounds of the short sizes, every solver in turn in each: the machine's speed drifts over
/// seconds (on a shared 2-core machine, a 30 µs solve read 27 µs in one run and 60 µs in the
/// next, PlaneGCS alike), and one solver timed during a slow spell and the other during a fast
/// one made the ratios at the smallest sizes swing from ×3 to ×9 between runs. Each round has
/// a fifth of the budget, and the median of each solver's round medians is reported.
const ROUNDS: usize = 5;

/// Runs the three solvers on `family` at each size. A peer that fails (or runs out of time)
/// at one size is not run at larger ones.
pub fn run_family(
    s: &Setup<'_>,
    family: Family,
    sizes: &[usize],
    mut log: impl FnMut(&str),
) -> Vec<Row> {
    let mut rows = Vec::new();
    let mut planegcs_stopped: Option<String> = None;
    let mut wasm_stopped: Option<String> = None;
    for &size in sizes {
        let p = generate(family, Variant::Solvable, size);
        // Each round gets its share of the budget.
        let budget = s.budget_s / ROUNDS as f64;
        let round = |wasm_stopped: &Option<String>, planegcs_stopped: &Option<String>| {
            let native = match run::run_in_process(Solver::Loci, &p, s.reps, budget) {
                Ok(o) => Timing::from_output(&p, &o),
                Err(e) => Timing::Skipped(e.to_string()),
            };
            let wasm = match wasm_stopped {
                Some(why) => Timing::Skipped(why.clone()),
                None => run_wasm(s, &p, budget),
            };
            let planegcs = match (planegcs_stopped, &s.runners.node) {
                (Some(why), _) => Timing::Skipped(why.clone()),
                (None, None) => Timing::Skipped("not installed".into()),
                (None, Some(_)) => run_planegcs(s, &p, budget),
            };
            [native, wasm, planegcs]
        };
        let first = round(&wasm_stopped, &planegcs_stopped);
        let short = first
            .iter()
            .all(|t| t.solved_ms().is_none_or(|ms| ms < ROUNDS_BELOW_MS));
        let mut samples: [Vec<Timing>; 3] = first.map(|t| vec![t]);
        if short {
            for _ in 1..ROUNDS {
                for (k, t) in round(&wasm_stopped, &planegcs_stopped)
                    .into_iter()
                    .enumerate()
                {
                    samples[k].push(t);
                }
            }
        }
        let [native, wasm, planegcs] = samples.map(median_of_rounds);
        if wasm.solved_ms().is_none() && wasm_stopped.is_none() {
            wasm_stopped = Some(format!("not solved at size {size}"));
        }
        if planegcs_stopped.is_none() && s.runners.node.is_some() && planegcs.solved_ms().is_none()
        {
            planegcs_stopped = Some(format!("not solved at size {size}"));
        }
        let row = Row {
            family,
            size,
            unknowns: 2 * p.points.len(),
            native,
            wasm,
            planegcs,
        };
        log(&line(&row));
        rows.push(row);
    }
    rows
}

/// PlaneGCS on `p` under node.
fn run_planegcs(s: &Setup<'_>, p: &Problem, budget_s: f64) -> Timing {
    let files = ProblemFiles::new(p, s.work);
    let (v, out, _) = run::run_solver(
        Solver::PlaneGcs,
        &files,
        s.runners,
        s.reps,
        budget_s,
        s.limit,
    );
    files.remove();
    match out {
        Some(o) => Timing::from_output(p, &o),
        None => Timing::Ran {
            solve_ms: f64::NAN,
            build_ms: f64::NAN,
            verdict: v,
        },
    }
}

/// One solver's rounds as one timing: the first that did not solve, if any did not (a solver
/// is judged by its worst answer), otherwise the round with the median solve time.
fn median_of_rounds(mut rounds: Vec<Timing>) -> Timing {
    if let Some(k) = rounds.iter().position(|t| t.solved_ms().is_none()) {
        return rounds.swap_remove(k);
    }
    rounds.sort_by(|a, b| {
        let (a, b) = (a.solved_ms(), b.solved_ms());
        a.unwrap_or(f64::NAN).total_cmp(&b.unwrap_or(f64::NAN))
    });
    let mid = rounds.len() / 2;
    rounds.swap_remove(mid)
}

fn ratio(a: Option<f64>, b: Option<f64>) -> String {
    match (a, b) {
        (Some(a), Some(b)) if b > 0.0 => format!("×{:.2}", a / b),
        _ => "–".into(),
    }
}

fn line(r: &Row) -> String {
    format!(
        "{} {}: native {} ms, wasm {} ms, PlaneGCS {} ms",
        r.family.name(),
        r.size,
        r.native.cell(),
        r.wasm.cell(),
        r.planegcs.cell()
    )
}

/// The markdown table of a run.
#[must_use]
pub fn table(rows: &[Row]) -> String {
    let mut s = String::from(
        "| family | size | unknowns | native loci (ms) | loci-wasm (ms) | loci-wasm build (ms) | wasm / native | PlaneGCS (ms) | PlaneGCS / loci-wasm |\n\
         | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n",
    );
    for r in rows {
        let build = match &r.wasm {
            Timing::Ran { build_ms, .. } => format!("{build_ms:.3}"),
            Timing::Skipped(_) => "–".into(),
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.family.name(),
            r.size,
            r.unknowns,
            r.native.cell(),
            r.wasm.cell(),
            build,
            ratio(r.wasm.solved_ms(), r.native.solved_ms()),
            r.planegcs.cell(),
            ratio(r.planegcs.solved_ms(), r.wasm.solved_ms()),
        );
    }
    s
}
