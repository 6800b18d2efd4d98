// The drag benchmark through PlaneGCS (npm @salusoft89/planegcs, FreeCAD's solver in
// WebAssembly).
//
// usage: node planegcs_drag.mjs SKETCH SIZE STEPS
//
// SKETCH is `four_bar` or `hinged`: the sketches of loci-bench's `drag` command and of
// slvs_drag.py, built as PlaneGCS primitives. As FreeCAD's sketcher does while dragging, the
// dragged point's parameters are fixed and set to the cursor at each step, then the system is
// solved (DogLeg) and the solution applied. Prints one JSON object like slvs_drag.py's.
import { performance } from "node:perf_hooks";
import { init_planegcs_module, GcsWrapper, Algorithm, SolveStatus } from "@salusoft89/planegcs";

const [kind, sizeArg, stepsArg] = process.argv.slice(2);
const size = Number(sizeArg);
const steps = Number(stepsArg);
const prims = [];
let nc = 0;
const point = (id, x, y, fixed = false) => prims.push({ id, type: "point", x, y, fixed });
const line = (id, a, b, len) => {
  prims.push({ id, type: "line", p1_id: a, p2_id: b });
  if (len !== undefined) prims.push({ id: `c${nc++}`, type: "p2p_distance", p1_id: a, p2_id: b, distance: len });
};
let shapes, grip, path, tris;
if (kind === "four_bar") {
  point("A", 0, 0, true);
  point("D", 4, 0, true);
  point("B", 1, 0, true); // the dragged point: fixed, moved by hand
  point("C", 3.6667, 2.9814);
  point("E", 1.588, 2.158);
  line("AB", "A", "B", 1.0);
  line("BC", "B", "C", 4.0);
  line("DC", "D", "C", 3.0);
  line("BE", "B", "E", 2.5);
  line("CE", "C", "E", 2.5);
  let n = 10;
  let k = 0;
  while (n + 8 <= size) {
    const x0 = 10 + 6 * (k % 40);
    const y0 = 6 * Math.floor(k / 40);
    const q = [[0, 0], [4, 0], [4, 2], [0, 2]].map(([ox, oy], i) => {
      const id = `r${k}p${i}`;
      point(id, x0 + ox, y0 + oy, i === 0);
      return id;
    });
    for (let i = 0; i < 4; i++) line(`r${k}l${i}`, q[i], q[(i + 1) % 4]);
    prims.push({ id: `c${nc++}`, type: "horizontal_l", l_id: `r${k}l0` });
    prims.push({ id: `c${nc++}`, type: "horizontal_l", l_id: `r${k}l2` });
    prims.push({ id: `c${nc++}`, type: "vertical_l", l_id: `r${k}l1` });
    prims.push({ id: `c${nc++}`, type: "vertical_l", l_id: `r${k}l3` });
    prims.push({ id: `c${nc++}`, type: "p2p_distance", p1_id: q[0], p2_id: q[1], distance: 4 });
    prims.push({ id: `c${nc++}`, type: "p2p_distance", p1_id: q[1], p2_id: q[2], distance: 2 });
    n += 8;
    k += 1;
  }
  shapes = n;
  grip = "B";
  path = Array.from({ length: steps }, (_, i) => {
    const t = (2 * Math.PI * (i + 1)) / steps;
    return [Math.cos(t), Math.sin(t)];
  });
  tris = [["B", "C", "E"]];
} else {
  const n = Math.max(Math.floor((size - 1) / 5), 1);
  const h = Math.sqrt(3) / 2;
  point("q0", 0, 0, true);
  tris = [];
  for (let i = 0; i < n; i++) {
    const apex = `a${i}`;
    const next = `q${i + 1}`;
    point(apex, i + 0.5, i % 2 === 0 ? h : -h);
    point(next, i + 1, 0, i + 1 === n);
    line(`t${i}a`, `q${i}`, apex, 1);
    line(`t${i}b`, apex, next, 1);
    line(`t${i}c`, `q${i}`, next, 1);
    tris.push([`q${i}`, apex, next]);
  }
  shapes = 1 + 5 * n;
  grip = `q${n}`;
  path = Array.from({ length: steps }, (_, i) => {
    const t = (2 * Math.PI * (i + 1)) / steps;
    return [n - 1 + Math.cos(t), Math.sin(t)];
  });
}

const mod = await init_planegcs_module();
const gcs = new GcsWrapper(new mod.GcsSystem());
gcs.push_primitives_and_params(prims);
const at = (id) => gcs.p_param_index.get(id);
const xy = (id) => [gcs.gcs.get_p_param(at(id)), gcs.gcs.get_p_param(at(id) + 1)];
const orient = ([a, b, c]) => {
  const [p, q, r] = [xy(a), xy(b), xy(c)];
  return Math.sign((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
};
const times = [];
let flipped = 0;
let failed = 0;
let signs = tris.map(orient);
for (const [x, y] of path) {
  const t0 = performance.now();
  gcs.gcs.set_p_param(at(grip), x, true);
  gcs.gcs.set_p_param(at(grip) + 1, y, true);
  const code = gcs.solve(Algorithm.DogLeg);
  gcs.apply_solution();
  times.push(performance.now() - t0);
  if (!(code === SolveStatus.Success || code === SolveStatus.Converged)) failed += 1;
  const now = tris.map(orient);
  if (now.some((s, i) => s !== signs[i])) flipped += 1;
  signs = now;
}
const rest = times.slice(1).sort((a, b) => a - b);
console.log(JSON.stringify({ sketch: kind, shapes, steps, first_ms: times[0], median_ms: rest[Math.floor(rest.length / 2)],
  p99_ms: rest[Math.floor((rest.length * 99) / 100)],
  worst_ms: rest[rest.length - 1], flipped, failed }));
gcs.destroy_gcs_module();
