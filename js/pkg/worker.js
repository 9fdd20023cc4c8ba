// Web Worker that runs the wasm engines off the main thread. `PatternSynthClient`
// (patternsynth/client) starts it; see the README for bundlers that need it passed in.
//
// Protocol: { id, method, args, fields?, preview? } in; { id, progress } ... then
// { id, result } or { id, error, name } out. `fields` keeps only those fields of the
// result (a page showing a large stroke result need not receive its strokes: reading
// 36,000 of them took the page's main thread 0.7 s), and `svgBlob` among them is the
// SVG as a Blob; `preview` adds `result.preview`, the strokes drawn to an ImageBitmap
// here (render.js). A synchronous wasm call cannot read messages, so cancelling
// is done by the client terminating this worker. After a trap the engine replaces its
// own instance (instance.js), so this worker stays usable.
import * as vector from './vector.js';
import * as texture from './texture.js';
import * as codec from './codec.js';
import { METHODS } from './api.js';
import { renderStrokes } from './render.js';
import { checkStyle, restyleStrokes, restyleSvg } from './restyle.js';

// Each call loads only the module that has it: a worker that makes textures never
// fetches the vector engine (or the codecs), and one that draws strokes never fetches
// the texture engine. Bundlers emit each module's wasm as its own asset.
const MODULES = { vector, texture, codec };
const loading = {};
/** The entry of `name` once its wasm is instantiated (fetched on first use only). */
function engine(name) {
  loading[name] ??= MODULES[name].default().then(() => MODULES[name], (e) => {
    loading[name] = null;
    throw e;
  });
  return loading[name];
}

// The last stroke result a call asked to keep (`keep: true`), for `restyle`: a page
// recolours a result of tens of thousands of strokes without synthesizing it again,
// and without holding its strokes.
let kept = null;

/** The kept result in `style` (restyle.js): the SVG as a Blob, and drawn (`preview`). */
async function restyle([style, preview]) {
  if (!kept) throw new Error('Nothing to restyle: this worker keeps no stroke result (call synthesizeStrokes or strokeTile with { keep: true } first; an aborted call starts a fresh worker).');
  const s = checkStyle(style);
  const out = { svgBlob: new Blob([restyleSvg(kept.svg, s)], { type: 'image/svg+xml' }) };
  if (preview) {
    const strokes = restyleStrokes(kept.strokes, kept.classes, s);
    out.preview = await renderStrokes(strokes, kept.width, kept.height, { ...preview, background: s.background ?? undefined, opacity: s.opacity });
  }
  return out;
}

// Pixel buffers and previews go back by transfer, not by copy.
const transferables = (r) => {
  if (r instanceof Uint8Array) return [r.buffer];
  // An image, { image, layout } (keepLayout), or an array of images (applyLayout).
  const images = Array.isArray(r) ? r : [r?.image ?? r];
  const list = images.map((i) => i?.data?.buffer).filter((b) => b instanceof ArrayBuffer);
  if (r?.layout?.data?.buffer instanceof ArrayBuffer) list.push(r.layout.data.buffer);
  if (typeof ImageBitmap === 'function' && r?.preview instanceof ImageBitmap) list.push(r.preview);
  return list;
};

/** The result as the page asked for it: drawn (`preview`), then cut to `fields`. */
async function shape(result, args, { fields, preview }) {
  if (!fields && !preview) return result;
  if (result === null || typeof result !== 'object') throw new Error('fields and preview apply to results that are objects.');
  let out = result;
  if (fields) {
    if (!Array.isArray(fields) || !fields.every((f) => typeof f === 'string')) throw new Error('fields must be an array of result field names.');
    out = Object.fromEntries(fields.filter((f) => f in result).map((f) => [f, result[f]]));
    // A large SVG as a Blob made here: the page gets a reference instead of copying and
    // encoding the text on its own thread (25 MB took it 0.3 s).
    if (fields.includes('svgBlob') && typeof result.svg === 'string') out.svgBlob = new Blob([result.svg], { type: 'image/svg+xml' });
  }
  if (preview) {
    if (!Array.isArray(result.strokes)) throw new Error('preview applies to results with strokes.');
    out.preview = await renderStrokes(result.strokes, result.width ?? args[1]?.width, result.height ?? args[1]?.height, preview);
  }
  return out;
}

// Banded texture synthesis (bands.js): { id, bands: 'open' | 'run' | 'close', ... }.
async function bandsMessage({ id, bands, handle, method, args, step, state, parent, from, to }) {
  const api = await engine('texture');
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
    if (method === 'restyle') {
      const result = await restyle(args);
      return void self.postMessage({ id, result }, transferables(result));
    }
    const spec = Object.hasOwn(METHODS, method) ? METHODS[method] : null;
    if (!spec) throw new Error(`Unknown method '${method}'.`);
    // `version` is in every module: the one already loaded, else the smallest.
    const api = await engine(spec.module ?? (loading.vector ? 'vector' : 'texture'));
    const callArgs = args.slice(0, spec.args);
    if (spec.progress) {
      callArgs.length = spec.args;
      callArgs.push((fraction) => { self.postMessage({ id, progress: fraction }); });
    }
    const full = api[method](...callArgs);
    if (data.keep) {
      if (!Array.isArray(full?.strokes) || typeof full.svg !== 'string') throw new Error('keep applies to stroke results (synthesizeStrokes, strokeTile).');
      kept = { strokes: full.strokes, classes: full.classes, svg: full.svg, width: full.width ?? callArgs[1]?.width, height: full.height ?? callArgs[1]?.height };
    }
    const result = await shape(full, callArgs, data);
    self.postMessage({ id, result }, transferables(result));
  } catch (e) {
    self.postMessage({ id, error: e instanceof Error ? e.message : String(e), name: e?.name });
  }
};
