// Two tabs of the page at once: they overwrote each other's drawing and settings,
// silently (tab A reloaded showed tab B's one stroke, A's undo history gone). Now the
// second tab says plainly that another tab keeps the work, is read-only (a stroke drawn
// on it is not kept), and can take over; the first tab then says so in turn. A single
// tab reloads as before, never told it is open elsewhere. Leaves screenshots of the
// message in out/tabs-*.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { drawPolyline, openEmptyCanvas, strokeCount, strokesPast } from './harness.mjs';

let a, b, url, close;
before(async () => {
  ({ page: a, url, close } = await openEmptyCanvas());
  mkdirSync('out', { recursive: true });
});
after(async () => close?.());

// (Every drawing here has strokes: "0 strokes" is the page's text before it is read back.)
const counted = (page) => page.waitForFunction(() => /[1-9]\d* strokes?/.test(document.querySelector('#stroke-count').textContent));
const banner = (page) => page.$eval('#elsewhere', (e) => (e.hidden ? null : { role: e.getAttribute('role'), text: e.textContent.trim() }));
/** Opens another tab of the page in the same browser (one profile, one IndexedDB). */
async function openTab(viewport = { width: 1400, height: 1000 }) {
  const page = await a.context().newPage();
  page.on('pageerror', (e) => console.error('page error:', e.message));
  await page.setViewportSize(viewport);
  await page.goto(url);
  await counted(page);
  return page;
}
const stroke = (k) => [[100 + 40 * k, 100], [130 + 40 * k, 200], [100 + 40 * k, 300]];

test('a single tab reloads as before, with its drawing and undo history', async () => {
  await drawPolyline(a, stroke(0));
  await strokesPast(a, 0);
  await a.reload();
  await counted(a);
  assert.equal(await strokeCount(a), 1);
  assert.equal(await banner(a), null, 'no message in a single tab');
  assert.equal(await a.$eval('main', (m) => m.inert), false);
});

test('a second tab is read-only and says so; the first keeps its work and its undo', async () => {
  await drawPolyline(a, stroke(1));
  await strokesPast(a, 1);
  b = await openTab();
  await b.waitForSelector('#elsewhere:not([hidden])', { timeout: 5000 });
  const said = await banner(b);
  assert.equal(said.role, 'alert');
  assert.match(said.text, /open in another tab.*read-only/s);
  assert.equal(await b.$eval('main', (m) => m.inert), true);
  assert.equal(await strokeCount(b), 2, 'the second tab shows the work kept');
  // What the audit did in tab B: clear, draw one stroke (and an undo from the keys).
  // Nothing of it reaches A's work.
  const clear = await b.locator('#clear').boundingBox();
  await b.mouse.click(clear.x + clear.width / 2, clear.y + clear.height / 2);
  await drawPolyline(b, stroke(5));
  await b.keyboard.press('Control+z');
  await b.waitForTimeout(300);
  assert.equal(await strokeCount(b), 2, 'a read-only tab takes no strokes');
  await a.reload();
  await counted(a);
  assert.equal(await strokeCount(a), 2, "tab A has its own drawing after a reload, not tab B's");
  assert.equal(await banner(a), null);
  await a.click('#undo');
  assert.equal(await strokeCount(a), 1, "tab A's undo history is there");
  await a.click('#redo');
  assert.equal(await strokeCount(a), 2);
  await b.screenshot({ path: 'out/tabs-read-only.png' });
});

test('the second tab takes over with the latest work; the first becomes read-only and says so', async () => {
  await drawPolyline(a, stroke(2));
  await strokesPast(a, 2);
  await Promise.all([b.waitForEvent('load'), b.click('#take-over')]);
  await counted(b);
  assert.equal(await banner(b), null, 'the tab taken over is not read-only');
  assert.equal(await strokeCount(b), 3, "it starts from the first tab's latest work");
  await a.waitForSelector('#elsewhere:not([hidden])', { timeout: 5000 });
  assert.match((await banner(a)).text, /another tab.*read-only/s);
  assert.equal(await a.$eval('main', (m) => m.inert), true);
  await a.screenshot({ path: 'out/tabs-taken-over.png' });
  await drawPolyline(b, stroke(3));
  await strokesPast(b, 3);
  // The first tab, read-only now, writes nothing even from its own code.
  await a.evaluate(() => window.playground.drawing && document.querySelector('#clear').click());
  await b.reload();
  await counted(b);
  assert.equal(await strokeCount(b), 4);
  await b.click('#undo');
  assert.equal(await strokeCount(b), 3);
  // At a phone's width, the message and its button fit.
  const phone = await openTab({ width: 390, height: 844 });
  await phone.waitForSelector('#elsewhere:not([hidden])', { timeout: 5000 });
  const box = await phone.locator('#take-over').boundingBox();
  assert.ok(box.x >= 0 && box.x + box.width <= 390 && box.height >= 24, `the button fits: ${JSON.stringify(box)}`);
  await phone.screenshot({ path: 'out/tabs-phone.png' });
  await phone.close();
});
