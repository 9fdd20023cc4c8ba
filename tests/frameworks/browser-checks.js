// What every framework site's page does in the browser (the test copies this file into
// each site): strokes on the main thread with patternsynth/vector, a texture through the
// worker client with progress, a call aborted with an AbortController (rejects with
// AbortError), a call after the abort that works, and the codecs in the worker.
// `wasmUrl` and `workerUrl` are for setups that bundle no wasm or workers (Rollup: the
// README's recipe); left out, the package finds its files itself.
import init, { synthesizeStrokes } from 'patternsynth/vector';
import { PatternSynthClient } from 'patternsynth/client';

const grid = Array.from({ length: 16 }, (_, i) => ({ points: [[10 + (i % 4) * 20, 10 + Math.floor(i / 4) * 20], [16 + (i % 4) * 20, 16 + Math.floor(i / 4) * 20]], width: 2, stroke: '#224466' }));
const image = (w, h) => ({ width: w, height: h, data: Uint8ClampedArray.from({ length: w * h * 4 }, (_, i) => (i % 4 === 3 ? 255 : (i * 2654435761) >>> 24)) });

export async function checks({ wasmUrl, workerUrl } = {}) {
  await init(wasmUrl);
  const strokes = synthesizeStrokes(grid, { width: 300, height: 300, seed: 1 }).strokes.length;
  const client = workerUrl ? new PatternSynthClient(workerUrl) : new PatternSynthClient();
  const progress = [];
  const texture = await client.synthesizeTexture(image(32, 32), { width: 64, height: 64, seed: 1 }, { onProgress: (f) => progress.push(f) });
  const controller = new AbortController();
  const long = client.synthesizeTexture(image(64, 64), { width: 1024, height: 1024 }, { signal: controller.signal });
  setTimeout(() => controller.abort(), 100);
  const aborted = await long.then(() => 'resolved', (e) => e.name);
  const after = await client.synthesizeTexture(image(32, 32), { width: 48, height: 40 });
  const decoded = await client.decodeImage(await client.encodePng(image(8, 6)));
  return { strokes, texture: [texture.width, texture.height, texture.data.constructor.name], progress: progress.length, lastProgress: progress.at(-1), aborted, after: [after.width, after.height], decoded: [decoded.width, decoded.height] };
}

/** Runs the checks once and leaves their outcome in window.result for the test. */
export function report(options) {
  window.result ??= checks(options).catch((e) => ({ error: `${e.name}: ${e.message}` }));
}
