// Issue 30's verbs through the package in Node: fill a hole, mend a photograph into a
// tile, keep parts of an exemplar out, follow a guide, draw from several exemplars,
// replay a layout on other maps, transfer a style; and their errors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as ps from '../../pkg/node/index.js';

const load = (name) => ps.decodeImage(readFileSync(new URL(`../fixtures/textures/${name}.png`, import.meta.url)));

/** An RGBA image `w x h` from `f(x, y) -> [r, g, b, a?]`. */
const make = (w, h, f) => {
  const data = new Uint8ClampedArray(w * h * 4);
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) {
    const [r, g, b, a = 255] = f(x, y);
    data.set([r, g, b, a], 4 * (y * w + x));
  }
  return { width: w, height: h, data };
};
/** A mask: opaque white where `inside(x, y)`. */
const maskOf = (w, h, inside) => make(w, h, (x, y) => (inside(x, y) ? [255, 255, 255] : [0, 0, 0]));
const px = (img, x, y) => Array.from(img.data.subarray(4 * (y * img.width + x), 4 * (y * img.width + x) + 4));
const sub = (img, x0, y0, w, h) => make(w, h, (x, y) => px(img, x0 + x, y0 + y));

/** RMS colour difference between 7 x 7 windows of `out` centred at `points` and their
 *  best matches among the windows of `ex` whose every pixel passes `allowed`. */
function energy(out, ex, points, allowed = () => true) {
  const centres = [];
  for (let y = 3; y < ex.height - 3; y++) for (let x = 3; x < ex.width - 3; x++) {
    let ok = true;
    for (let dy = -3; dy <= 3 && ok; dy++) for (let dx = -3; dx <= 3 && ok; dx++) ok = allowed(x + dx, y + dy);
    if (ok) centres.push([x, y]);
  }
  let total = 0;
  for (const [x, y] of points) {
    let best = Infinity;
    for (const [cx, cy] of centres) {
      let acc = 0;
      for (let dy = -3; dy <= 3 && acc < best; dy++) for (let dx = -3; dx <= 3; dx++) {
        const i = 4 * ((y + dy) * out.width + x + dx), j = 4 * ((cy + dy) * ex.width + cx + dx);
        for (let c = 0; c < 3; c++) acc += (out.data[i + c] - ex.data[j + c]) ** 2;
      }
      best = Math.min(best, acc);
    }
    total += best / 147;
  }
  return Math.sqrt(total / points.length);
}

test('inpaintTexture fills a hole like the photograph around it and keeps every other pixel', () => {
  for (const name of ['gravel', 'brick', 'grass']) {
    const img = load(name);
    const { width: w, height: h } = img;
    const inHole = (x, y) => Math.hypot(x - 64, y - 60) < 18;
    const mask = maskOf(w, h, inHole);
    const out = ps.inpaintTexture(img, mask, { seed: 1 });
    assert.equal(out.width, w);
    let changed = 0;
    for (let i = 0; i < w * h; i++) {
      const x = i % w, y = Math.floor(i / w);
      if (!inHole(x, y)) for (let c = 0; c < 4; c++) assert.equal(out.data[4 * i + c], img.data[4 * i + c], `${name}: kept pixel ${x},${y} changed`);
      else changed += out.data[4 * i] !== img.data[4 * i] ? 1 : 0;
    }
    assert.ok(changed > 100, `${name}: the hole was filled (${changed} pixels differ)`);
    // Windows inside the hole against windows wholly outside it: the fill is about as
    // close to the photograph as the photograph's own content there. Patch energy cannot
    // tell a flat fill (a flat window matches smooth places well), so the fill must also
    // keep the photograph's contrast: its luminance spread within a third of the ring's
    // around the hole.
    const points = [];
    for (let y = 48; y <= 72; y += 6) for (let x = 52; x <= 76; x += 6) if (inHole(x, y)) points.push([x, y]);
    const outside = (x, y) => !inHole(x, y);
    const ours = energy(out, img, points, outside);
    const truth = energy(img, img, points, outside);
    assert.ok(ours < 1.35 * truth + 2, `${name}: fill energy ${ours.toFixed(2)} against the photograph's own ${truth.toFixed(2)}`);
    const spread = (image, pred) => {
      const v = [];
      for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) if (pred(x, y)) { const [r, g, b] = px(image, x, y); v.push(0.299 * r + 0.587 * g + 0.114 * b); }
      const m = v.reduce((a, b) => a + b, 0) / v.length;
      return Math.sqrt(v.reduce((a, b) => a + (b - m) ** 2, 0) / v.length);
    };
    const inside = spread(out, inHole), ring = spread(img, (x, y) => !inHole(x, y) && Math.hypot(x - 64, y - 60) < 30);
    assert.ok(inside > 0.67 * ring && inside < 1.5 * ring, `${name}: spread in the hole ${inside.toFixed(1)}, around it ${ring.toFixed(1)}`);
  }
  // The seed changes the filling; the same seed gives the same image.
  const img = load('gravel');
  const mask = maskOf(128, 128, (x, y) => x > 40 && x < 70 && y > 40 && y < 70);
  const a = ps.inpaintTexture(img, mask, { seed: 1 }), b = ps.inpaintTexture(img, mask, { seed: 2 });
  assert.deepEqual(ps.inpaintTexture(img, mask, { seed: 1 }).data, a.data);
  assert.notDeepEqual(a.data, b.data);
});

test('inpaintTexture keeps alpha and fills from where sampleMask allows only', () => {
  // Left half striped across, right half striped down (the same two greys), half
  // transparent; a hole in the right half. The fill's stripes show where it came from
  // (the healing evens out colour, not the direction of the stripes).
  const img = make(96, 64, (x, y) => { const v = (x < 48 ? y : x) % 6 < 3 ? 60 : 190; return [v, v, v, 128]; });
  const hole = (x, y) => x >= 60 && x < 84 && y >= 20 && y < 44;
  const mask = maskOf(96, 64, hole);
  const rightOut = maskOf(96, 64, (x) => x >= 48);
  const across = (out) => {
    let dx = 0, dy = 0;
    for (let y = 24; y < 40; y++) for (let x = 64; x < 80; x++) {
      dx += Math.abs(px(out, x + 1, y)[0] - px(out, x, y)[0]);
      dy += Math.abs(px(out, x, y + 1)[0] - px(out, x, y)[0]);
    }
    return dy / (dx + 1);
  };
  const free = ps.inpaintTexture(img, mask);
  const kept = ps.inpaintTexture(img, mask, { sampleMask: rightOut });
  assert.ok(across(free) < 0.3, `without a sample mask the hole is striped down like its half (${across(free).toFixed(2)})`);
  assert.ok(across(kept) > 3, `with the right half kept out, the stripes run across (${across(kept).toFixed(2)})`);
  for (let y = 20; y < 44; y++) for (let x = 60; x < 84; x++) assert.equal(px(kept, x, y)[3], 128, 'a filled pixel keeps its source alpha');
});

test("seamlessTile 'mend' keeps the photograph but a band, at any size, and removes its seam", () => {
  for (const name of ['gravel', 'grass', 'wood']) {
    const img = sub(load(name), 3, 5, 120, 100);
    const res = ps.seamlessTile(img, { method: 'mend' });
    assert.equal(res.image.width, 120);
    assert.equal(res.image.height, 100);
    // The inner 75% x 75% bit for bit.
    for (let y = 13; y < 87; y++) for (let x = 15; x < 105; x++) assert.deepEqual(px(res.image, x, y), px(img, x, y), `${name} ${x},${y}`);
    const before = ps.seamlessTile(img, { method: 'mend', band: 0.02 }).seamScore;
    assert.ok(res.seamScore >= 0.75 && res.seamScore <= 1.25, `${name}: seam ${res.seamScore.toFixed(2)} (a 2% band: ${before.toFixed(2)})`);
    assert.ok(res.restorationRate > 0.8, `${name}: colours kept (${res.restorationRate})`);
  }
  // A wider band keeps less.
  const img = sub(load('gravel'), 0, 0, 100, 100);
  const wide = ps.seamlessTile(img, { method: 'mend', band: 0.5 }).image;
  let same = 0;
  for (let i = 0; i < 100 * 100; i++) same += wide.data[4 * i] === img.data[4 * i] && wide.data[4 * i + 2] === img.data[4 * i + 2] ? 1 : 0;
  assert.ok(same >= 0.25 * 100 * 100 && same < 0.6 * 100 * 100, `band 0.5 keeps the inner half of each side (${same})`);
  assert.throws(() => ps.seamlessTile(img, { method: 'mend', band: 1.5 }), /band must be above 0 and below 1/);
  assert.throws(() => ps.seamlessTile(img, { method: 'mend', size: 64 }), /keeps the image's own size/);
  assert.throws(() => ps.seamlessTile(img, { band: 0.2 }), /option of method 'mend'/);
});

test('sampleMask keeps exemplar pixels out of synthesizeTexture, blendTextures and seamlessTile', () => {
  const wood = load('wood'), gravel = load('gravel');
  // Left half wood, right half gravel; the wood half kept out.
  const both = make(128, 64, (x, y) => (x < 64 ? px(wood, x, y) : px(gravel, x - 64, y)));
  const woodOut = maskOf(128, 64, (x) => x < 64);
  const { image, layout } = ps.synthesizeTexture(both, { width: 96, height: 96, sampleMask: woodOut, keepLayout: true });
  assert.ok(layout.data.every((v) => (v & 4095) >= 64), 'no output pixel copies the masked half');
  assert.equal(image.width, 96);
  // Blend: a mask for A only.
  const out = ps.blendTextures(both, gravel, { width: 48, height: 48, sampleMask: [woodOut, null] });
  assert.equal(out.width, 48);
  // A tile from the unmasked half only: no orange.
  const tile = ps.seamlessTile(both, { method: 'synthesis', width: 64, height: 64, sampleMask: maskOf(128, 64, (x) => x < 64) });
  let orange = 0;
  for (let i = 0; i < 64 * 64; i++) orange += tile.image.data[4 * i] - tile.image.data[4 * i + 2] > 40 ? 1 : 0;
  assert.ok(orange < 40, `a synthesized tile with the wood kept out has ${orange} orange pixels`);
  assert.throws(() => ps.seamlessTile(both, { method: 'etfmcm', sampleMask: woodOut }), /applies to methods 'synthesis' and 'mend'/);
  assert.throws(() => ps.synthesizeTexture(both, { width: 32, height: 32, sampleMask: maskOf(128, 64, () => true) }), /leaves no pixel/);
  assert.throws(() => ps.synthesizeTexture(both, { width: 32, height: 32, sampleMask: maskOf(64, 64, () => false) }), /must be 128x64/);
});

test('guides: the output follows the target where the exemplar guide says which texture is which', () => {
  const wood = load('wood'), gravel = load('gravel');
  const both = make(128, 64, (x, y) => (x < 64 ? px(wood, x, y) : px(gravel, x - 64, y)));
  const exGuide = make(128, 64, (x) => (x < 64 ? [0, 0, 0] : [255, 255, 255]));
  const inDisc = (x, y) => Math.hypot(x - 64, y - 64) < 36;
  const target = make(128, 128, (x, y) => (inDisc(x, y) ? [255, 255, 255] : [0, 0, 0]));
  const out = ps.synthesizeTexture(both, { width: 128, height: 128, guides: { exemplar: exGuide, target } });
  const redness = (pred) => {
    let sum = 0, n = 0;
    for (let y = 0; y < 128; y++) for (let x = 0; x < 128; x++) if (pred(x, y)) { sum += px(out, x, y)[0] - px(out, x, y)[2]; n++; }
    return sum / n;
  };
  const inside = redness((x, y) => Math.hypot(x - 64, y - 64) < 28), outside = redness((x, y) => Math.hypot(x - 64, y - 64) > 44);
  assert.ok(outside > inside + 30, `wood outside the disc (${outside.toFixed(1)}), gravel inside (${inside.toFixed(1)})`);
  assert.throws(() => ps.synthesizeTexture(both, { width: 64, height: 64, guides: { exemplar: exGuide, target } }), /target guide is 128x128; it must be the output's size, 64x64/);
});

test('several exemplars are one pool; the layout replays on other maps pixel for pixel', () => {
  // Two photographs of one material (two parts of the gravel fixture, of other sizes).
  const gravel = load('gravel');
  const wood = sub(gravel, 0, 0, 128, 64), other = sub(gravel, 10, 64, 96, 64);
  const { image, layout } = ps.synthesizeTexture([wood, other], { width: 160, height: 120, seed: 3, keepLayout: true });
  assert.deepEqual(layout.exemplars, [[128, 64], [96, 64]]);
  assert.equal(layout.data.length, 160 * 120);
  const share = layout.data.filter((v) => v >>> 24 === 1).length / layout.data.length;
  assert.ok(share > 0.15 && share < 0.85, `both exemplars drawn from (the second ${share.toFixed(2)})`);
  // The layout names each output pixel's source exactly.
  for (let i = 0; i < layout.data.length; i += 37) {
    const v = layout.data[i], ex = [wood, other][v >>> 24];
    assert.deepEqual(px(image, i % 160, Math.floor(i / 160)), px(ex, v & 4095, (v >>> 12) & 4095));
  }
  // Replayed on the colour maps themselves: the synthesis, pixel for pixel; on an
  // inverted "normal map" of each, the inverse.
  const invert = (img) => make(img.width, img.height, (x, y) => px(img, x, y).map((v, c) => (c < 3 ? 255 - v : v)));
  const [same, inverted] = ps.applyLayout(layout, [[wood, other], [invert(wood), invert(other)]]);
  assert.deepEqual(same.data, image.data);
  for (let i = 0; i < 160 * 120 * 4; i += 4 * 13) assert.equal(inverted.data[i], 255 - image.data[i]);
  // One exemplar: a map is an image.
  const one = ps.synthesizeTexture(gravel, { width: 64, height: 64, keepLayout: true });
  assert.deepEqual(ps.applyLayout(one.layout, [gravel])[0].data, one.image.data);
  // Errors name what is wrong.
  assert.throws(() => ps.applyLayout(layout, [[wood]]), /Map 1 has 1 images; the layout is from 2 exemplars/);
  assert.throws(() => ps.applyLayout(layout, [[wood, wood]]), /exemplar 2 is 128x64; the exemplar is 96x64/);
  assert.throws(() => ps.applyLayout({ ...layout, data: layout.data.slice(1) }, [[wood, other]]), /needs one per pixel/);
  assert.throws(() => ps.synthesizeTexture([], { width: 8, height: 8 }), /empty/);
});

test('transferStyle lays the style texture out as the target’s light and dark', () => {
  const style = load('gravel');
  const target = make(96, 80, (x, y) => { const v = (x + y) % 48 < 24 ? 230 : 30; return [v, v, v]; });
  const out = ps.transferStyle(style, target, { seed: 1 });
  assert.equal(out.width, 96);
  assert.equal(out.height, 80);
  const lum = (img, x, y) => { const [r, g, b] = px(img, x, y); return 0.299 * r + 0.587 * g + 0.114 * b; };
  let bright = 0, dark = 0, nb = 0, nd = 0;
  for (let y = 0; y < 80; y++) for (let x = 0; x < 96; x++) {
    if ((x + y) % 48 >= 4 && (x + y) % 48 < 20) { bright += lum(out, x, y); nb++; }
    if ((x + y) % 48 >= 28 && (x + y) % 48 < 44) { dark += lum(out, x, y); nd++; }
  }
  assert.ok(bright / nb > dark / nd + 15, `bright stripes ${(bright / nb).toFixed(1)}, dark ${(dark / nd).toFixed(1)}`);
});

test('transferStyle keeps a masked part of the style out (a logo on the photograph)', () => {
  // Gravel with a red square on it, which a designer keeps out of the result.
  const gravel = load('gravel');
  const logo = (x, y) => x >= 40 && x < 72 && y >= 30 && y < 62;
  const style = make(gravel.width, gravel.height, (x, y) => (logo(x, y) ? [230, 20, 20] : px(gravel, x, y)));
  const target = make(96, 80, (x, y) => { const v = (x + y) % 48 < 24 ? 230 : 30; return [v, v, v]; });
  const red = (img) => {
    let n = 0;
    for (let i = 0; i < img.width * img.height; i++) n += img.data[4 * i] - img.data[4 * i + 1] > 120 ? 1 : 0;
    return n;
  };
  for (const seed of [1, 2, 3]) {
    assert.ok(red(ps.transferStyle(style, target, { seed })) > 0 || seed > 1, 'unmasked, the logo is copied');
    const out = ps.transferStyle(style, target, { seed, sampleMask: maskOf(style.width, style.height, logo) });
    assert.equal(red(out), 0, `seed ${seed}: no red pixel with the logo masked`);
  }
  assert.throws(() => ps.transferStyle(make(3, 3, () => [0, 0, 0]), target), /The style image is 3x3, smaller than the 5x5 neighbourhood/);
  assert.throws(() => ps.transferStyle(style, target, { sampleMask: maskOf(10, 10, () => true) }), /must be/);
});

test('bad masks and layouts are refused with the reason', () => {
  const img = load('wood');
  assert.throws(() => ps.inpaintTexture(img, maskOf(64, 64, () => true)), /mask is 64x64; it must be 128x128/);
  assert.throws(() => ps.inpaintTexture(img, maskOf(128, 128, () => true)), /covers the whole image/);
  assert.throws(() => ps.inpaintTexture(img, 'hole'), /mask must be an object/);
  // A mask that leaves one pixel: the mask is why, not a sample mask nobody gave.
  let err = '';
  try { ps.inpaintTexture(img, maskOf(128, 128, (x, y) => x !== 5 || y !== 5)); } catch (e) { err = e.message; }
  assert.match(err, /The mask leaves no (pixel|unmasked patch of \d+x\d+ pixels) to copy from/);
  assert.doesNotMatch(err, /sample mask/);
  assert.throws(() => ps.inpaintTexture({ width: 1, height: 40, data: new Uint8Array(160) }, maskOf(1, 40, (x, y) => y === 5)), /1x40; a fill needs at least 3 pixels on a side/);
  assert.throws(() => ps.inpaintTexture(img, maskOf(128, 128, () => false), { sampleMsk: img }), /unknown option `sampleMsk` \(expected one of [^)]*sampleMask/);
  assert.throws(() => ps.applyLayout({ width: 2, height: 1, exemplars: [[4, 4]], data: new Uint32Array([0, 9]) }, [img]), /entry 1 points at exemplar 1 pixel \(9, 0\)/);
  assert.throws(() => ps.applyLayout('layout', [img]), /must be the `layout`/);
  // An inpaint with nothing masked returns the image.
  assert.deepEqual(ps.inpaintTexture(img, maskOf(128, 128, () => false)).data, img.data);
});
