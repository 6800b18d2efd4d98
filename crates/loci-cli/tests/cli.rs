//! End-to-end: the `loci` binary on the shipped examples and on bad files.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn loci(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_loci"))
        .args(args)
        .output()
        .expect("the loci binary runs")
}

fn examples() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut v: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("examples/ exists")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    v.sort();
    assert!(v.len() >= 4, "examples found: {v:?}");
    v
}

fn expected_code(p: &Path) -> i32 {
    if p.file_name().unwrap() == "inconsistent.json" {
        1
    } else {
        0
    }
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cli-tests");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

#[test]
fn every_example_solves_with_the_expected_exit_code() {
    for p in examples() {
        let out = loci(&["solve", p.to_str().unwrap()]);
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert_eq!(
            out.status.code(),
            Some(expected_code(&p)),
            "{}: {stdout}{}",
            p.display(),
            String::from_utf8_lossy(&out.stderr)
        );
        let name = p.file_name().unwrap().to_str().unwrap();
        assert!(stdout.contains(name), "the report names the file: {stdout}");
        assert!(
            stdout.contains("outcome") && stdout.contains("dof"),
            "{stdout}"
        );
        assert!(
            out.stderr.is_empty(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

#[test]
fn json_output_parses_and_carries_the_outcome() {
    for p in examples() {
        let out = loci(&["solve", p.to_str().unwrap(), "--json"]);
        assert_eq!(
            out.status.code(),
            Some(expected_code(&p)),
            "{}",
            p.display()
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout)
            .unwrap_or_else(|e| panic!("{}: not JSON ({e})", p.display()));
        let outcome = v["outcome"].as_str().expect("an outcome string");
        if expected_code(&p) == 0 {
            assert!(matches!(outcome, "okay" | "redundant_okay"), "{outcome}");
        } else {
            assert_eq!(outcome, "inconsistent");
            assert!(
                !v["failed"].as_array().unwrap().is_empty(),
                "conflicts are named"
            );
        }
        assert!(v["dof"].is_u64());
        assert!(v["params"].as_array().is_some_and(|a| !a.is_empty()));
    }
}

#[test]
fn triangle_json_has_the_solved_values() {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/triangle.json");
    let out = loci(&["solve", p.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["outcome"], "okay");
    assert_eq!(v["dof"], 0);
    assert_eq!(v["group"], 2);
    let val = |h: u64| {
        v["params"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["h"] == h)
            .and_then(|p| p["val"].as_f64())
            .unwrap()
    };
    let (ax, ay, bx, by) = (val(11), val(12), val(13), val(14));
    assert_eq!((ax, ay), (0.5, -0.3), "the dragged point stays");
    assert!(((bx - ax).hypot(by - ay) - 30.0).abs() < 1e-9);
}

#[test]
fn output_file_is_a_solved_problem_that_solves_again_unchanged() {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/slot_mechanism.json");
    let out_path = scratch("slot_solved.json");
    let out = loci(&[
        "solve",
        p.to_str().unwrap(),
        "-o",
        out_path.to_str().unwrap(),
        "--json",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let first: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let again = loci(&["solve", out_path.to_str().unwrap(), "--json"]);
    assert_eq!(again.status.code(), Some(0));
    let second: serde_json::Value = serde_json::from_slice(&again.stdout).unwrap();
    assert_eq!(
        first["params"], second["params"],
        "a solved problem stays put"
    );
    assert_eq!(second["iterations"], 0);
}

#[test]
fn malformed_file_exits_3_naming_the_file() {
    let bad = scratch("truncated.json");
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/triangle.json"),
    )
    .unwrap();
    std::fs::write(&bad, &text[..text.len() / 2]).unwrap();
    let out = loci(&["solve", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(3));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("truncated.json"), "{err}");
    assert!(err.contains("line"), "says where: {err}");
    assert!(out.stdout.is_empty());

    let unknown = scratch("unknown_type.json");
    std::fs::write(&unknown, text.replace("\"line_segment\"", "\"squiggle\"")).unwrap();
    let out = loci(&["solve", unknown.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(3));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("unknown_type.json") && err.contains("squiggle"),
        "{err}"
    );
}

#[test]
fn invalid_model_and_missing_file_exit_3() {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/triangle.json"),
    )
    .unwrap();
    let dangling = scratch("dangling.json");
    std::fs::write(
        &dangling,
        text.replacen("\"pt_a\": 301", "\"pt_a\": 399", 1),
    )
    .unwrap();
    let out = loci(&["solve", dangling.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(3));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("dangling.json") && err.contains("entity 399"),
        "{err}"
    );

    let missing = scratch("does_not_exist.json");
    let out = loci(&["solve", missing.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&out.stderr).contains("does_not_exist.json"));
}

#[test]
fn convert_to_slvs_writes_a_file_that_solves_like_the_json() {
    for p in examples() {
        let out = scratch(&format!(
            "{}.slvs",
            p.file_stem().unwrap().to_string_lossy()
        ));
        let o = loci(&[
            "convert",
            p.to_str().unwrap(),
            "--to",
            "slvs",
            "-o",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}: {o:?}", p.display());
        let bytes = std::fs::read(&out).unwrap();
        assert!(bytes.starts_with(b"\xb1\xb2\xb3SolveSpaceREVa"));
        // The file solves group by group with the exit code the JSON solve gives.
        let o = loci(&["solve", out.to_str().unwrap()]);
        assert_eq!(
            o.status.code(),
            Some(expected_code(&p)),
            "{}: {o:?}",
            p.display()
        );
        // And converts back to JSON.
        let o = loci(&["convert", out.to_str().unwrap(), "--to", "json"]);
        assert!(o.status.success(), "{o:?}");
        let text = String::from_utf8(o.stdout).unwrap();
        assert!(text.contains("\"line_segment\""), "{text}");
    }
}

#[test]
fn convert_to_slvs_of_a_bad_problem_exits_3() {
    let bad = scratch("bad-convert.json");
    std::fs::write(&bad, "{\"params\": [], \"entities\": [{\"h\": 1, \"group\": 1, \"type\": \"line_segment\", \"points\": [7, 8]}], \"constraints\": []}").unwrap();
    let o = loci(&["convert", bad.to_str().unwrap(), "--to", "slvs"]);
    assert_eq!(o.status.code(), Some(3), "{o:?}");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("bad-convert.json"), "{err}");
}
