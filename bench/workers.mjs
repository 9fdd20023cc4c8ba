// Scaling of banded texture synthesis over workers, in headless Chromium against the
// playground's package: output size x workers (1, 2, 4), median ms and speed-up over
// one worker, and the scanline schedule in one worker beside them. The grass
// photograph (128 x 128) is the exemplar. `node bench/workers.mjs [sizes] [runs]`,
// e.g. `node bench/workers.mjs 512,1024,2048 3`.
import { chromium } from 'playwright-core';
import { CHROMIUM } from '../tests/browser/chromium.mjs';
import { serve } from '../scripts/static-server.mjs';

const sizes = (process.argv[2] ?? '512,1024,2048').split(',').map(Number);
const runs = Number(process.argv[3] ?? 3);
const server = await serve('www', 0);
const browser = await chromium.launch(CHROMIUM);
try {
  const page = await browser.newPage();
  page.on('pageerror', (e) => console.error('page error:', e.message));
  await page.goto(`http://127.0.0.1:${server.address().port}/`);
  const rows = await page.evaluate(async ({ sizes, runs }) => {
    const { PatternSynthClient } = await import('./pkg/client.js');
    const bmp = await createImageBitmap(await (await fetch('./textures/grass.png')).blob());
    const ctx = new OffscreenCanvas(bmp.width, bmp.height).getContext('2d');
    ctx.drawImage(bmp, 0, 0);
    const grass = ctx.getImageData(0, 0, bmp.width, bmp.height);
    const median = (t) => t.sort((a, b) => a - b)[t.length >> 1];
    const time = async (client, opts) => {
      await client.version(); // workers started and loaded before timing
      await client.synthesizeTexture(grass, { width: 64, height: 64 });
      const t = [];
      for (let i = 0; i < (opts.width > 1024 ? 1 : runs); i++) {
        const s = performance.now();
        await client.synthesizeTexture(grass, opts);
        t.push(performance.now() - s);
      }
      return median(t);
    };
    const rows = [];
    for (const side of sizes) {
      const opts = { width: side, height: side, seed: 1 };
      const row = { side, cores: navigator.hardwareConcurrency };
      const one = new PatternSynthClient(undefined, { workers: 1 });
      row.scanline = await time(one, { ...opts, schedule: 'scanline' });
      one.terminate();
      for (const workers of [1, 2, 4]) {
        const client = new PatternSynthClient(undefined, { workers });
        // The helpers start on the first banded call: warm them with one.
        await client.synthesizeTexture(grass, { width: 128, height: 128, schedule: 'bands' });
        row[workers] = await time(client, opts);
        client.terminate();
      }
      rows.push(row);
    }
    return rows;
  }, { sizes, runs });
  console.log(`Chromium, ${rows[0].cores} cores; exemplar grass 128 x 128; median of ${runs} (1 run at 2048)`);
  console.log('| output | scanline, 1 worker ms | bands, 1 worker ms | 2 workers ms | speed-up | 4 workers ms | speed-up |');
  console.log('|---|---|---|---|---|---|---|');
  for (const r of rows) {
    console.log(`| ${r.side}² | ${r.scanline.toFixed(0)} | ${r[1].toFixed(0)} | ${r[2].toFixed(0)} | ${(r[1] / r[2]).toFixed(2)} | ${r[4].toFixed(0)} | ${(r[1] / r[4]).toFixed(2)} |`);
  }
} finally {
  await browser.close();
  server.close();
}
