//! Sketch files: the examples validate against `docs/sketch.schema.json`, load, solve and
//! write back a file that reads the same; bad files are refused with the name at fault.

use loci::format::sketch::{is_sketch_json, SketchFile, SketchFileError};
use loci::sketch::Spec;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn examples() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(root().join("examples/sketches"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    v.sort();
    assert_eq!(v.len(), 3);
    v
}

fn validator() -> jsonschema::Validator {
    let text = std::fs::read_to_string(root().join("docs/sketch.schema.json")).unwrap();
    let schema: Value = serde_json::from_str(&text).unwrap();
    jsonschema::draft202012::new(&schema).expect("a valid schema")
}

#[test]
fn examples_validate_load_solve_and_write_back() {
    let v = validator();
    for p in examples() {
        let text = std::fs::read_to_string(&p).unwrap();
        assert!(is_sketch_json(&text));
        let instance: Value = serde_json::from_str(&text).unwrap();
        let errs: Vec<String> = v.iter_errors(&instance).map(|e| e.to_string()).collect();
        assert!(errs.is_empty(), "{}: {errs:#?}", p.display());
        let file = SketchFile::from_json(&text).unwrap();
        let mut l = file.load().unwrap();
        let r = l.sketch.solve().unwrap();
        assert!(r.outcome.is_ok(), "{}: {r:?}", p.display());
        for (id, _) in l.sketch.constraints() {
            assert!(
                l.sketch.measure(id).unwrap().residual < 1e-8,
                "{}",
                p.display()
            );
        }
        // Written back with the solved coordinates, it validates and reads the same.
        let out = SketchFile::from_sketch(&l.sketch, |s| l.shape_name(s).map(str::to_string));
        let written: Value = serde_json::from_str(&out.to_json()).unwrap();
        assert!(v.iter_errors(&written).next().is_none());
        let again = SketchFile::from_json(&out.to_json())
            .unwrap()
            .load()
            .unwrap();
        assert_eq!(
            again.shapes.keys().collect::<Vec<_>>(),
            l.shapes.keys().collect::<Vec<_>>()
        );
        let mut a2 = again.sketch;
        let r = a2.solve().unwrap();
        assert!(r.outcome.is_ok());
        for (name, id) in &l.shapes {
            if let Some(pt) = l.sketch.as_point(*id) {
                let q = a2.as_point(again.shapes[name]).unwrap();
                let (x, y) = (l.sketch.point(pt), a2.point(q));
                assert!((x[0] - y[0]).hypot(x[1] - y[1]) < 1e-9, "{name}");
            }
        }
    }
}

#[test]
fn the_bracket_reads_back_its_reference_dimension() {
    let text = std::fs::read_to_string(root().join("examples/sketches/bracket.json")).unwrap();
    let mut l = SketchFile::from_json(&text).unwrap().load().unwrap();
    assert!(l.sketch.solve().unwrap().outcome.is_ok());
    let d = l.constraints["diagonal"];
    let m = l.sketch.measure(d).unwrap();
    assert!((m.value.unwrap() - 1700f64.sqrt()).abs() < 1e-9);
}

#[test]
fn every_constraint_type_of_the_api_is_in_the_schema() {
    let text = std::fs::read_to_string(root().join("docs/sketch.schema.json")).unwrap();
    let schema: Value = serde_json::from_str(&text).unwrap();
    let types: Vec<String> = schema["$defs"]["constraint"]["oneOf"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| {
            v["properties"]["type"]["const"]
                .as_str()
                .unwrap()
                .to_string()
        })
        .collect();
    let n = String::from("x");
    let all: Vec<Spec<String>> = serde_json::from_value(serde_json::json!(types
        .iter()
        .map(
            |t| serde_json::json!({"type": t, "point": n, "shape": n, "line": n, "arc": n,
            "a": n, "b": n, "value": 1.0, "degrees": 1.0, "axis": "vertical"})
        )
        .collect::<Vec<_>>()))
    .unwrap();
    assert_eq!(all.len(), 25);
    for (s, t) in all.iter().zip(&types) {
        assert_eq!(s.name(), t);
    }
}

#[test]
fn bad_files_name_what_is_wrong() {
    let load = |t: &str| SketchFile::from_json(t).and_then(|f| f.load().map(|_| ()));
    let err = load(
        r#"{"sketch": {"points": [{"name": "a", "x": 0, "y": 0}],
        "lines": [{"name": "l", "a": "a", "b": "nope"}]}}"#,
    )
    .unwrap_err();
    assert!(
        matches!(&err, SketchFileError::UnknownName { name, .. } if name == "nope"),
        "{err}"
    );
    let err = load(
        r#"{"sketch": {"points": [{"name": "a", "x": 0, "y": 0}, {"name": "a", "x": 1, "y": 0}]}}"#,
    )
    .unwrap_err();
    assert!(matches!(err, SketchFileError::DuplicateName(_)));
    let err = load(
        r#"{"sketch": {"points": [{"name": "a", "x": 0, "y": 0}, {"name": "b", "x": 1, "y": 0}],
        "constraints": [{"name": "r", "type": "radius", "shape": "a", "value": 1}]}}"#,
    )
    .unwrap_err();
    let msg = err.to_string();
    assert!(
        msg.contains("constraint r (radius)") && msg.contains("a circle or an arc"),
        "{msg}"
    );
    assert!(matches!(
        load(r#"{"sketch": {"shapes": []}}"#),
        Err(SketchFileError::Json(_))
    ));
    assert!(!is_sketch_json(r#"{"params": [], "entities": []}"#));
}
