// Assemblies through the package: the shipped examples solve with every mate holding; poses
// come as Float64Array; bad mates throw AssemblyError naming the mate.
import { test } from "node:test";
import assert from "node:assert/strict";
import loci, { example } from "./load.mjs";

const { Assembly, AssemblyError, FormatError } = loci;

test("the door hinge opens 60 degrees and keeps one motion", () => {
  const asm = Assembly.fromJson(example("assembly/door_hinge.json"));
  const r = asm.solve();
  assert.ok(r.mates.every((m) => ["satisfied", "adjusted", "redundant"].includes(m.status)), JSON.stringify(r.mates));
  const opening = r.mates.find((m) => m.kind === "angle");
  assert.ok(Math.abs(opening.value - 60) < 1e-6);
  const names = asm.componentNames();
  const poses = asm.poses();
  assert.ok(poses instanceof Float64Array);
  assert.equal(poses.length, 7 * names.length);
  // The door turned 60 degrees about z: quaternion (cos 30, 0, 0, sin 30).
  const i = names.indexOf("door");
  const q = Array.from(poses.slice(7 * i + 3, 7 * i + 7));
  assert.ok(Math.abs(Math.abs(q[0]) - Math.cos(Math.PI / 6)) < 1e-9 && Math.abs(Math.abs(q[3]) - 0.5) < 1e-9, q.join());
});

test("the 3D four-bar solves; the stepped mode converges too", () => {
  const asm = Assembly.fromJson(example("assembly/four_bar_3d.json"));
  const r = asm.solve();
  assert.ok(r.mates.every((m) => m.status !== "conflicting" && m.status !== "unsatisfied"), JSON.stringify(r.mates));
  assert.ok(r.residual < 1e-8);
  const again = Assembly.fromJson(example("assembly/door_hinge.json"));
  const run = again.solveStepped();
  assert.ok(run.iterations.length > 0);
  assert.ok(Array.isArray(run.iterations[0].poses));
});

test("an assembly built by calls: a ball joint; bad mates are named", () => {
  const asm = new Assembly();
  asm.addComponent({ name: "base", grounded: true, references: { c: { type: "vertex", point: [0, 0, 0] } } });
  asm.addComponent({
    name: "arm",
    pose: { translation: [0.3, 0.2, 0.1], rotation: [1, 0, 0, 0] },
    references: { c: { type: "vertex", point: [0, 0, 0] } },
  });
  const id = asm.addMate({ type: "ball", a: { component: "base", reference: "c" }, b: { component: "arm", reference: "c" } });
  const r = asm.solve();
  assert.equal(r.mates[0].id, id);
  assert.ok(["adjusted", "satisfied"].includes(r.mates[0].status));
  assert.equal(r.components.find((c) => c.name === "arm").dof, 3);
  const t = Array.from(asm.poses().slice(7, 10));
  assert.ok(t.every((x) => Math.abs(x) < 1e-9), t.join());
  // A mate on a component that does not exist is reported by the solve, by name.
  const bad = asm.addMate({ type: "ball", a: { component: "base", reference: "c" }, b: { component: "nope", reference: "c" } });
  const m = asm.solve().mates.find((x) => x.id === bad);
  assert.equal(m.status, "invalid_selection");
  assert.match(m.message, /component `nope` does not exist/);
  assert.throws(() => asm.addMate({ id, type: "fixed", a: { component: "base", reference: "c" }, b: { component: "arm", reference: "c" } }),
    (e) => e instanceof AssemblyError && e.object === `mate ${id}`);
  assert.throws(() => asm.addComponent({ name: "arm" }), (e) => e instanceof AssemblyError && e.object === "component arm");
  assert.throws(() => asm.setPose("ghost", [0, 0, 0, 1, 0, 0, 0]), (e) => e instanceof AssemblyError && e.object === "component ghost");
  assert.throws(() => Assembly.fromJson('{"loci_assembly": 9}'), FormatError);
});
