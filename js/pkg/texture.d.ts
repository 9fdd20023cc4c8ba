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
import type { Rgba, RgbaImage, TextureOptions, BlendOptions, SeamlessOptions, SeamlessResult, Progress, Mask, Layout, TextureWithLayout, InpaintOptions, StyleOptions } from './types.js';
/** More of a texture, from one exemplar or several drawn from as one pool. */
export function synthesizeTexture(image: Rgba | Rgba[], opts: TextureOptions & { keepLayout: true }, onProgress?: Progress): TextureWithLayout;
export function synthesizeTexture(image: Rgba | Rgba[], opts: TextureOptions, onProgress?: Progress): RgbaImage;
/** `image` with the pixels where `mask` is opaque white filled from the rest of it; every
 *  other pixel identical. */
export function inpaintTexture(image: Rgba, mask: Mask, opts?: InpaintOptions, onProgress?: Progress): RgbaImage;
/** An image of `target`'s size in `style`'s texture, following `target`'s light and dark. */
export function transferStyle(style: Rgba, target: Rgba, opts?: StyleOptions, onProgress?: Progress): RgbaImage;
/** Replays a layout on other maps of the exemplars (normal, roughness, height): per map one
 *  image (one exemplar) or an array of one image per exemplar; one image per map back. */
export function applyLayout(layout: Layout, maps: (Rgba | Rgba[])[]): RgbaImage[];
export function blendTextures(a: Rgba, b: Rgba, opts: BlendOptions, onProgress?: Progress): RgbaImage;
export function seamlessTile(image: Rgba, opts?: SeamlessOptions, onProgress?: Progress): SeamlessResult;
/** Whether this JavaScript engine runs wasm SIMD: `init()` then loads the SIMD build, else the
 *  scalar one (`*_scalar_bg.wasm`, the same images). A page passing its own wasm URL picks by it. */
export const simd: boolean;
