// Zoom and pan of the texture previews (issue 29): the blend's texture and the seamless
// tile repeated zoom with the buttons and the keyboard (+, −, 0, arrows on the focused
// view), pan once zoomed, stay inside their frame, and fit again with a new result.
// The level is screen pixels per picture pixel (issue 25's trial: a tile shown at twice
// its size read 100%), and 1 (or the 1:1 button) shows the pixels one to one.
// Screenshots: out/zoom-blend.png, out/zoom-seamless.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { openPlayground } from './harness.mjs';

let page, close;
before(async () => {
  mkdirSync('out', { recursive: true });
  ({ page, close } = await openPlayground({ height: 1100 }));
});
after(async () => close?.());

/** The zoomed picture's CSS transform as [scale, x, y] ([1, 0, 0] when fitted). */
const transform = (id) => page.$eval(`#${id}`, (v) => {
  const t = v.firstElementChild.style.transform;
  const m = t.match(/translate\(([-\d.]+)px, ([-\d.]+)px\) scale\(([\d.]+)\)/);
  return m ? [Number(m[3]), Number(m[1]), Number(m[2])] : [1, 0, 0];
});

/** Screen pixels per picture pixel of the fitted picture, measured on the page: the
 *  blend's canvas box over its pixels; the tile's background size (it is drawn as a
 *  background, whatever width its repeat's box has) over the tile's pixels. */
const fittedScale = {
  blend: () => page.$eval('#blend-result', (c) => c.clientWidth / c.width),
  seam: () => page.evaluate(() => parseFloat(getComputedStyle(document.querySelector('#seam-repeat')).backgroundSize) / document.querySelector('#seam-result').width),
};
const level = async (prefix) => Number((await page.textContent(`#${prefix}-zoom-level`)).replace('%', ''));

async function zoomsAndPans(prefix, view) {
  const fit = await fittedScale[prefix]();
  assert.equal(await level(prefix), Math.round(100 * fit), `fitted at ${fit}`);
  await page.click(`#${prefix}-zoom-in`);
  assert.equal((await transform(view))[0], 1.5);
  await page.focus(`#${view}`);
  await page.keyboard.press('+');
  assert.equal(await level(prefix), Math.round(225 * fit));
  const [s, x0, y0] = await transform(view);
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('ArrowUp');
  const [, x1, y1] = await transform(view);
  // (Left and up show what lies left of and above the view: the picture moves right and down.)
  assert.ok(x1 >= x0 && y1 >= y0 && (x1 > x0 || y1 > y0), `panned: ${x0},${y0} -> ${x1},${y1}`);
  // Never past the picture's edge: the frame stays covered.
  const w = await page.$eval(`#${view}`, (v) => v.clientWidth);
  assert.ok(x1 <= 0 && x1 >= w - w * s - 0.5, `${x1} within [${w - w * s}, 0]`);
  await page.screenshot({ path: `out/zoom-${prefix === 'seam' ? 'seamless' : 'blend'}.png` });
  await page.keyboard.press('0');
  assert.deepEqual(await transform(view), [1, 0, 0]);
  // One to one where the fitted picture is smaller; else it stays fitted.
  await page.keyboard.press('1');
  assert.equal(await level(prefix), Math.max(100, Math.round(100 * fit)));
  const one = (await transform(view))[0];
  assert.ok(Math.abs(one - Math.max(1, 1 / fit)) < 1e-4, `zoom ${one} for a picture fitted at ${fit}`);
  await page.keyboard.press('0');
  // The 1:1 button does it for a mouse or a finger, where the picture is fitted smaller
  // than one to one (and is off where it is not, or already one to one).
  const button = `#${prefix}-zoom-actual`;
  if (prefix === 'blend') assert.ok(fit < 1, `a 512 texture fitted at ${fit}`);
  if (fit < 1) {
    await page.click(button);
    assert.equal(await level(prefix), 100);
    assert.ok(await page.$eval(button, (b) => b.disabled), 'off once one to one');
    await page.keyboard.press('0');
  } else assert.ok(await page.$eval(button, (b) => b.disabled), `off for a picture fitted at ${fit}`);
}

test('the blend texture zooms and pans', async () => {
  await page.click('#tab-button-blend');
  await page.waitForFunction(() => document.querySelector('#slot-a canvas').width === 128);
  // (Larger than its box: fitted under one to one, so 1:1 zooms in.)
  await page.fill('#blend-width', '512');
  await page.fill('#blend-height', '512');
  await page.click('#blend-run');
  await page.waitForFunction(() => document.querySelector('#blend-messages').textContent === 'Done.', null, { timeout: 60000 });
  await zoomsAndPans('blend', 'blend-view');
});

test('the seamless tile repeated zooms and pans, and a new tile is fitted again', async () => {
  await page.click('#tab-button-seamless');
  await page.waitForFunction(() => document.querySelector('#seam-source').width > 0);
  await page.click('#seam-run');
  await page.waitForFunction(() => document.querySelector('#seam-repeat').classList.contains('shown'), null, { timeout: 120_000 });
  await zoomsAndPans('seam', 'seam-view');
  await page.click('#seam-zoom-in');
  await page.click('#seam-run');
  await page.waitForFunction(() => !document.querySelector('#seam-run').disabled && document.querySelector('#seam-repeat').classList.contains('shown'), null, { timeout: 120_000 });
  assert.deepEqual(await transform('seam-view'), [1, 0, 0], 'a new tile is shown whole');
});
