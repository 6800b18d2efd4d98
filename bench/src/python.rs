//! The Python-side cost benchmark (`loci-bench python`): one chain built and solved through
//! `loci.Sketch` and `loci.slvs` (the Python package), through SolveSpace's own Python module
//! (`slvs` 3.3 from the Python Package Index) and in Rust through [`loci::sketch::Sketch`], in one run, with ratios.
//!
//! The chain (the same as `runners/python_chain.py` builds): points P0..Pn on a staircase,
//! P0 fixed, segment 0 horizontal, every segment's length given and every segment
//! perpendicular to the next, so the answer is unique near the start, where every point but
//! P0 is moved by up to 0.25. Each repetition builds and solves afresh; the best build and the
//! best solve are kept.

use loci::sketch::{LineId, PointId, Sketch};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The staircase the chain solves to: even segments along +x (5, 6 or 7 long), odd ones
/// along +y or -y (3 or 4 long, up then down).
#[must_use]
pub fn exact_points(n: usize) -> Vec<[f64; 2]> {
    let mut pts = vec![[0.0, 0.0]];
    let (mut x, mut y) = (0.0, 0.0);
    for i in 0..n {
        if i % 2 == 0 {
            x += 5.0 + ((i / 2) % 3) as f64;
        } else {
            let len = 3.0 + ((i / 2) % 2) as f64;
            y += if (i / 2) % 2 == 0 { len } else { -len };
        }
        pts.push([x, y]);
    }
    pts
}

/// Where the chain starts: every point but the first moved by up to 0.25.
#[must_use]
pub fn start_points(n: usize) -> Vec<[f64; 2]> {
    exact_points(n)
        .into_iter()
        .enumerate()
        .map(|(k, [x, y])| {
            if k == 0 {
                [x, y]
            } else {
                let k = k as f64;
                [x + 0.25 * (1.3 * k).sin(), y + 0.25 * (0.7 * k).cos()]
            }
        })
        .collect()
}

/// The chain as a sketch, and its points.
///
/// # Panics
/// Never for the chain's own shapes and constraints.
#[must_use]
pub fn chain(n: usize) -> (Sketch, Vec<PointId>) {
    let exact = exact_points(n);
    let mut s = Sketch::new();
    let pts: Vec<PointId> = start_points(n)
        .into_iter()
        .map(|[x, y]| s.add_point(x, y).expect("finite"))
        .collect();
    let lines: Vec<LineId> = (0..n)
        .map(|i| s.add_line(pts[i], pts[i + 1]).expect("two points"))
        .collect();
    s.fix(pts[0]).expect("a point");
    s.horizontal(lines[0]).expect("a line");
    for i in 0..n {
        let [a, b] = [exact[i], exact[i + 1]];
        s.length(lines[i], (b[0] - a[0]).hypot(b[1] - a[1]))
            .expect("a positive length");
    }
    for i in 1..n {
        s.perpendicular(lines[i - 1], lines[i]).expect("two lines");
    }
    (s, pts)
}

/// One path's figures.
#[derive(Clone, Debug)]
pub struct Timing {
    /// Building the chain, seconds.
    pub build: f64,
    /// Solving it, seconds.
    pub solve: f64,
    /// How the solve ended.
    pub outcome: String,
    /// Where the last point ended.
    pub end: [f64; 2],
}

impl Timing {
    /// Build and solve.
    #[must_use]
    pub fn total(&self) -> f64 {
        self.build + self.solve
    }
}

/// Builds and solves the chain in Rust, `reps` times; the best build and best solve.
#[must_use]
pub fn rust(n: usize, reps: usize) -> Timing {
    let mut best = Timing {
        build: f64::INFINITY,
        solve: f64::INFINITY,
        outcome: String::new(),
        end: [0.0; 2],
    };
    for _ in 0..reps.max(1) {
        let t0 = Instant::now();
        let (mut s, pts) = chain(n);
        let t1 = Instant::now();
        let r = s.solve();
        let t2 = Instant::now();
        best.build = best.build.min((t1 - t0).as_secs_f64());
        best.solve = best.solve.min((t2 - t1).as_secs_f64());
        best.outcome = r.map_or_else(|e| format!("error: {e}"), |r| r.outcome.name().to_owned());
        best.end = s.point(*pts.last().expect("n + 1 points"));
    }
    best
}

/// A Python path, by the runner's name for it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Api {
    /// `loci.Sketch`.
    Sketch,
    /// `loci.slvs`.
    LociSlvs,
    /// SolveSpace 3.3's own module, `slvs` from the Python Package Index.
    PypiSlvs,
}

impl Api {
    /// The runner's argument.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Api::Sketch => "sketch",
            Api::LociSlvs => "slvs",
            Api::PypiSlvs => "pypi-slvs",
        }
    }

    /// The name in the table.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Api::Sketch => "Python loci.Sketch",
            Api::LociSlvs => "Python loci.slvs",
            Api::PypiSlvs => "Python PyPI slvs 3.3",
        }
    }
}

/// Runs `runners/python_chain.py` under `python`, stopping it after `limit`: the timing, or
/// why there is none.
pub fn python(
    python: &Path,
    bench: &Path,
    api: Api,
    n: usize,
    reps: usize,
    limit: Duration,
) -> Result<Timing, String> {
    let mut child = Command::new(python)
        .arg(bench.join("runners/python_chain.py"))
        .args([api.key(), &n.to_string(), &reps.to_string()])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("{} did not start: {e}", python.display()))?;
    let start = Instant::now();
    loop {
        match child.try_wait() {
            Ok(Some(_)) => break,
            Ok(None) if start.elapsed() < limit => std::thread::sleep(Duration::from_millis(20)),
            _ => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!("stopped after the {} s limit", limit.as_secs()));
            }
        }
    }
    let out = child.wait_with_output().map_err(|e| e.to_string())?;
    let stdout = String::from_utf8_lossy(&out.stdout);
    let v = stdout
        .lines()
        .rev()
        .find_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .ok_or_else(|| {
            let err = String::from_utf8_lossy(&out.stderr);
            err.lines()
                .rev()
                .find(|l| !l.trim().is_empty())
                .unwrap_or("no output")
                .to_owned()
        })?;
    let f = |k: &str| v[k].as_f64().unwrap_or(f64::NAN);
    Ok(Timing {
        build: f("build_s"),
        solve: f("solve_s"),
        outcome: v["outcome"].as_str().unwrap_or("?").to_owned(),
        end: [
            v["end"][0].as_f64().unwrap_or(f64::NAN),
            v["end"][1].as_f64().unwrap_or(f64::NAN),
        ],
    })
}

/// One row of the table: a path at one size.
#[derive(Clone, Debug)]
pub struct Row {
    /// Segments.
    pub n: usize,
    /// The path's name.
    pub label: &'static str,
    /// Its figures, or why there are none.
    pub timing: Result<Timing, String>,
}

fn ms(s: f64) -> String {
    if s < 0.01 {
        format!("{:.2}", s * 1e3)
    } else {
        format!("{:.1}", s * 1e3)
    }
}

/// The table, with each path's total against Rust's, and SolveSpace's module's against
/// `loci.slvs`'s.
#[must_use]
pub fn table(rows: &[Row]) -> String {
    let mut out = String::from(
        "| segments | path | build ms | solve ms | total ms | total / Rust | outcome | end point |\n\
         | ---: | --- | ---: | ---: | ---: | ---: | --- | --- |\n",
    );
    for r in rows {
        let rust = rows
            .iter()
            .find(|x| x.n == r.n && x.label == "Rust loci::sketch")
            .and_then(|x| x.timing.as_ref().ok())
            .map(Timing::total);
        match &r.timing {
            Ok(t) => {
                let ratio = rust.map_or("-".into(), |b| format!("{:.2}x", t.total() / b));
                out.push_str(&format!(
                    "| {} | {} | {} | {} | {} | {ratio} | {} | ({:.4}, {:.4}) |\n",
                    r.n,
                    r.label,
                    ms(t.build),
                    ms(t.solve),
                    ms(t.total()),
                    t.outcome,
                    t.end[0],
                    t.end[1]
                ));
            }
            Err(why) => out.push_str(&format!(
                "| {} | {} | - | - | - | - | {why} | - |\n",
                r.n, r.label
            )),
        }
    }
    let mut sizes: Vec<usize> = rows.iter().map(|r| r.n).collect();
    sizes.dedup();
    out.push('\n');
    for n in sizes {
        let get = |label: &str| {
            rows.iter()
                .find(|r| r.n == n && r.label == label)
                .and_then(|r| r.timing.as_ref().ok())
        };
        let solved = |t: &Timing| t.outcome == "okay" || t.outcome == "redundant_okay";
        if let (Some(ours), Some(theirs)) = (get(Api::LociSlvs.label()), get(Api::PypiSlvs.label()))
        {
            if solved(theirs) {
                out.push_str(&format!(
                    "{n} segments: PyPI slvs takes {:.0}x as long as loci.slvs (build and solve)\n",
                    theirs.total() / ours.total()
                ));
            } else {
                out.push_str(&format!(
                    "{n} segments: PyPI slvs does not solve it ({} after {} ms); loci.slvs solves it in {} ms\n",
                    theirs.outcome,
                    ms(theirs.total()),
                    ms(ours.total())
                ));
            }
        } else if let (Some(ours), Some(Err(why))) = (
            get(Api::LociSlvs.label()),
            rows.iter()
                .find(|r| r.n == n && r.label == Api::PypiSlvs.label())
                .map(|r| r.timing.as_ref()),
        ) {
            out.push_str(&format!(
                "{n} segments: PyPI slvs {why}; loci.slvs took {} ms\n",
                ms(ours.total())
            ));
        }
    }
    out
}

/// The interpreter that has the `loci` package: `$CARGO_TARGET_DIR/py-venv` (or the
/// workspace's `target/py-venv`), where `crates/loci-py/run-tests.sh` installs it.
#[must_use]
pub fn default_python(bench: &Path) -> PathBuf {
    let target =
        std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| bench.join("../target"), PathBuf::from);
    target.join("py-venv/bin/python")
}

/// Every path at every size.
#[must_use]
pub fn run_all(
    sizes: &[usize],
    loci_python: &Path,
    slvs_python: &Path,
    bench: &Path,
    limit: Duration,
) -> Vec<Row> {
    let mut rows = Vec::new();
    for &n in sizes {
        let reps = if n >= 10_000 { 3 } else { 5 };
        let rust = rust(n, reps);
        rows.push(Row {
            n,
            label: "Rust loci::sketch",
            timing: Ok(rust),
        });
        for api in [Api::Sketch, Api::LociSlvs, Api::PypiSlvs] {
            let py = if api == Api::PypiSlvs {
                slvs_python
            } else {
                loci_python
            };
            // SolveSpace's solve grows quickly with the chain: one repetition past 1,000.
            let reps = if api == Api::PypiSlvs && n > 1000 {
                1
            } else {
                reps
            };
            rows.push(Row {
                n,
                label: api.label(),
                timing: python(py, bench, api, n, reps, limit),
            });
        }
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rust_chain_solves_to_the_staircase() {
        let (mut s, pts) = chain(50);
        let r = s.solve().unwrap();
        assert!(r.outcome.is_ok(), "{r:?}");
        for (p, want) in pts.iter().zip(exact_points(50)) {
            let got = s.point(*p);
            assert!((got[0] - want[0]).abs() < 1e-9 && (got[1] - want[1]).abs() < 1e-9);
        }
    }

    #[test]
    fn the_start_is_near_the_answer() {
        for (a, b) in start_points(100).iter().zip(exact_points(100)) {
            assert!((a[0] - b[0]).hypot(a[1] - b[1]) <= 0.25 * 2f64.sqrt());
        }
    }
}
