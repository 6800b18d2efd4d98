//! The harness end to end on small problems: generators give valid problems loci and ezpz
//! solve, the checker catches wrong answers, and `--quick` writes the report.

use loci_bench::check::{max_residual, start_points, TOLERANCE};
use loci_bench::compare::Results;
use loci_bench::generate::generate;
use loci_bench::problem::{Con, Family, Variant};
use loci_bench::run::{judge, median, run_in_process, RunOutput, Solver, Verdict};
use loci_bench::{peers, slvs};

#[test]
fn generators_are_deterministic_and_valid() {
    for f in Family::ALL {
        for v in Variant::ALL {
            let a = generate(f, v, 10);
            assert_eq!(a, generate(f, v, 10), "{} is not deterministic", a.label());
            let sp = slvs::build(&a).expect("translates to the SolveSpace model");
            sp.system.validate().expect("a valid loci system");
            assert_eq!(sp.points.len(), a.points.len());
            let extra = usize::from(v != Variant::Solvable);
            assert_eq!(sp.system.constraints().len(), a.cons.len());
            // A variant is the solvable problem, same start, plus one constraint.
            let base = generate(f, Variant::Solvable, 10);
            assert_eq!(a.cons.len(), base.cons.len() + extra);
            assert_eq!(a.cons[..base.cons.len()], base.cons[..]);
            assert_eq!(a.points, base.points);
            if f.is_2d() {
                let ez = peers::to_ezpz(&a).expect("planar problems go to ezpz");
                assert_eq!(ez.guesses.len(), 2 * a.points.len());
                let gcs = peers::to_planegcs(&a).expect("planar problems go to PlaneGCS");
                let n = gcs.as_array().map_or(0, Vec::len);
                assert_eq!(
                    n,
                    a.points.len() + a.lines.len() + 2 * a.arcs.len() + a.cons.len()
                );
            } else {
                assert!(peers::to_ezpz(&a).is_none());
                assert!(peers::to_planegcs(&a).is_none());
            }
        }
    }
    // The records the SolveSpace runners read name every point and end with the output list.
    let p = generate(Family::Fillets, Variant::Solvable, 3);
    let rec = slvs::to_records(&slvs::build(&p).unwrap());
    assert!(rec.starts_with("G 2\n"));
    let last = rec.lines().last().unwrap();
    assert_eq!(last.split_whitespace().count(), 1 + p.points.len());
    assert_eq!(
        rec.lines().filter(|l| l.starts_with("C ")).count(),
        p.cons.len()
    );
}

#[test]
fn loci_and_ezpz_solve_every_family_and_the_checker_agrees() {
    for f in Family::ALL {
        let p = generate(f, Variant::Solvable, 10);
        assert!(
            max_residual(&p, &start_points(&p)) > TOLERANCE,
            "{} starts solved",
            p.label()
        );
        let solvers: &[Solver] = if f.is_2d() {
            &[Solver::Loci, Solver::Ezpz]
        } else {
            &[Solver::Loci]
        };
        for &s in solvers {
            let out = run_in_process(s, &p, 2, 1.0).unwrap();
            assert_eq!(out.solve_ms.len(), 2);
            assert_eq!(
                judge(&p, &out).0,
                Verdict::Solved,
                "{} on {}: {}",
                s.name(),
                p.label(),
                out.detail
            );
        }
        let bad = generate(f, Variant::Inconsistent, 10);
        let out = run_in_process(Solver::Loci, &bad, 1, 1.0).unwrap();
        assert!(
            matches!(judge(&bad, &out).0, Verdict::Detected { .. }),
            "loci on {}: {}",
            bad.label(),
            out.detail
        );
    }
}

/// Profiles hold angles of a degree or two that the start turns the other way. Their sign
/// reaches loci (whose 2D angle keeps the sign it starts with) as it reaches ezpz, so loci
/// solves every size with each angle on its intended side. Given only `|deg|`, loci kept the
/// start's sign, a sketch in which some slots cannot be placed (8x8, 15x15 and 20x20 failed).
#[test]
fn profiles_solve_with_every_angle_on_its_intended_side() {
    for n in [8, 15, 20] {
        let p = generate(Family::Profiles, Variant::Solvable, n);
        let out = run_in_process(Solver::Loci, &p, 1, 5.0).unwrap();
        assert_eq!(
            judge(&p, &out).0,
            Verdict::Solved,
            "{}: {}",
            p.label(),
            out.detail
        );
        let dir = |l: usize| {
            let [a, b] = p.lines[l];
            let (s, e) = (out.points[a], out.points[b]);
            [e[0] - s[0], e[1] - s[1]]
        };
        let s = start_points(&p);
        let mut turned = 0;
        for c in &p.cons {
            if let Con::Angle { l1, l2, deg } = *c {
                let (u, v) = (dir(l1), dir(l2));
                let got = (u[0] * v[1] - u[1] * v[0])
                    .atan2(u[0] * v[0] + u[1] * v[1])
                    .to_degrees();
                assert!(
                    (got - deg).abs() < 1e-6,
                    "{}: angle {got} for {deg}",
                    p.label()
                );
                let (su, sv) = (
                    [
                        s[p.lines[l1][1]][0] - s[p.lines[l1][0]][0],
                        s[p.lines[l1][1]][1] - s[p.lines[l1][0]][1],
                    ],
                    [
                        s[p.lines[l2][1]][0] - s[p.lines[l2][0]][0],
                        s[p.lines[l2][1]][1] - s[p.lines[l2][0]][1],
                    ],
                );
                if (su[0] * sv[1] - su[1] * sv[0]).signum() != deg.signum() {
                    turned += 1;
                }
            }
        }
        assert!(
            turned > 0,
            "{}: no angle starts turned the other way",
            p.label()
        );
    }
}

/// An impossible length in a large sheet of profiles: Newton's damped steps reach the
/// least-squares point and then lower the merit by next to nothing at every step. The solve
/// stops there and names the profile the length closes (its six other dimensions and the
/// length), where it used to crawl on to its 1,000th iteration.
#[test]
fn an_impossible_length_in_profiles_is_named_without_crawling() {
    let p = generate(Family::Profiles, Variant::Inconsistent, 30);
    let mut sp = slvs::build(&p).unwrap();
    let r = loci::solve(
        &mut sp.system,
        slvs::SOLVE_GROUP.into(),
        &[],
        &loci::Config::default(),
    )
    .unwrap();
    assert_eq!(r.outcome, loci::Outcome::Inconsistent);
    assert!(r.iterations < 100, "{} iterations", r.iterations);
    // The extra length is the last constraint; the first profile's sides and angles close it.
    let last = sp.system.constraints().last().unwrap().h;
    assert!(r.failed.contains(&last), "{:?}", r.failed);
    assert_eq!(r.failed.len(), 7, "{:?}", r.failed);
}

/// One wrong diagonal in a mesh with a length on every edge: every circuit through it fails
/// where the solve stops, and each other one holds once the diagonal is left out. The
/// diagnosis names the smallest (the diagonal and the five edges of its cell) and not the 44
/// larger ones through the same diagonal that it used to shrink and list.
#[test]
fn one_wrong_diagonal_in_a_mesh_is_named_once() {
    let p = generate(Family::Mesh, Variant::Inconsistent, 10);
    let sp = slvs::build(&p).unwrap();
    let d = sp.system.diagnose(slvs::SOLVE_GROUP).unwrap();
    assert_eq!(d.outcome, loci::Outcome::Inconsistent);
    assert_eq!(d.conflicting.len(), 1, "{:?}", d.conflicting);
    let set = &d.conflicting[0];
    assert!(set.verified);
    assert_eq!(set.members.len(), 6, "{:?}", set.members);
    let last = sp.system.constraints().last().unwrap().h;
    assert!(
        set.members.contains(&loci::Member::Constraint(last)),
        "{:?}",
        set.members
    );
    let mut sys = sp.system.clone();
    let r = loci::solve(
        &mut sys,
        slvs::SOLVE_GROUP.into(),
        &[],
        &loci::Config::default(),
    )
    .unwrap();
    assert_eq!(r.failed.len(), 6, "{:?}", r.failed);
}

#[test]
fn checker_catches_a_wrong_answer() {
    let p = generate(Family::Fillets, Variant::Solvable, 10);
    let good = run_in_process(Solver::Loci, &p, 1, 1.0).unwrap();
    assert!(max_residual(&p, &good.points) < TOLERANCE);
    // Moving one free point by 1e-3 breaks the constraints on it.
    let mut moved = good.clone();
    let free = p.points.iter().position(|q| !q.fixed).unwrap();
    moved.points[free][1] += 1e-3;
    let (v, r) = judge(&p, &moved);
    assert!(matches!(v, Verdict::Wrong { .. }), "{v:?}");
    assert!(r.unwrap() > 5e-4);
    // Moving a fixed point is wrong too, even though no constraint names it.
    let mut shifted = good.clone();
    let fixed = p.points.iter().position(|q| q.fixed).unwrap();
    shifted.points[fixed][0] += 1e-3;
    assert!(matches!(judge(&p, &shifted).0, Verdict::Wrong { .. }));
    // A claim of success that returns the start, a short list or NaN is wrong.
    let lazy = RunOutput {
        status: "ok".into(),
        points: start_points(&p),
        ..RunOutput::default()
    };
    assert!(matches!(judge(&p, &lazy).0, Verdict::Wrong { .. }));
    let mut short = good.clone();
    short.points.pop();
    assert_eq!(max_residual(&p, &short.points), f64::INFINITY);
    let mut nan = good.clone();
    nan.points[free][0] = f64::NAN;
    assert_eq!(max_residual(&p, &nan.points), f64::INFINITY);
    // A solver's own failure is reported as such, and as detection on inconsistent problems.
    let failed = RunOutput {
        status: "failed".into(),
        detail: "inconsistent".into(),
        ..RunOutput::default()
    };
    assert!(matches!(judge(&p, &failed).0, Verdict::Failed { .. }));
    let bad = generate(Family::Fillets, Variant::Inconsistent, 10);
    assert!(matches!(judge(&bad, &failed).0, Verdict::Detected { .. }));
}

#[test]
fn the_inconsistent_variant_changes_the_extra_constraint_only() {
    for f in Family::ALL {
        let r = generate(f, Variant::Redundant, 10);
        let i = generate(f, Variant::Inconsistent, 10);
        let (a, b) = (r.cons.last().unwrap(), i.cons.last().unwrap());
        match (a, b) {
            (Con::Distance { d: x, .. }, Con::Distance { d: y, .. }) => {
                assert!((y - x - 1.0).abs() < 1e-12, "{x} -> {y}");
            }
            (Con::Angle { deg: x, .. }, Con::Angle { deg: y, .. }) => {
                assert!(((y - x).abs() - 10.0).abs() < 1e-12, "{x} -> {y}");
            }
            other => panic!("unexpected extra constraints {other:?}"),
        }
    }
}

#[test]
fn median_of_odd_and_even_counts() {
    assert_eq!(median(&[]), None);
    assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
    assert_eq!(median(&[4.0, 1.0, 3.0, 2.0]), Some(2.5));
}

#[test]
fn quick_mode_writes_the_report() {
    let out = std::env::temp_dir().join(format!("loci-bench-smoke-{}", std::process::id()));
    let run = std::process::Command::new(env!("CARGO_BIN_EXE_loci-bench"))
        .args(["--quick", "--out"])
        .arg(&out)
        .output()
        .expect("runs");
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let md = std::fs::read_to_string(out.join("benchmarks.md")).unwrap();
    let svg = std::fs::read_to_string(out.join("benchmarks.svg")).unwrap();
    let json = std::fs::read_to_string(out.join("benchmarks.json")).unwrap();
    let res: Results = serde_json::from_str(&json).unwrap();
    let _ = std::fs::remove_dir_all(&out);
    assert!(md.contains("![time against size, per family](benchmarks.svg)"));
    assert!(md.contains("### chain\n"));
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert!(svg.contains("<polyline"));
    // Every loci and ezpz cell ran through a worker and got its expected verdict.
    assert!(res.cells.len() >= 30);
    for c in &res.cells {
        let expect_time = c.solver == Solver::Loci || c.family.is_2d();
        if !expect_time {
            assert!(matches!(c.verdict, Verdict::NotRun { .. }));
            continue;
        }
        match c.variant {
            Variant::Inconsistent => {
                assert!(matches!(c.verdict, Verdict::Detected { .. }), "{c:?}")
            }
            _ => assert_eq!(c.verdict, Verdict::Solved, "{c:?}"),
        }
        assert!(c.solve_ms.is_some_and(|t| t > 0.0) && c.runs >= 1, "{c:?}");
    }
}
