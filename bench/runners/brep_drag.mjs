// The drag benchmark through BREP.io's sketch solver (npm brep-io-kernel, export
// SketchSolver2D).
//
// usage: node brep_drag.mjs SKETCH SIZE STEPS   (run where brep-io-kernel is installed)
//
// SKETCH is `four_bar` or `hinged`: the sketches of loci-bench's `drag` command, built as
// BREP.io sketch JSON (points, line geometries, and its constraint symbols: ⟺ distance,
// ━ horizontal, │ vertical, ⏚ ground). The dragged point is grounded; each step moves it to
// the cursor and calls ConstraintSolver.solveSketch(). Prints one JSON object like
// slvs_drag.py's, with the largest length error seen; a step counts as failed when a length is
// off by more than 1e-4.
import { performance } from "node:perf_hooks";
import { ConstraintSolver } from "brep-io-kernel/SketchSolver2D";

const [kind, sizeArg, stepsArg] = process.argv.slice(2);
const size = Number(sizeArg);
const steps = Number(stepsArg);
const points = [];
const geometries = [];
const cons = [];
let nid = 1;
const point = (x, y) => {
  const id = nid++;
  points.push({ id, x, y, fixed: false, construction: false, externalReference: false });
  return id;
};
const ground = (p) => cons.push({ id: nid++, type: "⏚", points: [p] });
const line = (a, b, len) => {
  const id = nid++;
  geometries.push({ id, type: "line", points: [a, b], construction: false });
  if (len !== undefined) cons.push({ id: nid++, type: "⟺", points: [a, b], value: len });
  return id;
};
let shapes, grip, path, tris;
if (kind === "four_bar") {
  const A = point(0, 0), D = point(4, 0), B = point(1, 0), C = point(3.6667, 2.9814), E = point(1.588, 2.158);
  ground(A);
  ground(D);
  ground(B);
  line(A, B, 1); line(B, C, 4); line(D, C, 3); line(B, E, 2.5); line(C, E, 2.5);
  let n = 10;
  let k = 0;
  while (n + 8 <= size) {
    const x0 = 10 + 6 * (k % 40);
    const y0 = 6 * Math.floor(k / 40);
    const q = [[0, 0], [4, 0], [4, 2], [0, 2]].map(([ox, oy]) => point(x0 + ox, y0 + oy));
    for (let i = 0; i < 4; i++) line(q[i], q[(i + 1) % 4]);
    ground(q[0]);
    cons.push({ id: nid++, type: "━", points: [q[0], q[1]] });
    cons.push({ id: nid++, type: "━", points: [q[3], q[2]] });
    cons.push({ id: nid++, type: "│", points: [q[1], q[2]] });
    cons.push({ id: nid++, type: "│", points: [q[0], q[3]] });
    cons.push({ id: nid++, type: "⟺", points: [q[0], q[1]], value: 4 });
    cons.push({ id: nid++, type: "⟺", points: [q[1], q[2]], value: 2 });
    n += 8;
    k += 1;
  }
  shapes = n;
  grip = B;
  path = Array.from({ length: steps }, (_, i) => {
    const t = (2 * Math.PI * (i + 1)) / steps;
    return [Math.cos(t), Math.sin(t)];
  });
  tris = [[B, C, E]];
} else {
  const n = Math.max(Math.floor((size - 1) / 5), 1);
  const h = Math.sqrt(3) / 2;
  let corner = point(0, 0);
  ground(corner);
  tris = [];
  for (let i = 0; i < n; i++) {
    const apex = point(i + 0.5, i % 2 === 0 ? h : -h);
    const next = point(i + 1, 0);
    line(corner, apex, 1); line(apex, next, 1); line(corner, next, 1);
    tris.push([corner, apex, next]);
    corner = next;
  }
  ground(corner);
  shapes = 1 + 5 * n;
  grip = corner;
  path = Array.from({ length: steps }, (_, i) => {
    const t = (2 * Math.PI * (i + 1)) / steps;
    return [n - 1 + Math.cos(t), Math.sin(t)];
  });
}

const solver = new ConstraintSolver({ sketch: { points, geometries, constraints: cons } });
const byId = () => new Map(solver.sketchObject.points.map((p) => [p.id, p]));
const orient = (m, [a, b, c]) => {
  const [p, q, r] = [m.get(a), m.get(b), m.get(c)];
  return Math.sign((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x));
};
const dist = (p, q) => Math.hypot(p.x - q.x, p.y - q.y);
const times = [];
let flipped = 0;
let worstErr = 0;
let failed = 0;
let m = byId();
let signs = tris.map((t) => orient(m, t));
for (const [x, y] of path) {
  const t0 = performance.now();
  const g = solver.sketchObject.points.find((p) => p.id === grip);
  g.x = x;
  g.y = y;
  solver.solveSketch();
  times.push(performance.now() - t0);
  m = byId();
  // A step fails when a length is left off by more than 1e-4 (the solver rounds coordinates
  // to a few decimals, so 1e-6 is out of its reach).
  const err = Math.max(...cons.filter((c) => c.type === "⟺").map((c) => Math.abs(dist(m.get(c.points[0]), m.get(c.points[1])) - c.value)));
  worstErr = Math.max(worstErr, err);
  const bad = err > 1e-4;
  if (bad) failed += 1;
  const now = tris.map((t) => orient(m, t));
  if (now.some((s, i) => s !== signs[i])) flipped += 1;
  signs = now;
}
const rest = times.slice(1).sort((a, b) => a - b);
console.log(JSON.stringify({ sketch: kind, shapes, steps, first_ms: times[0], median_ms: rest[Math.floor(rest.length / 2)],
  p99_ms: rest[Math.floor((rest.length * 99) / 100)],
  worst_ms: rest[rest.length - 1], flipped, failed, worst_length_error: worstErr }));
