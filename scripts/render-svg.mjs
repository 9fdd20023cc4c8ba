// Renders SVG files to PNG in headless Chromium, side by side: to look at outputs.
// Usage: node scripts/render-svg.mjs out.png a.svg b.svg ...
import { chromium } from 'playwright-core';
import { readFileSync } from 'node:fs';
import { CHROMIUM } from '../tests/browser/chromium.mjs';

const [outPng, ...files] = process.argv.slice(2);
const browser = await chromium.launch(CHROMIUM);
const page = await browser.newPage({ viewport: { width: 1000, height: 800 } });
const cells = files.map((f) => `<figure><figcaption>${f}</figcaption>${readFileSync(f, 'utf8')}</figure>`).join('');
await page.setContent(`<style>body{margin:0;display:flex;flex-wrap:wrap;font:12px sans-serif;background:#fff}
  figure{margin:4px;border:1px solid #ccc} svg{width:480px;height:400px;display:block}</style>${cells}`);
await page.screenshot({ path: outPng, fullPage: true });
await browser.close();
