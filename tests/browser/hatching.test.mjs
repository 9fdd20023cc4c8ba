// Hatching drawn with the mouse as a hand draws it (issue 27, "draw four or five
// hatching strokes"): five lines side by side, spaced by eye, one drawn the other way
// and two run past their end. Ghosts go on by the spacing across the lines; Tab accepts
// them, each a line about a gap on from the last and parallel to it; undo takes them
// back; with both ghosts taken, the status says the hatching goes on from the next line
// drawn. Screenshots: out/hatching-ghosts.png, out/hatching-accepted.png.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { acceptWithTab, drawPolyline, openEmptyCanvas, settled, strokeCount } from './harness.mjs';

/** The lines' direction (70 degrees down from the x axis) and the normal across them. */
const DIR = [Math.cos((70 * Math.PI) / 180), Math.sin((70 * Math.PI) / 180)];
const ACROSS = [DIR[1], -DIR[0]];
const GAP = 30;

/** Line `k`: begun on a baseline `GAP` apart across the lines (off by `off` across),
 *  `len` long, drawn backwards where `back`. */
function line(k, off, len, back) {
  const start = [200 + (k * GAP + off) * ACROSS[0], 150 + (k * GAP + off) * ACROSS[1]];
  const pts = Array.from({ length: 7 }, (_, i) => [start[0] + (len * i * DIR[0]) / 6, start[1] + (len * i * DIR[1]) / 6]);
  return back ? pts.reverse() : pts;
}

const mid = (pts) => [(pts[0][0] + pts.at(-1)[0]) / 2, (pts[0][1] + pts.at(-1)[1]) / 2];
const across = (p) => p[0] * ACROSS[0] + p[1] * ACROSS[1];

test('hatching drawn by hand with the mouse: ghosts go on at its spacing, Tab accepts, undo takes them back', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openEmptyCanvas({ height: 1000 });
  try {
    const drawn = [line(0, 0, 160, false), line(1, 2, 160, true), line(2, -1.5, 190, false), line(3, 1, 160, false), line(4, -1, 185, false)];
    for (const l of drawn) await drawPolyline(page, l);
    await settled(page);
    const status = await page.textContent('#suggest-status');
    assert.match(status, /^[1-9]\d* suggested stroke/, status);
    await page.screenshot({ path: 'out/hatching-ghosts.png' });
    await acceptWithTab(page);
    await settled(page);
    await page.screenshot({ path: 'out/hatching-accepted.png' });
    const strokes = await page.evaluate(() => window.playground.drawing().strokes.map((s) => s.points));
    const ghosts = strokes.slice(drawn.length);
    assert.ok(ghosts.length >= 1 && ghosts.length <= 3, `${ghosts.length} lines accepted`);
    // Each accepted line a gap on from the one before it across the lines (within 0.3
    // of the gap), parallel to them (within 5 degrees), and about as long.
    let last = across(mid(strokes[drawn.length - 1]));
    for (const g of ghosts) {
      const gap = across(mid(g)) - last;
      assert.ok(Math.abs(gap - GAP) < 0.3 * GAP, `a ghost ${gap.toFixed(1)} on from the line before`);
      const d = [g.at(-1)[0] - g[0][0], g.at(-1)[1] - g[0][1]];
      const len = Math.hypot(...d);
      const sin = Math.abs(d[0] * DIR[1] - d[1] * DIR[0]) / len;
      assert.ok(sin < Math.sin((5 * Math.PI) / 180), `a ghost turned ${((Math.asin(sin) * 180) / Math.PI).toFixed(1)} degrees`);
      assert.ok(len > 140 && len < 200, `a ghost ${len.toFixed(0)} long`);
      last = across(mid(g));
    }
    // Both ghosts taken, the hatching waits for the hand, and says so.
    if (ghosts.length === 2) {
      const waiting = await page.textContent('#suggest-status');
      assert.match(waiting, /hatching goes on from the lines you draw/, waiting);
    }
    await page.click('#undo');
    assert.equal(await strokeCount(page), drawn.length, 'undo takes the accepted lines back');
  } finally {
    await close();
  }
});
