// The playground for a keyboard, a screen reader and a finger (issue 29): Tab moves
// focus everywhere (it accepts ghosts only once after drawing on the canvas; Enter
// accepts them from the keyboard); every control is reachable and
// named (axe-core, and Chromium's accessibility tree); the tabs follow the WAI-ARIA
// pattern; on a phone-sized touch screen targets are at least 24 px, a tap is not a
// stroke and the hints say "tap"; no tab overflows sideways at 390, 1024 and 1440 px;
// a refused tile takes the previous one off the screen. Leaves screenshots in out/.
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { openPlayground } from './harness.mjs';

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
const TABS = ['strokes', 'blend', 'seamless', 'retouch'];
mkdirSync('out', { recursive: true });

const opened = [];
async function open(opts) {
  const p = await openPlayground(opts);
  opened.push(p);
  await p.page.waitForFunction(() => /[1-9]\d* strokes/.test(document.querySelector('#stroke-count').textContent));
  return p;
}
after(async () => { for (const p of opened) await p.close(); });

const strokeCount = (page) => page.evaluate(() => Number(document.querySelector('#stroke-count').textContent.split(' ')[0]));
const focused = (page) => page.evaluate(() => {
  const e = document.activeElement;
  return e === document.body ? 'body' : `${e.tagName.toLowerCase()}${e.id ? `#${e.id}` : ''}${e.className ? `.${e.className}` : ''}:${(e.getAttribute('aria-label') ?? e.textContent).trim().slice(0, 30)}`;
});

/** Controls in Chromium's accessibility tree with an interactive role and no name. */
async function unnamed(page) {
  const cdp = await page.context().newCDPSession(page);
  const { nodes } = await cdp.send('Accessibility.getFullAXTree');
  const roles = new Set(['button', 'checkbox', 'radio', 'textbox', 'spinbutton', 'slider', 'combobox', 'progressbar', 'tab', 'tabpanel', 'link', 'image', 'img', 'canvas', 'listbox', 'switch']);
  return nodes
    .filter((n) => !n.ignored && roles.has(n.role?.value) && !(n.name?.value ?? '').trim())
    .map((n) => `${n.role.value} (backend node ${n.backendDOMNodeId})`);
}

async function axe(page) {
  if (!(await page.evaluate(() => 'axe' in window))) await page.addScriptTag({ content: AXE });
  const r = await page.evaluate(() => window.axe.run(document, { resultTypes: ['violations'] }));
  return r.violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
}

test('from a fresh load Tab moves focus through the controls and adds no strokes', async () => {
  const { page } = await open();
  const before = await strokeCount(page);
  const seen = [];
  for (let i = 0; i < 24; i++) {
    await page.keyboard.press('Tab');
    seen.push(await focused(page));
  }
  assert.equal(await strokeCount(page), before, 'Tab added strokes');
  assert.ok(!seen.includes('body'), seen.join(' | '));
  for (const name of ['Vector strokes', 'Import SVG', 'Undo']) assert.ok(seen.some((s) => s.includes(name)), `${name} not reached: ${seen.join(' | ')}`);
  // On the canvas reached by keyboard, Enter accepts the ghosts and Tab moves on.
  await page.focus('#draw');
  await page.waitForFunction(() => !document.querySelector('#accept-ghosts').disabled, null, { timeout: 15_000 });
  await page.keyboard.press('Enter');
  assert.ok(await strokeCount(page) > before, 'Enter accepted the ghosts');
  await page.focus('#draw');
  await page.keyboard.press('Tab');
  assert.notEqual(await focused(page), 'canvas#draw', 'Tab leaves the canvas reached by keyboard');
  await page.evaluate(() => document.querySelector('#clear').click());
  await page.focus('#draw');
  await page.keyboard.press('Tab');
  assert.notEqual(await focused(page), 'canvas#draw', 'with no ghosts, Tab leaves the canvas');
  assert.equal(await strokeCount(page), 0);
});

test('every tab: no axe violations, no unnamed control; file pickers are buttons in the Tab order', async () => {
  const { page } = await open();
  for (const tab of TABS) {
    await page.click(`[data-tab="${tab}"]`);
    // The maps' picker shows with the action that uses them.
    if (tab === 'retouch') await page.selectOption('#ret-action', 'more');
    await page.waitForTimeout(300);
    assert.deepEqual(await axe(page), [], `axe on ${tab}`);
    assert.deepEqual(await unnamed(page), [], `unnamed controls on ${tab}`);
    const pickers = await page.$$eval(`#tab-${tab} .file-button`, (bs) => bs.map((b) => b.tabIndex >= 0 && b.offsetParent !== null));
    assert.ok(pickers.length >= 1 && pickers.every(Boolean), `${tab}: ${pickers}`);
  }
});

test('tabs follow the WAI-ARIA pattern: one in the Tab order, arrows and Home/End select', async () => {
  const { page } = await open();
  await page.focus('[data-tab="strokes"]');
  const state = () => page.evaluate(() => [...document.querySelectorAll('[role="tab"]')].map((t) => `${t.dataset.tab}:${t.getAttribute('aria-selected')}:${t.tabIndex}:${document.getElementById(t.getAttribute('aria-controls')).hidden}`));
  assert.deepEqual(await state(), ['strokes:true:0:false', 'blend:false:-1:true', 'seamless:false:-1:true', 'retouch:false:-1:true']);
  await page.keyboard.press('ArrowRight');
  assert.deepEqual(await state(), ['strokes:false:-1:true', 'blend:true:0:false', 'seamless:false:-1:true', 'retouch:false:-1:true']);
  assert.match(await focused(page), /Blend textures/);
  await page.keyboard.press('End');
  assert.equal((await state())[3], 'retouch:true:0:false');
  await page.keyboard.press('ArrowRight');
  assert.equal((await state())[0], 'strokes:true:0:false', 'wraps around');
  await page.keyboard.press('Tab');
  assert.doesNotMatch(await focused(page), /Blend textures|Seamless tile|Fill & mend/, 'Tab leaves the tab list');
  const panels = await page.$$eval('[role="tabpanel"]', (ps) => ps.map((p) => document.getElementById(p.getAttribute('aria-labelledby'))?.textContent));
  assert.deepEqual(panels, ['Vector strokes', 'Blend textures', 'Seamless tile', 'Fill & mend']);
});

test('a phone: targets of at least 24 px, a tap is not a stroke, hints without keys', async () => {
  const { page } = await open({ width: 390, height: 844, touch: true });
  for (const tab of TABS) {
    await page.click(`[data-tab="${tab}"]`);
    // Controls shown only in some states, shown: a layout set by hand, a tile of any size.
    if (tab === 'strokes') await page.selectOption('#repeat-type', 'oblique');
    if (tab === 'seamless') await page.selectOption('#seam-size', 'custom');
    if (tab === 'retouch') await page.selectOption('#ret-action', 'more');
    const small = await page.evaluate(() => [...document.querySelectorAll('button, a.button, input:not([type=hidden]), select, [role=tab]')]
      .filter((e) => e.offsetParent !== null && !e.hidden)
      .map((e) => ({ e, r: e.getBoundingClientRect() }))
      .filter(({ r }) => r.width < 24 || r.height < 24)
      .map(({ e, r }) => `${e.id || e.type || e.tagName} ${Math.round(r.width)}x${Math.round(r.height)}`));
    assert.deepEqual(small, [], `${tab}: targets under 24 px`);
    await page.screenshot({ path: `out/a11y-phone-${tab}.png`, fullPage: true });
  }
  await page.click('[data-tab="strokes"]');
  // The lattice's handles on the shrunk canvas: a finger 10 px from the tip still takes
  // it (24 px target), and the drag draws nothing.
  const box0 = await page.locator('#draw').boundingBox();
  const k = box0.width / 800;
  const [across] = await page.$$eval('#period-across', (i) => i.map((e) => Number(e.value)));
  const origin = await page.evaluate(() => window.playground.latticeOrigin());
  const tip = [box0.x + (origin[0] + across) * k + 10, box0.y + origin[1] * k];
  const client = await page.context().newCDPSession(page);
  const touch = (type, [x, y]) => client.send('Input.dispatchTouchEvent', { type, touchPoints: type === 'touchEnd' ? [] : [{ x, y }] });
  const strokesBefore = await strokeCount(page);
  await touch('touchStart', tip);
  await touch('touchMove', [tip[0] + 20, tip[1]]);
  await touch('touchMove', [tip[0] + 40, tip[1]]);
  await touch('touchEnd', tip);
  await page.waitForTimeout(100);
  const dragged = Number(await page.inputValue('#period-across'));
  assert.ok(dragged > across + 20, `the handle followed the finger: ${across} -> ${dragged}`);
  assert.equal(await strokeCount(page), strokesBefore, 'dragging a handle drew nothing');
  await page.selectOption('#repeat-type', 'auto');
  const before = await strokeCount(page);
  const box = await page.locator('#draw').boundingBox();
  await page.touchscreen.tap(box.x + box.width * 0.9, box.y + box.height * 0.9);
  await page.waitForTimeout(200);
  assert.equal(await strokeCount(page), before, 'a tap added a stroke');
  const hints = await page.evaluate(() => [...document.querySelectorAll('kbd')].filter((k) => k.offsetParent !== null).length);
  assert.equal(hints, 0, 'key hints shown on a touch screen');
});

test('no tab overflows sideways at 390, 1024 and 1440 px, with a 512 px seamless tile shown', async () => {
  for (const width of [390, 1024, 1440]) {
    const { page } = await open({ width, height: 900 });
    for (const tab of TABS) {
      await page.click(`[data-tab="${tab}"]`);
      if (tab === 'seamless' && width !== 1024) {
        await page.selectOption('#seam-size', '512');
        await page.selectOption('#seam-method', 'synthesis');
        await page.click('#seam-run');
        await page.waitForFunction(() => document.querySelector('#seam-repeat').classList.contains('shown'), null, { timeout: 120_000 });
        await page.screenshot({ path: `out/a11y-seamless-${width}.png` });
      }
      const over = await page.evaluate(() => document.scrollingElement.scrollWidth - window.innerWidth);
      assert.ok(over <= 0, `${tab} at ${width} px overflows by ${over} px`);
    }
  }
});

test('a refused tile takes the previous tile, its text and its download off the screen', async () => {
  const { page } = await open();
  await page.click('#make-tile');
  await page.waitForFunction(() => document.querySelector('#tile-preview').classList.contains('shown'), null, { timeout: 30_000 });
  assert.equal(await page.getAttribute('#tile-download', 'aria-disabled'), null);
  // One stroke: no repeat to tile.
  await page.evaluate(() => document.querySelector('#clear').click());
  const box = await page.locator('#draw').boundingBox();
  await page.mouse.move(box.x + 100, box.y + 100);
  await page.mouse.down();
  await page.mouse.move(box.x + 160, box.y + 140, { steps: 4 });
  await page.mouse.up();
  await page.click('#make-tile');
  await page.waitForFunction(() => /No tile/.test(document.querySelector('#tile-info').textContent), null, { timeout: 30_000 });
  assert.equal(await page.evaluate(() => document.querySelector('#tile-preview').classList.contains('shown')), false);
  assert.equal(await page.getAttribute('#tile-download', 'aria-disabled'), 'true');
  assert.equal(await page.getAttribute('#tile-download', 'href'), null);
});

// Long tasks are timings on a shared machine: the test asserts the structure that keeps
// the page free (a canvas drawn in the worker, no SVG parsed on the page) and a bound
// well under the 988 ms measured before, and prints the longest (51 ms unloaded).
test('a result of 36,000 strokes is shown without a long task on the page (drawn in the worker)', async (t) => {
  const { page } = await open();
  await page.evaluate(() => {
    window.longTasks = [];
    new PerformanceObserver((l) => { for (const e of l.getEntries()) window.longTasks.push(Math.round(e.duration)); }).observe({ type: 'longtask' });
  });
  await page.fill('#out-width', '12000');
  await page.fill('#out-height', '8000');
  await page.click('#synthesize');
  await page.waitForFunction(() => /^\d+ strokes, \d+ classes/.test(document.querySelector('#result-info').textContent), null, { timeout: 120_000 });
  await page.waitForTimeout(1000);
  const info = await page.textContent('#result-info');
  assert.ok(Number(info.split(' ')[0]) > 20_000, info);
  const long = await page.evaluate(() => window.longTasks);
  t.diagnostic(`long tasks while showing ${info}: ${long.join(', ') || 'none'} ms`);
  assert.ok(long.every((ms) => ms <= 300), `long tasks ${long} ms while showing ${info}`);
  assert.equal(await page.$$eval('#preview canvas', (cs) => cs.length), 1);
  assert.equal(await page.$$eval('#preview img', (is) => is.length), 0, 'no SVG image for the page to parse');
  assert.equal(await page.getAttribute('#download', 'download'), 'pattern-12000x8000.svg');
  await page.locator('#preview').screenshot({ path: 'out/a11y-large-result.png' });
});

test('a tile offers its CSS (the SVG inline), a copy button, and a view offset by half a tile', async () => {
  const { page } = await open();
  await page.context().grantPermissions(['clipboard-read', 'clipboard-write']);
  await page.click('#make-tile');
  await page.waitForFunction(() => document.querySelector('#tile-preview').classList.contains('shown'), null, { timeout: 30_000 });
  await page.click('#tile-copy');
  const css = await page.inputValue('#tile-css');
  assert.ok(await page.isVisible('#tile-css'));
  const m = css.match(/^background-image: url\("data:image\/svg\+xml,([^"]+)"\);\nbackground-size: ([\d.]+)px ([\d.]+)px;\nbackground-repeat: repeat;$/);
  assert.ok(m, css.slice(0, 200));
  const svg = decodeURIComponent(m[1]);
  const tileSvg = await page.evaluate(async () => (await fetch(document.querySelector('#tile-download').href)).text());
  assert.equal(svg, tileSvg.replace(/\s*\n\s*/g, ''));
  assert.match(svg, new RegExp(`viewBox="0 0 ${m[2]} ${m[3]}"`));
  assert.equal(await page.evaluate(() => navigator.clipboard.readText()), css);
  const position = () => page.evaluate(() => document.querySelector('#tile-preview').style.backgroundPosition);
  assert.equal(await position(), '0px 0px');
  await page.check('#tile-offset');
  const [x, y] = (await position()).split(' ').map(parseFloat);
  const size = await page.evaluate(() => document.querySelector('#tile-preview').style.backgroundSize.split(' ').map(parseFloat));
  assert.ok(Math.abs(x - size[0] / 2) < 0.01 && Math.abs(y - size[1] / 2) < 0.01, `${x},${y} against ${size}`);
  await page.locator('#tab-strokes .settings').screenshot({ path: 'out/a11y-tile-css.png' });
});

/** Draws a short stroke at canvas point (x, y). */
async function stroke(page, x, y) {
  const box = await page.locator('#draw').boundingBox();
  await page.mouse.move(box.x + x, box.y + y);
  await page.mouse.down();
  await page.mouse.move(box.x + x + 30, box.y + y + 20, { steps: 4 });
  await page.mouse.up();
}

test('nothing lost: the drawing and its undo history survive a reload, and a session file restores all', async () => {
  const { page } = await open();
  await page.click('#clear');
  for (const [x, y] of [[50, 50], [150, 50], [250, 50]]) await stroke(page, x, y);
  await page.click('#undo');
  assert.equal(await strokeCount(page), 2);
  await page.waitForTimeout(300); // the write starts with the change; let it commit
  await page.reload();
  await page.waitForFunction(() => /^2 strokes/.test(document.querySelector('#stroke-count').textContent));
  await page.click('#redo');
  assert.equal(await strokeCount(page), 3, 'redo after a reload');
  await page.click('#undo');
  await page.click('#undo');
  assert.equal(await strokeCount(page), 1, 'undo after a reload');
  await page.click('#redo');
  const drawn = await page.evaluate(() => window.playground.drawing().strokes);

  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#session-export')]);
  assert.match(download.suggestedFilename(), /^patternsynth-session-\d{4}-\d\d-\d\d\.json$/);
  const file = await download.path();
  const fresh = await open();
  assert.notEqual(await strokeCount(fresh.page), 2);
  await fresh.page.setInputFiles('#session-import', file);
  await fresh.page.waitForFunction(() => /^2 strokes/.test(document.querySelector('#stroke-count').textContent));
  assert.deepEqual(await fresh.page.evaluate(() => window.playground.drawing().strokes), drawn);
  await fresh.page.click('#undo');
  assert.equal(await strokeCount(fresh.page), 1, 'the history came with the file');

  // A file that is not a session: said beside the buttons (no dialog), nothing changed.
  let dialogs = 0;
  fresh.page.on('dialog', (d) => { dialogs += 1; d.dismiss(); });
  await fresh.page.setInputFiles('#session-import', { name: 'notes.json', mimeType: 'application/json', buffer: Buffer.from('{"hello": 1}') });
  await fresh.page.waitForFunction(() => /notes\.json is not a patternsynth session.*nothing was changed/.test(document.querySelector('#session-status').textContent));
  await fresh.page.setInputFiles('#session-import', { name: 'photo.json', mimeType: 'application/json', buffer: Buffer.from('\x89PNG') });
  await fresh.page.waitForFunction(() => /photo\.json is not a patternsynth session \(not JSON\)/.test(document.querySelector('#session-status').textContent));
  assert.equal(dialogs, 0);
  assert.equal(await strokeCount(fresh.page), 1);
});

test('when the browser will not keep the drawing, the page says so', async () => {
  const server = await open();
  const { page } = server;
  await page.evaluate(() => {
    IDBObjectStore.prototype.put = function () { throw new DOMException('The quota has been exceeded.', 'QuotaExceededError'); };
  });
  await stroke(page, 60, 300);
  await page.waitForFunction(() => /would not keep the drawing.*Export session/.test(document.querySelector('#messages').textContent), null, { timeout: 5000 });
});

test('the vector pattern downloads as a PNG of a chosen width, drawn in the worker', async () => {
  const { page } = await open();
  await page.fill('#out-width', '600');
  await page.fill('#out-height', '400');
  await page.click('#synthesize');
  await page.waitForFunction(() => document.querySelector('#messages').textContent === 'Done.', null, { timeout: 60_000 });
  await page.fill('#png-width', '900');
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-png')]);
  assert.equal(download.suggestedFilename(), 'pattern-600x400-900px.png');
  const png = readFileSync(await download.path());
  assert.deepEqual([...png.subarray(1, 4)].map((c) => String.fromCharCode(c)).join(''), 'PNG');
  assert.deepEqual([png.readUInt32BE(16), png.readUInt32BE(20)], [900, 600], 'the width asked for, the aspect kept');
  await page.fill('#png-width', '9000');
  await page.click('#download-png');
  await page.waitForFunction(() => /from 16 to 8192/.test(document.querySelector('#messages').textContent));
});

test('axe and the accessibility tree stay clean with results shown: a pattern, ghosts, a tile and its CSS, a blend, a seamless tile', async () => {
  const { page } = await open();
  const clean = async (state) => {
    assert.deepEqual(await axe(page), [], `axe with ${state}`);
    assert.deepEqual(await unnamed(page), [], `unnamed controls with ${state}`);
  };
  await page.waitForFunction(() => !document.querySelector('#accept-ghosts').disabled, null, { timeout: 15_000 });
  await clean('ghosts shown');
  await page.click('#synthesize');
  await page.waitForFunction(() => document.querySelector('#messages').textContent === 'Done.', null, { timeout: 60_000 });
  await page.click('#make-tile');
  await page.waitForFunction(() => document.querySelector('#tile-preview').classList.contains('shown'), null, { timeout: 30_000 });
  await page.click('#tile-copy');
  await clean('a pattern, a tile and its CSS shown');
  await page.click('[data-tab="blend"]');
  await page.click('#blend-run');
  await page.waitForFunction(() => /^\d+×\d+/.test(document.querySelector('#blend-info').textContent), null, { timeout: 120_000 });
  await clean('a blend shown');
  await page.click('[data-tab="seamless"]');
  await page.click('#seam-run');
  await page.waitForFunction(() => document.querySelector('#seam-repeat').classList.contains('shown'), null, { timeout: 120_000 });
  await page.click('#seam-copy');
  await clean('a seamless tile and its CSS shown');
});
