// Busy examples (issue 7): examples of about 500, 1,000 and 2,000 elements grown to about
// 20,000 output elements, native and wasm under Node on the same SVG, medians of 5.
// Periodic: a tile of scattered elements of three kinds repeated 3x3 (as an imported
// SVG tile); irregular: the same kinds scattered with no repeat (free growth).
//   cargo build --release --example bench_svg && node bench/busy.mjs
import { execFileSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { parseSvg, synthesizeStrokes } from '../pkg/node/index.js';
import { rng } from '../tests/node/fuzz.mjs';

const KINDS = [
  (x, y) => `<path d="M${x} ${y - 3}v6" stroke="#1e1e1e" stroke-width="1.5" fill="none"/>`,
  (x, y) => `<circle cx="${x}" cy="${y}" r="3" fill="#c85028"/>`,
  (x, y) => `<path d="M${x - 3} ${y + 2}l3 -4l3 4" stroke="#285aa0" fill="none"/>`,
];
/** `count` elements at least `gap` apart in a square of side `size` (on a torus when periodic). */
function scatter(count, size, gap, periodic, seed) {
  const r = rng(seed);
  const pts = [];
  for (let tries = 0; pts.length < count && tries < count * 300; tries++) {
    const p = [r.next() * size, r.next() * size];
    const ok = pts.every((q) => {
      let dx = Math.abs(q[0] - p[0]), dy = Math.abs(q[1] - p[1]);
      if (periodic) { dx = Math.min(dx, size - dx); dy = Math.min(dy, size - dy); }
      return Math.hypot(dx, dy) >= gap;
    });
    if (ok) pts.push([...p, r.int(3)]);
  }
  return pts;
}

const dir = mkdtempSync(join(tmpdir(), 'busy-'));
const rows = [];
const scaling = [];
const median = (f) => {
  const times = [];
  let out;
  for (let i = 0; i < 5; i++) {
    const t0 = performance.now();
    out = f();
    times.push(performance.now() - t0);
  }
  return [times.sort((a, b) => a - b)[2], out];
};
for (const [kind, n] of [['periodic', 500], ['periodic', 1000], ['periodic', 2000], ['irregular', 500], ['irregular', 1000], ['irregular', 2000]]) {
  const spacing = 10;
  let body, area;
  if (kind === 'periodic') {
    const per = Math.round(n / 9), tile = Math.sqrt(per) * spacing;
    const motif = scatter(per, tile, 0.7 * spacing, true, n);
    body = '';
    for (let j = 0; j < 3; j++) for (let i = 0; i < 3; i++) body += motif.map(([x, y, k]) => KINDS[k](+(x + i * tile).toFixed(3), +(y + j * tile).toFixed(3))).join('');
    area = 9 * tile * tile;
  } else {
    const side = Math.sqrt(n) * spacing;
    body = scatter(n, side, 0.7 * spacing, false, n).map(([x, y, k]) => KINDS[k](+x.toFixed(3), +y.toFixed(3))).join('');
    area = side * side;
  }
  const svg = `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ${Math.sqrt(area)} ${Math.sqrt(area)}">${body}</svg>`;
  const strokes = parseSvg(svg);
  const side = Math.round(Math.sqrt(area * 20000 / strokes.length));
  const file = join(dir, `${kind}-${n}.svg`);
  writeFileSync(file, svg);
  const native = JSON.parse(execFileSync('target/release/examples/bench_svg', [file, side, side], { encoding: 'utf8' }));
  const times = [];
  let out = 0;
  for (let i = 0; i < 5; i++) {
    const t0 = performance.now();
    out = synthesizeStrokes(strokes, { width: side, height: side, variation: false }).strokes.length;
    times.push(performance.now() - t0);
  }
  const wasm = times.sort((a, b) => a - b)[2];
  rows.push(`| ${kind} | ${strokes.length} | ${out} | ${native.ms.toFixed(0)} | ${wasm.toFixed(0)} | ${(wasm / native.ms).toFixed(2)} | ${(1000 * wasm / out).toFixed(1)} |`);
  console.error(rows.at(-1));
  // Cost against output size (wasm): near-linear means a steady cost per element.
  if (n === 2000) {
    for (const target of [5000, 10000, 20000, 40000, 80000]) {
      const s = Math.round(Math.sqrt(area * target / strokes.length));
      const [ms, r] = median(() => synthesizeStrokes(strokes, { width: s, height: s, variation: false }));
      scaling.push(`| ${kind} | ${strokes.length} | ${r.strokes.length} | ${ms.toFixed(0)} | ${(1000 * ms / r.strokes.length).toFixed(1)} |`);
      console.error(scaling.at(-1));
    }
  }
}
console.log('| example | elements | out | native ms | wasm ms | wasm/native | µs per output element (wasm) |\n|---|---:|---:|---:|---:|---:|---:|');
console.log(rows.join('\n'));
console.log('\n| example | elements | out | wasm ms | µs per output element |\n|---|---:|---:|---:|---:|');
console.log(scaling.join('\n'));
