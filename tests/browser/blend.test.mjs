// The Blend tab end to end in headless Chromium: built-in photographs load, a blend runs
// in the worker, a long run is cancelled, the PNG downloads and decodes to the right
// size with A's look at the top and B's at the bottom (patch energy), a mask can be
// painted. Leaves a screenshot in out/blend.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { openPlayground, patchEnergy } from './harness.mjs';
import { decodeImage } from '../../pkg/node/index.js';

let page, close;

before(async () => {
  ({ page, close } = await openPlayground({ tab: 'blend' }));
  await page.waitForFunction(() => document.querySelector('#slot-a canvas').width === 128 && document.querySelector('#slot-b canvas').width === 128);
});

after(async () => close?.());

test('a long blend can be cancelled', async () => {
  await page.fill('#blend-width', '1024');
  await page.fill('#blend-height', '1024');
  await page.click('#blend-run');
  await page.waitForFunction(() => document.querySelector('#blend-progress').value > 0.01, null, { timeout: 60000 });
  await page.click('#blend-cancel');
  await page.waitForFunction(() => document.querySelector('#blend-messages').textContent === 'Cancelled.');
  assert.equal(await page.isDisabled('#blend-run'), false);
});

test('blend wood into gravel, download the PNG, A on top and B below', async () => {
  await page.fill('#blend-width', '128');
  await page.fill('#blend-height', '128');
  await page.click('#blend-run');
  await page.waitForFunction(() => document.querySelector('#blend-messages').textContent === 'Done.', null, { timeout: 60000 });
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#blend-download')]);
  assert.match(download.suggestedFilename(), /^(blend|texture)-\d+x\d+\.png$/);
  const out = decodeImage(readFileSync(await download.path()));
  assert.equal(out.width, 128);
  assert.equal(out.height, 128);
  const a = decodeImage(readFileSync('tests/fixtures/textures/wood.png'));
  const b = decodeImage(readFileSync('tests/fixtures/textures/gravel.png'));
  const top = [0, 20], bottom = [108, 128];
  const [ta, tb, ba, bb] = [patchEnergy(out, a, top), patchEnergy(out, b, top), patchEnergy(out, a, bottom), patchEnergy(out, b, bottom)];
  console.log({ ta, tb, ba, bb });
  assert.ok(ta < 0.7 * tb, `top resembles A: ${ta} vs ${tb}`);
  assert.ok(bb < 0.7 * ba, `bottom resembles B: ${bb} vs ${ba}`);
  mkdirSync('out', { recursive: true });
  await page.screenshot({ path: 'out/blend.png', fullPage: true });
});

test('painting on the coefficient switches to a mask, and single-exemplar mode runs', async () => {
  const box = await page.locator('#blend-mask').boundingBox();
  await page.mouse.move(box.x + 40, box.y + 200);
  await page.mouse.down();
  await page.mouse.move(box.x + 200, box.y + 200, { steps: 8 });
  await page.mouse.up();
  assert.equal(await page.inputValue('#blend-transition'), 'mask');
  await page.check('input[name="blend-mode"][value="single"]');
  await page.fill('#blend-width', '96');
  await page.fill('#blend-height', '64');
  await page.click('#blend-run');
  await page.waitForFunction(() => document.querySelector('#blend-messages').textContent === 'Done.', null, { timeout: 60000 });
  assert.match(await page.textContent('#blend-info'), /96×64, single exemplar, \d+ ms$/);
  // Sixteen times the exemplar's area: the page says its features recur that often.
  await page.fill('#blend-width', '512');
  await page.fill('#blend-height', '512');
  await page.click('#blend-run');
  await page.waitForFunction(() => document.querySelector('#blend-info').textContent.startsWith('512×512'), null, { timeout: 60000 });
  const area = await page.evaluate(() => {
    const c = document.querySelector('#slot-a canvas');
    return c.width * c.height;
  });
  const times = Math.round((512 * 512) / area);
  assert.ok(times >= 16, `exemplar of ${area} pixels`);
  assert.match(await page.textContent('#blend-info'), new RegExp(`512×512, single exemplar, \\d+ ms\\. The output is ${times} times the exemplar's area`));
  await page.check('input[name="blend-mode"][value="blend"]');
});

test('a 4096 x 4096 texture: progress throughout, cancel, then made in the workers and downloaded at that size', async () => {
  await page.check('input[name="blend-mode"][value="single"]');
  await page.fill('#blend-width', '4096');
  await page.fill('#blend-height', '4096');
  // The progress bar's values as the page shows them, one per frame.
  const watch = () => page.evaluate(() => {
    window.seen = [];
    const bar = document.querySelector('#blend-progress');
    const look = () => { window.seen.push(bar.value); if (window.seen.length < 100000) requestAnimationFrame(look); };
    look();
  });
  await watch();
  await page.click('#blend-run');
  await page.waitForFunction(() => document.querySelector('#blend-progress').value > 0.05, null, { timeout: 120000 });
  await page.click('#blend-cancel');
  await page.waitForFunction(() => document.querySelector('#blend-messages').textContent === 'Cancelled.');
  await watch();
  await page.click('#blend-run');
  await page.waitForFunction(() => document.querySelector('#blend-messages').textContent === 'Done.', null, { timeout: 240000 });
  assert.match(await page.textContent('#blend-info'), /^4096×4096, single exemplar, \d+ ms/);
  const seen = await page.evaluate(() => window.seen);
  const steps = new Set(seen.filter((v) => v > 0 && v < 1).map((v) => v.toFixed(2)));
  assert.ok(steps.size >= 20, `the progress bar moved through ${steps.size} values`);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#blend-download')]);
  const out = decodeImage(readFileSync(await download.path()));
  assert.equal(out.width, 4096);
  assert.equal(out.height, 4096);
  // Not one colour: the texture's spread of grey levels spans most of the exemplar's.
  let lo = 255, hi = 0;
  for (let i = 0; i < out.data.length; i += 4 * 997) { lo = Math.min(lo, out.data[i]); hi = Math.max(hi, out.data[i]); }
  assert.ok(hi - lo > 60, `red from ${lo} to ${hi}`);
  await page.fill('#blend-width', '128');
  await page.fill('#blend-height', '128');
  await page.check('input[name="blend-mode"][value="blend"]');
});

test('a 2048 x 2048 photograph is scaled to the cap with a message, and a blend from it runs', async () => {
  // Smooth noise (a photograph's scale of detail), encoded by the package itself.
  const side = 2048;
  const data = new Uint8ClampedArray(side * side * 4);
  for (let y = 0; y < side; y++) for (let x = 0; x < side; x++) {
    const v = 128 + 60 * Math.sin(x / 13) * Math.cos(y / 17) + 30 * Math.sin((x + 2 * y) / 5);
    data.set([v, 0.8 * v, 0.6 * v, 255], 4 * (y * side + x));
  }
  const { encodePng } = await import('../../pkg/node/index.js');
  const png = Buffer.from(encodePng({ width: side, height: side, data }));
  await page.setInputFiles('#slot-a input[type=file]', { name: 'large.png', mimeType: 'image/png', buffer: png });
  await page.waitForFunction(() => document.querySelector('#slot-a canvas').width === 512, null, { timeout: 60000 });
  assert.match(await page.textContent('#blend-messages'), /large\.png: scaled from 2048×2048 to 512×512/);
  await page.fill('#blend-width', '128');
  await page.fill('#blend-height', '128');
  await page.click('#blend-run');
  await page.waitForFunction(() => document.querySelector('#blend-messages').textContent === 'Done.', null, { timeout: 60000 });
  await page.selectOption('#slot-a select', 'wood');
  await page.waitForFunction(() => document.querySelector('#slot-a canvas').width === 128);
});

test('a file that is not an image gets a clear message', async () => {
  await page.setInputFiles('#slot-a input[type=file]', { name: 'notes.png', mimeType: 'image/png', buffer: Buffer.from('hello') });
  await page.waitForFunction(() => /not an image/.test(document.querySelector('#blend-messages').textContent));
});

test('an opened texture and the painted mask survive a reload', async () => {
  // A 40x30 PNG made by the package itself: two colour halves.
  const data = new Uint8ClampedArray(40 * 30 * 4);
  for (let i = 0; i < 40 * 30; i++) data.set(i % 40 < 20 ? [200, 40, 40, 255] : [40, 40, 200, 255], 4 * i);
  const { encodePng } = await import('../../pkg/node/index.js');
  const png = Buffer.from(encodePng({ width: 40, height: 30, data }));
  await page.setInputFiles('#slot-b input[type=file]', { name: 'halves.png', mimeType: 'image/png', buffer: png });
  await page.waitForFunction(() => document.querySelector('#slot-b canvas').width === 40);
  // The page says it loaded the file once the file is kept (IndexedDB is asynchronous).
  await page.waitForFunction(() => /Loaded halves\.png as texture B/.test(document.querySelector('#blend-messages').textContent));
  await page.reload();
  await page.click('[data-tab="blend"]');
  await page.waitForFunction(() => document.querySelector('#slot-b canvas').width === 40 && document.querySelector('#slot-a canvas').width === 128);
  const [left, right] = await page.evaluate(() => {
    const ctx = document.querySelector('#slot-b canvas').getContext('2d');
    return [[...ctx.getImageData(5, 15, 1, 1).data], [...ctx.getImageData(35, 15, 1, 1).data]];
  });
  assert.deepEqual(left.slice(0, 3), [200, 40, 40]);
  assert.deepEqual(right.slice(0, 3), [40, 40, 200]);
  assert.equal(await page.inputValue('#blend-transition'), 'mask');
  // Picking a built-in again forgets the kept file.
  await page.selectOption('#slot-b select', 'grass');
  await page.waitForFunction(() => document.querySelector('#slot-b canvas').width === 128);
  await page.waitForFunction(async () => (await (await import('./shared/store.js')).get('patternsynth.blend.exemplar.v1.b')) === undefined);
});
