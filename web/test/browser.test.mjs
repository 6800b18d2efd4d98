// The sketcher in a real browser: Debian's chromium, headless, driven by playwright-core. It
// loads the page, drags the four-bar's crank pin with real mouse events along a circle, reads
// back every point after every move and checks the bar lengths hold, the fixed pivots stay and
// the coupler triangle never turns over; draws a line and adds a conflicting dimension from
// the toolbar and checks the conflict is listed in red by name; saves the sketch as JSON and
// as .slvs and opens the .slvs again; shows the door hinge assembly; solves a 10,000-segment
// chain in the page; times drag steps at 1,000 shapes; and saves a screenshot to
// docs/img/web-sketcher.png.
//
// usage: node web/test/browser.test.mjs   (after scripts/build-wasm.sh; CHROMIUM overrides
// /usr/bin/chromium)
import { test, after, before } from "node:test";
import assert from "node:assert/strict";
import { mkdtempSync, rmSync, mkdirSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { fileURLToPath } from "node:url";
import { createRequire } from "node:module";
import { serve } from "./serve.mjs";

const require = createRequire(new URL("../../crates/loci-wasm/package.json", import.meta.url));
const { chromium } = require("playwright-core");

const shot = fileURLToPath(new URL("../../docs/img/web-sketcher.png", import.meta.url));
let browser, page, server, profile;
const problems = [];

before(async () => {
  const s = await serve();
  server = s.server;
  profile = mkdtempSync(join(tmpdir(), "loci-chromium-"));
  // A fresh profile (playwright passes it as --user-data-dir).
  browser = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
    headless: true,
    args: [
      "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
      "--disable-background-networking", "--disable-component-update", "--disable-sync",
    ],
    viewport: { width: 1280, height: 760 },
    acceptDownloads: true,
  });
  page = browser.pages()[0] ?? (await browser.newPage());
  page.on("pageerror", (e) => problems.push(`page error: ${e.message}`));
  page.on("console", (m) => m.type() === "error" && problems.push(`console: ${m.text()}`));
  await page.goto(s.url);
  await page.waitForSelector("body[data-ready=true]", { timeout: 30000 });
});

after(async () => {
  await browser?.close();
  server?.close();
  if (profile) rmSync(profile, { recursive: true, force: true });
});

/** Every point of the sketch by name: [x, y]. */
const points = () =>
  page.evaluate(() => {
    const { app } = window.lociApp;
    const out = {};
    for (const s of app.shapes) if (s.kind === "point") out[s.name] = app.sketch.point(s.id);
    return out;
  });

const clientOf = (x, y) => page.evaluate(([x, y]) => window.lociApp.clientXY(x, y), [x, y]);
const dist = (p, q) => Math.hypot(p[0] - q[0], p[1] - q[1]);
const area = (a, b, c) => (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);

test("the four-bar follows its crank pin dragged round a circle with the mouse", async () => {
  const start = await points();
  assert.deepEqual(Object.keys(start).sort(), ["A", "B", "C", "D", "E"]);
  assert.equal(await page.textContent("#dof"), "1");
  const sign = Math.sign(area(start.B, start.C, start.E));
  // Show the whole path of the cursor.
  await page.evaluate(() => window.lociApp.fit([-2.2, -2.2, 5, 4.2]));
  await page.mouse.move(...(await clientOf(...start.B)));
  await page.mouse.down();
  const steps = 90;
  for (let k = 1; k <= steps; k++) {
    // Round a circle of radius 2 about A, out of the crank's reach: the pin follows the
    // direction of the cursor.
    const t = (2 * Math.PI * k) / steps;
    await page.mouse.move(...(await clientOf(2 * Math.cos(t), 2 * Math.sin(t))));
    const p = await points();
    assert.deepEqual(p.A, [0, 0], `step ${k}: A moved`);
    assert.deepEqual(p.D, [4, 0], `step ${k}: D moved`);
    for (const [a, b, len] of [["A", "B", 1], ["B", "C", 4], ["D", "C", 3], ["B", "E", 2.5], ["C", "E", 2.5]]) {
      assert.ok(Math.abs(dist(p[a], p[b]) - len) < 1e-7, `step ${k}: |${a}${b}| = ${dist(p[a], p[b])}, not ${len}`);
    }
    assert.equal(Math.sign(area(p.B, p.C, p.E)), sign, `step ${k}: the coupler triangle flipped`);
    // Where the mouse is, in model units: the pin points at it (up to a pixel).
    const px = await page.evaluate(() => 1 / window.lociApp.view.scale);
    const want = Math.atan2(Math.sin(t), Math.cos(t));
    const got = Math.atan2(p.B[1], p.B[0]);
    const diff = Math.abs(Math.atan2(Math.sin(got - want), Math.cos(got - want)));
    assert.ok(diff < (2 * px) / 2 + 1e-6, `step ${k}: the crank points ${got}, the cursor ${want}`);
  }
  await page.mouse.up();
  const times = await page.evaluate(() => window.lociApp.app.dragTimes);
  assert.equal(times.length, steps);
  console.log(`four-bar drag in chromium: ${steps} steps, median ${median(times).toFixed(3)} ms`);
  assert.equal(await page.textContent("#dof"), "1");
  assert.equal(await page.textContent("#message"), "");
});

test("a line drawn with the mouse, and a conflicting dimension listed in red by name", async () => {
  // Draw a free line below the linkage.
  await page.click('[data-tool="line"]');
  const before = await page.evaluate(() => window.lociApp.app.shapes.length);
  await page.mouse.click(...(await clientOf(-1, -2)));
  await page.mouse.click(...(await clientOf(3, -2.5)));
  const after = await page.evaluate(() => window.lociApp.app.shapes.length);
  assert.equal(after, before + 3, "two points and a line");
  assert.equal(await page.textContent("#dof"), "5");
  await page.click('[data-tool="select"]');
  // Select the crank (click its middle) and give it a second length: a conflict.
  const p = await points();
  await page.mouse.click(...(await clientOf((p.A[0] + p.B[0]) / 2, (p.A[1] + p.B[1]) / 2)));
  page.once("dialog", (d) => d.accept("1.5"));
  await page.click('[data-c="length"]');
  const bad = await page.$$eval("#constraint-list li.bad span", (xs) => xs.map((x) => x.textContent));
  assert.ok(bad.length >= 2, `conflicting constraints listed: ${bad}`);
  assert.ok(bad.every((n) => n.includes("length")), bad.join());
  const colour = await page.$eval("#constraint-list li.bad", (li) => getComputedStyle(li).color);
  assert.equal(colour, "rgb(207, 34, 46)");
  // Removing the new dimension ends the conflict.
  const last = await page.$$eval("#constraint-list li", (xs) => xs.length);
  await page.click(`#constraint-list li:nth-child(${last}) button`);
  assert.equal(await page.$$eval("#constraint-list li.bad", (xs) => xs.length), 0);
  // Save: the sketch file downloads with the drawn line in it.
  const [download] = await Promise.all([page.waitForEvent("download"), page.click("#save-json")]);
  const path = await download.path();
  const { readFileSync } = await import("node:fs");
  const saved = JSON.parse(readFileSync(path, "utf8"));
  assert.equal(saved.sketch.lines.length, 7);
  assert.equal(saved.sketch.points.length, 7);
});

test("the gallery loads the slot and bracket fully solved, and a screenshot is saved", async () => {
  for (const name of ["slot", "bracket"]) {
    await page.selectOption("#gallery", name);
    await page.waitForFunction((n) => window.lociApp.app.shapes.length > 0 && document.querySelector("#gallery").value === n, name);
    const outcome = await page.textContent("#outcome");
    assert.ok(outcome === "okay" || outcome === "redundant okay", `${name}: ${outcome}`);
    assert.equal(await page.$$eval("#constraint-list li.bad", (xs) => xs.length), 0, name);
  }
  // The bracket saved as .slvs and opened again: a read-only view whose groups all solve.
  const [slvs] = await Promise.all([page.waitForEvent("download"), page.click("#save-slvs")]);
  const { readFileSync } = await import("node:fs");
  const bytes = readFileSync(await slvs.path());
  assert.match(bytes.subarray(0, 40).toString("latin1"), /SolveSpaceREVa/);
  await page.setInputFiles("#open", { name: "bracket.slvs", mimeType: "application/octet-stream", buffer: bytes });
  await page.waitForFunction(() => document.querySelector("#outcome").textContent.includes("bracket.slvs"));
  assert.match(await page.textContent("#outcome"), /(\d+) of \1 groups ok/);
  // The assembly view: the door hinge opens and every mate holds.
  await page.selectOption("#gallery", "asm:door_hinge");
  await page.waitForFunction(() => document.querySelector("#outcome").textContent.includes("door_hinge"));
  assert.match(await page.textContent("#outcome"), /every mate holds/);
  await page.selectOption("#gallery", "four_bar");
  await page.waitForFunction(() => window.lociApp.app.shapes.length === 11);
  await page.evaluate(() => window.lociApp.fit([-1.2, -1.2, 5, 4.2]));
  const p = await points();
  // Leave the crank part way round for the picture.
  await page.mouse.move(...(await clientOf(...p.B)));
  await page.mouse.down();
  for (let k = 1; k <= 10; k++) {
    const t = (k / 10) * 1.2;
    await page.mouse.move(...(await clientOf(Math.cos(t), Math.sin(t))));
  }
  await page.mouse.up();
  mkdirSync(fileURLToPath(new URL("../../docs/img/", import.meta.url)), { recursive: true });
  await page.screenshot({ path: shot });
});

test("a 10,000-segment chain solves in the page, timed", async () => {
  const r = await page.evaluate(async () => {
    const { Sketch } = await import("/pkg/web.js");
    // Segments of their own joined end to start, each with its length and its angle to the
    // previous one, the first point fixed, drawn 5% off their lengths and 3 degrees off.
    const n = 10000;
    const s = new Sketch();
    let x = 0, y = 0, heading = 0.3;
    const lines = [], lens = [];
    let prevEnd = null;
    let seed = 7;
    const rnd = () => ((seed = (seed * 16807) % 2147483647) / 2147483647);
    for (let i = 0; i < n; i++) {
      const len = 5 + 10 * rnd();
      const a = s.addPoint(x, y);
      const turn = (15 + 60 * rnd()) * (rnd() < 0.5 ? 1 : -1);
      const h = heading + ((turn + 3) * Math.PI) / 180;
      x += 1.05 * len * Math.cos(h);
      y += 1.05 * len * Math.sin(h);
      const b = s.addPoint(x, y);
      const l = s.addLine(a, b);
      s.addConstraint({ type: "length", line: l, value: len });
      if (i === 0) s.addConstraint({ type: "fix", point: a });
      else {
        s.addConstraint({ type: "coincident", a: prevEnd, b: a });
        s.addConstraint({ type: "angle", a: lines[i - 1], b: l, degrees: turn });
      }
      heading += (turn * Math.PI) / 180;
      lines.push(l);
      lens.push(len);
      prevEnd = b;
    }
    const t0 = performance.now();
    const rep = s.solve();
    const ms = performance.now() - t0;
    let worst = 0;
    for (let i = 0; i < n; i++) worst = Math.max(worst, Math.abs(s.lineLength(lines[i]) - lens[i]));
    s.free();
    return { outcome: rep.outcome, ms, worst, iterations: rep.iterations };
  });
  assert.equal(r.outcome, "okay");
  assert.ok(r.worst < 1e-7, `a length is off by ${r.worst}`);
  console.log(`10,000-segment chain in chromium: solved in ${r.ms.toFixed(1)} ms (${r.iterations} iterations)`);
});

test("drag steps at 1,000 shapes, timed in the browser", async () => {
  for (const [name, grip] of [["gen:fourbar1000", "B"], ["gen:triangles1000", "end"]]) {
    await page.evaluate((n) => window.lociApp.gallery(n), name);
    const shapes = await page.evaluate(() => window.lociApp.app.shapes.length);
    assert.ok(shapes >= 990 && shapes <= 1000, `${name}: ${shapes} shapes`);
    const g = (await points())[grip];
    await page.evaluate(([x, y]) => window.lociApp.fit([x - 3, y - 2.5, x + 2, y + 2.5]), g);
    await page.mouse.move(...(await clientOf(...g)));
    await page.mouse.down();
    const steps = 120;
    for (let k = 1; k <= steps; k++) {
      const t = (2 * Math.PI * k) / steps;
      const c = name === "gen:fourbar1000" ? [Math.cos(t), Math.sin(t)] : [g[0] - 1 + Math.cos(t), g[1] + Math.sin(t)];
      await page.mouse.move(...(await clientOf(...c)));
    }
    await page.mouse.up();
    const times = await page.evaluate(() => window.lociApp.app.dragTimes);
    assert.equal(times.length, steps);
    const rest = times.slice(1).sort((a, b) => a - b);
    console.log(
      `drag in chromium, ${name.slice(4)} (${shapes} shapes): first step ${times[0].toFixed(3)} ms, ` +
        `mean ${(rest.reduce((a, b) => a + b, 0) / rest.length).toFixed(3)} ms, median ${median(rest).toFixed(3)} ms, 99th percentile ${rest[Math.floor(0.99 * (rest.length - 1))].toFixed(3)} ms, worst ${rest[rest.length - 1].toFixed(3)} ms`,
    );
    assert.equal(await page.textContent("#message"), "");
  }
  assert.deepEqual(problems, []);
});

function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.floor((s.length - 1) / 2)];
}
