// The worker client in Chromium, against the package as the playground serves it: a
// worker that cannot start rejects the call with the cause, and the next call starts a
// working one; a bad input in the worker is a clear error and the worker stays usable.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openPlayground } from './harness.mjs';
import { serve } from '../../scripts/static-server.mjs';

test('the client recovers from a worker that fails to start and from bad input', async () => {
  const { page, close } = await openPlayground();
  try {
    const out = await page.evaluate(async () => {
      const { PatternSynthClient } = await import('./pkg/client.js');
      let made = 0;
      const client = new PatternSynthClient(() => {
        made += 1;
        return new Worker(made === 1 ? './pkg/no-such-worker.js' : './pkg/worker.js', { type: 'module' });
      });
      const grid = Array.from({ length: 9 }, (_, i) => ({ points: [[10 + (i % 3) * 20, 10 + Math.floor(i / 3) * 20], [15 + (i % 3) * 20, 15 + Math.floor(i / 3) * 20]], width: 1 }));
      const first = await client.synthesizeStrokes(grid, { width: 200, height: 200 }).then(() => 'resolved', (e) => e.message);
      const second = await client.synthesizeStrokes(grid, { width: 200, height: 200 }).then((r) => r.strokes.length, (e) => e.message);
      const bad = await client.parseSvg(42).then(() => 'resolved', (e) => `${e.name}: ${e.message}`);
      const deep = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9">' + '<g>'.repeat(300) + '<rect width="1" height="1"/>' + '</g>'.repeat(300) + '</svg>';
      const nested = await client.parseSvg(deep).then(() => 'resolved', (e) => e.message);
      const after = await client.parseSvg('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9"><rect width="1" height="1"/></svg>').then((s) => s.length, (e) => e.message);
      let sync;
      try { new PatternSynthClient(42); } catch (e) { sync = e.message; }
      const missing = await new PatternSynthClient('./pkg/missing-worker.js').version().then(() => 'resolved', (e) => e.message);
      return { first, second, bad, nested, after, made, sync, missing };
    });
    assert.match(out.first, /The patternsynth worker failed/);
    assert.match(out.first, /"With a bundler" in the package README/);
    assert.match(out.missing, /The worker script is http:\/\/127\.0\.0\.1:\d+\/pkg\/missing-worker\.js\. If your bundler does not bundle workers.*"With a bundler"/);
    assert.ok(out.second > 50, `second call: ${out.second}`);
    assert.equal(out.bad, 'Error: The SVG (the document\'s text) must be a string, got a number.');
    assert.match(out.nested, /nests 302 levels deep/);
    assert.equal(out.after, 1);
    assert.equal(out.made, 2, 'one failed worker, one that kept working');
    assert.match(out.sync, /takes a Worker, a function returning a Worker, or the URL/);
  } finally {
    await close();
  }
});

test('fields and preview: a large stroke result comes back as a Blob and an image drawn in the worker', async () => {
  const { page, close } = await openPlayground();
  try {
    const out = await page.evaluate(async () => {
      const { PatternSynthClient } = await import('./pkg/client.js');
      const client = new PatternSynthClient('./pkg/worker.js');
      const grid = Array.from({ length: 9 }, (_, i) => ({ points: [[10 + (i % 3) * 20, 10 + Math.floor(i / 3) * 20], [15 + (i % 3) * 20, 15 + Math.floor(i / 3) * 20]], width: 2, stroke: '#ff0000' }));
      const full = await client.synthesizeStrokes(grid, { width: 300, height: 150, seed: 1 });
      const r = await client.synthesizeStrokes(grid, { width: 300, height: 150, seed: 1 }, { fields: ['svgBlob', 'classes'], preview: { width: 200, height: 200, background: '#ffffff' } });
      const c = new OffscreenCanvas(r.preview.width, r.preview.height).getContext('2d');
      c.drawImage(r.preview, 0, 0);
      const px = c.getImageData(0, 0, r.preview.width, r.preview.height).data;
      let red = 0;
      for (let i = 0; i < px.length; i += 4) red += px[i] > 200 && px[i + 1] < 80 && px[i + 2] < 80;
      const bad = await client.synthesizeStrokes(grid, { width: 300, height: 150 }, { preview: { width: 0, height: 5 } }).then(() => 'resolved', (e) => e.message);
      return {
        keys: Object.keys(r).sort(), size: [r.preview.width, r.preview.height], red,
        same: (await r.svgBlob.text()) === full.svg, type: r.svgBlob.type, classes: r.classes.length === full.strokes.length, bad,
      };
    });
    assert.deepEqual(out.keys, ['classes', 'preview', 'svgBlob']);
    assert.deepEqual(out.size, [200, 100], 'fitted, aspect kept');
    assert.ok(out.red > 100, `${out.red} red pixels drawn`);
    assert.ok(out.same && out.classes && out.type === 'image/svg+xml');
    assert.match(out.bad, /preview: width and height must be from 1 to 8192/);
  } finally {
    await close();
  }
});

test('a worker script on another origin (a CDN) fails with its URL and the way round', async () => {
  const { page, close } = await openPlayground();
  const other = await serve('www', 0);
  try {
    const message = await page.evaluate(async (url) => {
      const { PatternSynthClient } = await import('./pkg/client.js');
      return new PatternSynthClient(url).version().then(() => 'resolved', (e) => e.message);
    }, `http://localhost:${other.address().port}/pkg/worker.js`);
    assert.match(message, /worker script http:\/\/localhost:\d+\/pkg\/worker\.js is on another origin than the page/);
    assert.match(message, /same-origin blob: module.*From another origin/);
  } finally {
    other.close();
    await close();
  }
});

test('a worker fetches the wasm of the call it runs, and nothing else', async () => {
  const { chromium } = await import('playwright-core');
  const { CHROMIUM } = await import('./chromium.mjs');
  const { mkdtempSync, writeFileSync, cpSync, readdirSync, statSync } = await import('node:fs');
  const { tmpdir } = await import('node:os');
  const { join } = await import('node:path');
  // A page with nothing but the package: the playground's own worker would add its
  // modules to the count.
  const dir = mkdtempSync(join(tmpdir(), 'patternsynth-fetch-'));
  cpSync('www/pkg', join(dir, 'pkg'), { recursive: true });
  writeFileSync(join(dir, 'index.html'), '<!doctype html><meta charset="utf-8"><title>fetch</title>');
  const names = new Map(readdirSync('www/pkg/wasm').filter((f) => f.endsWith('.wasm')).map((f) => [statSync(join('www/pkg/wasm', f)).size, f]));
  const server = await serve(dir, 0);
  const browser = await chromium.launch(CHROMIUM);
  // One fresh page per call type: which .wasm files it fetched, and their bytes.
  const fetched = async (call, script, noSimdModule = false) => {
    const context = await browser.newContext();
    if (script) await context.addInitScript(script);
    // Workers take no init scripts: there the package's own answer is replaced.
    if (noSimdModule) {
      await context.route('**/pkg/simd.js', (r) => r.fulfill({ contentType: 'text/javascript', body: 'export const simd = false; export const supportsSimd = () => false;' }));
    }
    // The served file each .wasm response names, by size: a response's body can stay
    // pending in Chromium (a CI run of the bundler test waited on one), a file's size cannot.
    const sizes = [];
    context.on('response', (r) => {
      const path = decodeURIComponent(new URL(r.url()).pathname);
      if (path.endsWith('.wasm')) sizes.push(statSync(join(dir, path)).size);
    });
    const page = await context.newPage();
    await page.goto(`http://127.0.0.1:${server.address().port}/index.html`);
    const result = await page.evaluate(call);
    await context.close();
    return { result, files: sizes.map((s) => names.get(s) ?? s).sort(), bytes: sizes.reduce((a, b) => a + b, 0) };
  };
  try {
    const texture = await fetched(async () => {
      const { PatternSynthClient } = await import('./pkg/client.js');
      const data = new Uint8ClampedArray(64 * 64 * 4).map((_, i) => (i % 4 === 3 ? 255 : (i * 37) % 251));
      const out = await new PatternSynthClient('./pkg/worker.js').synthesizeTexture({ width: 64, height: 64, data }, { width: 256, height: 256, seed: 1 });
      return [out.width, out.height];
    });
    const vector = await fetched(async () => {
      const { PatternSynthClient } = await import('./pkg/client.js');
      const row = Array.from({ length: 4 }, (_, i) => ({ points: [[10 + 20 * i, 10], [15 + 20 * i, 20]], width: 1 }));
      return (await new PatternSynthClient('./pkg/worker.js').synthesizeStrokes(row, { width: 200, height: 100 })).strokes.length > 4;
    });
    console.log(`one 256x256 texture call fetched ${texture.files.join(', ')} (${texture.bytes} bytes); one stroke call ${vector.files.join(', ')} (${vector.bytes} bytes)`);
    assert.deepEqual(texture.result, [256, 256]);
    assert.deepEqual(texture.files, ['texture_bg.wasm']);
    assert.equal(vector.result, true);
    assert.deepEqual(vector.files, ['vector_bg.wasm']);
    // A browser without wasm SIMD (its validate refuses the SIMD probe, as such an engine does)
    // fetches the scalar build, and gets the same image.
    const texture64 = async () => {
      const m = await import('./pkg/texture.js');
      await m.default();
      const data = new Uint8ClampedArray(64 * 64 * 4).map((_, i) => (i % 4 === 3 ? 255 : (i * 37) % 251));
      return Array.from(m.synthesizeTexture({ width: 64, height: 64, data }, { width: 96, height: 96, seed: 2 }).data);
    };
    // (js/pkg/simd.js's probe is the only module this small: 29 bytes.)
    const noSimd = () => {
      const validate = WebAssembly.validate;
      WebAssembly.validate = (bytes) => bytes.byteLength > 64 && validate(bytes);
    };
    const [simd, scalar] = [await fetched(texture64), await fetched(texture64, noSimd)];
    assert.deepEqual(simd.files, ['texture_bg.wasm']);
    assert.deepEqual(scalar.files, ['texture_scalar_bg.wasm']);
    assert.ok(simd.result.length === 96 * 96 * 4 && simd.result.every((v, i) => v === scalar.result[i]), 'the same image from both builds');
    // Through the worker client, as the playground calls it.
    const inWorker = async () => {
      const { PatternSynthClient } = await import('./pkg/client.js');
      const data = new Uint8ClampedArray(64 * 64 * 4).map((_, i) => (i % 4 === 3 ? 255 : (i * 37) % 251));
      return Array.from((await new PatternSynthClient('./pkg/worker.js').synthesizeTexture({ width: 64, height: 64, data }, { width: 96, height: 96, seed: 2 })).data);
    };
    const worker = await fetched(inWorker, null, true);
    assert.deepEqual(worker.files, ['texture_scalar_bg.wasm']);
    assert.ok(worker.result.every((v, i) => v === simd.result[i]), 'the worker\'s scalar build makes the same image');
  } finally {
    await browser.close();
    server.close();
  }
});
