// patternsynth/texture: see texture.js.
import type { Diagnostics, Init, InitSync } from './types.js';
export type * from './types.js';

declare const init: Init;
export default init;
export declare const initSync: InitSync;
/** How many times the engine replaced its instance after a trap (a bug) or an exception thrown through it. */
export function restarts(): number;
/** Restarts, renewals (instances replaced after a call left memory over 64 MB above the start, to give it back) and wasm memory now and at the start, in bytes. */
export function diagnostics(): Diagnostics;
export function version(): string;
import type { Rgba, RgbaImage, TextureOptions, BlendOptions, SeamlessOptions, SeamlessResult, Progress } from './types.js';
export function synthesizeTexture(image: Rgba, opts: TextureOptions, onProgress?: Progress): RgbaImage;
export function blendTextures(a: Rgba, b: Rgba, opts: BlendOptions, onProgress?: Progress): RgbaImage;
export function seamlessTile(image: Rgba, opts?: SeamlessOptions, onProgress?: Progress): SeamlessResult;
/** Whether this JavaScript engine runs wasm SIMD: `init()` then loads the SIMD build, else the
 *  scalar one (`*_scalar_bg.wasm`, the same images). A page passing its own wasm URL picks by it. */
export const simd: boolean;
