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

// Repetitions that are not lattices (issue 27: within 50 ms at 200 strokes): rings of
// eight petals drawn one after another across the canvas, the latest ring three petals
// in (its ghosts complete it); and hatching lines along a wide arc, each turned with it.
const petal = (cx, cy, theta, len) => {
  const pts = [];
  for (let k = 0; k <= 20; k++) {
    const t = (k / 20) * 2 * Math.PI;
    const along = 0.5 * len * (1 - Math.cos(t)), across = (len / 6) * Math.sin(t);
    pts.push([cx + along * Math.cos(theta) - across * Math.sin(theta) + jit() * 0.3, cy + along * Math.sin(theta) + across * Math.cos(theta) + jit() * 0.3]);
  }
  return { points: pts, width: 2, stroke: '#335522' };
};
function rings(n) {
  const out = [];
  for (let r = 0; out.length < n; r++) {
    const cx = 60 + 120 * (r % 10), cy = 60 + 120 * Math.floor(r / 10);
    // Every ring whole but the last, which stops three petals in.
    const petals = out.length + 8 <= n - 3 ? 8 : Math.min(3, n - out.length);
    for (let k = 0; k < petals; k++) out.push(petal(cx, cy, (k * Math.PI) / 4, 50));
    if (petals < 8) break;
  }
  return out;
}
// Rings of six to nine petals, each petal turned a little by hand (about 3 degrees).
function varied(n) {
  const out = [];
  for (let r = 0; out.length < n; r++) {
    const cx = 60 + 120 * (r % 10), cy = 60 + 120 * Math.floor(r / 10), count = 6 + (r % 4);
    const petals = out.length + count <= n - 3 ? count : Math.min(3, n - out.length);
    for (let k = 0; k < petals; k++) out.push(petal(cx, cy, (k * 2 * Math.PI) / count + jit() * 0.05, 50));
    if (petals < count) break;
  }
  return out;
}
function hatching(n) {
  const out = [];
  for (let k = 0; k < n; k++) {
    const phi = -1.2 + k * 0.012, r = 600;
    const cx = 700 + r * Math.sin(phi) + jit() * 0.2, cy = 700 - r * Math.cos(phi) + jit() * 0.2;
    const dx = Math.sin(phi) * 35, dy = -Math.cos(phi) * 35;
    out.push({ points: [[cx - dx, cy - dy], [cx + dx, cy + dy]], width: 2, stroke: '#222222' });
  }
  return out;
}
// Rosettes of nine leaves, each drawn as two mirrored arcs and a midrib (motifs of
// several strokes), turned a little by hand.
const arc = (x0, y0, x1, y1, bow) => {
  const pts = [];
  for (let k = 0; k <= 12; k++) {
    const t = k / 12, b = bow * 4 * t * (1 - t);
    pts.push([x0 + (x1 - x0) * t - (y1 - y0) * b + jit() * 0.3, y0 + (y1 - y0) * t + (x1 - x0) * b + jit() * 0.3]);
  }
  return { points: pts, width: 2, stroke: '#335522' };
};
function leaves(n) {
  const out = [];
  for (let r = 0; out.length < n; r++) {
    const cx = 80 + 170 * (r % 8), cy = 80 + 170 * Math.floor(r / 8);
    for (let k = 0; k < 9 && out.length < n; k++) {
      const th = (k * 2 * Math.PI) / 9 + jit() * 0.04, tx = cx + 70 * Math.cos(th), ty = cy + 70 * Math.sin(th);
      const [mx, my, dx, dy] = [(cx + tx) / 2, (cy + ty) / 2, 28 * Math.cos(th), 28 * Math.sin(th)];
      for (const s of [arc(cx, cy, tx, ty, 0.2), arc(cx, cy, tx, ty, -0.2), arc(mx - dx, my - dy, mx + dx, my + dy, 0)]) {
        if (out.length < n) out.push(s);
      }
    }
  }
  return out;
}
// Vines: a wavy stem drawn across the canvas (a point every 4 px, as coalesced pointer
// events give), then a leaf every 50 px along it, each leaning off the stem; the latest
// vine three leaves in (its ghosts go on along the stem: suggest::along).
function vines(n) {
  const out = [];
  for (let v = 0; out.length < n; v++) {
    const cy = 80 + 140 * v, f = (x) => cy + 30 * Math.sin(x / 40);
    const stem = [];
    for (let x = 40; x <= 1440; x += 4) stem.push([x + jit() * 0.3, f(x) + jit() * 0.3]);
    out.push({ points: stem, width: 2, stroke: '#335522' });
    const left = n - out.length;
    const count = left >= 28 + 4 ? 28 : Math.min(3, left);
    for (let k = 0; k < count; k++) {
      const x = 60 + 50 * k, th = Math.atan2(f(x + 1) - f(x), 1) - 0.6;
      const p = petal(x, f(x), th, 36);
      out.push(p);
    }
    if (count < 28) break;
  }
  return out;
}
// Cold: the first call on a drawing (new strokes every time); stroke by stroke: each
// call after the one for the drawing one stroke shorter, as the page makes them (the
// worker remembers the shape distances it has measured).
console.log('\n| drawing | strokes | proposals | cold: median ms | stroke by stroke: median ms | slowest ms |');
console.log('|---|---:|---:|---:|---:|---:|');
const region = { region: [0, 0, 1500, 1500] };
const drawings = [
  ['rings of petals', rings],
  ['rings of 6-9 petals turned by hand', varied],
  ['turning hatching', hatching],
  ['rosettes of three-stroke leaves', leaves],
  ['leaves along drawn stems', vines],
];
for (const [name, make] of drawings) {
  for (const n of [60, 200]) {
    const cold = [];
    let count = 0;
    for (let k = 0; k < 9; k++) {
      const d = make(n);
      const s = performance.now();
      count = ps.suggestStrokes(d, region).strokes.length;
      cold.push(performance.now() - s);
    }
    const d = make(n);
    ps.suggestStrokes(d.slice(0, n - 10), region);
    const warm = [];
    for (let m = n - 9; m <= n; m++) {
      const s = performance.now();
      ps.suggestStrokes(d.slice(0, m), region);
      warm.push(performance.now() - s);
    }
    console.log(`| ${name} | ${d.length} | ${count} | ${median(cold).toFixed(1)} | ${median(warm).toFixed(1)} | ${Math.max(...warm).toFixed(1)} |`);
  }
}
