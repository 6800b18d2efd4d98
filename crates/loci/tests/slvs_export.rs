//! Writing loci systems as `.slvs` files: every example converts, loads back with loci's
//! reader and solves to the parameters the JSON solve finds; and SolveSpace's fixtures go
//! `.slvs` -> JSON -> `.slvs` with every parameter value kept.

use loci::format::json::Problem;
use loci::format::slvs::{export, solve_all, GroupResult, SlvsFile};
use loci::System;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn examples() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(root().join("examples"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    v.sort();
    assert!(v.len() >= 5);
    v
}

#[test]
fn every_example_converts_and_solves_to_the_same_parameters() {
    for path in examples() {
        let name = path.display().to_string();
        let problem = Problem::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let out = export(&problem.system).unwrap_or_else(|e| panic!("{name}: {e}"));
        let mut file = SlvsFile::parse(&out.bytes).unwrap_or_else(|e| panic!("{name}: {e}"));
        // Every parameter of the system has a place in the file, at its value.
        for p in problem.system.params() {
            let q = out
                .params
                .get(&p.h)
                .unwrap_or_else(|| panic!("{name}: {} not written", p.h));
            assert_eq!(file.system.value(*q), Some(p.val), "{name}: {}", p.h);
        }
        // loci's JSON solve of the requested group, and the file solved group by group.
        let req = problem.request();
        let mut sys: System = problem.system.clone();
        let rep = loci::solve(&mut sys, req.group, &req.dragged, &req.config()).unwrap();
        let results = solve_all(&mut file, &loci::Config::default());
        let g = out.groups[&req.group];
        let r = results.iter().find(|r| r.group == g).unwrap();
        let GroupResult::Solved(frep) = &r.result else {
            panic!("{name}: group {} not solved: {:?}", g.0, r.result)
        };
        assert_eq!(frep.outcome, rep.outcome, "{name}");
        assert_eq!(frep.dof, rep.dof, "{name}");
        for p in sys.params() {
            let got = file.system.value(out.params[&p.h]).unwrap();
            assert!(
                (got - p.val).abs() < 1e-8 * (1.0 + p.val.abs()),
                "{name}: {}: file {got}, JSON {}",
                p.h,
                p.val
            );
        }
    }
}

#[test]
fn a_shared_point_is_tied_by_a_coincident_constraint() {
    // The triangle's lines share their corners: the second line to use a corner gets a point
    // of its own, tied to the first.
    let path = root().join("examples/triangle.json");
    let problem = Problem::from_json(&std::fs::read_to_string(path).unwrap()).unwrap();
    let out = export(&problem.system).unwrap();
    let file = SlvsFile::parse(&out.bytes).unwrap();
    let added = file.system.constraints().len() - problem.system.constraints().len();
    assert_eq!(added, 3, "one tie per shared corner");
    let text = String::from_utf8_lossy(&out.bytes);
    assert!(text.contains("Group.name=#references"));
    assert!(text.contains("Request.type=200"), "line requests");
}

fn fixtures() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("LOCI_SOLVESPACE_FIXTURES") {
        return Some(PathBuf::from(p));
    }
    let p = root().join("../shared/samples/solvespace");
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

#[test]
fn solvespace_fixtures_go_through_json_and_back_keeping_every_value() {
    let Some(dir) = fixtures() else {
        eprintln!("note: SolveSpace fixtures not found; round trip not checked");
        return;
    };
    let mut files = Vec::new();
    collect(&dir, &mut files);
    files.sort();
    assert_eq!(files.len(), 236);
    for f in &files {
        let name = f.display().to_string();
        let loaded = SlvsFile::parse(&std::fs::read(f).unwrap()).unwrap();
        let json = Problem {
            system: loaded.system.clone(),
            solve: None,
        }
        .to_json();
        let back = Problem::from_json(&json).unwrap().system;
        let out = export(&back).unwrap_or_else(|e| panic!("{name}: {e}"));
        let again = SlvsFile::parse(&out.bytes).unwrap_or_else(|e| panic!("{name}: {e}"));
        for p in loaded.system.params() {
            let q = out
                .params
                .get(&p.h)
                .unwrap_or_else(|| panic!("{name}: {} lost", p.h));
            let v = again.system.value(*q).unwrap();
            // Written with 20 decimals, as SolveSpace writes.
            assert!(
                (v - p.val).abs() <= 1e-15 * (1.0 + p.val.abs()),
                "{name}: {}",
                p.h
            );
        }
    }
}

/// `solvespace-cli`, when SolveSpace is installed (Debian's `solvespace` package).
fn solvespace_cli() -> Option<PathBuf> {
    // `version` prints the version (on either stream, depending on the build) and exits
    // with status 1.
    let out = std::process::Command::new("solvespace-cli")
        .arg("version")
        .output()
        .ok()?;
    let text = [out.stdout, out.stderr].concat();
    String::from_utf8_lossy(&text)
        .contains("SolveSpace version")
        .then(|| PathBuf::from("solvespace-cli"))
}

#[test]
fn solvespace_opens_the_converted_examples_and_solves_them_as_loci_does() {
    let Some(cli) = solvespace_cli() else {
        eprintln!("note: solvespace-cli not installed; SolveSpace's reading not checked");
        return;
    };
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("slvs-export");
    std::fs::create_dir_all(&dir).unwrap();
    for path in examples() {
        let name = path.display().to_string();
        let problem = Problem::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap();
        let out = export(&problem.system).unwrap();
        let file = dir.join(format!(
            "{}.slvs",
            path.file_stem().unwrap().to_string_lossy()
        ));
        std::fs::write(&file, &out.bytes).unwrap();
        // SolveSpace loads the file, solves every group and saves it again.
        let run = std::process::Command::new(&cli)
            .arg("regenerate")
            .arg(&file)
            .output()
            .unwrap();
        assert!(run.status.success(), "{name}: {run:?}");
        let saved = SlvsFile::parse(&std::fs::read(&file).unwrap())
            .unwrap_or_else(|e| panic!("{name}: SolveSpace's save: {e}"));
        let req = problem.request();
        let mut sys: System = problem.system.clone();
        let rep = loci::solve(&mut sys, req.group, &req.dragged, &req.config()).unwrap();
        if !rep.outcome.is_ok() {
            continue;
        }
        // SolveSpace's answer is one of loci's: solving from it moves nothing.
        let mut again = saved.clone();
        let results = solve_all(&mut again, &loci::Config::default());
        assert!(results.iter().all(|r| r.is_ok()), "{name}: {results:?}");
        for p in saved.file_params() {
            let (a, b) = (
                saved.system.value(p).unwrap(),
                again.system.value(p).unwrap(),
            );
            assert!((a - b).abs() < 1e-9 * (1.0 + a.abs()), "{name}: {p} moved");
        }
        // Where the answer is unique, it is the one the JSON solve finds; an
        // under-constrained problem may settle elsewhere along its free directions.
        if rep.dof > 0 {
            continue;
        }
        for p in sys.params() {
            let got = saved.system.value(out.params[&p.h]).unwrap();
            assert!(
                (got - p.val).abs() < 1e-6 * (1.0 + p.val.abs()),
                "{name}: {}: SolveSpace {got}, loci {}",
                p.h,
                p.val
            );
        }
    }
}

#[test]
fn circles_sharing_a_radius_and_a_normal_are_tied() {
    use loci::{Constraint, ConstraintKind, Entity, Param};
    // Two circles in 3D around (0,0,0) and (5,0,0) with one radius entity and one normal;
    // a diameter of 4 on the first.
    let mut sys = System::new();
    for (h, v) in [(1, 0.0), (2, 0.0), (3, 0.0), (4, 5.0), (5, 0.0), (6, 0.0)] {
        sys.add_param(Param::new(h, 1, v)).unwrap();
    }
    for (h, v) in [(7, 1.0), (8, 0.0), (9, 0.0), (10, 0.0), (11, 1.5)] {
        sys.add_param(Param::new(h, 2, v)).unwrap();
    }
    sys.add_entity(Entity::point_3d(100, 1, [1, 2, 3])).unwrap();
    sys.add_entity(Entity::point_3d(101, 1, [4, 5, 6])).unwrap();
    sys.add_entity(Entity::normal_3d(102, 2, [7, 8, 9, 10]))
        .unwrap();
    sys.add_entity(Entity::distance(103, 2, None, 11)).unwrap();
    sys.add_entity(Entity::circle(104, 2, None, 100, 102, 103))
        .unwrap();
    sys.add_entity(Entity::circle(105, 2, None, 101, 102, 103))
        .unwrap();
    sys.add_constraint(
        Constraint::new(1, 2, ConstraintKind::Diameter)
            .with_entities([104, 0, 0, 0])
            .with_val(4.0),
    )
    .unwrap();
    let out = export(&sys).unwrap();
    let mut file = SlvsFile::parse(&out.bytes).unwrap();
    let kinds: Vec<ConstraintKind> = file.system.constraints().iter().map(|c| c.kind).collect();
    for k in [
        ConstraintKind::Diameter,
        ConstraintKind::EqualRadius,
        ConstraintKind::SameOrientation,
        ConstraintKind::PointsCoincident,
    ] {
        assert!(kinds.contains(&k), "{k} in {kinds:?}");
    }
    let results = solve_all(&mut file, &loci::Config::default());
    assert!(results.iter().all(|r| r.is_ok()), "{results:?}");
    // The shared radius went to the first circle; the second follows it by equal_radius.
    let r = file.system.value(out.params[&loci::ParamId(11)]).unwrap();
    assert!((r - 2.0).abs() < 1e-9, "radius {r}");
    let second: Vec<f64> = file
        .system
        .entities()
        .iter()
        .filter_map(|e| match e.kind {
            loci::EntityKind::Distance { param } => file.system.value(param),
            _ => None,
        })
        .collect();
    assert_eq!(second.len(), 2);
    assert!(second.iter().all(|v| (v - 2.0).abs() < 1e-9), "{second:?}");
}

#[test]
fn more_requests_than_a_file_can_number_is_an_error() {
    use loci::{Entity, Param};
    let mut sys = System::new();
    for h in 1..=3 * 0x4000 {
        sys.add_param(Param::new(h, 1, 0.0)).unwrap();
    }
    for i in 0..0x4000 {
        sys.add_entity(Entity::point_3d(
            i + 1,
            1,
            [3 * i + 1, 3 * i + 2, 3 * i + 3],
        ))
        .unwrap();
    }
    match export(&sys) {
        Err(loci::format::slvs::ExportError::TooLarge { needed }) => assert!(needed > 0x3fff),
        other => panic!("expected TooLarge, got {:?}", other.map(|e| e.bytes.len())),
    }
}
