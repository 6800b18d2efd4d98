//! `json`: bytes into loci's JSON problem reader; what parses is written back and read again,
//! solved, diagnosed and exported to `.slvs` (which must read back), as `loci solve`,
//! `loci check` and `loci convert` do.

use super::geometry::{Geo, Unit};
use super::resolve::{two_component_cross, Skips};
use loci::format::json::Problem;
use loci::format::slvs::{export, SlvsFile};
use loci::{Config, System};

/// Larger problems are skipped: time and memory grow with the square of the number of
/// constraints on one pair of points (a known limitation), which would make every large
/// input a timeout rather than a finding.
pub const MAX_OBJECTS: usize = 300;

/// Newton iterations per component, so that one input stays fast.
pub const MAX_ITERATIONS: usize = 20;

/// Runs one input as the fuzz target does; panics on a finding.
pub fn run(data: &[u8]) {
    run_with(data, Skips::FUZZ);
}

/// Runs one input with the given checks; panics on a finding.
pub fn run_with(data: &[u8], skips: Skips) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let problem = match Problem::from_json(text) {
        Ok(p) => p,
        Err(e) => {
            let _ = e.to_string();
            return;
        }
    };
    let sys = &problem.system;
    if sys.params().len() + sys.entities().len() + sys.constraints().len() > MAX_OBJECTS {
        return;
    }

    // What loci writes, loci reads back as the same model.
    let written = problem.to_json();
    let again = Problem::from_json(&written)
        .unwrap_or_else(|e| panic!("a problem loci wrote does not read back: {e}\n{written}"));
    assert_eq!(
        again.system.params(),
        sys.params(),
        "params change on a round trip"
    );
    assert_eq!(
        again.system.entities(),
        sys.entities(),
        "entities change on a round trip"
    );
    assert_eq!(
        again.system.constraints(),
        sys.constraints(),
        "constraints change on a round trip"
    );

    let req = problem.request();
    let mut cfg: Config = req.config();
    cfg.max_iterations = cfg.max_iterations.min(MAX_ITERATIONS);
    cfg.verify_conflicts_up_to = cfg.verify_conflicts_up_to.min(8);

    // Solve, as `loci solve` does.
    let mut solved = sys.clone();
    match loci::solve(&mut solved, req.group, &req.dragged, &cfg) {
        Ok(rep) => {
            let _ = rep.outcome.to_string();
            if rep.outcome.is_ok() {
                for p in solved.params() {
                    assert!(
                        p.val.is_finite(),
                        "{} is {} after an {} solve",
                        p.h,
                        p.val,
                        rep.outcome
                    );
                }
                if cfg.tolerance <= 1e-8 {
                    check_solution(sys, &solved, req.group.0, rep.outcome, skips);
                }
            } else {
                assert_eq!(
                    solved.params(),
                    sys.params(),
                    "a {} solve changed parameter values",
                    rep.outcome
                );
            }
            let _ = loci::format::json::SolveResult::new(&solved, req.group, &rep).to_json();
        }
        Err(e) => {
            let _ = e.to_string();
            assert_eq!(
                solved.params(),
                sys.params(),
                "a failed solve changed parameter values"
            );
        }
    }

    // Diagnose, as `loci check` does.
    match loci::diagnose(sys, req.group, &cfg) {
        Ok(d) => {
            let _ = serde_json::to_string(&d);
        }
        Err(e) => {
            let _ = e.to_string();
        }
    }

    // Export, as `loci convert --to slvs` does: what loci writes, loci reads.
    if let Ok(ex) = export(sys) {
        if let Err(e) = SlvsFile::parse(&ex.bytes) {
            panic!(
                "an exported .slvs file does not read back: {e}\n{}",
                String::from_utf8_lossy(&ex.bytes)
            );
        }
    }
}

/// Relative tolerance of the independent check (loci's own is `cfg.tolerance` on its
/// differently scaled residuals).
const CHECK_TOL: f64 = 1e-7;

/// After a solve loci calls successful, every constraint of the group that
/// [`super::geometry`] models holds, read independently of loci's equations.
fn check_solution(
    before: &System,
    after: &System,
    group: u32,
    outcome: loci::Outcome,
    skips: Skips,
) {
    // Both before and after: a 2D point's coordinates are lengths only in a rotation.
    if !Geo::models(before) || !Geo::models(after) {
        return;
    }
    let (g, start) = (Geo { sys: after }, Geo { sys: before });
    let size = g.size().max(start.size());
    for c in after.constraints() {
        if c.group.0 != group || (skips.two_component_cross && two_component_cross(c)) {
            continue;
        }
        let Some(rs) = g.residuals(c, &start) else {
            continue;
        };
        for (r, u) in rs {
            let tol = match u {
                Unit::Length => CHECK_TOL * size,
                Unit::Pure => CHECK_TOL,
            };
            assert!(
                r.abs() <= tol,
                "outcome {outcome} but {} ({}) does not hold: residual {r:e} (tolerance {tol:e})",
                c.h,
                c.kind
            );
        }
    }
}
