// The Seamless tile tab end to end in headless Chromium: a built-in photograph loads,
// E-TFMCM and toroidal synthesis make tiles in the worker, the PNG downloads and wraps
// without a seam, a long run is cancelled, a non-square image is cropped with a
// message. Leaves a screenshot in out/seamless.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { openPlayground, patchEnergy } from './harness.mjs';
import { decodeImage, encodePng } from '../../pkg/node/index.js';
import { lineArt } from '../node/line-art.mjs';

let page, close;

before(async () => {
  ({ page, close } = await openPlayground({ tab: 'seamless' }));
  await page.waitForFunction(() => document.querySelector('#seam-source').width === 128);
});

after(async () => close?.());

/** Wrap-around difference over neighbouring-pixel difference (about 1: no seam). */
function seam(img) {
  const { width: w, height: h, data } = img;
  const d = (i, j) => Math.abs(data[i] - data[j]) + Math.abs(data[i + 1] - data[j + 1]) + Math.abs(data[i + 2] - data[j + 2]);
  const at = (x, y) => 4 * (y * w + x);
  let inner = 0, n = 0, wrap = 0;
  for (let y = 0; y < h; y++) for (let x = 0; x + 1 < w; x++) { inner += d(at(x, y), at(x + 1, y)); n++; }
  for (let y = 0; y < h; y++) wrap += d(at(w - 1, y), at(0, y));
  return (wrap / h) / (inner / n);
}

async function run() {
  await page.click('#seam-run');
  await page.waitForFunction(() => !document.querySelector('#seam-run').disabled && document.querySelector('#seam-progress').value === 1, null, { timeout: 60000 });
}

test('a new visitor gets toroidal synthesis, the method measured best', async () => {
  assert.equal(await page.inputValue('#seam-method'), 'synthesis');
  assert.equal(await page.isVisible('#seam-refine'), false);
});

test('E-TFMCM tile of the built-in gravel: downloads, wraps without a seam', async () => {
  await page.selectOption('#seam-method', 'etfmcm');
  await run();
  assert.match(await page.textContent('#seam-info'), /128×128, restoration rate \d+\.\d%/);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#seam-download')]);
  assert.match(download.suggestedFilename(), /^seamless-\w+-\d+x\d+\.png$/);
  const img = decodeImage(readFileSync(await download.path()));
  assert.equal(img.width, 128);
  const s = seam(img);
  assert.ok(s < 1.3, `seam ${s}`);
  mkdirSync('out', { recursive: true });
  await page.screenshot({ path: 'out/seamless.png', fullPage: true });
});

test('E-TFMCM refined by default keeps the bricks whole; unticked, the paper\'s tile', async () => {
  await page.selectOption('#seam-texture', 'brick');
  await page.waitForFunction(() => document.querySelector('#seam-source').width === 128);
  await page.selectOption('#seam-method', 'etfmcm');
  assert.equal(await page.isChecked('#seam-refine'), true);
  const tile = async () => {
    await run();
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#seam-download')]);
    return decodeImage(readFileSync(await download.path()));
  };
  const refined = await tile();
  await page.uncheck('#seam-refine');
  const paper = await tile();
  const brick = decodeImage(readFileSync('tests/fixtures/textures/brick.png'));
  const all = [0, 128];
  const [er, ep] = [patchEnergy(refined, brick, all), patchEnergy(paper, brick, all)];
  assert.ok(er < 0.8 * ep, `patch energy refined ${er} against the paper's ${ep}`);
  assert.ok(seam(refined) < 1.3, `seam ${seam(refined)}`);
  await page.check('#seam-refine');
  await page.selectOption('#seam-method', 'synthesis');
  assert.equal(await page.isVisible('#seam-refine'), false, 'synthesis has nothing to refine');
  await page.selectOption('#seam-method', 'etfmcm');
  await page.selectOption('#seam-texture', 'gravel');
  await page.waitForFunction(() => document.querySelector('#seam-source').width === 128);
});

test('toroidal synthesis at 64 also wraps', async () => {
  await page.selectOption('#seam-method', 'synthesis');
  await page.selectOption('#seam-size', '64');
  await run();
  assert.match(await page.textContent('#seam-info'), /^64×64/);
  // At the image's own scale: a 64 tile of the 128 photograph is not the photograph scaled.
  assert.doesNotMatch(await page.textContent('#seam-messages'), /Scaled/);
});

test('toroidal synthesis makes a tile of any width and height, previewed repeated', async () => {
  await page.selectOption('#seam-method', 'etfmcm');
  await page.selectOption('#seam-size', 'custom');
  assert.equal(await page.isVisible('#seam-width'), true);
  await page.fill('#seam-width', '150');
  await page.fill('#seam-height', '90');
  await page.click('#seam-run');
  await page.waitForFunction(() => /toroidal synthesis/.test(document.querySelector('#seam-messages').textContent));
  await page.selectOption('#seam-method', 'synthesis');
  await run();
  assert.match(await page.textContent('#seam-info'), /^150×90/);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#seam-download')]);
  assert.equal(download.suggestedFilename(), 'seamless-synthesis-150x90.png');
  assert.equal(await page.isVisible('#seam-t0'), false, 'T0 is E-TFMCM\'s');
  const img = decodeImage(readFileSync(await download.path()));
  assert.deepEqual([img.width, img.height], [150, 90]);
  const s = seam(img);
  assert.ok(s < 1.3, `seam ${s}`);
  await page.screenshot({ path: 'out/seamless-any-size.png', fullPage: true });
  await page.selectOption('#seam-size', '');
  assert.equal(await page.isVisible('#seam-width'), false);
});

test('a long run can be cancelled', async () => {
  await page.selectOption('#seam-size', '512');
  await page.click('#seam-run');
  await page.waitForFunction(() => document.querySelector('#seam-progress').value > 0.01, null, { timeout: 30000 });
  await page.click('#seam-cancel');
  await page.waitForFunction(() => document.querySelector('#seam-messages').textContent === 'Cancelled.');
  assert.equal(await page.isDisabled('#seam-run'), false);
  await page.selectOption('#seam-size', '');
});

test('a 2048 x 2048 photograph is scaled to fit with a message, and its tile is made', async () => {
  const side = 2048;
  const data = new Uint8ClampedArray(side * side * 4);
  for (let y = 0; y < side; y++) for (let x = 0; x < side; x++) {
    const v = 128 + 60 * Math.sin(x / 13) * Math.cos(y / 17) + 30 * Math.sin((x + 2 * y) / 5);
    data.set([v, 0.8 * v, 0.6 * v, 255], 4 * (y * side + x));
  }
  const png = Buffer.from(encodePng({ width: side, height: side, data }));
  await page.setInputFiles('#seam-file', { name: 'large.png', mimeType: 'image/png', buffer: png });
  await page.waitForFunction(() => document.querySelector('#seam-source').width === 1024, null, { timeout: 60000 });
  assert.match(await page.textContent('#seam-messages'), /large\.png: scaled from 2048×2048 to 1024×1024 \(textures are capped at 1024 px/);
  await page.selectOption('#seam-method', 'etfmcm');
  await page.selectOption('#seam-size', '128');
  await run();
  assert.match(await page.textContent('#seam-info'), /^128×128/);
  await page.selectOption('#seam-size', '');
});

test('line art on a transparent ground gives a tile on a transparent ground', async () => {
  const png = Buffer.from(encodePng(lineArt(128, 14, 3)));
  await page.setInputFiles('#seam-file', { name: 'rings.png', mimeType: 'image/png', buffer: png });
  await page.waitForFunction(() => document.querySelector('#seam-source').width === 128);
  await page.selectOption('#seam-method', 'synthesis');
  await run();
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#seam-download')]);
  const tile = decodeImage(readFileSync(await download.path()));
  let clear = 0, inked = 0;
  for (let i = 3; i < tile.data.length; i += 4) { clear += tile.data[i] === 0; inked += tile.data[i] >= 128; }
  const n = tile.width * tile.height;
  // Before, the tile came back opaque, its ground black.
  assert.ok(clear / n > 0.75, `clear ${clear / n}`);
  assert.ok(inked / n > 0.02, `inked ${inked / n}`);
  mkdirSync('out', { recursive: true });
  await page.screenshot({ path: 'out/seamless-clear.png', fullPage: true });
  // The preview shows the clear ground as a checker, as image editors do.
  const checker = await page.evaluate(() => getComputedStyle(document.querySelector('#seam-view')).backgroundImage);
  assert.match(checker, /conic-gradient/);
  await page.locator('#seam-view').screenshot({ path: 'out/seamless-clear-tile.png' });
});

test('a non-square image is cropped with a message; not an image is refused', async () => {
  const data = new Uint8ClampedArray(90 * 40 * 4);
  for (let i = 0; i < 90 * 40; i++) data.set([(i * 37) % 256, (i * 11) % 256, 90, 255], 4 * i);
  const png = Buffer.from(encodePng({ width: 90, height: 40, data }));
  await page.setInputFiles('#seam-file', { name: 'wide.png', mimeType: 'image/png', buffer: png });
  await page.waitForFunction(() => document.querySelector('#seam-source').width === 90);
  await page.selectOption('#seam-method', 'etfmcm');
  await run();
  assert.match(await page.textContent('#seam-messages'), /Cropped the 90x40 image to its centre 40x40/);
  assert.match(await page.textContent('#seam-info'), /^32×32/);
  await page.setInputFiles('#seam-file', { name: 'notes.png', mimeType: 'image/png', buffer: Buffer.from('hello') });
  await page.waitForFunction(() => /not an image/.test(document.querySelector('#seam-messages').textContent));
});
