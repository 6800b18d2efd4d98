//! The inputs the fuzz targets (`fuzz/`, run with `cargo fuzz`) found problems with, and a
//! sample of their JSON seeds, replayed through the very same checks (`fuzz/src/cases`)
//! without libFuzzer, so that `cargo test` keeps them fixed.
//!
//! - `fuzz/regressions/json/*`: loci's JSON reader, a round trip, solve, diagnose and export;
//! - `fuzz/regressions/slvs/*`: the `.slvs` reader, solving every group, saving and reloading;
//! - `fuzz/regressions/resolve/*`: the structured target's byte strings, which build a
//!   system through the Rust API, solve, edit and re-solve it and check every answer
//!   independently of loci's equations;
//! - `fuzz/regressions/{sketch_file,assembly_file}/*`: the sketch and assembly file readers,
//!   a solve, and writing back;
//! - `fuzz/corpus/*`: the seeds of the JSON, sketch file and assembly file targets.
//!
//! `c_abi` findings are kept as the JSON problem of the same model under `json/`.

#[allow(dead_code)]
#[path = "../../../fuzz/src/cases/mod.rs"]
mod cases;

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

/// Saved inputs that still fail, with why. They are replayed all the same and may pass or
/// fail; remove an entry once its bug is fixed (the test then says so).
const KNOWN_FAILURES: &[(&str, &str)] = &[];

fn fuzz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz")
}

fn files(dir: &Path) -> Vec<PathBuf> {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut v: Vec<PathBuf> = rd
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file())
        .collect();
    v.sort();
    v
}

/// Every check on, including those the fuzz targets skip while a known bug is open.
fn run(target: &str, data: &[u8]) {
    use cases::resolve::Skips;
    match target {
        "json" => cases::json::run_with(data, Skips::NONE),
        "slvs" => cases::slvs::run(data),
        "resolve" => cases::resolve::run_with(data, Skips::NONE),
        "sketch_file" => cases::files::sketch(data),
        "assembly_file" => cases::files::assembly(data),
        other => panic!("no replay for target {other}"),
    }
}

/// Replays every file of `dir` with `target`'s checks; returns the failures that are not
/// known, with their messages.
fn replay(target: &str, dir: &Path, name_prefix: &str) -> (usize, Vec<String>) {
    let mut failures = Vec::new();
    let mut n = 0;
    for f in files(dir) {
        let name = format!(
            "{name_prefix}{}",
            f.file_name().unwrap_or_default().to_string_lossy()
        );
        let data = std::fs::read(&f).expect("readable");
        n += 1;
        let outcome = catch_unwind(AssertUnwindSafe(|| run(target, &data)));
        let known = KNOWN_FAILURES.iter().find(|(k, _)| *k == name);
        match (outcome, known) {
            (Ok(()), None) => {}
            (Ok(()), Some(_)) => {
                eprintln!("{name} passes now: remove it from KNOWN_FAILURES");
            }
            (Err(_), Some((_, why))) => eprintln!("{name} still fails (known: {why})"),
            (Err(e), None) => {
                let msg = e
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| e.downcast_ref::<&str>().map(|s| (*s).to_string()))
                    .unwrap_or_default();
                let first = msg.lines().next().unwrap_or_default().to_string();
                failures.push(format!("{name}: {first}"));
            }
        }
    }
    (n, failures)
}

#[test]
fn fuzz_regressions_stay_fixed() {
    let root = fuzz_dir().join("regressions");
    let mut all = Vec::new();
    for target in ["json", "slvs", "resolve", "sketch_file", "assembly_file"] {
        let (_, f) = replay(target, &root.join(target), &format!("{target}/"));
        all.extend(f);
    }
    assert!(all.is_empty(), "fuzz regressions fail:\n{}", all.join("\n"));
}

#[test]
fn fuzz_json_seeds_pass_the_json_checks() {
    let (n, failures) = replay("json", &fuzz_dir().join("corpus/json"), "corpus/json/");
    assert!(n > 0, "no JSON seeds found in fuzz/corpus/json");
    assert!(
        failures.is_empty(),
        "JSON seeds fail:\n{}",
        failures.join("\n")
    );
}

#[test]
fn fuzz_file_seeds_pass_the_file_checks() {
    for target in ["sketch_file", "assembly_file"] {
        let dir = fuzz_dir().join("corpus").join(target);
        let (n, failures) = replay(target, &dir, &format!("corpus/{target}/"));
        assert!(n > 0, "no seeds found in fuzz/corpus/{target}");
        assert!(
            failures.is_empty(),
            "{target} seeds fail:\n{}",
            failures.join("\n")
        );
    }
}
