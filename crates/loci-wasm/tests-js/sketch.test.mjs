// The sketcher through the package: built by calls and from files, solved, read back,
// dragged, diagnosed, saved; bad calls throw SketchError naming the shape.
import { test } from "node:test";
import assert from "node:assert/strict";
import loci, { example } from "./load.mjs";

const { Sketch, SketchError, InputError, FormatError } = loci;

const dist = (p, q) => Math.hypot(p[0] - q[0], p[1] - q[1]);
const area = (a, b, c) => (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);

test("a line built by calls is fixed, horizontal and 10 long after a solve", () => {
  const s = new Sketch();
  const a = s.addPoint(0, 0);
  const b = s.addPoint(9, 1);
  const l = s.addLine(a, b);
  s.addConstraint({ type: "fix", point: a });
  s.addConstraint({ type: "horizontal", line: l });
  const len = s.addConstraint({ type: "length", line: l, value: 10 });
  const r = s.solve();
  assert.equal(r.outcome, "okay");
  assert.deepEqual(s.point(a), [0, 0]);
  const [x, y] = s.point(b);
  assert.ok(Math.abs(x - 10) < 1e-9 && Math.abs(y) < 1e-9, `${x}, ${y}`);
  assert.ok(Math.abs(s.measure(len).value - 10) < 1e-9);
  assert.ok(s.measure(len).residual < 1e-9);
  // Geometry comes packed as one Float64Array in the order of shapes().
  const g = s.geometry();
  assert.ok(g instanceof Float64Array);
  assert.equal(g.length, 2 + 2 + 4);
  assert.deepEqual(Array.from(g.slice(4)), [0, 0, x, y]);
  const c = s.check();
  assert.equal(c.dof, 0);
  assert.deepEqual(c.free, []);
  assert.deepEqual([...c.fixed].sort(), [a, b, l].sort());
});

test("a shape of the wrong kind throws SketchError naming it", () => {
  const s = new Sketch();
  const p = s.addPoint(0, 0, "P");
  assert.throws(
    () => s.addConstraint({ type: "length", line: p, value: 3 }),
    (e) => e instanceof SketchError && e.object === `shape ${p}` && /a point, but a line is expected/.test(e.message),
  );
  assert.throws(() => s.addLine(p, 4242), (e) => e instanceof SketchError && e.object === "shape 4242");
  assert.throws(() => s.addPoint(Number.NaN, 0), InputError);
  assert.throws(() => s.dragTo(1, 1), (e) => e instanceof InputError && /no drag/.test(e.message));
  assert.throws(() => s.addPoint(1, 1, "P"), (e) => e instanceof SketchError && e.object === "P");
  assert.throws(() => Sketch.fromJson("{ nope"), FormatError);
  assert.throws(
    () => Sketch.fromJson('{"sketch":{"points":[{"name":"a","x":0,"y":0}],"constraints":[{"type":"fix","point":"b"}]}}'),
    (e) => e instanceof SketchError && /#1/.test(e.object) && /names "b"/.test(e.message),
  );
  // Every error is an Error with a stack, and a LociError.
  try {
    s.addConstraint({ type: "horizontal", line: p });
    assert.fail("no error");
  } catch (e) {
    assert.ok(e instanceof Error && e instanceof loci.LociError && e.stack);
  }
});

test("conflicting constraints are named in the check and the solve", () => {
  const s = new Sketch();
  const a = s.addPoint(0, 0);
  const b = s.addPoint(5, 0);
  const l = s.addLine(a, b);
  s.addConstraint({ type: "fix", point: a });
  s.addConstraint({ type: "length", line: l, value: 5 }, { name: "five" });
  s.addConstraint({ type: "distance", a, b, value: 7 }, { name: "seven" });
  const r = s.solve();
  assert.equal(r.outcome, "inconsistent");
  assert.ok(r.failed_names.some((n) => n.startsWith("five")) || r.failed_names.some((n) => n.startsWith("seven")), r.failed_names.join());
  const c = s.check();
  assert.equal(c.outcome, "inconsistent");
  assert.equal(c.conflicting.length, 1);
  const names = c.conflicting[0].map((id) => c.names[id]);
  assert.deepEqual(names.sort(), ["five (length)", "seven (distance)"]);
});

test("the four-bar linkage follows a dragged crank pin without flipping", () => {
  const s = Sketch.fromJson(example("sketches/four_bar.json"));
  assert.equal(s.solve().outcome, "okay");
  const byName = Object.fromEntries(s.shapes().map((x) => [x.name, x.id]));
  const [A, B, C, D, E] = ["A", "B", "C", "D", "E"].map((n) => byName[n]);
  const sign = Math.sign(area(s.point(B), s.point(C), s.point(E)));
  assert.equal(s.check().dof, 1);
  s.beginDrag(B);
  assert.ok(s.dragging);
  for (let k = 1; k <= 72; k++) {
    const t = (k * 5 * Math.PI) / 180;
    const step = s.dragTo(2 * Math.cos(t), 2 * Math.sin(t));
    assert.ok(step.outcome === "okay" || step.outcome === "redundant_okay", JSON.stringify(step));
    const [a, b, c, d, e] = [A, B, C, D, E].map((p) => s.point(p));
    assert.deepEqual(a, [0, 0]);
    assert.deepEqual(d, [4, 0]);
    for (const [p, q, want] of [[a, b, 1], [b, c, 4], [d, c, 3], [b, e, 2.5], [c, e, 2.5]]) {
      assert.ok(Math.abs(dist(p, q) - want) < 1e-7, `step ${k}: ${dist(p, q)} != ${want}`);
    }
    // The crank pin goes as far toward the target as the crank allows: along its direction.
    assert.ok(Math.abs(Math.atan2(b[1], b[0]) - Math.atan2(Math.sin(t), Math.cos(t))) < 1e-6, `step ${k}`);
    assert.equal(Math.sign(area(b, c, e)), sign, `step ${k}: the coupler triangle flipped`);
  }
  s.endDrag();
  assert.ok(!s.dragging);
  // The soft constraints are gone with the drag; the file written reads back the same.
  const again = Sketch.fromJson(s.toJson());
  assert.deepEqual(again.point(byName.B), s.point(B));
});

test("a free polyline dragged by its end keeps its lengths (soft constraints)", () => {
  const s = new Sketch();
  const p = [[0, 0], [1, 0], [2, 0], [3, 0]].map(([x, y]) => s.addPoint(x, y));
  const l = [0, 1, 2].map((i) => s.addLine(p[i], p[i + 1]));
  assert.deepEqual(
    s.softConstraints().map((x) => x.keeps),
    ["line_length", "line_length", "line_length"],
  );
  s.beginDrag(p[3]);
  const st = s.dragTo(2.5, 1);
  assert.ok(st.reached && st.miss < 1e-6, JSON.stringify(st));
  for (const x of l) assert.ok(Math.abs(s.lineLength(x) - 1) < 1e-7);
  s.endDrag();
});

test("circles and arcs: radius, equal radius, tangency, saved as .slvs", () => {
  const s = new Sketch();
  const c = s.addPoint(0, 0);
  const circle = s.addCircle(c, 2);
  const a0 = s.addPoint(5, 0);
  const a1 = s.addPoint(9, 0);
  const a2 = s.addPoint(5, 4);
  const arc = s.addArc(a0, a1, a2);
  s.addConstraint({ type: "fix", point: c });
  s.addConstraint({ type: "radius", shape: circle, value: 3 });
  s.addConstraint({ type: "equal_radius", a: circle, b: arc });
  s.addConstraint({ type: "tangent", a: circle, b: arc });
  assert.equal(s.solve().outcome, "okay");
  assert.equal(s.check().outcome, "okay");
  const [cx, cy] = s.point(a0);
  assert.ok(Math.abs(Math.hypot(cx, cy) - 6) < 1e-9, "outside tangency: centres 3 + 3 apart");
  assert.ok(Math.abs(s.radius(circle) - 3) < 1e-9);
  assert.ok(Math.abs(s.radius(arc) - 3) < 1e-9);
  const kinds = s.shapes().map((x) => x.kind);
  assert.deepEqual(kinds, ["point", "circle", "point", "point", "point", "arc"]);
  const bytes = s.toSlvs();
  assert.ok(bytes instanceof Uint8Array);
  assert.match(new TextDecoder("latin1").decode(bytes.slice(0, 40)), /SolveSpaceREVa/);
  const sys = loci.System.fromSlvs(bytes);
  const groups = sys.solveAll();
  assert.ok(groups.every((g) => g.ok), JSON.stringify(groups));
});
