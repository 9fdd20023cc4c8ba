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

// Banded texture synthesis (bands.js): { id, bands: 'open' | 'run' | 'close', ... }.
async function bandsMessage({ id, bands, handle, method, args, step, state, parent, from, to }) {
  await ready;
  // A band is a small part of the call: a report every 100 ms is plenty, and spares
  // the page thousands of messages.
  let last = 0;
  const progress = (fraction) => {
    const now = performance.now();
    if (now - last < 100) return;
    last = now;
    self.postMessage({ id, progress: fraction });
  };
  switch (bands) {
    case 'open': return api.bands.open(method, args);
    case 'run': return api.bands.run(handle, step, state, parent, from, to, progress);
    case 'close': return api.bands.close(handle);
    default: throw new Error(`Unknown band message '${bands}'.`);
  }
}

self.onmessage = async ({ data }) => {
  const { id, method, args = [] } = data;
  try {
    if (data.bands) {
      const result = await bandsMessage(data);
      const buffer = result?.data?.buffer ?? result?.buffer;
      return void self.postMessage({ id, result }, buffer instanceof ArrayBuffer ? [buffer] : []);
    }
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
