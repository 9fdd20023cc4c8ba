// Texture benchmark: the native figures (timings, patch energies, band energies,
// repetition) from examples/bench_texture, the same default-mode cases timed in wasm
// under Node (median of 3), and texture-synthesis-cli side by side when installed.
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { decodeImage, synthesizeTexture, blendTextures } from '../pkg/node/index.js';

const native = execFileSync('target/release/examples/bench_texture', { encoding: 'utf8' }).trim().split('\n').map((l) => JSON.parse(l));

const fixture = (name) => decodeImage(readFileSync(`tests/fixtures/textures/${name}.png`));
const square = (img, side) => {
  const data = new Uint8ClampedArray(side * side * 4);
  for (let y = 0; y < side; y++) for (let x = 0; x < side; x++) {
    const sx = side <= img.width ? x : Math.floor((x * img.width) / side), sy = side <= img.height ? y : Math.floor((y * img.height) / side);
    data.set(img.data.subarray(4 * (sy * img.width + sx), 4 * (sy * img.width + sx) + 4), 4 * (y * side + x));
  }
  return { width: side, height: side, data };
};
const median = (f, runs = 3) => {
  const t = [];
  for (let i = 0; i < runs; i++) { const s = performance.now(); f(); t.push(performance.now() - s); }
  return t.sort((a, b) => a - b)[runs >> 1];
};

const rows = [];
for (const n of native) {
  let wasm = '';
  if (!n.exhaustive) {
    const a = square(fixture(n.a), n.ex);
    wasm = n.case === 'single'
      ? median(() => synthesizeTexture(a, { width: n.out, height: n.out, seed: 1 }))
      : median(() => blendTextures(a, square(fixture(n.b), n.ex), { width: n.out, height: n.out, seed: 1, coefficient: 'linear' }));
  }
  const energy = n.case === 'single' ? n.energy.toFixed(2) : `top A ${n.top_a.toFixed(1)} / B ${n.top_b.toFixed(1)}; bottom A ${n.bottom_a.toFixed(1)} / B ${n.bottom_b.toFixed(1)}`;
  rows.push([n.case, n.b ? `${n.a} → ${n.b}` : n.a, `${n.ex}→${n.out}`, n.exhaustive ? 'exhaustive' : 'default', n.ms.toFixed(0),
    wasm === '' ? '—' : wasm.toFixed(0), wasm === '' ? '—' : (wasm / n.ms).toFixed(2), energy, n.repetition === undefined ? '—' : n.repetition.toFixed(3)]);
}
console.log('| engine | exemplar | size | mode | ms native | ms wasm | wasm/native | patch energy | repetition |');
console.log('|---|---|---|---|---|---|---|---|---|');
for (const r of rows) console.log(`| ${r.join(' | ')} |`);

// Working memory: peak bytes allocated from RGBA in to RGBA out, over the images' size.
console.log('\n| memory case | output | images (RGBA bytes) | peak working bytes | ratio |');
console.log('|---|---|---|---|---|');
for (const m of execFileSync('target/release/examples/bench_texture', ['--memory'], { encoding: 'utf8' }).trim().split('\n').map((l) => JSON.parse(l))) {
  console.log(`| ${m.what} | ${m.out}² | ${m.images_bytes} | ${m.peak_bytes} | ${m.ratio.toFixed(2)} |`);
}

// The well-known native multi-threaded synthesizer, same exemplars, 128 -> 256.
const cli = spawnSync('texture-synthesis', ['--version'], { encoding: 'utf8' });
if (cli.status === 0) {
  const dir = mkdtempSync(join(tmpdir(), 'ts-'));
  const pairs = [];
  console.log('\n| exemplar | texture-synthesis ms (2 threads) | its patch energy | its repetition |');
  console.log('|---|---|---|---|');
  const res = [];
  for (const name of ['wood', 'brick', 'grass', 'gravel']) {
    for (const seed of [1, 2, 3]) {
      const out = join(dir, `${name}-${seed}.png`);
      const t = performance.now();
      execFileSync('texture-synthesis', ['--out', out, '--out-size', '256', '--no-progress', '--seed', `${seed}`, 'generate', `tests/fixtures/textures/${name}.png`]);
      if (seed === 1) {
        res.push([name, performance.now() - t]);
        pairs.push(`${name}=${out}`);
      }
    }
  }
  const ref = execFileSync('target/release/examples/bench_texture', ['--reference', ...pairs], { encoding: 'utf8' }).trim().split('\n').map((l) => JSON.parse(l));
  res.forEach(([name, ms], i) => console.log(`| ${name} | ${ms.toFixed(0)} | ${ref[i].energy.toFixed(2)} | ${ref[i].repetition.toFixed(3)} |`));
  // One seed is noisy (theirs is not even deterministic): the mean over seeds 1-3.
  const tune = (env) => execFileSync('target/release/examples/tune_texture', { encoding: 'utf8', env: { ...process.env, SEEDS: '3', ...env } }).trim();
  console.log('\nmean patch energy over seeds 1-3, 128 -> 256:');
  console.log(`  ours:              ${tune({})}`);
  console.log(`  texture-synthesis: ${tune({ REF: dir })}`);
} else {
  console.log('\n(texture-synthesis-cli not installed: `cargo install --locked texture-synthesis-cli` to compare)');
}
