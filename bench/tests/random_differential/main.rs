//! A randomized differential test of loci against SolveSpace, judging every answer itself.
//!
//! Each seed names one random system in the SolveSpace model ([`case`]): 2D in a workplane or
//! 3D free in space, built from a true configuration and started near it, in one of three
//! variants (base, redundant, conflicting). loci (`loci::solve`, and a reused `loci::Solver`)
//! and SolveSpace (PyPI `slvs` in `bench/.venv`) solve it; [`judge`] grades each answer
//! against the truth with the independent residual check of [`check`], and the run prints
//! counts per variant and the seed of every case where loci is wrong.
//!
//! The default run checks [`DEFAULT_SYSTEMS`] seeds and the [`PINNED_SEEDS`]; more on demand:
//!
//! ```sh
//! LOCI_DIFF_SYSTEMS=5000 cargo test --release -p loci-bench --test random_differential -- --nocapture
//! LOCI_DIFF_SEEDS=17,42 LOCI_DIFF_VERBOSE=1 cargo test ... # some seeds, every answer shown
//! ```
//!
//! (`LOCI_DIFF_FIRST_SEED` starts elsewhere; `LOCI_DIFF_SCALE=0.001` draws every length that
//! many times as long, see [`case::drawing_scale`]; `LOCI_DIFF_PYTHON` names another Python with
//! `slvs`; `LOCI_DIFF_DUMP=DIR` writes each system as a loci JSON problem, `seed-N.json` at
//! its start, `seed-N.truth.json` at the true configuration and `seed-N.restart.json` at the
//! second start the re-solves take, for `loci solve` and `loci check`.) Without SolveSpace the test says so loudly and still checks loci's half.

mod case;
mod check;
mod gadgets;
mod geom;
mod judge;
mod peer;
mod report;
mod rng;
mod sketch;
mod steps;

use case::case;
use judge::Grade;
use report::Row;
use std::time::Instant;

/// The systems of the default run (seeds 0 ..).
const DEFAULT_SYSTEMS: u64 = 120;

/// Seeds beyond the default sample that the default run checks too: one for each distinct
/// kind of wrong answer larger runs have found, so that every fix is checked by
/// `cargo test`. (Seeds name systems of this generator: changing the generator changes them.)
const PINNED_SEEDS: &[u64] = &[
    203, 310, 311, 516, 599, 806, 833, 844, 850, 976, 991, 1043, 1061, 1186, 1287, 1493, 2473,
    2485, 2830, 3323, 3347, 3364, 3923, 3953, 4204, 4465, 4650, 4996, 7929, 8169, 22011, 25105,
    59100, 570880, 590044,
];

/// Seeds drawn at another scale ([`case::case_at`]) that loci once answered wrongly there,
/// checked by the default run too, loci's half (no peer needed). At 1e5 (coordinates up to
/// a million) seed 1 did not converge, its residual stuck at 2.3e-10, two roundings of its
/// coordinates, above a tolerance of 1e-10; seed 29 with its dimension switched to one that
/// holds was called inconsistent from there.
const PINNED_SCALED: &[(u64, f64)] = &[(1, 1e5), (29, 1e5)];

/// Seeds where loci is known to answer wrongly today (or to fail where SolveSpace succeeds),
/// with the reason. The test tolerates these and says when one of them passes, so that it
/// can be removed as the fix lands.
const KNOWN_FAILURES: &[(u64, &str)] = &[];

fn env_u64(name: &str) -> Option<u64> {
    std::env::var(name).ok().and_then(|v| v.trim().parse().ok())
}

fn seeds() -> Vec<u64> {
    if let Ok(list) = std::env::var("LOCI_DIFF_SEEDS") {
        return list
            .split(',')
            .filter_map(|s| s.trim().parse().ok())
            .collect();
    }
    let first = env_u64("LOCI_DIFF_FIRST_SEED");
    let n = env_u64("LOCI_DIFF_SYSTEMS");
    let mut seeds: Vec<u64> =
        (first.unwrap_or(0)..first.unwrap_or(0) + n.unwrap_or(DEFAULT_SYSTEMS)).collect();
    if first.is_none() && n.is_none() {
        seeds.extend(PINNED_SEEDS);
    }
    seeds
}

#[test]
fn random_systems_against_solvespace() {
    let seeds = seeds();
    let t0 = Instant::now();
    let cases: Vec<case::Case> = seeds.iter().map(|&s| case(s)).collect();
    if let Some(dir) = std::env::var_os("LOCI_DIFF_DUMP") {
        dump(std::path::Path::new(&dir), &cases);
    }
    let peer = peer::Peer::find();
    let answers = match &peer {
        Ok(p) => {
            let systems: Vec<(u64, &loci::System)> =
                cases.iter().map(|c| (c.seed, &c.system)).collect();
            Some(p.solve_all(&systems))
        }
        Err(why) => {
            eprintln!(
                "\n!!!!!!!!\n!!! random differential: SolveSpace is NOT available ({why}).\n\
                 !!! Only loci's half is checked. To compare, install SolveSpace 3.3's solver as .ci/run does:\n\
                 !!!   python3 -m venv bench/.venv && bench/.venv/bin/pip install slvs==3.3\n!!!!!!!!\n"
            );
            None
        }
    };
    let t_peer = t0.elapsed();
    let rows: Vec<Row> = cases
        .iter()
        .map(|c| {
            let (loci, loci_said, notes) = judge::loci(c);
            let ss = answers.as_ref().map(|a| {
                let answer = a
                    .get(&c.seed)
                    .cloned()
                    .unwrap_or_else(|| peer::Answer::Broken("no answer".into()));
                judge::solvespace(c, &answer)
            });
            Row {
                seed: c.seed,
                label: c.label(),
                gadgets: c.gadgets.iter().map(|g| format!("{g:?}")).collect(),
                dim: c.dim,
                variant: c.variant,
                kinds: c.system.constraints().iter().map(|k| k.kind).collect(),
                loci,
                loci_said,
                ss,
                resolve: judge::resolve(c),
                notes,
            }
        })
        .collect();
    let peer_name = peer
        .as_ref()
        .map(|p| format!("SolveSpace {} (PyPI slvs)", p.version))
        .ok();
    let verbose = std::env::var_os("LOCI_DIFF_VERBOSE").is_some();
    println!(
        "{}",
        report::summary(&rows, peer_name.as_deref(), t0.elapsed(), t_peer, verbose)
    );

    // What may not happen: loci wrong, loci failing where SolveSpace succeeds, a reused
    // Solver wrong; unless listed as known.
    let known = |s: u64| KNOWN_FAILURES.iter().any(|&(k, _)| k == s);
    let bad: Vec<&Row> = rows.iter().filter(|r| r.loci_bad()).collect();
    for &(s, why) in KNOWN_FAILURES {
        if let Some(r) = rows.iter().find(|r| r.seed == s) {
            // (Without SolveSpace a failure of loci's cannot be compared: say nothing.)
            let unknowable = r.ss.is_none() && matches!(r.loci, Grade::Failed(_));
            if !r.loci_bad() && !unknowable {
                println!("NOTE: known failure seed {s} now passes ({why}): remove it from KNOWN_FAILURES");
            }
        }
    }
    let unknown: Vec<String> = bad
        .iter()
        .filter(|r| !known(r.seed))
        .map(|r| r.seed.to_string())
        .collect();
    assert!(
        unknown.is_empty(),
        "loci is wrong (or fails where SolveSpace succeeds) on seeds {} (see above)",
        unknown.join(",")
    );
    // Both failing on a satisfiable system is acceptable only when rare.
    let satisfiable = rows
        .iter()
        .filter(|r| r.variant != case::Variant::Conflicting)
        .count();
    let both_failed = rows
        .iter()
        .filter(|r| {
            r.variant != case::Variant::Conflicting
                && matches!(r.loci, Grade::Failed(_))
                && !r.ss.as_ref().is_some_and(|(g, _)| g.is_right())
        })
        .count();
    assert!(
        both_failed * 20 <= satisfiable,
        "{both_failed} of {satisfiable} satisfiable systems were solved by neither solver"
    );
}

/// Writes each case as loci JSON problems: at its start and at its truth.
fn dump(dir: &std::path::Path, cases: &[case::Case]) {
    std::fs::create_dir_all(dir).expect("create the dump directory");
    for c in cases {
        let mut truth = c.system.clone();
        for &(p, v) in &c.truth {
            truth.set_value(p, v);
        }
        let mut restart = c.system.clone();
        for &(p, v) in &c.restart {
            restart.set_value(p, v);
        }
        for (name, sys) in [("", &c.system), (".truth", &truth), (".restart", &restart)] {
            let problem = loci::format::json::Problem {
                system: sys.clone(),
                solve: None,
            };
            let path = dir.join(format!("seed-{}{name}.json", c.seed));
            std::fs::write(&path, problem.to_json()).expect("write a dumped system");
        }
    }
}

#[test]
fn generated_systems_hold_at_their_truth() {
    for seed in 0..600 {
        let a = case(seed);
        let again = case(seed);
        let records = |c: &case::Case| {
            loci_bench::slvs::to_records(&loci_bench::slvs::SlvsProblem {
                system: c.system.clone(),
                points: Vec::new(),
            })
        };
        assert_eq!(
            records(&a),
            records(&again),
            "seed {seed} is not deterministic"
        );
        a.system.validate().expect("a valid system");
        let n = a.system.constraints().len();
        assert!(
            (5..=48).contains(&n),
            "seed {seed} {}: {n} constraints",
            a.label()
        );
        // Every constraint holds at the truth, but the planted contradicting one, which
        // fails clearly.
        let mut sys = a.system.clone();
        for &(p, v) in &a.truth {
            sys.set_value(p, v);
        }
        let bad = check::violations(&sys, &check::values_of(&sys), a.size);
        if a.satisfiable() {
            assert!(
                bad.is_empty(),
                "seed {seed} {}: {bad:?} at the truth",
                a.label()
            );
        } else {
            let planted = a
                .planted
                .iter()
                .map(|h| h.0.to_string())
                .collect::<Vec<_>>();
            assert_eq!(
                bad.len(),
                1,
                "seed {seed} {}: {bad:?} at the truth",
                a.label()
            );
            assert!(
                planted.iter().any(|h| bad[0].0.ends_with(&format!(" {h}"))),
                "seed {seed} {}: {bad:?}, planted {planted:?}",
                a.label()
            );
            assert!(bad[0].1 > 1e-3, "seed {seed} {}: {bad:?}", a.label());
        }
    }
}

#[test]
fn systems_drawn_far_from_the_origin_are_answered_rightly() {
    for &(seed, scale) in PINNED_SCALED {
        let c = case::case_at(seed, scale);
        let (grade, said, _) = judge::loci(&c);
        assert!(
            grade.is_right(),
            "seed {seed} at scale {scale} {}: loci said {said}: {grade:?}",
            c.label()
        );
        if let Some(r) = judge::resolve(&c) {
            assert!(
                !r.wrong,
                "seed {seed} at scale {scale} {}: {}",
                c.label(),
                r.what
            );
        }
    }
}
