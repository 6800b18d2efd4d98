//! The whole comparison: which problems, which solvers, and the table of what happened.

use crate::generate::{generate, recorded_size};
use crate::problem::{Family, Variant};
use crate::run::{median, run_solver, ProblemFiles, Runners, Solver, Verdict};
use crate::setup::Availability;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;
use std::time::Duration;

/// How a comparison runs.
#[derive(Clone, Debug)]
pub struct Settings {
    /// Small sizes only.
    pub quick: bool,
    /// Solvers to run.
    pub solvers: Vec<Solver>,
    /// Families to run.
    pub families: Vec<Family>,
    /// Largest size to try (as reported: squares for the grid).
    pub max_size: usize,
    /// Generator sizes to use instead of the built-in ladders (the grid takes sides).
    pub sizes: Option<Vec<usize>>,
    /// Repetitions per problem (the median is reported).
    pub reps: usize,
    /// Repetitions stop once the solves add up to this many seconds.
    pub budget_s: f64,
    /// A worker still running after this is killed and recorded as a timeout.
    pub limit: Duration,
    /// Rounds over the solvers for problems that solve in under [`ROUND_MAX_MS`].
    pub rounds: usize,
}

/// Solves up to this long are timed in [`Settings::rounds`] rounds.
pub const ROUND_MAX_MS: f64 = 50.0;

impl Settings {
    /// The full comparison, or the quick one (loci and ezpz, small sizes).
    #[must_use]
    pub fn new(quick: bool) -> Self {
        Settings {
            quick,
            solvers: if quick {
                vec![Solver::Loci, Solver::Ezpz]
            } else {
                Solver::ALL.to_vec()
            },
            families: Family::ALL.to_vec(),
            max_size: usize::MAX,
            sizes: None,
            // Small problems solve in microseconds, where a few samples on a shared machine
            // moved ratios by a quarter between runs; slow solvers stop at the budget anyway.
            reps: if quick { 3 } else { 31 },
            budget_s: if quick { 0.5 } else { 2.0 },
            limit: Duration::from_secs(if quick { 20 } else { 30 }),
            rounds: if quick { 1 } else { 5 },
        }
    }

    /// The generator sizes of a family and variant (the grid's are sides).
    #[must_use]
    pub fn sizes(&self, family: Family, variant: Variant) -> Vec<usize> {
        let grid = family.takes_side();
        let all: &[usize] = if let Some(s) = &self.sizes {
            s
        } else {
            match (self.quick, variant, grid) {
                (true, Variant::Solvable, false) => &[10, 100],
                (true, Variant::Solvable, true) => &[3, 10],
                (true, _, false) => &[10],
                (true, _, true) => &[3],
                (false, Variant::Solvable, false) => &[10, 100, 1_000, 10_000, 100_000],
                (false, Variant::Solvable, true) => &[3, 10, 32, 50, 100, 316],
                (false, _, false) => &[10, 100, 1_000, 10_000],
                (false, _, true) => &[3, 10, 32, 100],
            }
        };
        all.iter()
            .copied()
            .filter(|&s| recorded_size(family, s) <= self.max_size)
            .collect()
    }
}

/// One solver on one problem.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Cell {
    /// Family.
    pub family: Family,
    /// Variant.
    pub variant: Variant,
    /// Size as reported (squares for the grid).
    pub size: usize,
    /// Solver.
    pub solver: Solver,
    /// What happened.
    pub verdict: Verdict,
    /// Median solve time, milliseconds.
    pub solve_ms: Option<f64>,
    /// Median build time, milliseconds.
    pub build_ms: Option<f64>,
    /// Repetitions run.
    pub runs: usize,
    /// Largest residual the checker found.
    pub residual: Option<f64>,
    /// The solver's own words.
    pub detail: String,
}

/// Everything a comparison found.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct Results {
    /// Every cell, in run order.
    pub cells: Vec<Cell>,
    /// Solver versions, or why a solver was not available.
    pub versions: BTreeMap<String, String>,
    /// Machine, date and settings.
    pub meta: BTreeMap<String, String>,
}

impl Results {
    /// The cell of a solver on a problem.
    #[must_use]
    pub fn cell(&self, f: Family, v: Variant, size: usize, s: Solver) -> Option<&Cell> {
        self.cells
            .iter()
            .find(|c| c.family == f && c.variant == v && c.size == size && c.solver == s)
    }
}

/// Where each solver stands within one family and variant as sizes grow.
#[derive(Default)]
struct Progress {
    stopped: Option<String>,
    last: Option<(usize, f64)>,
}

/// Runs the comparison, writing problem files under `work`. `log` receives one line per cell.
pub fn compare(
    settings: &Settings,
    runners: &Runners,
    avail: &Availability,
    work: &Path,
    mut log: impl FnMut(&str),
) -> Results {
    let mut res = Results::default();
    for (s, a) in avail {
        res.versions.insert(
            s.heading().to_string(),
            match a {
                Ok(v) => v.clone(),
                Err(e) => format!("not available: {e}"),
            },
        );
    }
    let limit_ms = settings.limit.as_secs_f64() * 1e3;
    for &family in &settings.families {
        for variant in Variant::ALL {
            let mut progress: BTreeMap<Solver, Progress> = BTreeMap::new();
            for gen_size in settings.sizes(family, variant) {
                let problem = generate(family, variant, gen_size);
                let size = problem.size;
                let files = ProblemFiles::new(&problem, work);
                // Samples of the solvers that ran, for the extra rounds below.
                let mut samples: Vec<(usize, Vec<f64>, Vec<f64>)> = Vec::new();
                for &solver in &settings.solvers {
                    let st = progress.entry(solver).or_default();
                    let skip = if !family.is_2d() && !solver.does_3d() {
                        Some("n/a (2D only)".to_string())
                    } else if let Some(Err(_)) = avail.get(&solver) {
                        Some("not available".to_string())
                    } else if let Some(why) = &st.stopped {
                        Some(format!("not run: {why} at a smaller size"))
                    } else if let Some((s0, ms)) = st
                        .last
                        .filter(|(s0, ms)| ms * size as f64 / *s0 as f64 > limit_ms)
                    {
                        Some(format!(
                            "not run: {ms:.0} ms at size {s0} extrapolates past the {:.0} s limit",
                            settings.limit.as_secs_f64()
                        ))
                    } else {
                        None
                    };
                    let cell = match skip {
                        Some(reason) => Cell {
                            family,
                            variant,
                            size,
                            solver,
                            verdict: Verdict::NotRun { reason },
                            solve_ms: None,
                            build_ms: None,
                            runs: 0,
                            residual: None,
                            detail: String::new(),
                        },
                        None => {
                            let (verdict, out, residual) = run_solver(
                                solver,
                                &files,
                                runners,
                                settings.reps,
                                settings.budget_s,
                                settings.limit,
                            );
                            let out = out.unwrap_or_default();
                            if verdict.has_time() {
                                samples.push((
                                    res.cells.len(),
                                    out.solve_ms.clone(),
                                    out.build_ms.clone(),
                                ));
                            }
                            Cell {
                                family,
                                variant,
                                size,
                                solver,
                                solve_ms: median(&out.solve_ms),
                                build_ms: median(&out.build_ms),
                                runs: out.solve_ms.len(),
                                residual,
                                detail: out.detail,
                                verdict,
                            }
                        }
                    };
                    if cell.verdict.stops_growth() {
                        st.stopped = Some(crate::report::verdict_text(&cell.verdict));
                    }
                    if let (true, Some(ms)) = (cell.verdict.has_time(), cell.solve_ms) {
                        st.last = Some((size, ms));
                    }
                    log(&format!(
                        "{:<34} {:<9} {}",
                        problem.label(),
                        solver.name(),
                        crate::report::cell_text(&cell, None)
                    ));
                    res.cells.push(cell);
                }
                // Short solves are timed again in further rounds, every solver in turn, and the
                // median taken over all rounds: a burst of load on a shared machine then falls
                // on all solvers alike rather than on whichever ran during it.
                for _ in 1..settings.rounds {
                    for (ci, solve, build) in &mut samples {
                        let cell = &res.cells[*ci];
                        if cell.solve_ms.is_none_or(|ms| ms > ROUND_MAX_MS) {
                            continue;
                        }
                        let (verdict, out, _) = run_solver(
                            cell.solver,
                            &files,
                            runners,
                            settings.reps,
                            settings.budget_s,
                            settings.limit,
                        );
                        if let (true, Some(out)) = (verdict.has_time(), out) {
                            solve.extend(out.solve_ms);
                            build.extend(out.build_ms);
                        }
                    }
                }
                for (ci, solve, build) in &samples {
                    let cell = &mut res.cells[*ci];
                    cell.solve_ms = median(solve);
                    cell.build_ms = median(build);
                    cell.runs = solve.len();
                }
                files.remove();
            }
        }
    }
    res
}
