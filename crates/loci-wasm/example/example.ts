// Uses the three layers of the loci package with its types: `tsc --strict` must accept it,
// and run under Node it checks what it computes (scripts/web-tests.sh does both).
import { readFileSync } from "node:fs";
import { createRequire } from "node:module";
import {
  init, System, Sketch, Assembly, SketchError, LociError,
  type PointId, type LineId, type SketchReport, type DragStep, type AssemblyReport,
  type ConstraintSpec, type Outcome, type ShapeInfo, type MateStatus, type SolveReport,
} from "loci-wasm/web";

const require = createRequire(import.meta.url);
await init(readFileSync(require.resolve("loci-wasm/web/loci_wasm_bg.wasm")));

function check(ok: boolean, what: string): void {
  if (!ok) throw new Error(`example: ${what}`);
}

// 1. The SolveSpace model, built by calls.
const sys = new System();
const wp: [number, number][] = [[1, 0], [2, 0], [3, 0], [4, 1], [5, 0], [6, 0], [7, 0]];
for (const [h, v] of wp) sys.addParam(h, 1, v);
sys.addEntity({ h: 101, group: 1, type: "point_in_3d", params: [1, 2, 3] });
sys.addEntity({ h: 102, group: 1, type: "normal_in_3d", params: [4, 5, 6, 7] });
sys.addEntity({ h: 200, group: 1, type: "workplane", origin: 101, normal: 102 });
const x1 = sys.addParam(11, 2, 1), y1 = sys.addParam(12, 2, 2);
const x2 = sys.addParam(13, 2, 9), y2 = sys.addParam(14, 2, 3);
sys.addEntity({ h: 301, group: 2, type: "point_in_2d", workplane: 200, params: [11, 12] });
sys.addEntity({ h: 302, group: 2, type: "point_in_2d", workplane: 200, params: [13, 14] });
sys.addConstraint({ h: 1, group: 2, type: "pt_pt_distance", workplane: 200, pt_a: 301, pt_b: 302, val: 10 });
const report: SolveReport = sys.solve(2, { dragged: [x1, y1] });
const outcome: Outcome = report.outcome;
check(outcome === "okay", "the system solves");
const d = Math.hypot(sys.value(x2)! - sys.value(x1)!, sys.value(y2)! - sys.value(y1)!);
check(Math.abs(d - 10) < 1e-9, "the points are 10 apart");
const values: Float64Array = sys.values();
check(values.length === 11, "eleven parameters");

// 2. The sketcher: shapes with typed handles, constraints, a drag.
const s = new Sketch();
const a: PointId = s.addPoint(0, 0, "a");
const b: PointId = s.addPoint(3, 0.5, "b");
const c: PointId = s.addPoint(3, 3, "c");
const ab: LineId = s.addLine(a, b);
const bc: LineId = s.addLine(b, c);
const specs: ConstraintSpec[] = [
  { type: "fix", point: a },
  { type: "horizontal", line: ab },
  { type: "length", line: ab, value: 4 },
  { type: "perpendicular", a: ab, b: bc },
];
for (const spec of specs) s.addConstraint(spec);
const sr: SketchReport = s.solve();
check(sr.outcome === "okay", "the sketch solves");
// Mistakes the types catch (never run): a point for a line, an unknown kind, a line for a point.
export function mistakes(): void {
  // @ts-expect-error: a point is not a line
  s.addConstraint({ type: "length", line: a, value: 1 });
  // @ts-expect-error: no such constraint kind
  s.addConstraint({ type: "lenght", line: ab, value: 1 });
  // @ts-expect-error: a line is not a point
  s.addLine(ab, b);
  // @ts-expect-error: a sketch handle is not a parameter of the model
  sys.value(a);
}
s.beginDrag(c);
const step: DragStep = s.dragTo(4, 6);
s.endDrag();
check(step.reached && Math.abs(s.point(c)[0] - 4) < 1e-7, "c follows the drag along the vertical");
const lines = s.shapes().filter((x: ShapeInfo): x is Extract<ShapeInfo, { kind: "line" }> => x.kind === "line");
const [p, q]: [PointId, PointId] = lines[0].points;
check(p === a && q === b, "the first line runs from a to b");
try {
  s.addLine(a, 9999 as PointId);
  check(false, "an unknown point is refused");
} catch (e) {
  check(e instanceof SketchError && e instanceof LociError && e.object === "shape 9999", "SketchError names the shape");
}

// 3. Assemblies: a door on a hinge, opened 60 degrees.
const asm = new Assembly();
const hinge = { type: "axis", point: [0, 0, 0], direction: [0, 0, 1] } as const;
asm.addComponent({ name: "frame", grounded: true, references: { hinge: { ...hinge, point: [0, 0, 0], direction: [0, 0, 1] } } });
asm.addComponent({ name: "door", references: { hinge: { type: "axis", point: [0, 0, 0], direction: [0, 0, 1] }, face: { type: "face", point: [0, 0, 0], normal: [1, 0, 0] } } });
asm.addMate({ type: "revolute", a: { component: "frame", reference: "hinge" }, b: { component: "door", reference: "hinge" } });
const ar: AssemblyReport = asm.solve();
const statuses: MateStatus[] = ar.mates.map((m) => m.status);
check(statuses.every((x) => x === "satisfied" || x === "adjusted"), "the hinge holds");
check(ar.components.find((x) => x.name === "door")?.dof === 1, "the door turns about the hinge");
const poses: Float64Array = asm.poses();
check(poses.length === 14, "two poses of seven numbers");

console.log("example: the three layers work");
