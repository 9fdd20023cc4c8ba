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
