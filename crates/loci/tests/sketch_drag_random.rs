//! Random linkages dragged along random paths: after every step each constraint holds (checked
//! here from the points, not from the solver's word), no rigid triangle turns over (three
//! points with all three distances fixed keep their orientation: their area is fixed by the
//! lengths, so a change of sign is a jump, never a motion), and no hinge of two bars changes
//! the sense it bends in without passing through straight.
//!
//! The linkages: rigid triangles hinged at shared corners, bars between points, one or two
//! fixed points, some bars drawn as lines (whose triangles the drag watches itself) and some
//! as bare distances between points (which it does not). Their lengths are read from where the
//! points are drawn, so every sketch holds at its start.
//!
//! `LOCI_RANDOM_DRAGS=N` drags N linkages (12 by default), from `LOCI_RANDOM_FIRST_DRAG`.

mod common;

use common::rng::Rng;
use loci::sketch::{PointId, Sketch};

/// Steps of each drag.
const STEPS: u32 = 150;

/// How far a constraint may miss once a step has been taken.
const HOLDS: f64 = 1e-6;

/// A hinge whose sine of bend changes sign by more than this in one solve jumped to the other
/// branch rather than passing through straight.
const BENT: f64 = 0.1;

/// A linkage: its points, its bars (`(a, b, length)`) and its fixed points.
struct Linkage {
    sketch: Sketch,
    points: Vec<PointId>,
    start: Vec<[f64; 2]>,
    bars: Vec<(usize, usize, f64)>,
    /// Whether each bar is drawn as a line (else a distance between bare points).
    lines: Vec<bool>,
    fixed: Vec<usize>,
    /// The size of the drawing, for the steps of the path and the jumps.
    size: f64,
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

fn area(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
}

/// A chain of rigid triangles from a fixed corner, each hinged to the one before at a corner,
/// with extra bars closing loops (some to a second fixed point), as long as some freedom is
/// left.
fn linkage(seed: u64) -> Linkage {
    let mut rng = Rng(seed ^ 0xD4A6_0000);
    let size = 10.0;
    let mut pts: Vec<[f64; 2]> = vec![[0.0, 0.0]];
    let mut bars: Vec<(usize, usize)> = Vec::new();
    let triangles = 1 + rng.below(4);
    let mut hinge = 0;
    for _ in 0..triangles {
        // Two new corners near the hinge, the triangle not too thin.
        let h = pts[hinge];
        let (b, c) = loop {
            let b = [h[0] + rng.uniform(-3.0, 3.0), h[1] + rng.uniform(-3.0, 3.0)];
            let c = [h[0] + rng.uniform(-3.0, 3.0), h[1] + rng.uniform(-3.0, 3.0)];
            let s = dist(h, b).max(dist(h, c)).max(dist(b, c));
            if area(h, b, c).abs() > 0.15 * s * s && dist(h, b) > 0.5 && dist(h, c) > 0.5 {
                break (b, c);
            }
        };
        let (ib, ic) = (pts.len(), pts.len() + 1);
        pts.push(b);
        pts.push(c);
        bars.extend([(hinge, ib), (hinge, ic), (ib, ic)]);
        hinge = if rng.below(2) == 0 { ib } else { ic };
    }
    let mut fixed = vec![0];
    // Loops closed: a bar from a corner to a new fixed point, or between two corners of
    // different triangles, while at least one freedom is left.
    let freedoms = |pts: &[[f64; 2]], bars: &[(usize, usize)], fixed: &[usize]| {
        2 * pts.len() as i64 - bars.len() as i64 - 2 * fixed.len() as i64
    };
    for _ in 0..rng.below(3) {
        if rng.below(2) == 0 {
            let corner = 1 + rng.below(pts.len() - 1);
            let c = pts[corner];
            let g = [c[0] + rng.uniform(-3.0, 3.0), c[1] + rng.uniform(-3.0, 3.0)];
            let ig = pts.len();
            pts.push(g);
            if freedoms(
                &pts,
                &[bars.clone(), vec![(corner, ig)]].concat(),
                &[fixed.clone(), vec![ig]].concat(),
            ) < 1
            {
                pts.pop();
                continue;
            }
            bars.push((corner, ig));
            fixed.push(ig);
        } else {
            let a = rng.below(pts.len());
            let b = rng.below(pts.len());
            if a == b
                || bars
                    .iter()
                    .any(|&(p, q)| (p, q) == (a, b) || (p, q) == (b, a))
            {
                continue;
            }
            if freedoms(&pts, &[bars.clone(), vec![(a, b)]].concat(), &fixed) < 1 {
                continue;
            }
            bars.push((a, b));
        }
    }
    let mut sketch = Sketch::new();
    let points: Vec<PointId> = pts
        .iter()
        .map(|p| sketch.add_point(p[0], p[1]).unwrap())
        .collect();
    let mut with_len = Vec::new();
    let mut lines = Vec::new();
    for &(a, b) in &bars {
        let len = dist(pts[a], pts[b]);
        let as_line = rng.below(2) == 0;
        lines.push(as_line);
        if as_line {
            let l = sketch.add_line(points[a], points[b]).unwrap();
            sketch.length(l, len).unwrap();
        } else {
            sketch.distance(points[a], points[b], len).unwrap();
        }
        with_len.push((a, b, len));
    }
    for &f in &fixed {
        sketch.fix(points[f]).unwrap();
    }
    Linkage {
        sketch,
        points,
        start: pts,
        bars: with_len,
        lines,
        fixed,
        size,
    }
}

/// The rigid triangles: triples of points with a bar on every side.
fn rigid_triangles(l: &Linkage) -> Vec<[usize; 3]> {
    let n = l.points.len();
    let has = |a: usize, b: usize| {
        l.bars
            .iter()
            .any(|&(p, q, _)| (p, q) == (a, b) || (p, q) == (b, a))
    };
    let mut out = Vec::new();
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                if has(a, b) && has(b, c) && has(a, c) {
                    out.push([a, b, c]);
                }
            }
        }
    }
    out
}

/// What went wrong with one linkage's drag, if anything.
/// What one linkage's drag showed: rigid triangles watched, the largest move of a point per
/// move of the cursor while the grip followed it, steps where it did, and the time the steps
/// took.
struct Dragged {
    triangles: usize,
    worst_jump: f64,
    /// Steps taken in pieces over which a hinge came to bend the other way: through straight
    /// in short pieces, or swung round where the grip's nearest reachable place jumped (as a
    /// pin's does when the cursor crosses its pivot).
    swings: usize,
    followed: usize,
    took: f64,
    /// The grip's distance from the cursor after each step, over the drawing's size, summed.
    missed: f64,
}

fn drag_one(seed: u64) -> Result<Dragged, String> {
    let mut l = linkage(seed);
    let mut rng = Rng(seed ^ 0x0D2A_6000);
    let free: Vec<usize> = (0..l.points.len())
        .filter(|i| !l.fixed.contains(i))
        .collect();
    let grip = free[rng.below(free.len())];
    let triangles = rigid_triangles(&l);
    // Hinges: two bars meeting at a point, with their lengths.
    let mut hinges = Vec::new();
    for (i, &(a0, b0, l0)) in l.bars.iter().enumerate() {
        for &(a1, b1, l1) in &l.bars[i + 1..] {
            let shared = [
                (a0, b0, a1, b1),
                (b0, a0, a1, b1),
                (a0, b0, b1, a1),
                (b0, a0, b1, a1),
            ]
            .into_iter()
            .find(|&(_, p, q, _)| p == q);
            if let Some((a, b, _, c)) = shared {
                if a != c {
                    hinges.push(([a, b, c], l0, l1));
                }
            }
        }
    }
    if std::env::var("LOCI_RANDOM_DRAG_VERBOSE").is_ok() {
        eprintln!(
            "seed {seed}: points {:?}, bars {:?} (lines {:?}), fixed {:?}, grip {grip}",
            l.start, l.bars, l.lines, l.fixed
        );
    }
    let signs: Vec<f64> = triangles
        .iter()
        .map(|t| area(l.start[t[0]], l.start[t[1]], l.start[t[2]]).signum())
        .collect();
    let bars = l.bars.clone();
    let fixed: Vec<(usize, [f64; 2])> = l.fixed.iter().map(|&f| (f, l.start[f])).collect();
    let points = l.points.clone();
    let size = l.size;
    let read = |s: &Sketch| -> Vec<[f64; 2]> { points.iter().map(|&p| s.point(p)).collect() };
    let mut drag = l
        .sketch
        .begin_drag(points[grip])
        .map_err(|e| format!("begin_drag: {e}"))?;
    let mut at = read(drag.sketch());
    let mut target = at[grip];
    let mut heading = rng.uniform(0.0, std::f64::consts::TAU);
    let mut worst_jump = 0.0f64;
    let mut swings = 0;
    // Whether the grip reached the cursor at the last step.
    let mut followed = true;
    let (mut steps_followed, mut took_all, mut missed) = (0, 0.0, 0.0);
    let steps = STEPS;
    for k in 0..steps {
        // A smooth wandering path, with now and then a long jump of the cursor.
        heading += rng.uniform(-0.4, 0.4);
        // Back towards the drawing when the cursor has wandered off.
        if target[0].hypot(target[1]) > 0.6 * size {
            heading = (-target[1]).atan2(-target[0]) + rng.uniform(-0.5, 0.5);
        }
        let h = if k % 50 == 49 {
            0.3 * size
        } else {
            0.02 * size
        };
        let prev_target = target;
        target = [target[0] + h * heading.cos(), target[1] + h * heading.sin()];
        let clock = std::time::Instant::now();
        let st = drag.step(target).map_err(|e| format!("step {k}: {e}"))?;
        let took = clock.elapsed().as_secs_f64() * 1e3;
        took_all += took;
        missed += st.miss / size;
        let now = read(drag.sketch());
        if std::env::var("LOCI_RANDOM_DRAG_VERBOSE").is_ok() {
            eprintln!("step {k}: {took:.3} ms, target {target:?} {st:?}\n  points {now:?}");
        }
        // The constraints hold wherever the drag left the sketch, whatever it said.
        for &(a, b, len) in &bars {
            let miss = (dist(now[a], now[b]) - len).abs();
            if miss > HOLDS * len.max(1.0) {
                return Err(format!(
                    "step {k} ({st:?}): the bar {a}-{b} of length {len} reads {}",
                    dist(now[a], now[b])
                ));
            }
        }
        for &(f, p) in &fixed {
            if dist(now[f], p) > HOLDS {
                return Err(format!(
                    "step {k}: the fixed point {f} moved to {:?}",
                    now[f]
                ));
            }
        }
        for (t, &sign) in triangles.iter().zip(&signs) {
            let s = area(now[t[0]], now[t[1]], now[t[2]]).signum();
            if s != sign {
                return Err(format!(
                    "step {k} ({st:?}): the rigid triangle {t:?} turned over"
                ));
            }
        }
        // Every hinge (two bars meeting at a point) keeps the sense in which it bends, unless
        // it passes through straight, in short pieces: in a step taken whole (one solve), a
        // sense that changes by more than `BENT` is a jump to the linkage's other branch. A
        // step reached in one solve and closed on the cursor in a second is two pieces, each
        // within `BENT` of straight where it crosses (seed 20,439, step 63: 0.153 to -0.0001,
        // a hinge folded flat as the cursor passed, which bends on the other side in the
        // steps after, a little more at each). How far the points moved against how far the
        // cursor did is only measured: near the centre of its reach an arm swings round fast
        // as the cursor passes, without changing branch.
        let mut swung = false;
        for &([a, b, c], lab, lbc) in &hinges {
            let bend = |p: &[[f64; 2]]| 2.0 * area(p[a], p[b], p[c]) / (lab * lbc);
            let (was, is) = (bend(&at), bend(&now));
            if was * is < 0.0 && (was - is).abs() > BENT {
                if st.refused == 0 && st.pieces <= 1 {
                    return Err(format!(
                        "step {k} ({st:?}): the hinge {a}-{b}-{c} turned from {was:.3} to {is:.3}"
                    ));
                }
                swung = true;
            }
        }
        swings += usize::from(swung);
        let follows = st.reached && st.miss <= HOLDS * size;
        if follows && followed {
            let moved = at
                .iter()
                .zip(&now)
                .map(|(a, b)| dist(*a, *b))
                .fold(0.0f64, f64::max);
            worst_jump = worst_jump.max(moved / dist(prev_target, target));
        }
        followed = follows;
        steps_followed += usize::from(follows);
        at = now;
    }
    Ok(Dragged {
        triangles: triangles.len(),
        worst_jump,
        swings,
        followed: steps_followed,
        took: took_all,
        missed,
    })
}

#[test]
fn random_linkages_dragged_along_random_paths_hold_and_never_flip() {
    // A hinge folded flat in a step of two pieces (see `drag_one`), found past the
    // seeds run by default.
    if let Err(e) = drag_one(20_439) {
        panic!("seed 20439: {e}");
    }
    let n: u64 = std::env::var("LOCI_RANDOM_DRAGS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(12);
    let first: u64 = std::env::var("LOCI_RANDOM_FIRST_DRAG")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0);
    let mut failures = Vec::new();
    let (mut triangles, mut worst, mut followed, mut took) = (0, 0.0f64, 0, 0.0);
    let (mut missed, mut steps) = (0.0, 0);
    let mut swings = 0;
    for seed in first..first + n {
        match drag_one(seed) {
            Ok(d) => {
                steps += STEPS;
                triangles += d.triangles;
                worst = worst.max(d.worst_jump);
                swings += d.swings;
                followed += d.followed;
                took += d.took;
                missed += d.missed;
            }
            Err(e) => failures.push(format!("seed {seed}: {e}")),
        }
    }
    eprintln!(
        "{n} linkages dragged, {triangles} rigid triangles watched, the grip on the cursor at \
         {followed} steps, largest move per cursor move there {worst:.1}, {swings} steps in \
         pieces bending a hinge the other way, the grip {:.4} of the drawing's size from the \
         cursor on average, steps {took:.0} ms in all; {} failed",
        missed / f64::from(steps),
        failures.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
