//! The drag benchmark's peers, run in the same invocation as loci on the same sketches and
//! path: SolveSpace (`runners/slvs_drag.py` under `bench/.venv`), PlaneGCS
//! (`runners/planegcs_drag.mjs`) and BREP.io's sketch solver (`runners/brep_drag.mjs`), each
//! under node with `bench/node_modules`. Each runner builds the sketch through its own API
//! from the same recipe as [`crate::drag`] and prints one JSON object of figures. A peer that
//! is not installed, fails, or runs past its time limit is reported as skipped with the reason.

use crate::drag::DragFigures;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// A peer of the drag benchmark.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Peer {
    /// SolveSpace through PyPI `slvs`.
    SolveSpace,
    /// PlaneGCS through npm `@salusoft89/planegcs`.
    PlaneGcs,
    /// BREP.io's `SketchSolver2D` through npm `brep-io-kernel`.
    Brep,
}

impl Peer {
    /// Every peer, in table order.
    pub const ALL: [Peer; 3] = [Peer::SolveSpace, Peer::PlaneGcs, Peer::Brep];

    /// The name shown in tables.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Peer::SolveSpace => "SolveSpace",
            Peer::PlaneGcs => "PlaneGCS",
            Peer::Brep => "BREP.io",
        }
    }

    /// The name on the command line.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Peer::SolveSpace => "slvs",
            Peer::PlaneGcs => "planegcs",
            Peer::Brep => "brep",
        }
    }

    /// The program and runner script, or why the peer cannot run here.
    fn command(self, bench: &Path) -> Result<(PathBuf, PathBuf), String> {
        let (program, package, script) = match self {
            Peer::SolveSpace => {
                let py = bench.join(".venv/bin/python");
                if !py.exists() {
                    return Err(format!(
                        "no {} (python -m venv bench/.venv && bench/.venv/bin/pip install slvs)",
                        py.display()
                    ));
                }
                (py, None, "slvs_drag.py")
            }
            Peer::PlaneGcs => (
                PathBuf::from("node"),
                Some("@salusoft89/planegcs"),
                "planegcs_drag.mjs",
            ),
            Peer::Brep => (
                PathBuf::from("node"),
                Some("brep-io-kernel"),
                "brep_drag.mjs",
            ),
        };
        if let Some(pkg) = package {
            let have_node = Command::new("node")
                .arg("--version")
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .status()
                .is_ok_and(|s| s.success());
            if !have_node {
                return Err("no node on PATH".into());
            }
            if !bench.join("node_modules").join(pkg).exists() {
                return Err(format!(
                    "npm package {pkg} not installed (npm install in bench/)"
                ));
            }
        }
        Ok((program, bench.join("runners").join(script)))
    }
}

/// What one peer did on one sketch.
#[derive(Clone, Debug)]
pub enum PeerRun {
    /// It ran: its figures (first step, median, 99th percentile, worst, flips; `short` counts
    /// the steps its solver reported failed).
    Ran(DragFigures),
    /// It did not run, and why.
    Skipped(String),
}

/// The runner's name for a sketch of [`crate::drag`].
fn kind(sketch: &str) -> &'static str {
    if sketch.starts_with("four-bar") {
        "four_bar"
    } else {
        "hinged"
    }
}

/// Runs one peer on one sketch, stopping it after `limit`.
#[must_use]
pub fn run_peer(
    peer: Peer,
    bench: &Path,
    sketch: &'static str,
    size: usize,
    steps: usize,
    limit: Duration,
) -> PeerRun {
    let (program, script) = match peer.command(bench) {
        Ok(c) => c,
        Err(why) => return PeerRun::Skipped(why),
    };
    let out_path = std::env::temp_dir().join(format!(
        "loci-drag-{}-{}-{size}-{}.json",
        peer.key(),
        kind(sketch),
        std::process::id()
    ));
    let err_path = out_path.with_extension("err");
    let (Ok(out), Ok(err)) = (
        std::fs::File::create(&out_path),
        std::fs::File::create(&err_path),
    ) else {
        return PeerRun::Skipped("cannot write a temporary file".into());
    };
    let child = Command::new(&program)
        .arg(&script)
        .args([kind(sketch), &size.to_string(), &steps.to_string()])
        .current_dir(bench)
        .stdin(Stdio::null())
        .stdout(out)
        .stderr(err)
        .spawn();
    let mut child = match child {
        Ok(c) => c,
        Err(e) => return PeerRun::Skipped(format!("{} did not start: {e}", program.display())),
    };
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(s)) => break Some(s),
            Ok(None) if start.elapsed() < limit => std::thread::sleep(Duration::from_millis(50)),
            _ => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
        }
    };
    let stdout = std::fs::read_to_string(&out_path).unwrap_or_default();
    let stderr = std::fs::read_to_string(&err_path).unwrap_or_default();
    let _ = std::fs::remove_file(&out_path);
    let _ = std::fs::remove_file(&err_path);
    let Some(status) = status else {
        return PeerRun::Skipped(format!("stopped after the {} s limit", limit.as_secs()));
    };
    let json = stdout
        .lines()
        .rev()
        .find_map(|l| serde_json::from_str::<serde_json::Value>(l).ok());
    let Some(v) = json.filter(|_| status.success()) else {
        // The last line that says what went wrong (node ends with its version line).
        let lines: Vec<&str> = stderr.lines().filter(|l| !l.trim().is_empty()).collect();
        let telling = |l: &&&str| {
            let l = l.to_ascii_lowercase();
            l.contains("error") || l.contains("memory") || l.contains("abort")
        };
        let why = lines
            .iter()
            .rev()
            .find(telling)
            .or_else(|| lines.iter().rev().find(|l| !l.starts_with("Node.js")))
            .copied()
            .unwrap_or("no output")
            .trim()
            .chars()
            .take(120)
            .collect::<String>();
        return PeerRun::Skipped(format!("failed ({status}): {why}"));
    };
    let num = |k: &str| {
        v.get(k)
            .and_then(serde_json::Value::as_f64)
            .unwrap_or(f64::NAN)
    };
    let count = |k: &str| v.get(k).and_then(serde_json::Value::as_u64).unwrap_or(0) as usize;
    // A solver that refuses the sketch fails every step quickly: its times are not a drag's.
    if count("steps") > 0 && count("failed") >= count("steps") {
        let setup = v
            .get("setup_result")
            .map(|r| format!(" (its first solve returned {r})"))
            .unwrap_or_default();
        return PeerRun::Skipped(format!("its solver failed every step{setup}"));
    }
    PeerRun::Ran(DragFigures {
        sketch,
        shapes: count("shapes"),
        steps: count("steps"),
        first_ms: num("first_ms"),
        median_ms: num("median_ms"),
        p99_ms: num("p99_ms"),
        worst_ms: num("worst_ms"),
        flipped: count("flipped"),
        short: count("failed"),
    })
}

/// loci's figures and each peer's on the same sketch.
#[derive(Clone, Debug)]
pub struct Row {
    /// loci's figures.
    pub loci: DragFigures,
    /// Each peer asked for, in order.
    pub peers: Vec<(Peer, PeerRun)>,
}

/// One table of every solver on every sketch, with each peer's median step over loci's, then
/// the list of peers skipped and why.
#[must_use]
pub fn table(rows: &[Row]) -> String {
    let mut s = String::from(
        "| sketch | shapes | solver | first step (ms) | median step (ms) | 99th percentile (ms) | worst step (ms) | steps with a flip | steps failed or short | median / loci's |\n\
         | --- | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n",
    );
    let mut skipped = String::new();
    for r in rows {
        let line = |who: &str, f: &DragFigures, ratio: &str| {
            format!(
                "| {} | {} | {who} | {:.3} | {:.4} | {:.3} | {:.3} | {} | {} | {ratio} |\n",
                f.sketch,
                f.shapes,
                f.first_ms,
                f.median_ms,
                f.p99_ms,
                f.worst_ms,
                f.flipped,
                f.short
            )
        };
        s.push_str(&line("loci", &r.loci, "1"));
        for (peer, run) in &r.peers {
            match run {
                PeerRun::Ran(f) => {
                    let ratio = format!("×{:.0}", f.median_ms / r.loci.median_ms);
                    s.push_str(&line(peer.name(), f, &ratio));
                }
                PeerRun::Skipped(why) => skipped.push_str(&format!(
                    "- {} on {} ({} shapes): skipped, {why}\n",
                    peer.name(),
                    r.loci.sketch,
                    r.loci.shapes
                )),
            }
        }
    }
    if !skipped.is_empty() {
        s.push('\n');
        s.push_str(&skipped);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn figures(median_ms: f64) -> DragFigures {
        DragFigures {
            sketch: "hinged triangles",
            shapes: 96,
            steps: 600,
            first_ms: 0.1,
            median_ms,
            p99_ms: 0.5,
            worst_ms: 1.0,
            flipped: 0,
            short: 0,
        }
    }

    #[test]
    fn peers_not_installed_are_skipped_with_the_reason() {
        let empty = std::env::temp_dir().join(format!("loci-drag-empty-{}", std::process::id()));
        std::fs::create_dir_all(&empty).unwrap();
        for peer in Peer::ALL {
            let run = run_peer(
                peer,
                &empty,
                "hinged triangles",
                100,
                10,
                Duration::from_secs(5),
            );
            let PeerRun::Skipped(why) = run else {
                panic!("{peer:?} ran without being installed");
            };
            assert!(
                why.contains(".venv") || why.contains("not installed") || why.contains("node"),
                "{peer:?}: {why}"
            );
        }
        let _ = std::fs::remove_dir(&empty);
    }

    #[test]
    fn the_table_gives_each_peer_its_ratio_and_lists_the_skipped() {
        let rows = [Row {
            loci: figures(0.02),
            peers: vec![
                (Peer::SolveSpace, PeerRun::Ran(figures(0.5))),
                (Peer::PlaneGcs, PeerRun::Skipped("no node on PATH".into())),
            ],
        }];
        let t = table(&rows);
        assert!(t.contains("| hinged triangles | 96 | SolveSpace |"), "{t}");
        assert!(t.contains("| ×25 |"), "{t}");
        assert!(
            t.contains("- PlaneGCS on hinged triangles (96 shapes): skipped, no node on PATH"),
            "{t}"
        );
    }
}
