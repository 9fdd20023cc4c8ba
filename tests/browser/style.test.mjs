// Recolouring a vector result without synthesizing it again (issue 29): the default
// example synthesized once, then a palette, one class's colour picked by hand, a
// background and an opacity, each seen in the preview the worker draws, in the SVG
// download and in the PNG download; the worker is never asked to synthesize again.
// Screenshots: out/style-*.png.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { openPlayground } from './harness.mjs';
import { parseSvg } from '../../pkg/node/index.js';

/** Share of the preview's opaque pixels near `hex`, and the colour at its corner. */
const previewColours = (page, hex) => page.evaluate((hex) => {
  const c = document.querySelector('#preview canvas');
  const o = new OffscreenCanvas(c.width, c.height).getContext('2d'); // the canvas is a bitmap renderer's
  o.drawImage(c, 0, 0);
  const px = o.getImageData(0, 0, c.width, c.height).data;
  const [r, g, b] = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
  let painted = 0, near = 0;
  for (let i = 0; i < px.length; i += 4) {
    if (px[i + 3] < 200) continue;
    painted++;
    if (Math.abs(px[i] - r) + Math.abs(px[i + 1] - g) + Math.abs(px[i + 2] - b) < 40) near++;
  }
  return { painted, near: near / Math.max(1, painted), corner: [...px.slice(0, 4)] };
}, hex);

test('a result is recoloured, given a background and an opacity, without a second synthesis', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openPlayground({ height: 1100 });
  try {
    await page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
    // Every call the page makes, by method.
    await page.evaluate(() => {
      window.calls = [];
      const run = window.patternsynth.run.bind(window.patternsynth);
      window.patternsynth.run = (method, ...rest) => { window.calls.push(method); return run(method, ...rest); };
    });
    assert.equal(await page.$eval('#style', (f) => f.disabled), true, 'no colours before a result');
    await page.fill('#out-width', '600');
    await page.fill('#out-height', '400');
    await page.click('#synthesize');
    await page.waitForFunction(() => document.querySelector('#messages').textContent === 'Done.', null, { timeout: 60000 });
    assert.equal(await page.$eval('#style', (f) => f.disabled), false);
    const swatches = await page.$$eval('#class-colors input', (l) => l.map((i) => i.value));
    assert.ok(swatches.length >= 2, `one swatch per class: ${swatches}`);
    const asDrawn = await previewColours(page, '#1f2a44');
    assert.deepEqual(asDrawn.corner.slice(3), [0], 'no background by default (transparent, as the SVG)');
    await page.screenshot({ path: 'out/style-drawn.png' });

    // A palette of one colour: every class inked alike.
    await page.selectOption('#palette', 'ink');
    await page.evaluate(() => window.playground.restyled());
    await page.waitForFunction(() => [...document.querySelectorAll('#class-colors input')].every((i) => i.value === '#1f2a44'));
    await page.waitForTimeout(200);
    await page.evaluate(() => window.playground.restyled());
    const inked = await previewColours(page, '#1f2a44');
    assert.ok(inked.near > 0.9, `inked: ${inked.near.toFixed(2)} of ${inked.painted} painted pixels near the ink`);

    // One class by hand, a background, half opacity.
    await page.$eval('#class-colors input', (i) => { i.value = '#ff0000'; i.dispatchEvent(new Event('input', { bubbles: true })); });
    await page.check('#bg-on');
    await page.$eval('#bg-color', (i) => { i.value = '#ffeecc'; i.dispatchEvent(new Event('input', { bubbles: true })); });
    await page.$eval('#opacity', (i) => { i.value = '0.5'; i.dispatchEvent(new Event('input', { bubbles: true })); });
    await page.waitForTimeout(200);
    await page.evaluate(() => window.playground.restyled());
    const styled = await previewColours(page, '#ffeecc');
    assert.deepEqual(styled.corner, [255, 238, 204, 255], 'the background under the pattern');
    const red = await page.evaluate(() => {
      const c = document.querySelector('#preview canvas');
      const o = new OffscreenCanvas(c.width, c.height).getContext('2d');
      o.drawImage(c, 0, 0);
      const px = o.getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      // Red at half opacity over the cream background: about (255, 119, 102).
      for (let i = 0; i < px.length; i += 4) n += px[i] > 230 && px[i + 1] > 90 && px[i + 1] < 150 && px[i + 2] > 70 && px[i + 2] < 130;
      return n;
    });
    assert.ok(red > 50, `${red} pixels of class 1 in red at half opacity`);
    await page.screenshot({ path: 'out/style-restyled.png' });

    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download')]);
    const svg = readFileSync(await download.path(), 'utf8');
    assert.match(svg, /<rect width="100%" height="100%" fill="#ffeecc"\/>\n<g opacity="0.5">/);
    assert.match(svg, /class="c0"[^>]*stroke="#ff0000"/);
    assert.doesNotMatch(svg, /class="c1"[^>]*(stroke|fill)="#(?!1f2a44)[0-9a-f]{6}"/, 'class 2 inked');
    assert.ok(parseSvg(svg).length > 100, 'the restyled SVG reads back');

    await page.fill('#png-width', '300');
    const [png] = await Promise.all([page.waitForEvent('download'), page.click('#download-png')]);
    const bytes = readFileSync(await png.path());
    assert.equal(bytes.readUInt32BE(16), 300);
    assert.equal(bytes.readUInt32BE(20), 200);

    const calls = await page.evaluate(() => window.calls);
    assert.equal(calls.filter((c) => c === 'synthesizeStrokes').length, 1, `calls: ${calls.join(', ')}`);
    assert.ok(calls.filter((c) => c === 'restyle').length >= 3, `calls: ${calls.join(', ')}`);

    // Reset: the drawn colours, no background, opaque; kept across a reload.
    await page.click('#style-reset');
    await page.waitForTimeout(200);
    await page.evaluate(() => window.playground.restyled());
    assert.deepEqual((await previewColours(page, '#1f2a44')).corner.slice(3), [0]);
  } finally {
    await close();
  }
});

test('the result zooms and pans with the buttons, the keys, Ctrl + wheel and a drag', async () => {
  const { page, close } = await openPlayground({ height: 1100 });
  try {
    await page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
    assert.equal(await page.isDisabled('#zoom-in'), true, 'nothing to zoom before a result');
    await page.click('#synthesize');
    await page.waitForFunction(() => document.querySelector('#messages').textContent === 'Done.', null, { timeout: 60000 });
    const transform = () => page.$eval('#preview canvas', (c) => c.style.transform);
    assert.equal(await transform(), '');
    await page.click('#zoom-in');
    await page.click('#zoom-in');
    assert.equal(await page.textContent('#zoom-level'), '225%');
    assert.match(await transform(), /scale\(2\.25\)/);
    // A drag pans; it cannot leave the picture's edge inside the view.
    const box = await page.locator('#preview').boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 60, box.y + box.height / 2 + 30, { steps: 4 });
    await page.mouse.up();
    const [tx, ty] = (await transform()).match(/translate\(([-\d.]+)px, ([-\d.]+)px\)/).slice(1).map(Number);
    assert.ok(tx <= 0 && ty <= 0 && tx >= box.width * (1 - 2.25) - 1, `translate ${tx}, ${ty}`);
    // Settled, the picture is drawn again at the zoom: sharp, not a stretched bitmap.
    const base = await page.$eval('#preview', (v) => v.clientWidth);
    await page.waitForFunction((base) => document.querySelector('#preview canvas').width >= Math.floor(2.25 * base) - 2, base, { timeout: 10000 }).catch(() => {});
    const drawnWidth = await page.$eval('#preview canvas', (c) => c.width);
    assert.ok(drawnWidth >= 2 * base, `drawn ${drawnWidth} px wide for a ${base} px view at 225%`);
    await page.screenshot({ path: 'out/zoom.png' });
    // A recolour keeps the zoom; the keys: 0 fits, + zooms in, arrows pan.
    await page.selectOption('#palette', 'ocean');
    await page.evaluate(() => new Promise((ok) => setTimeout(ok, 150)).then(() => window.playground.restyled()));
    assert.match(await transform(), /scale\(2\.25\)/);
    await page.focus('#preview');
    await page.keyboard.press('0');
    assert.equal(await transform(), '');
    await page.keyboard.press('+');
    await page.keyboard.press('ArrowLeft');
    assert.match(await transform(), /scale\(1\.5\)/);
    // Ctrl + wheel about the pointer.
    await page.mouse.move(box.x + 20, box.y + 20);
    await page.keyboard.down('Control');
    await page.mouse.wheel(0, -300);
    await page.keyboard.up('Control');
    assert.ok(await page.evaluate(() => window.playground.zoom()) > 1.5);
    await page.click('#zoom-fit');
    assert.equal(await page.textContent('#zoom-level'), '100%');
  } finally {
    await close();
  }
});

test('the tile and its CSS take the colours too', async () => {
  const { page, close } = await openPlayground({ height: 1400 });
  try {
    await page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
    await page.waitForFunction(() => document.querySelectorAll('#legend .chip').length > 1);
    await page.click('#make-tile');
    await page.waitForFunction(() => /Tile ready/.test(document.querySelector('#messages').textContent), null, { timeout: 60000 });
    assert.equal(await page.$eval('#style', (f) => f.disabled), false, 'a tile alone enables the colours');
    assert.ok(await page.$$eval('#class-colors input', (l) => l.length) >= 2, 'swatches from the drawing\'s classes');
    await page.selectOption('#palette', 'sunset');
    await page.check('#bg-on');
    await page.$eval('#bg-color', (i) => { i.value = '#102030'; i.dispatchEvent(new Event('input', { bubbles: true })); });
    const css = await page.inputValue('#tile-css');
    assert.match(css, /%23ff6b35/, 'the first class in the palette\'s first colour');
    assert.match(css, /fill%3D%22%23102030%22/, 'the background in the tile');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#tile-download')]);
    const svg = readFileSync(await download.path(), 'utf8');
    assert.match(svg, /<rect width="100%" height="100%" fill="#102030"\/>/);
    assert.match(svg, /class="c0"[^>]*stroke="#ff6b35"/);
    await page.locator('#tile-preview').screenshot({ path: 'out/style-tile.png' });

    // Scale: the CSS repeats the tile at twice its size; turned: an SVG <pattern> fills
    // the element (a turned lattice has no axis-aligned period).
    const size = (await page.inputValue('#tile-css')).match(/background-size: ([\d.]+)px ([\d.]+)px/).slice(1).map(Number);
    await page.$eval('#tile-scale', (i) => { i.value = '2'; i.dispatchEvent(new Event('input', { bubbles: true })); });
    const doubled = (await page.inputValue('#tile-css')).match(/background-size: ([\d.]+)px ([\d.]+)px/).slice(1).map(Number);
    assert.deepEqual(doubled.map((v, i) => Math.round(v / size[i])), [2, 2]);
    assert.equal(await page.textContent('#tile-scale-out'), '200%');
    await page.$eval('#tile-rotate', (i) => { i.value = '30'; i.dispatchEvent(new Event('input', { bubbles: true })); });
    const turned = decodeURIComponent((await page.inputValue('#tile-css')).match(/url\("data:image\/svg\+xml,(.*)"\)/)[1]);
    assert.match(turned, /<pattern id="tile" patternUnits="userSpaceOnUse" width="[\d.]+" height="[\d.]+" patternTransform="rotate\(30\) scale\(2\)">/);
    assert.match(turned, /<rect width="100%" height="100%" fill="url\(#tile\)"\/><\/svg>$/);
    assert.doesNotMatch(await page.inputValue('#tile-css'), /background-repeat/);
    // The snippet works as CSS: an element with it shows the pattern's colours.
    const painted = await page.evaluate(async (css) => {
      const div = document.createElement('div');
      div.style.cssText = `width: 300px; height: 200px; ${css}`;
      document.body.append(div);
      const url = getComputedStyle(div).backgroundImage.slice(5, -2);
      const img = new Image();
      img.src = url;
      await img.decode();
      const c = new OffscreenCanvas(300, 200).getContext('2d');
      c.drawImage(img, 0, 0, 300, 200);
      const px = c.getImageData(0, 0, 300, 200).data;
      let orange = 0;
      for (let i = 0; i < px.length; i += 4) orange += px[i] > 200 && px[i + 1] > 80 && px[i + 1] < 140 && px[i + 2] < 90;
      div.remove();
      return orange;
    }, await page.inputValue('#tile-css'));
    assert.ok(painted > 100, `${painted} pixels of the first class's colour drawn from the turned pattern`);
    await page.locator('#tile-preview').screenshot({ path: 'out/style-tile-turned.png' });
  } finally {
    await close();
  }
});
