// The browser sketcher: draw points, lines, circles and arcs, constrain them from the toolbar,
// drag any free point or shape (soft constraints keep the rest), see fully constrained and free
// geometry in their colours, the degrees of freedom and conflicting constraints by name; load
// and save loci sketch JSON and .slvs; a gallery of the shipped examples.
import { init, Sketch, System, Assembly, LociError } from "../pkg/web.js";
import { View, COLOURS, PACKED, bounds } from "./view.js";
import { fourBarAmongRectangles, hingedTriangles } from "./gallery.js";
import { SystemView, AssemblyView } from "./readonly.js";

await init();

const canvas = document.getElementById("view");
const view = new View(canvas);
const $ = (id) => document.getElementById(id);

const app = {
  sketch: new Sketch(),
  shapes: [],
  byId: new Map(),
  geometry: new Float64Array(),
  status: null,
  report: null,
  bad: new Set(),
  badConstraints: new Set(),
  redundantConstraints: new Set(),
  fixed: new Set(),
  selection: new Set(),
  tool: "select",
  pending: [],
  drag: null,
  dragTimes: [],
  readonly: null,
};

function message(text) {
  $("message").textContent = text ?? "";
}

/** Runs an edit; a loci error is shown by name instead of thrown. */
function guarded(f) {
  try {
    return f();
  } catch (e) {
    if (e instanceof LociError) {
      message(`${e.name}: ${e.message}`);
      return undefined;
    }
    throw e;
  }
}

/** Reads the shapes and geometry again (after a structural edit). */
function reload() {
  app.shapes = app.sketch.shapes();
  app.byId = new Map(app.shapes.map((s) => [s.id, s]));
  app.geometry = app.sketch.geometry();
}

/** Solves, diagnoses and redraws: after every edit and at the end of a drag. */
function refresh({ solve = true } = {}) {
  if (solve) app.report = guarded(() => app.sketch.solve()) ?? app.report;
  reload();
  app.status = guarded(() => app.sketch.check()) ?? null;
  app.fixed = new Set(app.status?.fixed ?? []);
  app.badConstraints = new Set([...(app.status?.conflicting ?? []).flat(), ...(app.report?.outcome === "inconsistent" ? app.report.failed : [])]);
  app.redundantConstraints = new Set((app.status?.redundant ?? []).flat());
  const specs = app.sketch.constraints();
  app.bad = new Set();
  for (const c of specs) {
    if (!app.badConstraints.has(c.id)) continue;
    for (const [k, v] of Object.entries(c.spec)) {
      if (k !== "type" && typeof v === "number" && app.byId.has(v)) app.bad.add(v);
    }
  }
  $("dof").textContent = app.status ? String(app.status.dof) : "?";
  $("outcome").textContent = app.status ? app.status.outcome.replaceAll("_", " ") : "";
  const list = $("constraint-list");
  list.replaceChildren(
    ...specs.map((c) => {
      const li = document.createElement("li");
      li.dataset.id = String(c.id);
      if (app.badConstraints.has(c.id)) li.className = "bad";
      else if (app.redundantConstraints.has(c.id)) li.className = "redundant";
      const label = document.createElement("span");
      label.textContent = c.name + (c.reference ? " (ref)" : "");
      const del = document.createElement("button");
      del.textContent = "×";
      del.title = "Remove this constraint";
      del.onclick = () => {
        guarded(() => app.sketch.removeConstraint(c.id));
        refresh();
      };
      li.append(label, del);
      return li;
    }),
  );
  draw();
}

function style(sh) {
  if (app.selection.has(sh.id)) return COLOURS.selected;
  if (app.bad.has(sh.id)) return COLOURS.bad;
  return app.fixed.has(sh.id) ? COLOURS.fixed : COLOURS.free;
}

function draw() {
  view.clear();
  if (app.readonly) {
    app.readonly.draw(view);
    return;
  }
  view.drawShapes(app.shapes, app.geometry, style, (sh) => sh.construction);
  if (app.shapes.length <= 60) view.drawNames(app.shapes, app.geometry);
  // The clicks of a shape being drawn.
  view.ctx.fillStyle = COLOURS.preview;
  for (const [x, y] of app.pending.map((p) => p.at)) {
    const [px, py] = view.toScreen(x, y);
    view.ctx.beginPath();
    view.ctx.arc(px, py, 5, 0, 2 * Math.PI);
    view.ctx.fill();
  }
}

function load(sketch, { fit = true } = {}) {
  app.sketch.free();
  app.sketch = sketch;
  app.readonly = null;
  app.selection.clear();
  app.pending = [];
  app.dragTimes = [];
  refresh();
  if (fit) {
    view.fit(bounds(app.shapes, app.geometry));
    draw();
  }
}

// ---------------------------------------------------------------------------------------------
// Mouse: drawing tools, selection and dragging.

function eventXY(ev) {
  const r = canvas.getBoundingClientRect();
  return [(ev.clientX - r.left) * (canvas.width / r.width), (ev.clientY - r.top) * (canvas.height / r.height)];
}

/** The point under the cursor, or a new one there. */
function pointAt(px, py) {
  const hit = view.hit(app.shapes, app.geometry, px, py);
  if (hit && hit.kind === "point") return hit.id;
  const [x, y] = view.toWorld(px, py);
  return app.sketch.addPoint(x, y);
}

canvas.addEventListener("mousedown", (ev) => {
  if (app.readonly) return;
  message("");
  const [px, py] = eventXY(ev);
  if (app.tool !== "select") {
    guarded(() => clickTool(px, py));
    return;
  }
  const hit = view.hit(app.shapes, app.geometry, px, py);
  if (!hit) {
    app.selection.clear();
    draw();
    return;
  }
  if (ev.shiftKey) {
    if (app.selection.has(hit.id)) app.selection.delete(hit.id);
    else app.selection.add(hit.id);
  } else if (!app.selection.has(hit.id)) {
    app.selection.clear();
    app.selection.add(hit.id);
  }
  app.drag = { shape: hit.id, started: false, from: [px, py] };
  draw();
});

// Moves and the release are followed on the whole window, so that a drag goes on outside the canvas.
window.addEventListener("mousemove", (ev) => {
  const d = app.drag;
  if (!d) return;
  const [px, py] = eventXY(ev);
  if (!d.started) {
    if (Math.hypot(px - d.from[0], py - d.from[1]) < 3) return;
    try {
      app.sketch.beginDrag(d.shape);
    } catch (e) {
      app.drag = null;
      if (e instanceof LociError) message(`${e.name}: ${e.message}`);
      return;
    }
    d.started = true;
    // Drag from where the grip is, not where the click was, so that nothing jumps.
    const [wx, wy] = view.toWorld(...d.from);
    d.offset = [0, 0];
    const sh = app.byId.get(d.shape);
    if (sh.kind === "point") {
      const [gx, gy] = app.sketch.point(d.shape);
      d.offset = [gx - wx, gy - wy];
    }
  }
  const [wx, wy] = view.toWorld(px, py);
  const t0 = performance.now();
  const step = app.sketch.dragTo(wx + d.offset[0], wy + d.offset[1]);
  const ms = performance.now() - t0;
  app.dragTimes.push(ms);
  d.last = step;
  app.geometry = app.sketch.geometry();
  const recent = app.dragTimes.slice(-20);
  const mean = recent.reduce((a, b) => a + b, 0) / recent.length;
  $("drag-time").textContent = `drag step: ${mean.toFixed(2)} ms mean of the last ${recent.length} (${step.pieces} piece${step.pieces === 1 ? "" : "s"}${step.flips_prevented ? `, ${step.flips_prevented} flips prevented` : ""})`;
  draw();
});

function endDrag() {
  const d = app.drag;
  app.drag = null;
  if (d?.started) {
    app.sketch.endDrag();
    refresh({ solve: false });
  }
}
window.addEventListener("mouseup", endDrag);

function clickTool(px, py) {
  const [x, y] = view.toWorld(px, py);
  if (app.tool === "point") {
    app.sketch.addPoint(x, y);
    refresh();
    return;
  }
  app.pending.push({ px, py, at: [x, y] });
  const need = { line: 2, circle: 2, arc: 3 }[app.tool];
  if (app.pending.length < need) {
    draw();
    return;
  }
  const clicks = app.pending;
  app.pending = [];
  if (app.tool === "line") {
    const a = pointAt(clicks[0].px, clicks[0].py);
    reload();
    const b = pointAt(clicks[1].px, clicks[1].py);
    app.sketch.addLine(a, b);
  } else if (app.tool === "circle") {
    const c = pointAt(clicks[0].px, clicks[0].py);
    const [cx, cy] = app.sketch.point(c);
    app.sketch.addCircle(c, Math.max(1e-3, Math.hypot(clicks[1].at[0] - cx, clicks[1].at[1] - cy)));
  } else if (app.tool === "arc") {
    const c = pointAt(clicks[0].px, clicks[0].py);
    reload();
    const [cx, cy] = app.sketch.point(c);
    const r = Math.hypot(clicks[1].at[0] - cx, clicks[1].at[1] - cy);
    const a1 = Math.atan2(clicks[2].at[1] - cy, clicks[2].at[0] - cx);
    const s = pointAt(clicks[1].px, clicks[1].py);
    const e = app.sketch.addPoint(cx + r * Math.cos(a1), cy + r * Math.sin(a1));
    app.sketch.addArc(c, s, e);
  }
  refresh();
}

// ---------------------------------------------------------------------------------------------
// Toolbar: tools, constraints, files, gallery.

function setTool(tool) {
  app.tool = tool;
  app.pending = [];
  for (const b of document.querySelectorAll("#tools button")) b.classList.toggle("on", b.dataset.tool === tool);
  draw();
}
for (const b of document.querySelectorAll("#tools button")) b.onclick = () => setTool(b.dataset.tool);

const selected = () => [...app.selection].map((id) => app.byId.get(id)).filter(Boolean);
const ofKind = (list, ...kinds) => list.filter((s) => kinds.includes(s.kind));
const round = (s) => s.kind === "circle" || s.kind === "arc";

function ask(what, current) {
  const v = window.prompt(what, String(Math.round(current * 1e6) / 1e6));
  if (v === null) return null;
  const x = Number(v);
  if (!Number.isFinite(x)) {
    message(`${what}: ${v} is not a number`);
    return null;
  }
  return x;
}

/** The end of an arc nearest to a point. */
function nearestEnd(arc, xy) {
  const [, s, e] = arc.points;
  const d = (p) => {
    const [x, y] = app.sketch.point(p);
    return Math.hypot(x - xy[0], y - xy[1]);
  };
  return d(s) <= d(e) ? "start" : "end";
}

/** The constraints the toolbar button `kind` adds on the selection. */
function constraintsFor(kind, sel) {
  const pts = ofKind(sel, "point");
  const lines = ofKind(sel, "line");
  const rounds = sel.filter(round);
  const out = [];
  switch (kind) {
    case "fix":
      for (const s of sel) out.push(s.kind === "point" ? { type: "fix", point: s.id } : { type: "fix_shape", shape: s.id });
      break;
    case "horizontal":
    case "vertical":
      for (const l of lines) out.push({ type: kind, line: l.id });
      break;
    case "length":
      if (lines.length === 1 && pts.length === 1) {
        // Signed as loci measures it: positive to the right of the line's direction.
        const [p, q] = lines[0].points.map((x) => app.sketch.point(x));
        const [x, y] = app.sketch.point(pts[0].id);
        const d = ((q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0])) / -Math.hypot(q[0] - p[0], q[1] - p[1]);
        const v = ask(`distance from ${pts[0].name} to ${lines[0].name} (positive to the right)`, d);
        if (v !== null) out.push({ type: "point_line_distance", point: pts[0].id, line: lines[0].id, value: v });
      } else if (pts.length === 2) {
        const [a, b] = pts.map((p) => app.sketch.point(p.id));
        const v = ask("distance", Math.hypot(b[0] - a[0], b[1] - a[1]));
        if (v !== null) out.push({ type: "distance", a: pts[0].id, b: pts[1].id, value: v });
      } else {
        for (const l of lines) {
          const v = ask(`length of ${l.name}`, app.sketch.lineLength(l.id));
          if (v !== null) out.push({ type: "length", line: l.id, value: v });
        }
      }
      break;
    case "coincident":
    case "on":
      if (pts.length === 2 && kind === "coincident") out.push({ type: "coincident", a: pts[0].id, b: pts[1].id });
      else if (pts.length === 1 && lines.length === 1) out.push({ type: "point_on_line", point: pts[0].id, line: lines[0].id });
      else if (pts.length === 1 && rounds.length === 1) out.push({ type: "point_on_circle", point: pts[0].id, shape: rounds[0].id });
      break;
    case "parallel":
    case "perpendicular":
      if (lines.length === 2) out.push({ type: kind, a: lines[0].id, b: lines[1].id });
      break;
    case "angle":
      if (lines.length === 2) {
        const dir = (l) => {
          const [p, q] = l.points.map((p) => app.sketch.point(p));
          return Math.atan2(q[1] - p[1], q[0] - p[0]);
        };
        let now = ((dir(lines[1]) - dir(lines[0])) * 180) / Math.PI;
        now = ((now + 540) % 360) - 180;
        const v = ask("angle (degrees, counter-clockwise from the first line)", now);
        if (v !== null) out.push({ type: "angle", a: lines[0].id, b: lines[1].id, degrees: v });
      }
      break;
    case "equal":
      if (lines.length === 2) out.push({ type: "equal_length", a: lines[0].id, b: lines[1].id });
      else if (rounds.length === 2) out.push({ type: "equal_radius", a: rounds[0].id, b: rounds[1].id });
      break;
    case "radius":
      for (const r of rounds) {
        const v = ask(`radius of ${r.name}`, app.sketch.radius(r.id));
        if (v !== null) out.push({ type: "radius", shape: r.id, value: v });
      }
      break;
    case "tangent":
      if (lines.length === 1 && rounds.length === 1) {
        const [l, r] = [lines[0], rounds[0]];
        const spec = { type: "tangent", a: l.id, b: r.id };
        if (r.kind === "arc") {
          const ends = l.points.map((p) => app.sketch.point(p));
          const e0 = nearestEnd(r, ends[0]);
          const e1 = nearestEnd(r, ends[1]);
          spec.b_end = e0 === e1 ? e0 : e0;
        }
        out.push(spec);
      } else if (rounds.length === 2) {
        out.push({ type: "tangent", a: rounds[0].id, b: rounds[1].id });
      }
      break;
    case "midpoint":
      if (pts.length === 1 && lines.length === 1) out.push({ type: "midpoint", point: pts[0].id, line: lines[0].id });
      break;
    case "concentric":
      if (rounds.length === 2) out.push({ type: "concentric", a: rounds[0].id, b: rounds[1].id });
      break;
  }
  return out;
}

for (const b of document.querySelectorAll("#constraints-bar button")) {
  b.onclick = () => {
    message("");
    const kind = b.dataset.c;
    const sel = selected();
    if (kind === "delete") {
      for (const s of sel) if (app.byId.has(s.id)) guarded(() => app.sketch.removeShape(s.id));
      app.selection.clear();
      refresh();
      return;
    }
    if (kind === "construction") {
      for (const s of sel) guarded(() => app.sketch.setConstruction(s.id, !s.construction));
      refresh({ solve: false });
      return;
    }
    const specs = constraintsFor(kind, sel);
    if (specs.length === 0) {
      message(`${b.textContent}: select ${hint(kind)}`);
      return;
    }
    for (const spec of specs) guarded(() => app.sketch.addConstraint(spec));
    refresh();
  };
}

function hint(kind) {
  return {
    fix: "points or shapes", horizontal: "lines", vertical: "lines", length: "a line, two points, or a point and a line",
    coincident: "two points, or a point and a line or circle", on: "a point and a line or circle",
    parallel: "two lines", perpendicular: "two lines", angle: "two lines", equal: "two lines or two circles/arcs",
    radius: "circles or arcs", tangent: "a line and a circle/arc, or two circles/arcs", midpoint: "a point and a line",
    concentric: "two circles/arcs",
  }[kind];
}

document.addEventListener("keydown", (ev) => {
  if (ev.target instanceof HTMLInputElement) return;
  const tool = { s: "select", p: "point", l: "line", c: "circle", a: "arc" }[ev.key];
  if (tool) setTool(tool);
  if (ev.key === "Escape") { app.pending = []; app.selection.clear(); draw(); }
  if (ev.key === "Delete" || ev.key === "Backspace") document.querySelector('[data-c="delete"]').click();
});

function download(name, data, type) {
  const url = URL.createObjectURL(new Blob([data], { type }));
  const a = Object.assign(document.createElement("a"), { href: url, download: name });
  a.click();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

$("new").onclick = () => load(new Sketch(), { fit: false });
$("save-json").onclick = () => download("sketch.json", app.readonly ? app.readonly.json() : app.sketch.toJson(), "application/json");
$("save-slvs").onclick = () => guarded(() => download("sketch.slvs", app.readonly ? app.readonly.slvs() : app.sketch.toSlvs(), "application/octet-stream"));

$("open").onchange = async (ev) => {
  const file = ev.target.files[0];
  ev.target.value = "";
  if (!file) return;
  const bytes = new Uint8Array(await file.arrayBuffer());
  guarded(() => openBytes(file.name, bytes));
};

/** Opens a file by its content: a sketch, an assembly, a loci problem or a .slvs file. */
function openBytes(name, bytes) {
  if (name.endsWith(".slvs")) {
    showReadonly(new SystemView(System.fromSlvs(bytes), name));
    return;
  }
  const text = new TextDecoder().decode(bytes);
  const json = JSON.parse(text);
  if (json.sketch) load(Sketch.fromJson(text));
  else if (json.loci_assembly !== undefined || json.components) showReadonly(new AssemblyView(Assembly.fromJson(text), name));
  else showReadonly(new SystemView(System.fromJson(text), name));
}

function showReadonly(v) {
  app.readonly = v;
  app.selection.clear();
  $("dof").textContent = v.dof();
  $("outcome").textContent = v.summary();
  $("constraint-list").replaceChildren(...v.lines().map((t) => Object.assign(document.createElement("li"), { textContent: t })));
  view.fit(v.bounds());
  draw();
  v.animate?.(() => draw());
}

async function gallery(name) {
  if (name.startsWith("gen:")) {
    const s = new Sketch();
    const info = name === "gen:fourbar1000" ? fourBarAmongRectangles(s, 1000) : hingedTriangles(s, 1000);
    load(s);
    return info;
  }
  if (name.startsWith("asm:")) {
    const text = await (await fetch(`pkg/examples/assembly/${name.slice(4)}.json`)).text();
    showReadonly(new AssemblyView(Assembly.fromJson(text), name.slice(4)));
    return null;
  }
  const text = await (await fetch(`pkg/examples/sketches/${name}.json`)).text();
  load(Sketch.fromJson(text));
  return null;
}
$("gallery").onchange = (ev) => ev.target.value && gallery(ev.target.value);

// What a test (or the console) reads: the sketch, screen positions, drag times.
window.lociApp = {
  app,
  view,
  gallery,
  pointByName(name) {
    return app.shapes.find((s) => s.name === name)?.id;
  },
  /** The client (page) coordinates of a point of the model. */
  clientXY(x, y) {
    const r = canvas.getBoundingClientRect();
    const [px, py] = view.toScreen(x, y);
    return [r.left + (px * r.width) / canvas.width, r.top + (py * r.height) / canvas.height];
  },
  /** Shows the box [minx, miny, maxx, maxy] of the model. */
  fit(box) {
    view.fit(box);
    draw();
  },
  PACKED,
  ready: true,
};

await gallery("four_bar");
$("gallery").value = "four_bar";
document.body.dataset.ready = "true";
