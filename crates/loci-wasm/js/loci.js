// The typed layer of the loci package over the raw wasm-bindgen classes: values parsed from
// JSON into plain objects, handles as numbers, errors rethrown as Error subclasses that name
// the object at fault. Its types are in loci.d.ts.

let raw = null;

/** Called once by the entry module (index.js or web.js) with the raw bindings. */
export function setBindings(bindings) {
  raw = bindings;
}

function bindings() {
  if (raw === null) {
    throw new InputError("the WebAssembly module is not loaded; await init() first", null);
  }
  return raw;
}

/** Every error loci throws: `object` names the object at fault when there is one. */
export class LociError extends Error {
  constructor(message, object) {
    super(message);
    this.name = new.target.name;
    this.object = object ?? null;
  }
}
/** The SolveSpace model is invalid: a dangling or wrong reference, a bad handle or number. */
export class ModelError extends LociError {}
/** A solve cannot start: an unknown group or dragged parameter, a bad option. */
export class SolveError extends LociError {}
/** The sketcher refused a call: an unknown shape, a shape of the wrong kind, a bad value. */
export class SketchError extends LociError {}
/** An assembly refused a call: an unknown component, reference or mate. */
export class AssemblyError extends LociError {}
/** A file cannot be read: JSON, a sketch, an assembly or `.slvs`. */
export class FormatError extends LociError {}
/** An argument of the wrong shape: a handle that is not one, a missing drag. */
export class InputError extends LociError {}

const CLASSES = { ModelError, SolveError, SketchError, AssemblyError, FormatError, InputError };

/** Runs a raw call; a loci error comes out as its subclass, anything else unchanged. */
function call(f) {
  try {
    return f();
  } catch (e) {
    const cls = e && typeof e === "object" ? CLASSES[e.lociClass] : undefined;
    if (cls) throw new cls(e.message, e.object);
    throw e;
  }
}

function handle(v, what) {
  if (!Number.isInteger(v) || v < 1 || v > 0xffffffff) {
    throw new InputError(`${what} must be a handle (an integer from 1), not ${String(v)}`, what);
  }
  return v;
}

function finite(v, what) {
  if (typeof v !== "number" || !Number.isFinite(v)) {
    throw new InputError(`${what} must be a finite number, not ${String(v)}`, what);
  }
  return v;
}

/** The version of loci the package was built from. */
export function version() {
  return bindings().version();
}

const OUTCOMES = ["okay", "redundant_okay", "inconsistent", "did_not_converge"];

// A solve's report from its numbers (`packed` in src/system.rs): the object its JSON reads
// as, fields in the same order, a residual that is no finite number null as in JSON.
function reportOf(p) {
  const nf = p[7];
  const ne = p[8 + nf];
  // Plain loops: a typed-array view per list cost more than the rest of a small report.
  const failed = new Array(nf);
  for (let i = 0; i < nf; i++) failed[i] = p[8 + i];
  const r = { outcome: OUTCOMES[p[0]], dof: p[1], failed };
  if (ne > 0) {
    const entities = new Array(ne);
    for (let i = 0; i < ne; i++) entities[i] = p[9 + nf + i];
    r.failed_entities = entities;
  }
  r.iterations = p[2];
  r.residual = Number.isFinite(p[3]) ? p[3] : null;
  r.unknowns = p[4];
  r.equations = p[5];
  r.components = p[6];
  return r;
}

/** A SolveSpace-model system: parameters, entities and constraints in groups. */
export class System {
  constructor(inner) {
    this.inner = inner ?? new (bindings().RawSystem)();
  }
  static fromJson(text) {
    return new System(call(() => bindings().RawSystem.fromJson(text)));
  }
  static fromSlvs(bytes) {
    return new System(call(() => bindings().RawSystem.fromSlvs(bytes)));
  }
  toJson() {
    return this.inner.toJson();
  }
  toSlvs() {
    return call(() => this.inner.toSlvs());
  }
  model() {
    return JSON.parse(this.inner.modelJson());
  }
  addParam(h, group, value) {
    handle(h, "param handle");
    return call(() => this.inner.addParam(h, group, value));
  }
  addEntity(entity) {
    return call(() => this.inner.addEntity(JSON.stringify(entity)));
  }
  addConstraint(constraint) {
    return call(() => this.inner.addConstraint(JSON.stringify(constraint)));
  }
  removeConstraint(h) {
    return this.inner.removeConstraint(handle(h, "constraint handle"));
  }
  value(h) {
    return this.inner.value(handle(h, "param handle"));
  }
  setValue(h, v) {
    return this.inner.setValue(handle(h, "param handle"), finite(v, "value"));
  }
  paramHandles() {
    return this.inner.paramHandles();
  }
  values() {
    return this.inner.values();
  }
  setValues(values) {
    call(() => this.inner.setValues(Float64Array.from(values)));
  }
  groups() {
    return Array.from(this.inner.groups());
  }
  solve(group, options = {}) {
    const { dragged = [], ...rest } = options;
    const opts = Object.keys(rest).length ? JSON.stringify(rest) : "";
    return reportOf(call(() => this.inner.solvePacked(group, Uint32Array.from(dragged), opts)));
  }
  solveRequest() {
    return reportOf(call(() => this.inner.solveRequestPacked()));
  }
  solveAll() {
    return JSON.parse(call(() => this.inner.solveAll()));
  }
  check(group) {
    return JSON.parse(call(() => this.inner.check(group)));
  }
  free() {
    this.inner.free();
  }
}

/** A 2D sketch: named shapes, user and soft constraints, drags. */
export class Sketch {
  constructor(inner) {
    this.inner = inner ?? new (bindings().RawSketch)();
  }
  static fromJson(text) {
    return new Sketch(call(() => bindings().RawSketch.fromJson(text)));
  }
  toJson() {
    return this.inner.toJson();
  }
  toSlvs() {
    return call(() => this.inner.toSlvs());
  }
  toProblemJson() {
    return this.inner.toProblemJson();
  }
  addPoint(x, y, name) {
    return call(() => this.inner.addPoint(finite(x, "x"), finite(y, "y"), name));
  }
  addLine(a, b, name) {
    return call(() => this.inner.addLine(handle(a, "a"), handle(b, "b"), name));
  }
  addCircle(center, radius, name) {
    return call(() => this.inner.addCircle(handle(center, "center"), finite(radius, "radius"), name));
  }
  addArc(center, start, end, name) {
    return call(() =>
      this.inner.addArc(handle(center, "center"), handle(start, "start"), handle(end, "end"), name),
    );
  }
  setConstruction(shape, on) {
    call(() => this.inner.setConstruction(handle(shape, "shape"), on));
  }
  removeShape(shape) {
    return JSON.parse(call(() => this.inner.removeShape(handle(shape, "shape"))));
  }
  movePoint(point, x, y) {
    call(() => this.inner.movePoint(handle(point, "point"), finite(x, "x"), finite(y, "y")));
  }
  addConstraint(spec, options = {}) {
    return call(() =>
      this.inner.addConstraint(JSON.stringify(spec), options.reference === true, options.name),
    );
  }
  removeConstraint(id) {
    call(() => this.inner.removeConstraint(handle(id, "constraint")));
  }
  setValue(id, value) {
    call(() => this.inner.setValue(handle(id, "constraint"), finite(value, "value")));
  }
  measure(id) {
    return JSON.parse(call(() => this.inner.measure(handle(id, "constraint"))));
  }
  solve() {
    return JSON.parse(call(() => this.inner.solve()));
  }
  check() {
    const c = JSON.parse(call(() => this.inner.check()));
    c.free = c.free.map(([shape, dof]) => ({ shape, dof }));
    return c;
  }
  shapes() {
    return JSON.parse(this.inner.shapes());
  }
  constraints() {
    return JSON.parse(this.inner.constraints());
  }
  softConstraints() {
    return JSON.parse(this.inner.softConstraints());
  }
  geometry() {
    return this.inner.geometry();
  }
  point(p) {
    const v = call(() => this.inner.pointXY(handle(p, "point")));
    return [v[0], v[1]];
  }
  radius(shape) {
    return call(() => this.inner.radius(handle(shape, "shape")));
  }
  lineLength(line) {
    return call(() => this.inner.lineLength(handle(line, "line")));
  }
  beginDrag(shape) {
    call(() => this.inner.beginDrag(handle(shape, "shape")));
  }
  dragTo(x, y) {
    return JSON.parse(call(() => this.inner.dragTo(finite(x, "x"), finite(y, "y"))));
  }
  endDrag() {
    this.inner.endDrag();
  }
  get dragging() {
    return this.inner.dragging;
  }
  free() {
    this.inner.free();
  }
}

/** Rigid components placed by poses and related by mates. */
export class Assembly {
  constructor(inner) {
    this.inner = inner ?? new (bindings().RawAssembly)();
  }
  static fromJson(text) {
    return new Assembly(call(() => bindings().RawAssembly.fromJson(text)));
  }
  toJson() {
    return this.inner.toJson();
  }
  addComponent(component) {
    return call(() => this.inner.addComponent(JSON.stringify(component)));
  }
  addMate(mate) {
    return call(() => this.inner.addMate(JSON.stringify(mate)));
  }
  solve() {
    return JSON.parse(call(() => this.inner.solve()));
  }
  solveStepped() {
    return JSON.parse(call(() => this.inner.solveStepped()));
  }
  componentNames() {
    return JSON.parse(this.inner.componentNames());
  }
  components() {
    return JSON.parse(this.inner.components());
  }
  poses() {
    return this.inner.poses();
  }
  setPose(component, pose) {
    call(() => this.inner.setPose(component, Float64Array.from(pose)));
  }
  measureAngle(id) {
    return JSON.parse(this.inner.measureAngle(id));
  }
  free() {
    this.inner.free();
  }
}
