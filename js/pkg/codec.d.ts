// patternsynth/codec: see codec.js.
import type { Init, InitSync } from './types.js';
export type * from './types.js';

declare const init: Init;
export default init;
export declare const initSync: InitSync;
/** How many times a trap (a bug) made the engine restart. */
export function restarts(): number;
export function version(): string;
import type { Rgba, RgbaImage } from './types.js';
/** PNG or JPEG bytes to RGBA. */
export function decodeImage(bytes: Uint8Array | ArrayBuffer): RgbaImage;
/** RGBA to PNG bytes. */
export function encodePng(image: Rgba): Uint8Array<ArrayBuffer>;
