// Sketches the gallery builds by calls, as loci's drag benchmark does (bench/src/drag.rs):
// the four-bar linkage among fixed rectangles, and a chain of hinged rigid triangles.

/** A crank-rocker with a coupler triangle, beside fully dimensioned rectangles up to `size` shapes. */
export function fourBarAmongRectangles(s, size) {
  const p = (x, y, name) => s.addPoint(x, y, name);
  const a = p(0, 0, "A");
  const d = p(4, 0, "D");
  const b = p(1, 0, "B");
  const c = p(3.6667, 2.9814, "C");
  const e = p(1.588, 2.158, "E");
  s.addConstraint({ type: "fix", point: a });
  s.addConstraint({ type: "fix", point: d });
  const bar = (u, v, len, name) => {
    const l = s.addLine(u, v, name);
    if (len !== undefined) s.addConstraint({ type: "length", line: l, value: len });
    return l;
  };
  bar(a, b, 1, "crank");
  bar(b, c, 4, "coupler");
  bar(d, c, 3, "rocker");
  bar(b, e, 2.5, "BE");
  bar(c, e, 2.5, "CE");
  let n = 10;
  for (let k = 0; n + 8 <= size; k++, n += 8) {
    const x0 = 10 + 6 * (k % 40);
    const y0 = 6 * Math.floor(k / 40);
    const q = [[0, 0], [4, 0], [4, 2], [0, 2]].map(([x, y]) => p(x0 + x, y0 + y));
    const l = [0, 1, 2, 3].map((i) => s.addLine(q[i], q[(i + 1) % 4]));
    s.addConstraint({ type: "fix", point: q[0] });
    s.addConstraint({ type: "horizontal", line: l[0] });
    s.addConstraint({ type: "horizontal", line: l[2] });
    s.addConstraint({ type: "vertical", line: l[1] });
    s.addConstraint({ type: "vertical", line: l[3] });
    s.addConstraint({ type: "length", line: l[0], value: 4 });
    s.addConstraint({ type: "length", line: l[1], value: 2 });
  }
  return { grip: b, triangle: [b, c, e] };
}

/** Rigid unit triangles joined at their corners, the first corner fixed: about `size` shapes. */
export function hingedTriangles(s, size) {
  const n = Math.max(1, Math.floor((size - 1) / 5));
  const h = Math.sqrt(3) / 2;
  let corner = s.addPoint(0, 0, "start");
  s.addConstraint({ type: "fix", point: corner });
  const triangles = [];
  for (let i = 0; i < n; i++) {
    const apex = s.addPoint(i + 0.5, i % 2 === 0 ? h : -h);
    const next = s.addPoint(i + 1, 0, i === n - 1 ? "end" : undefined);
    for (const [u, v] of [[corner, apex], [apex, next], [corner, next]]) {
      s.addConstraint({ type: "length", line: s.addLine(u, v), value: 1 });
    }
    triangles.push([corner, apex, next]);
    corner = next;
  }
  return { grip: corner, triangles };
}
