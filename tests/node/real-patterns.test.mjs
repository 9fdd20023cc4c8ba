// Real patterns: a 3x3 repeat of an openly licensed tile as the example, 10x10 periods
// synthesized; the result must be the tile's periodic extension: every ideal site
// filled with the right element, nothing stray, nothing stacked, no drift.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseSvg, synthesizeStrokes } from '../../pkg/node/index.js';
import { STYLES, tile } from './real-patterns.mjs';

const centre = (s) => {
  const xs = s.points.map((p) => p[0]), ys = s.points.map((p) => p[1]);
  return [(Math.min(...xs) + Math.max(...xs)) / 2, (Math.min(...ys) + Math.max(...ys)) / 2];
};

export function measure(name) {
  const { svg, px, py } = tile(name);
  const strokes = parseSvg(svg);
  const n = strokes.length / 9; // strokes per tile (subpaths split)
  assert.ok(Number.isInteger(n), `${name}: ${strokes.length} strokes in a 3x3 repeat`);
  const [w, h] = [10 * px, 10 * py];
  const t0 = performance.now();
  const out = synthesizeStrokes(strokes, { width: w, height: h, variation: false, seed: 1 });
  const ms = performance.now() - t0;
  const cls = out.classification.classes;
  const refs = strokes.map(centre);
  const xs = refs.map((p) => p[0]), ys = refs.map((p) => p[1]);
  const shift = [w / 2 - (Math.min(...xs) + Math.max(...xs)) / 2, h / 2 - (Math.min(...ys) + Math.max(...ys)) / 2];
  const tol = 0.05 * Math.min(px, py);
  // Ideal sites: each tile element at every period offset. Tiles may overlap their
  // neighbours (a piece of one tile on a piece of the next): one site per class there.
  const sites = [];
  for (let k = 0; k < n; k++) {
    const [x, y] = refs[k];
    for (let i = -12; i <= 12; i++) for (let j = -12; j <= 12; j++) {
      const p = [x + shift[0] + i * px, y + shift[1] + j * py];
      if (p[0] < -tol || p[0] > w + tol || p[1] < -tol || p[1] > h + tol) continue;
      if (sites.some((s) => s.c === cls[k] && Math.hypot(s.p[0] - p[0], s.p[1] - p[1]) < tol)) continue;
      sites.push({ p, c: cls[k], hits: 0 });
    }
  }
  let stray = 0, maxResidual = 0;
  out.strokes.forEach((s, idx) => {
    const c = centre(s);
    let best = null, bd = Infinity;
    for (const site of sites) {
      if (site.c !== out.classes[idx]) continue;
      const d = Math.hypot(site.p[0] - c[0], site.p[1] - c[1]);
      if (d < bd) { bd = d; best = site; }
    }
    if (best && bd < tol) { best.hits++; maxResidual = Math.max(maxResidual, bd / Math.min(px, py)); } else stray++;
  });
  // Sites strictly inside (a site on the very border may fall either side of it).
  const inner = sites.filter((s) => s.p[0] > tol && s.p[0] < w - tol && s.p[1] > tol && s.p[1] < h - tol);
  const covered = inner.filter((s) => s.hits > 0).length;
  const stacked = sites.reduce((a, s) => a + Math.max(0, s.hits - 1), 0);
  return { name, perTile: n, out: out.strokes.length, sites: inner.length, coverage: covered / inner.length, stray, stacked, maxResidual, ms: Math.round(ms) };
}

for (const name of Object.keys(STYLES)) {
  test(`svg-patterns '${name}' grows to its periodic extension`, () => {
    const r = measure(name);
    console.log(JSON.stringify(r));
    assert.equal(r.coverage, 1, `${name}: coverage ${r.coverage}`);
    assert.equal(r.stray, 0, `${name}: stray`);
    assert.equal(r.stacked, 0, `${name}: stacked`);
    assert.ok(r.maxResidual < 0.01, `${name}: drift ${r.maxResidual}`);
  });
}
