// A stem drawn with the mouse and three leaves along it (issue 27, "a stem and three
// leaves"): the ghosts follow the drawn stem round its bends, each leaf turned with it;
// Tab accepts them, and "Fill the canvas" adds leaves up to the stem's end, and no
// further. Screenshots:
// out/vine-ghosts.png, out/vine-accepted.png.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { acceptWithTab, drawPolyline, openEmptyCanvas, settled, strokeCount, strokesPast, synthesizeDrawing } from './harness.mjs';

/** The stem: a sine across the 800 x 500 canvas, from x = 60 to 740. */
const stem = (x) => [x, 250 + 60 * Math.sin((x - 400) / 70)];
const STEM = Array.from({ length: 69 }, (_, k) => stem(60 + 10 * k));

/** Points along the stem every `gap` of arc length from x = `from`, each with the
 *  stem's direction there. */
function sites(from, gap, count) {
  const out = [];
  let along = 0;
  for (let x = from; out.length < count && x < 740; x += 0.25) {
    const [p, q] = [stem(x), stem(x + 0.25)];
    if (out.length === 0 || along >= gap) {
      out.push([p, Math.atan2(q[1] - p[1], q[0] - p[0])]);
      along = 0;
    }
    along += Math.hypot(q[0] - p[0], q[1] - p[1]);
  }
  return out;
}

/** A leaf: a loop 40 long from its base `p`, leaning 0.6 off the stem's direction
 *  `phi`, its points wobbling by `wobble` across. */
function leaf([p, phi], wobble, phase) {
  const theta = phi - 0.6;
  return Array.from({ length: 25 }, (_, k) => {
    const t = (k / 24) * 2 * Math.PI;
    const along = 20 * (1 - Math.cos(t)), across = 7 * Math.sin(t) + (((k + phase) % 3) - 1) * wobble;
    return [p[0] + along * Math.cos(theta) - across * Math.sin(theta), p[1] + along * Math.sin(theta) + across * Math.cos(theta)];
  });
}

/** The distance from `p` to the drawn stem. */
function offStem(p) {
  let best = Infinity;
  for (let i = 0; i + 1 < STEM.length; i++) {
    const [a, b] = [STEM[i], STEM[i + 1]];
    const [dx, dy] = [b[0] - a[0], b[1] - a[1]];
    const u = Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)));
    best = Math.min(best, Math.hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dy));
  }
  return best;
}

test('a stem and three leaves drawn with the mouse: ghosts follow the stem to its end, Tab accepts', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openEmptyCanvas({ height: 1000 });
  try {
    await drawPolyline(page, STEM, 2);
    const at = sites(80, 50, 3);
    for (let k = 0; k < 3; k++) await drawPolyline(page, leaf(at[k], 0.6, k), 2);
    await settled(page);
    const status = await page.textContent('#suggest-status');
    assert.match(status, /^[1-9]\d* suggested stroke/, status);
    await page.screenshot({ path: 'out/vine-ghosts.png' });
    // Tab (just after drawing) accepts the ghosts.
    await acceptWithTab(page);
    await settled(page);
    // "Fill the canvas" adds every leaf the stem still carries.
    const accepted = await strokeCount(page);
    await page.click('#fill-canvas');
    await strokesPast(page, accepted);
    await settled(page);
    await page.screenshot({ path: 'out/vine-accepted.png' });
    const leaves = (await page.evaluate(() => window.playground.drawing().strokes.map((s) => s.points))).slice(1);
    // Leaves every 50 along the stem from x = 80 to its end at 740: about 19 (the arc is
    // about 1,000 long); each begins on the stem (the ghosts carry the base with them)
    // and the last before its end.
    assert.ok(leaves.length >= 15, `${leaves.length} leaves`);
    for (const l of leaves) assert.ok(offStem(l[0]) < 6, `a leaf begins ${offStem(l[0]).toFixed(1)} off the stem`);
    const bases = leaves.map((l) => l[0]);
    for (let i = 1; i < bases.length; i++) {
      const d = Math.hypot(bases[i][0] - bases[i - 1][0], bases[i][1] - bases[i - 1][1]);
      assert.ok(d > 30 && d < 52, `leaves ${i - 1} and ${i} are ${d.toFixed(1)} apart`);
    }
    assert.ok(Math.max(...bases.map((b) => b[0])) <= 745, 'no leaf past the stem\'s end');
    await page.click('#undo');
    assert.ok((await strokeCount(page)) < leaves.length + 1, 'undo takes the accepted leaves back');
  } finally {
    await close();
  }
});

/** Draws `pts` (canvas coordinates) with a finger: touch events through the DevTools
 *  protocol, as a phone's screen sends them. */
async function drawWithFinger(page, client, pts) {
  const box = await page.locator('#draw').boundingBox();
  const at = ([x, y]) => ({ x: box.x + (x * box.width) / 800, y: box.y + (y * box.height) / 500 });
  await client.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [at(pts[0])] });
  for (const p of pts.slice(1)) await client.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [at(p)] });
  await client.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}

test('on a phone, leaves round a circle drawn with a finger (begun between two leaves, its end past its start) go on round it; a tap accepts', async () => {
  mkdirSync('out', { recursive: true });
  const { page, close } = await openEmptyCanvas({ width: 390, height: 844, touch: true });
  try {
    const client = await page.context().newCDPSession(page);
    const [cx, cy, r] = [400, 250, 110];
    const on = (t) => [cx + r * Math.cos(t), cy + r * Math.sin(t)];
    // The circle from 100 degrees round to 0.2 rad past where it began.
    const from = (100 * Math.PI) / 180;
    const circle = Array.from({ length: 121 }, (_, k) => on(from + ((2 * Math.PI + 0.2) * k) / 120));
    await drawWithFinger(page, client, circle);
    // Leaves every 30 degrees from 0, each leaning off the circle's direction there.
    const site = (k) => [on((k * Math.PI) / 6), (k * Math.PI) / 6 + Math.PI / 2];
    for (let k = 0; k < 4; k++) await drawWithFinger(page, client, leaf(site(k), 0.6, k));
    await settled(page);
    const status = await page.textContent('#suggest-status');
    assert.match(status, /^[1-9]\d* suggested stroke/, status);
    await page.screenshot({ path: 'out/vine-phone-ghosts.png', fullPage: true });
    // A tap on Accept adds them; they go on round the circle past 100 degrees, where
    // the finger began it, each on the circle.
    const before = await strokeCount(page);
    const accept = await page.locator('#accept-ghosts').boundingBox();
    await page.touchscreen.tap(accept.x + accept.width / 2, accept.y + accept.height / 2);
    await strokesPast(page, before);
    await settled(page);
    await page.screenshot({ path: 'out/vine-phone-accepted.png', fullPage: true });
    const leaves = (await page.evaluate(() => window.playground.drawing().strokes.map((s) => s.points))).slice(5);
    assert.ok(leaves.length >= 2, `${leaves.length} leaves accepted`);
    const angle = (p) => ((Math.atan2(p[1] - cy, p[0] - cx) + 2 * Math.PI) % (2 * Math.PI)) * (180 / Math.PI);
    for (const [k, l] of leaves.entries()) {
      const base = l[0];
      assert.ok(Math.abs(Math.hypot(base[0] - cx, base[1] - cy) - r) < 6, `leaf ${k} begins off the circle`);
      assert.ok(Math.abs(angle(base) - 30 * (4 + k)) < 6, `leaf ${k} at ${angle(base).toFixed(0)} degrees, not ${30 * (4 + k)}`);
    }
  } finally {
    await close();
  }
});

/** A wave across the canvas with no stem drawn, and leaves every `gap` along it. */
const wave = (x) => [x, 250 + 50 * Math.sin((x - 400) / 64)];
function waveSites(from, gap, count) {
  const out = [];
  let along = 0;
  for (let x = from; out.length < count; x += 0.25) {
    const [p, q] = [wave(x), wave(x + 0.25)];
    if (out.length === 0 || along >= gap) {
      out.push([p, Math.atan2(q[1] - p[1], q[0] - p[0])]);
      along = 0;
    }
    along += Math.hypot(q[0] - p[0], q[1] - p[1]);
  }
  return out;
}

test('leaves drawn along a wave with no stem, and a stem with three leaves on alternate sides, synthesize along their curves', async () => {
  mkdirSync('out', { recursive: true });
  const synthesize = async (page) => {
    const { messages, info } = await synthesizeDrawing(page);
    assert.equal(messages, 'Done.');
    return info;
  };
  {
    // Six leaves up a wave and over its crest, by hand (each with its own wobble).
    const { page, close } = await openEmptyCanvas({ height: 1000 });
    try {
      for (const [k, site] of waveSites(250, 45, 6).entries()) await drawPolyline(page, leaf(site, 0.6, k), 2);
      const info = await synthesize(page);
      await page.screenshot({ path: 'out/wave-synthesized.png' });
      // (Grown, they were a scatter of leaves in rows: "irregular".)
      assert.match(info, /continued along its curve/, info);
      assert.ok(Number(info.split(' ')[0]) > 6, info);
      assert.equal(await strokeCount(page), 6, 'the drawing is kept as drawn');
    } finally {
      await close();
    }
  }
  {
    // The stem, then three leaves, each on the other side from the one before.
    const { page, close } = await openEmptyCanvas({ height: 1000 });
    try {
      await drawPolyline(page, STEM, 2);
      const at = sites(80, 50, 3);
      for (let k = 0; k < 3; k++) {
        const [p, phi] = at[k];
        // (The other side: the leaf mirrored across the stem's direction.)
        const pts = leaf([p, phi], 0.6, k).map(([x, y]) => {
          const [dx, dy] = [x - p[0], y - p[1]], [c, s] = [Math.cos(phi), Math.sin(phi)];
          const [u, v] = [dx * c + dy * s, -dx * s + dy * c];
          const w = k % 2 ? -v : v;
          return [p[0] + u * c - w * s, p[1] + u * s + w * c];
        });
        await drawPolyline(page, pts, 2);
      }
      const info = await synthesize(page);
      await page.screenshot({ path: 'out/vine-alternate-synthesized.png' });
      // (The drawing came back as drawn, nothing added.) The stem carries about 19.
      assert.match(info, /continued along its curve/, info);
      assert.ok(Number(info.split(' ')[0]) >= 15, info);
    } finally {
      await close();
    }
  }
});
