//! End-to-end: `loci solve`, `loci check` and `loci drag` on the sketch examples.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn loci(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_loci"))
        .args(args)
        .output()
        .expect("the loci binary runs")
}

fn example(name: &str) -> String {
    let p: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/sketches")
        .join(name);
    p.display().to_string()
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn sketch_files_solve_and_check_by_content() {
    for f in ["slot.json", "bracket.json", "four_bar.json"] {
        let o = loci(&["solve", &example(f)]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{f}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        assert!(stdout(&o).contains("sketch okay"), "{}", stdout(&o));
        let o = loci(&["check", &example(f), "--json"]);
        assert_eq!(o.status.code(), Some(0), "{f}");
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        for c in v["constraints"].as_array().unwrap() {
            assert!(c["residual"].as_f64().unwrap() < 1e-8, "{f}: {c}");
        }
    }
    let o = loci(&["check", &example("bracket.json")]);
    assert!(
        stdout(&o).contains("0 degrees of freedom"),
        "{}",
        stdout(&o)
    );
    let o = loci(&["solve", &example("slot.json"), "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["outcome"], "okay");
    let tr = v["sketch"]["points"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["name"] == "tr")
        .unwrap()
        .clone();
    assert!(
        (tr["x"].as_f64().unwrap() - 10.0).abs() < 1e-9
            && (tr["y"].as_f64().unwrap() - 2.0).abs() < 1e-9
    );
}

#[test]
fn drag_prints_every_step() {
    let o = loci(&[
        "drag",
        &example("four_bar.json"),
        "--point",
        "B",
        "--to",
        "-1,0",
        "--steps",
        "7",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let out = stdout(&o);
    assert_eq!(
        out.lines().filter(|l| l.starts_with("step ")).count(),
        7,
        "{out}"
    );
    assert!(out.contains("step 7/7: okay"), "{out}");
    let o = loci(&[
        "drag",
        &example("four_bar.json"),
        "--point",
        "Z",
        "--to",
        "0,0",
    ]);
    assert_eq!(o.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&o.stderr).contains("\"Z\""));
    let o = loci(&[
        "drag",
        &example("four_bar.json"),
        "--point",
        "B",
        "--to",
        "x",
    ]);
    assert_ne!(o.status.code(), Some(0));
}
