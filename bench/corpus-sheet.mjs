// Contact sheets of issue 7's corpus: each case's example (the 3x3 repeat) beside the
// synthesized 10x10 periods, rendered by Chromium, 16 cases per sheet:
// out/corpus-1.png, out/corpus-2.png, ...   node bench/corpus-sheet.mjs
import { chromium } from 'playwright-core';
import { mkdirSync } from 'node:fs';
import * as ps from '../pkg/node/index.js';
import { CHROMIUM } from '../tests/browser/chromium.mjs';
import { corpus } from '../tests/node/corpus.mjs';

const url = (svg) => `data:image/svg+xml;base64,${Buffer.from(svg).toString('base64')}`;
const cases = corpus().map((c) => {
  const strokes = ps.parseSvg(c.svg);
  const w = 10 * Math.abs(c.a[0]) + 10 * Math.abs(c.b[0]), h = 10 * Math.abs(c.a[1]) + 10 * Math.abs(c.b[1]);
  const out = ps.synthesizeStrokes(strokes, { width: w, height: h, variation: false, seed: 1 });
  return `<figure><figcaption>${c.corpus} ${c.name} (${strokes.length} → ${out.strokes.length})</figcaption>
    <img class="ex" src="${url(c.svg)}"><img class="out" src="${url(out.svg)}"></figure>`;
});
mkdirSync('out', { recursive: true });
const browser = await chromium.launch(CHROMIUM);
const page = await browser.newPage({ viewport: { width: 1600, height: 900 } });
for (let i = 0; i * 16 < cases.length; i++) {
  await page.setContent(`<style>body{margin:0;display:flex;flex-wrap:wrap;font:11px sans-serif}
    figure{margin:4px;width:390px} img{border:1px solid #ccc;vertical-align:top;background:#fff}
    .ex{width:120px;height:120px;object-fit:contain} .out{width:260px;height:260px;object-fit:contain}</style>${cases.slice(i * 16, i * 16 + 16).join('')}`);
  await page.waitForLoadState('networkidle');
  await page.screenshot({ path: `out/corpus-${i + 1}.png`, fullPage: true });
  console.log(`out/corpus-${i + 1}.png`);
}
await browser.close();
