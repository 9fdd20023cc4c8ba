// patternsynth: the vector and texture engines in one module (see patternsynth.js);
// the codecs load separately (initCodecs).
import type { Diagnostics, Init, InitSync } from './types.js';
export type * from './types.js';

declare const init: Init;
export default init;
export declare const initSync: InitSync;
/** How many times the engine replaced its instance after a trap (a bug) or an exception thrown through it. */
export function restarts(): number;
/** Restarts, renewals (instances replaced after a call left memory over 64 MB above the start, to give it back) and wasm memory now and at the start, in bytes. */
export function diagnostics(): Diagnostics;
/** Loads the image codec module (decodeImage, encodePng); Node loads it at import. */
export declare const initCodecs: Init;
export declare const initCodecsSync: InitSync;
export { version, parseSvg, parseSvgReport, classifyStrokes, synthesizeStrokes, strokeTile, suggestStrokes } from './vector.js';
export { synthesizeTexture, blendTextures, seamlessTile, inpaintTexture, transferStyle, applyLayout } from './texture.js';
export { decodeImage, encodePng } from './codec.js';
/** Whether this JavaScript engine runs wasm SIMD: `init()` then loads the SIMD build, else the
 *  scalar one (`*_scalar_bg.wasm`, the same images). A page passing its own wasm URL picks by it. */
export const simd: boolean;
