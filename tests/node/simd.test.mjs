// The texture engine ships twice: built with wasm SIMD (what Node and every current
// browser load) and without (js/pkg/simd.js picks one at load). Both must give the
// same images, byte for byte: each sums a pixel's channels in lanes and adds the lanes
// in one order (src/raster/synthesis/lanes.rs). A change that makes them differ would
// give users of old browsers other images for the same seed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createHash } from 'node:crypto';
import * as simdEntry from '../../pkg/node/texture.js';
import { decodeImage } from '../../pkg/node/codec.js';
import { supportsSimd, simd } from '../../pkg/simd.js';

const scalar = await import('../../pkg/wasm/texture.js?scalar');
scalar.initSync({ module: new WebAssembly.Module(readFileSync('pkg/wasm/texture_scalar_bg.wasm')) });

const fixture = (name, side) => {
  const img = decodeImage(readFileSync(`tests/fixtures/textures/${name}.png`));
  const data = new Uint8ClampedArray(side * side * 4);
  for (let y = 0; y < side; y++) data.set(img.data.subarray(4 * y * img.width, 4 * (y * img.width + side)), 4 * y * side);
  return { width: side, height: side, data };
};
const digest = (img) => createHash('sha256').update(img.data).digest('hex');

test('SIMD is detected in Node, and a JavaScript engine that refuses the probe gets the scalar build', () => {
  assert.equal(simd, true);
  assert.equal(simdEntry.simd, true, 'the entry says which build it loads');
  assert.equal(supportsSimd({ validate: () => false }), false);
  assert.equal(supportsSimd({ validate: () => { throw new TypeError('no'); } }), false);
  assert.equal(supportsSimd(null), false);
});

test('the scalar and SIMD builds make the same textures, blends and tiles', () => {
  const gravel = fixture('gravel', 96), brick = fixture('brick', 96);
  const cases = [
    ['synthesizeTexture 160² (scanline)', (m) => m.synthesizeTexture(gravel, { width: 160, height: 160, seed: 3 }, undefined)],
    ['synthesizeTexture 512² (banded)', (m) => m.synthesizeTexture(brick, { width: 512, height: 512, seed: 1 }, undefined)],
    ['blendTextures 128²', (m) => m.blendTextures(gravel, brick, { width: 128, height: 128, seed: 2, coefficient: 'linear' }, undefined)],
    ['seamlessTile synthesis 96²', (m) => m.seamlessTile(brick, { method: 'synthesis', width: 96, height: 96, seed: 5 }, undefined)],
    ['seamlessTile E-TFMCM refined 64²', (m) => m.seamlessTile(brick, { method: 'etfmcm', size: 64, seed: 4 }, undefined)],
    ['seamlessTile by default 64²', (m) => m.seamlessTile(brick, { size: 64, seed: 4 }, undefined)],
    ['synthesizeTexture exhaustive 64²', (m) => m.synthesizeTexture(gravel, { width: 64, height: 64, seed: 1, exhaustive: true }, undefined)],
  ];
  for (const [name, run] of cases) {
    // seamlessTile answers with its report, the image in it.
    const image = (r) => r.image ?? r;
    const a = image(run(simdEntry)), b = image(run(scalar));
    assert.equal(a.width, b.width);
    assert.equal(digest(a), digest(b), `${name}: the two builds differ`);
  }
});
