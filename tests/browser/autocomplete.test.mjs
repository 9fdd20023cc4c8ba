// Autocomplete on the Vector strokes canvas, in headless Chromium with pointer events:
// a motif drawn three times brings ghosts of the next copies; Tab, a tap on a ghost or
// the button accepts them as one undo step; Escape and a contradicting stroke dismiss
// them; "Fill the canvas" adds the whole field. Leaves screenshots in out/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { openPlayground } from './harness.mjs';

let page, close, box;
const SPACING = 70; // canvas units between copies of the motif

before(async () => {
  ({ page, close } = await openPlayground({ height: 900 }));
  await page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
  box = await page.locator('#draw').boundingBox();
  mkdirSync('out', { recursive: true });
});

after(async () => close?.());

/** Drags along canvas points (800 x 500 logical units). */
async function drag(points) {
  const at = ([x, y]) => [box.x + (x * box.width) / 800, box.y + (y * box.height) / 500];
  await page.mouse.move(...at(points[0]));
  await page.mouse.down();
  for (const p of points.slice(1)) await page.mouse.move(...at(p), { steps: 3 });
  await page.mouse.up();
}

/** A cross (two strokes) at `(x, y)`, with a little hand-drawn wobble. */
async function cross(x, y, k = 0) {
  const j = [0.8, -0.6, 0.4, -1][k % 4];
  await drag([[x - 15, y - 15 + j], [x, y + j / 2], [x + 15, y + 15]]);
  await drag([[x + 15 + j, y - 15], [x, y], [x - 15, y + 15 - j]]);
}

const count = async () => Number((await page.textContent('#stroke-count')).split(' ')[0]);
const strokes = () => page.evaluate(() => window.playground.drawing().strokes);
/** Waits until the suggestion for the drawing as it is now has arrived. */
const settled = () => page.waitForFunction(() => document.querySelector('#suggest-status').getAttribute('aria-busy') === 'false', null, { timeout: 15000 });
const waitGhosts = () => page.waitForFunction(() => !document.querySelector('#accept-ghosts').disabled, null, { timeout: 15000 });
const centre = (s) => {
  const xs = s.points.map((p) => p[0]), ys = s.points.map((p) => p[1]);
  return [(Math.min(...xs) + Math.max(...xs)) / 2, (Math.min(...ys) + Math.max(...ys)) / 2];
};

test('three crosses in a row bring ghosts of the next ones; Tab accepts them as one undo step', async () => {
  await page.click('#clear');
  await cross(100, 120, 0);
  await cross(100 + SPACING, 120, 1);
  // (Two copies may already bring ghosts; whether they arrive before the next stroke is
  // a race, so the test asks only after the third copy, once its answer has settled.)
  await cross(100 + 2 * SPACING, 120, 2);
  await settled();
  await waitGhosts();
  const status = await page.textContent('#suggest-status');
  const shown = Number(status.match(/^(\d+) suggested/)[1]);
  assert.equal(shown, 6, status); // the next three crosses, two strokes each
  await page.screenshot({ path: 'out/autocomplete-ghosts.png', clip: { x: box.x, y: box.y, width: box.width, height: box.height } });

  await page.keyboard.press('Tab');
  await page.waitForFunction(() => document.querySelector('#stroke-count').textContent === '12 strokes');
  // The accepted copies continue the row: same line, one spacing apart.
  const xs = (await strokes()).map(centre).filter((_, i) => i % 2 === 0);
  xs.forEach(([x, y], i) => {
    assert.ok(Math.abs(x - (100 + i * SPACING)) < 3, `copy ${i} at x ${x}`);
    assert.ok(Math.abs(y - 120) < 3, `copy ${i} at y ${y}`);
  });
  // Focus stayed on the canvas. Accepted copies sit where the fit put them and say
  // nothing new of the periods: three drawn copies leave the copies beyond the accepted
  // ones too uncertain, until one more is drawn by hand.
  assert.equal(await page.evaluate(() => document.activeElement.id), 'draw');
  await settled();
  assert.match(await page.textContent('#suggest-status'), /too uncertain: draw one more/);
  await page.screenshot({ path: 'out/autocomplete-accepted.png', clip: { x: box.x, y: box.y, width: box.width, height: box.height } });

  await page.click('#undo');
  assert.equal(await count(), 6, 'one undo takes all accepted strokes back');
  await page.click('#redo');
  assert.equal(await count(), 12);
  await cross(100 + 6 * SPACING, 120, 3);
  await waitGhosts();
  assert.equal(await count(), 14);
});

test('Escape dismisses the ghosts until the drawing changes; a tap on a ghost accepts', async () => {
  await waitGhosts();
  await page.focus('#draw');
  await page.keyboard.press('Escape');
  assert.equal(await page.isDisabled('#accept-ghosts'), true);
  assert.match(await page.textContent('#suggest-status'), /Dismissed/);
  assert.equal(await count(), 14);
  // Undo and redo bring back the same drawing: still dismissed.
  await page.click('#undo');
  await page.click('#redo');
  await page.waitForTimeout(300);
  assert.equal(await page.isDisabled('#accept-ghosts'), true);
  // Drawing on the next copy by hand brings ghosts again; a tap on one accepts them all
  // (whole crosses, to the canvas's edge).
  await cross(100 + 7 * SPACING, 120, 0);
  await waitGhosts();
  assert.equal(await count(), 16);
  await drag([[100 + 8 * SPACING, 120]]);
  await page.waitForFunction(() => Number(document.querySelector('#stroke-count').textContent.split(' ')[0]) > 16);
  const added = (await count()) - 16;
  assert.ok(added >= 2 && added % 2 === 0, `${added} strokes accepted`);
});

test('a stroke that contradicts the repetition makes the ghosts go away; drawing is never lost', async () => {
  // A fresh row of three crosses brings ghosts.
  await page.click('#clear');
  for (let i = 0; i < 3; i++) await cross(100 + i * SPACING, 120, i);
  await waitGhosts();
  // A long squiggle across the row's line is no copy of the motif.
  await drag([[300, 300], [420, 340], [380, 420], [520, 380], [600, 460]]);
  // Wait for the answer to this drawing, not a status left from the one before.
  await page.waitForFunction(() => {
    const status = document.querySelector('#suggest-status');
    return document.querySelector('#accept-ghosts').disabled && status.getAttribute('aria-busy') === 'false' && status.textContent !== '';
  });
  assert.equal(await count(), 7);
  assert.match(await page.textContent('#suggest-status'), /latest stroke does not repeat|no repetition/i);
  // Strokes drawn in quick succession while suggestions are computed are all kept.
  await page.click('#undo');
  for (let k = 0; k < 3; k++) await drag([[100 + k * 20, 400], [110 + k * 20, 440]]);
  assert.equal(await count(), 9);
});

test('the button accepts, and "Fill the canvas" adds the whole field as one step', async () => {
  await page.click('#clear');
  for (let i = 0; i < 3; i++) await cross(120 + i * SPACING, 100, i);
  for (let i = 0; i < 2; i++) await cross(120 + i * SPACING, 100 + SPACING, i + 1);
  await waitGhosts();
  await page.click('#accept-ghosts');
  await page.waitForFunction(() => Number(document.querySelector('#stroke-count').textContent.split(' ')[0]) > 10);
  const before = await count();
  await page.click('#fill-canvas');
  await page.waitForFunction(() => /Filled the canvas/.test(document.querySelector('#messages').textContent), null, { timeout: 15000 });
  const filled = await count();
  // Crosses every SPACING over an 800 x 500 canvas from (120, 100): 10 x 6 sites fit
  // (those whose centre is on the canvas), two strokes each.
  const cols = Math.floor((800 - 120) / SPACING) + 1 + Math.floor(120 / SPACING);
  const rows = Math.floor((500 - 100) / SPACING) + 1 + Math.floor(100 / SPACING);
  assert.equal(filled, 2 * cols * rows, `${filled} strokes after fill, ${before} before`);
  const centres = (await strokes()).map(centre);
  for (const [x, y] of centres) {
    const ex = (x - 120) / SPACING, ey = (y - 100) / SPACING;
    assert.ok(Math.abs(ex - Math.round(ex)) < 0.06 && Math.abs(ey - Math.round(ey)) < 0.06, `stroke at ${x}, ${y} off the lattice`);
  }
  await page.screenshot({ path: 'out/autocomplete-fill.png', clip: { x: box.x, y: box.y, width: box.width, height: box.height } });
  await page.click('#undo');
  assert.equal(await count(), before);
});

test('once focus has left the canvas, Tab back onto it and Tab again moves on', async () => {
  await page.click('#clear');
  for (let k = 0; k < 3; k++) await cross(100 + k * SPACING, 120, k);
  await settled();
  await waitGhosts();
  await page.keyboard.press('Shift+Tab');
  assert.notEqual(await page.evaluate(() => document.activeElement.id), 'draw');
  await page.keyboard.press('Tab');
  assert.equal(await page.evaluate(() => document.activeElement.id), 'draw');
  // (It accepted the ghosts left from the drawing: 6 strokes became 12.)
  await page.keyboard.press('Tab');
  assert.notEqual(await page.evaluate(() => document.activeElement.id), 'draw');
  assert.equal(await count(), 6);
});
