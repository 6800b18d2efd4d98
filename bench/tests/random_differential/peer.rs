//! SolveSpace as the peer: PyPI `slvs` (SolveSpace 3.3's own solver) in `bench/.venv`, the
//! venv `loci-bench` sets up and `.ci/run` provides. All systems of a run go to one Python
//! process (`runners/slvs_batch.py`), written as libslvs records by loci-bench's writer; if
//! SolveSpace crashes on a system, that system is recorded as a crash and the rest are sent to
//! a new process.

use loci::{ConstraintId, ParamId, System};
use loci_bench::run::run_with_limit;
use loci_bench::slvs::{to_records, SlvsProblem};
use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

/// SolveSpace's result codes (`SLVS_RESULT_*`).
pub const OKAY: i32 = 0;
pub const INCONSISTENT: i32 = 1;
pub const REDUNDANT_OKAY: i32 = 4;

/// What SolveSpace answered for one system.
#[derive(Clone, Debug)]
pub enum Answer {
    Solved {
        result: i32,
        dof: i32,
        failed: Vec<ConstraintId>,
        values: HashMap<ParamId, f64>,
    },
    /// The binding refused the input, or SolveSpace crashed or hung on it.
    Broken(String),
}

pub struct Peer {
    python: PathBuf,
    script: PathBuf,
    pub version: String,
}

fn bench_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

impl Peer {
    /// The venv's Python with `slvs` importable (`LOCI_DIFF_PYTHON` overrides it), or why not.
    pub fn find() -> Result<Peer, String> {
        let python = std::env::var_os("LOCI_DIFF_PYTHON")
            .map(PathBuf::from)
            .unwrap_or_else(|| bench_dir().join(".venv/bin/python"));
        let out = Command::new(&python)
            .args([
                "-c",
                "import slvs, importlib.metadata as m; print(m.version('slvs'))",
            ])
            .output()
            .map_err(|e| format!("{}: {e}", python.display()))?;
        if !out.status.success() {
            let err = String::from_utf8_lossy(&out.stderr);
            return Err(format!(
                "{}: cannot import slvs: {}",
                python.display(),
                err.lines().last().unwrap_or("")
            ));
        }
        Ok(Peer {
            python,
            script: bench_dir().join("runners/slvs_batch.py"),
            version: String::from_utf8_lossy(&out.stdout).trim().to_string(),
        })
    }

    /// SolveSpace's answer for every system, by seed.
    pub fn solve_all(&self, systems: &[(u64, &System)]) -> HashMap<u64, Answer> {
        let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
        let file = dir.join(format!("random_differential_{}.txt", std::process::id()));
        let mut answers = HashMap::new();
        let mut rest: Vec<(u64, &System)> = systems.to_vec();
        while !rest.is_empty() {
            let mut text = String::new();
            for (seed, sys) in &rest {
                let _ = writeln!(text, "S {seed}");
                text.push_str(&to_records(&SlvsProblem {
                    system: (*sys).clone(),
                    points: Vec::new(),
                }));
            }
            std::fs::write(&file, text).expect("write the systems for SolveSpace");
            let mut cmd = Command::new(&self.python);
            cmd.arg(&self.script).arg(&file);
            let limit = Duration::from_secs(60 + rest.len() as u64);
            let end = run_with_limit(cmd, limit).expect("start Python");
            for line in end.stdout.lines() {
                if let Some((seed, a)) = parse(line) {
                    answers.insert(seed, a);
                }
            }
            // The first system without an answer is where SolveSpace died; go on after it.
            let Some(pos) = rest.iter().position(|(s, _)| !answers.contains_key(s)) else {
                break;
            };
            let why = match end.status {
                None => "timed out".to_string(),
                Some(st) => {
                    let tail = end.stderr.lines().rev().find(|l| !l.trim().is_empty());
                    format!("crashed ({st}): {}", tail.unwrap_or(""))
                }
            };
            answers.insert(rest[pos].0, Answer::Broken(why));
            rest.drain(..=pos);
        }
        let _ = std::fs::remove_file(&file);
        answers
    }
}

fn parse(line: &str) -> Option<(u64, Answer)> {
    let mut words = line.splitn(3, ' ');
    let tag = words.next()?;
    let seed: u64 = words.next()?.parse().ok()?;
    let rest = words.next().unwrap_or("");
    match tag {
        "X" => Some((seed, Answer::Broken(format!("refused: {rest}")))),
        "R" => {
            let mut parts = rest.split('|');
            let head: Vec<i32> = parts
                .next()?
                .split_whitespace()
                .filter_map(|w| w.parse().ok())
                .collect();
            let failed = parts
                .next()?
                .split_whitespace()
                .filter_map(|w| w.parse().ok().map(ConstraintId))
                .collect();
            let values = parts
                .next()?
                .split_whitespace()
                .filter_map(|kv| {
                    let (k, v) = kv.split_once('=')?;
                    Some((ParamId(k.parse().ok()?), v.parse().ok()?))
                })
                .collect();
            Some((
                seed,
                Answer::Solved {
                    result: *head.first()?,
                    dof: *head.get(1)?,
                    failed,
                    values,
                },
            ))
        }
        _ => None,
    }
}
