//! CadQuery's assembly solver (PyPI `cadquery`, its `Assembly.solve`, IPOPT through casadi)
//! on the assembly benchmark's revolute chains, run by `runners/cadquery_assembly.py` from
//! the same start as loci's.
//!
//! CadQuery is large (it brings OpenCascade), so it is opt-in: `loci-bench assembly
//! --cadquery PYTHON` names an interpreter that can `import cadquery` (for example a virtual
//! environment made with `python3 -m venv cq && cq/bin/pip install cadquery`).

use crate::assembly::{chain, start_poses};
use crate::run::runner_json;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

/// What CadQuery did on one chain.
#[derive(Clone, Debug, PartialEq)]
pub struct CadqueryRun {
    /// Whether `Assembly.solve` returned and every joint holds within the runner's measure
    /// (pivots within 1e-6, hinge and arm angles within 1e-4 degrees).
    pub converged: bool,
    /// Best wall time of `Assembly.solve`, milliseconds (building the assembly excluded).
    pub ms: f64,
    /// Largest distance left between a tip and the next pivot.
    pub pivot_gap: f64,
    /// Largest angle error left (hinges or arms), degrees.
    pub angle_error_deg: f64,
}

/// Why CadQuery could not be run: `Err` carries the reason, worded for the table.
pub type CadqueryResult = Result<CadqueryRun, String>;

/// Largest pivot gap that counts as converged.
const GAP: f64 = 1e-6;
/// Largest angle error, degrees, that counts as converged.
const ANGLE_DEG: f64 = 1e-4;

/// Runs the chain of `n` links through CadQuery with interpreter `python`, the best of
/// `reps` solves, stopping the runner after `limit`.
pub fn cadquery_chain(
    n: usize,
    reps: usize,
    limit: Duration,
    python: &Path,
    bench: &Path,
) -> CadqueryResult {
    let probe = Command::new(python)
        .args(["-c", "import cadquery"])
        .output()
        .map_err(|e| format!("not run: {} does not start: {e}", python.display()))?;
    if !probe.status.success() {
        return Err(format!(
            "not run: {} cannot import cadquery",
            python.display()
        ));
    }
    let dir = std::env::temp_dir();
    let start = dir.join(format!("loci-asm-cq-start-{}-{n}.json", std::process::id()));
    let out = dir.join(format!("loci-asm-cq-{}-{n}.json", std::process::id()));
    let poses = start_poses(&chain(n, 1));
    std::fs::write(
        &start,
        serde_json::to_string(&poses).map_err(|e| e.to_string())?,
    )
    .map_err(|e| format!("not run: {e}"))?;
    let mut cmd = Command::new(python);
    cmd.arg(bench.join("runners/cadquery_assembly.py"))
        .arg(&start)
        .arg(reps.max(1).to_string())
        .arg(&out);
    let v = runner_json(cmd, limit, &out, "python");
    let _ = std::fs::remove_file(&start);
    let v = v?;
    if let Some(status) = v["status"].as_str().filter(|s| *s != "ok") {
        return Err(status.to_string());
    }
    let f = |k: &str| v[k].as_f64().unwrap_or(f64::NAN);
    let (gap, angle) = (f("pivot_gap"), f("hinge_deg").max(f("arm_deg")));
    Ok(CadqueryRun {
        converged: gap <= GAP && angle <= ANGLE_DEG,
        ms: f("solve_ms"),
        pivot_gap: gap,
        angle_error_deg: angle,
    })
}

/// The table cell for CadQuery beside loci's `loci_ms`.
#[must_use]
pub fn cell(r: &CadqueryResult, loci_ms: f64) -> String {
    match r {
        Ok(c) if c.converged => format!("{:.0} ms (×{:.0} loci's time)", c.ms, c.ms / loci_ms),
        Ok(c) => format!(
            "not converged, {:.0} ms (pivots off by {:.1e}, angles by {:.1e}°)",
            c.ms, c.pivot_gap, c.angle_error_deg
        ),
        Err(why) => why.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn without_cadquery_it_says_why_and_runs_nothing() {
        let r = cadquery_chain(
            10,
            1,
            Duration::from_secs(5),
            Path::new("/nonexistent/python"),
            Path::new(env!("CARGO_MANIFEST_DIR")),
        );
        let why = r.unwrap_err();
        assert!(why.starts_with("not run: "), "{why}");
        assert_eq!(cell(&Err(why.clone()), 1.0), why);
    }
}
