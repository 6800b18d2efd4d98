//! Installing the peers: a venv with PyPI `slvs`, PlaneGCS from npm, and the C runner over
//! Debian's libslvs. A peer that cannot be had is recorded as not available, never an error.

use crate::run::{run_with_limit, Runners, Solver};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

/// The pinned PyPI release of SolveSpace's Python binding.
pub const SLVS_PYPI: &str = "slvs==3.3";

/// What setup found for each solver: its version, or why it is not available.
pub type Availability = BTreeMap<Solver, Result<String, String>>;

/// Runs a command with a limit; its trimmed stdout on success, else a short reason.
fn capture(mut cmd: Command, limit_s: u64) -> Result<String, String> {
    let shown = format!("{:?}", cmd.get_program());
    cmd.env("PIP_DISABLE_PIP_VERSION_CHECK", "1");
    match run_with_limit(cmd, Duration::from_secs(limit_s)) {
        Ok(end) => match end.status {
            Some(s) if s.success() => Ok(end.stdout.trim().to_string()),
            Some(s) => Err(format!("{shown} failed ({s}): {}", end.last_words(160))),
            None => Err(format!("{shown} timed out after {limit_s} s")),
        },
        Err(e) => Err(format!("{shown} could not start: {e}")),
    }
}

fn cmd(program: impl AsRef<std::ffi::OsStr>, args: &[&str]) -> Command {
    let mut c = Command::new(program);
    c.args(args);
    c
}

/// The venv's Python with `slvs` importable, creating and filling the venv if needed.
fn python_slvs(bench: &Path) -> Result<(PathBuf, String), String> {
    let venv = bench.join(".venv");
    let py = venv.join("bin").join("python");
    let version = || {
        capture(
            cmd(
                &py,
                &[
                    "-c",
                    "import slvs, importlib.metadata as m; print(m.version('slvs'))",
                ],
            ),
            60,
        )
    };
    if let Ok(v) = version() {
        return Ok((py, v));
    }
    if !py.exists() {
        let venv_s = venv.to_string_lossy().into_owned();
        capture(cmd("python3", &["-m", "venv", &venv_s]), 300)?;
    }
    capture(cmd(&py, &["-m", "pip", "install", "-q", SLVS_PYPI]), 600)?;
    version().map(|v| (py, v))
}

/// `node` with PlaneGCS installed under `bench/node_modules`, installing it if needed.
fn node_planegcs(bench: &Path) -> Result<(PathBuf, String), String> {
    let node = PathBuf::from("node");
    let node_v = capture(cmd(&node, &["--version"]), 30)?;
    let pkg = bench.join("node_modules/@salusoft89/planegcs/package.json");
    if !pkg.exists() {
        let mut c = cmd("npm", &["install", "--no-audit", "--no-fund", "--silent"]);
        c.current_dir(bench);
        capture(c, 600)?;
    }
    let text = std::fs::read_to_string(&pkg).map_err(|e| format!("{}: {e}", pkg.display()))?;
    let v: serde_json::Value = serde_json::from_str(&text).map_err(|e| e.to_string())?;
    let ver = v["version"].as_str().unwrap_or("?").to_string();
    Ok((node, format!("{ver} (node {node_v})")))
}

/// The C runner compiled against libslvs, installing `libslvs1-dev` with apt when it is
/// missing and this is a Debian machine where we may.
fn slvs_c(bench: &Path, build_dir: &Path) -> Result<(PathBuf, String), String> {
    if !Path::new("/usr/include/slvs.h").exists() {
        let apt = Path::new("/usr/bin/apt-get").exists();
        let root = capture(cmd("id", &["-u"]), 10).is_ok_and(|u| u == "0");
        if !(apt && root) {
            return Err("libslvs1-dev is not installed".into());
        }
        let mut c = cmd(
            "apt-get",
            &[
                "install",
                "-y",
                "-qq",
                "--no-install-recommends",
                "libslvs1-dev",
            ],
        );
        c.env("DEBIAN_FRONTEND", "noninteractive");
        if capture(c, 600).is_err() {
            capture(cmd("apt-get", &["update", "-qq"]), 600)?;
            let mut c = cmd(
                "apt-get",
                &[
                    "install",
                    "-y",
                    "-qq",
                    "--no-install-recommends",
                    "libslvs1-dev",
                ],
            );
            c.env("DEBIAN_FRONTEND", "noninteractive");
            capture(c, 600)?;
        }
    }
    std::fs::create_dir_all(build_dir).map_err(|e| e.to_string())?;
    let exe = build_dir.join("slvs_runner");
    let src = bench.join("runners/slvs_runner.c");
    let (exe_s, src_s) = (
        exe.to_string_lossy().into_owned(),
        src.to_string_lossy().into_owned(),
    );
    capture(cmd("cc", &["-O2", "-o", &exe_s, &src_s, "-lslvs"]), 120)?;
    let ver = capture(cmd("dpkg-query", &["-W", "-f=${Version}", "libslvs1"]), 30)
        .unwrap_or_else(|_| "unknown version".into());
    Ok((exe, ver))
}

/// Sets up the wanted peers. loci and ezpz are always there.
#[must_use]
pub fn setup(bench: &Path, build_dir: &Path, wanted: &[Solver]) -> (Runners, Availability) {
    let mut avail = Availability::new();
    let mut runners = Runners {
        this_exe: std::env::current_exe().unwrap_or_else(|_| PathBuf::from("loci-bench")),
        slvs_c: None,
        python: None,
        node: None,
        scripts: bench.join("runners"),
    };
    for &s in wanted {
        let got = match s {
            Solver::Loci => Ok(format!("{} (this tree)", env!("CARGO_PKG_VERSION"))),
            Solver::Ezpz => Ok("0.2.29 (crates.io)".to_string()),
            Solver::SlvsPy => python_slvs(bench).map(|(py, v)| {
                runners.python = Some(py);
                format!("{v} (PyPI)")
            }),
            Solver::PlaneGcs => node_planegcs(bench).map(|(node, v)| {
                runners.node = Some(node);
                v
            }),
            Solver::SlvsC => slvs_c(bench, build_dir).map(|(exe, v)| {
                runners.slvs_c = Some(exe);
                format!("libslvs1 {v} (Debian)")
            }),
        };
        avail.insert(s, got);
    }
    (runners, avail)
}
