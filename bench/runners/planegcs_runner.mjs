// Runs one benchmark problem through PlaneGCS (the npm package @salusoft89/planegcs, FreeCAD's
// solver compiled to WebAssembly).
//
// usage: node planegcs_runner.mjs PROBLEM.json REPS BUDGET_S OUT.json
//
// PROBLEM.json is an array of sketch primitives (see loci-bench's peers::to_planegcs). Each
// repetition pushes them into a fresh GcsSystem (timed as the build) and calls solve with the
// default DogLeg algorithm (timed as the solve); repetitions stop early once the solves add up
// to BUDGET_S seconds. OUT.json receives {status, detail, build_ms, solve_ms, points}.
import { readFileSync, writeFileSync } from "node:fs";
import { performance } from "node:perf_hooks";
import { init_planegcs_module, GcsWrapper, Algorithm, SolveStatus } from "@salusoft89/planegcs";

const [path, repsArg, budgetArg, outPath] = process.argv.slice(2);
const prims = JSON.parse(readFileSync(path, "utf8"));
const reps = Number(repsArg);
const budgetMs = Number(budgetArg) * 1e3;
const mod = await init_planegcs_module();

// With LOCI_BENCH_WARMUP_S=S (loci-bench wasm), untimed solves first until S seconds or 1,000
// solves have passed, as the loci-wasm runner does: node recompiles hot WebAssembly with its
// optimising compiler as it runs. Without it, nothing changes.
if (process.env.LOCI_BENCH_WARMUP_S) {
  const until = performance.now() + 1e3 * Number(process.env.LOCI_BENCH_WARMUP_S);
  for (let k = 0; k < 1000 && performance.now() < until; k++) {
    const gcs = new GcsWrapper(new mod.GcsSystem());
    gcs.push_primitives_and_params(structuredClone(prims));
    gcs.solve(Algorithm.DogLeg);
    gcs.destroy_gcs_module();
  }
}
const buildMs = [];
const solveMs = [];
let spent = 0;
let status = "ok";
let detail = "";
let points = [];
for (let r = 0; r < reps; r++) {
  const t0 = performance.now();
  const gcs = new GcsWrapper(new mod.GcsSystem());
  gcs.push_primitives_and_params(structuredClone(prims));
  const t1 = performance.now();
  const code = gcs.solve(Algorithm.DogLeg);
  const t2 = performance.now();
  buildMs.push(t1 - t0);
  solveMs.push(t2 - t1);
  spent += t2 - t1;
  const last = r + 1 === reps || spent > budgetMs;
  if (last) {
    const ok = code === SolveStatus.Success || code === SolveStatus.Converged;
    const conflicting = gcs.has_gcs_conflicting_constraints();
    status = ok && !conflicting ? "ok" : "failed";
    const names = ["success", "converged", "failed", "solution invalid"];
    detail = names[code] ?? `status ${code}`;
    if (conflicting) detail += ", conflicting constraints";
    if (gcs.has_gcs_redundant_constraints()) detail += ", redundant constraints";
    gcs.apply_solution();
    const byId = new Map();
    for (const o of gcs.sketch_index.get_primitives()) if (o.type === "point") byId.set(o.id, o);
    points = prims.filter((o) => o.type === "point").map((o) => {
      const p = byId.get(o.id);
      return [p.x, p.y, 0];
    });
  }
  gcs.destroy_gcs_module();
  if (last) break;
}
writeFileSync(outPath, JSON.stringify({ status, detail, build_ms: buildMs, solve_ms: solveMs, points }));
