//! Placements that hold only because a point ran off towards infinity are no answer.
//!
//! Parallel and perpendicular are written as the sine and cosine of the angle between two
//! lines, whatever their lengths. Two sides that meet at a corner and must be parallel get as
//! close to it as one likes when the corner runs off: the solve must not take that for a
//! solution, and must go on to the finite placement where there is one.

use loci::format::sketch::{LoadedSketch as Loaded, SketchFile};
use std::path::Path;

/// A hexagon `point_100`..`point_105` with its last side fixed, its first side perpendicular
/// to the second and fourth, the third parallel to the second and the fifth to the third: so
/// `point_101` to `point_105` lie on one line. `point_103` is on a circle. Drawn with the
/// points moved off by up to 0.5 (random sketch 20,859, cut down to what shows the fault).
const HEXAGON: &str = r#"{"sketch": {
 "points": [
  {"name": "point_100", "x": 1.9512667438711828, "y": -2.076428120833149},
  {"name": "point_101", "x": 3.817091642919169, "y": -6.591579226250502},
  {"name": "point_102", "x": 7.927218591739228, "y": -4.159796994581804},
  {"name": "point_103", "x": 10.913869388345779, "y": -2.733364713688316},
  {"name": "point_104", "x": 6.153982242767849, "y": -4.4951087757296},
  {"name": "point_105", "x": 3.1272450128734337, "y": -6.70568267385128},
  {"name": "point_112", "x": 11.102618232654098, "y": -4.501620361485243}],
 "lines": [
  {"name": "line_106", "a": "point_100", "b": "point_101"},
  {"name": "line_107", "a": "point_101", "b": "point_102"},
  {"name": "line_108", "a": "point_102", "b": "point_103"},
  {"name": "line_109", "a": "point_103", "b": "point_104"},
  {"name": "line_110", "a": "point_104", "b": "point_105"},
  {"name": "line_111", "a": "point_105", "b": "point_100"}],
 "circles": [{"name": "circle_114", "center": "point_112", "radius": 1.335320942049811}],
 "constraints": [
  {"type": "perpendicular", "a": "line_106", "b": "line_107"},
  {"type": "parallel", "a": "line_107", "b": "line_108"},
  {"type": "perpendicular", "a": "line_106", "b": "line_109"},
  {"type": "parallel", "a": "line_108", "b": "line_110"},
  {"type": "point_on_circle", "point": "point_103", "shape": "circle_114"},
  {"type": "fix_shape", "shape": "line_111"}]}}"#;

fn point(l: &Loaded, name: &str) -> [f64; 2] {
    l.sketch.point(l.sketch.as_point(l.shapes[name]).unwrap())
}

/// Solves `l` and checks the answer from the coordinates: every constraint holds, no point
/// ended more than 100 from the origin, `point_101` to `point_105` are on one line, and solved
/// again nothing moves.
fn solves_in_the_drawing(mut l: Loaded) {
    let r = l.sketch.solve().unwrap();
    assert!(r.outcome.is_ok(), "{r:?}");
    for (id, _) in l.sketch.constraints() {
        assert!(l.sketch.measure(id).unwrap().residual < 1e-9, "{id:?}");
    }
    let names: Vec<String> = l.shapes.keys().cloned().collect();
    let mut before = Vec::new();
    for name in &names {
        if let Some(p) = l.sketch.as_point(l.shapes[name]) {
            let [x, y] = l.sketch.point(p);
            assert!(x.hypot(y) < 100.0, "{name} at ({x}, {y})");
            before.push([x, y]);
        }
    }
    let (a, b) = (point(&l, "point_105"), point(&l, "point_101"));
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    for name in ["point_102", "point_103", "point_104"] {
        let p = point(&l, name);
        let off = (dx * (p[1] - a[1]) - dy * (p[0] - a[0])) / dx.hypot(dy);
        assert!(off.abs() < 1e-9, "{name} is {off} off the line");
    }
    let again = l.sketch.solve().unwrap();
    assert!(again.outcome.is_ok());
    let mut after = Vec::new();
    for name in &names {
        if let Some(p) = l.sketch.as_point(l.shapes[name]) {
            after.push(l.sketch.point(p));
        }
    }
    for (p, q) in before.iter().zip(&after) {
        assert!((p[0] - q[0]).hypot(p[1] - q[1]) < 1e-9);
    }
}

#[test]
fn a_corner_sent_towards_infinity_is_no_answer() {
    let l = SketchFile::from_json(HEXAGON).unwrap().load().unwrap();
    solves_in_the_drawing(l);
}

#[test]
fn the_whole_sketch_20859_solves_in_the_drawing() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../bench/data/sketch_point_thrown_to_infinity.json");
    let text = std::fs::read_to_string(path).unwrap();
    let l = SketchFile::from_json(&text).unwrap().load().unwrap();
    solves_in_the_drawing(l);
}
