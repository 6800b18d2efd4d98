// The assembly benchmark's revolute chain through BREP.io's assembly solver (npm
// brep-io-kernel, export AssemblyConstraintHistory), headless under node with `three`.
//
// usage: node brep_assembly.mjs START.json MAX_PASSES OUT.json   (run where brep-io-kernel is installed)
//
// START.json holds loci's starting pose of every link (`[tx, ty, tz, w, x, y, z]` per link,
// link 0 at the answer and fixed). Each link is a THREE.Group marked as an assembly component,
// holding a pivot vertex at its origin, a tip vertex at (1,0,0), a hinge edge along z and an
// arm edge along x, the same references as loci's chain. Each joint is three of BREP.io's
// constraints: coincident (previous tip, this pivot), parallel (the hinges) and angle (30
// degrees between the arms). runAll() relaxes them one at a time, one pass over all of them
// per iteration, until a pass applies nothing or MAX_PASSES is reached.
// OUT.json receives {passes, converged, solve_ms, max_point_error, max_angle_error_deg}.
import { readFileSync, writeFileSync } from "node:fs";
import { performance } from "node:perf_hooks";
import * as THREE from "three";

// The package's `AssemblyConstraintHistory` export is its bundled kernel, whose WebAssembly
// loader reads a data: URL as a file under node and aborts (ENAMETOOLONG). The same class
// ships as source beside the package's `SketchSolver2D` export; it needs only `three`.
const src = new URL(".", import.meta.resolve("brep-io-kernel/SketchSolver2D"));
const { AssemblyConstraintHistory } = await import(
  new URL("assemblyConstraints/AssemblyConstraintHistory.js", src).href
);

const [startPath, passesArg, outPath] = process.argv.slice(2);
const poses = JSON.parse(readFileSync(startPath, "utf8"));
const maxPasses = Number(passesArg);

const scene = new THREE.Scene();
const vertex = (name, p) => {
  const g = new THREE.BufferGeometry();
  g.setAttribute("position", new THREE.Float32BufferAttribute(p, 3));
  const o = new THREE.Points(g);
  o.name = name;
  o.type = "VERTEX";
  return o;
};
const edge = (name, a, b) => {
  const g = new THREE.BufferGeometry();
  g.setAttribute("position", new THREE.Float32BufferAttribute([...a, ...b], 3));
  const o = new THREE.Line(g);
  o.name = name;
  o.type = "EDGE";
  return o;
};
const links = poses.map((p, i) => {
  const c = new THREE.Group();
  c.name = `link${i}`;
  c.isAssemblyComponent = true;
  c.fixed = i === 0;
  c.position.set(p[0], p[1], p[2]);
  c.quaternion.set(p[4], p[5], p[6], p[3]);
  c.add(vertex(`link${i}:pivot`, [0, 0, 0]));
  c.add(vertex(`link${i}:tip`, [1, 0, 0]));
  c.add(edge(`link${i}:hinge`, [0, 0, 0], [0, 0, 1]));
  c.add(edge(`link${i}:arm`, [0, 0, 0], [1, 0, 0]));
  scene.add(c);
  return c;
});
scene.updateMatrixWorld(true);

const partHistory = { scene, features: [] };
const history = new AssemblyConstraintHistory(partHistory);
for (let i = 1; i < links.length; i++) {
  const a = `link${i - 1}`, b = `link${i}`;
  await history.addConstraint("coincident", { elements: [`${a}:tip`, `${b}:pivot`] });
  await history.addConstraint("parallel", { elements: [`${a}:hinge`, `${b}:hinge`] });
  await history.addConstraint("angle", { elements: [`${a}:arm`, `${b}:arm`], angle: 30 });
}

let passes = 0;
const t0 = performance.now();
const results = await history.runAll(partHistory, {
  iterations: maxPasses,
  hooks: { onIterationComplete: ({ iteration }) => { passes = iteration + 1; } },
});
const ms = performance.now() - t0;

// Measured here, not taken from the solver: the pivots on the tips, hinges parallel, the
// arms 30 degrees apart (signed).
scene.updateMatrixWorld(true);
const world = (c, p) => new THREE.Vector3(...p).applyMatrix4(c.matrixWorld);
const dir = (c, d) => new THREE.Vector3(...d).applyQuaternion(c.getWorldQuaternion(new THREE.Quaternion()));
let maxPoint = 0, maxAngle = 0;
for (let i = 1; i < links.length; i++) {
  const [a, b] = [links[i - 1], links[i]];
  maxPoint = Math.max(maxPoint, world(a, [1, 0, 0]).distanceTo(world(b, [0, 0, 0])));
  const ha = dir(a, [0, 0, 1]), hb = dir(b, [0, 0, 1]);
  maxAngle = Math.max(maxAngle, THREE.MathUtils.radToDeg(ha.angleTo(hb)));
  // Signed about the first hinge, so that a chain folded the other way (-30) does not pass.
  const ua = dir(a, [1, 0, 0]), ub = dir(b, [1, 0, 0]);
  const arm = THREE.MathUtils.radToDeg(Math.atan2(new THREE.Vector3().crossVectors(ua, ub).dot(ha), ua.dot(ub)));
  maxAngle = Math.max(maxAngle, Math.abs(arm - 30));
}
const statuses = {};
for (const r of results) statuses[r.status] = (statuses[r.status] || 0) + 1;
const converged = results.every((r) => r.satisfied) && maxPoint < 1e-4 && maxAngle < 1e-2;
writeFileSync(outPath, JSON.stringify({
  passes, converged, solve_ms: ms, max_point_error: maxPoint, max_angle_error_deg: maxAngle, statuses,
}));
