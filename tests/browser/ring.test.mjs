// Petals drawn around a centre with the mouse (issue 27): after three, ghosts complete
// the ring at the same turn; Tab accepts them; undo takes them back; synthesized, three
// petals become rosettes of eight; petals drawn as two arcs each are completed whole.
// Two flowers side by side, one whole and one begun, synthesize into both flowers
// whole, repeated together. Pen taps round a centre, five of eight, get the other three,
// and synthesize into rosettes.
// Screenshots: out/ring-ghosts.png, out/ring-accepted.png, out/ring-synthesized.png,
// out/ring-two-arcs.png, out/ring-two-arcs-accepted.png, out/ring-two-flowers.png,
// out/ring-taps.png, out/ring-taps-synthesized.png.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { drawPolyline, openEmptyCanvas, settled, strokeCentre, strokeCount, synthesizeDrawing } from './harness.mjs';

/** Draws a petal with the mouse: a loop `len` long from `centre` (the middle of the
 *  800 x 500 canvas) along `theta`, its points wobbling by `wobble` across; begun `begin`
 *  points of 28 round from its base, and drawn the other way round when `backwards`. */
async function drawPetal(page, theta, wobble, phase = 0, begin = 0, backwards = false, centre = [400, 250], len = 110) {
  const box = await page.locator('#draw').boundingBox();
  const at = (x, y) => [box.x + (x * box.width) / 800, box.y + (y * box.height) / 500];
  const pts = [];
  for (let k = 0; k <= 28; k++) {
    const t = (k / 28) * 2 * Math.PI;
    const along = (len / 2) * (1 - Math.cos(t)), across = (len / 6) * Math.sin(t) + ((k + phase) % 3 - 1) * wobble;
    const [cx, cy] = centre;
    pts.push([cx + along * Math.cos(theta) - across * Math.sin(theta), cy + along * Math.sin(theta) + across * Math.cos(theta)]);
  }
  if (begin || backwards) {
    const loop = pts.slice(0, 28);
    const turned = [...loop.slice(begin), ...loop.slice(0, begin)];
    if (backwards) turned.reverse();
    pts.splice(0, pts.length, ...turned, turned[0]);
  }
  await page.mouse.move(...at(...pts[0]));
  await page.mouse.down();
  for (const p of pts.slice(1)) await page.mouse.move(...at(...p), { steps: 2 });
  await page.mouse.up();
}

/** Draws half a petal with the mouse: an arc from the centre (400, 250) 110 out along
 *  `theta`, bulging `bulge` of that to its left (to its right where negative), its
 *  points wobbling by `wobble`. */
async function drawArc(page, theta, bulge, wobble, phase = 0) {
  const box = await page.locator('#draw').boundingBox();
  const at = (x, y) => [box.x + (x * box.width) / 800, box.y + (y * box.height) / 500];
  const pts = [];
  for (let k = 0; k <= 16; k++) {
    const t = k / 16;
    const along = 110 * t, across = -bulge * 110 * 4 * t * (1 - t) + ((k + phase) % 3 - 1) * wobble;
    pts.push(at(400 + along * Math.cos(theta) - across * Math.sin(theta), 250 + along * Math.sin(theta) + across * Math.cos(theta)));
  }
  await page.mouse.move(...pts[0]);
  await page.mouse.down();
  for (const p of pts.slice(1)) await page.mouse.move(...p, { steps: 2 });
  await page.mouse.up();
}

/** Accepts ghosts (Tab just after drawing, then Enter on the canvas) until none are
 *  left, and checks that eight petals lie on the ring (each centre about 55 units from
 *  (400, 250)). */
async function acceptTheRing(page) {
  let before = await strokeCount(page);
  for (const key of ['Tab', 'Enter', 'Enter', 'Enter']) {
    await page.keyboard.press(key);
    await page.waitForFunction((n) => Number(document.querySelector('#stroke-count').textContent.split(' ')[0]) > n, before);
    before = await strokeCount(page);
    await settled(page);
    if (!/suggested stroke/.test(await page.textContent('#suggest-status'))) break;
  }
  assert.equal(await strokeCount(page), 8, 'the ring of eight is complete');
  const centres = await page.evaluate(() => window.playground.drawing().strokes.map((s) => {
    const xs = s.points.map((p) => p[0]), ys = s.points.map((p) => p[1]);
    return [(Math.min(...xs) + Math.max(...xs)) / 2, (Math.min(...ys) + Math.max(...ys)) / 2];
  }));
  for (const [x, y] of centres) assert.ok(Math.abs(Math.hypot(x - 400, y - 250) - 55) < 8, `${x}, ${y}`);
}

test('three petals drawn around a centre: ghosts complete the ring, Tab accepts, undo takes them back', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openEmptyCanvas({ height: 1000 });
  try {
    const step = (2 * Math.PI) / 8;
    for (let k = 0; k < 3; k++) await drawPetal(page, k * step, 0.6);
    await settled(page);
    const status = await page.textContent('#suggest-status');
    assert.match(status, /^[1-9]\d* suggested stroke/, status);
    await page.screenshot({ path: 'out/ring-ghosts.png' });
    // Tab (the hand is on the canvas after drawing) accepts; then Enter on the canvas,
    // until the ring closes.
    await acceptTheRing(page);
    await page.screenshot({ path: 'out/ring-accepted.png' });
    await page.click('#undo');
    assert.ok((await strokeCount(page)) < 8, 'undo takes the accepted petals back');
  } finally {
    await close();
  }
});

test('petals begun anywhere on their outline, one drawn the other way round, are completed too', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openEmptyCanvas({ height: 1000 });
  try {
    const step = (2 * Math.PI) / 8;
    // Begun at the base, a third of the way round, and near the tip drawn backwards.
    for (const [k, begin, backwards] of [[0, 0, false], [1, 9, false], [2, 17, true]]) await drawPetal(page, k * step, 0.6, k, begin, backwards);
    await settled(page);
    const status = await page.textContent('#suggest-status');
    assert.match(status, /^[1-9]\d* suggested stroke/, status);
    await page.screenshot({ path: 'out/ring-begun-anywhere.png' });
    await acceptTheRing(page);
    await page.screenshot({ path: 'out/ring-begun-anywhere-accepted.png' });
  } finally {
    await close();
  }
});

test('three petals drawn around a centre synthesize into rosettes of eight', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openEmptyCanvas({ height: 1000 });
  try {
    // Three petals of eight, by hand (a little wobble in each).
    for (let k = 0; k < 3; k++) await drawPetal(page, (k * 2 * Math.PI) / 8, 0.6, k);
    const { messages, info } = await synthesizeDrawing(page);
    assert.equal(messages, 'Done.');
    await page.screenshot({ path: 'out/ring-synthesized.png' });
    assert.match(info, /completed as a ring/, info);
    // Several rosettes of eight (those at the edges cut).
    const strokes = Number(info.split(' ')[0]);
    assert.ok(strokes >= 4 * 8, info);
    assert.equal(Number((await page.textContent('#stroke-count')).split(' ')[0]), 3, 'the drawing is kept as drawn');
  } finally {
    await close();
  }
});

test('petals drawn as two arcs each: the ghosts complete the ring petal by petal, both arcs', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openEmptyCanvas({ height: 1000 });
  try {
    // Three petals of eight, each its left arc then its right (a ring of two-stroke
    // motifs got "no repetition" before).
    const step = (2 * Math.PI) / 8;
    for (let k = 0; k < 3; k++) {
      await drawArc(page, k * step, 0.18, 0.6, k);
      await drawArc(page, k * step, -0.18, 0.6, k + 1);
    }
    await settled(page);
    const status = await page.textContent('#suggest-status');
    assert.match(status, /^[1-9]\d* suggested stroke/, status);
    await page.screenshot({ path: 'out/ring-two-arcs.png' });
    let before = await strokeCount(page);
    for (const key of ['Tab', 'Enter', 'Enter', 'Enter', 'Enter']) {
      await page.keyboard.press(key);
      await page.waitForFunction((n) => Number(document.querySelector('#stroke-count').textContent.split(' ')[0]) > n, before);
      before = await strokeCount(page);
      await settled(page);
      if (!/suggested stroke/.test(await page.textContent('#suggest-status'))) break;
    }
    await page.screenshot({ path: 'out/ring-two-arcs-accepted.png' });
    assert.equal(await strokeCount(page), 16, 'eight petals of two arcs');
    assert.match(await page.textContent('#suggest-status'), /complete/);
    // Each petal's two arcs: their middles about 55 out along one of the eight turns,
    // one each side of it.
    const middles = await page.evaluate(() => window.playground.drawing().strokes.map((s) => s.points[Math.floor(s.points.length / 2)]));
    const sides = new Map();
    for (const [x, y] of middles) {
      const r = Math.hypot(x - 400, y - 250), angle = Math.atan2(y - 250, x - 400);
      const k = ((Math.round(angle / step) % 8) + 8) % 8;
      const off = angle - Math.round(angle / step) * step;
      assert.ok(Math.abs(r - 58.5) < 9 && Math.abs(Math.abs(off) - 0.35) < 0.13, `an arc's middle at ${x.toFixed(0)}, ${y.toFixed(0)}`);
      sides.set(`${k}${Math.sign(off)}`, true);
    }
    assert.equal(sides.size, 16, 'both sides of every petal');
  } finally {
    await close();
  }
});

test('two flowers drawn side by side, one of them begun, synthesize into both flowers whole', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openEmptyCanvas({ height: 1000 });
  try {
    // Six petals round (200, 250), then three of eight round (600, 250); no ghost taken.
    for (let k = 0; k < 6; k++) await drawPetal(page, (k * 2 * Math.PI) / 6 + 0.3, 0.6, k, 0, false, [200, 250], 90);
    for (let k = 0; k < 3; k++) await drawPetal(page, (k * 2 * Math.PI) / 8, 0.6, k, 0, false, [600, 250], 90);
    assert.equal(await strokeCount(page), 9);
    const { messages, info } = await synthesizeDrawing(page);
    assert.equal(messages, 'Done.');
    await page.screenshot({ path: 'out/ring-two-flowers.png' });
    assert.match(info, /completed as a ring/, info);
    // Each flower at least three times over the 1200 x 800 output, the second with its
    // eight petals: (6 + 8) x 3 strokes at the least (it was the drawing as it was: 9).
    const strokes = Number(info.split(' ')[0]);
    assert.ok(strokes >= 3 * (6 + 8), info);
    assert.equal(await strokeCount(page), 9, 'the drawing is kept as drawn');
  } finally {
    await close();
  }
});

test('pen taps round a centre: five taps half round get the rest of the ring, and synthesize into rosettes', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openEmptyCanvas({ height: 1000 });
  try {
    // Five taps of a ring of eight, 90 round (400, 250), each a pixel or so off.
    for (let k = 0; k < 5; k++) {
      const t = (k * 2 * Math.PI) / 8;
      const [x, y] = [400 + 90 * Math.cos(t) + (k % 2), 250 + 90 * Math.sin(t) - (k % 3) * 0.5];
      await drawPolyline(page, [[x, y], [x + 1, y + 0.5]], 1);
    }
    await settled(page);
    const status = await page.textContent('#suggest-status');
    assert.match(status, /^[1-3] suggested stroke/, status);
    await page.screenshot({ path: 'out/ring-taps.png' });
    // Tab, then Enter on the canvas, till the ring is whole.
    for (const key of ['Tab', 'Enter', 'Enter']) {
      const before = await strokeCount(page);
      await page.keyboard.press(key);
      await page.waitForFunction((n) => Number(document.querySelector('#stroke-count').textContent.split(' ')[0]) > n, before);
      await settled(page);
      if (!/suggested stroke/.test(await page.textContent('#suggest-status'))) break;
    }
    assert.equal(await strokeCount(page), 8, 'the ring of eight taps is whole');
    assert.match(await page.textContent('#suggest-status'), /ring is complete/);
    const centres = (await page.evaluate(() => window.playground.drawing().strokes)).map(strokeCentre);
    for (const [x, y] of centres) assert.ok(Math.abs(Math.hypot(x - 400, y - 250) - 90) < 8, `${x}, ${y}`);
    const { messages, info } = await synthesizeDrawing(page);
    assert.equal(messages, 'Done.');
    await page.screenshot({ path: 'out/ring-taps-synthesized.png' });
    assert.match(info, /completed as a ring/, info);
    // The preview shows the taps (a lone point strokes nothing on a canvas): inked
    // pixels, about a tap's few for each of the result's strokes.
    const inked = await page.evaluate(() => {
      // (The preview holds a bitmap from the worker: read through a 2D copy.)
      const c = document.querySelector('#preview canvas');
      const copy = document.createElement('canvas');
      [copy.width, copy.height] = [c.width, c.height];
      const ctx = copy.getContext('2d');
      ctx.drawImage(c, 0, 0);
      const px = ctx.getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 0; i < px.length; i += 4) if (px[i + 3] > 0 && px[i] + px[i + 1] + px[i + 2] < 600) n++;
      return n;
    });
    assert.ok(inked >= Number(info.split(' ')[0]), `${inked} inked pixels`);
  } finally {
    await close();
  }
});
