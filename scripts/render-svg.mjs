// Renders SVG files to PNG in headless Chromium, side by side: to look at outputs.
// Usage: node scripts/render-svg.mjs [--tile] out.png a.svg b.svg ...
// --tile: each SVG repeats as a CSS background over a 400x400 box, at twice its size.
import { chromium } from 'playwright-core';
import { readFileSync } from 'node:fs';
import { CHROMIUM } from '../tests/browser/chromium.mjs';

const args = process.argv.slice(2);
const tile = args[0] === '--tile';
const [outPng, ...files] = tile ? args.slice(1) : args;
const browser = await chromium.launch(CHROMIUM);
const page = await browser.newPage({ viewport: { width: 1000, height: 800 } });
const background = (f) => {
  const svg = readFileSync(f, 'utf8');
  const [, w, h] = svg.match(/width="([\d.]+)" height="([\d.]+)"/);
  const url = `data:image/svg+xml;base64,${Buffer.from(svg).toString('base64')}`;
  return `<div style="width:400px;height:400px;background:url(${url}) 0 0/${2 * w}px ${2 * h}px repeat"></div>`;
};
// (Each SVG as an image of its own: inline, their ids (`<use href="#s0">`) collide and
// every SVG after the first drew the first one's shapes.)
const image = (f) => `<img src="data:image/svg+xml;base64,${Buffer.from(readFileSync(f, 'utf8')).toString('base64')}">`;
const cells = files.map((f) => `<figure><figcaption>${f}</figcaption>${tile ? background(f) : image(f)}</figure>`).join('');
await page.setContent(`<style>body{margin:0;display:flex;flex-wrap:wrap;font:12px sans-serif;background:#fff}
  figure{margin:4px;border:1px solid #ccc} img{width:480px;height:400px;display:block;object-fit:contain}</style>${cells}`);
await page.waitForFunction(() => [...document.images].every((i) => i.complete));
await page.screenshot({ path: outPng, fullPage: true });
await browser.close();
