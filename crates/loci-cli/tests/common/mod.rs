//! SolveSpace's regression fixtures, for the end-to-end tests that run every one of them.

use std::path::{Path, PathBuf};

/// Every `.slvs` fixture, sorted: from `../shared/samples/solvespace` beside the checkout (or
/// where `LOCI_SOLVESPACE_FIXTURES` points); `None` without them.
pub fn solvespace_fixtures() -> Option<Vec<PathBuf>> {
    let dir = match std::env::var_os("LOCI_SOLVESPACE_FIXTURES") {
        Some(p) => PathBuf::from(p),
        None => Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/samples/solvespace"),
    };
    if !dir.is_dir() {
        return None;
    }
    let mut files = Vec::new();
    collect(&dir, &mut files);
    files.sort();
    assert!(files.len() >= 200, "{} fixtures", files.len());
    Some(files)
}

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            collect(&p, out);
        } else if p.extension().is_some_and(|x| x == "slvs") {
            out.push(p);
        }
    }
}
