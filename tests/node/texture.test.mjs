// The texture API under Node: decode, synthesize, blend, encode, and clear errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as ps from '../../pkg/node/index.js';
import { lineArt } from './line-art.mjs';

const load = (name) => ps.decodeImage(readFileSync(new URL(`../fixtures/textures/${name}.png`, import.meta.url)));

const crop = (img, side) => {
  const data = new Uint8ClampedArray(side * side * 4);
  for (let y = 0; y < side; y++) data.set(img.data.subarray(y * img.width * 4, y * img.width * 4 + side * 4), y * side * 4);
  return { width: side, height: side, data };
};

test('decodeImage reads the fixtures; encodePng round-trips', () => {
  const wood = load('wood');
  assert.equal(wood.width, 128);
  assert.equal(wood.data.length, 128 * 128 * 4);
  const png = ps.encodePng(wood);
  assert.ok(png instanceof Uint8Array && png[1] === 0x50 /* 'P' */);
  const back = ps.decodeImage(png);
  assert.deepEqual(Array.from(back.data.subarray(0, 64)), Array.from(wood.data.subarray(0, 64)));
});

test('synthesizeTexture makes the requested size, with progress', () => {
  const ex = crop(load('gravel'), 48);
  const seen = [];
  const out = ps.synthesizeTexture(ex, { width: 80, height: 60, seed: 2 }, (f) => { seen.push(f); });
  assert.equal(out.width, 80);
  assert.equal(out.height, 60);
  assert.equal(out.data.length, 80 * 60 * 4);
  assert.ok(seen.length > 5 && seen.at(-1) === 1);
  assert.ok(out.data.every((v, i) => i % 4 !== 3 || v === 255), 'opaque');
});

test('blendTextures: top like A (orange wood), bottom like B (grey gravel)', () => {
  const a = crop(load('wood'), 48), b = crop(load('gravel'), 48);
  for (const coefficient of ['linear', 'ease', 'steep']) {
    const out = ps.blendTextures(a, b, { width: 64, height: 64, coefficient, seed: 1 });
    const redness = (y0, y1) => {
      let s = 0, n = 0;
      for (let y = y0; y < y1; y++) for (let x = 0; x < 64; x++) { const i = (y * 64 + x) * 4; s += out.data[i] - out.data[i + 2]; n++; }
      return s / n;
    };
    assert.ok(redness(0, 10) > redness(54, 64) + 20, `${coefficient}: ${redness(0, 10)} vs ${redness(54, 64)}`);
  }
  // A caller-supplied map: A on the left half only.
  const map = new Float32Array(64 * 64).map((_, i) => (i % 64 < 32 ? 1 : 0));
  const out = ps.blendTextures(a, b, { width: 64, height: 64, coefficient: map });
  const col = (x) => { let s = 0; for (let y = 0; y < 64; y++) { const i = (y * 64 + x) * 4; s += out.data[i] - out.data[i + 2]; } return s / 64; };
  assert.ok(col(10) > col(54) + 20);
  // Radial and angled ramps are accepted.
  ps.blendTextures(a, b, { width: 32, height: 32, coefficient: 'radial', transfer: 'ease' });
  ps.blendTextures(a, b, { width: 32, height: 32, coefficient: 'steep', angle: 0 });
});

test('bad images and options throw clear Errors', () => {
  const a = crop(load('wood'), 32);
  const cases = [
    [() => ps.synthesizeTexture({ width: 0, height: 5, data: new Uint8Array(0) }, { width: 8, height: 8 }), /empty/],
    [() => ps.synthesizeTexture({ width: 4, height: 4, data: new Uint8Array(10) }, { width: 8, height: 8 }), /needs 64/],
    [() => ps.synthesizeTexture({ width: 4, height: 4, data: [1, 2, 3] }, { width: 8, height: 8 }), /Uint8Array/],
    [() => ps.synthesizeTexture('nope', { width: 8, height: 8 }), /object/],
    [() => ps.synthesizeTexture(a, { width: 100000, height: 8 }), /largest side/],
    [() => ps.synthesizeTexture(a, { width: 4097, height: 16 }), /the largest side accepted is 4096/],
    [() => ps.synthesizeTexture({ width: 3, height: 3, data: new Uint8Array(36) }, { width: 8, height: 8 }), /smaller than the 5x5/],
    [() => ps.synthesizeTexture(a, { width: 8, height: 8, wdth: 3 }), /unknown option `wdth`/],
    [() => ps.blendTextures(a, a, { width: 4, height: 4, coefficient: new Float32Array(16).fill(NaN) }), /not a number/],
    [() => ps.blendTextures(a, a, { width: 4, height: 4, coefficient: 'sideways' }), /Unknown transition/],
    [() => ps.decodeImage(new Uint8Array([1, 2, 3])), /neither PNG nor JPEG|not supported/],
  ];
  for (const [fn, want] of cases) assert.throws(fn, (e) => e instanceof Error && want.test(e.message), String(want));
  assert.throws(() => ps.synthesizeTexture(a, { width: 200, height: 200 }, () => false), /Cancelled/);
});

test('seamlessTile: E-TFMCM and synthesis tiles with their figures, clear errors', () => {
  const img = crop(load('brick'), 64);
  const seen = [];
  const e = ps.seamlessTile(img, { method: 'etfmcm', seed: 3 }, (f) => { seen.push(f); });
  assert.equal(e.image.width, 64);
  assert.equal(e.image.data.length, 64 * 64 * 4);
  assert.ok(e.restorationRate > 0.75 && e.restorationRate <= 1, `${e.restorationRate}`);
  assert.ok(e.seamScore < 1.3, `${e.seamScore}`);
  assert.ok(['r', 'g', 'b'].includes(e.channel));
  assert.equal(e.decisions.byJ3.reduce((a, b) => a + b) + e.decisions.pairwise + e.decisions.mean, 64 * 64 - 2);
  assert.deepEqual(e.warnings, []);
  assert.equal(seen.at(-1), 1);
  const s = ps.seamlessTile(img, { method: 'synthesis', size: 32 });
  assert.equal(s.image.width, 32);
  assert.equal(s.channel, null);
  // A smaller tile keeps the image's scale: no image scaled down, no warning.
  assert.deepEqual(s.warnings, []);
  // The default is the page's: toroidal synthesis (issue 25: it keeps structure).
  const d = ps.seamlessTile(img, { size: 32 });
  assert.equal(d.channel, null);
  assert.deepEqual(d.image.data, s.image.data);
  assert.throws(() => ps.seamlessTile(img, { method: 'fractal' }), /unknown variant `fractal`/);
  assert.throws(() => ps.seamlessTile(img, { size: 48 }), /power of two/);
  assert.throws(() => ps.seamlessTile(img, { maxCount: 3 }), /unknown option `maxCount`/);
  assert.throws(() => ps.seamlessTile({ width: 4, height: 4, data: new Uint8Array(64) }, {}), /at least 8/);
});

// Line art on a clear ground through a PNG round trip, then the defaults.
test('a picture on a transparent ground keeps its transparency in tiles and textures', () => {
  const art = ps.decodeImage(ps.encodePng(lineArt(96, 10, 7)));
  const clear = (img) => {
    let n = 0;
    for (let i = 3; i < img.data.length; i += 4) n += img.data[i] === 0;
    return n / (img.data.length / 4);
  };
  const ground = clear(art);
  assert.ok(ground > 0.8, `${ground}`);
  const tile = ps.seamlessTile(art, { width: 128, height: 128 });
  const texture = ps.synthesizeTexture(art, { width: 160, height: 128 });
  for (const [what, out] of [['tile', tile.image], ['texture', texture]]) {
    // Before, every pixel came back opaque (the clear ground black).
    assert.ok(Math.abs(clear(out) - ground) < 0.08, `${what}: ${clear(out)} clear against ${ground}`);
    for (let i = 0; i < out.data.length; i += 4) {
      if (out.data[i + 3] === 255) assert.deepEqual([...out.data.subarray(i, i + 3)], [20, 30, 90], `${what} at ${i / 4}`);
    }
  }
  assert.ok(!tile.warnings.join(' ').includes('transparency'), tile.warnings.join(' '));
  // A blend mixes the alphas as the colours: A's clear ground at the top, B (opaque
  // wood) at the bottom.
  const blend = ps.blendTextures(art, crop(load('wood'), 96), { width: 96, height: 96 });
  const meanAlpha = (y0, y1) => {
    let sum = 0;
    for (let i = y0 * 96 * 4 + 3; i < y1 * 96 * 4; i += 4) sum += blend.data[i];
    return sum / ((y1 - y0) * 96 * 255);
  };
  assert.ok(meanAlpha(0, 12) < 0.3, `top ${meanAlpha(0, 12)}`);
  assert.ok(meanAlpha(84, 96) > 0.9, `bottom ${meanAlpha(84, 96)}`);
  // E-TFMCM reads colours only: its tile is the picture over white (a clear ground
  // holding black shows white), and says so.
  const dark = { ...art, data: art.data.map((v, i) => (art.data[i - (i % 4) + 3] === 0 ? 0 : v)) };
  const e = ps.seamlessTile(dark, { method: 'etfmcm' });
  assert.ok(e.restorationRate > 0.6, `restoration ${e.restorationRate}`);
  let white = 0;
  for (let i = 0; i < e.image.data.length; i += 4) white += e.image.data[i] > 200;
  assert.ok(white / (e.image.data.length / 4) > 0.5, `white share ${white}`);
  assert.match(ps.seamlessTile(art, { method: 'etfmcm' }).warnings.join(' '), /transparency/);
});
