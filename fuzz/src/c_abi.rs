//! `c_abi`: arbitrary data decoded into a `Slvs_System` and passed to `Slvs_Solve`, as a C
//! program would (arrays it owns, counts that may be shorter than the arrays, negative, or
//! zero with a null pointer; a `failed` array of any room, or none).
//!
//! Asserted: no panic or abort (libFuzzer turns a panic caught inside `Slvs_Solve` into a
//! crash too, so `LOCI_SLVS_RESULT_INTERNAL_ERROR` is never seen), a known result code, no
//! write past `faileds` entries of `failed`, no parameter written unless the result says
//! values were written, and finite values when they are.

use arbitrary::{Arbitrary, Result, Unstructured};
use loci_slvs::abi::*;
use loci_slvs::Slvs_Solve;
use std::os::raw::c_int;

/// A handle: mostly small (so that references often resolve), sometimes zero or huge.
#[derive(Clone, Copy, Debug)]
pub struct Handle(pub u32);

impl<'a> Arbitrary<'a> for Handle {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let b = u8::arbitrary(u)?;
        Ok(Handle(match b {
            0..=239 => u32::from(b % 40),
            240..=247 => u32::from(b - 240) + 100,
            248 => u32::MAX,
            249 => 0x8000_0000,
            _ => u32::arbitrary(u)?,
        }))
    }
}

/// A group: 0 to 3 mostly.
#[derive(Clone, Copy, Debug)]
pub struct Group(pub u32);

impl<'a> Arbitrary<'a> for Group {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let b = u8::arbitrary(u)?;
        Ok(Group(if b < 250 {
            u32::from(b % 4)
        } else {
            u32::arbitrary(u)?
        }))
    }
}

/// A value: mostly small round numbers, sometimes any double (NaN, infinities, huge).
#[derive(Clone, Copy, Debug)]
pub struct Val(pub f64);

impl<'a> Arbitrary<'a> for Val {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let b = u8::arbitrary(u)?;
        Ok(Val(match b {
            0..=99 => f64::from(i8::arbitrary(u)?),
            100..=199 => f64::from(i16::arbitrary(u)?) / 256.0,
            200..=239 => f64::from(u8::arbitrary(u)?) / 255.0,
            240..=244 => 0.0,
            _ => f64::arbitrary(u)?,
        }))
    }
}

const ENTITY_TYPES: [c_int; 10] = [
    SLVS_E_POINT_IN_3D,
    SLVS_E_POINT_IN_2D,
    SLVS_E_NORMAL_IN_3D,
    SLVS_E_NORMAL_IN_2D,
    SLVS_E_DISTANCE,
    SLVS_E_WORKPLANE,
    SLVS_E_LINE_SEGMENT,
    SLVS_E_CUBIC,
    SLVS_E_CIRCLE,
    SLVS_E_ARC_OF_CIRCLE,
];

/// An entity type: one of the ten mostly, sometimes any number.
#[derive(Clone, Copy, Debug)]
pub struct EntityType(pub c_int);

impl<'a> Arbitrary<'a> for EntityType {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let b = u8::arbitrary(u)?;
        Ok(EntityType(if b < 250 {
            ENTITY_TYPES[usize::from(b) % ENTITY_TYPES.len()]
        } else {
            c_int::arbitrary(u)?
        }))
    }
}

/// A constraint type: one of the 38 mostly (100000..100037), sometimes any number.
#[derive(Clone, Copy, Debug)]
pub struct ConstraintType(pub c_int);

impl<'a> Arbitrary<'a> for ConstraintType {
    fn arbitrary(u: &mut Unstructured<'a>) -> Result<Self> {
        let b = u8::arbitrary(u)?;
        Ok(ConstraintType(if b < 250 {
            100_000 + c_int::from(b % 38)
        } else {
            c_int::arbitrary(u)?
        }))
    }
}

/// `Slvs_Param`.
#[derive(Clone, Copy, Debug, Arbitrary)]
pub struct P {
    h: Handle,
    group: Group,
    val: Val,
}

/// `Slvs_Entity`.
#[derive(Clone, Copy, Debug, Arbitrary)]
pub struct E {
    h: Handle,
    group: Group,
    ty: EntityType,
    wrkpl: Handle,
    point: [Handle; 4],
    normal: Handle,
    distance: Handle,
    param: [Handle; 4],
}

/// `Slvs_Constraint`.
#[derive(Clone, Copy, Debug, Arbitrary)]
pub struct C {
    h: Handle,
    group: Group,
    ty: ConstraintType,
    wrkpl: Handle,
    val: Val,
    pt_a: Handle,
    pt_b: Handle,
    entity: [Handle; 4],
    other: i8,
    other2: i8,
}

/// How the counts relate to the arrays.
#[derive(Clone, Copy, Debug, Arbitrary)]
pub enum Counts {
    /// Counts equal to the arrays' lengths.
    Exact,
    /// Counts at most the lengths (the rest of each array is not the caller's model).
    Shorter(u8, u8, u8),
    /// One count negative.
    Negative(u8, i8),
    /// Empty arrays passed as null pointers with zero counts.
    NullEmpty,
}

/// One call of `Slvs_Solve`.
#[derive(Clone, Debug, Arbitrary)]
pub struct Input {
    params: Vec<P>,
    entities: Vec<E>,
    constraints: Vec<C>,
    dragged: [Handle; 4],
    calculate_faileds: bool,
    group: Group,
    failed_room: u8,
    null_failed: bool,
    counts: Counts,
}

/// Most of each array that is used, so that one input stays fast.
const MAX_ITEMS: usize = 64;

/// Extra `failed` entries past the caller's room, which must stay untouched.
const GUARD: usize = 8;
const SENTINEL: u32 = 0xdead_beef;

impl Input {
    /// The C arrays.
    pub fn arrays(&self) -> (Vec<Slvs_Param>, Vec<Slvs_Entity>, Vec<Slvs_Constraint>) {
        let params = self
            .params
            .iter()
            .take(MAX_ITEMS)
            .map(|p| Slvs_Param {
                h: p.h.0,
                group: p.group.0,
                val: p.val.0,
            })
            .collect();
        let entities = self
            .entities
            .iter()
            .take(MAX_ITEMS)
            .map(|e| Slvs_Entity {
                h: e.h.0,
                group: e.group.0,
                r#type: e.ty.0,
                wrkpl: e.wrkpl.0,
                point: e.point.map(|h| h.0),
                normal: e.normal.0,
                distance: e.distance.0,
                param: e.param.map(|h| h.0),
            })
            .collect();
        let constraints = self
            .constraints
            .iter()
            .take(MAX_ITEMS)
            .map(|c| Slvs_Constraint {
                h: c.h.0,
                group: c.group.0,
                r#type: c.ty.0,
                wrkpl: c.wrkpl.0,
                valA: c.val.0,
                ptA: c.pt_a.0,
                ptB: c.pt_b.0,
                entityA: c.entity[0].0,
                entityB: c.entity[1].0,
                entityC: c.entity[2].0,
                entityD: c.entity[3].0,
                other: c_int::from(c.other),
                other2: c_int::from(c.other2),
            })
            .collect();
        (params, entities, constraints)
    }

    /// The group solved.
    pub fn group(&self) -> u32 {
        self.group.0
    }

    /// The dragged handles.
    pub fn dragged(&self) -> [u32; 4] {
        self.dragged.map(|h| h.0)
    }
}

fn count(len: usize, limit: Option<u8>) -> c_int {
    let n = limit.map_or(len, |l| len.min(usize::from(l)));
    c_int::try_from(n).expect("small")
}

fn ptr_or_null<T>(v: &mut [T], null: bool) -> *mut T {
    if null && v.is_empty() {
        std::ptr::null_mut()
    } else {
        v.as_mut_ptr()
    }
}

/// Runs one input; panics on a finding.
pub fn run(input: &Input) {
    let (mut params, mut entities, mut constraints) = input.arrays();
    let (mut np, mut ne, mut nc) = (
        count(params.len(), None),
        count(entities.len(), None),
        count(constraints.len(), None),
    );
    let null = matches!(input.counts, Counts::NullEmpty);
    match input.counts {
        Counts::Exact | Counts::NullEmpty => {}
        Counts::Shorter(a, b, c) => {
            np = count(params.len(), Some(a));
            ne = count(entities.len(), Some(b));
            nc = count(constraints.len(), Some(c));
        }
        Counts::Negative(which, v) => {
            let v = -c_int::from(v).abs() - 1;
            match which % 3 {
                0 => np = v,
                1 => ne = v,
                _ => nc = v,
            }
        }
    }
    let room = usize::from(input.failed_room % 16);
    let mut failed = vec![SENTINEL; room + GUARD];
    let before = params.clone();
    let mut sys = Slvs_System {
        param: ptr_or_null(&mut params, null),
        params: np,
        entity: ptr_or_null(&mut entities, null),
        entities: ne,
        constraint: ptr_or_null(&mut constraints, null),
        constraints: nc,
        dragged: input.dragged(),
        calculateFaileds: c_int::from(input.calculate_faileds),
        failed: if input.null_failed {
            std::ptr::null_mut()
        } else {
            failed.as_mut_ptr()
        },
        faileds: c_int::try_from(room).expect("small"),
        dof: -99,
        result: -99,
    };
    // SAFETY: every array pointer is null with a zero count, or points into a live Vec at
    // least as long as its count; `failed` has at least `faileds` entries (or is null).
    unsafe { Slvs_Solve(&mut sys, input.group()) };

    let result = sys.result;
    assert!(
        matches!(
            result,
            SLVS_RESULT_OKAY
                | SLVS_RESULT_INCONSISTENT
                | SLVS_RESULT_DIDNT_CONVERGE
                | LOCI_SLVS_RESULT_INVALID_INPUT
        ),
        "Slvs_Solve returned result {result} ({})",
        last_error()
    );
    assert!(sys.dof >= -1, "dof {}", sys.dof);
    assert!(
        failed[room..].iter().all(|&h| h == SENTINEL),
        "failed[] written past its {room} entries"
    );
    if !input.null_failed {
        assert!(sys.faileds >= 0, "faileds {}", sys.faileds);
    }
    let written = params
        .iter()
        .zip(&before)
        .any(|(a, b)| a.val.to_bits() != b.val.to_bits());
    match result {
        SLVS_RESULT_OKAY => {
            for p in &params[..usize::try_from(np).unwrap_or(0)] {
                assert!(
                    p.val.is_finite() || p.group != input.group(),
                    "param {} = {} after an okay solve",
                    p.h,
                    p.val
                );
            }
        }
        SLVS_RESULT_INCONSISTENT => {}
        _ => assert!(!written, "result {result} but parameters were written"),
    }
    // Nothing past the caller's count is touched.
    let np = usize::try_from(np).unwrap_or(0);
    for (a, b) in params.iter().zip(&before).skip(np) {
        assert!(
            a.val.to_bits() == b.val.to_bits(),
            "param {} past the count was written",
            a.h
        );
    }
}

fn last_error() -> String {
    let mut buf = vec![0 as std::os::raw::c_char; 512];
    // SAFETY: `buf` is 512 bytes long.
    let _ = unsafe { loci_slvs::Loci_Slvs_LastError(buf.as_mut_ptr(), 512) };
    buf.iter()
        .take_while(|&&c| c != 0)
        .map(|&c| c as u8 as char)
        .collect()
}
