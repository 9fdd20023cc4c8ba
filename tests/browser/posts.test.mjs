// Fence posts along an arc, drawn with the mouse (issue 27: "a row of fence posts along
// an arc: autocomplete proposes nothing, or a straight row off the curve"): six
// upright posts, each a little off its place, along an arc bowing up. The ghosts go on
// round the arc, upright; Tab accepts them; undo takes them back. Screenshot:
// out/posts-ghosts.png.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { acceptWithTab, drawPolyline, openEmptyCanvas, settled, strokeCount } from './harness.mjs';

const R = 220;
const STEP = 42;
const CENTRE = [400, 140 + R];
/** The foot of post `k` on the arc (post 3 at its top). */
const foot = (k) => {
  const phi = -Math.PI / 2 + ((k - 3) * STEP) / R;
  return [CENTRE[0] + R * Math.cos(phi), CENTRE[1] + R * Math.sin(phi)];
};
/** Post `k`, 45 tall, its foot off by `dx`, `dy`. */
const post = (k, dx = 0, dy = 0) => {
  const [x, y] = foot(k);
  return Array.from({ length: 5 }, (_, i) => [x + dx, y + dy - (45 * i) / 4]);
};

test('fence posts drawn along an arc: ghosts go on round it, upright; Tab accepts, undo takes them back', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openEmptyCanvas({ height: 1000 });
  try {
    const offs = [[0, 0], [1, -1], [-1, 1], [1, 1], [-1, 0], [1, -1]];
    for (let k = 0; k < offs.length; k++) await drawPolyline(page, post(k, ...offs[k]));
    await settled(page);
    const status = await page.textContent('#suggest-status');
    assert.match(status, /^[1-9]\d* suggested stroke/, status);
    await page.screenshot({ path: 'out/posts-ghosts.png' });
    await acceptWithTab(page);
    const strokes = await page.evaluate(() => window.playground.drawing().strokes.map((s) => s.points));
    const ghosts = strokes.slice(offs.length);
    assert.ok(ghosts.length >= 1, 'a ghost accepted');
    // Each accepted post at the next foot on the arc (within 0.3 of the step), upright
    // (within 6 degrees), not on the straight row through the last two.
    ghosts.forEach((g, j) => {
      const bottom = g.reduce((a, p) => (p[1] > a[1] ? p : a));
      const top = g.reduce((a, p) => (p[1] < a[1] ? p : a));
      const want = foot(offs.length + j);
      const off = Math.hypot(bottom[0] - want[0], bottom[1] - want[1]);
      assert.ok(off < 0.3 * STEP, `ghost ${j} ${off.toFixed(1)} off its foot on the arc`);
      const lean = Math.abs(Math.atan2(top[0] - bottom[0], bottom[1] - top[1]) * 180 / Math.PI);
      assert.ok(lean < 6, `ghost ${j} leans ${lean.toFixed(1)} degrees`);
    });
    await page.click('#undo');
    assert.equal(await strokeCount(page), offs.length, 'undo takes the accepted posts back');
  } finally {
    await close();
  }
});
