//! `loci assemble` on the example assemblies.

use std::path::{Path, PathBuf};
use std::process::Command;

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/assembly")
        .join(name)
}

fn loci(args: &[&str]) -> (i32, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_loci"))
        .args(args)
        .output()
        .unwrap();
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8(o.stdout).unwrap(),
        String::from_utf8(o.stderr).unwrap(),
    )
}

#[test]
fn prints_the_report_and_writes_solved_poses() {
    let door = example("door_hinge.json");
    let out = std::env::temp_dir().join(format!("loci-door-{}.json", std::process::id()));
    let (code, stdout, stderr) = loci(&[
        "assemble",
        door.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("assembly dof: 0"), "{stdout}");
    assert!(
        stdout.contains("opening") && stdout.contains("adjusted") && stdout.contains("value 60 "),
        "{stdout}"
    );
    assert!(stdout.contains("frame at (0, 0, 0): grounded"), "{stdout}");
    // The written file solves with nothing left to move.
    let (code, stdout, _) = loci(&["assemble", out.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(
        !stdout.contains("adjusted") && stdout.contains("satisfied"),
        "{stdout}"
    );
    std::fs::remove_file(out).ok();
}

#[test]
fn steps_prints_every_pass() {
    let (code, stdout, stderr) = loci(&[
        "assemble",
        example("door_hinge.json").to_str().unwrap(),
        "--steps",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("stepped mode") && stdout.contains("converged"),
        "{stdout}"
    );
    assert!(
        stdout.contains("pass    1: REVO1 ") && stdout.contains("door at ("),
        "{stdout}"
    );
}

#[test]
fn json_report_and_bad_files() {
    let (code, stdout, _) = loci(&[
        "assemble",
        example("four_bar_3d.json").to_str().unwrap(),
        "--json",
    ]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(v["dof"], 1);
    let bad = std::env::temp_dir().join(format!("loci-bad-{}.json", std::process::id()));
    std::fs::write(&bad, "{ \"components\": [ { \"name\": 1 } ] }").unwrap();
    let (code, _, stderr) = loci(&["assemble", bad.to_str().unwrap()]);
    assert_eq!(code, 3);
    assert!(stderr.contains("line 1"), "{stderr}");
    std::fs::remove_file(bad).ok();
}
