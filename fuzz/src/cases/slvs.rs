//! `slvs`: bytes into loci's `.slvs` reader; what loads is solved group by group as
//! `loci solve FILE.slvs` does, saved and read again, and converted to loci's JSON, which
//! must read back.

use loci::format::json::Problem;
use loci::format::slvs::{solve_all, SlvsFile};
use loci::Config;

/// Larger models are skipped (see [`super::json::MAX_OBJECTS`]).
pub const MAX_OBJECTS: usize = 600;

/// Newton iterations per component, so that one input stays fast.
pub const MAX_ITERATIONS: usize = 20;

/// Runs one input; panics on a finding.
pub fn run(data: &[u8]) {
    let mut file = match SlvsFile::parse(data) {
        Ok(f) => f,
        Err(e) => {
            let _ = (e.to_string(), e.line());
            return;
        }
    };
    let sys = &file.system;
    if sys.params().len() + sys.entities().len() + sys.constraints().len() > MAX_OBJECTS {
        return;
    }

    // loci's JSON of the file (`loci convert --to json`) reads back as the same model.
    let written = Problem {
        system: file.system.clone(),
        solve: None,
    }
    .to_json();
    let again = Problem::from_json(&written)
        .unwrap_or_else(|e| panic!("the JSON of a loaded .slvs file does not read back: {e}"));
    assert_eq!(
        again.system.params(),
        file.system.params(),
        "params change through JSON"
    );
    assert_eq!(
        again.system.entities(),
        file.system.entities(),
        "entities change through JSON"
    );
    assert_eq!(
        again.system.constraints(),
        file.system.constraints(),
        "constraints change through JSON"
    );

    let cfg = Config::default().with_max_iterations(MAX_ITERATIONS);
    for g in solve_all(&mut file, &cfg) {
        let _ = (format!("{} {} {}", g.group, g.name, g.result), g.is_ok());
    }
    for p in file.system.params() {
        assert!(p.val.is_finite(), "{} is {} after solving", p.h, p.val);
    }

    // Saving rewrites parameter values only; the saved file loads again.
    let saved = file.to_bytes();
    let reloaded = SlvsFile::parse(&saved)
        .unwrap_or_else(|e| panic!("a solved and saved .slvs file does not load again: {e}"));
    for h in file.file_params() {
        let Some(a) = file.system.value(h) else {
            continue;
        };
        let Some(b) = reloaded.system.value(h) else {
            panic!("{h} is lost by saving and loading again");
        };
        assert!(
            (a - b).abs() <= 1e-12 * (1.0 + a.abs()),
            "{h} was {a}, saved and loaded again it is {b}"
        );
    }
}
