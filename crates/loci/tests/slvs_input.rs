//! `.slvs` files at the edges of SolveSpace's handle numbering, and the messages of files
//! loci cannot read: each names the object as the file writes it, in hex, with its line, and
//! says it once.

use loci::format::slvs::{solve_all, GroupResult, SlvsError, SlvsFile};
use loci::{Config, ParamId};
use std::path::Path;

fn data(name: &str) -> Vec<u8> {
    std::fs::read(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/data")
            .join(name),
    )
    .unwrap()
}

/// The magic's three high bytes, which are not text.
const HIGH: &[u8] = b"\xb1\xb2\xb3";

/// The same sketch twice: a datum point of request 0004 and one of request 3fff (below) or
/// 4000 (above), 10 apart, as text after the magic's high bytes. From request 4000 on, a
/// request's handles (`h << 16`) have bit 30 set, which SolveSpace also uses for the helper
/// parameters of constraints.
fn twins() -> (String, String) {
    let text = |n| {
        let b = data(n);
        String::from_utf8(b.strip_prefix(HIGH).unwrap().to_vec()).unwrap()
    };
    (
        text("request_handle_3fff.slvs"),
        text("request_handle_4000.slvs"),
    )
}

fn parse(text: &str) -> Result<SlvsFile, SlvsError> {
    SlvsFile::parse(&[HIGH, text.as_bytes()].concat())
}

/// Solves every group; returns each group's outcome and dof, and every parameter of the
/// solved group 2 with request 3fff's handles written as 4000's.
fn solved(text: &str) -> (Vec<String>, Vec<(u32, f64)>) {
    let mut f = parse(text).unwrap();
    let res = solve_all(&mut f, &Config::default());
    let outcomes = res
        .iter()
        .map(|r| match &r.result {
            GroupResult::Solved(rep) => format!("{}: {} dof {}", r.group, rep.outcome, rep.dof),
            other => format!("{}: {other}", r.group),
        })
        .collect();
    let mut params: Vec<(u32, f64)> = f
        .system
        .params()
        .iter()
        .filter(|p| p.group.0 == 2)
        .map(|p| {
            let h = if p.h.0 >> 16 == 0x3fff {
                0x4000_0000 | (p.h.0 & 0xffff)
            } else {
                p.h.0
            };
            (h, p.val)
        })
        .collect();
    params.sort_by_key(|p| p.0);
    (outcomes, params)
}

#[test]
fn request_4000_loads_and_solves_like_request_3fff() {
    let (low, high) = twins();
    // Its parameters are in the file, and now in the model, in the request's group.
    let f = parse(&high).unwrap();
    for i in 0x10..=0x12 {
        let p = f.system.param(ParamId(0x4000_0000 | i)).unwrap();
        assert_eq!(p.group.0, 2);
    }
    assert_eq!(solved(&low), solved(&high));
    let (outcomes, _) = solved(&high);
    assert_eq!(outcomes[1], "group 2: okay dof 5");

    // Solved values too, when the solve has to move the points: the distance becomes 12.
    let stretch = |t: &str| t.replace("Constraint.valA=10.0", "Constraint.valA=12.0");
    let (lo, hi) = (solved(&stretch(&low)), solved(&stretch(&high)));
    assert_eq!(lo, hi);
    let (_, params) = hi;
    let at = |h: u32| params.iter().find(|p| p.0 == h).unwrap().1;
    let (a, b) = (
        (at(0x0004_0010), at(0x0004_0011)),
        (at(0x4000_0010), at(0x4000_0011)),
    );
    let d = ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt();
    assert!((d - 12.0).abs() < 1e-9, "distance {d}");
}

#[test]
fn a_constraint_s_helper_parameter_is_still_skipped() {
    // SolveSpace numbers a constraint's own unknowns `c | 0x40000000 | i`; with no entity
    // holding it, such a parameter is the constraint's, which loci does not need.
    let (low, _) = twins();
    let extra = low.replacen(
        "Request.h.v=00000001",
        "Param.h.v.=40000001\nParam.val=3.0\nAddParam\n\nRequest.h.v=00000001",
        1,
    );
    let f = parse(&extra).unwrap();
    assert!(f.system.param(ParamId(0x4000_0001)).is_none());
    assert_eq!(solved(&extra), solved(&low));
}

#[test]
fn request_handles_past_7fff_are_refused_by_name() {
    let (_, high) = twins();
    let big = high.replace("Request.h.v=00004000", "Request.h.v=00008000");
    let e = parse(&big).unwrap_err();
    assert!(
        matches!(e, SlvsError::HandleTooLarge { handle: 0x8000, .. }),
        "{e}"
    );
    let line = big
        .lines()
        .position(|l| l == "Request.h.v=00008000")
        .unwrap()
        + 1;
    assert_eq!(
        e.to_string(),
        format!(
            "line {line}: Request.h.v=00008000 is too large: the handles of a request's \
             entities and parameters are its own shifted left by 16 bits, so it must be at \
             most 00007fff"
        )
    );
}

fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.starts_with(needle))
        .unwrap_or_else(|| panic!("no {needle}"))
        + 1
}

/// Every message: the object in hex as the file writes it, the line, once.
#[test]
fn errors_name_objects_as_the_file_does() {
    let (_, high) = twins();
    let cases: Vec<(String, String)> = vec![
        {
            // The entity's own parameter is missing.
            let t = high.replace("Param.h.v.=40000011", "Param.h.v.=40000099");
            let line = line_of(&t, "Entity.h.v=40000000");
            (
                t,
                format!(
                    "line {line}: Entity.h.v=40000000: its parameter params[1], \
                     Param.h.v.=40000011, is not in the file"
                ),
            )
        },
        {
            let t = high.replace("Constraint.ptB.v=40000000", "Constraint.ptB.v=00090000");
            let line = line_of(&t, "Constraint.ptB.v=");
            (
                t,
                format!(
                    "line {line}: Constraint.h.v=00000001: Constraint.ptB.v=00090000 refers to \
                     an entity that is not in the file"
                ),
            )
        },
        {
            // A workplane where a point is needed: found by the model's check, placed at
            // the field.
            let t = high.replace("Constraint.ptB.v=40000000", "Constraint.ptB.v=00010000");
            let line = line_of(&t, "Constraint.ptB.v=");
            (
                t,
                format!(
                    "line {line}: Constraint.h.v=00000001: Constraint.ptB.v=00010000 is a \
                     workplane, but a point is expected"
                ),
            )
        },
        {
            let t = high.replace("Entity.h.v=40000000", "Entity.h.v=00040000");
            let first = line_of(&t, "Entity.h.v=00040000");
            let line = t
                .lines()
                .enumerate()
                .filter(|(_, l)| *l == "Entity.h.v=00040000")
                .nth(1)
                .unwrap()
                .0
                + 1;
            (
                t,
                format!(
                    "line {line}: Entity.h.v=00040000 is defined twice (first at line {first})"
                ),
            )
        },
        {
            let t = high.replace("Constraint.type=30", "Constraint.type=999");
            let line = line_of(&t, "Constraint.type=");
            (
                t,
                format!("line {line}: Constraint.h.v=00000001: unknown type Constraint.type=999"),
            )
        },
        {
            let t = high.replace("Constraint.ptB.v=40000000", "Constraint.ptB.v=40zz0000");
            let line = line_of(&t, "Constraint.ptB.v=");
            (
                t,
                format!(
                    "line {line}: Constraint.h.v=00000001: Constraint.ptB.v=40zz0000: expected \
                     a hexadecimal number of at most 8 digits"
                ),
            )
        },
        {
            let t = high.replacen(
                "Request.group.v=00000002\nRequest.construction=0\nAddRequest\n\nEntity",
                "Request.group.v=00000009\nRequest.construction=0\nAddRequest\n\nEntity",
                1,
            );
            let line = line_of(&t, "Request.group.v=00000009");
            (
                t,
                format!(
                    "line {line}: Request.h.v=00004000: Request.group.v=00000009 refers to a \
                     group that is not in the file"
                ),
            )
        },
        {
            let t = high.replace(
                "Entity.h.v=40000000\n",
                "Entity.h.v=40000000\nEntity.colour=1\n",
            );
            let line = line_of(&t, "Entity.colour");
            (
                t,
                format!("line {line}: Entity.h.v=40000000: unknown key `Entity.colour`"),
            )
        },
        {
            let cut = high.rfind("AddConstraint").unwrap();
            let t = high[..cut].to_string();
            let line = line_of(&t, "Constraint.h.v=00000001");
            (
                t,
                format!(
                    "line {line}: file is truncated: the Constraint record \
                     Constraint.h.v=00000001 starting here has no AddConstraint line"
                ),
            )
        },
    ];
    for (text, want) in cases {
        let e = parse(&text).unwrap_err();
        assert_eq!(e.to_string(), want);
        assert_eq!(
            e.line(),
            want[5..want.find(':').unwrap()].parse::<usize>().unwrap()
        );
        // The message is whole: no source to print after it again.
        assert!(std::error::Error::source(&e).is_none(), "{e}");
        // And no decimal handles.
        assert!(!e.to_string().contains("1073741"), "{e}");
    }
}
