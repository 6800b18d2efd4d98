//! `loci conformance DIR`: checks every `.slvs` file under DIR against the values
//! SolveSpace saved in it and prints the Markdown report.

use anyhow::Context;
use loci::format::slvs::conformance::{check, render_markdown, seed_for, FixtureCheck};
use std::path::{Path, PathBuf};

/// Runs the check over `dir` and returns the report; file names are relative to `dir`.
pub(crate) fn run(
    dir: &Path,
    command: &str,
) -> anyhow::Result<(String, Vec<(String, FixtureCheck)>)> {
    let mut files = Vec::new();
    collect(dir, &mut files).with_context(|| format!("cannot read {}", dir.display()))?;
    files.sort();
    let mut results = Vec::new();
    for f in files {
        let name = f
            .strip_prefix(dir)
            .unwrap_or(&f)
            .to_string_lossy()
            .replace('\\', "/");
        let bytes = std::fs::read(&f).with_context(|| format!("cannot read {}", f.display()))?;
        results.push((name.clone(), check(&bytes, seed_for(&name))));
    }
    Ok((render_markdown(&results, command), results))
}

fn collect(dir: &Path, out: &mut Vec<PathBuf>) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        if path.is_dir() {
            collect(&path, out)?;
        } else if path.extension().is_some_and(|e| e == "slvs") {
            out.push(path);
        }
    }
    Ok(())
}
