//! Random sketches of every kind of user constraint, drawn so that each constraint holds, then
//! moved off and solved. Whatever a solve says is checked here from the coordinates (each
//! constraint's [`Sketch::measure`]), not taken from the solver's word:
//!
//! - a sketch that holds at its drawing solves again from a start moved off it (its
//!   constraints are consistent, however redundant): `okay` or `redundant_okay`, every user
//!   constraint holds, every circle's radius is positive, and every soft constraint reported
//!   kept still has the length, radius or angle it had at the start of the solve; solved
//!   again, nothing moves; a free point dragged ten steps leaves every constraint holding;
//! - then one dimension is changed by a lot. A solve that says `okay` must hold every
//!   constraint at the new value; one that fails leaves the drawing where it was, names some
//!   constraints, and those named fail again on their own (every other user constraint
//!   removed).
//!
//! The sketches: a closed polygon whose sides are horizontal, vertical, parallel or
//! perpendicular to earlier sides or of equal length by construction, some corners joined by a
//! shared point and some by a coincident constraint; circles centred on corners, concentric,
//! of equal radii, through a corner, tangent to a side or to another circle; arcs with a line
//! or another arc tangent at an end; points on sides, at midpoints, mirrored about a side or
//! an axis, at a distance from a side; a line along a side; a cubic with a line tangent at
//! its start; locked and fixed shapes; dimensions (lengths, distances, signed angles, radii,
//! diameters, sweeps) read from the drawing; and reference dimensions of the wrong value, which
//! must not drive.
//!
//! `LOCI_RANDOM_SKETCHES=N` solves N sketches (150 by default, and the [`PINNED`] seeds), from
//! `LOCI_RANDOM_FIRST_SKETCH`; `LOCI_RANDOM_SKETCH_NUDGE=D` moves the free points by up to D
//! (0.05 by default; from further off only wrong answers count, not a solve that gives up);
//! `LOCI_RANDOM_SKETCH_VERBOSE=1` prints each one's constraints and outcomes;
//! `LOCI_RANDOM_SKETCH_DUMP=DIR` writes each sketch as a sketch file, `DIR/seed-N.json` as
//! moved off before its first solve and `DIR/seed-N-changed.json` with its dimension changed,
//! for `loci solve` and `loci check`.

#[path = "../common/mod.rs"]
mod common;
mod drawing;

use common::rng::Rng;
use drawing::{dist, drawing, far_off};
use loci::format::sketch::SketchFile;
use loci::sketch::{PointId, Sketch, SketchConstraintId, SketchReport, Soft, Spec};
use loci::Outcome;

/// How far a constraint may miss (model units; degrees for angles) once solved.
const HOLDS: f64 = 1e-6;

/// How far a point may move when a sketch that holds is solved again.
const STILL: f64 = 1e-9;

/// How far every free point is moved off the drawing before the first solve.
const NUDGE: f64 = 0.05;

/// How many times the drawing's size a point may end from where it was, the size being the
/// farthest coordinate or the largest dimension, and at least one. Parallel and perpendicular
/// are judged by the sine and cosine of an angle, and two sides that meet can be parallel to
/// within any sine when their corner runs off towards infinity; such a placement holds no
/// constraint in the sense meant, however small its residuals.
const FAR: f64 = 1e4;

/// What a soft constraint keeps, read from the drawing.
fn kept_value(s: &Sketch, soft: Soft) -> f64 {
    match soft {
        Soft::LineLength(l) => {
            let [a, b] = s.line(l);
            dist(a, b)
        }
        Soft::ArcRadius(a) => s.arc(a).radius,
        Soft::ArcStart(a) => s.arc(a).start_angle,
        Soft::ArcEnd(a) => s.arc(a).end_angle,
    }
}

fn coordinates(s: &Sketch, points: &[PointId]) -> Vec<[f64; 2]> {
    points.iter().map(|&p| s.point(p)).collect()
}

/// The constraints that miss by more than [`HOLDS`], with their residuals.
fn missing(s: &Sketch, ids: &[SketchConstraintId]) -> Vec<(SketchConstraintId, f64)> {
    ids.iter()
        .map(|&id| {
            (
                id,
                s.measure(id).expect("a constraint of the sketch").residual,
            )
        })
        .filter(|&(_, r)| !(r <= HOLDS))
        .collect()
}

/// Checks one solve against the drawing; the findings, if any.
fn check_solve(
    s: &mut Sketch,
    ids: &[SketchConstraintId],
    points: &[PointId],
    must_hold: bool,
) -> (SketchReport, Vec<String>) {
    let before = coordinates(s, points);
    let soft_before: Vec<(Soft, f64)> = s
        .soft_constraints()
        .into_iter()
        .map(|k| (k, kept_value(s, k)))
        .collect();
    let r = s.solve().expect("the default settings are valid");
    let mut found = Vec::new();
    if r.outcome.is_ok() {
        let size = before
            .iter()
            .flat_map(|p| p.iter().map(|v| v.abs()))
            .chain(
                ids.iter()
                    .filter_map(|&id| s.constraint(id).and_then(|c| c.0.value()).map(f64::abs)),
            )
            .fold(1.0, f64::max);
        let farthest = coordinates(s, points)
            .iter()
            .zip(&before)
            .map(|(a, b)| dist(*a, *b))
            .fold(0.0, f64::max);
        if !(farthest <= FAR * size) {
            found.push(format!(
                "said {:?}, with a point moved {farthest:e} in a drawing of size {size}",
                r.outcome
            ));
        }
        for (id, res) in missing(s, ids) {
            found.push(format!(
                "said {:?}, but {} {:?} misses by {res:e}",
                r.outcome,
                s.constraint(id).map_or("?", |c| c.0.name()),
                id
            ));
        }
        for (shape, _) in s.shapes().collect::<Vec<_>>() {
            if let Some(c) = s.as_circle(shape) {
                let radius = s.circle(c).1;
                if !(radius > 0.0) {
                    found.push(format!(
                        "said {:?}, with a circle of radius {radius}",
                        r.outcome
                    ));
                }
            }
        }
        for k in &r.kept {
            let Some(&(_, v)) = soft_before.iter().find(|(w, _)| w == k) else {
                found.push(format!("kept {k:?}, which was not a soft constraint"));
                continue;
            };
            let now = kept_value(s, *k);
            let off = match k {
                // Degrees, either way round.
                Soft::ArcStart(_) | Soft::ArcEnd(_) => {
                    ((now - v + 180.0).rem_euclid(360.0) - 180.0).abs()
                }
                _ => (now - v).abs(),
            };
            if !(off <= HOLDS) {
                found.push(format!("kept {k:?}, but it moved by {off:e}"));
            }
        }
    } else {
        if must_hold {
            found.push(format!(
                "a sketch that holds as drawn read {:?} (failed {:?})",
                r.outcome, r.failed
            ));
        }
        // Within rounding: a point fixed where merged coordinates (a horizontal line between
        // two fixed points) agree only to the last bit is put back exactly where it was fixed.
        let moved = coordinates(s, points)
            .iter()
            .zip(&before)
            .map(|(a, b)| dist(*a, *b))
            .fold(0.0, f64::max);
        if !(moved <= STILL) {
            found.push(format!("read {:?} and moved the drawing", r.outcome));
        }
        if r.failed.is_empty() {
            found.push(format!("read {:?} and named nothing", r.outcome));
        }
    }
    (r, found)
}

/// Drags a free point ten steps of up to a tenth of the drawing each way: after every step,
/// every user constraint holds and every circle's radius is positive (a drag keeps a step only
/// when its solve succeeds).
fn dragged(
    s: &mut Sketch,
    ids: &[SketchConstraintId],
    fixed: &[PointId],
    points: &[PointId],
    rng: &mut Rng,
) -> Vec<String> {
    let free: Vec<PointId> = points
        .iter()
        .copied()
        .filter(|p| !fixed.contains(p))
        .collect();
    if free.is_empty() {
        return Vec::new();
    }
    let p = free[rng.below(free.len())];
    let Ok(mut drag) = s.begin_drag(p) else {
        // A point of a locked or fixed shape the test did not see as fixed: nothing to drag.
        return Vec::new();
    };
    let mut found = Vec::new();
    for k in 0..10 {
        let g = drag.grip();
        let target = [g[0] + rng.uniform(-1.0, 1.0), g[1] + rng.uniform(-1.0, 1.0)];
        let step = drag.step(target).expect("a finite target");
        let sk = drag.sketch();
        for (id, r) in missing(sk, ids) {
            found.push(format!(
                "drag step {k} ({:?}): {} {id:?} misses by {r:e}",
                step.outcome,
                sk.constraint(id).map_or("?", |c| c.0.name())
            ));
        }
        for (shape, _) in sk.shapes().collect::<Vec<_>>() {
            if let Some(c) = sk.as_circle(shape) {
                let radius = sk.circle(c).1;
                if !(radius > 0.0) {
                    found.push(format!("drag step {k}: a circle of radius {radius}"));
                }
            }
        }
    }
    found
}

/// Writes `s` to `LOCI_RANDOM_SKETCH_DUMP/seed-{name}.json` when that is set.
fn dump(s: &Sketch, name: &str) {
    if let Ok(dir) = std::env::var("LOCI_RANDOM_SKETCH_DUMP") {
        let path = std::path::Path::new(&dir).join(format!("seed-{name}.json"));
        let text = SketchFile::from_sketch(s, |_| None).to_json();
        std::fs::create_dir_all(&dir).expect("a directory to write to");
        std::fs::write(&path, text).expect("a file to write to");
    }
}

/// Runs one seed; the findings, if any.
fn run(seed: u64, nudge: f64, verbose: bool) -> Vec<String> {
    let (mut s, ids, points) = drawing(seed);
    let mut found: Vec<String> = missing(&s, &ids)
        .into_iter()
        .map(|(id, r)| {
            format!(
                "drawn to hold, but {:?} misses by {r:e} (a fault of this test)",
                s.constraint(id).map(|c| c.0)
            )
        })
        .collect();
    if !found.is_empty() {
        return found;
    }
    // The free points move; fixed ones would go back before the solve starts.
    let fixed: Vec<PointId> = ids
        .iter()
        .flat_map(|&id| match s.constraint(id) {
            Some((Spec::Fix { point }, _)) => s.as_point(*point).into_iter().collect(),
            Some((Spec::FixShape { shape }, _)) => s.defining_points(*shape),
            _ => Vec::new(),
        })
        .collect();
    let mut rng = Rng(seed ^ 0xAB0F_F5E7);
    for &p in &points {
        if !fixed.contains(&p) {
            let [x, y] = s.point(p);
            s.move_point(
                p,
                [
                    x + rng.uniform(-nudge, nudge),
                    y + rng.uniform(-nudge, nudge),
                ],
            )
            .expect("a point of the sketch");
        }
    }
    dump(&s, &seed.to_string());
    // From further off than the default, a sketch may fold onto another branch that cannot
    // close, and Newton may say so: only wrong answers count there.
    let (r, f) = check_solve(&mut s, &ids, &points, nudge <= NUDGE);
    let f: Vec<String> = f.into_iter().map(|f| format!("moved off: {f}")).collect();
    if verbose {
        println!(
            "seed {seed}: {} constraints {:?}: {:?}, failed {:?}, {} soft kept, {} dropped",
            ids.len(),
            ids.iter()
                .map(|&id| s.constraint(id).map_or("?", |c| c.0.name()))
                .collect::<Vec<_>>(),
            r.outcome,
            r.failed,
            r.kept.len(),
            r.dropped.len()
        );
    }
    found.extend(f);
    if !r.outcome.is_ok() {
        return found;
    }
    // Solved again where it holds, nothing moves.
    let solved = coordinates(&s, &points);
    let again = s.solve().expect("the default settings are valid");
    let moved = coordinates(&s, &points)
        .iter()
        .zip(&solved)
        .map(|(a, b)| dist(*a, *b))
        .fold(0.0, f64::max);
    if !again.outcome.is_ok() || !(moved <= STILL) {
        found.push(format!(
            "solved again where it holds: {:?}, a point moved by {moved:e}",
            again.outcome
        ));
    }
    found.extend(dragged(&mut s, &ids, &fixed, &points, &mut rng));
    // One dimension changed by a lot.
    let dims: Vec<SketchConstraintId> = ids
        .iter()
        .copied()
        .filter(|&id| s.constraint(id).is_some_and(|c| c.0.value().is_some()))
        .collect();
    if dims.is_empty() {
        return found;
    }
    let id = dims[rng.below(dims.len())];
    let v = s
        .constraint(id)
        .and_then(|c| c.0.value())
        .expect("a dimension");
    let changed = far_off(s.constraint(id).map_or("?", |c| c.0.name()), v);
    s.set_value(id, changed).expect("a dimension takes a value");
    dump(&s, &format!("{seed}-changed"));
    let (r, f) = check_solve(&mut s, &ids, &points, false);
    let f: Vec<String> = f
        .into_iter()
        .map(|f| format!("{id:?} changed to {changed}: {f}"))
        .collect();
    if verbose {
        println!(
            "  {id:?} to {changed}: {:?}, failed {:?}",
            r.outcome, r.failed
        );
    }
    found.extend(f);
    if !r.outcome.is_ok() && !r.failed.is_empty() {
        // The named constraints fail on their own.
        let mut alone = s.clone();
        for &other in &ids {
            if !r.failed.contains(&other) {
                alone
                    .remove_constraint(other)
                    .expect("a constraint of the sketch");
            }
        }
        let again = alone.solve().expect("the default settings are valid");
        if again.outcome.is_ok() && r.outcome == Outcome::Inconsistent {
            found.push(format!(
                "named {:?} as inconsistent, but they hold on their own",
                r.failed
            ));
        }
    }
    found
}

/// Seeds that found a wrong answer, run besides the range asked for: 742, a fixed point held
/// where a solve from a solution built another way had moved it (`okay`, the point off its
/// place); 1,274, a circle whose radius went negative in the first solve; 105, a dimension
/// changed and a circle's radius taken through zero (`okay`, the circle drawn at a negative
/// radius); 1,169, a circle's radius taken through zero by a drag step; 8,300, a satisfiable
/// set named in a conflict, its solution past a fold that the first scattered starts missed;
/// 31,931, a conflict named without the lock it needed, its other members solving alone with
/// the drawing scaled 60 times over.
const PINNED: [u64; 6] = [742, 1274, 105, 1169, 8300, 31_931];

/// Seeds that found a wrong answer from further off, with how far: 20,859, a hexagon whose
/// four sides are held parallel, solved by sending their shared corner to (-7.7e8, -2.7e8),
/// where the sine between the sides was 1.2e-10 (`redundant_okay`, a point off the line
/// through the others).
const PINNED_FROM_AFAR: [(u64, f64); 1] = [(20_859, 0.5)];

#[test]
fn random_sketches_solve_back_and_their_verdicts_hold() {
    let count: u64 = std::env::var("LOCI_RANDOM_SKETCHES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(150);
    let first: u64 = std::env::var("LOCI_RANDOM_FIRST_SKETCH")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0);
    let verbose = std::env::var("LOCI_RANDOM_SKETCH_VERBOSE").is_ok_and(|v| v == "1");
    let nudge: f64 = std::env::var("LOCI_RANDOM_SKETCH_NUDGE")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(NUDGE);
    let mut failures = Vec::new();
    let seeds = (first..first + count).chain(PINNED).map(|s| (s, nudge));
    for (seed, nudge) in seeds.chain(PINNED_FROM_AFAR) {
        for f in run(seed, nudge, verbose) {
            failures.push(format!("seed {seed}: {f}"));
        }
    }
    for f in &failures {
        println!("{f}");
    }
    println!(
        "{} sketches, {} findings",
        count as usize + PINNED.len() + PINNED_FROM_AFAR.len(),
        failures.len()
    );
    assert!(failures.is_empty(), "{} findings", failures.len());
}
