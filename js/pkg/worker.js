// Web Worker that runs the wasm engines off the main thread. `PatternSynthClient`
// (patternsynth/client) starts it; see the README for bundlers that need it passed in.
//
// Protocol: { id, method, args } in; { id, progress } ... then { id, result } or
// { id, error, name } out. A synchronous wasm call cannot read messages, so cancelling
// is done by the client terminating this worker. After a trap the engine replaces its
// own instance (instance.js), so this worker stays usable.
import init, * as api from './patternsynth.js';
import { METHODS } from './api.js';

const ready = init();
// The codecs load on first use only: browsers rarely need them.
let codecs = null;

// Pixel buffers go back by transfer, not by copy.
const transferables = (r) => {
  const image = r?.image ?? r;
  if (r instanceof Uint8Array) return [r.buffer];
  return image?.data?.buffer instanceof ArrayBuffer ? [image.data.buffer] : [];
};

self.onmessage = async ({ data }) => {
  const { id, method, args = [] } = data;
  try {
    const spec = Object.hasOwn(METHODS, method) ? METHODS[method] : null;
    if (!spec) throw new Error(`Unknown method '${method}'.`);
    if (spec.module === 'codec') await (codecs ??= api.initCodecs().catch((e) => { codecs = null; throw e; }));
    else await ready;
    const callArgs = args.slice(0, spec.args);
    if (spec.progress) {
      callArgs.length = spec.args;
      callArgs.push((fraction) => { self.postMessage({ id, progress: fraction }); });
    }
    const result = api[method](...callArgs);
    self.postMessage({ id, result }, transferables(result));
  } catch (e) {
    self.postMessage({ id, error: e instanceof Error ? e.message : String(e), name: e?.name });
  }
};
