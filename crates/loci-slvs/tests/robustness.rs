//! Bad input through the C entry point: typed result codes, never a crash, nothing written.

use loci_slvs::abi::*;
use loci_slvs::Slvs_Solve;
use std::ptr;

fn param(h: u32, group: u32, val: f64) -> Slvs_Param {
    Slvs_Param { h, group, val }
}

fn point2(h: u32, wp: u32, u: u32, v: u32) -> Slvs_Entity {
    Slvs_Entity {
        h,
        group: 2,
        r#type: SLVS_E_POINT_IN_2D,
        wrkpl: wp,
        point: [0; 4],
        normal: 0,
        distance: 0,
        param: [u, v, 0, 0],
    }
}

fn constraint(h: u32, ty: i32, wp: u32, val: f64, a: u32, b: u32) -> Slvs_Constraint {
    Slvs_Constraint {
        h,
        group: 2,
        r#type: ty,
        wrkpl: wp,
        valA: val,
        ptA: a,
        ptB: b,
        entityA: 0,
        entityB: 0,
        entityC: 0,
        entityD: 0,
        other: 0,
        other2: 0,
    }
}

/// The xy plane in group 1 and two points in it in group 2 (params 11..14).
struct Model {
    params: Vec<Slvs_Param>,
    entities: Vec<Slvs_Entity>,
    constraints: Vec<Slvs_Constraint>,
    failed: Vec<u32>,
}

impl Model {
    fn new() -> Self {
        let mut params: Vec<_> = (1..=7)
            .map(|h| param(h, 1, if h == 4 { 1.0 } else { 0.0 }))
            .collect();
        params.extend([
            param(11, 2, 0.0),
            param(12, 2, 0.0),
            param(13, 2, 9.0),
            param(14, 2, 1.0),
        ]);
        let blank = |h, ty| Slvs_Entity {
            h,
            group: 1,
            r#type: ty,
            wrkpl: 0,
            point: [0; 4],
            normal: 0,
            distance: 0,
            param: [0; 4],
        };
        let mut origin = blank(101, SLVS_E_POINT_IN_3D);
        origin.param = [1, 2, 3, 0];
        let mut normal = blank(102, SLVS_E_NORMAL_IN_3D);
        normal.param = [4, 5, 6, 7];
        let mut wp = blank(200, SLVS_E_WORKPLANE);
        wp.point[0] = 101;
        wp.normal = 102;
        let entities = vec![
            origin,
            normal,
            wp,
            point2(301, 200, 11, 12),
            point2(302, 200, 13, 14),
        ];
        let constraints = vec![constraint(1, 100_001, 200, 10.0, 301, 302)];
        Model {
            params,
            entities,
            constraints,
            failed: vec![0; 8],
        }
    }

    fn system(&mut self) -> Slvs_System {
        Slvs_System {
            param: self.params.as_mut_ptr(),
            params: self.params.len() as i32,
            entity: self.entities.as_mut_ptr(),
            entities: self.entities.len() as i32,
            constraint: self.constraints.as_mut_ptr(),
            constraints: self.constraints.len() as i32,
            dragged: [0; 4],
            calculateFaileds: 1,
            failed: self.failed.as_mut_ptr(),
            faileds: self.failed.len() as i32,
            dof: -99,
            result: -99,
        }
    }
}

fn solve(sys: &mut Slvs_System) {
    // SAFETY: every pointer in `sys` comes from a live Vec of the stated length.
    unsafe { Slvs_Solve(sys, 2) };
}

fn last_error() -> String {
    let mut buf = vec![0i8; 256];
    // SAFETY: `buf` is 256 bytes long.
    let n = unsafe { loci_slvs::Loci_Slvs_LastError(buf.as_mut_ptr(), 256) };
    let bytes: Vec<u8> = buf
        .iter()
        .take_while(|&&c| c != 0)
        .map(|&c| c as u8)
        .collect();
    assert_eq!(n as usize, bytes.len());
    String::from_utf8(bytes).unwrap()
}

#[test]
fn a_good_model_solves_and_clears_the_error() {
    let mut m = Model::new();
    let mut s = m.system();
    solve(&mut s);
    assert_eq!((s.result, s.dof, s.faileds), (SLVS_RESULT_OKAY, 3, 0));
    let d = ((m.params[9].val - m.params[7].val).powi(2)
        + (m.params[10].val - m.params[8].val).powi(2))
    .sqrt();
    assert!((d - 10.0).abs() < 1e-9, "distance {d}");
    assert_eq!(last_error(), "");
}

#[test]
fn null_array_with_a_count_is_invalid_input() {
    let mut m = Model::new();
    let mut s = m.system();
    s.constraint = ptr::null_mut();
    solve(&mut s);
    assert_eq!(
        (s.result, s.dof, s.faileds),
        (LOCI_SLVS_RESULT_INVALID_INPUT, -1, 0)
    );
    assert_eq!(last_error(), "sys->constraint is null but its count is 1");
    assert_eq!(m.params[9].val, 9.0, "nothing written");
}

#[test]
fn negative_count_is_invalid_input() {
    let mut m = Model::new();
    let mut s = m.system();
    s.entities = -3;
    solve(&mut s);
    assert_eq!(s.result, LOCI_SLVS_RESULT_INVALID_INPUT);
    assert!(last_error().contains("entities is -3"), "{}", last_error());
}

#[test]
fn dangling_handle_names_the_constraint() {
    let mut m = Model::new();
    m.constraints[0].ptB = 999;
    let mut s = m.system();
    solve(&mut s);
    assert_eq!((s.result, s.faileds), (LOCI_SLVS_RESULT_INVALID_INPUT, 1));
    assert_eq!(m.failed[0], 1);
    assert!(last_error().contains("entity 999"), "{}", last_error());
}

#[test]
fn nan_value_and_unknown_types_are_invalid_input() {
    let mut m = Model::new();
    m.constraints[0].valA = f64::NAN;
    let mut s = m.system();
    solve(&mut s);
    assert_eq!((s.result, m.failed[0]), (LOCI_SLVS_RESULT_INVALID_INPUT, 1));

    let mut m = Model::new();
    m.params[8].val = f64::INFINITY;
    let mut s = m.system();
    solve(&mut s);
    assert_eq!((s.result, s.faileds), (LOCI_SLVS_RESULT_INVALID_INPUT, 0));
    assert!(last_error().contains("param 12"), "{}", last_error());

    let mut m = Model::new();
    m.constraints[0].r#type = 123;
    let mut s = m.system();
    solve(&mut s);
    assert_eq!((s.result, m.failed[0]), (LOCI_SLVS_RESULT_INVALID_INPUT, 1));

    let mut m = Model::new();
    m.entities[3].r#type = 7;
    let mut s = m.system();
    solve(&mut s);
    assert_eq!(s.result, LOCI_SLVS_RESULT_INVALID_INPUT);
    assert!(
        last_error().contains("entity 301: type 7"),
        "{}",
        last_error()
    );
}

#[test]
fn two_d_only_constraint_without_workplane_names_it() {
    let mut m = Model::new();
    m.constraints.push(constraint(2, 100_019, 0, 0.0, 301, 302));
    let mut s = m.system();
    solve(&mut s);
    assert_eq!(
        (s.result, s.faileds, m.failed[0]),
        (LOCI_SLVS_RESULT_INVALID_INPUT, 1, 2)
    );
}

#[test]
fn null_system_and_null_failed_are_harmless() {
    // SAFETY: a null system is allowed and ignored.
    unsafe { Slvs_Solve(ptr::null_mut(), 2) };
    assert!(last_error().contains("null"));
    let mut m = Model::new();
    let mut s = m.system();
    s.failed = ptr::null_mut();
    s.faileds = 5;
    m.constraints
        .push(constraint(2, 100_001, 200, 20.0, 301, 302));
    let mut s2 = m.system();
    s2.failed = ptr::null_mut();
    s2.faileds = 5;
    solve(&mut s2);
    assert_eq!(s2.result, SLVS_RESULT_INCONSISTENT);
    assert_eq!(s2.faileds, 5, "left alone without an array");
    let _ = s;
}

#[test]
fn short_failed_array_is_not_overrun() {
    let mut m = Model::new();
    m.constraints
        .push(constraint(2, 100_001, 200, 20.0, 301, 302));
    m.failed = vec![0; 1];
    let mut s = m.system();
    solve(&mut s);
    assert_eq!((s.result, s.faileds), (SLVS_RESULT_INCONSISTENT, 2));
    assert_eq!(m.failed, vec![1]);
}

#[test]
fn redundant_but_solved_writes_values_and_reports_inconsistent() {
    let mut m = Model::new();
    m.constraints
        .push(constraint(2, 100_001, 200, 10.0, 302, 301));
    let mut s = m.system();
    solve(&mut s);
    assert_eq!(
        (s.result, s.dof, s.faileds),
        (SLVS_RESULT_INCONSISTENT, 3, 2)
    );
    assert_eq!(&m.failed[..2], &[1, 2]);
    let d = ((m.params[9].val - m.params[7].val).powi(2)
        + (m.params[10].val - m.params[8].val).powi(2))
    .sqrt();
    assert!((d - 10.0).abs() < 1e-9, "solved values written: {d}");
    // Without calculateFaileds the redundant ones are not named, as libslvs does.
    let mut m = Model::new();
    m.constraints
        .push(constraint(2, 100_001, 200, 10.0, 302, 301));
    let mut s = m.system();
    s.calculateFaileds = 0;
    solve(&mut s);
    assert_eq!((s.result, s.faileds), (SLVS_RESULT_INCONSISTENT, 0));
}
