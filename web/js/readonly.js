// Views of what the sketcher does not edit: a loci problem or .slvs file (its geometry drawn
// from the solved values, projected on the xy plane) and an assembly (its components'
// references by their poses, in an isometric view, animated through the stepped solve).
import { COLOURS } from "./view.js";

/** v rotated by the unit quaternion q = [w, x, y, z]. */
function rotate(q, v) {
  const [w, x, y, z] = q;
  const [vx, vy, vz] = v;
  // t = 2 (q.xyz × v); v' = v + w t + q.xyz × t
  const tx = 2 * (y * vz - z * vy), ty = 2 * (z * vx - x * vz), tz = 2 * (x * vy - y * vx);
  return [vx + w * tx + (y * tz - z * ty), vy + w * ty + (z * tx - x * tz), vz + w * tz + (x * ty - y * tx)];
}

function boxOf(points) {
  const b = [Infinity, Infinity, -Infinity, -Infinity];
  for (const [x, y] of points) {
    b[0] = Math.min(b[0], x); b[1] = Math.min(b[1], y); b[2] = Math.max(b[2], x); b[3] = Math.max(b[3], y);
  }
  return b;
}

export class SystemView {
  constructor(sys, name) {
    this.sys = sys;
    this.name = name;
    if (name.endsWith(".slvs")) {
      this.groups = sys.solveAll();
    } else {
      this.report = sys.solveRequest();
    }
    this.build();
  }

  build() {
    const model = this.sys.model();
    const val = new Map();
    const hs = this.sys.paramHandles();
    const vs = this.sys.values();
    hs.forEach((h, i) => val.set(h, vs[i]));
    const ents = new Map(model.entities.map((e) => [e.h, e]));
    const v = (h) => val.get(h) ?? 0;
    const point = (h, depth = 0) => {
      const e = ents.get(h);
      if (!e || depth > 8) return null;
      if (e.type === "point_in_2d") {
        const wp = ents.get(e.workplane);
        const o = wp && point(wp.origin, depth + 1);
        const n = wp && ents.get(wp.normal);
        if (!o || !n || !n.params) return null;
        const q = n.params.map(v);
        const r = rotate(q, [v(e.params[0]), v(e.params[1]), 0]);
        return [o[0] + r[0], o[1] + r[1], o[2] + r[2]];
      }
      if (e.params && e.params.length === 3 && e.type.startsWith("point")) return e.params.map(v);
      return null;
    };
    this.segments = [];
    this.circles = [];
    this.points = [];
    for (const e of model.entities) {
      if (e.type === "line_segment") {
        const [a, b] = e.points.map((p) => point(p));
        if (a && b) this.segments.push([a, b]);
      } else if (e.type === "circle") {
        const c = point(e.center);
        const r = ents.get(e.radius);
        if (c && r) this.circles.push([c, Math.abs(v(r.param)), 0, 2 * Math.PI]);
      } else if (e.type === "arc_of_circle") {
        const [c, s, t] = [e.center, e.start, e.end].map((p) => point(p));
        if (c && s && t) {
          const a0 = Math.atan2(s[1] - c[1], s[0] - c[0]);
          const a1 = Math.atan2(t[1] - c[1], t[0] - c[0]);
          this.circles.push([c, Math.hypot(s[0] - c[0], s[1] - c[1]), a0, a1]);
        }
      } else if (e.type.startsWith("point")) {
        const p = point(e.h);
        if (p) this.points.push(p);
      }
    }
  }

  draw(view) {
    const ctx = view.ctx;
    ctx.strokeStyle = COLOURS.readonly;
    ctx.lineWidth = 1.5;
    for (const [a, b] of this.segments) {
      ctx.beginPath();
      ctx.moveTo(...view.toScreen(a[0], a[1]));
      ctx.lineTo(...view.toScreen(b[0], b[1]));
      ctx.stroke();
    }
    for (const [c, r, a0, a1] of this.circles) {
      const [cx, cy] = view.toScreen(c[0], c[1]);
      ctx.beginPath();
      ctx.arc(cx, cy, r * view.scale, -a0, -a1, true);
      ctx.stroke();
    }
    ctx.fillStyle = COLOURS.readonly;
    for (const p of this.points) {
      const [x, y] = view.toScreen(p[0], p[1]);
      ctx.fillRect(x - 2, y - 2, 4, 4);
    }
  }

  bounds() {
    return boxOf([...this.points, ...this.segments.flat()]);
  }

  dof() {
    if (this.report) return String(this.report.dof);
    return this.groups.map((g) => g.dof ?? "–").join(" / ");
  }

  summary() {
    if (this.report) return `${this.name}: ${this.report.outcome.replaceAll("_", " ")} (read only)`;
    const ok = this.groups.filter((g) => g.ok).length;
    return `${this.name}: ${ok} of ${this.groups.length} groups ok (read only)`;
  }

  lines() {
    if (this.report) return [`solve: ${this.report.outcome}, failed: ${this.report.failed.join(", ") || "none"}`];
    return this.groups.map((g) => `group ${g.group} ${g.name}: ${g.result}`);
  }

  json() {
    return this.sys.toJson();
  }

  slvs() {
    return this.sys.toSlvs();
  }
}

/** Isometric projection of a world point. */
function iso(p) {
  const c = Math.cos(Math.PI / 6), s = Math.sin(Math.PI / 6);
  return [(p[0] - p[1]) * c, p[2] + (p[0] + p[1]) * s];
}

const PALETTE = ["#57606a", "#0969da", "#1a7f37", "#8250df", "#bf3989", "#bc4c00"];

export class AssemblyView {
  constructor(asm, name) {
    this.asm = asm;
    this.name = name;
    this.components = asm.components();
    const run = asm.solveStepped();
    this.frames = run.iterations.map((it) => it.poses);
    this.report = asm.solve();
    this.frames.push(this.report.components.map((c) => c.pose));
    this.frame = 0;
    let size = 0;
    for (const c of this.components) for (const r of Object.values(c.references ?? {})) {
      const p = r.point ?? r.center ?? [0, 0, 0];
      size = Math.max(size, Math.hypot(...p));
    }
    this.size = Math.max(size, 1);
  }

  /** The drawn pieces of every component at the current frame, in the iso plane. */
  pieces() {
    const poses = this.frames[Math.min(this.frame, this.frames.length - 1)];
    const L = this.size * 0.6;
    return this.components.map((c, i) => {
      const pose = poses[i] ?? c.pose;
      const world = (p) => {
        const r = rotate(pose.rotation, p);
        return [r[0] + pose.translation[0], r[1] + pose.translation[1], r[2] + pose.translation[2]];
      };
      const dir = (d) => rotate(pose.rotation, d);
      const segs = [];
      const dots = [world([0, 0, 0])];
      for (const r of Object.values(c.references ?? {})) {
        if (r.type === "axis" || r.type === "edge") {
          const p = world(r.point), d = dir(r.direction);
          segs.push([[p[0] - L * d[0], p[1] - L * d[1], p[2] - L * d[2]], [p[0] + L * d[0], p[1] + L * d[1], p[2] + L * d[2]]]);
        } else if (r.type === "face") {
          const p = world(r.point), n = dir(r.normal);
          // A square in the face's plane, and its normal.
          const t = Math.abs(n[2]) < 0.9 ? [0, 0, 1] : [1, 0, 0];
          const u = [n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]];
          const un = Math.hypot(...u);
          const uu = u.map((x) => (x / un) * L * 0.5);
          const vv = [n[1] * uu[2] - n[2] * uu[1], n[2] * uu[0] - n[0] * uu[2], n[0] * uu[1] - n[1] * uu[0]];
          const corner = (a, b) => [p[0] + a * uu[0] + b * vv[0], p[1] + a * uu[1] + b * vv[1], p[2] + a * uu[2] + b * vv[2]];
          const sq = [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)];
          for (let k = 0; k < 4; k++) segs.push([sq[k], sq[(k + 1) % 4]]);
          segs.push([p, [p[0] + n[0] * L * 0.3, p[1] + n[1] * L * 0.3, p[2] + n[2] * L * 0.3]]);
        } else if (r.type === "vertex") {
          dots.push(world(r.point));
        } else if (r.type === "circular_edge") {
          const p = world(r.center);
          dots.push(p);
        }
        if (r.point) segs.push([world([0, 0, 0]), world(r.point)]);
      }
      return { colour: PALETTE[i % PALETTE.length], segs: segs.map(([a, b]) => [iso(a), iso(b)]), dots: dots.map(iso) };
    });
  }

  draw(view) {
    const ctx = view.ctx;
    ctx.lineWidth = 2;
    for (const p of this.pieces()) {
      ctx.strokeStyle = p.colour;
      ctx.fillStyle = p.colour;
      for (const [a, b] of p.segs) {
        ctx.beginPath();
        ctx.moveTo(...view.toScreen(a[0], a[1]));
        ctx.lineTo(...view.toScreen(b[0], b[1]));
        ctx.stroke();
      }
      for (const d of p.dots) {
        const [x, y] = view.toScreen(d[0], d[1]);
        ctx.fillRect(x - 3, y - 3, 6, 6);
      }
    }
  }

  bounds() {
    const all = [];
    for (let f = 0; f < this.frames.length; f++) {
      this.frame = f;
      for (const p of this.pieces()) all.push(...p.segs.flat(), ...p.dots);
    }
    this.frame = 0;
    return boxOf(all);
  }

  /** Plays the stepped solve, then stays on the final solve's poses. */
  animate(redraw) {
    const n = this.frames.length;
    const stride = Math.max(1, Math.ceil(n / 90));
    const tick = () => {
      this.frame = Math.min(this.frame + stride, n - 1);
      redraw();
      if (this.frame < n - 1) setTimeout(tick, 30);
    };
    setTimeout(tick, 30);
  }

  dof() {
    return String(this.report.dof);
  }

  summary() {
    const bad = this.report.mates.filter((m) => !["satisfied", "adjusted", "redundant"].includes(m.status));
    return `${this.name}: ${this.report.outcome.replaceAll("_", " ")}, ${bad.length ? `${bad.length} mates fail` : "every mate holds"} (read only)`;
  }

  lines() {
    return [
      ...this.report.mates.map((m) => `${m.id} (${m.kind}): ${m.status}${m.value !== undefined ? ` = ${m.value.toFixed(3)}` : ""}`),
      ...this.report.components.map((c) => `${c.name}: ${c.grounded ? "grounded" : c.dof === null ? "motions not computed" : c.dof === 0 ? "fully placed" : `${c.dof} dof; ${c.motions.join("; ")}`}`),
    ];
  }

  json() {
    return this.asm.toJson();
  }

  slvs() {
    throw new Error("an assembly has no .slvs form");
  }
}
