// What seam fusion costs (synthesis::fusion): synthesizeTexture with fuseSeams on and
// off, interleaved, one thread, the built package under Node (the SIMD module where
// Node runs it). Exemplar: the 128 x 128 top-left of the gravel fixture.
//   node bench/fusion.mjs [sizes] [runs]      e.g. node bench/fusion.mjs 256,1024 5
import * as ps from '../pkg/node/index.js';
import { readFileSync } from 'node:fs';

const full = ps.decodeImage(readFileSync(new URL('../tests/fixtures/textures/gravel.png', import.meta.url)));
const side = 128;
const data = new Uint8ClampedArray(side * side * 4);
for (let y = 0; y < side; y++) data.set(full.data.subarray(4 * y * full.width, 4 * (y * full.width + side)), 4 * y * side);
const exemplar = { width: side, height: side, data };
const median = (a) => [...a].sort((x, y) => x - y)[a.length >> 1];
for (const size of (process.argv[2] ?? '256').split(',').map(Number)) {
  const ms = { fused: [], unfused: [] };
  for (let r = 0; r < Number(process.argv[3] ?? 5); r++) {
    for (const fuseSeams of [true, false]) {
      const t = performance.now();
      ps.synthesizeTexture(exemplar, { width: size, height: size, seed: 1, fuseSeams });
      ms[fuseSeams ? 'fused' : 'unfused'].push(performance.now() - t);
    }
  }
  const [f, u] = [median(ms.fused), median(ms.unfused)];
  console.log(`${size}²: fused ${f.toFixed(1)} ms, unfused ${u.toFixed(1)} ms, ratio ${(f / u).toFixed(2)}`);
}
