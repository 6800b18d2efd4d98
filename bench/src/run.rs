//! Running one solver on one problem: in a worker process, with a time limit, and the
//! verdict on what came back.
//!
//! Every solver runs in a child process, loci and ezpz included (the child is this same
//! program, calling them as libraries in-process), so a solver that hangs, crashes or
//! exhausts memory costs one recorded cell and never the whole comparison.

use crate::check::{max_residual, TOLERANCE};
use crate::peers;
use crate::problem::{Problem, Variant};
use crate::slvs;
use serde::{Deserialize, Serialize};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// The solvers compared.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Solver {
    /// loci, called in-process.
    Loci,
    /// ezpz from crates.io, called in-process.
    Ezpz,
    /// SolveSpace's C library from Debian (`libslvs1-dev`), through a small C runner.
    SlvsC,
    /// SolveSpace's Python binding from PyPI (`slvs`).
    SlvsPy,
    /// FreeCAD's PlaneGCS compiled to WebAssembly (npm `@salusoft89/planegcs`), under node.
    PlaneGcs,
}

impl Solver {
    /// Every solver, in report order.
    pub const ALL: [Solver; 5] = [
        Solver::Loci,
        Solver::Ezpz,
        Solver::SlvsPy,
        Solver::SlvsC,
        Solver::PlaneGcs,
    ];

    /// The `snake_case` name used on the command line.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Solver::Loci => "loci",
            Solver::Ezpz => "ezpz",
            Solver::SlvsC => "slvs_c",
            Solver::SlvsPy => "slvs_py",
            Solver::PlaneGcs => "planegcs",
        }
    }

    /// The solver named `s`.
    #[must_use]
    pub fn from_name(s: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|x| x.name() == s)
    }

    /// A column heading.
    #[must_use]
    pub fn heading(self) -> &'static str {
        match self {
            Solver::Loci => "loci",
            Solver::Ezpz => "ezpz",
            Solver::SlvsC => "SolveSpace (libslvs, C)",
            Solver::SlvsPy => "SolveSpace (PyPI slvs)",
            Solver::PlaneGcs => "PlaneGCS (npm wasm)",
        }
    }

    /// Whether the solver takes problems in space.
    #[must_use]
    pub fn does_3d(self) -> bool {
        matches!(self, Solver::Loci | Solver::SlvsC | Solver::SlvsPy)
    }
}

/// What a runner reports for one problem.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct RunOutput {
    /// `ok` (the solver says it solved), `failed` (it says it could not), `refused` (it will
    /// not take a problem this size) or `error` (it raised an error).
    pub status: String,
    /// The solver's own words on the outcome.
    pub detail: String,
    /// Time to build the problem in the solver's API, per repetition, milliseconds.
    pub build_ms: Vec<f64>,
    /// Time of the solve call alone, per repetition, milliseconds.
    pub solve_ms: Vec<f64>,
    /// Coordinates of every problem point after the last repetition.
    pub points: Vec<[f64; 3]>,
}

fn elapsed_ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// Runs loci or ezpz on `p` in this process: up to `reps` repetitions, stopping once the
/// solves add up to `budget_s` seconds.
///
/// # Errors
/// When `solver` is not one of the in-process solvers, or the problem cannot be translated.
pub fn run_in_process(
    solver: Solver,
    p: &Problem,
    reps: usize,
    budget_s: f64,
) -> anyhow::Result<RunOutput> {
    let mut out = RunOutput::default();
    let mut spent = 0.0;
    for _ in 0..reps.max(1) {
        let t0 = Instant::now();
        match solver {
            Solver::Loci => {
                let mut sp = slvs::build(p)?;
                out.build_ms.push(elapsed_ms(t0));
                let t1 = Instant::now();
                let res = loci::solve(
                    &mut sp.system,
                    slvs::SOLVE_GROUP.into(),
                    &[],
                    &loci::Config::default(),
                );
                out.solve_ms.push(elapsed_ms(t1));
                match res {
                    Ok(r) => {
                        out.status = if r.outcome.is_ok() { "ok" } else { "failed" }.into();
                        out.detail = format!(
                            "{} (dof {}, {} failed, {} iterations)",
                            r.outcome,
                            r.dof,
                            r.failed.len(),
                            r.iterations
                        );
                    }
                    Err(e) => {
                        out.status = "error".into();
                        out.detail = e.to_string();
                    }
                }
                out.points = slvs::read_points(&sp);
            }
            Solver::Ezpz => {
                let ez = peers::to_ezpz(p)
                    .ok_or_else(|| anyhow::anyhow!("ezpz takes planar problems only"))?;
                let guesses = ez.guesses.clone();
                out.build_ms.push(elapsed_ms(t0));
                let t1 = Instant::now();
                let res = ezpz::solve(&ez.requests, guesses, ezpz::Config::default());
                out.solve_ms.push(elapsed_ms(t1));
                let values = match res {
                    Ok(o) => {
                        let sat = o.is_satisfied() && o.converged();
                        out.status = if sat { "ok" } else { "failed" }.into();
                        out.detail = format!(
                            "{} unsatisfied, converged {}, {} iterations",
                            o.unsatisfied().len(),
                            o.converged(),
                            o.iterations()
                        );
                        o.final_values().to_vec()
                    }
                    Err(e) => {
                        out.status = "error".into();
                        out.detail = e.error.to_string();
                        ez.guesses.iter().map(|g| g.1).collect()
                    }
                };
                out.points = (0..p.points.len())
                    .map(|i| {
                        let v = |k: usize| values.get(k).copied().unwrap_or(f64::NAN);
                        [v(2 * i), v(2 * i + 1), 0.0]
                    })
                    .collect();
            }
            other => anyhow::bail!("{} does not run in process", other.name()),
        }
        spent += out.solve_ms.last().copied().unwrap_or(0.0) / 1e3;
        if spent > budget_s {
            break;
        }
    }
    Ok(out)
}

/// How a child process ended.
#[derive(Debug)]
pub struct ChildEnd {
    /// Its exit status; `None` when it was killed for running out of time.
    pub status: Option<ExitStatus>,
    /// Everything it wrote to stdout.
    pub stdout: String,
    /// Everything it wrote to stderr.
    pub stderr: String,
    /// How long it ran.
    pub wall: Duration,
}

impl ChildEnd {
    /// The last line it wrote to stderr that is not blank, cut to `n` characters: why it
    /// failed, for a message.
    #[must_use]
    pub fn last_words(&self, n: usize) -> String {
        self.stderr
            .lines()
            .rev()
            .find(|l| !l.trim().is_empty())
            .unwrap_or("")
            .chars()
            .take(n)
            .collect()
    }
}

/// Runs a peer's runner script, `cmd`, which writes its answer as JSON to `out`, for at most
/// `limit`: the answer, or why there is none, worded for a table cell (`program` names what
/// could not start).
///
/// # Errors
/// The runner did not start, ran out of time, failed (its last line of stderr), or wrote no
/// readable JSON.
pub fn runner_json(
    cmd: Command,
    limit: Duration,
    out: &Path,
    program: &str,
) -> Result<serde_json::Value, String> {
    let end = run_with_limit(cmd, limit).map_err(|e| format!("{program} could not start: {e}"))?;
    match end.status {
        None => {
            let _ = std::fs::remove_file(out);
            return Err(format!("stopped after {} s", limit.as_secs()));
        }
        Some(s) if !s.success() => {
            return Err(format!("runner failed: {}", end.last_words(120)));
        }
        Some(_) => {}
    }
    let text = std::fs::read_to_string(out).map_err(|e| format!("no output: {e}"))?;
    let _ = std::fs::remove_file(out);
    serde_json::from_str(&text).map_err(|e| e.to_string())
}

/// Runs `cmd` to the end or until `limit`, then kills it. Output is read on threads so a
/// chatty child never blocks on a full pipe.
///
/// # Errors
/// When the command cannot be started.
pub fn run_with_limit(mut cmd: Command, limit: Duration) -> std::io::Result<ChildEnd> {
    let start = Instant::now();
    let mut child = cmd
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()?;
    let pipe = |r: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut s = Vec::new();
            if let Some(mut r) = r {
                let _ = r.read_to_end(&mut s);
            }
            String::from_utf8_lossy(&s).into_owned()
        })
    };
    let out = pipe(
        child
            .stdout
            .take()
            .map(|x| Box::new(x) as Box<dyn Read + Send>),
    );
    let err = pipe(
        child
            .stderr
            .take()
            .map(|x| Box::new(x) as Box<dyn Read + Send>),
    );
    let status = loop {
        if let Some(s) = child.try_wait()? {
            break Some(s);
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    Ok(ChildEnd {
        status,
        stdout: out.join().unwrap_or_default(),
        stderr: err.join().unwrap_or_default(),
        wall: start.elapsed(),
    })
}

/// What happened when a solver met a problem.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "verdict", rename_all = "snake_case")]
pub enum Verdict {
    /// Solved, and the checker agrees.
    Solved,
    /// On an inconsistent problem: the solver reported that it cannot be solved.
    Detected {
        /// The solver's words.
        detail: String,
    },
    /// The solver claimed success but the coordinates miss a constraint.
    Wrong {
        /// The largest residual found.
        residual: f64,
    },
    /// The solver reported failure on a solvable problem, or raised an error.
    Failed {
        /// The solver's words.
        detail: String,
    },
    /// The solver refused the problem (too large).
    Refused {
        /// The solver's words.
        detail: String,
    },
    /// Killed after the time limit.
    Timeout {
        /// The limit, seconds.
        limit_s: f64,
    },
    /// The process died: out of memory, or a crash.
    Crashed {
        /// What is known: the signal or exit code and the last words on stderr.
        detail: String,
    },
    /// Not run: the solver cannot express this family, is not installed, or failed or was
    /// too slow at a smaller size.
    NotRun {
        /// Why.
        reason: String,
    },
}

impl Verdict {
    /// Whether the cell carries a time worth plotting and comparing.
    #[must_use]
    pub fn has_time(&self) -> bool {
        matches!(self, Verdict::Solved | Verdict::Detected { .. })
    }

    /// Whether larger sizes are pointless after this (the solver will not get further).
    #[must_use]
    pub fn stops_growth(&self) -> bool {
        matches!(
            self,
            Verdict::Refused { .. } | Verdict::Timeout { .. } | Verdict::Crashed { .. }
        )
    }
}

/// Judges a runner's output on problem `p`.
#[must_use]
pub fn judge(p: &Problem, out: &RunOutput) -> (Verdict, Option<f64>) {
    match out.status.as_str() {
        "ok" => {
            let r = max_residual(p, &out.points);
            if r < TOLERANCE {
                (Verdict::Solved, Some(r))
            } else {
                (Verdict::Wrong { residual: r }, Some(r))
            }
        }
        "refused" => (
            Verdict::Refused {
                detail: out.detail.clone(),
            },
            None,
        ),
        "failed" if p.variant == Variant::Inconsistent => (
            Verdict::Detected {
                detail: out.detail.clone(),
            },
            None,
        ),
        _ => (
            Verdict::Failed {
                detail: format!("{}: {}", out.status, out.detail),
            },
            None,
        ),
    }
}

/// Names the way a child died from its status and stderr.
#[must_use]
pub fn describe_death(status: Option<ExitStatus>, stderr: &str) -> String {
    let last: Vec<&str> = stderr.lines().rev().take(3).collect();
    let tail = last.into_iter().rev().collect::<Vec<_>>().join(" | ");
    let lower = stderr.to_lowercase();
    let oom = lower.contains("out of memory")
        || lower.contains("aborted(oom)")
        || lower.contains("memory access out of bounds")
        || lower.contains("cannot enlarge memory")
        || lower.contains("array buffer allocation failed")
        || lower.contains("memory.grow");
    #[cfg(unix)]
    let signal = {
        use std::os::unix::process::ExitStatusExt;
        status.and_then(|s| s.signal())
    };
    #[cfg(not(unix))]
    let signal: Option<i32> = None;
    let how = match (signal, status.and_then(|s| s.code())) {
        (Some(9), _) => "killed (signal 9, likely out of memory)".to_string(),
        (Some(s), _) => format!("signal {s}"),
        (None, Some(c)) => format!("exit code {c}"),
        _ => "unknown end".to_string(),
    };
    let short: String = tail.chars().take(200).collect();
    if oom {
        format!("out of memory ({how}): {short}")
    } else {
        format!("{how}: {short}")
    }
}

/// Where a worker finds what it needs.
#[derive(Clone, Debug)]
pub struct Runners {
    /// This program (for loci and ezpz workers).
    pub this_exe: PathBuf,
    /// The compiled libslvs runner, if available.
    pub slvs_c: Option<PathBuf>,
    /// The Python interpreter of the venv holding `slvs`, if available.
    pub python: Option<PathBuf>,
    /// `node`, if PlaneGCS is available.
    pub node: Option<PathBuf>,
    /// The directory holding the runner scripts.
    pub scripts: PathBuf,
}

/// The files a problem is written to, one per input format, made on first use.
pub struct ProblemFiles<'a> {
    problem: &'a Problem,
    stem: PathBuf,
}

impl<'a> ProblemFiles<'a> {
    /// Files for `problem` named after `stem`.
    #[must_use]
    pub fn new(problem: &'a Problem, dir: &Path) -> Self {
        let stem = dir.join(problem.label().replace('/', "_"));
        ProblemFiles { problem, stem }
    }

    fn file(
        &self,
        ext: &str,
        make: impl FnOnce() -> anyhow::Result<String>,
    ) -> anyhow::Result<PathBuf> {
        let path = self.stem.with_extension(ext);
        if !path.exists() {
            std::fs::write(&path, make()?)?;
        }
        Ok(path)
    }

    /// The neutral problem as JSON (for loci and ezpz workers).
    ///
    /// # Errors
    /// When the file cannot be written.
    pub fn neutral(&self) -> anyhow::Result<PathBuf> {
        self.file("json", || Ok(serde_json::to_string(self.problem)?))
    }

    /// libslvs records.
    ///
    /// # Errors
    /// When the file cannot be written.
    pub fn records(&self) -> anyhow::Result<PathBuf> {
        self.file("slvs.txt", || {
            Ok(slvs::to_records(&slvs::build(self.problem)?))
        })
    }

    /// PlaneGCS primitives.
    ///
    /// # Errors
    /// When the file cannot be written or the problem is not planar.
    pub fn planegcs(&self) -> anyhow::Result<PathBuf> {
        self.file("gcs.json", || {
            let v = peers::to_planegcs(self.problem)
                .ok_or_else(|| anyhow::anyhow!("PlaneGCS takes planar problems only"))?;
            Ok(serde_json::to_string(&v)?)
        })
    }

    /// Removes the files made.
    pub fn remove(&self) {
        for ext in ["json", "slvs.txt", "gcs.json", "out.json"] {
            let _ = std::fs::remove_file(self.stem.with_extension(ext));
        }
    }

    fn out(&self) -> PathBuf {
        self.stem.with_extension("out.json")
    }
}

/// Runs `solver` on a problem in a worker process and judges the result. Returns the
/// verdict, the runner's output (when there was one) and the largest residual checked.
#[must_use]
pub fn run_solver(
    solver: Solver,
    files: &ProblemFiles<'_>,
    runners: &Runners,
    reps: usize,
    budget_s: f64,
    limit: Duration,
) -> (Verdict, Option<RunOutput>, Option<f64>) {
    let not_run = |reason: String| (Verdict::NotRun { reason }, None, None);
    let out = files.out();
    let _ = std::fs::remove_file(&out);
    let args = |input: PathBuf| {
        vec![
            input.into_os_string(),
            reps.to_string().into(),
            budget_s.to_string().into(),
            out.clone().into_os_string(),
        ]
    };
    let cmd = match solver {
        Solver::Loci | Solver::Ezpz => files.neutral().map(|f| {
            let mut c = Command::new(&runners.this_exe);
            c.arg("worker").arg(solver.name()).args(args(f));
            c
        }),
        Solver::SlvsC => match &runners.slvs_c {
            Some(exe) => files.records().map(|f| {
                let mut c = Command::new(exe);
                c.args(args(f));
                c
            }),
            None => return not_run("not available".into()),
        },
        Solver::SlvsPy => match &runners.python {
            Some(py) => files.records().map(|f| {
                let mut c = Command::new(py);
                c.arg(runners.scripts.join("slvs_runner.py")).args(args(f));
                c
            }),
            None => return not_run("not available".into()),
        },
        Solver::PlaneGcs => match &runners.node {
            Some(node) => files.planegcs().map(|f| {
                let mut c = Command::new(node);
                c.arg(runners.scripts.join("planegcs_runner.mjs"))
                    .args(args(f));
                c
            }),
            None => return not_run("not available".into()),
        },
    };
    let cmd = match cmd {
        Ok(c) => c,
        Err(e) => return not_run(format!("could not write its input: {e}")),
    };
    let end = match run_with_limit(cmd, limit) {
        Ok(e) => e,
        Err(e) => return not_run(format!("could not start: {e}")),
    };
    let Some(status) = end.status else {
        return (
            Verdict::Timeout {
                limit_s: limit.as_secs_f64(),
            },
            None,
            None,
        );
    };
    let parsed = std::fs::read_to_string(&out)
        .ok()
        .and_then(|s| serde_json::from_str::<RunOutput>(&s).ok());
    match parsed {
        Some(o) if status.success() => {
            let (v, r) = judge(files.problem, &o);
            (v, Some(o), r)
        }
        _ => (
            Verdict::Crashed {
                detail: describe_death(Some(status), &end.stderr),
            },
            None,
            None,
        ),
    }
}

/// The median of a list (the mean of the middle two for an even count).
#[must_use]
pub fn median(v: &[f64]) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    let n = s.len();
    Some(if n % 2 == 1 {
        s[n / 2]
    } else {
        (s[n / 2 - 1] + s[n / 2]) / 2.0
    })
}
