// Settings kept in IndexedDB (issue 29): a change survives a reload; nothing of it is
// left in localStorage; an older page's settings in localStorage are moved over; and
// a write the browser refuses is said on the page.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openPlayground } from './harness.mjs';

const KEY = 'patternsynth.strokes.settings.v1';
/** The value IndexedDB keeps under `key`, read in the page. */
const kept = (page, key) => page.evaluate((key) => new Promise((ok, fail) => {
  const r = indexedDB.open('patternsynth');
  r.onsuccess = () => {
    const g = r.result.transaction('kept').objectStore('kept').get(key);
    g.onsuccess = () => { ok(g.result ?? null); r.result.close(); };
    g.onerror = () => fail(g.error);
  };
  r.onerror = () => fail(r.error);
}), key);

test('settings live in IndexedDB, survive a reload, move over from localStorage, and a refused write is said', async () => {
  const { page, close } = await openPlayground();
  try {
    await page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
    await page.fill('#seed', '7');
    await page.fill('#out-width', '640');
    await page.selectOption('#repeat-type', 'brick');
    await page.waitForFunction((key) => new Promise((ok) => {
      const r = indexedDB.open('patternsynth');
      r.onsuccess = () => { const g = r.result.transaction('kept').objectStore('kept').get(`settings:${key}`); g.onsuccess = () => ok(g.result?.seed === 7 && g.result?.repeat?.type === 'brick'); };
    }), KEY);
    assert.equal(await page.evaluate(() => Object.keys(localStorage).filter((k) => k.startsWith('patternsynth.')).length), 0, 'nothing in localStorage');
    await page.reload();
    await page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
    assert.equal(await page.inputValue('#seed'), '7');
    assert.equal(await page.inputValue('#out-width'), '640');
    assert.equal(await page.inputValue('#repeat-type'), 'brick');

    // An older page's settings: in localStorage, none in IndexedDB.
    await page.evaluate(async (key) => {
      await new Promise((ok) => { const r = indexedDB.open('patternsynth'); r.onsuccess = () => { const tx = r.result.transaction('kept', 'readwrite'); tx.objectStore('kept').delete(`settings:${key}`); tx.oncomplete = () => { r.result.close(); ok(); }; }; });
      localStorage.setItem(key, JSON.stringify({ seed: 9, width: 500, height: 300 }));
    }, KEY);
    await page.reload();
    await page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
    assert.equal(await page.inputValue('#seed'), '9');
    await page.waitForFunction((key) => localStorage.getItem(key) === null, KEY);
    assert.equal((await kept(page, `settings:${KEY}`))?.seed, 9, 'moved to IndexedDB');

    // The browser refuses every write: said beside the session buttons.
    await page.evaluate(() => {
      IDBObjectStore.prototype.put = function () { throw new DOMException('The quota has been exceeded.', 'QuotaExceededError'); };
    });
    await page.fill('#seed', '11');
    await page.waitForFunction(() => /Settings could not be kept/.test(document.querySelector('#session-status').textContent));
    assert.match(await page.textContent('#session-status'), /quota has been exceeded.*last until this page closes/);
  } finally {
    await close();
  }
});
