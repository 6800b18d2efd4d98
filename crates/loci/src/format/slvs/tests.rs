//! Reading, solving and writing small `.slvs` files, and every kind of malformed input.

use super::*;
use crate::model::ParamId;
use crate::{Config, ConstraintKind, Outcome};

/// Two points in the XY workplane of group 2, 10 apart, the first on the origin's
/// horizontal; saved unsolved (the second point is 8 away) with cosmetic keys loci keeps.
const SKETCH: &str = "@MAGIC@


Group.h.v=00000001
Group.type=5000
Group.name=#references
Group.color=ff000000
Group.remap={
}
AddGroup

Group.h.v=00000002
Group.type=5001
Group.order=1
Group.name=sketch-in-plane
Group.activeWorkplane.v=80020000
Group.subtype=6000
Group.predef.q.w=1.00000000000000000000
Group.predef.origin.v=00010001
Group.remap={
}
AddGroup

Param.h.v.=00010010
AddParam

Param.h.v.=00010011
AddParam

Param.h.v.=00010012
AddParam

Param.h.v.=00010020
Param.val=1.00000000000000000000
AddParam

Param.h.v.=00010021
AddParam

Param.h.v.=00010022
AddParam

Param.h.v.=00010023
AddParam

Param.h.v.=00040010
Param.val=-5.00000000000000000000
AddParam

Param.h.v.=00040011
AddParam

Param.h.v.=00050010
Param.val=3.00000000000000000000
AddParam

Param.h.v.=00050011
Param.val=1.00000000000000000000
AddParam

Request.h.v=00000001
Request.type=100
Request.group.v=00000001
AddRequest

Request.h.v=00000004
Request.type=101
Request.workplane.v=80020000
Request.group.v=00000002
AddRequest

Request.h.v=00000005
Request.type=101
Request.workplane.v=80020000
Request.group.v=00000002
AddRequest

Entity.h.v=00010000
Entity.type=10000
Entity.point[0].v=00010001
Entity.normal.v=00010020
AddEntity

Entity.h.v=00010001
Entity.type=2000
Entity.construction=1
AddEntity

Entity.h.v=00010020
Entity.type=3000
Entity.point[0].v=00010001
Entity.actNormal.w=1.00000000000000000000
AddEntity

Entity.h.v=00040000
Entity.type=2001
Entity.workplane.v=80020000
Entity.actPoint.x=-5.00000000000000000000
AddEntity

Entity.h.v=00050000
Entity.type=2001
Entity.workplane.v=80020000
Entity.actPoint.x=3.00000000000000000000
Entity.actPoint.y=1.00000000000000000000
AddEntity

Entity.h.v=80020000
Entity.type=10000
Entity.point[0].v=80020002
Entity.normal.v=80020001
AddEntity

Entity.h.v=80020001
Entity.type=3010
Entity.point[0].v=80020002
Entity.actNormal.w=1.00000000000000000000
AddEntity

Entity.h.v=80020002
Entity.type=2012
Entity.construction=1
AddEntity

Constraint.h.v=00000001
Constraint.type=30
Constraint.group.v=00000002
Constraint.workplane.v=80020000
Constraint.valA=10.00000000000000000000
Constraint.ptA.v=00040000
Constraint.ptB.v=00050000
Constraint.disp.offset.y=2.50000000000000000000
AddConstraint

Constraint.h.v=00000002
Constraint.type=20
Constraint.group.v=00000002
Constraint.workplane.v=80020000
Constraint.ptA.v=00040000
Constraint.ptB.v=00010001
AddConstraint

Constraint.h.v=00000003
Constraint.type=1000
Constraint.group.v=00000002
Constraint.workplane.v=80020000
Constraint.comment=a note
AddConstraint

";

/// The text as bytes, with SolveSpace's magic first line (which is not UTF-8).
fn bytes(text: &str) -> Vec<u8> {
    match text.strip_prefix("@MAGIC@") {
        Some(rest) => [super::records::MAGIC, rest.as_bytes()].concat(),
        None => text.as_bytes().to_vec(),
    }
}

fn load(text: &str) -> Result<SlvsFile, SlvsError> {
    SlvsFile::parse(&bytes(text))
}

#[test]
fn construction_flags_are_read_for_modelled_entities() {
    let f = load(SKETCH).unwrap();
    // The reference plane's origin and the copied workplane's origin carry the flag; the
    // sketch's own points do not.
    let got: Vec<u32> = f.construction.iter().map(|h| h.0).collect();
    assert!(got.contains(&0x0001_0001), "{got:x?}");
    assert!(!got.contains(&0x0004_0000), "{got:x?}");
    assert!(!got.contains(&0x0005_0000), "{got:x?}");
    for h in &f.construction {
        assert!(f.system.entity(*h).is_some());
    }
    // A request's flag marks the entities it generates.
    let text = SKETCH.replacen(
        "Request.h.v=00000004\nRequest.type=101\n",
        "Request.h.v=00000004\nRequest.type=101\nRequest.construction=1\n",
        1,
    );
    assert_ne!(text, SKETCH);
    let f = load(&text).unwrap();
    assert!(f.construction.contains(&EntityId(0x0004_0000)));
    assert!(!f.construction.contains(&EntityId(0x0005_0000)));
}

#[test]
fn loads_groups_params_entities_and_constraints() {
    let f = load(SKETCH).unwrap();
    assert_eq!(f.groups.len(), 2);
    assert_eq!(f.groups[0].status, GroupStatus::References);
    assert_eq!(f.groups[1].kind, GroupKind::DrawingWorkplane);
    assert_eq!(f.groups[1].status, GroupStatus::Solve);
    // Omitted values are 0; request params belong to their request's group.
    let p = f.system.param(ParamId(0x0004_0011)).unwrap();
    assert_eq!((p.val, p.group), (0.0, GroupId(2)));
    assert_eq!(f.system.value(ParamId(0x0005_0010)), Some(3.0));
    // A datum point is its request's entity 0, with params 0x10, 0x11.
    let e = f.system.entity(crate::EntityId(0x0005_0000)).unwrap();
    assert_eq!(
        e.kind.params(),
        &[ParamId(0x0005_0010), ParamId(0x0005_0011)]
    );
    // The comment is skipped with a note; the other two are mapped by SolveSpace's numbers.
    let kinds: Vec<_> = f.system.constraints().iter().map(|c| c.kind).collect();
    assert_eq!(
        kinds,
        [
            ConstraintKind::PtPtDistance,
            ConstraintKind::PointsCoincident
        ]
    );
    assert!(f.notes.iter().any(|n| n.message.contains("comment")));
}

#[test]
fn solves_group_by_group() {
    let mut f = load(SKETCH).unwrap();
    let res = solve_all(&mut f, &Config::default());
    assert_eq!(res.len(), 2);
    assert_eq!(res[0].result, GroupResult::References);
    let GroupResult::Solved(r) = &res[1].result else {
        panic!("group 2 not solved: {:?}", res[1].result)
    };
    assert_eq!(r.outcome, Outcome::Okay);
    // Point A is pinned to the origin (2 equations), the distance takes one more: 4 - 3.
    assert_eq!(r.dof, 1);
    assert!(res[1].is_ok());
    let v = |h: u32| f.system.value(ParamId(h)).unwrap();
    assert!(v(0x0004_0010).abs() < 1e-12 && v(0x0004_0011).abs() < 1e-12);
    let d = (v(0x0005_0010).powi(2) + v(0x0005_0011).powi(2)).sqrt();
    assert!((d - 10.0).abs() < 1e-9, "distance {d}");
}

#[test]
fn saving_rewrites_only_param_values() {
    let mut f = load(SKETCH).unwrap();
    let _ = solve_all(&mut f, &Config::default());
    let out = f.to_bytes();
    let text = String::from_utf8_lossy(&out);
    let (old, new): (Vec<&str>, Vec<&str>) = (SKETCH.lines().collect(), text.lines().collect());
    // Every line but the values is kept, in order.
    let kept = |v: &[&str]| -> Vec<String> {
        v.iter()
            .filter(|l| !l.starts_with("Param.val=") && !l.starts_with("@MAGIC@"))
            .map(|l| (*l).to_string())
            .collect()
    };
    assert_eq!(kept(&old[1..]), kept(&new[1..]));
    // Point A moved from (-5, 0) to the origin: its value line is rewritten in place.
    assert!(!new.contains(&"Param.val=-5.00000000000000000000"));
    assert!(new
        .iter()
        .any(|l| l.starts_with("Param.val=0.00000000000000000")
            || l.starts_with("Param.val=-0.0000000000000000")));
    assert!(new.contains(&"Constraint.disp.offset.y=2.50000000000000000000"));
    assert!(out.starts_with(super::records::MAGIC));
}

#[test]
fn a_zero_that_becomes_nonzero_gets_a_value_line() {
    let mut f = load(SKETCH).unwrap();
    assert!(f.system.set_value(ParamId(0x0004_0011), 2.5));
    let text = String::from_utf8_lossy(&f.to_bytes()).into_owned();
    assert!(text.contains("Param.h.v.=00040011\nParam.val=2.50000000000000000000\nAddParam"));
    assert_eq!(text.lines().count(), SKETCH.lines().count() + 1);
}

#[test]
fn round_trip_keeps_the_solved_parameters() {
    let mut f = load(SKETCH).unwrap();
    let _ = solve_all(&mut f, &Config::default());
    let again = SlvsFile::parse(&f.to_bytes()).unwrap();
    assert_eq!(again.system.constraints(), f.system.constraints());
    // Values are written as SolveSpace writes them, with 20 decimals: exact above 1e-4 or
    // so, and to 5e-21 below.
    for p in f.file_params() {
        let (a, b) = (f.system.value(p).unwrap(), again.system.value(p).unwrap());
        assert!((a - b).abs() <= 1e-20 || a == b, "{p}: {a} vs {b}");
    }
    // Solving the saved file again changes nothing.
    let mut again = again;
    let res = solve_all(&mut again, &Config::default());
    assert!(res.iter().all(GroupSolve::is_ok));
    for p in f.file_params() {
        let d = (f.system.value(p).unwrap() - again.system.value(p).unwrap()).abs();
        assert!(d < 1e-12, "{p} moved by {d}");
    }
}

#[test]
fn crlf_line_ends_are_read_and_kept() {
    let crlf = SKETCH.replace('\n', "\r\n");
    let mut f = load(&crlf).unwrap();
    let _ = solve_all(&mut f, &Config::default());
    let out = String::from_utf8_lossy(&f.to_bytes()).into_owned();
    assert!(out.matches("\r\n").count() >= crlf.matches("\r\n").count());
    assert!(!out.replace("\r\n", "").contains('\n'));
    assert!(SlvsFile::parse(&f.to_bytes()).is_ok());
}

fn err(text: &str) -> SlvsError {
    match load(text) {
        Ok(_) => panic!("malformed file loaded"),
        Err(e) => e,
    }
}

fn line_of(text: &str, needle: &str) -> usize {
    text.lines().position(|l| l.starts_with(needle)).unwrap() + 1
}

#[test]
fn truncated_file_names_the_open_record() {
    let cut = &SKETCH[..SKETCH.find("AddConstraint").unwrap()];
    let e = err(cut);
    assert!(matches!(e, SlvsError::Truncated { .. }), "{e}");
    assert_eq!(e.line(), line_of(SKETCH, "Constraint.h.v=00000001"));
    assert!(e.to_string().contains("Constraint"), "{e}");
}

#[test]
fn truncated_remap_block() {
    let cut = "Group.h.v=00000001\nGroup.remap={\n    1 00040000 1002\n";
    let e = err(cut);
    assert!(matches!(e, SlvsError::Truncated { line: 2, .. }), "{e}");
}

#[test]
fn empty_file_has_no_groups() {
    assert_eq!(err(""), SlvsError::NoGroups);
}

#[test]
fn bad_hex_handle() {
    let bad = SKETCH.replace("Constraint.ptB.v=00050000", "Constraint.ptB.v=0005zz00");
    let e = err(&bad);
    assert_eq!(e.line(), line_of(&bad, "Constraint.ptB.v="));
    assert!(
        matches!(&e, SlvsError::BadValue { key, .. } if key == "Constraint.ptB.v"),
        "{e}"
    );
}

#[test]
fn bad_number() {
    let bad = SKETCH.replace("Param.val=3.0", "Param.val=x3.0");
    let e = err(&bad);
    assert!(matches!(e, SlvsError::BadValue { .. }), "{e}");
    assert_eq!(e.line(), line_of(&bad, "Param.val=x3"));
}

#[test]
fn unknown_key() {
    let bad = SKETCH.replace(
        "Entity.construction=1\nAddEntity",
        "Entity.colour=1\nAddEntity",
    );
    let e = err(&bad);
    assert!(
        matches!(&e, SlvsError::UnknownKey { key, .. } if key == "Entity.colour"),
        "{e}"
    );
    assert_eq!(e.line(), line_of(&bad, "Entity.colour"));
}

#[test]
fn unrecognised_line() {
    let bad = SKETCH.replace(
        "AddRequest\n\nRequest.h.v=00000004",
        "AddRequest\nhello\nRequest.h.v=00000004",
    );
    let e = err(&bad);
    assert!(matches!(e, SlvsError::UnrecognizedLine { .. }), "{e}");
    assert_eq!(e.line(), line_of(&bad, "hello"));
}

#[test]
fn constraint_pointing_at_a_missing_entity() {
    let bad = SKETCH.replace("Constraint.ptB.v=00050000", "Constraint.ptB.v=00090000");
    let e = err(&bad);
    assert!(
        matches!(
            &e,
            SlvsError::Dangling {
                handle: 0x0009_0000,
                field: "Constraint.ptB.v",
                ..
            }
        ),
        "{e}"
    );
    assert_eq!(e.line(), line_of(&bad, "Constraint.ptB.v="));
}

#[test]
fn entity_pointing_at_a_missing_entity() {
    let bad = SKETCH.replace("Entity.normal.v=80020001", "Entity.normal.v=80020009");
    let e = err(&bad);
    assert!(matches!(e, SlvsError::Model { .. }), "{e}");
    // At the reference itself, named as the file writes it.
    let line = line_of(&bad, "Entity.normal.v=80020009");
    assert_eq!(e.line(), line);
    assert_eq!(
        e.to_string(),
        format!(
            "line {line}: Entity.h.v=80020000: Entity.normal.v=80020009 refers to an entity \
             that is not in the file"
        )
    );
}

#[test]
fn record_closed_by_the_wrong_add_line() {
    let bad = SKETCH.replace(
        "Constraint.comment=a note\nAddConstraint",
        "Constraint.comment=a note\nAddEntity",
    );
    let e = err(&bad);
    assert!(matches!(e, SlvsError::MixedRecord { .. }), "{e}");
}

#[test]
fn duplicate_handles() {
    let bad = SKETCH.replace("Constraint.h.v=00000002", "Constraint.h.v=00000001");
    let e = err(&bad);
    assert!(
        matches!(
            e,
            SlvsError::Duplicate {
                record: "Constraint",
                handle: 1,
                ..
            }
        ),
        "{e}"
    );
}

#[test]
fn unknown_constraint_type() {
    let bad = SKETCH.replace("Constraint.type=20\n", "Constraint.type=99\n");
    let e = err(&bad);
    assert!(matches!(e, SlvsError::UnknownType { code: 99, .. }), "{e}");
}

#[test]
fn unsupported_group_kinds_are_reported_by_name() {
    let ext = SKETCH.replace(
        "Group.h.v=00000002\nGroup.type=5001",
        "Group.h.v=00000002\nGroup.type=5101",
    );
    let mut f = load(&ext).unwrap();
    let res = solve_all(&mut f, &Config::default());
    match &res[1].result {
        GroupResult::Unsupported(why) => assert!(why.contains("lathe"), "{why}"),
        r => panic!("lathe group solved: {r:?}"),
    }
    // Nothing moved.
    assert_eq!(f.system.value(ParamId(0x0004_0010)), Some(-5.0));
}

#[test]
fn text_garbage_never_panics() {
    let mut s = 0x1234_5678u64;
    let bytes = bytes(SKETCH);
    for _ in 0..300 {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        let mut b = bytes.to_vec();
        let i = (s as usize) % b.len();
        b[i] = (s >> 32) as u8;
        let cut = (s >> 40) as usize % b.len();
        let _ = SlvsFile::parse(&b[..cut.max(i + 1)]);
        if let Ok(mut f) = SlvsFile::parse(&b) {
            let _ = solve_all(&mut f, &Config::default());
            let _ = f.to_bytes();
        }
    }
}

/// A linked part (group 3) placed at (1, 2, 3) turned a quarter turn about z, with two
/// imported points, the line between them and a normal, as SolveSpace saves them (the
/// imported file itself is not needed).
const LINKED: &str = "@MAGIC@


Group.h.v=00000001
Group.type=5000
Group.name=#references
Group.remap={
}
AddGroup

Group.h.v=00000003
Group.type=5300
Group.order=2
Group.name=part
Group.remap={
}
Group.impFileRel=part.slvs
AddGroup

Param.h.v.=80030000
Param.val=1.00000000000000000000
AddParam

Param.h.v.=80030001
Param.val=2.00000000000000000000
AddParam

Param.h.v.=80030002
Param.val=3.00000000000000000000
AddParam

Param.h.v.=80030003
Param.val=0.70710678118654757274
AddParam

Param.h.v.=80030004
AddParam

Param.h.v.=80030005
AddParam

Param.h.v.=80030006
Param.val=0.70710678118654757274
AddParam

Entity.h.v=80030001
Entity.type=11000
Entity.point[0].v=80030002
Entity.point[1].v=80030003
AddEntity

Entity.h.v=80030002
Entity.type=2011
Entity.actPoint.x=1.00000000000000000000
Entity.actPoint.y=3.00000000000000000000
Entity.actPoint.z=3.00000000000000000000
AddEntity

Entity.h.v=80030003
Entity.type=2011
Entity.actPoint.x=-1.00000000000000000000
Entity.actPoint.y=2.00000000000000000000
Entity.actPoint.z=3.00000000000000000000
AddEntity

Entity.h.v=80030004
Entity.type=3011
Entity.point[0].v=80030002
Entity.actNormal.w=0.70710678118654757274
Entity.actNormal.vz=0.70710678118654757274
AddEntity

";

#[test]
fn linked_parts_recover_their_base_geometry_and_solve() {
    use crate::EntityKind;
    let mut f = load(LINKED).unwrap();
    assert_eq!(f.groups[1].kind, GroupKind::Linked);
    assert_eq!(f.groups[1].status, GroupStatus::Solve);
    let close = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12);
    // The bases are the saved positions taken back through the saved motion.
    for (h, want) in [
        (0x8003_0002, [1.0, 0.0, 0.0]),
        (0x8003_0003, [0.0, 2.0, 0.0]),
    ] {
        match &f.system.entity(crate::EntityId(h)).unwrap().kind {
            EntityKind::PointNRotTrans {
                base, translation, ..
            } => {
                assert!(close(base, &want), "{h:08x}: {base:?}");
                assert_eq!(translation[0], ParamId(0x8003_0000));
            }
            k => panic!("{h:08x} is {k:?}"),
        }
    }
    match &f.system.entity(crate::EntityId(0x8003_0004)).unwrap().kind {
        EntityKind::NormalNRot { base, .. } => assert!(close(base, &[1.0, 0.0, 0.0, 0.0])),
        k => panic!("normal is {k:?}"),
    }
    // Nothing holds the part: it solves where it is, free to move six ways.
    let res = solve_all(&mut f, &Config::default());
    let GroupResult::Solved(r) = &res[1].result else {
        panic!("linked group not solved: {:?}", res[1].result)
    };
    assert_eq!((r.outcome, r.dof), (Outcome::Okay, 6));
    assert_eq!(f.system.value(ParamId(0x8003_0001)), Some(2.0));
}

#[test]
fn a_linked_part_without_its_motion_is_not_modelled() {
    let cut = LINKED.replace(
        "Param.h.v.=80030006\nParam.val=0.70710678118654757274\nAddParam\n",
        "",
    );
    let mut f = load(&cut).unwrap();
    let res = solve_all(&mut f, &Config::default());
    match &res[1].result {
        GroupResult::Unsupported(why) => assert!(why.contains("rotation"), "{why}"),
        r => panic!("solved without its rotation: {r:?}"),
    }
}
