//! Every constraint type and implicit condition, checked three ways from one table per family:
//!
//! 1. the residual vanishes on a hand-built configuration that satisfies it, and takes the
//!    expected value on one that does not;
//! 2. [`Equation::jacobian`](super::Equation::jacobian) matches central differences at seeded
//!    random points around that configuration;
//! 3. from a perturbed start, [`crate::solve`] comes back to a configuration where every
//!    equation of the group holds (evaluated here, not taken from the report).
//!
//! Each case is built in up to three forms ([`Form`]): in a workplane, free in space, and in a
//! workplane on points that belong to another workplane or to space.

mod carried;
mod circles;
mod curves;
mod fast;
mod fixture;
mod lines;
mod orientation;
mod points;
mod spurious;

use std::collections::{BTreeMap, BTreeSet};

use fixture::{
    assert_close, compile_all, compile_target, Break, Built, Case, Expect, Form, Fx, One, Rng,
    Target, MOVING,
};
use proptest::prelude::*;

use crate::model::{ConstraintKind, GroupId, PlaneRule};
use crate::solve::{solve, Config};

fn all_cases() -> Vec<Case> {
    [
        points::cases(),
        lines::cases(),
        circles::cases(),
        curves::cases(),
        orientation::cases(),
    ]
    .into_iter()
    .flatten()
    .collect()
}

fn label(case: &Case, form: Form) -> String {
    format!("{} [{form:?}]", case.name)
}

/// A seed that depends only on the case's label, so a failure reproduces on its own.
fn seed(label: &str) -> u64 {
    label.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
    })
}

/// Builds a case in a fresh fixture and adds its constraint to the system.
fn build(case: &Case, form: Form) -> (Fx, Built) {
    let mut fx = Fx::new();
    let b = (case.build)(&mut fx, form);
    if let Target::Constraint(c) = &b.target {
        fx.sys.add_constraint(c.clone()).expect("fresh constraint");
    }
    (fx, b)
}

fn norm(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum::<f64>().sqrt()
}

/// Check 1: zero when satisfied, the expected value when broken.
fn check_residuals(cases: &[Case]) {
    for case in cases {
        for &form in case.forms {
            let what = label(case, form);
            let (mut fx, b) = build(case, form);
            let mut one = compile_target(&fx.sys, &b.target);
            let r = one.residuals(&one.x(&fx.sys));
            assert!(
                !r.is_empty() && r.iter().all(|v| v.abs() < 1e-12),
                "{what}: satisfied configuration gives {r:?}"
            );
            // The count of residuals, evaluated or known from the kind, is what they are.
            assert_eq!(one.eq.rows(&one.x(&fx.sys)), r.len(), "{what}");
            // The equation keeps the branch it chose at the satisfied configuration.
            match &b.brk {
                Break::Set(values) => fx.set(values),
                Break::Val(v) => one.eq.val = *v,
                Break::Flags(o, o2) => (one.eq.other, one.eq.other2) = (*o, *o2),
            }
            let r = one.residuals(&one.x(&fx.sys));
            assert_eq!(one.eq.rows(&one.x(&fx.sys)), r.len(), "{what}");
            let Expect::Rows(want) = &b.expect;
            assert_close(&what, &r, want, 1e-9);
            assert!(norm(&r) > 1e-3, "{what}: broken configuration gives {r:?}");
        }
    }
}

/// Compares the exact Jacobian with central differences at `x`.
fn check_jacobian_at(what: &str, one: &One, x: &[f64]) {
    let n = x.len();
    let (res, jac) = one.jacobian(x);
    assert_close(what, &res, &one.residuals(x), 1e-14);
    assert!(jac.iter().all(|v| v.is_finite()), "{what}: {jac:?}");
    // The solver differentiates with respect to its unknowns only: every other slot, say.
    let active: Vec<u16> = (0..n as u16).filter(|k| k % 2 == 1).collect();
    let rows = res.len();
    let mut sub_res = vec![f64::NAN; rows];
    let mut sub = vec![f64::NAN; rows * active.len()];
    one.eq.jacobian_active(x, &active, &mut sub_res, &mut sub);
    assert_close(what, &sub_res, &res, 1e-14);
    for r in 0..rows {
        for (j, &k) in active.iter().enumerate() {
            let (got, want) = (sub[r * active.len() + j], jac[r * n + k as usize]);
            let ok = (got - want).abs() <= 1e-12 * (1.0 + want.abs());
            assert!(ok, "{what}: active d row {r} / d slot {k}: {got} vs {want}");
        }
    }
    let mut xp = x.to_vec();
    for k in 0..n {
        let h = 1e-6 * (1.0 + x[k].abs());
        xp[k] = x[k] + h;
        let rp = one.residuals(&xp);
        xp[k] = x[k] - h;
        let rm = one.residuals(&xp);
        xp[k] = x[k];
        for (r, (p, m)) in rp.iter().zip(&rm).enumerate() {
            let fd = (p - m) / (2.0 * h);
            let exact = jac[r * n + k];
            assert!(
                (exact - fd).abs() <= 1e-6 * (1.0 + fd.abs()),
                "{what}: d row {r} / d slot {k}: exact {exact}, differences {fd} at {x:?}"
            );
        }
    }
}

/// Points around the satisfied configuration: itself, then every slot moved by up to 0.3.
fn random_points(x0: &[f64], rng: &mut Rng, count: usize) -> Vec<Vec<f64>> {
    let mut out = vec![x0.to_vec()];
    for _ in 1..count {
        out.push(x0.iter().map(|v| v + rng.signed(0.0, 0.3)).collect());
    }
    out
}

/// Check 2: exact derivatives.
fn check_jacobians(cases: &[Case]) {
    for case in cases {
        for &form in case.forms {
            let what = label(case, form);
            let (fx, b) = build(case, form);
            let one = compile_target(&fx.sys, &b.target);
            let mut rng = Rng::new(seed(&what));
            for x in random_points(&one.x(&fx.sys), &mut rng, 6) {
                check_jacobian_at(&what, &one, &x);
            }
        }
    }
}

/// Check 3: a perturbed start solves back, judged by the equations themselves.
fn check_solves(cases: &[Case]) {
    for case in cases {
        for &form in case.forms {
            let what = label(case, form);
            let (mut fx, _) = build(case, form);
            let start: Vec<(u32, f64)> = fx
                .sys
                .params()
                .iter()
                .filter(|p| p.group == GroupId(MOVING))
                .map(|p| (p.h.0, p.val))
                .collect();
            assert!(!start.is_empty(), "{what}: nothing moves");
            let mut rng = Rng::new(seed(&what));
            // Draw perturbations until one clearly breaks the configuration (a draw can
            // happen to keep, say, a line's direction).
            let mut tries = 0;
            let eqs = loop {
                let moved: Vec<(u32, f64)> = start
                    .iter()
                    .map(|&(p, v)| (p, v + rng.signed(0.1, 0.3)))
                    .collect();
                fx.set(&moved);
                let eqs = compile_all(&fx.sys, MOVING);
                let before = eqs
                    .iter()
                    .flat_map(|(_, one)| one.residuals(&one.x(&fx.sys)))
                    .fold(0.0, |m: f64, r| m.max(r.abs()));
                tries += 1;
                if before > 1e-2 {
                    break eqs;
                }
                assert!(tries < 5, "{what}: perturbations keep the configuration");
            };
            let report = solve(&mut fx.sys, GroupId(MOVING), &[], &Config::default())
                .unwrap_or_else(|e| panic!("{what}: {e}"));
            assert!(report.outcome.is_ok(), "{what}: {report:?}");
            for (name, one) in &eqs {
                let r = one.residuals(&one.x(&fx.sys));
                assert!(
                    r.iter().all(|v| v.abs() < 1e-9),
                    "{what}: {name} left at {r:?} ({report:?})"
                );
            }
        }
    }
}

/// Runs the three checks on one family's table.
fn check_family(cases: &[Case]) {
    check_residuals(cases);
    check_jacobians(cases);
    check_solves(cases);
}

#[test]
fn every_kind_is_covered_in_each_form_it_allows() {
    let cases = all_cases();
    let mut forms: BTreeMap<Option<ConstraintKind>, BTreeSet<Form>> = BTreeMap::new();
    for c in &cases {
        forms.entry(c.kind).or_default().extend(c.forms);
    }
    for &k in ConstraintKind::ALL {
        let f = forms.get(&Some(k)).cloned().unwrap_or_default();
        let ok = match k.signature().plane {
            PlaneRule::Either => f.contains(&Form::Plane) && f.contains(&Form::Free),
            PlaneRule::Required => f.contains(&Form::Plane),
            PlaneRule::Ignored => !f.is_empty(),
        };
        assert!(ok, "{k}: covered in {f:?}");
    }
    let implicit = cases.iter().filter(|c| c.kind.is_none()).count();
    assert_eq!(
        implicit, 4,
        "unit quaternion, arc radii, moved point and rotated normal"
    );
    // The figures for the record (shown with --nocapture): every pair runs all three checks.
    let kinds = || forms.iter().filter(|(k, _)| k.is_some()).map(|(_, f)| f);
    let per_form = |form| kinds().filter(|f| f.contains(&form)).count();
    eprintln!(
        "{} constraint types, {} type x form pairs (plane {}, free {}, mixed {}); {} cases",
        kinds().count(),
        kinds().map(BTreeSet::len).sum::<usize>(),
        per_form(Form::Plane),
        per_form(Form::Free),
        per_form(Form::Mixed),
        cases.iter().map(|c| c.forms.len()).sum::<usize>(),
    );
}

#[test]
fn some_equation_reads_more_than_thirty_two_parameters() {
    // The Jacobian is taken in passes of at most 16 directions, on the stack up to 32 slots
    // and on the heap beyond: make sure the tables exercise every path.
    let most = all_cases()
        .iter()
        .flat_map(|c| c.forms.iter().map(move |&f| (c, f)))
        .map(|(c, f)| {
            let (fx, b) = build(c, f);
            compile_target(&fx.sys, &b.target).locals.len()
        })
        .max()
        .unwrap_or(0);
    assert!(most > 32, "largest equation reads {most} parameters");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Exact derivatives match central differences at random points of random cases.
    #[test]
    fn jacobian_matches_differences(case in 0usize..10_000, form in 0usize..3, offsets in prop::collection::vec(-0.3f64..0.3, 64)) {
        let cases = all_cases();
        let case = &cases[case % cases.len()];
        let form = case.forms[form % case.forms.len()];
        let (fx, b) = build(case, form);
        let one = compile_target(&fx.sys, &b.target);
        let x: Vec<f64> = one.x(&fx.sys).iter().zip(offsets.iter().cycle()).map(|(v, d)| v + d).collect();
        check_jacobian_at(&label(case, form), &one, &x);
    }
}
