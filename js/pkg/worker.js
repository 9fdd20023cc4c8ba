// Web Worker that runs the wasm engines off the main thread. Start it with
// `new Worker(new URL('patternsynth/worker', import.meta.url), { type: 'module' })`, or
// let `PatternSynthClient` (patternsynth/client) do it for you.
//
// Protocol: { id, method, args } in; { id, progress } ... then { id, result } or
// { id, error } out. A synchronous wasm call cannot read messages, so cancelling is done
// by the client terminating this worker.
import init, * as api from './patternsynth.js';

const ready = init();
const METHODS = new Set([
  'parseSvg', 'parseSvgReport', 'classifyStrokes', 'synthesizeStrokes', 'strokeTile', 'exampleStrokes', 'version',
  'synthesizeTexture', 'blendTextures', 'seamlessTile', 'decodeImage', 'encodePng',
]);
const WITH_PROGRESS = new Set(['synthesizeStrokes', 'synthesizeTexture', 'blendTextures', 'seamlessTile']);

// Pixel buffers go back by transfer, not by copy.
const transferables = (r) => {
  const image = r?.image ?? r;
  if (r instanceof Uint8Array) return [r.buffer];
  return image?.data?.buffer instanceof ArrayBuffer ? [image.data.buffer] : [];
};

self.onmessage = async ({ data }) => {
  const { id, method, args = [] } = data;
  try {
    await ready;
    if (!METHODS.has(method)) throw new Error(`Unknown method '${method}'.`);
    const call = WITH_PROGRESS.has(method)
      ? api[method](...args, (fraction) => { self.postMessage({ id, progress: fraction }); })
      : api[method](...args);
    self.postMessage({ id, result: call }, transferables(call));
  } catch (e) {
    self.postMessage({ id, error: e instanceof Error ? e.message : String(e) });
  }
};
