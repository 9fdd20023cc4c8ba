// Seamless-tile benchmark: the native figures of examples/bench_seamless (time, the
// paper's restoration rate, seam score, E-TFMCM's decisions) for 128 and 512 tiles of
// the four photographs, and the same cases timed in wasm under Node (median of 3).
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { decodeImage, seamlessTile } from '../pkg/node/index.js';

const median = (f, runs = 3) => {
  const t = [];
  for (let i = 0; i < runs; i++) { const s = performance.now(); f(); t.push(performance.now() - s); }
  return t.sort((a, b) => a - b)[runs >> 1];
};

console.log('| exemplar | method | tile | ms native | ms wasm | wasm/native | restoration rate | seam score | decided by J3 = 4 / 3 / 2 / 1, pairwise, mean |');
console.log('|---|---|---|---|---|---|---|---|---|');
for (const size of ['128', '512']) {
  const rows = execFileSync('target/release/examples/bench_seamless', [size], { encoding: 'utf8' }).trim().split('\n').map((l) => JSON.parse(l));
  for (const r of rows) {
    const img = decodeImage(readFileSync(`tests/fixtures/textures/${r.exemplar}.png`));
    const wasm = median(() => seamlessTile(img, { method: r.method, size: r.size, seed: 1 }));
    const d = r.decisions ? `${r.decisions.j3[4]} / ${r.decisions.j3[3]} / ${r.decisions.j3[2]} / ${r.decisions.j3[1]}, ${r.decisions.pairwise}, ${r.decisions.mean}` : '—';
    console.log(`| ${r.exemplar} | ${r.method} | ${r.size} | ${r.ms.toFixed(0)} | ${wasm.toFixed(0)} | ${(wasm / r.ms).toFixed(2)} | ${r.restoration.toFixed(3)} | ${r.seam.toFixed(2)} | ${d} |`);
  }
}
