// Irregular examples (issue 23): no lattice, so the output is a mosaic of the example's
// own windows. Prints, with the default options:
// - a low-poly triangle mesh (every piece shares its edges): the share of the area left
//   uncovered and covered twice, in the example and in the output;
// - scattered icons of several parts (three kinds, no repeat): the share of output icons
//   whole (every part at its offset from the first) and the mix of kinds.
//   node bench/irregular.mjs
import * as ps from '../pkg/node/index.js';

const rng = (seed) => () => ((seed = (seed * 1664525 + 1013904223) >>> 0) / 4294967296);
const hex = (c) => '#' + c.map((v) => v.toString(16).padStart(2, '0')).join('');

/** A jittered grid of `n x n` squares of side `s`, each cut into two triangles. */
function mesh(n, s, seed) {
  const r = rng(seed);
  const v = [];
  for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) {
    const edge = i === 0 || j === 0 || i === n || j === n;
    v.push([i * s + (edge ? 0 : (r() - 0.5) * 0.4 * s), j * s + (edge ? 0 : (r() - 0.5) * 0.4 * s)]);
  }
  const at = (i, j) => v[j * (n + 1) + i];
  const colours = [[200, 90, 60], [60, 120, 180], [230, 190, 80]];
  const tri = (p) => ({ points: p, width: 0, stroke: null, fill: hex(colours[Math.floor(r() * 3)]), closed: true });
  const out = [];
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
    out.push(tri([at(i, j), at(i + 1, j), at(i + 1, j + 1)]), tri([at(i, j), at(i + 1, j + 1), at(i, j + 1)]));
  }
  return out;
}

/** Share of sample points in `rect` covered by no triangle, and by two or more. */
function cover(strokes, [x0, y0, x1, y1], step) {
  const tris = strokes.filter((s) => s.points.length === 3).map((s) => s.points);
  const inside = (p, [a, b, c]) => {
    const d = (u, v, w) => (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0]);
    const s1 = d(a, b, p), s2 = d(b, c, p), s3 = d(c, a, p);
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
  };
  let none = 0, twice = 0, all = 0;
  for (let y = y0 + step / 2; y < y1; y += step) for (let x = x0 + step / 2; x < x1; x += step) {
    let k = 0;
    for (const t of tris) if (inside([x, y], t) && ++k > 1) break;
    all++; none += k === 0; twice += k > 1;
  }
  return [none / all, twice / all];
}

const pct = (v) => (100 * v).toFixed(1) + '%';
const m = mesh(8, 30, 3);
const mOut = ps.synthesizeStrokes(m, { width: 480, height: 480, seed: 1 });
const [n0, t0] = cover(m, [0, 0, 240, 240], 2);
const [n1, t1] = cover(mOut.strokes, [20, 20, 460, 460], 2);
console.log('| triangle mesh | uncovered | covered twice | strokes |\n|---|---:|---:|---:|');
console.log(`| example (8 x 8 squares, 128 triangles) | ${pct(n0)} | ${pct(t0)} | ${m.length} |`);
console.log(`| output 480 x 480 | ${pct(n1)} | ${pct(t1)} | ${mOut.strokes.length} |`);

// Three icons of several parts, each drawn exactly (relative part offsets), scattered.
const line = (pts, c) => ({ points: pts, width: 2, stroke: c, fill: null, closed: false });
const ICONS = [
  // a tree: trunk and crown
  (x, y) => [line([[x, y + 4], [x, y + 14]], '#6b4a2a'), { ...line([[x - 8, y + 4], [x, y - 12], [x + 8, y + 4]], '#2f7d32'), closed: true }],
  // a key: ring, shaft, tooth
  (x, y) => [{ ...line([[x - 10, y - 3], [x - 4, y - 3], [x - 4, y + 3], [x - 10, y + 3]], '#b8860b'), closed: true }, line([[x - 4, y], [x + 10, y]], '#b8860b'), line([[x + 7, y], [x + 7, y + 5]], '#b8860b')],
  // a sun: disc and two rays
  (x, y) => [{ ...line([[x - 4, y - 4], [x + 4, y - 4], [x + 4, y + 4], [x - 4, y + 4]], '#e0a000'), closed: true }, line([[x - 9, y], [x - 6, y]], '#e0a000'), line([[x + 6, y], [x + 9, y]], '#e0a000')],
];
const r = rng(11);
const placed = [];
const icons = [];
while (placed.length < 36) {
  const p = [20 + r() * 260, 20 + r() * 260];
  if (placed.every((q) => Math.hypot(q[0] - p[0], q[1] - p[1]) > 34)) { placed.push(p); icons.push(ICONS[placed.length % 3](p[0], p[1])); }
}
const strokes = icons.flat();
const out = ps.synthesizeStrokes(strokes, { width: 900, height: 900, seed: 1 });
const centre = (s) => { const xs = s.points.map((q) => q[0]), ys = s.points.map((q) => q[1]); return [(Math.min(...xs) + Math.max(...xs)) / 2, (Math.min(...ys) + Math.max(...ys)) / 2]; };
const key = (s) => `${s.stroke}|${s.points.length}|${s.closed}`;
// Each kind's parts and their offsets from its first part, from one drawn icon.
const kinds = ICONS.map((f) => { const ps0 = f(0, 0); const c0 = centre(ps0[0]); return ps0.map((s) => ({ key: key(s), off: centre(s).map((v, i) => v - c0[i]) })); });
const firstKeys = kinds.map((k) => k[0].key);
const outC = out.strokes.map(centre);
let whole = 0, total = 0;
const mix = [0, 0, 0];
out.strokes.forEach((s, i) => {
  const k = firstKeys.indexOf(key(s));
  if (k < 0 || kinds[k][0].key !== key(s)) return;
  const [x, y] = outC[i];
  if (x < 30 || y < 30 || x > 870 || y > 870) return; // icons cut by the edge
  total++; mix[k]++;
  const ok = kinds[k].slice(1).every((p) => out.strokes.some((o, j) => key(o) === p.key && Math.hypot(outC[j][0] - x - p.off[0], outC[j][1] - y - p.off[1]) < 1.5));
  whole += ok;
});
const exMix = [12, 12, 12].map((v) => v / 36);
console.log('\n| scattered icons (3 kinds of 2-3 parts, 36 in the example) | value |\n|---|---:|');
console.log(`| output icons (first parts away from the edge) | ${total} |`);
console.log(`| whole (every part at its offset) | ${pct(whole / total)} |`);
console.log(`| mix of kinds: example | ${exMix.map((v) => v.toFixed(2)).join(' / ')} |`);
console.log(`| mix of kinds: output | ${mix.map((v) => (v / total).toFixed(2)).join(' / ')} |`);
console.log(`| motif kinds found | ${out.classification.kinds} (instances ${new Set(out.classification.instances).size}) |`);
