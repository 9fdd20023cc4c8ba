// Lays PNG files side by side (pixelated, at 2x or a given width) and screenshots the
// sheet: to look at texture outputs. Usage: node scripts/contact-sheet.mjs out.png a.png b.png ...
import { chromium } from 'playwright-core';
import { readFileSync } from 'node:fs';
import { CHROMIUM } from '../tests/browser/chromium.mjs';

const [outPng, ...files] = process.argv.slice(2);
const browser = await chromium.launch(CHROMIUM);
const page = await browser.newPage({ viewport: { width: 1100, height: 600 } });
const cells = files.map((f) => `<figure><img src="data:image/png;base64,${readFileSync(f).toString('base64')}"><figcaption>${f}</figcaption></figure>`).join('');
await page.setContent(`<style>body{margin:0;display:flex;flex-wrap:wrap;font:11px sans-serif}
  figure{margin:3px} img{width:256px;image-rendering:pixelated;display:block}</style>${cells}`);
await page.screenshot({ path: outPng, fullPage: true });
await browser.close();
