//! Carried entities read as expressions of their pose (see `equations::carried`): the same
//! solutions, degrees of freedom and failed lists as a solve that keeps their own unknowns
//! and implicit equations, derivatives that are those of the composition, and own parameters
//! written back onto their implicit conditions.

use super::super::carried::{without, Carried};
use super::super::compile::{compile_group, resolve_constraint};
use super::super::refs::Resolver;
use super::super::{Equation, Owner, Rows};
use crate::assembly::Selection;
use crate::assembly::{Assembly, AssemblyReport, Component, Mate, MateKind, Pose, Reference};
use crate::diagnose::Member;
use crate::model::{
    Constraint, ConstraintKind as K, Entity, EntityId, GroupId, Param, ParamId, System,
};
use crate::solve::{solve, Config, Outcome, Report, Solver};
use std::collections::HashMap;

const MOVING: u32 = 2;
const POSE: u32 = 200;
/// The moved points (bases at the origin, (1, 0, 0) and (0, 1, 0.5)), the turned normal and
/// the translated point of [`linked`].
const AT_ORIGIN: u32 = 201;
const AT_X: u32 = 202;
const AT_Y: u32 = 203;
const TURNED: u32 = 204;
const SHIFTED: u32 = 205;
/// Constants: points at (5, 0, 0) and (5, 1, 0), a normal turned a quarter turn about z,
/// the translated point's base.
const A: u32 = 100;
const B: u32 = 101;
const N: u32 = 102;
const BASE: u32 = 103;

fn axis_angle(axis: [f64; 3], angle: f64) -> [f64; 4] {
    let n = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let (s, c) = (angle / 2.0).sin_cos();
    [c, s * axis[0] / n, s * axis[1] / n, s * axis[2] / n]
}

/// A part in group 2 placed by a translation and the rotation normal [`POSE`], starting
/// away from every case's answer, carrying three points, a normal and (by its own
/// translation) a copy of a constant point; each copy's own parameters start where its
/// carrier puts it.
fn linked() -> System {
    let mut sys = System::new();
    let mut next = 1u32;
    let mut param = |sys: &mut System, g: u32, v: f64| {
        let h = next;
        next += 1;
        sys.add_param(Param::new(h, g, v)).unwrap();
        h
    };
    let quarter = axis_angle([0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2);
    let p = [5.0, 0.0, 0.0].map(|v| param(&mut sys, 1, v));
    sys.add_entity(Entity::point_3d(A, 1, p)).unwrap();
    let p = [5.0, 1.0, 0.0].map(|v| param(&mut sys, 1, v));
    sys.add_entity(Entity::point_3d(B, 1, p)).unwrap();
    let p = quarter.map(|v| param(&mut sys, 1, v));
    sys.add_entity(Entity::normal_3d(N, 1, p)).unwrap();
    let p = [1.0, 2.0, 3.0].map(|v| param(&mut sys, 1, v));
    sys.add_entity(Entity::point_3d(BASE, 1, p)).unwrap();

    let t = [0.3, -0.2, 0.1].map(|v| param(&mut sys, MOVING, v));
    let q = axis_angle([0.2, -0.3, 1.0], 0.4).map(|v| param(&mut sys, MOVING, v));
    sys.add_entity(Entity::normal_3d(POSE, MOVING, q)).unwrap();
    for (h, base) in [
        (AT_ORIGIN, [0.0; 3]),
        (AT_X, [1.0, 0.0, 0.0]),
        (AT_Y, [0.0, 1.0, 0.5]),
    ] {
        let own = [0.0; 3].map(|v| param(&mut sys, MOVING, v));
        sys.add_entity(Entity::point_n_rot_trans(h, MOVING, own, base, t, POSE))
            .unwrap();
    }
    let own = [1.0, 0.0, 0.0, 0.0].map(|v| param(&mut sys, MOVING, v));
    let base = axis_angle([1.0, 0.0, 0.0], 0.3);
    sys.add_entity(Entity::normal_n_rot(TURNED, MOVING, own, base, POSE))
        .unwrap();
    let shift = [0.5, -0.5, 0.2].map(|v| param(&mut sys, MOVING, v));
    let own = [0.0; 3].map(|v| param(&mut sys, MOVING, v));
    sys.add_entity(Entity::point_n_trans(SHIFTED, MOVING, own, BASE, shift, 2))
        .unwrap();
    // Own parameters where the carriers put them.
    let mut values: Vec<f64> = sys.params().iter().map(|p| p.val).collect();
    let carried = Carried::of(&sys, GroupId(MOVING), &[]);
    assert_eq!(carried.entities().len(), 5, "every copy is carried");
    carried.write_back(&sys, &mut values);
    let hs: Vec<ParamId> = sys.params().iter().map(|p| p.h).collect();
    for (h, v) in hs.into_iter().zip(values) {
        sys.set_value(h, v);
    }
    sys
}

/// The cases: what each shows, and the constraints added to [`linked`].
fn cases() -> Vec<(&'static str, Vec<Constraint>)> {
    let c = |h: u32, k: K| Constraint::new(h, MOVING, k);
    vec![
        (
            "two points on two targets: one rotation left, one equation redundant",
            vec![
                c(1, K::PointsCoincident).with_points(AT_ORIGIN, A),
                c(2, K::PointsCoincident).with_points(AT_X, B),
            ],
        ),
        (
            "a point and an axis: placed up to a turn about it",
            vec![
                c(1, K::PointsCoincident).with_points(AT_ORIGIN, A),
                c(2, K::Parallel).with_entities([TURNED, N, 0, 0]),
            ],
        ),
        (
            "placed fully, the copy of a constant point on a target",
            vec![
                c(1, K::PointsCoincident).with_points(AT_ORIGIN, A),
                c(2, K::Parallel).with_entities([TURNED, N, 0, 0]),
                c(3, K::PtPlaneDistance)
                    .with_points(AT_Y, 0)
                    .with_entities([0, 0, 0, 0])
                    .with_val(4.5),
                c(4, K::PointsCoincident).with_points(SHIFTED, B),
            ],
        ),
        (
            "two points of a rigid part on one target: inconsistent",
            vec![
                c(1, K::PointsCoincident).with_points(AT_ORIGIN, A),
                c(2, K::PointsCoincident).with_points(AT_X, A),
            ],
        ),
        (
            "a line through two carried points held on a constant point",
            vec![
                c(1, K::PtOnLine)
                    .with_points(A, 0)
                    .with_entities([300, 0, 0, 0]),
                c(2, K::ProjPtDistance)
                    .with_points(AT_ORIGIN, B)
                    .with_entities([TURNED, 0, 0, 0])
                    .with_val(0.25),
                c(3, K::PtPtDistance)
                    .with_points(SHIFTED, AT_Y)
                    .with_val(4.0),
            ],
        ),
    ]
}

/// [`linked`] with the constraints of a case, and a line between two carried points; a
/// plane distance is taken from the constant plane x = 0 (a workplane of group 1 built
/// here).
fn system(constraints: &[Constraint]) -> System {
    let mut sys = linked();
    sys.add_entity(Entity::line(300, MOVING, None, AT_ORIGIN, AT_X))
        .unwrap();
    // The plane x = 0: its normal is z turned a quarter turn about y.
    let o = [0.0; 3].map(|v| {
        let h = 900 + sys.params().len() as u32;
        sys.add_param(Param::new(h, 1, v)).unwrap();
        h
    });
    sys.add_entity(Entity::point_3d(400, 1, o)).unwrap();
    let q = axis_angle([0.0, 1.0, 0.0], std::f64::consts::FRAC_PI_2).map(|v| {
        let h = 900 + sys.params().len() as u32;
        sys.add_param(Param::new(h, 1, v)).unwrap();
        h
    });
    sys.add_entity(Entity::normal_3d(401, 1, q)).unwrap();
    sys.add_entity(Entity::workplane(402, 1, 400, 401)).unwrap();
    for c in constraints {
        let mut c = c.clone();
        if c.kind == K::PtPlaneDistance {
            c.entity_a = Some(EntityId(402));
        }
        sys.add_constraint(c).unwrap();
    }
    sys
}

fn values(sys: &System) -> Vec<f64> {
    sys.params().iter().map(|p| p.val).collect()
}

/// The largest residual of every implicit condition of the carried entities at `sys`'s
/// values, evaluated as the equations a solve without expressions has.
fn worst_condition(sys: &System) -> f64 {
    let v = values(sys);
    let compiled = without(|| compile_group(sys, GroupId(MOVING), &[], true, &v, &v)).unwrap();
    let carried = [AT_ORIGIN, AT_X, AT_Y, TURNED, SHIFTED].map(EntityId);
    let mut worst = 0.0f64;
    let mut n = 0;
    for k in &compiled.kernels {
        if let Owner::Entity(e) = k.owner {
            if carried.contains(&e) {
                n += 1;
                let mut x = Vec::new();
                k.gather(&v, &mut x);
                let mut out = Rows::new();
                k.eq.eval(&x, &mut out);
                for r in &out.v[..out.n] {
                    worst = worst.max(r.abs());
                }
            }
        }
    }
    assert_eq!(n, carried.len(), "every condition evaluated");
    worst
}

fn check_same(what: &str, new: &Report, old: &Report, a: &System, b: &System) {
    assert_eq!(new.outcome, old.outcome, "{what}: {new:?} vs {old:?}");
    assert_eq!(new.dof, old.dof, "{what}");
    if !new.outcome.is_ok() {
        // A failure is named by the solve without expressions, as before.
        assert_eq!(new, old, "{what}");
        assert_eq!(
            values(a),
            values(b),
            "{what}: a failed solve leaves every parameter"
        );
        return;
    }
    // DOF unchanged: as many unknowns gone as equations.
    assert_eq!(
        old.unknowns - new.unknowns,
        old.equations - new.equations,
        "{what}"
    );
    assert!(new.unknowns < old.unknowns, "{what}: fewer unknowns");
    assert!(
        worst_condition(a) <= 1e-12,
        "{what}: conditions written back"
    );
    if new.outcome == Outcome::RedundantOkay {
        // The implicit conditions of carried entities always hold and are never named; what
        // is named is redundant by the diagnosis (which reads them as before).
        let d = crate::diagnose::diagnose(b, GroupId(MOVING), &Config::default()).unwrap();
        let members: Vec<Member> = d
            .redundant
            .iter()
            .flat_map(|r| r.members.iter().chain(&r.involved).copied())
            .collect();
        let carried = [AT_ORIGIN, AT_X, AT_Y, TURNED, SHIFTED].map(EntityId);
        let named = !new.failed.is_empty() || !new.failed_entities.is_empty();
        assert_eq!(
            named,
            !old.failed.is_empty() || !old.failed_entities.is_empty(),
            "{what}: names only when asked to find them"
        );
        for c in &new.failed {
            assert!(
                members.contains(&Member::Constraint(*c)),
                "{what}: {c:?} in {d:?}"
            );
        }
        for e in &new.failed_entities {
            assert!(!carried.contains(e), "{what}");
            assert!(
                members.contains(&Member::Entity(*e)),
                "{what}: {e:?} in {d:?}"
            );
        }
    } else {
        assert_eq!(
            (&new.failed, &new.failed_entities),
            (&old.failed, &old.failed_entities)
        );
    }
    if new.dof == 0 {
        for (p, q) in a.params().iter().zip(b.params()) {
            assert!(
                (p.val - q.val).abs() <= 1e-8,
                "{what}: param {} {} vs {}",
                p.h.0,
                p.val,
                q.val
            );
        }
    }
}

#[test]
fn linked_part_solves_as_with_own_unknowns() {
    let mut seen_dof0 = false;
    let mut seen = Vec::new();
    for (what, cs) in cases() {
        let (mut a, mut b) = (system(&cs), system(&cs));
        let cfg = Config::default();
        let new = solve(&mut a, GroupId(MOVING), &[], &cfg).unwrap();
        let old = without(|| solve(&mut b, GroupId(MOVING), &[], &cfg)).unwrap();
        check_same(what, &new, &old, &a, &b);
        seen_dof0 |= new.outcome.is_ok() && new.dof == 0;
        seen.push(new.outcome);
        // And with the diagnosis of every failed constraint off.
        let cfg = Config::default().with_find_failed(false);
        let (mut a, mut b) = (system(&cs), system(&cs));
        let new = solve(&mut a, GroupId(MOVING), &[], &cfg).unwrap();
        let old = without(|| solve(&mut b, GroupId(MOVING), &[], &cfg)).unwrap();
        check_same(what, &new, &old, &a, &b);
    }
    assert!(seen_dof0, "a case with a unique answer");
    for o in [Outcome::Okay, Outcome::RedundantOkay, Outcome::Inconsistent] {
        assert!(seen.contains(&o), "a case ending {o}: {seen:?}");
    }
}

#[test]
fn a_dragged_carried_point_keeps_its_unknowns() {
    let cs = [Constraint::new(1, MOVING, K::PtPtDistance)
        .with_points(AT_X, A)
        .with_val(1.0)];
    let mut sys = system(&cs);
    let own = match &sys.entity(EntityId(AT_X)).unwrap().kind {
        crate::EntityKind::PointNRotTrans { params, .. } => *params,
        _ => unreachable!(),
    };
    // Dragged, it moves least, so it is no expression.
    assert_eq!(Carried::of(&sys, GroupId(MOVING), &own).entities().len(), 4);
    let before = own.map(|p| sys.value(p).unwrap());
    let mut old = sys.clone();
    let cfg = Config::default();
    let new = solve(&mut sys, GroupId(MOVING), &own, &cfg).unwrap();
    let old_r = without(|| solve(&mut old, GroupId(MOVING), &own, &cfg)).unwrap();
    assert!(new.outcome.is_ok(), "{new:?}");
    assert_eq!((new.outcome, new.dof), (old_r.outcome, old_r.dof));
    assert!(worst_condition(&sys) <= 1e-12);
    // The distance holds, as the point's own coordinates read it.
    let p = own.map(|h| sys.value(h).unwrap());
    let d = ((p[0] - 5.0).powi(2) + p[1].powi(2) + p[2].powi(2)).sqrt();
    assert!((d - 1.0).abs() < 1e-9, "{d}");
    assert_ne!(p, before, "the point moved to its target");
}

/// The Jacobian of `eq` with respect to its locals, by dual numbers.
fn jacobian(eq: &Equation, x: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let rows = eq.rows(x);
    let (mut r, mut j) = (vec![0.0; rows], vec![0.0; rows * x.len()]);
    eq.jacobian(x, &mut r, &mut j);
    (r, j)
}

/// Entries equal to rounding (relative to 1 + the entry).
fn assert_close_all(got: &[f64], want: &[f64], what: &str) {
    assert_eq!(got.len(), want.len(), "{what}");
    for (a, b) in got.iter().zip(want) {
        assert!(
            (a - b).abs() <= 1e-12 * (1.0 + b.abs()),
            "{what}: {got:?} vs {want:?}"
        );
    }
}

#[test]
fn derivatives_through_the_carrier_are_those_of_the_composition() {
    let v0 = values(&linked());
    for (what, cs) in cases() {
        let sys = system(&cs);
        let v = values(&sys);
        assert_eq!(v.len(), v0.len() + 7, "{what}");
        let carried = Carried::of(&sys, GroupId(MOVING), &[]);
        let implicit = without(|| compile_group(&sys, GroupId(MOVING), &[], true, &v, &v)).unwrap();
        // d own / d carrier, from each condition `own - f(carrier) = 0`, by parameter.
        let mut d_own: HashMap<usize, Vec<(usize, f64)>> = HashMap::new();
        for k in &implicit.kernels {
            let Owner::Entity(e) = k.owner else { continue };
            let i = sys.entity_index(e).unwrap();
            if !carried.entity(i) {
                continue;
            }
            let own: Vec<usize> = sys.entities()[i]
                .kind
                .params()
                .iter()
                .map(|p| sys.param_index(*p).unwrap())
                .collect();
            let x: Vec<f64> = k.locals.iter().map(|&p| v[p as usize]).collect();
            let (_, j) = jacobian(&k.eq, &x);
            for (row, &o) in own.iter().enumerate() {
                let entry = d_own.entry(o).or_default();
                for (s, &p) in k.locals.iter().enumerate() {
                    if !own.contains(&(p as usize)) {
                        entry.push((p as usize, -j[row * x.len() + s]));
                    }
                }
            }
        }
        for c in sys.constraints() {
            let (old, lo) = resolve_constraint(&Resolver::new(&sys), c).unwrap();
            let (mut new, ln) = resolve_constraint(&Resolver::carrying(&sys, &carried), c).unwrap();
            let xo: Vec<f64> = lo.params.iter().map(|&p| v[p as usize]).collect();
            let xn: Vec<f64> = ln.params.iter().map(|&p| v[p as usize]).collect();
            let mut old = old;
            old.choose(&xo);
            new.choose(&xn);
            let (ro, jo) = jacobian(&old, &xo);
            let (rn, jn) = jacobian(&new, &xn);
            assert_eq!(ro.len(), rn.len(), "{what}: constraint {}", c.h.0);
            for (a, b) in rn.iter().zip(&ro) {
                assert!((a - b).abs() <= 1e-12, "{what}: residual {a} vs {b}");
            }
            // The chain rule on the old locals, by parameter.
            let mut want: HashMap<(usize, usize), f64> = HashMap::new();
            for r in 0..ro.len() {
                for (s, &p) in lo.params.iter().enumerate() {
                    let d = jo[r * xo.len() + s];
                    let p = p as usize;
                    match d_own.get(&p) {
                        Some(through) => {
                            for &(q, dq) in through {
                                *want.entry((r, q)).or_default() += d * dq;
                            }
                        }
                        None => *want.entry((r, p)).or_default() += d,
                    }
                }
            }
            for r in 0..rn.len() {
                for (s, &p) in ln.params.iter().enumerate() {
                    let got = jn[r * xn.len() + s];
                    let w = want.get(&(r, p as usize)).copied().unwrap_or(0.0);
                    assert!(
                        (got - w).abs() <= 1e-12 * (1.0 + w.abs()),
                        "{what}: constraint {} row {r} param {p}: {got} vs {w}",
                        c.h.0
                    );
                }
            }
            // The written-out forms, where a kind has one, agree with the dual numbers to
            // rounding.
            let active: Vec<u16> = (0..xn.len() as u16).collect();
            let (mut rf, mut jf) = (vec![0.0; rn.len()], vec![0.0; jn.len()]);
            new.jacobian_active(&xn, &active, &mut rf, &mut jf);
            assert_close_all(&rf, &rn, what);
            assert_close_all(&jf, &jn, what);
            // And central differences.
            let h = 1e-6;
            for s in 0..xn.len() {
                let mut xp = xn.clone();
                let mut xm = xn.clone();
                xp[s] += h;
                xm[s] -= h;
                let (mut op, mut om) = (Rows::new(), Rows::new());
                new.eval(&xp, &mut op);
                new.eval(&xm, &mut om);
                for r in 0..op.n {
                    let fd = (op.v[r] - om.v[r]) / (2.0 * h);
                    let got = jn[r * xn.len() + s];
                    assert!((fd - got).abs() <= 1e-6 * (1.0 + got.abs()), "{what}");
                }
            }
        }
    }
}

#[test]
fn the_solver_cache_follows_structural_edits() {
    let cs = &cases()[2].1;
    let mut sys = system(cs);
    let mut solver = Solver::new(MOVING, &[], Config::default());
    let first = solver.solve(&mut sys).unwrap();
    assert_eq!((first.outcome, first.dof), (Outcome::Okay, 0));
    assert!(worst_condition(&sys) <= 1e-12);
    // A value edit: the cached structure, carried entities included, is reused.
    sys.set_value(ParamId(1), 5.5);
    let again = solver.solve(&mut sys).unwrap();
    assert_eq!(again.outcome, Outcome::Okay);
    assert!(worst_condition(&sys) <= 1e-12);
    assert!((sys.value(ParamId(1)).unwrap() - 5.5).abs() < 1e-15);
    let at = |s: &System, e: u32| match &s.entity(EntityId(e)).unwrap().kind {
        crate::EntityKind::PointNRotTrans { params, .. } => params.map(|p| s.value(p).unwrap()),
        _ => unreachable!(),
    };
    assert!(
        (at(&sys, AT_ORIGIN)[0] - 5.5).abs() < 1e-9,
        "follows the target"
    );
    // A structural edit: a workplane on a carried point makes it an unknown again.
    let o = at(&sys, AT_ORIGIN);
    let before = values(&sys);
    sys.add_entity(Entity::workplane(500, MOVING, AT_ORIGIN, POSE))
        .unwrap();
    assert_eq!(Carried::of(&sys, GroupId(MOVING), &[]).entities().len(), 4);
    let mut other = sys.clone();
    let cached = solver.solve(&mut sys).unwrap();
    let fresh = solve(&mut other, GroupId(MOVING), &[], &Config::default()).unwrap();
    assert_eq!(cached, fresh);
    assert_eq!(values(&sys), values(&other));
    assert_eq!((cached.outcome, cached.dof), (Outcome::Okay, 0));
    assert_eq!(values(&sys).len(), before.len());
    for (a, b) in at(&sys, AT_ORIGIN).iter().zip(o) {
        assert!((a - b).abs() < 1e-9);
    }
    assert!(worst_condition(&sys) <= 1e-12);
}

/// A mate added to [`chain`]: its kind, and the link and reference on each side.
type Extra<'a> = (MateKind, (usize, &'a str), (usize, &'a str));

/// A revolute chain of `n` links (link 0 grounded), each moved off its answer, with
/// `extra` mates added.
fn chain(n: usize, extra: &[Extra<'_>]) -> Assembly {
    let mut asm = Assembly::new();
    let mut at = [0.0f64; 3];
    for i in 0..n {
        let answer = Pose::from_axis_angle(at, [0.0, 0.0, 1.0], 30.0 * i as f64);
        let tip = answer.point([1.0, 0.0, 0.0]);
        let mut c = Component::new(format!("link{i}"), answer)
            .with("pivot", Reference::Vertex { point: [0.0; 3] })
            .with(
                "tip",
                Reference::Vertex {
                    point: [1.0, 0.0, 0.0],
                },
            )
            .with(
                "hinge",
                Reference::Axis {
                    point: [0.0; 3],
                    direction: [0.0, 0.0, 1.0],
                },
            )
            .with(
                "arm",
                Reference::Edge {
                    point: [0.0; 3],
                    direction: [1.0, 0.0, 0.0],
                },
            );
        if i == 0 {
            c.grounded = true;
        } else {
            // Off its answer: moved, and turned a few degrees about another axis.
            let k = i as f64;
            c.pose = Pose::from_axis_angle(
                [at[0] + 0.1 * k.sin(), at[1] - 0.2, at[2] + 0.05 * k],
                [0.05 * k, -0.04, 1.0],
                30.0 * k + 4.0,
            );
        }
        asm.add_component(c).unwrap();
        at = tip;
    }
    let s = |i: usize, r: &str| Selection::on(&format!("link{i}"), r);
    for i in 1..n {
        asm.add_mate(Mate::new(
            MateKind::Coincident,
            s(i - 1, "tip"),
            s(i, "pivot"),
        ))
        .unwrap();
        asm.add_mate(Mate::new(
            MateKind::Parallel,
            s(i - 1, "hinge"),
            s(i, "hinge"),
        ))
        .unwrap();
        asm.add_mate(Mate::new(
            MateKind::Angle { degrees: 30.0 },
            s(i - 1, "arm"),
            s(i, "arm"),
        ))
        .unwrap();
    }
    for (k, (i, a), (j, b)) in extra {
        asm.add_mate(Mate::new(k.clone(), s(*i, a), s(*j, b)))
            .unwrap();
    }
    asm
}

fn same_assembly(what: &str, new: &AssemblyReport, old: &AssemblyReport, diagnosed: bool) {
    assert_eq!(new.outcome, old.outcome, "{what}");
    assert_eq!(new.dof, old.dof, "{what}");
    assert_eq!(new.conflicts, old.conflicts, "{what}");
    if diagnosed || new.outcome != Outcome::RedundantOkay {
        assert_eq!(new.redundant, old.redundant, "{what}");
        for (a, b) in new.mates.iter().zip(&old.mates) {
            assert_eq!((&a.id, a.status), (&b.id, b.status), "{what}");
        }
    } else {
        // Without the diagnosis, the solver names the constraints whose equations take part
        // in a dependence. A coincidence of two carried points was an equality of their own
        // parameters, merged away before the rank test saw it; it is an equation now, and is
        // named with the rest of the dependence.
        assert_eq!(new.redundant.len(), old.redundant.len(), "{what}");
        for (n, o) in new.redundant.iter().zip(&old.redundant) {
            assert!(o.iter().all(|m| n.contains(m)), "{what}: {n:?} holds {o:?}");
        }
    }
    for (a, b) in new.components.iter().zip(&old.components) {
        assert_eq!(a.dof, b.dof, "{what}: {}", a.name);
        if new.dof == 0 || !new.outcome.is_ok() {
            for i in 0..3 {
                assert!(
                    (a.pose.translation[i] - b.pose.translation[i]).abs() < 1e-9,
                    "{what}: {}",
                    a.name
                );
            }
            for i in 0..4 {
                assert!(
                    (a.pose.rotation[i] - b.pose.rotation[i]).abs() < 1e-9,
                    "{what}: {}",
                    a.name
                );
            }
        }
    }
}

/// The assemblies of [`chain_cases`] and one whose mates hold a
/// face: every kind the written-out derivatives cover, a conflict and a redundancy.
fn assembly_cases() -> Vec<(&'static str, Assembly)> {
    let mut plate = chain(3, &[]);
    let face = Reference::Face {
        point: [0.0, 0.0, 0.0],
        normal: [0.0, 0.0, 1.0],
    };
    let mut floor = Component::new("floor", Pose::IDENTITY).with("top", face);
    floor.grounded = true;
    plate.add_component(floor).unwrap();
    plate
        .add_mate(Mate::new(
            MateKind::Coincident,
            Selection::on("link2", "tip"),
            Selection::on("floor", "top"),
        ))
        .unwrap();
    let mut cases = chain_cases();
    cases.push(("a chain whose last tip rests on a grounded face", plate));
    cases
}

/// Chains of links: one that solves, one with a conflict, one with a redundancy.
fn chain_cases() -> Vec<(&'static str, Assembly)> {
    vec![
        ("a chain of six links", chain(6, &[])),
        (
            "a second angle between the same arms conflicts",
            chain(
                3,
                &[(MateKind::Angle { degrees: 45.0 }, (1, "arm"), (2, "arm"))],
            ),
        ),
        (
            "a distance the chain already holds is redundant",
            chain(
                4,
                &[(
                    MateKind::Distance { value: 1.0 },
                    (1, "pivot"),
                    (2, "pivot"),
                )],
            ),
        ),
    ]
}

#[test]
fn written_out_derivatives_solve_assemblies_as_the_dual_numbers_do() {
    let mut outcomes = Vec::new();
    for (what, asm) in assembly_cases() {
        for diagnose in [false, true] {
            let mut a = asm.clone();
            let mut b = asm.clone();
            a.options.diagnose = diagnose;
            b.options.diagnose = diagnose;
            let written = a.solve().unwrap();
            let dual = super::super::spatial::dual_only(|| b.solve()).unwrap();
            // Everything the report says, and the poses to rounding, whatever the freedom.
            assert_eq!(written.outcome, dual.outcome, "{what}");
            assert_eq!(written.dof, dual.dof, "{what}");
            assert_eq!(written.iterations, dual.iterations, "{what}");
            assert_eq!(written.conflicts, dual.conflicts, "{what}");
            assert_eq!(written.redundant, dual.redundant, "{what}");
            for (m, n) in written.mates.iter().zip(&dual.mates) {
                assert_eq!((&m.id, m.status), (&n.id, n.status), "{what}");
            }
            for (c, d) in written.components.iter().zip(&dual.components) {
                assert_eq!(c.dof, d.dof, "{what}: {}", c.name);
                let (p, q) = (c.pose, d.pose);
                for (x, y) in p.translation.iter().zip(q.translation) {
                    assert!((x - y).abs() < 1e-9, "{what}: {}", c.name);
                }
                for (x, y) in p.rotation.iter().zip(q.rotation) {
                    assert!((x - y).abs() < 1e-9, "{what}: {}", c.name);
                }
            }
            outcomes.push(written.outcome);
        }
    }
    for o in [Outcome::Okay, Outcome::RedundantOkay, Outcome::Inconsistent] {
        assert!(outcomes.contains(&o), "a case ending {o}: {outcomes:?}");
    }
}

#[test]
fn assemblies_solve_as_with_own_unknowns() {
    let mut outcomes = Vec::new();
    for (what, asm) in chain_cases() {
        for diagnose in [false, true] {
            let mut a = asm.clone();
            let mut b = asm.clone();
            a.options.diagnose = diagnose;
            b.options.diagnose = diagnose;
            let new = a.solve().unwrap();
            let old = without(|| b.solve()).unwrap();
            same_assembly(what, &new, &old, diagnose);
            outcomes.push(new.outcome);
        }
    }
    for o in [Outcome::Okay, Outcome::RedundantOkay, Outcome::Inconsistent] {
        assert!(outcomes.contains(&o), "a case ending {o}: {outcomes:?}");
    }
}

#[test]
fn a_carried_point_is_no_larger_than_a_point_of_a_workplane() {
    use super::super::refs::{Frame, PointRef, Slot};
    // Sketches hold many references: the bases of carried entities live in the equation.
    let p2 = std::mem::size_of::<(Frame, [Slot; 2])>();
    assert!(
        std::mem::size_of::<PointRef>() <= p2 + 4,
        "{} against {p2}",
        std::mem::size_of::<PointRef>()
    );
}

/// The constraints of [`cases`] and the other kinds whose derivatives through a carrier are
/// written out (`equations/spatial.rs`): directions of a turned normal, of a line between
/// carried points and of a constant normal, parallel and perpendicular; distances along them.
fn spatial_constraints() -> Vec<Constraint> {
    let c = |h: u32, k: K| Constraint::new(h, MOVING, k);
    let mut all: Vec<Constraint> = cases().into_iter().flat_map(|(_, cs)| cs).collect();
    all.extend([
        c(10, K::Parallel).with_entities([TURNED, POSE, 0, 0]),
        c(11, K::Parallel).with_entities([300, N, 0, 0]),
        c(12, K::Perpendicular).with_entities([TURNED, N, 0, 0]),
        c(13, K::Perpendicular).with_entities([POSE, 300, 0, 0]),
        c(14, K::ProjPtDistance)
            .with_points(AT_Y, AT_X)
            .with_entities([300, 0, 0, 0])
            .with_val(0.5),
        c(15, K::ProjPtDistance)
            .with_points(SHIFTED, A)
            .with_entities([POSE, 0, 0, 0]),
        c(16, K::PointsCoincident).with_points(SHIFTED, AT_Y),
    ]);
    for (i, c) in all.iter_mut().enumerate() {
        c.h = (1 + i as u32).into();
    }
    all
}

proptest::proptest! {
    /// At any pose (its quaternion not quite of unit length, so that its own equation does
    /// not hold either), every equation of the group written out by hand has the residuals
    /// of the generic evaluation to the last bit and the dual numbers' derivatives to
    /// rounding, over all its slots and over some of them (others constants, as in a solve
    /// that merged or fixed them).
    #[test]
    fn written_out_derivatives_through_a_pose_match_dual_numbers(
        t in proptest::array::uniform3(-3.0..3.0f64),
        axis in proptest::array::uniform3(-1.0..1.0f64),
        angle in -3.1..3.1f64,
        scale in 0.9..1.1f64,
    ) {
        let mut sys = system(&spatial_constraints());
        let axis = if axis.iter().all(|v| v.abs() < 1e-3) { [0.0, 0.0, 1.0] } else { axis };
        let q = axis_angle(axis, angle).map(|v| v * scale);
        let pose = sys.entity(EntityId(POSE)).unwrap().kind.params().to_vec();
        for (p, v) in pose.iter().zip(q) {
            sys.set_value(*p, v);
        }
        let Some(crate::model::EntityKind::PointNRotTrans { translation, .. }) =
            sys.entity(EntityId(AT_ORIGIN)).map(|e| e.kind.clone())
        else {
            unreachable!("a moved point")
        };
        for (p, v) in translation.iter().zip(t) {
            sys.set_value(*p, v);
        }
        let v = values(&sys);
        let compiled = compile_group(&sys, GroupId(MOVING), &[], true, &v, &v).unwrap();
        let (mut written, mut covered) = (0, 0);
        for k in &compiled.kernels {
            use super::super::EqKind;
            if matches!(
                k.eq.kind,
                EqKind::UnitQuaternion
                    | EqKind::Constraint(
                        K::PointsCoincident | K::Parallel | K::Perpendicular | K::ProjPtDistance
                    )
            ) {
                covered += 2;
            }
            let mut x = Vec::new();
            k.gather(&v, &mut x);
            let all: Vec<u16> = (0..x.len() as u16).collect();
            let some: Vec<u16> = all.iter().copied().filter(|s| s % 3 != 1).collect();
            for active in [all, some] {
                let rows = k.rows;
                let (mut rf, mut jf) = (vec![0.0; rows], vec![0.0; rows * active.len()]);
                let (mut rd, mut jd) = (vec![0.0; rows], vec![0.0; rows * active.len()]);
                if !super::super::fast::jacobian(&k.eq, &x, &active, &mut rf, &mut jf) {
                    continue;
                }
                written += 1;
                k.eq.jacobian_dual(&x, &active, &mut rd, &mut jd);
                let what = format!("{:?}", k.owner);
                // The residuals are the generic `f64` evaluation's (the dual numbers' value
                // parts may divide differently, by an ulp).
                let mut generic = Rows::new();
                k.eq.eval(&x, &mut generic);
                proptest::prop_assert_eq!(
                    rf.iter().map(|r| r.to_bits()).collect::<Vec<_>>(),
                    generic.v[..rows].iter().map(|r| r.to_bits()).collect::<Vec<_>>(),
                    "{}", what
                );
                assert_close_all(&rf, &rd, &what);
                assert_close_all(&jf, &jd, &what);
            }
        }
        // Every such constraint and the pose's unit quaternion, none left to the dual numbers.
        proptest::prop_assert_eq!(written, covered);
        proptest::prop_assert!(covered >= 2 * 12);
    }
}
