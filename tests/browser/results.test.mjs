// A result not yet downloaded survives a reload: the vector pattern and its tile, the
// blended texture, the seamless tile and the fill & mend result each come back, the
// same, with their download (each was gone on reload). A result the browser will not
// keep makes leaving the page ask first, until it is downloaded.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { openPlayground } from './harness.mjs';

let page, close;
before(async () => {
  ({ page, close } = await openPlayground());
  await counted();
});
after(async () => close?.());

const counted = () => page.waitForFunction(() => /[1-9]\d* strokes?/.test(document.querySelector('#stroke-count').textContent));
const offered = (sel) => page.waitForFunction((s) => document.querySelector(s).getAttribute('aria-disabled') !== 'true', sel, { timeout: 10000 });
const done = (messages) => page.waitForFunction((m) => document.querySelector(m).textContent === 'Done.', messages, { timeout: 60000 });
const text = (sel) => page.textContent(sel);
async function reloadTo(tab) {
  await page.reload();
  await counted();
  await page.click(`[data-tab="${tab}"]`);
}
const downloaded = async (sel) => {
  const [d] = await Promise.all([page.waitForEvent('download'), page.click(sel)]);
  return { name: d.suggestedFilename(), bytes: readFileSync(await d.path()) };
};
const pixels = (sel) => page.$eval(sel, (c) => {
  const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let h = 0;
  for (let i = 0; i < d.length; i++) h = (h * 31 + d[i]) | 0;
  return `${c.width}x${c.height}:${h}`;
});

test('the vector pattern and its tile come back after a reload', async () => {
  await page.fill('#out-width', '240');
  await page.fill('#out-height', '160');
  await page.click('#synthesize');
  await done('#messages');
  await page.click('#make-tile');
  await page.waitForFunction(() => /tile, \d+ elements/.test(document.querySelector('#tile-info').textContent), null, { timeout: 30000 });
  const [info, tileInfo] = [await text('#result-info'), await text('#tile-info')];
  await page.waitForTimeout(300); // (the last write, under way; a reload then asks first)
  await page.reload();
  await counted();
  await offered('#download');
  await offered('#tile-download');
  assert.equal(await text('#result-info'), info);
  assert.equal(await text('#tile-info'), tileInfo);
  assert.ok(await page.$('#preview img, #preview canvas'), 'the pattern is shown');
  assert.equal(await page.isDisabled('#download-png'), false);
  const svg = await downloaded('#download');
  assert.match(svg.name, /^pattern-240x160\.svg$/);
  assert.match(svg.bytes.toString(), /<svg/);
  assert.match((await downloaded('#tile-download')).bytes.toString(), /<svg/);
  // The PNG of the result kept: the worker makes it again from the same options.
  const png = await downloaded('#download-png');
  assert.equal(png.bytes.subarray(1, 4).toString(), 'PNG');
});

test('the blended texture, the seamless tile and the fill & mend result come back after a reload', async () => {
  await page.click('[data-tab="blend"]');
  await page.waitForFunction(() => document.querySelector('#slot-a canvas').width === 128 && document.querySelector('#slot-b canvas').width === 128);
  await page.fill('#blend-width', '48');
  await page.fill('#blend-height', '40');
  await page.click('#blend-run');
  await done('#blend-messages');
  const blend = [await pixels('#blend-result'), await text('#blend-info')];

  await page.click('[data-tab="seamless"]');
  await page.selectOption('#seam-size', '64');
  await page.click('#seam-run');
  await page.waitForFunction(() => document.querySelector('#seam-repeat').classList.contains('shown') && !document.querySelector('#seam-run').disabled, null, { timeout: 60000 });
  const tileInfo = await text('#seam-info');
  const tile = await downloaded('#seam-download');

  await page.click('[data-tab="retouch"]');
  await page.selectOption('#ret-action', 'more');
  await page.fill('#ret-width', '40');
  await page.fill('#ret-height', '32');
  await page.click('#ret-run');
  await done('#ret-messages');
  const retouch = [await pixels('#ret-result'), await text('#ret-info')];
  await page.waitForTimeout(300);

  await reloadTo('blend');
  await offered('#blend-download');
  assert.deepEqual([await pixels('#blend-result'), await text('#blend-info')], blend);
  assert.match((await downloaded('#blend-download')).name, /^blend-48x40\.png$/);
  await page.click('[data-tab="seamless"]');
  await offered('#seam-download');
  assert.equal(await text('#seam-info'), tileInfo);
  assert.ok(await page.$eval('#seam-repeat', (e) => e.classList.contains('shown') && e.offsetWidth > 0));
  assert.deepEqual(await downloaded('#seam-download'), tile);
  await page.click('[data-tab="retouch"]');
  await offered('#ret-download');
  assert.deepEqual([await pixels('#ret-result'), await text('#ret-info')], retouch);
  assert.ok(await page.$eval('#ret-view', (e) => e.classList.contains('shown')));
});

test('a result the browser will not keep: said, and leaving asks first until it is downloaded', async () => {
  await page.click('[data-tab="blend"]');
  await page.evaluate(() => {
    const put = IDBObjectStore.prototype.put;
    IDBObjectStore.prototype.put = function (value, key) {
      if (String(key).startsWith('result:')) throw new DOMException('The quota has been exceeded.', 'QuotaExceededError');
      return put.call(this, value, key);
    };
  });
  await page.click('#blend-run');
  await page.waitForFunction(() => /would not keep the texture/.test(document.querySelector('#blend-messages').textContent), null, { timeout: 60000 });
  let asked = null;
  page.once('dialog', (d) => { asked = d.type(); d.dismiss(); });
  await page.reload({ timeout: 3000 }).catch(() => {});
  assert.equal(asked, 'beforeunload', 'leaving asks first');
  assert.match(await text('#blend-messages'), /would not keep/, 'the page stayed');
  await downloaded('#blend-download');
  page.once('dialog', (d) => { asked = `again: ${d.type()}`; d.accept(); });
  await page.reload();
  await counted();
  assert.equal(asked, 'beforeunload', 'once downloaded, leaving does not ask');
});
