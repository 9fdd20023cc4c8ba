// Vector benchmark: native vs wasm-in-Node on the same cases (median of runs), plus the
// wasm module's size. Usage: bash scripts/bench.sh (builds first).
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { synthesizeStrokes } from '../pkg/node/index.js';

const native = execFileSync('target/release/examples/bench_vector', { encoding: 'utf8' })
  .trim().split('\n').map((l) => JSON.parse(l));
const examples = JSON.parse(readFileSync('www/features/strokes/shared/examples.json', 'utf8'));
const families = Object.fromEntries(examples.map((e) => [e.name, e.strokes]));

const rows = [];
for (const n of native) {
  const strokes = families[n.name];
  if (strokes.length !== n.example) throw new Error(`${n.name}: example differs (${strokes.length} vs ${n.example})`);
  const runs = n.target >= 50000 ? 3 : 5;
  const times = [];
  let count = 0;
  for (let i = 0; i < runs; i++) {
    const t = performance.now();
    const r = synthesizeStrokes(strokes, { width: n.side, height: n.side });
    times.push(performance.now() - t);
    count = r.strokes.length;
  }
  times.sort((a, b) => a - b);
  const wasm = times[times.length >> 1];
  rows.push({ case: n.name, example: n.example, out: count, native_ms: n.ms, wasm_ms: wasm,
    'elem/s wasm': Math.round(count / (wasm / 1000)), 'wasm/native': wasm / n.ms, 'µs/elem wasm': (1000 * wasm) / count });
}

const fmt = (v) => (typeof v === 'number' ? (Number.isInteger(v) ? String(v) : v.toFixed(v < 10 ? 2 : 1)) : v);
const cols = Object.keys(rows[0]);
console.log('| ' + cols.join(' | ') + ' |');
console.log('|' + cols.map(() => '---').join('|') + '|');
for (const r of rows) console.log('| ' + cols.map((c) => fmt(r[c])).join(' | ') + ' |');
const wasm = readFileSync('pkg/wasm/full_bg.wasm');
console.log(`\nwasm module: ${wasm.length} bytes raw, ${gzipSync(wasm, { level: 9 }).length} bytes gzip`);
