// The drawing: world (model units, y up) to canvas pixels, drawing of shapes by state, and
// hit tests.

/** Numbers of the packed geometry per shape kind (Sketch.geometry()). */
export const PACKED = { point: 2, line: 4, circle: 3, arc: 6, cubic: 8 };

export const COLOURS = {
  fixed: "#1a7f37",
  free: "#0969da",
  bad: "#cf222e",
  selected: "#bf8700",
  preview: "#8c959f",
  readonly: "#57606a",
};

export class View {
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = canvas.getContext("2d");
    this.scale = 40;
    this.origin = [canvas.width / 2, canvas.height / 2];
  }

  toScreen(x, y) {
    return [this.origin[0] + x * this.scale, this.origin[1] - y * this.scale];
  }

  toWorld(px, py) {
    return [(px - this.origin[0]) / this.scale, (this.origin[1] - py) / this.scale];
  }

  /** Fits the box [minx, miny, maxx, maxy] in the canvas with a margin. */
  fit(box) {
    const [x0, y0, x1, y1] = box;
    if (!Number.isFinite(x0)) return;
    const w = Math.max(x1 - x0, 1e-3);
    const h = Math.max(y1 - y0, 1e-3);
    this.scale = Math.min((this.canvas.width - 80) / w, (this.canvas.height - 80) / h);
    this.origin = [
      this.canvas.width / 2 - ((x0 + x1) / 2) * this.scale,
      this.canvas.height / 2 + ((y0 + y1) / 2) * this.scale,
    ];
  }

  clear() {
    this.ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
  }

  /** Draws every shape; `style(shape)` gives its colour, `dashed(shape)` its dash. */
  drawShapes(shapes, geometry, style, dashed) {
    const ctx = this.ctx;
    let k = 0;
    const points = [];
    for (const sh of shapes) {
      const g = geometry.subarray(k, k + PACKED[sh.kind]);
      k += PACKED[sh.kind];
      ctx.strokeStyle = style(sh);
      ctx.lineWidth = 2;
      ctx.setLineDash(dashed(sh) ? [6, 4] : []);
      ctx.beginPath();
      if (sh.kind === "point") {
        points.push([sh, g[0], g[1]]);
        continue;
      } else if (sh.kind === "line") {
        ctx.moveTo(...this.toScreen(g[0], g[1]));
        ctx.lineTo(...this.toScreen(g[2], g[3]));
      } else if (sh.kind === "circle") {
        const [cx, cy] = this.toScreen(g[0], g[1]);
        ctx.arc(cx, cy, g[2] * this.scale, 0, 2 * Math.PI);
      } else if (sh.kind === "arc") {
        const [cx, cy] = this.toScreen(g[0], g[1]);
        const r = Math.hypot(g[2] - g[0], g[3] - g[1]);
        const a0 = Math.atan2(g[3] - g[1], g[2] - g[0]);
        const a1 = Math.atan2(g[5] - g[1], g[4] - g[0]);
        // Counter-clockwise in the model is clockwise on screen (y down).
        ctx.arc(cx, cy, r * this.scale, -a0, -a1, true);
      } else if (sh.kind === "cubic") {
        ctx.moveTo(...this.toScreen(g[0], g[1]));
        ctx.bezierCurveTo(...this.toScreen(g[2], g[3]), ...this.toScreen(g[4], g[5]), ...this.toScreen(g[6], g[7]));
      }
      ctx.stroke();
    }
    ctx.setLineDash([]);
    for (const [sh, x, y] of points) {
      const [px, py] = this.toScreen(x, y);
      ctx.fillStyle = style(sh);
      ctx.fillRect(px - 3.5, py - 3.5, 7, 7);
    }
  }

  /** Writes each point's name beside it, when it has one of its own. */
  drawNames(shapes, geometry) {
    const ctx = this.ctx;
    ctx.font = "12px system-ui, sans-serif";
    ctx.fillStyle = "#1f2328";
    let k = 0;
    for (const sh of shapes) {
      if (sh.kind === "point" && !sh.name.startsWith("point_")) {
        const [x, y] = this.toScreen(geometry[k], geometry[k + 1]);
        ctx.fillText(sh.name, x + 6, y - 6);
      }
      k += PACKED[sh.kind];
    }
  }

  /** The shape under the pixel (points first), or null. */
  hit(shapes, geometry, px, py, tolerance = 8) {
    let best = null;
    let bestD = tolerance;
    let k = 0;
    const offsets = [];
    for (const sh of shapes) {
      offsets.push(k);
      k += PACKED[sh.kind];
    }
    const d2seg = (ax, ay, bx, by) => {
      const vx = bx - ax, vy = by - ay;
      const t = Math.max(0, Math.min(1, ((px - ax) * vx + (py - ay) * vy) / (vx * vx + vy * vy || 1)));
      return Math.hypot(ax + t * vx - px, ay + t * vy - py);
    };
    for (const pass of ["point", "curve"]) {
      shapes.forEach((sh, i) => {
        const g = geometry.subarray(offsets[i], offsets[i] + PACKED[sh.kind]);
        let d = Infinity;
        if (pass === "point" && sh.kind === "point") {
          const [x, y] = this.toScreen(g[0], g[1]);
          d = Math.hypot(x - px, y - py);
        } else if (pass === "curve" && sh.kind === "line") {
          d = d2seg(...this.toScreen(g[0], g[1]), ...this.toScreen(g[2], g[3]));
        } else if (pass === "curve" && (sh.kind === "circle" || sh.kind === "arc")) {
          const [cx, cy] = this.toScreen(g[0], g[1]);
          const r = sh.kind === "circle" ? g[2] : Math.hypot(g[2] - g[0], g[3] - g[1]);
          d = Math.abs(Math.hypot(px - cx, py - cy) - r * this.scale);
        }
        if (d < bestD) {
          bestD = d;
          best = sh;
        }
      });
      if (best) return best;
    }
    return null;
  }
}

/** The bounding box of packed geometry (points and circle extents). */
export function bounds(shapes, geometry) {
  const box = [Infinity, Infinity, -Infinity, -Infinity];
  const add = (x, y) => {
    box[0] = Math.min(box[0], x); box[1] = Math.min(box[1], y);
    box[2] = Math.max(box[2], x); box[3] = Math.max(box[3], y);
  };
  let k = 0;
  for (const sh of shapes) {
    const g = geometry.subarray(k, k + PACKED[sh.kind]);
    k += PACKED[sh.kind];
    if (sh.kind === "circle") {
      add(g[0] - g[2], g[1] - g[2]);
      add(g[0] + g[2], g[1] + g[2]);
    } else {
      for (let i = 0; i + 1 < g.length; i += 2) add(g[i], g[i + 1]);
    }
  }
  return box;
}
