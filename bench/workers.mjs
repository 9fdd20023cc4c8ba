// Scaling of banded texture synthesis over workers, in headless Chromium against the
// playground's package: output size x workers (1, 2, 4), median ms and speed-up over
// one worker, and the scanline schedule in one worker beside them. The grass
// photograph (128 x 128) is the exemplar. The runs of each worker count alternate, so
// that the shared machine's changing load falls on all alike.
// `node bench/workers.mjs [sizes] [runs]`, e.g. `node bench/workers.mjs 512,1024,2048 3`.
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
    const median = (t) => [...t].sort((a, b) => a - b)[t.length >> 1];
    const time = async (client, opts) => {
      const s = performance.now();
      await client.synthesizeTexture(grass, opts);
      return performance.now() - s;
    };
    // All clients started and warmed first (the helpers start on the first banded
    // call), then the runs interleaved: run r of each in turn, so that a change in the
    // shared machine's load falls on every worker count alike.
    const setups = [['scanline', 1], [1, 1], [2, 2], [4, 4]];
    const clients = [];
    for (const [, workers] of setups) {
      const client = new PatternSynthClient(undefined, { workers });
      await client.synthesizeTexture(grass, { width: 128, height: 128, schedule: 'bands' });
      clients.push(client);
    }
    const rows = [];
    for (const side of sizes) {
      const opts = { width: side, height: side, seed: 1 };
      const t = setups.map(() => []);
      for (let r = 0; r < runs; r++) {
        for (const [i, [name]] of setups.entries()) {
          t[i].push(await time(clients[i], name === 'scanline' ? { ...opts, schedule: 'scanline' } : opts));
        }
      }
      const row = { side, cores: navigator.hardwareConcurrency };
      setups.forEach(([name], i) => { row[name] = median(t[i]); });
      rows.push(row);
    }
    clients.forEach((c) => c.terminate());
    return rows;
  }, { sizes, runs });
  console.log(`Chromium, ${rows[0].cores} cores; exemplar grass 128 x 128; median of ${runs} runs, interleaved`);
  console.log('| output | scanline, 1 worker ms | bands, 1 worker ms | 2 workers ms | speed-up | 4 workers ms | speed-up |');
  console.log('|---|---|---|---|---|---|---|');
  for (const r of rows) {
    console.log(`| ${r.side}² | ${r.scanline.toFixed(0)} | ${r[1].toFixed(0)} | ${r[2].toFixed(0)} | ${(r[1] / r[2]).toFixed(2)} | ${r[4].toFixed(0)} | ${(r[1] / r[4]).toFixed(2)} |`);
  }
} finally {
  await browser.close();
  server.close();
}
