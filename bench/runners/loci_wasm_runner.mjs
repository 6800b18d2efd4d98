// Runs one benchmark problem through loci compiled to WebAssembly (the npm package that
// scripts/build-wasm.sh builds in crates/loci-wasm/pkg), under node.
//
// usage: node loci_wasm_runner.mjs PROBLEM.json REPS BUDGET_S OUT.json
//
// PROBLEM.json is {"problem": <a loci JSON problem>, "points": [[param handles of point i], ...]}
// (see loci-bench's wasm module). Each repetition reads the problem into a fresh System (timed
// as the build) and solves its request (timed as the solve), as native loci does in
// loci-bench; repetitions stop early once builds and solves add up to BUDGET_S seconds. OUT.json
// receives {status, detail, build_ms, solve_ms, points}.
import { readFileSync, writeFileSync } from "node:fs";
import { performance } from "node:perf_hooks";

const [path, repsArg, budgetArg, outPath] = process.argv.slice(2);
// LOCI_WASM_PKG: another build of the package (a directory), to compare builds.
const pkg = process.env.LOCI_WASM_PKG
  ? new URL(`file://${process.env.LOCI_WASM_PKG.replace(/\/?$/, "/")}`)
  : new URL("../../crates/loci-wasm/pkg/", import.meta.url);
const loci = await import(new URL("web.js", pkg).href);
await loci.init(readFileSync(new URL("web/loci_wasm_bg.wasm", pkg)));

const input = JSON.parse(readFileSync(path, "utf8"));
const text = JSON.stringify(input.problem);
const reps = Number(repsArg);
const budgetMs = Number(budgetArg) * 1e3;
// Untimed solves first: node runs WebAssembly with a baseline compiler and recompiles the hot
// functions with its optimising one as they run, so early solves measure the compiler. One
// solve, or with LOCI_BENCH_WARMUP_S=S (loci-bench wasm sets it, and the PlaneGCS runner
// honours it the same way) solves until S seconds or 1,000 solves have passed.
{
  const until = performance.now() + 1e3 * Number(process.env.LOCI_BENCH_WARMUP_S ?? 0);
  for (let k = 0; k < 1000 && (k === 0 || performance.now() < until); k++) {
    const warm = loci.System.fromJson(text);
    try {
      warm.solveRequest();
    } catch {}
    warm.free();
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
  const sys = loci.System.fromJson(text);
  const t1 = performance.now();
  let report;
  try {
    report = sys.solveRequest();
  } catch (e) {
    status = "error";
    detail = `${e.name}: ${e.message}`;
  }
  const t2 = performance.now();
  buildMs.push(t1 - t0);
  solveMs.push(t2 - t1);
  // Building counts towards the budget too: a 100x100 grid builds in 110 ms and solves in 5.
  spent += t2 - t0;
  const last = r + 1 === reps || spent > budgetMs;
  if (last) {
    if (report) {
      const ok = report.outcome === "okay" || report.outcome === "redundant_okay";
      status = ok ? "ok" : "failed";
      detail = `${report.outcome} (dof ${report.dof}, ${report.failed.length} failed, ${report.iterations} iterations)`;
    }
    const handles = sys.paramHandles();
    const values = sys.values();
    const at = new Map();
    handles.forEach((h, i) => at.set(h, values[i]));
    points = input.points.map((ps) => [0, 1, 2].map((k) => (k < ps.length ? at.get(ps[k]) : 0)));
  }
  sys.free();
  if (last) break;
}
writeFileSync(outPath, JSON.stringify({ status, detail, build_ms: buildMs, solve_ms: solveMs, points }));
