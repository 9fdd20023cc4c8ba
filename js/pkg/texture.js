// patternsynth/texture: engines 2 and 3 only (texture synthesis, blends, seamless
// tiles) in their own wasm module. Images in and out are RGBA (an ImageData works);
// decode files with the browser (createImageBitmap) or patternsynth/codec.
import * as glue from './wasm/texture.js';
import { engine } from './instance.js';
import { simd } from './simd.js';

// The SIMD build where the engine runs it, else the scalar one (the same glue).
const texture = engine(
  glue,
  simd ? new URL('./wasm/texture_bg.wasm', import.meta.url) : new URL('./wasm/texture_scalar_bg.wasm', import.meta.url),
  'patternsynth/texture',
);

export default texture.init;
export const initSync = texture.initSync;
/** How many times the engine replaced its instance after a trap (a bug) or an exception
 *  thrown through it, for diagnostics. */
export const restarts = () => texture.restarts;
/** The engine's restarts, renewals (instances replaced to give memory back) and memory. */
export const diagnostics = () => texture.diagnostics();

/** Whether this engine runs wasm SIMD, and so loads the SIMD build (`init()` without a URL
 *  picks it; a page passing its own URL picks by this). */
export { simd };
export const version = texture.method('version');
export const synthesizeTexture = texture.method('synthesizeTexture');
export const blendTextures = texture.method('blendTextures');
export const seamlessTile = texture.method('seamlessTile');
export const inpaintTexture = texture.method('inpaintTexture');
export const transferStyle = texture.method('transferStyle');
export const applyLayout = texture.method('applyLayout');
/** The worker protocol of banded synthesis (bands.js and worker.js), not public API. */
export const bands = Object.freeze({
  open: texture.method('bandsOpen'),
  run: texture.method('bandsRun'),
  close: texture.method('bandsClose'),
});
