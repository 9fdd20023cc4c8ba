// End to end in headless Chromium: draw strokes with pointer events, see classes,
// synthesize in the worker, cancel a long run, download the SVG and check it, reload
// and find the drawing kept. Leaves a screenshot in out/playground.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { openPlayground } from './harness.mjs';
import { parseSvg } from '../../pkg/node/index.js';

let page, close;
const SPACING = 40; // canvas pixels between drawn strokes

before(async () => {
  ({ page, close } = await openPlayground({ height: 900 }));
  await page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
});

after(async () => close?.());

async function drawGrid() {
  await page.click('#clear');
  const box = await page.locator('#draw').boundingBox();
  const sx = box.width / 800, sy = box.height / 500;
  for (let j = 0; j < 4; j++) for (let i = 0; i < 5; i++) {
    const x = 200 + i * SPACING, y = 150 + j * SPACING;
    await page.mouse.move(box.x + x * sx, box.y + y * sy);
    await page.mouse.down();
    for (let k = 1; k <= 6; k++) await page.mouse.move(box.x + (x + 2 * k) * sx, box.y + (y + 2 * k) * sy);
    await page.mouse.up();
  }
}

test('a built-in example is there at once, with the default output size', async () => {
  const text = await page.textContent('#stroke-count');
  assert.match(text, /^[1-9]\d* strokes$/);
  // The pen's width (3) must not stand in for the output's.
  assert.equal(await page.inputValue('#out-width'), '1200');
  assert.equal(await page.inputValue('#out-height'), '800');
  // The examples menu lists the drawings of the static examples file.
  await page.waitForFunction(() => document.querySelectorAll('#examples option').length > 8);
  const names = await page.$$eval('#examples option', (o) => o.map((x) => x.value).filter(Boolean));
  for (const name of ['row', 'grid', 'hexagonal', 'brick', 'classes-by-shape', 'busy-tile']) assert.ok(names.includes(name), `${name} in ${names}`);
});

test('draw, classify, synthesize, download a periodic SVG', async () => {
  await drawGrid();
  assert.equal(await page.textContent('#stroke-count'), '20 strokes');
  // (The legend follows the drawing once its classification comes back from the
  // worker: wait for the one of all 20 strokes, not an earlier one's single chip.)
  await page.waitForFunction(() => document.querySelectorAll('#legend .chip').length === 1 && /class 1: 20/.test(document.querySelector('#legend').textContent)).catch(() => {});
  assert.match(await page.textContent('#legend'), /class 1: 20/);

  await page.fill('#out-width', '600');
  await page.fill('#out-height', '400');
  await page.click('#synthesize');
  await page.waitForFunction(() => document.querySelector('#messages').textContent === 'Done.', null, { timeout: 60000 });
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
  const svg = readFileSync(await download.path(), 'utf8');
  assert.equal(download.suggestedFilename(), 'pattern-600x400.svg');

  // Valid SVG that our own importer reads back, with a plausible element count.
  const strokes = parseSvg(svg);
  const expected = (600 / SPACING) * (400 / SPACING);
  assert.ok(strokes.length > 0.85 * expected && strokes.length < 1.2 * expected, `${strokes.length} vs ~${expected}`);
  assert.match(svg, /viewBox="0 0 600 400"/);
  // Periodic layout: reference points share one phase modulo the drawn spacing.
  const centres = strokes.map((s) => {
    const xs = s.points.map((p) => p[0]), ys = s.points.map((p) => p[1]);
    return [(Math.min(...xs) + Math.max(...xs)) / 2, (Math.min(...ys) + Math.max(...ys)) / 2];
  });
  const box = await page.locator('#draw').boundingBox();
  const period = SPACING * (800 / box.width) * (box.width / 800); // canvas units = CSS pixels here
  for (const axis of [0, 1]) {
    let c = 0, s = 0;
    for (const p of centres) {
      const a = (2 * Math.PI * p[axis]) / period;
      c += Math.cos(a); s += Math.sin(a);
    }
    const coherence = Math.hypot(c, s) / centres.length;
    assert.ok(coherence > 0.97, `axis ${axis}: phase coherence ${coherence}`);
  }
  mkdirSync('out', { recursive: true });
  await page.screenshot({ path: 'out/playground.png', fullPage: true });
});

test('a long run can be cancelled and the next run still works', async () => {
  await page.fill('#out-width', '16000');
  await page.fill('#out-height', '16000');
  await page.click('#synthesize');
  await page.waitForFunction(() => document.querySelector('#progress').value > 0.001, null, { timeout: 30000 });
  await page.click('#cancel');
  await page.waitForFunction(() => document.querySelector('#messages').textContent === 'Cancelled.');
  assert.equal(await page.isDisabled('#synthesize'), false);
  await page.fill('#out-width', '300');
  await page.fill('#out-height', '200');
  await page.click('#synthesize');
  await page.waitForFunction(() => document.querySelector('#messages').textContent === 'Done.', null, { timeout: 60000 });
  assert.match(await page.textContent('#result-info'), /300×200/);
});

test('bad input gets a clear message, not a crash', async () => {
  await page.click('#clear');
  await page.click('#synthesize');
  await page.waitForFunction(() => document.querySelector('#messages .error'));
  assert.match(await page.textContent('#messages'), /no strokes/i);
  await page.click('#undo'); // the cleared drawing comes back
  assert.equal(await page.textContent('#stroke-count'), '20 strokes');
});

test('importing an SVG replaces the drawing and reports dropped text', async () => {
  const svg = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><circle cx="20" cy="20" r="5" fill="red"/><circle cx="40" cy="20" r="5" fill="red"/><text x="5" y="90">hi</text></svg>';
  await page.setInputFiles('#import-svg', { name: 'dots.svg', mimeType: 'image/svg+xml', buffer: Buffer.from(svg) });
  await page.waitForFunction(() => document.querySelector('#stroke-count').textContent === '2 strokes');
  assert.match(await page.textContent('#messages'), /text/);
  await page.click('#undo');
  assert.equal(await page.textContent('#stroke-count'), '20 strokes');
});

test('reloading keeps the drawing, even just after an undo', async () => {
  await page.reload();
  await page.waitForFunction(() => document.querySelector('#stroke-count').textContent === '20 strokes');
  // The undo's write is made as the page goes: without it asked to commit at once, 6-7
  // reloads in 20 found the imported drawing instead.
  const svg = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><circle cx="20" cy="20" r="5"/><circle cx="40" cy="20" r="5"/></svg>';
  for (let i = 0; i < 8; i++) {
    await page.setInputFiles('#import-svg', { name: 'dots.svg', mimeType: 'image/svg+xml', buffer: Buffer.from(svg) });
    await page.waitForFunction(() => document.querySelector('#stroke-count').textContent === '2 strokes');
    await page.click('#undo');
    await page.reload();
    // (Not "0 strokes", the page's text before the drawing is read back: the reload's
    // load event may come first, and the test then failed with the drawing kept.)
    await page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
    assert.equal(await page.textContent('#stroke-count'), '20 strokes', `reload ${i + 1}`);
  }
});

test('a seamless tile of the drawn grid: one period of it, shown 3x3, downloadable', async () => {
  await page.selectOption('#tile-repeats', '2');
  await page.click('#make-tile');
  await page.waitForFunction(() => document.querySelector('#messages').textContent === 'Tile ready.', null, { timeout: 30000 });
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#tile-download')]);
  assert.match(download.suggestedFilename(), /^tile-\d+x\d+\.svg$/);
  const svg = readFileSync(await download.path(), 'utf8');
  const [, w, h] = svg.match(/width="([\d.]+)" height="([\d.]+)"/).map(Number);
  // Two drawn spacings each way, within the hand-drawn jitter of the pointer.
  assert.ok(Math.abs(w - 2 * SPACING) < 0.05 * SPACING && Math.abs(h - 2 * SPACING) < 0.05 * SPACING, `${w} x ${h}`);
  const strokes = parseSvg(svg);
  assert.ok(strokes.length >= 4, `${strokes.length} strokes`);
  assert.match(await page.textContent('#tile-info'), /4 elements/);
  // The preview repeats it: three tiles across.
  const box = await page.locator('#tile-preview').boundingBox();
  const size = await page.evaluate(() => document.querySelector('#tile-preview').style.backgroundSize);
  assert.ok(Math.abs(box.width - 3 * parseFloat(size)) < 2, `${box.width} vs ${size}`);
  await page.locator('#tab-strokes .settings').screenshot({ path: 'out/tile.png' });
});
