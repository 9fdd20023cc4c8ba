// The playground served from www/ on a free port, in headless Chromium with downloads
// on; page errors are printed. `close()` stops both.
import { chromium } from 'playwright-core';
import { CHROMIUM } from './chromium.mjs';
import { serve } from '../../scripts/static-server.mjs';

export async function openPlayground({ width = 1400, height = 1000, tab, touch = false } = {}) {
  const server = await serve('www', 0);
  const browser = await chromium.launch(CHROMIUM);
  const context = await browser.newContext({ acceptDownloads: true, viewport: { width, height }, hasTouch: touch, isMobile: touch });
  const page = await context.newPage();
  page.on('pageerror', (e) => console.error('page error:', e.message));
  const url = `http://127.0.0.1:${server.address().port}/`;
  await page.goto(url);
  if (tab) await page.click(`[data-tab="${tab}"]`);
  return { page, url, close: async () => { await browser.close(); server.close(); } };
}

/** The playground with its example drawing loaded and then cleared: an empty canvas to
 *  draw on (options as `openPlayground`'s). */
export async function openEmptyCanvas(options) {
  const opened = await openPlayground(options);
  try {
    await opened.page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
    await opened.page.click('#clear');
  } catch (e) {
    await opened.close();
    throw e;
  }
  return opened;
}

/** Waits until the autocomplete has answered the latest stroke. */
export const settled = (page) => page.waitForFunction(() => document.querySelector('#suggest-status').getAttribute('aria-busy') === 'false', null, { timeout: 15000 });

/** The strokes on the canvas, as the page counts them. */
export const strokeCount = async (page) => Number((await page.textContent('#stroke-count')).split(' ')[0]);

/** Waits until the page counts more strokes than `n`. */
export const strokesPast = (page, n) => page.waitForFunction((n) => Number(document.querySelector('#stroke-count').textContent.split(' ')[0]) > n, n);

/** Accepts the ghosts with Tab (just after drawing) and waits until they are strokes. */
export async function acceptWithTab(page) {
  const before = await strokeCount(page);
  await page.keyboard.press('Tab');
  await strokesPast(page, before);
}

/** Presses Synthesize and waits for its answer (and, when done, for the preview): the
 *  messages line, and the result's summary (`#result-info`). */
export async function synthesizeDrawing(page) {
  await page.click('#synthesize');
  await page.waitForFunction(() => /^(Done\.|.*error.*)$/i.test(document.querySelector('#messages').textContent) || document.querySelector('#messages .error'), null, { timeout: 120000 });
  const messages = await page.textContent('#messages');
  if (messages === 'Done.') await page.waitForFunction(() => document.querySelector('#preview canvas, #preview img'));
  return { messages, info: await page.textContent('#result-info') };
}

/** The centre of a stroke's bounding box (strokes as the package's JSON: `points`). */
export const strokeCentre = (s) => {
  const xs = s.points.map((p) => p[0]), ys = s.points.map((p) => p[1]);
  return [(Math.min(...xs) + Math.max(...xs)) / 2, (Math.min(...ys) + Math.max(...ys)) / 2];
};

/** Draws the polyline `pts` (in the canvas's 800 x 500 units) with the mouse, `steps`
 *  pointer moves between points. */
export async function drawPolyline(page, pts, steps = 3) {
  const box = await page.locator('#draw').boundingBox();
  const at = (x, y) => [box.x + (x * box.width) / 800, box.y + (y * box.height) / 500];
  await page.mouse.move(...at(...pts[0]));
  await page.mouse.down();
  for (const p of pts.slice(1)) await page.mouse.move(...at(...p), { steps });
  await page.mouse.up();
}

/** RMS over sampled pixels of the best 7x7 match in the exemplar (as the benchmark). */
export function patchEnergy(out, ex, rows, samples = 60) {
  let seed = 7;
  const rand = (n) => { seed = (seed * 1103515245 + 12345) % 2147483648; return seed % n; };
  const px = (img, x, y) => {
    x = ((x % img.width) + img.width) % img.width; y = ((y % img.height) + img.height) % img.height;
    const i = 4 * (y * img.width + x);
    return [img.data[i], img.data[i + 1], img.data[i + 2]];
  };
  let total = 0;
  for (let s = 0; s < samples; s++) {
    const x = rand(out.width), y = rows[0] + rand(rows[1] - rows[0]);
    const patch = [];
    for (let dy = -3; dy <= 3; dy++) for (let dx = -3; dx <= 3; dx++) patch.push(px(out, x + dx, y + dy));
    let best = Infinity;
    for (let cy = 3; cy < ex.height - 3; cy++) for (let cx = 3; cx < ex.width - 3; cx++) {
      let acc = 0, k = 0;
      for (let dy = -3; dy <= 3 && acc < best; dy++) for (let dx = -3; dx <= 3; dx++) {
        const i = 4 * ((cy + dy) * ex.width + cx + dx), q = patch[k++];
        acc += (ex.data[i] - q[0]) ** 2 + (ex.data[i + 1] - q[1]) ** 2 + (ex.data[i + 2] - q[2]) ** 2;
      }
      best = Math.min(best, acc);
    }
    total += best / 147;
  }
  return Math.sqrt(total / samples);
}
