//! loci against SolveSpace's 236 regression fixtures (see `docs/conformance.md`).
//!
//! The fixtures live outside the repository, in `../shared/samples/solvespace` beside it
//! (or where `LOCI_SOLVESPACE_FIXTURES` points). Without them the test prints a note and
//! passes, so a checkout without the fixtures still builds and tests.

use loci::format::slvs::conformance::{check, seed_for, FixtureCheck, Summary, Verdict};
use std::path::{Path, PathBuf};

/// The number of fixtures that match in every group today: all of them.
const MATCHED: usize = 236;

fn fixtures() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("LOCI_SOLVESPACE_FIXTURES") {
        return Some(PathBuf::from(p));
    }
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/samples/solvespace");
    p.is_dir().then_some(p)
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

fn run(dir: &Path) -> Vec<(String, FixtureCheck)> {
    let mut files = Vec::new();
    collect(dir, &mut files);
    files.sort();
    files
        .iter()
        .map(|f| {
            let name = f
                .strip_prefix(dir)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            let r = check(&std::fs::read(f).unwrap(), seed_for(&name));
            (name, r)
        })
        .collect()
}

#[test]
fn solvespace_fixtures_do_not_regress() {
    let Some(dir) = fixtures() else {
        eprintln!(
            "note: SolveSpace fixtures not found beside the repository (../shared/samples/\
             solvespace) and LOCI_SOLVESPACE_FIXTURES is not set; conformance not checked"
        );
        return;
    };
    let results = run(&dir);
    let s = Summary::of(&results);
    eprintln!("{s:?}");
    assert_eq!(
        s.total,
        236,
        "expected SolveSpace's 236 fixtures in {}",
        dir.display()
    );
    for (name, r) in &results {
        assert!(r.verdict.loaded(), "{name} does not load: {:?}", r.verdict);
        assert_eq!(r.verdict, Verdict::Matched, "{name}");
    }
    assert!(s.matched >= MATCHED, "matched {} < {MATCHED}", s.matched);
}
