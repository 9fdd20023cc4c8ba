// Texture synthesis at the speed limit (issue 25): one thread, medians of interleaved
// runs, for each build of the texture module (scalar or SIMD, wasm-opt -Oz or -O3)
// against the native build, at several output sizes. Exemplar: 128 x 128 of the gravel
// photograph (examples/speed.rs crops the same). Worker scaling in Chromium is
// bench/workers.mjs.
//   node bench/speed.mjs [sizes] [runs]      e.g. node bench/speed.mjs 256,1024,2048 5
// Builds the four variants into target/speed/ first (scripts/wasm-module.sh; cached).
import { execFileSync } from 'node:child_process';
import { readFileSync, statSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { decodeImage } from '../pkg/node/codec.js';

const sizes = (process.argv[2] ?? '256,1024,2048').split(',').map(Number);
const runs = Number(process.argv[3] ?? 5);
const variants = [['scalar', 0, 'Oz'], ['scalar', 0, 'O3'], ['simd', 1, 'Oz'], ['simd', 1, 'O3']];
for (const [, simd, opt] of variants) {
  execFileSync('bash', ['scripts/wasm-module.sh', 'texture', 'texture', String(simd), opt, `target/speed/${simd}-${opt}`], { stdio: 'inherit' });
}
execFileSync('cargo', ['build', '--release', '-q', '--example', 'speed'], { stdio: 'inherit' });

const full = decodeImage(readFileSync('tests/fixtures/textures/gravel.png'));
const side = Math.min(128, full.width, full.height);
const data = new Uint8ClampedArray(side * side * 4);
for (let y = 0; y < side; y++) data.set(full.data.subarray(4 * y * full.width, 4 * (y * full.width + side)), 4 * y * side);
const exemplar = { width: side, height: side, data };

// Each variant's glue imported as its own module instance (a query makes it another
// module), instantiated from its own bytes.
const engines = [];
for (const [kind, simd, opt] of variants) {
  const dir = `target/speed/${simd}-${opt}`;
  const glue = await import(`../${dir}/texture.js?${simd}-${opt}`);
  const bytes = readFileSync(`${dir}/texture_bg.wasm`);
  glue.initSync({ module: new WebAssembly.Module(bytes) });
  engines.push({ name: `${kind} -${opt}`, glue, bytes: statSync(`${dir}/texture_bg.wasm`).size, gzip: gzipSync(bytes).length });
}
const median = (t) => [...t].sort((a, b) => a - b)[t.length >> 1];

// The native build runs in its own process once per round, between the wasm builds'
// runs, so that each ratio to it is paired within a round (a change in the shared
// machine's load falls on both); its own warm-up call comes first (examples/speed.rs).
const nativeRun = (s) => JSON.parse(execFileSync('target/release/examples/speed', [String(s)], { encoding: 'utf8', env: { ...process.env, RUNS: '1' } }).trim()).ms;

console.log(`| build | bytes (gzip) | ${sizes.map((s) => `${s}² ms | vs native`).join(' | ')} |`);
console.log(`|---|---:|${sizes.map(() => '---:|---:').join('|')}|`);
const times = engines.map(() => ({}));
const ratios = engines.map(() => ({}));
const native = {};
for (const s of sizes) {
  const opts = { width: s, height: s, seed: 1 };
  engines.forEach((e) => e.glue.synthesizeTexture(exemplar, { ...opts, width: 64, height: 64 }, undefined));
  const t = engines.map(() => []);
  const n = [];
  // Round r runs every build in turn, native first.
  for (let r = 0; r < runs; r++) {
    n.push(nativeRun(s));
    engines.forEach((e, i) => {
      const start = performance.now();
      e.glue.synthesizeTexture(exemplar, opts, undefined);
      t[i].push(performance.now() - start);
    });
  }
  native[s] = median(n);
  engines.forEach((e, i) => {
    times[i][s] = median(t[i]);
    ratios[i][s] = median(t[i].map((v, r) => v / n[r]));
  });
}
console.log(`| native (x86-64, SSE) | — | ${sizes.map((s) => `${native[s].toFixed(0)} | 1.00`).join(' | ')} |`);
engines.forEach((e, i) => {
  console.log(`| ${e.name} | ${e.bytes} (${e.gzip}) | ${sizes.map((s) => `${times[i][s].toFixed(0)} | ${ratios[i][s].toFixed(2)}`).join(' | ')} |`);
});
console.log('\n(vs native: the median of each round\'s ratio, native and wasm run in the same round.)');
