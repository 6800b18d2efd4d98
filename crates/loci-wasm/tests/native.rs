//! The bindings' Rust side, natively: errors name the object at fault, a sketch read from a
//! file is dragged across calls and diagnosed by its names, systems and assemblies solve, and
//! the TypeScript types list every kind the core has.

use loci::ConstraintKind;
use loci_wasm::assembly::AssemblyBinding;
use loci_wasm::error::{Class, Fault};
use loci_wasm::sketch::SketchBinding;
use loci_wasm::system::System;
use serde_json::Value;

fn example(path: &str) -> String {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/");
    std::fs::read_to_string(format!("{root}{path}")).expect("example exists")
}

fn json(text: &str) -> Value {
    serde_json::from_str(text).expect("the bindings write JSON")
}

#[test]
fn a_sketch_error_names_the_shape_and_its_class() {
    let e: Fault = loci::sketch::SketchError::NoShape(
        serde_json::from_value(Value::from(4242u32)).expect("a shape handle"),
    )
    .into();
    assert_eq!(e.class, Class::Sketch);
    assert_eq!(e.object.as_deref(), Some("shape 4242"));
    assert_eq!(e.class.name(), "SketchError");
}

#[test]
fn a_file_with_an_unknown_name_is_refused_naming_the_constraint() {
    let text = r#"{"sketch":{"points":[{"name":"a","x":0,"y":0}],
        "constraints":[{"type":"fix","point":"b"}]}}"#;
    let e = SketchBinding::read(text).err().expect("refused");
    assert_eq!(e.class, Class::Sketch);
    assert!(
        e.object.as_deref().is_some_and(|o| o.contains("#1")),
        "{e:?}"
    );
    assert!(e.message.contains("\"b\""), "{}", e.message);
    let e = SketchBinding::read("{ nope").err().expect("refused");
    assert_eq!(e.class, Class::Format);
}

#[test]
fn the_four_bar_is_dragged_across_calls_and_keeps_its_bars() {
    let mut s = SketchBinding::read(&example("sketches/four_bar.json")).expect("reads");
    assert_eq!(json(&s.solve_sketch().expect("solves"))["outcome"], "okay");
    let check = json(&s.check_sketch().expect("diagnoses"));
    assert_eq!(check["dof"], 1);
    let b = s.sketch().shapes().nth(2).expect("B").0;
    let (a, d) = (s.point(100).expect("A"), s.point(101).expect("D"));
    let bp = s.point(b.entity().0).expect("B is a point");
    s.start(b.entity().0).expect("B is free");
    for k in 1..=36 {
        let t = f64::from(k) * 10f64.to_radians();
        let step = json(&s.step(2.0 * t.cos(), 2.0 * t.sin()).expect("a step"));
        assert_eq!(step["outcome"], "okay");
        let sk = s.sketch();
        let [x, y] = sk.point(bp);
        assert!(((x - sk.point(a)[0]).hypot(y - sk.point(a)[1]) - 1.0).abs() < 1e-7);
        assert_eq!(sk.point(d), [4.0, 0.0]);
    }
    s.end();
    // The drag's soft constraints are gone; the file keeps the names.
    let file = json(&s.write());
    assert_eq!(file["sketch"]["points"][2]["name"], "B");
    assert!(s.step(0.0, 0.0).is_err(), "no drag after the end");
}

#[test]
fn a_conflict_is_named_by_the_drawing() {
    let text = r#"{"sketch":{"points":[{"name":"a","x":0,"y":0},{"name":"b","x":5,"y":0}],
        "lines":[{"name":"ab","a":"a","b":"b"}],
        "constraints":[{"type":"fix","point":"a"},{"type":"length","line":"ab","value":5},
                       {"type":"distance","a":"a","b":"b","value":7}]}}"#;
    let mut s = SketchBinding::read(text).expect("reads");
    let r = json(&s.solve_sketch().expect("solves"));
    assert_eq!(r["outcome"], "inconsistent");
    let c = json(&s.check_sketch().expect("diagnoses"));
    let names: Vec<&str> = c["names"]
        .as_object()
        .expect("names")
        .values()
        .map(|v| v.as_str().expect("a name"))
        .collect();
    assert_eq!(names, ["length ab = 5", "distance a, b = 7"]);
}

#[test]
fn a_problem_file_solves_and_a_slvs_file_round_trips() {
    let mut sys = System::read_json(&example("two_points.json")).expect("reads");
    let r = json(&sys.solve_request().expect("solves"));
    assert_eq!(r["outcome"], "okay");
    let bytes = sys.write_slvs().expect("writes");
    let mut back = System::read_slvs(&bytes).expect("reads back");
    let groups = json(&back.solve_slvs().expect("solves"));
    assert!(
        groups
            .as_array()
            .expect("groups")
            .iter()
            .all(|g| g["ok"] == true),
        "{groups}"
    );
    let e = sys.solve_group(9, &[], "").expect_err("no group 9");
    assert_eq!(
        (e.class, e.object.as_deref()),
        (Class::Solve, Some("group 9"))
    );
}

#[test]
fn the_door_hinge_solves_with_every_mate_holding() {
    let mut a = AssemblyBinding::read(&example("assembly/door_hinge.json")).expect("reads");
    let r = json(&a.solve_all().expect("solves"));
    for m in r["mates"].as_array().expect("mates") {
        assert!(
            ["satisfied", "adjusted"].contains(&m["status"].as_str().unwrap()),
            "{m}"
        );
    }
    assert!(AssemblyBinding::read(r#"{"loci_assembly": 7}"#).is_err());
}

/// The `.d.ts` lists every constraint kind, sketch constraint and mate status of the core, so
/// that TypeScript accepts all of them.
#[test]
fn the_typescript_types_list_every_kind() {
    let dts = include_str!("../js/loci.d.ts");
    for k in ConstraintKind::ALL {
        assert!(
            dts.contains(&format!("\"{}\"", k.name())),
            "{} missing",
            k.name()
        );
    }
    let spec = include_str!("../../loci/src/sketch/spec.rs");
    let names: Vec<&str> = spec
        .lines()
        .filter_map(|l| l.trim().strip_prefix("Spec::"))
        .filter_map(|l| l.split("=> \"").nth(1))
        .map(|l| l.trim_end_matches("\","))
        .collect();
    assert_eq!(names.len(), 25, "{names:?}");
    for n in names {
        assert!(
            dts.contains(&format!("type: \"{n}\"")),
            "sketch constraint {n} missing"
        );
    }
    for st in [
        "satisfied",
        "adjusted",
        "blocked",
        "invalid_selection",
        "no_direction",
        "same_component",
        "not_attached",
        "redundant",
        "conflicting",
        "unsatisfied",
    ] {
        let s: loci::assembly::MateStatus =
            serde_json::from_value(Value::from(st)).expect("a status");
        assert!(dts.contains(&format!("\"{}\"", s.name())));
    }
}

#[test]
fn a_packed_report_holds_every_field_of_the_report() {
    let r = loci::Report {
        outcome: loci::Outcome::Inconsistent,
        dof: 2,
        failed: vec![loci::ConstraintId(3), loci::ConstraintId(70_000)],
        failed_entities: vec![loci::EntityId(9)],
        iterations: 5,
        residual: 0.25,
        unknowns: 12,
        equations: 11,
        components: 1,
    };
    assert_eq!(
        loci_wasm::system::packed(&r),
        vec![2.0, 2.0, 5.0, 0.25, 12.0, 11.0, 1.0, 2.0, 3.0, 70_000.0, 1.0, 9.0]
    );
    let okay = loci::Report::empty();
    assert_eq!(
        loci_wasm::system::packed(&okay),
        vec![0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    );
}
