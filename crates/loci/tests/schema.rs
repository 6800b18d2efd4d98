//! `docs/loci.schema.json` describes the files loci reads: every example validates, the
//! constraint types are exactly [`ConstraintKind::ALL`], and the fields each type requires are
//! those its signature uses.

use loci::format::json::{Problem, SolveResult};
use loci::{ConstraintKind, PlaneRule, Want, FIELD_NAMES};
use serde_json::{json, Value};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn schema() -> Value {
    let text = std::fs::read_to_string(root().join("docs/loci.schema.json")).unwrap();
    serde_json::from_str(&text).expect("the schema is JSON")
}

fn validator(schema: &Value) -> jsonschema::Validator {
    jsonschema::draft202012::new(schema).expect("a valid draft 2020-12 schema")
}

/// The schema, re-rooted at one of its `$defs`.
fn sub_validator(schema: &Value, def: &str) -> jsonschema::Validator {
    let s = json!({
        "$schema": schema["$schema"],
        "$defs": schema["$defs"],
        "$ref": format!("#/$defs/{def}"),
    });
    validator(&s)
}

fn errors(v: &jsonschema::Validator, instance: &Value) -> Vec<String> {
    v.iter_errors(instance)
        .map(|e| format!("{} at {}", e, e.instance_path()))
        .collect()
}

fn examples() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(root().join("examples"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    v.sort();
    assert!(!v.is_empty());
    v
}

#[test]
fn every_example_validates_against_the_schema() {
    let s = schema();
    let v = validator(&s);
    for p in examples() {
        let instance: Value = serde_json::from_str(&std::fs::read_to_string(&p).unwrap()).unwrap();
        let errs = errors(&v, &instance);
        assert!(errs.is_empty(), "{}: {errs:#?}", p.display());
        // And what loci writes back validates too.
        let problem = Problem::from_json(&instance.to_string()).unwrap();
        let written: Value = serde_json::from_str(&problem.to_json()).unwrap();
        let errs = errors(&v, &written);
        assert!(errs.is_empty(), "{} rewritten: {errs:#?}", p.display());
    }
}

#[test]
fn solve_results_validate_against_the_result_definition() {
    let s = schema();
    let v = sub_validator(&s, "result");
    for p in examples() {
        let mut problem = Problem::from_json(&std::fs::read_to_string(&p).unwrap()).unwrap();
        let req = problem.request();
        let rep = loci::solve(&mut problem.system, req.group, &req.dragged, &req.config()).unwrap();
        let out: Value =
            serde_json::from_str(&SolveResult::new(&problem.system, req.group, &rep).to_json())
                .unwrap();
        let errs = errors(&v, &out);
        assert!(errs.is_empty(), "{}: {errs:#?}", p.display());
    }
}

#[test]
fn schema_constraint_types_are_exactly_the_library_s() {
    let s = schema();
    let listed: Vec<&str> = s["$defs"]["constraintType"]["enum"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    let names: Vec<&str> = ConstraintKind::ALL.iter().map(|k| k.name()).collect();
    assert_eq!(listed, names);
}

#[test]
fn schema_required_fields_follow_each_signature() {
    let s = schema();
    let rules = s["$defs"]["constraint"]["allOf"].as_array().unwrap();
    assert_eq!(rules.len(), ConstraintKind::ALL.len());
    for &kind in ConstraintKind::ALL {
        let rule = rules
            .iter()
            .find(|r| r["if"]["properties"]["type"]["const"] == kind.name())
            .unwrap_or_else(|| panic!("no rule for {kind}"));
        let then = &rule["then"];
        let required: BTreeSet<&str> = then["required"]
            .as_array()
            .map(|a| a.iter().map(|v| v.as_str().unwrap()).collect())
            .unwrap_or_default();
        let sig = kind.signature();
        let mut want: BTreeSet<&str> = FIELD_NAMES
            .iter()
            .zip(sig.fields)
            .filter(|(_, w)| w.is_some())
            .map(|(n, _)| *n)
            .collect();
        // Types with two forms spell out the alternatives with anyOf.
        if matches!(kind, ConstraintKind::Horizontal | ConstraintKind::Vertical) {
            assert_eq!(
                then["anyOf"],
                json!([{"required": ["entity_a"]}, {"required": ["pt_a", "pt_b"]}]),
                "{kind}"
            );
            want.clear();
        }
        if kind == ConstraintKind::AtMidpoint {
            assert_eq!(
                then["anyOf"],
                json!([{"required": ["pt_a", "entity_a"]}, {"required": ["entity_a", "entity_b"]}]),
                "{kind}"
            );
            want.clear();
        }
        if sig.plane == PlaneRule::Required {
            want.insert("workplane");
        }
        assert_eq!(required, want, "{kind}");
    }
}

#[test]
fn schema_rejects_what_loci_rejects() {
    let s = schema();
    let v = validator(&s);
    let base: Value = serde_json::from_str(
        &std::fs::read_to_string(root().join("examples/triangle.json")).unwrap(),
    )
    .unwrap();
    let bad = |edit: &dyn Fn(&mut Value)| {
        let mut x = base.clone();
        edit(&mut x);
        x
    };
    let cases = [
        (
            "unknown constraint type",
            bad(&|x| x["constraints"][1]["type"] = json!("sideways")),
        ),
        (
            "unknown entity type",
            bad(&|x| x["entities"][3]["type"] = json!("blob")),
        ),
        ("zero handle", bad(&|x| x["params"][0]["h"] = json!(0))),
        (
            "missing pt_b",
            bad(&|x| {
                x["constraints"][2].as_object_mut().unwrap().remove("pt_b");
            }),
        ),
        (
            "2D point without workplane",
            bad(&|x| {
                x["entities"][3]
                    .as_object_mut()
                    .unwrap()
                    .remove("workplane");
            }),
        ),
        (
            "horizontal without workplane",
            bad(&|x| {
                x["constraints"][1]
                    .as_object_mut()
                    .unwrap()
                    .remove("workplane");
            }),
        ),
        (
            "three params for a 2D point",
            bad(&|x| x["entities"][3]["params"] = json!([11, 12, 13])),
        ),
        (
            "unknown option",
            bad(&|x| x["solve"]["options"] = json!({"speed": 11})),
        ),
        (
            "bad tolerance",
            bad(&|x| x["solve"]["options"] = json!({"tolerance": 0})),
        ),
        (
            "a value beyond 1e100",
            bad(&|x| x["params"][7]["val"] = json!(-1e101)),
        ),
        (
            "a dimension beyond 1e100",
            bad(&|x| x["constraints"][2]["val"] = json!(1e160)),
        ),
    ];
    for (what, instance) in cases {
        assert!(!v.is_valid(&instance), "the schema accepts: {what}");
        // And loci rejects it too, where the file is well-formed JSON of its shape.
        if what.contains("1e100") {
            let text = instance.to_string();
            assert!(Problem::from_json(&text).is_err(), "loci accepts: {what}");
        }
    }
    // A horizontal given as two points is fine.
    let ok = bad(&|x| {
        x["constraints"][1] = json!({"h": 2, "group": 2, "type": "horizontal",
            "workplane": 200, "pt_a": 301, "pt_b": 302});
    });
    assert!(v.is_valid(&ok), "{:#?}", errors(&v, &ok));
}

#[test]
fn the_format_doc_shows_the_shipped_example_verbatim() {
    let doc = std::fs::read_to_string(root().join("docs/format.md")).unwrap();
    let example = std::fs::read_to_string(root().join("examples/two_points.json")).unwrap();
    assert!(
        doc.contains(example.trim()),
        "docs/format.md and examples/two_points.json differ"
    );
    // Every type the library knows is documented in the table, with the entity types its
    // signature asks for.
    for &kind in loci::ConstraintKind::ALL {
        let head = format!("| `{}` | {} | ", kind.name(), kind.slvs_code());
        let row = doc
            .lines()
            .find(|l| l.starts_with(&head))
            .unwrap_or_else(|| panic!("{kind} is not in the table"));
        let fields = row[head.len()..].split(" | ").next().unwrap();
        for (name, want) in FIELD_NAMES.iter().zip(kind.signature().fields) {
            let Some(want) = want else { continue };
            let words = match want {
                Want::Point => "point",
                Want::Line => "line_segment",
                Want::Workplane => "workplane",
                Want::Normal => "normal",
                Want::LineOrNormal => "line_segment or normal",
                Want::CircleOrArc => "circle or arc_of_circle",
                Want::Arc => "arc_of_circle",
                Want::Cubic => "cubic",
                Want::Curve => "arc_of_circle or cubic",
            };
            let item = format!("`{name}`: {words}");
            assert!(
                fields
                    .split([',', ';'])
                    .any(|f| f.trim().trim_start_matches("or ") == item),
                "{kind}: the table says {fields:?}, the signature {item:?}"
            );
        }
    }
}
