// Issue 30's verbs against plain synthesis of the same output size (the issue asks each
// within 1.5x), through the built package in Node (wasm SIMD), one thread, medians of
// interleaved runs. The exemplars are the 128² fixtures; the photograph that inpainting
// and mending work on is a 256² synthesis of each (so every verb sees the same
// picture), and since those two read it as their exemplar, they are also compared with
// plain synthesis from it.
//   node bench/verbs.mjs [side] [runs]      e.g. node bench/verbs.mjs 256 5
import { readFileSync } from 'node:fs';
import * as ps from '../pkg/node/index.js';

const side = Number(process.argv[2] ?? 256);
const runs = Number(process.argv[3] ?? 5);
const load = (name) => ps.decodeImage(readFileSync(`tests/fixtures/textures/${name}.png`));
const make = (w, h, f) => {
  const data = new Uint8ClampedArray(w * h * 4);
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) data.set(f(x, y), 4 * (y * w + x));
  return { width: w, height: h, data };
};
const median = (t) => [...t].sort((a, b) => a - b)[t.length >> 1];

console.log(`| photograph | verb | ms (median of ${runs}) | x plain synthesis of ${side}² | x from the photograph |`);
console.log('|---|---|---:|---:|---:|');
for (const name of ['gravel', 'brick', 'grass']) {
  const ex = load(name);
  // The photograph the verbs work on: side x side.
  const photo = ps.synthesizeTexture(ex, { width: side, height: side, seed: 9 });
  const hole = make(side, side, (x, y) => (Math.hypot(x - side / 2, y - side / 2) < side * 0.18 ? [255, 255, 255, 255] : [0, 0, 0, 255]));
  const keepOut = make(ex.width, ex.height, (x) => (x < ex.width / 4 ? [255, 255, 255, 255] : [0, 0, 0, 255]));
  const ramp = make(ex.width, ex.height, (x) => { const v = Math.round((255 * x) / ex.width); return [v, v, v, 255]; });
  const disc = make(side, side, (x, y) => { const v = Math.hypot(x - side / 2, y - side / 2) < side / 3 ? 255 : 0; return [v, v, v, 255]; });
  // A photograph whose side is not 32 x 2^k (224 at 256) has a different coarsest level.
  const c = Math.round((side * 7) / 8);
  const cropped = make(c, c, (x, y) => Array.from(photo.data.subarray(4 * (y * side + x), 4 * (y * side + x) + 4)));
  const half = (y0) => make(ex.width, ex.height / 2, (x, y) => Array.from(ex.data.subarray(4 * ((y0 + y) * ex.width + x), 4 * ((y0 + y) * ex.width + x) + 4)));
  const verbs = {
    'plain synthesis': () => ps.synthesizeTexture(ex, { width: side, height: side }),
    // Inpainting and mending read the photograph itself, a larger exemplar.
    'plain synthesis from the photograph': () => ps.synthesizeTexture(photo, { width: side, height: side }),
    [`plain synthesis from a ${c}² crop`]: () => ps.synthesizeTexture(cropped, { width: side, height: side }),
    'inpaint (13% hole)': () => ps.inpaintTexture(photo, hole),
    'mend (band 0.25)': () => ps.seamlessTile(photo, { method: 'mend' }),
    'sample mask (a quarter out)': () => ps.synthesizeTexture(ex, { width: side, height: side, sampleMask: keepOut }),
    'guided': () => ps.synthesizeTexture(ex, { width: side, height: side, guides: { exemplar: ramp, target: disc } }),
    'two exemplars': () => ps.synthesizeTexture([half(0), half(ex.height / 2)], { width: side, height: side }),
    'keepLayout + applyLayout (2 maps)': () => { const r = ps.synthesizeTexture(ex, { width: side, height: side, keepLayout: true }); ps.applyLayout(r.layout, [ex, ex]); },
    'transferStyle': () => ps.transferStyle(ex, photo),
  };
  const times = Object.fromEntries(Object.keys(verbs).map((k) => [k, []]));
  for (let r = 0; r < runs; r++) {
    for (const [k, f] of Object.entries(verbs)) {
      const t = performance.now();
      f();
      times[k].push(performance.now() - t);
    }
  }
  const plain = median(times['plain synthesis']), fromPhoto = median(times['plain synthesis from the photograph']);
  for (const k of Object.keys(verbs)) {
    const m = median(times[k]);
    console.log(`| ${name} | ${k} | ${m.toFixed(0)} | ${(m / plain).toFixed(2)} | ${(m / fromPhoto).toFixed(2)} |`);
  }
}
