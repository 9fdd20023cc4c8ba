// patternsynth/codec: see codec.js.
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
import type { Rgba, RgbaImage } from './types.js';
/** PNG or JPEG bytes to RGBA. */
export function decodeImage(bytes: Uint8Array | ArrayBuffer): RgbaImage;
/** RGBA to PNG bytes. */
export function encodePng(image: Rgba): Uint8Array<ArrayBuffer>;
