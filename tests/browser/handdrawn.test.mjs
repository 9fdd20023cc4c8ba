// End to end in headless Chromium, drawn the way a person draws: a 3 x 3 grid of "+"
// crosses, each bar a pointer drag of many small steps with a little wobble (seeded),
// each copy a little different (endpoints off by up to 2 px, a slight bend). Ghosts
// proposed by autocomplete are left alone (never Tab, never a tap on one). Then the
// vector engine synthesizes the default output and its SVG is checked: many crosses,
// every bar on one square lattice fitted to the output, and one horizontal and one
// vertical bar at each occupied node. Leaves a screenshot in out/handdrawn-crosses.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { openPlayground, synthesizeDrawing } from './harness.mjs';
import { parseSvg } from '../../pkg/node/index.js';

const SPACING = 70; // canvas units between drawn crosses
const ARM = 15; // half a bar's length
const ORIGIN = [330, 180]; // centre of the top-left cross
const DRAWN = 18; // 9 crosses, two strokes each

let page, close, box;

before(async () => {
  ({ page, close } = await openPlayground({ height: 900 }));
  await page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
  box = await page.locator('#draw').boundingBox();
  mkdirSync('out', { recursive: true });
});

after(async () => close?.());

/** A small deterministic generator (mulberry32): uniform in [0, 1). */
function rng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
const rand = rng(20240611);
const between = (lo, hi) => lo + (hi - lo) * rand();

/** Canvas units (800 x 500) to page pixels. */
const at = ([x, y]) => [box.x + (x * box.width) / 800, box.y + (y * box.height) / 500];

/**
 * One bar from `p` to `q` as a hand would draw it: points every ~2 units, each moved by
 * up to ~1.2 units across the bar and 0.5 along it, on a bend of `bow` units at the middle.
 */
function handLine(p, q, bow) {
  const len = Math.hypot(q[0] - p[0], q[1] - p[1]);
  const t = [(q[0] - p[0]) / len, (q[1] - p[1]) / len], n = [-t[1], t[0]];
  const steps = Math.round(len / 2);
  const pts = [];
  for (let k = 0; k <= steps; k++) {
    const f = k / steps;
    const across = bow * Math.sin(Math.PI * f) + (k === 0 || k === steps ? 0 : between(-1.2, 1.2));
    const along = k === 0 || k === steps ? 0 : between(-0.5, 0.5);
    pts.push([p[0] + (q[0] - p[0]) * f + n[0] * across + t[0] * along, p[1] + (q[1] - p[1]) * f + n[1] * across + t[1] * along]);
  }
  return pts;
}

/** Presses, moves through `points` in small steps, releases. */
async function drag(points) {
  await page.mouse.move(...at(points[0]));
  await page.mouse.down();
  for (const p of points.slice(1)) await page.mouse.move(...at(p), { steps: 2 });
  await page.mouse.up();
}

/** A "+" at `(cx, cy)`: horizontal bar, then vertical, each end off by up to 2 units. */
async function cross(cx, cy) {
  const off = () => between(-2, 2);
  await drag(handLine([cx - ARM + off(), cy + off()], [cx + ARM + off(), cy + off()], between(-2, 2)));
  await drag(handLine([cx + off(), cy - ARM + off()], [cx + off(), cy + ARM + off()], between(-2, 2)));
}

const count = async () => Number((await page.textContent('#stroke-count')).split(' ')[0]);
const bbox = (s) => {
  const xs = s.points.map((p) => p[0]), ys = s.points.map((p) => p[1]);
  const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  return { c: [(x0 + x1) / 2, (y0 + y1) / 2], w: x1 - x0, h: y1 - y0 };
};
const median = (v) => {
  const s = [...v].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

/**
 * A square-ish lattice fitted to points: the nearest-neighbour offsets (beyond `minGap`,
 * so that the two bars of one cross do not pair up; folded to one
 * half-plane) fall in two clusters, the basis vectors are their component-wise medians,
 * and the origin is the circular mean of the points' phases along each; then the basis
 * and origin are refined by least squares over the points' nodes.
 */
function fitLattice(points, minGap) {
  const offsets = [];
  for (const p of points) {
    let best = null, bd = Infinity;
    for (const q of points) {
      if (q === p) continue;
      const d = Math.hypot(q[0] - p[0], q[1] - p[1]);
      if (d > minGap && d < bd) [best, bd] = [q, d];
    }
    if (best) offsets.push([best[0] - p[0], best[1] - p[1]]);
  }
  const s0 = median(offsets.map(([x, y]) => Math.hypot(x, y)));
  // Every offset between points at about the nearest-neighbour distance, folded so
  // that its angle lies in [-45°, 135°).
  const near = [];
  for (const p of points) for (const q of points) {
    const d = [q[0] - p[0], q[1] - p[1]], r = Math.hypot(...d);
    if (r < 0.8 * s0 || r > 1.25 * s0) continue;
    const ang = Math.atan2(d[1], d[0]);
    near.push(ang >= -Math.PI / 4 && ang < (3 * Math.PI) / 4 ? d : [-d[0], -d[1]]);
  }
  // The two clusters: around the most common direction, and the rest.
  const dir = (d) => Math.atan2(d[1], d[0]);
  const hist = new Map();
  for (const d of near) {
    const k = Math.round((dir(d) * 180) / Math.PI / 10);
    hist.set(k, (hist.get(k) ?? 0) + 1);
  }
  const mode = ([...hist].sort((x, y) => y[1] - x[1])[0][0] * 10 * Math.PI) / 180;
  const angleTo = (d, a) => Math.abs(Math.atan2(Math.sin(dir(d) - a), Math.cos(dir(d) - a)));
  const groupA = near.filter((d) => angleTo(d, mode) < Math.PI / 8);
  const groupB = near.filter((d) => angleTo(d, mode) > (3 * Math.PI) / 8);
  const a = [median(groupA.map((d) => d[0])), median(groupA.map((d) => d[1]))];
  const b = [median(groupB.map((d) => d[0])), median(groupB.map((d) => d[1]))];
  const det = a[0] * b[1] - a[1] * b[0];
  const frac = (p) => [(p[0] * b[1] - p[1] * b[0]) / det, (a[0] * p[1] - a[1] * p[0]) / det];
  const phase = (k) => {
    let c = 0, s = 0;
    for (const p of points) {
      const u = frac(p)[k] * 2 * Math.PI;
      c += Math.cos(u); s += Math.sin(u);
    }
    return { phase: Math.atan2(s, c) / (2 * Math.PI), coherence: Math.hypot(c, s) / points.length };
  };
  const [pu, pv] = [phase(0), phase(1)];
  const origin = [pu.phase * a[0] + pv.phase * b[0], pu.phase * a[1] + pv.phase * b[1]];
  // Refined by least squares over every point's node: p = origin + i a + j b (per axis,
  // the normal equations of three unknowns).
  const indices = points.map((p) => frac([p[0] - origin[0], p[1] - origin[1]]).map(Math.round));
  const solve3 = (m, r) => {
    const d = (x) => x[0][0] * (x[1][1] * x[2][2] - x[1][2] * x[2][1]) - x[0][1] * (x[1][0] * x[2][2] - x[1][2] * x[2][0]) + x[0][2] * (x[1][0] * x[2][1] - x[1][1] * x[2][0]);
    const D = d(m);
    return [0, 1, 2].map((k) => d(m.map((row, i) => row.map((v, j) => (j === k ? r[i] : v)))) / D);
  };
  const m = [[0, 0, 0], [0, 0, 0], [0, 0, 0]], rx = [0, 0, 0], ry = [0, 0, 0];
  points.forEach((p, n) => {
    const f = [1, ...indices[n]];
    for (let i = 0; i < 3; i++) {
      for (let j = 0; j < 3; j++) m[i][j] += f[i] * f[j];
      rx[i] += f[i] * p[0]; ry[i] += f[i] * p[1];
    }
  });
  const [ox, ax, bx] = solve3(m, rx), [oy, ay, by] = solve3(m, ry);
  return lattice([ax, ay], [bx, by], [ox, oy], { coherence: [pu.coherence, pv.coherence], initial: { a, b, origin } });
}

/** The lattice `origin + i a + j b`: fractional coordinates and the nearest node. */
function lattice(a, b, origin, extra = {}) {
  const det = a[0] * b[1] - a[1] * b[0];
  const frac = (p) => [(p[0] * b[1] - p[1] * b[0]) / det, (a[0] * p[1] - a[1] * p[0]) / det];
  /** The nearest node's indices and the distance to it. */
  const node = (p) => {
    const [u, v] = frac([p[0] - origin[0], p[1] - origin[1]]);
    const [i, j] = [Math.round(u), Math.round(v)];
    const n = [origin[0] + i * a[0] + j * b[0], origin[1] + i * a[1] + j * b[1]];
    return { i, j, at: n, dist: Math.hypot(p[0] - n[0], p[1] - n[1]) };
  };
  return { a, b, origin, node, frac, ...extra };
}

test('a hand-drawn 3x3 grid of crosses synthesizes into a clean lattice of crosses', async (t) => {
  await page.click('#clear');
  assert.equal(await count(), 0);

  let ghostsSeen = 0;
  const lost = [];
  for (let j = 0; j < 3; j++) for (let i = 0; i < 3; i++) {
    const before = await count();
    await cross(ORIGIN[0] + i * SPACING, ORIGIN[1] + j * SPACING);
    const now = await count();
    if (now !== before + 2) lost.push(`cross ${i},${j}: ${before} -> ${now}`);
    ghostsSeen = Math.max(ghostsSeen, Number((await page.textContent('#suggest-status')).match(/^(\d+) suggested/)?.[1] ?? 0));
  }
  assert.deepEqual(lost, [], 'every drag became exactly one stroke, none accepted ghosts');
  assert.equal(await count(), DRAWN);

  // Let autocomplete settle (ghosts may show; they are left alone) and look at classes.
  await page.waitForFunction(() => document.querySelector('#suggest-status').getAttribute('aria-busy') === 'false', null, { timeout: 15000 });
  // The classes of all the strokes (classification runs a moment after each change).
  await page.waitForFunction((n) => [...document.querySelectorAll('#legend .chip')].reduce((sum, c) => sum + Number(c.textContent.split(': ')[1]), 0) === n, DRAWN, { timeout: 15000 });
  const status = await page.textContent('#suggest-status');
  const legend = (await page.$$eval('#legend .chip', (cs) => cs.map((c) => c.textContent))).join(', ');
  const drawn = await page.evaluate(() => window.playground.drawing().strokes);
  t.diagnostic(`drawn: ${drawn.length} strokes, ${median(drawn.map((s) => s.points.length))} points each (median); classes: ${legend.trim()}`);
  t.diagnostic(`autocomplete: most ghosts seen while drawing ${ghostsSeen}; after the last stroke: "${status}"`);
  assert.equal(await count(), DRAWN, 'no ghost was accepted');

  // Synthesize with the vector engine at the default output size.
  const [W, H] = [Number(await page.inputValue('#out-width')), Number(await page.inputValue('#out-height'))];
  const { messages, info } = await synthesizeDrawing(page);
  assert.equal(messages, 'Done.');
  await page.screenshot({ path: 'out/handdrawn-crosses.png', fullPage: true });
  t.diagnostic(`result: ${info}`);
  assert.equal(await count(), DRAWN, 'synthesis did not change the drawing');

  // The output SVG, as the download link offers it.
  const svg = await page.evaluate(async () => (await fetch(document.querySelector('#download').href)).text());
  assert.match(svg, new RegExp(`viewBox="0 0 ${W} ${H}"`));
  const bars = parseSvg(svg).map(bbox);
  const horizontal = bars.filter((b) => b.w > b.h), vertical = bars.filter((b) => b.w <= b.h);
  const squat = bars.filter((b) => Math.max(b.w, b.h) < 2 * Math.min(b.w, b.h)).length;
  t.diagnostic(`output: ${bars.length} strokes in ${W}x${H}: ${horizontal.length} horizontal, ${vertical.length} vertical, ${squat} not bar-like (aspect < 2); median bar ${median(horizontal.map((b) => b.w)).toFixed(1)} x ${median(horizontal.map((b) => b.h)).toFixed(1)}`);

  // (1) Many crosses.
  assert.ok(bars.length >= 4 * DRAWN, `${bars.length} output strokes, want >= ${4 * DRAWN}`);

  // (2) One square lattice of spacing ~SPACING, fitted to the output, holds every bar.
  // Centres closer than half a bar are of one cross, not neighbours on the lattice.
  const barLength = median(bars.map((b) => Math.max(b.w, b.h)));
  const lattice = fitLattice(bars.map((b) => b.c), barLength / 2);
  const [la, lb] = [Math.hypot(...lattice.a), Math.hypot(...lattice.b)];
  const angle = (Math.acos((lattice.a[0] * lattice.b[0] + lattice.a[1] * lattice.b[1]) / (la * lb)) * 180) / Math.PI;
  const init = lattice.initial;
  t.diagnostic(`lattice from nearest-neighbour medians: a = (${init.a.map((x) => x.toFixed(2))}), b = (${init.b.map((x) => x.toFixed(2))})`);
  t.diagnostic(`lattice refined: a = (${lattice.a.map((x) => x.toFixed(2))}), b = (${lattice.b.map((x) => x.toFixed(2))}), |a| ${la.toFixed(2)}, |b| ${lb.toFixed(2)}, angle ${angle.toFixed(2)}°, origin (${lattice.origin.map((x) => x.toFixed(2))}), phase coherence ${lattice.coherence.map((x) => x.toFixed(4))}`);
  assert.ok(Math.abs(la - SPACING) < 0.1 * SPACING && Math.abs(lb - SPACING) < 0.1 * SPACING, `lattice spacing ${la} x ${lb}, want ~${SPACING}`);
  assert.ok(Math.abs(angle - 90) < 5 && Math.abs(la - lb) < 0.05 * SPACING, `lattice not square: ${la} x ${lb} at ${angle}°`);
  const placed = bars.map((b) => ({ ...b, horizontal: b.w > b.h, ...lattice.node(b.c) }));
  const dists = placed.map((p) => p.dist);
  const tol = 0.1 * SPACING;
  const off = placed.filter((p) => p.dist > tol);
  t.diagnostic(`distance of bar centres to their lattice node: median ${median(dists).toFixed(2)}, max ${Math.max(...dists).toFixed(2)}, ${off.length} beyond ${tol}`);
  assert.deepEqual(off.map((p) => `${p.horizontal ? 'H' : 'V'} bar at (${p.c.map((x) => x.toFixed(1))}), ${p.dist.toFixed(1)} from node (${p.at.map((x) => x.toFixed(1))})`), [], 'bars off the lattice');

  // (3) One horizontal and one vertical bar at each occupied node, away from the edges.
  const nodes = new Map();
  for (const p of placed) {
    const k = `${p.i},${p.j}`;
    const n = nodes.get(k) ?? { at: p.at, h: 0, v: 0 };
    n[p.horizontal ? 'h' : 'v']++;
    nodes.set(k, n);
  }
  const interior = ([x, y]) => x >= SPACING && x <= W - SPACING && y >= SPACING && y <= H - SPACING;
  // Every lattice node in the interior, occupied or not (to count holes too).
  const corners = [[0, 0], [W, 0], [0, H], [W, H]].map(([x, y]) => lattice.frac([x - lattice.origin[0], y - lattice.origin[1]]));
  const range = (k) => [Math.floor(Math.min(...corners.map((c) => c[k]))), Math.ceil(Math.max(...corners.map((c) => c[k])))];
  const [[i0, i1], [j0, j1]] = [range(0), range(1)];
  let interiorNodes = 0, holes = 0;
  const occupied = [], bad = [];
  for (let i = i0; i <= i1; i++) for (let j = j0; j <= j1; j++) {
    const at = [lattice.origin[0] + i * lattice.a[0] + j * lattice.b[0], lattice.origin[1] + i * lattice.a[1] + j * lattice.b[1]];
    if (!interior(at)) continue;
    interiorNodes++;
    const n = nodes.get(`${i},${j}`);
    if (!n) { holes++; continue; }
    occupied.push(n);
    if (n.h !== 1 || n.v !== 1) bad.push(`node (${at.map((x) => x.toFixed(0))}): ${n.h} H + ${n.v} V`);
  }
  const allNodes = [...nodes.values()];
  const good = occupied.length - bad.length;
  t.diagnostic(`nodes: ${allNodes.length} occupied in all (${allNodes.filter((n) => n.h === 1 && n.v === 1).length} with exactly 1 H + 1 V); interior ${interiorNodes}: ${occupied.length} occupied, ${holes} empty, ${good}/${occupied.length} = ${((100 * good) / Math.max(occupied.length, 1)).toFixed(1)}% exactly 1 H + 1 V`);
  if (bad.length) t.diagnostic(`interior nodes that are not one cross: ${bad.slice(0, 20).join('; ')}`);
  assert.ok(occupied.length >= 4, `${occupied.length} occupied interior nodes`);
  assert.ok(good >= 0.95 * occupied.length, `${good}/${occupied.length} interior nodes hold one H and one V bar: ${bad.join('; ')}`);
});
