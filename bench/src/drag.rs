//! The drag benchmark: one drag path of 600 steps on sketches of 100, 1,000 and 10,000
//! shapes, timing every step of `loci::sketch::Drag` and counting the steps after which any
//! triangle of the sketch is turned over.
//!
//! Two sketches at each size:
//! - **four-bar among rectangles**: a crank-rocker linkage with a coupler triangle, dragged by
//!   its crank through a full turn, beside fully dimensioned rectangles that fill the sketch up
//!   to the size. The drag touches one small component; the rest is never solved.
//! - **hinged triangles**: a chain of rigid triangles joined at their corners, the first corner
//!   fixed, the last dragged once round a circle of radius 1. Every shape moves at every step.

use loci::sketch::{LineId, PointId, Sketch};
use std::time::Instant;

/// The figures of one run.
#[derive(Clone, Debug)]
pub struct DragFigures {
    /// Which sketch.
    pub sketch: &'static str,
    /// Shapes in it.
    pub shapes: usize,
    /// Steps run.
    pub steps: usize,
    /// The first step, which compiles the equations (milliseconds).
    pub first_ms: f64,
    /// Median step time after the first (milliseconds).
    pub median_ms: f64,
    /// The 99th percentile of the step times after the first (milliseconds): the worst step
    /// without the few that the machine's other work preempted.
    pub p99_ms: f64,
    /// Worst step time after the first (milliseconds).
    pub worst_ms: f64,
    /// Steps after which some triangle was turned over.
    pub flipped: usize,
    /// Steps that did not reach their target (the grip stopped short).
    pub short: usize,
}

/// A sketch to drag: the sketch, the shape dragged, its path, and its triangles.
struct Case {
    sketch: Sketch,
    grip: PointId,
    path: Vec<[f64; 2]>,
    triangles: Vec<[PointId; 3]>,
}

fn line(s: &mut Sketch, a: PointId, b: PointId, len: Option<f64>) -> LineId {
    let l = s.add_line(a, b).expect("points exist");
    if let Some(v) = len {
        s.length(l, v).expect("a line");
    }
    l
}

fn four_bar_among_rectangles(size: usize, steps: usize) -> Case {
    let mut s = Sketch::new();
    let p = |s: &mut Sketch, x: f64, y: f64| s.add_point(x, y).expect("finite");
    let a = p(&mut s, 0.0, 0.0);
    let d = p(&mut s, 4.0, 0.0);
    let b = p(&mut s, 1.0, 0.0);
    let c = p(&mut s, 3.6667, 2.9814);
    let e = p(&mut s, 1.588, 2.158);
    s.fix(a).expect("a point");
    s.fix(d).expect("a point");
    line(&mut s, a, b, Some(1.0));
    line(&mut s, b, c, Some(4.0));
    line(&mut s, d, c, Some(3.0));
    line(&mut s, b, e, Some(2.5));
    line(&mut s, c, e, Some(2.5));
    let mut n = 10;
    let mut k = 0;
    while n + 8 <= size {
        let (x0, y0) = (10.0 + 6.0 * (k % 40) as f64, 6.0 * (k / 40) as f64);
        let q = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]
            .map(|o| p(&mut s, x0 + o[0], y0 + o[1]));
        let l: Vec<LineId> = (0..4)
            .map(|i| line(&mut s, q[i], q[(i + 1) % 4], None))
            .collect();
        s.fix(q[0]).expect("a point");
        s.horizontal(l[0]).expect("a line");
        s.horizontal(l[2]).expect("a line");
        s.vertical(l[1]).expect("a line");
        s.vertical(l[3]).expect("a line");
        s.length(l[0], 4.0).expect("a line");
        s.length(l[1], 2.0).expect("a line");
        n += 8;
        k += 1;
    }
    let rep = s.solve().expect("solves");
    assert!(rep.outcome.is_ok(), "{rep:?}");
    let path = (1..=steps)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / steps as f64;
            [t.cos(), t.sin()]
        })
        .collect();
    Case {
        sketch: s,
        grip: b,
        path,
        triangles: vec![[b, c, e]],
    }
}

fn hinged_triangles(size: usize, steps: usize) -> Case {
    let mut s = Sketch::new();
    let n = ((size - 1) / 5).max(1);
    let h = 3f64.sqrt() / 2.0;
    let mut corner = s.add_point(0.0, 0.0).expect("finite");
    s.fix(corner).expect("a point");
    let mut triangles = Vec::new();
    for i in 0..n {
        let x = i as f64;
        let apex = s
            .add_point(x + 0.5, if i % 2 == 0 { h } else { -h })
            .expect("finite");
        let next = s.add_point(x + 1.0, 0.0).expect("finite");
        line(&mut s, corner, apex, Some(1.0));
        line(&mut s, apex, next, Some(1.0));
        line(&mut s, corner, next, Some(1.0));
        triangles.push([corner, apex, next]);
        corner = next;
    }
    let rep = s.solve().expect("solves");
    assert!(rep.outcome.is_ok(), "{rep:?}");
    let end = s.point(corner);
    let path = (1..=steps)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / steps as f64;
            [end[0] - 1.0 + t.cos(), end[1] + t.sin()]
        })
        .collect();
    Case {
        sketch: s,
        grip: corner,
        path,
        triangles,
    }
}

fn orientation(s: &Sketch, t: &[PointId; 3]) -> f64 {
    let [a, b, c] = t.map(|p| s.point(p));
    ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).signum()
}

fn run(name: &'static str, mut case: Case) -> DragFigures {
    let shapes = case.sketch.shapes().count();
    let steps = case.path.len();
    let mut times = Vec::with_capacity(steps);
    let (mut flipped, mut short) = (0, 0);
    let mut signs: Vec<f64> = case
        .triangles
        .iter()
        .map(|t| orientation(&case.sketch, t))
        .collect();
    let mut drag = case.sketch.begin_drag(case.grip).expect("a free point");
    for target in &case.path {
        let t0 = Instant::now();
        let st = drag.step(*target).expect("the solver starts");
        times.push(t0.elapsed().as_secs_f64() * 1e3);
        short += usize::from(!st.reached);
        let now: Vec<f64> = case
            .triangles
            .iter()
            .map(|t| orientation(drag.sketch(), t))
            .collect();
        flipped += usize::from(now.iter().zip(&signs).any(|(a, b)| a != b));
        signs = now;
    }
    drop(drag);
    let first_ms = times[0];
    let mut rest = times[1..].to_vec();
    rest.sort_by(f64::total_cmp);
    DragFigures {
        sketch: name,
        shapes,
        steps,
        first_ms,
        median_ms: rest[rest.len() / 2],
        p99_ms: rest[(rest.len() * 99) / 100],
        worst_ms: rest[rest.len() - 1],
        flipped,
        short,
    }
}

/// Runs both sketches at each size.
#[must_use]
pub fn drag_benchmark(sizes: &[usize], steps: usize) -> Vec<DragFigures> {
    let mut out = Vec::new();
    for &n in sizes {
        out.push(run(
            "four-bar among rectangles",
            four_bar_among_rectangles(n, steps),
        ));
        out.push(run("hinged triangles", hinged_triangles(n, steps)));
    }
    out
}

/// The figures as a markdown table.
#[must_use]
pub fn drag_table(figures: &[DragFigures]) -> String {
    let mut s = String::from(
        "| sketch | shapes | steps | first step (ms) | median step (ms) | 99th percentile (ms) | worst step (ms) | steps with a flip | steps stopped short |\n\
         | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n",
    );
    for f in figures {
        s.push_str(&format!(
            "| {} | {} | {} | {:.3} | {:.4} | {:.3} | {:.3} | {} | {} |\n",
            f.sketch,
            f.shapes,
            f.steps,
            f.first_ms,
            f.median_ms,
            f.p99_ms,
            f.worst_ms,
            f.flipped,
            f.short
        ));
    }
    s
}
