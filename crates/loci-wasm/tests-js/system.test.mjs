// The SolveSpace model through the package: read from loci JSON, built by calls, solved,
// diagnosed, bulk values as Float64Array; errors name the object at fault.
import { test } from "node:test";
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import loci, { example } from "./load.mjs";

const { System, ModelError, SolveError, FormatError } = loci;

test("two points read from loci JSON solve to 10 apart and horizontal", () => {
  const sys = System.fromJson(example("two_points.json"));
  const r = sys.solveRequest();
  assert.equal(r.outcome, "okay");
  assert.equal(r.dof, 0);
  const [x1, y1, x2, y2] = [11, 12, 13, 14].map((h) => sys.value(h));
  assert.ok(Math.abs(Math.hypot(x2 - x1, y2 - y1) - 10) < 1e-9);
  assert.ok(Math.abs(y2 - y1) < 1e-9);
  assert.ok(sys.values() instanceof Float64Array);
  assert.equal(sys.values().length, sys.paramHandles().length);
  // Written and read back, bit for bit.
  const again = System.fromJson(sys.toJson());
  assert.deepEqual(Array.from(again.values()), Array.from(sys.values()));
});

/** A workplane in group 1 and two of its points 10 apart in group 2 (constraint 1), built by
 * calls. */
function twoPointsByCalls() {
  const sys = new System();
  [[1, 0], [2, 0], [3, 0], [4, 1], [5, 0], [6, 0], [7, 0]].forEach(([h, v]) => sys.addParam(h, 1, v));
  sys.addEntity({ h: 101, group: 1, type: "point_in_3d", params: [1, 2, 3] });
  sys.addEntity({ h: 102, group: 1, type: "normal_in_3d", params: [4, 5, 6, 7] });
  sys.addEntity({ h: 200, group: 1, type: "workplane", origin: 101, normal: 102 });
  [[11, 1], [12, 2], [13, 9], [14, 3]].forEach(([h, v]) => sys.addParam(h, 2, v));
  sys.addEntity({ h: 301, group: 2, type: "point_in_2d", workplane: 200, params: [11, 12] });
  sys.addEntity({ h: 302, group: 2, type: "point_in_2d", workplane: 200, params: [13, 14] });
  sys.addConstraint({ h: 1, group: 2, type: "pt_pt_distance", workplane: 200, pt_a: 301, pt_b: 302, val: 10 });
  return sys;
}

test("a system built by calls solves, and reports a conflict by constraint", () => {
  const sys = twoPointsByCalls();
  sys.addConstraint({ h: 2, group: 2, type: "where_dragged", workplane: 200, pt_a: 301 });
  const r = sys.solve(2);
  assert.equal(r.outcome, "okay");
  assert.equal(r.dof, 1);
  const d = Math.hypot(sys.value(13) - sys.value(11), sys.value(14) - sys.value(12));
  assert.ok(Math.abs(d - 10) < 1e-9);
  // A second distance that cannot hold with the first.
  sys.addConstraint({ h: 3, group: 2, type: "pt_pt_distance", workplane: 200, pt_a: 301, pt_b: 302, val: 12 });
  const bad = sys.solve(2);
  assert.equal(bad.outcome, "inconsistent");
  assert.deepEqual([...bad.failed].sort(), [1, 3]);
  const diag = sys.check(2);
  assert.equal(diag.conflicting.length, 1);
  assert.equal(sys.removeConstraint(3), true);
  assert.equal(sys.solve(2, { dragged: [13, 14], tolerance: 1e-12 }).outcome, "okay");
});

test("bad input throws ModelError, SolveError or FormatError naming the object", () => {
  const sys = new System();
  sys.addParam(1, 1, 0);
  assert.throws(() => sys.addParam(1, 1, 0), (e) => e instanceof ModelError && e.object === "param 1");
  sys.addEntity({ h: 5, group: 1, type: "point_in_3d", params: [1, 9, 1] });
  assert.throws(() => sys.solve(1), (e) => e instanceof ModelError && e.object === "entity 5" && /param 9/.test(e.message));
  const ok = System.fromJson(example("two_points.json"));
  assert.throws(() => ok.solve(7), (e) => e instanceof SolveError && e.object === "group 7" && /groups of this system are 1, 2/.test(e.message));
  assert.throws(() => ok.solve(2, { dragged: [99] }), (e) => e instanceof SolveError && e.object === "param 99");
  assert.throws(
    () => System.fromJson('{"params":[{"h":1,"group":1,"val":"x"}]}'),
    (e) => e instanceof FormatError && /line 1/.test(e.message),
  );
  assert.throws(() => System.fromSlvs(new Uint8Array([1, 2, 3])), FormatError);
  assert.throws(() => sys.setValues([1, 2, 3]), loci.InputError);
});

test("the report built from numbers is the report's JSON, field for field and in order", () => {
  // Okay, inconsistent (failed constraints), redundant: each solved from the same start by the
  // raw JSON call and by the wrapper.
  const build = (extra) => {
    const sys = twoPointsByCalls();
    extra.forEach((c) => sys.addConstraint(c));
    return sys;
  };
  const cases = [
    [],
    [{ h: 3, group: 2, type: "pt_pt_distance", workplane: 200, pt_a: 301, pt_b: 302, val: 12 }],
    [{ h: 4, group: 2, type: "pt_pt_distance", workplane: 200, pt_a: 302, pt_b: 301, val: 10 }],
  ];
  const outcomes = [];
  for (const extra of cases) {
    const viaJson = JSON.parse(build(extra).inner.solve(2, new Uint32Array(), ""));
    const viaNumbers = build(extra).solve(2);
    assert.equal(JSON.stringify(viaNumbers), JSON.stringify(viaJson));
    outcomes.push(viaNumbers.outcome);
    const fromFile = System.fromJson(example("two_points.json"));
    const rawFile = System.fromJson(example("two_points.json"));
    const rawReport = JSON.parse(rawFile.inner.solveRequest());
    assert.equal(JSON.stringify(fromFile.solveRequest()), JSON.stringify(rawReport));
  }
  assert.deepEqual(outcomes, ["okay", "inconsistent", "redundant_okay"]);
});

test("with SolveSpace's angle form Jansen's linkage ends where SolveSpace's test says", () => {
  const text = readFileSync(
    new URL("../../loci/tests/data/bugs/jansen_linkage.json", import.meta.url),
    "utf8",
  );
  const ends = [false, true].map((angles) => {
    const sys = System.fromJson(text);
    const r = sys.solve(1, { nearest: false, solvespace_angles: angles });
    assert.equal(r.outcome, "okay");
    return [sys.value(24), sys.value(25)];
  });
  const near = (a, b) => Math.abs(a - b) < 1e-5;
  assert.ok(near(ends[1][0], 18.93036) && near(ends[1][1], 13.63778), String(ends[1]));
  assert.ok(near(ends[0][0], 19.35966) && near(ends[0][1], 14.03307), String(ends[0]));
});
