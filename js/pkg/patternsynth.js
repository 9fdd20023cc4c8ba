// The package's main entry: the vector and texture engines in one wasm module. `await
// init()` once (or `initSync({ module })`), then call the functions; see README.md.
// The image codecs are a separate module: `await initCodecs()` before decodeImage or
// encodePng in a browser (Node loads them at import).
import * as glue from './wasm/full.js';
import { engine } from './instance.js';
import { simd } from './simd.js';

// The SIMD build where the engine runs it, else the scalar one (the same glue).
const full = engine(
  glue,
  simd ? new URL('./wasm/full_bg.wasm', import.meta.url) : new URL('./wasm/full_scalar_bg.wasm', import.meta.url),
  'patternsynth',
);

export default full.init;
export const initSync = full.initSync;
/** How many times the engine replaced its instance after a trap (a bug) or an exception
 *  thrown through it, for diagnostics. */
export const restarts = () => full.restarts;
/** The engine's restarts, renewals (instances replaced to give memory back) and memory. */
export const diagnostics = () => full.diagnostics();
export { default as initCodecs, initSync as initCodecsSync, decodeImage, encodePng } from './codec.js';

/** Whether this engine runs wasm SIMD, and so loads the SIMD build (`init()` without a URL
 *  picks it; a page passing its own URL picks by this). */
export { simd };
export const version = full.method('version');
export const parseSvg = full.method('parseSvg');
export const parseSvgReport = full.method('parseSvgReport');
export const classifyStrokes = full.method('classifyStrokes');
export const synthesizeStrokes = full.method('synthesizeStrokes');
export const strokeTile = full.method('strokeTile');
export const suggestStrokes = full.method('suggestStrokes');
export const synthesizeTexture = full.method('synthesizeTexture');
export const blendTextures = full.method('blendTextures');
export const seamlessTile = full.method('seamlessTile');
export const inpaintTexture = full.method('inpaintTexture');
export const transferStyle = full.method('transferStyle');
export const applyLayout = full.method('applyLayout');
/** The worker protocol of banded synthesis (bands.js and worker.js), not public API. */
export const bands = Object.freeze({
  open: full.method('bandsOpen'),
  run: full.method('bandsRun'),
  close: full.method('bandsClose'),
});
