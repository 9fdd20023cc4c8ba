// The Fill & mend tab end to end in headless Chromium: a mask painted over the built-in
// brick with pointer events (and from the keyboard), filled in the worker (every
// unpainted pixel of the download identical to the photograph), the mask surviving a
// reload, the photograph mended into a tile (the inner part kept, no seam), and more of
// it with a map laid out the same way. Screenshots: out/retouch-fill.png,
// out/retouch-mend.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { openPlayground } from './harness.mjs';
import { decodeImage } from '../../pkg/node/index.js';

let page, close;
const brick = decodeImage(readFileSync(new URL('../../www/textures/brick.png', import.meta.url)));

before(async () => {
  ({ page, close } = await openPlayground({ tab: 'retouch' }));
  await page.waitForFunction(() => document.querySelector('#ret-source').width === 128);
  mkdirSync('out', { recursive: true });
});

after(async () => close?.());

async function run() {
  await page.click('#ret-run');
  await page.waitForFunction(() => !document.querySelector('#ret-run').disabled && document.querySelector('#ret-progress').value === 1, null, { timeout: 60000 });
}

async function download() {
  const [d] = await Promise.all([page.waitForEvent('download'), page.click('#ret-download')]);
  return { name: d.suggestedFilename(), image: decodeImage(readFileSync(await d.path())) };
}

/** The mask as painted on the page (true = painted), at the photograph's size. */
const painted = () => page.evaluate(() => {
  const c = document.querySelector('#ret-mask');
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  return Array.from({ length: c.width * c.height }, (_, i) => d[4 * i + 3] > 0);
});

test('a mask painted with the pointer is filled; every other pixel is the photograph', async () => {
  assert.equal(await page.inputValue('#ret-action'), 'fill');
  // A stroke across the middle of the photograph with the mouse.
  const box = await page.locator('#ret-mask').boundingBox();
  await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.5);
  await page.mouse.down();
  for (let k = 1; k <= 10; k++) await page.mouse.move(box.x + box.width * (0.3 + 0.04 * k), box.y + box.height * (0.5 + 0.01 * k));
  await page.mouse.up();
  const mask = await painted();
  const count = mask.filter(Boolean).length;
  assert.ok(count > 300 && count < 0.3 * 128 * 128, `painted ${count} pixels`);
  await run();
  assert.match(await page.textContent('#ret-info'), /128×128, \d+ ms/);
  const { name, image } = await download();
  assert.equal(name, 'fill-128x128.png');
  let changed = 0;
  for (let i = 0; i < 128 * 128; i++) {
    const same = [0, 1, 2].every((c) => image.data[4 * i + c] === brick.data[4 * i + c]);
    if (!mask[i]) assert.ok(same, `unpainted pixel ${i % 128},${Math.floor(i / 128)} changed`);
    else changed += same ? 0 : 1;
  }
  assert.ok(changed > 0.3 * count, `the painted pixels were re-made (${changed} of ${count} differ)`);
  await page.screenshot({ path: 'out/retouch-fill.png', fullPage: true });
});

test('from the keyboard: the arrows move the brush and Space paints; Clear empties the mask', async () => {
  await page.focus('#ret-mask');
  const before = (await painted()).filter(Boolean).length;
  await page.keyboard.press('ArrowUp');
  await page.keyboard.press('ArrowUp');
  await page.keyboard.press('Space');
  await page.keyboard.down('Shift');
  for (let k = 0; k < 3; k++) await page.keyboard.press('ArrowLeft');
  await page.keyboard.up('Shift');
  const after = (await painted()).filter(Boolean).length;
  assert.ok(after > before + 200, `keyboard painting added ${after - before} pixels`);
  assert.ok(await page.evaluate(() => document.querySelector('.mask-stack').classList.contains('ring')), 'the brush ring shows');
});

test('the mask and the settings survive a reload', async () => {
  const mask = await painted();
  await page.selectOption('#ret-action', 'mend');
  // (The write starts with the change; a reload before IndexedDB commits it may lose it,
  // as settings.test.mjs waits for too: under a loaded machine the page came back with
  // 'fill'.)
  await page.waitForFunction((key) => new Promise((ok) => {
    const r = indexedDB.open('patternsynth');
    r.onsuccess = () => { const g = r.result.transaction('kept').objectStore('kept').get(`settings:${key}`); g.onsuccess = () => ok(g.result?.action === 'mend'); };
  }), 'patternsynth.retouch.settings.v1');
  await page.reload();
  await page.click('[data-tab="retouch"]');
  await page.waitForFunction(() => document.querySelector('#ret-mask-info').textContent === 'painted', null, { timeout: 10000 });
  assert.equal(await page.inputValue('#ret-action'), 'mend');
  const back = await painted();
  const same = back.filter((v, i) => v === mask[i]).length;
  assert.ok(same > 0.99 * mask.length, `the mask came back (${same} of ${mask.length} pixels agree)`);
});

test('mend: the photograph kept but its edges, repeated without a seam; Clear mask', async () => {
  await page.click('#ret-clear');
  assert.equal((await painted()).filter(Boolean).length, 0);
  await run();
  const info = await page.textContent('#ret-info');
  const score = Number(info.match(/seam score (\d+\.\d+)/)[1]);
  assert.ok(score > 0.1 && score < 1.3, info);
  const { name, image } = await download();
  assert.equal(name, 'mend-128x128.png');
  // The inner 75% x 75% is the photograph.
  for (let y = 16; y < 112; y += 3) for (let x = 16; x < 112; x += 3) {
    const i = 4 * (y * 128 + x);
    assert.deepEqual([...image.data.subarray(i, i + 3)], [...brick.data.subarray(i, i + 3)], `${x},${y}`);
  }
  // The preview shows it repeated 2 x 2.
  assert.equal(await page.evaluate(() => document.querySelector('#ret-result').width), 256);
  await page.screenshot({ path: 'out/retouch-mend.png', fullPage: true });
});

test('more of it at another size, with a map laid out the same way', async () => {
  await page.selectOption('#ret-action', 'more');
  await page.fill('#ret-width', '200');
  await page.fill('#ret-height', '150');
  // A "normal map": the photograph inverted, added as a file.
  const png = await page.evaluate(async () => {
    const src = document.querySelector('#ret-source');
    const c = new OffscreenCanvas(src.width, src.height);
    const ctx = c.getContext('2d');
    ctx.filter = 'invert(1)';
    ctx.drawImage(src, 0, 0);
    const blob = await c.convertToBlob({ type: 'image/png' });
    return Array.from(new Uint8Array(await blob.arrayBuffer()));
  });
  await page.setInputFiles('#ret-maps', { name: 'brick-normal.png', mimeType: 'image/png', buffer: Buffer.from(png) });
  await page.waitForFunction(() => document.querySelector('#ret-maps-list').textContent.includes('brick-normal.png'));
  await run();
  assert.match(await page.textContent('#ret-info'), /200×150, 1 map laid out the same way/);
  const { image } = await download();
  const [d] = await Promise.all([page.waitForEvent('download'), page.click('#ret-map-downloads a')]);
  assert.equal(d.suggestedFilename(), 'brick-normal-200x150.png');
  const map = decodeImage(readFileSync(await d.path()));
  assert.equal(map.width, 200);
  let off = 0;
  for (let i = 0; i < 200 * 150; i += 7) off += Math.abs(map.data[4 * i] - (255 - image.data[4 * i])) > 2 ? 1 : 0;
  assert.ok(off < 0.02 * (200 * 150 / 7), `the map is the texture inverted pixel for pixel (${off} differ)`);
});
