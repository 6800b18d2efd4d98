//! BREP.io's own assembly solver (npm `brep-io-kernel`, its `AssemblyConstraintHistory`) on
//! the assembly benchmark's revolute chains, run headless under node by
//! `runners/brep_assembly.mjs` from the same start as loci's.
//!
//! It is a peer only when `node` runs and `bench/node_modules` holds the package (`npm
//! install` in `bench/`); otherwise the reason is reported in its column instead of a time.

use crate::assembly::{chain, start_poses};
use crate::run::runner_json;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

/// What BREP.io's relaxation did on one chain.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepRun {
    /// Passes over all constraints (its `runAll` iterations).
    pub passes: usize,
    /// Whether every constraint reported itself satisfied and the measured errors are small
    /// (pivots within 1e-4, hinges and arm angles within 0.01 degrees).
    pub converged: bool,
    /// Wall time of `runAll`, milliseconds (building the scene excluded).
    pub ms: f64,
    /// Largest distance left between a tip and the next pivot.
    pub point_error: f64,
    /// Largest angle error left, degrees.
    pub angle_error_deg: f64,
}

/// Why BREP.io could not be run: `Err` carries the reason, worded for the table.
pub type BrepResult = Result<BrepRun, String>;

/// The installed `brep-io-kernel` version, or why it cannot run.
pub fn available(bench: &Path) -> Result<String, String> {
    let node = Command::new("node").arg("--version").output();
    match node {
        Ok(o) if o.status.success() => {}
        _ => return Err("not run: node is not installed".into()),
    }
    let pkg = bench.join("node_modules/brep-io-kernel/package.json");
    let three = bench.join("node_modules/three/package.json");
    if !pkg.exists() || !three.exists() {
        return Err(
            "not run: brep-io-kernel and three are not installed (npm install in bench/)".into(),
        );
    }
    let text = std::fs::read_to_string(&pkg).map_err(|e| format!("not run: {e}"))?;
    let v: serde_json::Value = serde_json::from_str(&text).map_err(|e| format!("not run: {e}"))?;
    Ok(v["version"].as_str().unwrap_or("?").to_string())
}

/// Runs the chain of `n` links through BREP.io with at most `max_passes` passes and
/// `limit` of wall time.
pub fn brep_chain(n: usize, max_passes: usize, limit: Duration, bench: &Path) -> BrepResult {
    available(bench)?;
    let dir = std::env::temp_dir();
    let start = dir.join(format!(
        "loci-asm-brep-start-{}-{n}.json",
        std::process::id()
    ));
    let out = dir.join(format!("loci-asm-brep-{}-{n}.json", std::process::id()));
    let poses = start_poses(&chain(n, 1));
    std::fs::write(
        &start,
        serde_json::to_string(&poses).map_err(|e| e.to_string())?,
    )
    .map_err(|e| format!("not run: {e}"))?;
    let mut cmd = Command::new("node");
    cmd.current_dir(bench)
        .arg(bench.join("runners/brep_assembly.mjs"))
        .arg(&start)
        .arg(max_passes.to_string())
        .arg(&out);
    let v = runner_json(cmd, limit, &out, "node");
    let _ = std::fs::remove_file(&start);
    let v = v?;
    let f = |k: &str| v[k].as_f64().unwrap_or(f64::NAN);
    Ok(BrepRun {
        passes: usize::try_from(v["passes"].as_u64().unwrap_or(0)).unwrap_or(usize::MAX),
        converged: v["converged"].as_bool().unwrap_or(false),
        ms: f("solve_ms"),
        point_error: f("max_point_error"),
        angle_error_deg: f("max_angle_error_deg"),
    })
}

/// The table cell for BREP.io beside loci's `loci_ms`.
#[must_use]
pub fn cell(r: &BrepResult, loci_ms: f64) -> String {
    match r {
        Ok(b) if b.converged => format!(
            "{} passes, {:.0} ms (×{:.0} loci's time)",
            b.passes,
            b.ms,
            b.ms / loci_ms
        ),
        Ok(b) => format!(
            "not converged after {} passes, {:.0} ms (pivots off by {:.1e}, angles by {:.1}°)",
            b.passes, b.ms, b.point_error, b.angle_error_deg
        ),
        Err(why) => why.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn without_the_package_it_says_why_and_runs_nothing() {
        let empty = std::env::temp_dir().join(format!("loci-no-brep-{}", std::process::id()));
        std::fs::create_dir_all(&empty).unwrap();
        let r = brep_chain(10, 10, Duration::from_secs(5), &empty);
        let _ = std::fs::remove_dir(&empty);
        let why = r.unwrap_err();
        assert!(why.starts_with("not run: "), "{why}");
        assert_eq!(cell(&Err(why.clone()), 1.0), why);
    }

    #[test]
    fn a_converged_run_reads_as_passes_time_and_ratio() {
        let b = BrepRun {
            passes: 1086,
            converged: true,
            ms: 1319.0,
            point_error: 1e-7,
            angle_error_deg: 1e-4,
        };
        assert_eq!(cell(&Ok(b), 1.5), "1086 passes, 1319 ms (×879 loci's time)");
    }
}
