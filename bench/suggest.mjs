// Autocomplete latency (issue 10: within 50 ms of pen-up for drawings of up to 200
// strokes), wasm under Node: a hand-jittered lattice of crosses and dots drawn copy by
// copy, suggestStrokes after the last stroke; median and slowest of 9 calls per size,
// and the same drawing with a stray last stroke (the case that must be rejected).
// `node bench/suggest.mjs` after a build.
import * as ps from '../pkg/node/index.js';

let seed = 7;
const rand = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
const jit = () => (rand() - 0.5) * 2;
function drawing(n) {
  const out = [];
  for (let j = 0; out.length < n; j++) {
    for (let i = 0; i < 10 && out.length < n; i++) {
      const x = 30 + 40 * i + jit(), y = 30 + 36 * j + jit();
      out.push({ points: [[x - 8, y], [x + 8, y]], width: 2, stroke: '#333333' });
      if (out.length < n) out.push({ points: [[x, y - 8], [x, y + 8]], width: 2, stroke: '#333333' });
      if (out.length < n) out.push({ points: [[x + 14, y + 12], [x + 15, y + 12]], width: 3, stroke: '#aa3322' });
    }
  }
  return out;
}
const median = (t) => [...t].sort((a, b) => a - b)[t.length >> 1];
console.log('| strokes | proposals | median ms | slowest ms | stray last stroke: median ms |');
console.log('|---:|---:|---:|---:|---:|');
for (const n of [30, 60, 120, 200, 400]) {
  const d = drawing(n);
  const region = [0, 0, 440, 40 + 36 * Math.ceil(n / 30)];
  const t = [], u = [];
  let count = 0;
  for (let k = 0; k < 9; k++) {
    let s = performance.now();
    count = ps.suggestStrokes(d, { region }).strokes.length;
    t.push(performance.now() - s);
    s = performance.now();
    ps.suggestStrokes([...d, { points: [[5, 5], [9, 30], [20, 3]], width: 2 }], { region });
    u.push(performance.now() - s);
  }
  console.log(`| ${n} | ${count} | ${median(t).toFixed(1)} | ${Math.max(...t).toFixed(1)} | ${median(u).toFixed(1)} |`);
}
