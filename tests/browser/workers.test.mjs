// Banded texture synthesis on several workers in Chromium: the client with 1, 2 and 3
// workers gives byte for byte the image of the one-call API, for syntheses and blends;
// progress rises to 1; aborting stops every worker and the next call works.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openPlayground } from './harness.mjs';

test('any number of workers gives the same image, with progress, and aborts cleanly', async () => {
  const { page, close } = await openPlayground();
  try {
    const out = await page.evaluate(async () => {
      const { PatternSynthClient } = await import('./pkg/client.js');
      const ps = await import('./pkg/patternsynth.js');
      await ps.default();
      const load = async (name) => {
        const bmp = await createImageBitmap(await (await fetch(`./textures/${name}.png`)).blob());
        const c = new OffscreenCanvas(bmp.width, bmp.height).getContext('2d');
        c.drawImage(bmp, 0, 0);
        return c.getImageData(0, 0, bmp.width, bmp.height);
      };
      const [grass, wood] = await Promise.all([load('grass'), load('wood')]);
      const same = (a, b) => a.width === b.width && a.height === b.height && a.data.length === b.data.length && a.data.every((v, i) => v === b.data[i]);
      const opts = { width: 200, height: 256, seed: 3, schedule: 'bands' };
      const blend = { width: 160, height: 200, seed: 4, schedule: 'bands', coefficient: 'ease' };
      const reference = ps.synthesizeTexture(grass, opts);
      const blended = ps.blendTextures(wood, grass, blend);
      const results = {};
      for (const workers of [1, 2, 3]) {
        const client = new PatternSynthClient(undefined, { workers });
        const progress = [];
        const image = await client.synthesizeTexture(grass, opts, { onProgress: (f) => progress.push(f) });
        const mixed = await client.blendTextures(wood, grass, blend);
        results[workers] = {
          same: same(image, reference),
          blendSame: same(mixed, blended),
          rising: progress.every((f, i) => i === 0 || f >= progress[i - 1]),
          last: progress.at(-1),
          reports: progress.length,
          helpers: client.helpers.length,
        };
        client.terminate();
      }
      // An abort in the middle of a banded call stops the workers; the next call works.
      const client = new PatternSynthClient(undefined, { workers: 2 });
      const controller = new AbortController();
      const aborted = client.synthesizeTexture(grass, { ...opts, width: 512, height: 512 }, {
        signal: controller.signal,
        onProgress: (f) => { if (f > 0.3) controller.abort(); },
      }).then(() => 'resolved', (e) => e.name);
      const abortName = await aborted;
      const helpersAfterAbort = client.helpers.length;
      const again = await client.synthesizeTexture(grass, opts);
      // A small default call runs in scanline order in one worker (no helpers needed).
      const small = new PatternSynthClient(undefined, { workers: 2 });
      const tiny = await small.synthesizeTexture(grass, { width: 64, height: 64, seed: 1 });
      const tinySame = same(tiny, ps.synthesizeTexture(grass, { width: 64, height: 64, seed: 1 })) && small.helpers.length === 0;
      let badWorkers;
      try { new PatternSynthClient(undefined, { workers: 0 }); } catch (e) { badWorkers = e.message; }
      return { results, abortName, helpersAfterAbort, againSame: same(again, reference), tinySame, badWorkers };
    });
    for (const [workers, r] of Object.entries(out.results)) {
      assert.ok(r.same, `${workers} workers: the same image as the one-call API`);
      assert.ok(r.blendSame, `${workers} workers: the same blend`);
      assert.ok(r.rising && r.reports > 5, `${workers} workers: progress rises (${r.reports} reports)`);
      assert.ok(r.last > 0.99, `${workers} workers: progress ends at ${r.last}`);
      assert.equal(r.helpers, Number(workers) - 1);
    }
    assert.equal(out.abortName, 'AbortError');
    assert.equal(out.helpersAfterAbort, 0, 'the abort terminated the helpers');
    assert.ok(out.againSame, 'the call after the abort works');
    assert.ok(out.tinySame, 'a small call: the same image, and no helper worker started');
    assert.match(out.badWorkers, /workers must be a whole number from 1/);
  } finally {
    await close();
  }
});

test("issue 30's syntheses share the workers too: a sample mask with a guide, and a style transfer", async () => {
  const { page, close } = await openPlayground();
  try {
    const out = await page.evaluate(async () => {
      const { PatternSynthClient } = await import('./pkg/client.js');
      const ps = await import('./pkg/patternsynth.js');
      await ps.default();
      const bmp = await createImageBitmap(await (await fetch('./textures/brick.png')).blob());
      const ctx = new OffscreenCanvas(bmp.width, bmp.height).getContext('2d');
      ctx.drawImage(bmp, 0, 0);
      const brick = ctx.getImageData(0, 0, bmp.width, bmp.height);
      const image = (w, h, f) => {
        const d = new Uint8ClampedArray(w * h * 4);
        for (let i = 0; i < w * h; i++) { const v = f(i % w, Math.floor(i / w)); d.set([v, v, v, 255], 4 * i); }
        return { width: w, height: h, data: d };
      };
      const same = (a, b) => a.width === b.width && a.data.length === b.data.length && a.data.every((v, i) => v === b.data[i]);
      const opts = {
        width: 256, height: 200, seed: 2, schedule: 'bands',
        sampleMask: image(128, 128, (x) => (x < 32 ? 255 : 0)),
        guides: { exemplar: image(128, 128, (x) => 2 * x), target: image(256, 200, (x, y) => (Math.hypot(x - 128, y - 100) < 60 ? 255 : 0)) },
      };
      const target = image(512, 512, (x, y) => ((x + y) % 128 < 64 ? 220 : 30));
      const client = new PatternSynthClient(undefined, { workers: 2 });
      const guided = await client.synthesizeTexture(brick, opts);
      const styled = await client.transferStyle(brick, target, { seed: 1 });
      const helpers = client.helpers.length;
      client.terminate();
      return { guidedSame: same(guided, ps.synthesizeTexture(brick, opts)), styleSame: same(styled, ps.transferStyle(brick, target, { seed: 1 })), helpers };
    });
    assert.ok(out.guidedSame, 'a masked, guided synthesis on 2 workers: the one-call image');
    assert.ok(out.styleSame, 'a 512² style transfer on 2 workers: the one-call image');
    assert.equal(out.helpers, 1, 'the second worker was used');
  } finally {
    await close();
  }
});
