// A layout set by hand (issue 29): one cross drawn once, "hexagonal" picked, the
// spacing dragged by its handle on the canvas, synthesized: every bar of the output
// sits on the hexagonal lattice of that spacing; scaled by half and turned by 30°, on
// that lattice scaled and turned; the tile repeats on it too.
// Screenshots: out/repeat-hexagonal.png, out/repeat-turned.png.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { openEmptyCanvas, strokeCentre } from './harness.mjs';
import { parseSvg } from '../../pkg/node/index.js';


test('a hexagonal layout set and dragged by hand repeats one drawn motif on it', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openEmptyCanvas({ height: 1300 });
  try {
    const box = await page.locator('#draw').boundingBox();
    const at = (x, y) => [box.x + (x * box.width) / 800, box.y + (y * box.height) / 500];
    const drag = async (points) => {
      await page.mouse.move(...at(...points[0]));
      await page.mouse.down();
      for (const p of points.slice(1)) await page.mouse.move(...at(...p), { steps: 3 });
      await page.mouse.up();
    };
    // One cross, by hand (a slight wobble in each bar), centred at (400, 250).
    await drag([[385, 251], [393, 249], [400, 250.5], [408, 250], [415, 249]]);
    await drag([[400.5, 235], [399, 243], [400, 250], [401, 258], [400, 265]]);
    await page.waitForFunction(() => document.querySelector('#stroke-count').textContent.startsWith('2 '));
    // No layout yet: the lattice is not shown, and the spacings are hidden.
    assert.equal(await page.isVisible('#period-across'), false);

    await page.selectOption('#repeat-type', 'hexagonal');
    assert.equal(await page.isVisible('#period-across'), true);
    assert.equal(await page.isVisible('#period-down'), false, 'a hexagonal layout has one spacing');
    await page.fill('#period-across', '60');
    // The handle of the first period sits at the drawing's middle plus (60, 0): drag it
    // to (80, 0).
    const origin = [400, 250];
    await drag([[origin[0] + 60, origin[1]], [origin[0] + 70, origin[1] + 1], [origin[0] + 80, origin[1]]]);
    assert.equal(await page.inputValue('#period-across'), '80');
    assert.equal(await page.textContent('#stroke-count').then((t) => t.split(' ')[0]), '2', 'a drag of a handle draws nothing');
    await page.screenshot({ path: 'out/repeat-hexagonal.png' });

    await page.fill('#out-width', '600');
    await page.fill('#out-height', '400');
    await page.click('#synthesize');
    await page.waitForFunction(() => document.querySelector('#messages').textContent === 'Done.', null, { timeout: 60000 });
    const svg = await page.evaluate(async () => (await fetch(document.querySelector('#download').href)).text());
    const bars = parseSvg(svg).map(strokeCentre);
    // 600 x 400 over cells of 80 x 69.3: about 43 crosses, two bars each (edges cut some).
    assert.ok(bars.length >= 70, `${bars.length} bars`);
    const offLattice = (bars, a, b) => {
      const det = a[0] * b[1] - a[1] * b[0];
      const [x0, y0] = bars[0];
      let worst = 0;
      for (const [x, y] of bars) {
        const [dx, dy] = [x - x0, y - y0];
        const u = (dx * b[1] - dy * b[0]) / det, w = (a[0] * dy - a[1] * dx) / det;
        const [fu, fw] = [u - Math.round(u), w - Math.round(w)];
        worst = Math.max(worst, Math.hypot(fu * a[0] + fw * b[0], fu * a[1] + fw * b[1]));
      }
      return worst;
    };
    const worst = offLattice(bars, [80, 0], [40, 40 * Math.sqrt(3)]);
    assert.ok(worst < 3, `every bar within 3 units of the lattice (worst ${worst.toFixed(2)})`);

    // The result scaled by half and turned by 30°: the same layout, half as large, turned.
    const slide = (id, v) => page.$eval(`#${id}`, (el, v) => { el.value = v; el.dispatchEvent(new Event('input')); }, v);
    await slide('out-scale', 0.5);
    await slide('out-rotate', 30);
    await page.click('#synthesize');
    await page.waitForFunction(() => document.querySelector('#messages').textContent === 'Done.' && !document.querySelector('#synthesize').disabled, null, { timeout: 60000 });
    const turnedSvg = await page.evaluate(async () => (await fetch(document.querySelector('#download').href)).text());
    const turned = parseSvg(turnedSvg).map(strokeCentre);
    // Four times as many copies: about 170 crosses.
    assert.ok(turned.length >= 4 * 70, `${turned.length} bars`);
    const turn = ([x, y]) => [0.5 * (x * Math.cos(Math.PI / 6) - y * Math.sin(Math.PI / 6)), 0.5 * (x * Math.sin(Math.PI / 6) + y * Math.cos(Math.PI / 6))];
    const worstTurned = offLattice(turned, turn([80, 0]), turn([40, 40 * Math.sqrt(3)]));
    assert.ok(worstTurned < 2, `every bar on the turned lattice (worst ${worstTurned.toFixed(2)})`);
    await page.screenshot({ path: 'out/repeat-turned.png' });
    await slide('out-scale', 1);
    await slide('out-rotate', 0);

    // The tile repeats on the same layout: one period across and two rows down, twice
    // each way (the page's default of 2 repeats).
    await page.click('#make-tile');
    await page.waitForFunction(() => /×/.test(document.querySelector('#tile-info').textContent), null, { timeout: 30000 });
    const info = await page.textContent('#tile-info');
    assert.match(info, /^160×277\.1\d? tile/, info);
  } finally {
    await close();
  }
});
