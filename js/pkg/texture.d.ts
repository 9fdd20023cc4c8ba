// patternsynth/texture: see texture.js.
import type { Init, InitSync } from './types.js';
export type * from './types.js';

declare const init: Init;
export default init;
export declare const initSync: InitSync;
/** How many times a trap (a bug) made the engine restart. */
export function restarts(): number;
export function version(): string;
import type { Rgba, RgbaImage, TextureOptions, BlendOptions, SeamlessOptions, SeamlessResult, Progress } from './types.js';
export function synthesizeTexture(image: Rgba, opts: TextureOptions, onProgress?: Progress): RgbaImage;
export function blendTextures(a: Rgba, b: Rgba, opts: BlendOptions, onProgress?: Progress): RgbaImage;
export function seamlessTile(image: Rgba, opts?: SeamlessOptions, onProgress?: Progress): SeamlessResult;
